//! The controller API's execution control on a two-task system: start, stop in the
//! middle of a move, steps into, over and out, a step backward, breakpoints, PP to
//! Main and to a routine, program pointers and call stacks. Expected values come from
//! the RAPID rules (worked out in the comments), not from a run.

mod api_common;

use api_common::{line_of, session, ROBOT};
use rapid_controller::api::{ApiError, RunOutcome, Session, StartFrom, StepKind, Until};
use rapid_controller::{ProgramState, StopKind};
use rapid_robot::RobotResources;

const FILE: &str = "T_ROB1/MainModule.mod";

/// T_ROB1's TCP x (mm) where its robot stands at the controller's time.
fn tcp_x(session: &mut Session) -> f64 {
    let time = session.time();
    let robot = session.controller_mut().tasks[0].loaded.vm.resources_mut().robot_mut();
    let joints = robot.joints_at(time);
    robot.flange_of(&joints).0.translation.vector.x
}

fn pp_line(session: &Session, task: &str) -> u32 {
    match session.program_pointer(task) {
        Ok(Some(at)) => at.line,
        other => panic!("no program pointer for {task}: {other:?}"),
    }
}

fn read(session: &mut Session, path: &str) -> String {
    match session.read_data(path) {
        Ok(data) => data.value,
        Err(err) => panic!("{path}: {err}"),
    }
}

/// Runs one statement at a time until T_ROB1's program pointer is on `line`.
fn run_to_line(session: &mut Session, line: u32) {
    for _ in 0..10_000 {
        if pp_line(session, "T_ROB1") == line {
            return;
        }
        session.run(1);
    }
    panic!("T_ROB1 never reached line {line}");
}

/// Carries out the step asked for, to the program standing stopped again.
fn finish_step(session: &mut Session) {
    assert_eq!(session.run_until(Until::Stopped, 1_000_000), RunOutcome::Stopped);
}

#[test]
fn a_booted_program_stands_stopped_at_main() {
    let mut session = session();
    assert_eq!(session.program_state(), ProgramState::Stopped);
    assert_eq!(pp_line(&session, "T_ROB1"), line_of(ROBOT, "MoveJ p10"));
    // Nothing runs while the program is stopped.
    assert_eq!(session.run(100), RunOutcome::Stopped);
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "5");
    assert!(matches!(session.stop(StopKind::Stop), Err(ApiError::WrongState(_))));
    let names: Vec<String> = session.tasks().into_iter().map(|t| t.name).collect();
    assert_eq!(names, ["T_ROB1", "T_OTHER"]);
}

#[test]
fn a_stop_in_the_middle_of_a_move_holds_the_robot_and_the_program_pointer() {
    let mut session = session();
    let move_l = line_of(ROBOT, "MoveL p20");
    assert!(session.start(StartFrom::Pointer).is_ok());
    run_to_line(&mut session, move_l);
    // The PP comes to the MoveL as it starts (the MoveJ's fine point reached). Its
    // 100 mm at v100 take 1.06 s (rapid-cli tests/path.rs: 1.01 s and 0.05 s of
    // settling): 0.5 s later the robot is about half-way, and it ends at x = 400.
    let until = session.time() + 0.5;
    assert_eq!(session.run_until(Until::Time(until), 1_000_000), RunOutcome::Running);
    assert!(session.stop(StopKind::Stop).is_ok());
    assert_eq!(session.program_state(), ProgramState::Stopped);
    assert_eq!(pp_line(&session, "T_ROB1"), move_l, "the PP stays on the move");
    let stopped_at = tcp_x(&mut session);
    // 0.01 s of acceleration to 100 mm/s (0.5 mm), then 0.49 s at 100 mm/s (49 mm):
    // x ≈ 349.5, give or take where in the round the move started.
    assert!(stopped_at > 340.0 && stopped_at < 360.0, "half-way from p10 to p20: {stopped_at}");
    // Time passes; the robot stands and the program pointer does not move.
    let later = session.time() + 1.0;
    assert_eq!(session.run_until(Until::Time(later), 1_000_000), RunOutcome::Running);
    assert!(session.time() >= later);
    assert!((tcp_x(&mut session) - stopped_at).abs() < 1e-6);
    assert_eq!(pp_line(&session, "T_ROB1"), move_l);
    // Started again, the move goes on to p20; main ends with reg1 = 5 * 2 + 100 + 1.
    assert!(session.start(StartFrom::Pointer).is_ok());
    let ended = session.run_until(Until::Steps(100_000), 100_000);
    assert_eq!(ended, RunOutcome::Running, "T_OTHER still waits for `shared`");
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "111");
    assert_eq!(read(&mut session, "T_ROB1/MainModule/here"), "[400,0,400]");
}

#[test]
fn steps_go_into_over_and_out_of_a_routine() {
    let mut session = session();
    let (call, first, second, after) = (
        line_of(ROBOT, "    Helper;"),
        line_of(ROBOT, "reg1 := reg1 * scale"),
        line_of(ROBOT, "reg1 := reg1 + 100"),
        line_of(ROBOT, "reg1 := reg1 + 1"),
    );
    // Over the MoveJ and the MoveL: each step is one statement (the move with its wait).
    for expected in [line_of(ROBOT, "MoveL p20"), call] {
        assert!(session.step("T_ROB1", StepKind::Over).is_ok());
        finish_step(&mut session);
        assert_eq!(pp_line(&session, "T_ROB1"), expected);
    }
    // The other task did not run during the steps: it still stands at its first statement.
    assert_eq!(pp_line(&session, "T_OTHER"), line_of(api_common::OTHER, "WaitUntil"));
    assert!(matches!(session.step("T_ROB1", StepKind::Out), Err(ApiError::Refused(_))));
    // Into Helper: its first statement, main's frame below it at the call.
    assert!(session.step("T_ROB1", StepKind::Into).is_ok());
    finish_step(&mut session);
    let stack = session.call_stack("T_ROB1").unwrap_or_default();
    let frames: Vec<(String, u32)> = stack.iter().map(|f| (f.at.routine.clone(), f.at.line)).collect();
    assert_eq!(frames, [("Helper".to_owned(), first), ("main".to_owned(), call)]);
    assert_eq!(stack[0].at.file, FILE);
    // Helper's routine data, main has none.
    assert_eq!(session.frame_locals("T_ROB1", 0), Ok(vec![("scale".to_owned(), "2".to_owned())]));
    assert_eq!(session.frame_locals("T_ROB1", 1), Ok(Vec::new()));
    assert!(matches!(session.frame_locals("T_ROB1", 2), Err(ApiError::NotFound(_))));
    assert!(session.step("T_ROB1", StepKind::Over).is_ok());
    finish_step(&mut session);
    assert_eq!(pp_line(&session, "T_ROB1"), second);
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "10");
    // Out: Helper's last statement runs (10 + 100) and the PP is back in main.
    assert!(session.step("T_ROB1", StepKind::Out).is_ok());
    finish_step(&mut session);
    assert_eq!(pp_line(&session, "T_ROB1"), after);
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "110");
    assert_eq!(session.call_stack("T_ROB1").map(|s| s.len()), Ok(1));
}

#[test]
fn a_step_backward_runs_the_backward_handler_and_refuses_a_move() {
    let mut session = session();
    let call = line_of(ROBOT, "    Helper;");
    for _ in 0..3 {
        assert!(session.step("T_ROB1", StepKind::Over).is_ok());
        finish_step(&mut session);
    }
    assert_eq!(pp_line(&session, "T_ROB1"), line_of(ROBOT, "reg1 := reg1 + 1"));
    // Backward over `Helper;`: Helper's BACKWARD handler runs (bwd 0 → 1) and the
    // PP stands on the call again (§1.21); reg1 keeps what Helper made of it.
    assert_eq!(session.step_backward("T_ROB1"), Ok(rapid_vm::BackStep::RanBackwardHandler("Helper".to_owned())));
    assert_eq!(pp_line(&session, "T_ROB1"), call);
    assert_eq!(read(&mut session, "T_ROB1/MainModule/bwd"), "1");
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "110");
    // Backward over the MoveL would move the robot back: not supported yet.
    assert!(matches!(session.step_backward("T_ROB1"), Err(ApiError::Unsupported(_))));
    assert_eq!(pp_line(&session, "T_ROB1"), call);
}

#[test]
fn a_breakpoint_stops_the_program_before_its_statement() {
    let mut session = session();
    let first = line_of(ROBOT, "reg1 := reg1 * scale");
    let sub = session.subscribe();
    let at = session.set_breakpoint("MainModule.mod", first).unwrap_or_default();
    assert_eq!(at.len(), 1);
    assert_eq!((at[0].task.as_str(), at[0].routine.as_str(), at[0].line), ("T_ROB1", "Helper", first));
    // A line with no statement starting on it (the BACKWARD keyword) is no place.
    let backward = line_of(ROBOT, "BACKWARD");
    assert!(matches!(session.set_breakpoint("MainModule.mod", backward), Err(ApiError::NotFound(_))));
    assert!(session.start(StartFrom::Pointer).is_ok());
    let hit = match session.run_until(Until::Stopped, 1_000_000) {
        RunOutcome::Breakpoint(hit) => hit,
        other => panic!("no breakpoint hit: {other:?}"),
    };
    assert_eq!((hit.at.task.as_str(), hit.at.line, hit.line), ("T_ROB1", first, first));
    assert_eq!(session.program_state(), ProgramState::Stopped);
    // Stopped before the statement: reg1 is still 5.
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "5");
    let stack = session.call_stack("T_ROB1").unwrap_or_default();
    assert_eq!(stack.iter().map(|f| f.at.line).collect::<Vec<_>>(), [first, line_of(ROBOT, "    Helper;")]);
    let changes = session.poll(sub).map(|b| b.changes).unwrap_or_default();
    let breakpoint =
        rapid_controller::api::Change::Breakpoint { task: "T_ROB1".into(), file: "MainModule.mod".into(), line: first };
    assert!(changes.contains(&breakpoint), "{changes:?}");
    let stopped = rapid_controller::api::Change::Execution { state: "Stopped".into() };
    assert!(changes.contains(&stopped), "{changes:?}");
    // Started again, the statement at the breakpoint runs (it is passed once).
    assert!(session.clear_breakpoint("MainModule.mod", first));
    assert!(session.start(StartFrom::Pointer).is_ok());
    assert_eq!(session.run_until(Until::Steps(1000), 1000), RunOutcome::Running);
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "111");
}

#[test]
fn pp_to_main_and_to_a_routine_move_the_program_pointer() {
    let mut session = session();
    let first = line_of(ROBOT, "reg1 := reg1 * scale");
    assert!(session.pp_to_routine("T_ROB1", "Helper").is_ok());
    assert_eq!(pp_line(&session, "T_ROB1"), first);
    assert!(session.start(StartFrom::Pointer).is_ok());
    assert_eq!(session.run_until(Until::Steps(100), 100), RunOutcome::Running);
    // Helper alone ran: 5 * 2 + 100; T_ROB1 has ended, T_OTHER still waits.
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "110");
    assert!(session.stop(StopKind::Stop).is_ok());
    assert!(matches!(session.pp_to_routine("T_ROB1", "NoSuch"), Err(ApiError::NotFound(_))));
    // PP to Main: variables get their initial values again, persistents keep theirs.
    assert!(session.write_data("T_ROB1/MainModule/here", "[7,8,9]").is_ok());
    assert!(session.pp_to_main().is_ok());
    assert_eq!(pp_line(&session, "T_ROB1"), line_of(ROBOT, "MoveJ p10"));
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "5");
    assert_eq!(read(&mut session, "T_ROB1/MainModule/here"), "[7,8,9]");
}

#[test]
fn a_paced_clock_asks_the_caller_to_sleep_and_a_virtual_one_jumps() {
    let program = "MODULE MainModule
  VAR num done := 0;
  PROC main()
    WaitTime 0.5;
    done := 1;
  ENDPROC
ENDMODULE
";
    // Virtual: the 0.5 s wait is jumped over at once.
    let mut session = api_common::with_signals(program, &[], &[]);
    assert!(session.start(StartFrom::Pointer).is_ok());
    let wall = std::time::Instant::now();
    assert_eq!(session.run_until(Until::Steps(10), 10), RunOutcome::Ended);
    assert!(session.time() >= 0.5);
    assert!(wall.elapsed().as_secs_f64() < 0.5);
    // Paced ten times faster than real: the wait takes 0.05 s of wall-clock time, and
    // `run` says how long to sleep instead of sleeping.
    let mut session = api_common::with_signals(program, &[], &[]);
    session.set_clock(rapid_controller::api::ClockPolicy::Paced { rate: 10.0 });
    assert!(session.start(StartFrom::Pointer).is_ok());
    let wall = std::time::Instant::now();
    let mut sleeps = 0;
    let end = loop {
        match session.run(10) {
            RunOutcome::Sleep(d) => {
                assert!(d.as_secs_f64() <= 0.05 + 1e-9, "{d:?}");
                sleeps += 1;
                std::thread::sleep(d);
            }
            RunOutcome::Running => {}
            other => break other,
        }
    };
    assert_eq!(end, RunOutcome::Ended);
    assert!(sleeps >= 1);
    assert!(wall.elapsed().as_secs_f64() >= 0.05 - 0.002, "{:?}", wall.elapsed());
    assert_eq!(read(&mut session, "T_ROB1/MainModule/done"), "1");
}

#[test]
fn a_stop_ends_a_step_over_at_the_next_statement() {
    let mut session = session();
    assert!(session.pp_to_routine("T_ROB1", "main").is_ok());
    for _ in 0..2 {
        assert!(session.step("T_ROB1", StepKind::Over).is_ok());
        finish_step(&mut session);
    }
    assert_eq!(pp_line(&session, "T_ROB1"), line_of(ROBOT, "    Helper;"));
    // Step over the call, but stop after its first statement: the call is entered
    // (one statement run), and the step ends there, inside Helper.
    assert!(session.step("T_ROB1", StepKind::Over).is_ok());
    assert_eq!(session.run(1), RunOutcome::Running);
    assert!(session.stop(StopKind::Stop).is_ok());
    finish_step(&mut session);
    assert_eq!(pp_line(&session, "T_ROB1"), line_of(ROBOT, "reg1 := reg1 * scale"));
    assert_eq!(session.call_stack("T_ROB1").map(|s| s.len()), Ok(2));
}

/// A program of one task runs alone, in slices, as fast as the interpreter; a
/// breakpoint must stop it all the same, before its statement.
#[test]
fn a_breakpoint_stops_a_program_of_one_task() {
    let text = "MODULE MainModule
  VAR num n := 0;
  PROC main()
    FOR i FROM 1 TO 10 DO
      n := n + 1;
    ENDFOR
    n := n + 100;
  ENDPROC
ENDMODULE
";
    let mut session = api_common::with_signals(text, &[], &[]);
    let line = line_of(text, "n := n + 100");
    assert_eq!(session.set_breakpoint("MainModule.mod", line).map(|at| at.len()), Ok(1));
    assert!(session.start(StartFrom::Pointer).is_ok());
    match session.run_until(Until::Stopped, 1_000_000) {
        RunOutcome::Breakpoint(hit) => assert_eq!(hit.at.line, line),
        other => panic!("no breakpoint hit: {other:?}"),
    }
    // The loop ran its ten rounds; the statement at the breakpoint has not run.
    assert_eq!(read(&mut session, "T_ROB1/MainModule/n"), "10");
}
