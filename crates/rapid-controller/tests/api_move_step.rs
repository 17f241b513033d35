//! The move step (`StepKind::Motion`, RWS's `execmode=stepmotion`, the PC SDK's
//! "execute to next motion instruction"): the stopped program runs on, into the
//! routines it calls, until a motion instruction has run, and stands stopped at the
//! statement after it. Expected pointers and positions are worked out by hand from
//! the program below.

mod api_common;

use api_common::{line_of, with_signals};
use rapid_controller::api::{RunOutcome, Session, StepKind, Until};
use rapid_controller::ProgramState;
use rapid_robot::RobotResources;

const PROGRAM: &str = "MODULE MainModule
  VAR num n := 0;
  CONST robtarget p10 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget p20 := [[400, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    n := 1;
    Approach;
    n := 4;
    MoveL p20, v100, z10, tool0;
    n := 5;
    n := 6;
  ENDPROC
  PROC Approach()
    n := 2;
    MoveJ p10, v1000, fine, tool0;
    n := 3;
  ENDPROC
ENDMODULE
";

/// T_ROB1's TCP x (mm) where its robot stands at the controller's time.
fn tcp_x(session: &mut Session) -> f64 {
    let time = session.time();
    let robot = &mut session.controller_mut().tasks[0].loaded.vm.resources_mut().robot_mut();
    let joints = robot.joints_at(time);
    robot.flange_of(&joints).0.translation.vector.x
}

/// Where T_ROB1's program pointer stands: (routine, line).
fn pointer(session: &Session) -> (String, u32) {
    match session.program_pointer("T_ROB1") {
        Ok(Some(at)) => (at.routine, at.line),
        other => panic!("no program pointer: {other:?}"),
    }
}

fn n(session: &mut Session) -> String {
    session.read_data("T_ROB1/MainModule/n").map(|d| d.value).unwrap_or_default()
}

/// One move step, carried out to the program standing stopped again (or ended).
fn move_step(session: &mut Session) -> RunOutcome {
    assert!(session.step("T_ROB1", StepKind::Motion).is_ok());
    let outcome = session.run_until(Until::Stopped, 1_000_000);
    assert!(!matches!(session.program_state(), ProgramState::Stepping { .. }), "the step is over");
    outcome
}

#[test]
fn a_move_step_runs_to_the_statement_after_the_next_motion_instruction() {
    let mut session = with_signals(PROGRAM, &[], &[]);
    assert_eq!(pointer(&session), ("main".to_owned(), line_of(PROGRAM, "n := 1")));

    // `n := 1`, into Approach, `n := 2`, the MoveJ to p10 (a stop point: the step
    // ends once the robot stands there): the pointer on `n := 3` inside Approach.
    assert_eq!(move_step(&mut session), RunOutcome::Stopped);
    assert_eq!(pointer(&session), ("Approach".to_owned(), line_of(PROGRAM, "n := 3")));
    assert_eq!(n(&mut session), "2");
    assert!((tcp_x(&mut session) - 300.0).abs() < 1e-3, "at p10: {}", tcp_x(&mut session));
    assert_eq!(session.call_stack("T_ROB1").map(|s| s.len()), Ok(2));

    // `n := 3`, back in main, `n := 4`, the MoveL to p20, programmed as a fly-by
    // point (z10): stepped, its zone is a stop point (the overview manual's figure of
    // step execution: each forward step of a move ends with the robot at the
    // programmed point), so the step ends with the robot at p20, not 10 mm or more
    // short of it moving on while the program stands.
    assert_eq!(move_step(&mut session), RunOutcome::Stopped);
    assert_eq!(pointer(&session), ("main".to_owned(), line_of(PROGRAM, "n := 5")));
    assert_eq!(n(&mut session), "4");
    let at_end = tcp_x(&mut session);
    assert!((at_end - 400.0).abs() < 1e-3, "at p20: {at_end}");

    // No motion instruction is left: the step runs `n := 5` and `n := 6` and ends
    // with the task.
    assert_eq!(move_step(&mut session), RunOutcome::Ended);
    assert_eq!(n(&mut session), "6");
    assert!(session.all_normal_ended());
}

const MODES: &str = "MODULE MainModule
  VAR num mode := 0;
  VAR num modes := 0;
  VAR num back := 0;
  CONST robtarget p10 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget p20 := [[400, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveJ p10, v1000, fine, tool0;
    mode := RunMode();
    Mark;
    MoveL p20, v100, z50, tool0;
    modes := RunMode();
  ENDPROC
  PROC Mark()
    mode := mode + 10;
  BACKWARD
    back := RunMode();
  ENDPROC
ENDMODULE
";

fn read(session: &mut Session, name: &str) -> String {
    session.read_data(&format!("T_ROB1/MainModule/{name}")).map(|d| d.value).unwrap_or_default()
}

/// One forward step over the statement at the pointer, carried out.
fn step_over(session: &mut Session) {
    assert!(session.step("T_ROB1", StepKind::Over).is_ok());
    assert_eq!(session.run_until(Until::Stopped, 1_000_000), RunOutcome::Stopped);
}

#[test]
fn run_mode_tells_stepping_from_running_and_a_stepped_move_ends_at_its_target() {
    let mut session = with_signals(MODES, &[], &[]);
    // Forward steps: RunMode() is RUN_INSTR_FWD (2); Mark adds 10.
    step_over(&mut session);
    step_over(&mut session);
    assert_eq!(read(&mut session, "mode"), "2");
    step_over(&mut session);
    assert_eq!(read(&mut session, "mode"), "12");
    // A step backward over `Mark;` runs its BACKWARD handler: RUN_INSTR_BWD (3).
    assert!(session.step_backward("T_ROB1").is_ok());
    assert_eq!(read(&mut session, "back"), "3");
    // Forward again over Mark, then the MoveL to p20 with z50: a stop point while
    // stepping, so the robot stands at x = 400 when the step ends (a 50 mm zone would
    // have left the instruction done 50 mm or more before p20).
    step_over(&mut session);
    step_over(&mut session);
    let x = tcp_x(&mut session);
    assert!((x - 400.0).abs() < 1e-3, "at p20: {x}");
    // Continuous start from here: RUN_CONT_CYCLE (1).
    assert!(session.start(rapid_controller::api::StartFrom::Pointer).is_ok());
    assert_eq!(session.run_until(Until::Stopped, 1_000_000), RunOutcome::Ended);
    assert_eq!(read(&mut session, "modes"), "1");
}
