//! The panel part of the API: motors, run mode, the robots' positions.

mod api_common;

use rapid_controller::api::{RunOutcome, StartFrom, Until};

#[test]
fn motors_off_refuses_a_start_and_on_allows_it() {
    let mut s = api_common::session();
    assert!(s.motors_on());
    s.set_motors(false);
    assert!(!s.motors_on());
    assert!(s.start(StartFrom::Pointer).is_err());
    s.set_motors(true);
    assert!(s.start(StartFrom::Pointer).is_ok());
}

#[test]
fn the_robot_stands_at_the_target_it_moved_to() {
    let mut s = api_common::session();
    s.start(StartFrom::Pointer).expect("starts");
    // T_ROB1 moves to p10 then p20 ([400, 0, 400], tool0) and then waits for nothing;
    // T_OTHER waits for `shared`, so run to a time well past both moves.
    let outcome = s.run_until(Until::Time(20.0), 10_000_000);
    assert!(matches!(outcome, RunOutcome::Running | RunOutcome::Stopped | RunOutcome::Ended), "{outcome:?}");
    let units = s.mechunits();
    assert_eq!(units.len(), 1, "one robot: T_ROB1's");
    let rob = &units[0];
    assert_eq!(rob.task, "T_ROB1");
    for (got, want) in rob.trans.iter().zip([400.0, 0.0, 400.0]) {
        assert!((got - want).abs() < 0.01, "flange at {:?}", rob.trans);
    }
    // The orientation [0, 0, 1, 0] (q1 >= 0 as the controller shows it).
    for (got, want) in rob.orient.iter().zip([0.0, 0.0, 1.0, 0.0]) {
        assert!((got - want).abs() < 1e-6, "orient {:?}", rob.orient);
    }
    // No external axes: 9E9.
    assert!(rob.extax.iter().all(|&e| e > 8.9e9), "{:?}", rob.extax);
}

#[test]
fn cycle_once_ends_every_normal_task() {
    let mut s =
        api_common::with_signals("MODULE M\n  PROC main()\n    WaitTime 0.1;\n  ENDPROC\nENDMODULE\n", &[], &[]);
    assert!(!s.all_normal_ended());
    s.set_cycles(1);
    s.start(StartFrom::Pointer).expect("starts");
    s.run_until(Until::Time(1.0), 100_000);
    assert!(s.all_normal_ended());
}

#[test]
fn a_module_loaded_from_home_is_linked_and_unloaded_again() {
    let root = std::env::temp_dir().join(format!("rapid-api-modules-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(root.join("HOME")).unwrap();
    std::fs::write(root.join("HOME/Extra.mod"), "MODULE Extra\n  PERS num extra := 42;\nENDMODULE\n").unwrap();
    let mut s = api_common::session();
    s.controller_mut().tasks[0].loaded.vm.resources_mut().devices.set_root(&root);
    assert_eq!(s.modules("T_ROB1").unwrap(), vec!["MainModule".to_owned()]);
    assert_eq!(s.modules("T_OTHER").unwrap(), vec!["Other".to_owned()]);
    assert!(s.read_data("T_ROB1/extra").is_err());
    s.load_module("T_ROB1", "HOME:/Extra.mod").expect("loads");
    assert!(s.modules("T_ROB1").unwrap().iter().any(|m| m == "Extra"));
    // A second load of the same module is refused (ERR_LOADED).
    assert!(s.load_module("T_ROB1", "HOME:/Extra.mod").is_err());
    s.unload_module("T_ROB1", "Extra").expect("unloads");
    assert!(!s.modules("T_ROB1").unwrap().iter().any(|m| m == "Extra"));
    assert!(s.unload_module("T_ROB1", "Extra").is_err());
    assert!(s.load_module("T_ROB1", "HOME:/Missing.mod").is_err());
    assert!(s.load_module("T_ROB1", "HOME:/../Extra.mod").is_err(), "a path leaving the device");
    // Not while the program runs.
    s.start(StartFrom::Pointer).unwrap();
    assert!(s.load_module("T_ROB1", "HOME:/Extra.mod").is_err());
    let _ = std::fs::remove_dir_all(&root);
}

/// A MoveL of 200 mm at v100 from a stand-still to a stand-still, timed by the program.
const TIMED_MOVE: &str = "MODULE MainModule
  VAR clock c;
  VAR num took := -1;
  PROC main()
    MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    ClkReset c;
    ClkStart c;
    MoveL Offs(CRobT(), 0, 200, 0), v100, fine, tool0;
    ClkStop c;
    took := ClkRead(c \\HighRes);
  ENDPROC
ENDMODULE
";

/// The virtual time the timed MoveL takes at speed override `percent`.
fn timed_move(percent: Option<f64>) -> f64 {
    let mut s = api_common::with_signals(TIMED_MOVE, &[], &[]);
    if let Some(percent) = percent {
        s.set_speed_override(percent).expect("1..100 is taken");
    }
    s.set_cycles(1);
    s.start(StartFrom::Pointer).expect("starts");
    s.run_until(Until::Time(30.0), 10_000_000);
    assert!(s.all_normal_ended());
    s.read_data("T_ROB1/took").expect("took").value.parse().expect("a number")
}

#[test]
fn a_new_speed_override_slows_a_move_under_way() {
    let mut s = api_common::with_signals(TIMED_MOVE, &[], &[]);
    s.set_cycles(1);
    s.start(StartFrom::Pointer).expect("starts");
    // To the MoveL: the pointer stands on it as it starts (the MoveAbsJ's fine point
    // reached, the clock started).
    let line = TIMED_MOVE.lines().position(|l| l.contains("MoveL")).unwrap() as u32 + 1;
    for _ in 0..10_000 {
        if s.program_pointer("T_ROB1").ok().flatten().is_some_and(|at| at.line == line) {
            break;
        }
        s.run(1);
    }
    let started = s.time();
    // 1 s into the move at 100 mm/s (0.01 s of ramp at 10 000 mm/s²): 99.5 mm done.
    // At 50 % the robot brakes to 50 mm/s in 0.005 s (0.375 mm), cruises 100 mm in
    // 2 s and brakes to a stop in 0.005 s (0.125 mm): 2.01 s where 1.01 s were left,
    // so 1 s more than the whole move's time at full speed.
    s.run_until(Until::Time(started + 1.0), 10_000_000);
    s.set_speed_override(50.0).expect("50 % is taken");
    s.run_until(Until::Time(started + 30.0), 10_000_000);
    assert!(s.all_normal_ended());
    let took: f64 = s.read_data("T_ROB1/took").expect("took").value.parse().expect("a number");
    let full = timed_move(None);
    assert!((took - full - 1.0).abs() < 0.01, "full speed {full}, slowed after 1 s {took}");
}

#[test]
fn the_speed_override_slows_the_programmed_moves() {
    assert_eq!(api_common::session().speed_override(), 100.0);
    // 200 mm at 100 mm/s is 2 s at full speed, 200 mm at 50 mm/s 4 s at 50 %, each
    // plus the short ramps from and to a stand-still (well under 0.1 s at 1 g).
    let full = timed_move(None);
    let half = timed_move(Some(50.0));
    assert!((2.0..2.1).contains(&full), "{full}");
    assert!((4.0..4.1).contains(&half), "{half}");
    assert!((half / full - 2.0).abs() < 0.05, "{full} {half}");
    // 0 % (the robot standing still in its move) and more than 100 % are refused.
    let mut s = api_common::session();
    assert!(s.set_speed_override(0.0).is_err());
    assert!(s.set_speed_override(101.0).is_err());
    assert_eq!(s.speed_override(), 100.0);
    s.set_speed_override(25.0).unwrap();
    assert_eq!(s.speed_override(), 25.0);
}
