//! The controller state a program does not change: only manual reduced speed mode
//! limits the TCP speed (what happens to it across PP to Main, with the robot's active
//! tool, work object and payload, is rapid-robot's `tests/active_sysdata.rs`).

use rapid_vm::builtins::controller::{ControllerState, OpMode};

#[test]
fn only_manual_reduced_speed_limits_the_tcp() {
    assert_eq!(ControllerState::new(OpMode::Auto, 100.0).tcp_speed_limit(), None);
    assert_eq!(ControllerState::new(OpMode::ManualFull, 100.0).tcp_speed_limit(), None);
    assert_eq!(ControllerState::new(OpMode::ManualReduced, 100.0).tcp_speed_limit(), Some(250.0));
}
