//! The controller API's one run loop: a step over a waiting statement, the clock
//! policies, a run that can no longer progress. Expected values are worked out from
//! the RAPID rules in the comments.

mod api_common;

use api_common::line_of;
use rapid_controller::api::{RunOutcome, Session, StartFrom, StepKind, Until};
use rapid_controller::{Bound, ProgramState, RunBounds, WallClock};
use rapid_vm::RecordingHost;

fn pp_line(session: &Session) -> u32 {
    match session.program_pointer("T_ROB1") {
        Ok(Some(at)) => at.line,
        other => panic!("no program pointer: {other:?}"),
    }
}

fn read(session: &mut Session, path: &str) -> String {
    match session.read_data(path) {
        Ok(data) => data.value,
        Err(err) => panic!("{path}: {err}"),
    }
}

const WAITS: &str = "MODULE MainModule
  VAR num n := 0;
  PROC main()
    n := 1;
    WaitDI di1, 1;
    n := 2;
  ENDPROC
ENDMODULE
";

#[test]
fn a_step_over_a_wait_stops_at_the_wait() {
    let mut session = api_common::with_signals(WAITS, &["di1"], &[]);
    assert!(session.step("T_ROB1", StepKind::Over).is_ok());
    assert_eq!(session.run_until(Until::Stopped, 1_000_000), RunOutcome::Stopped);
    assert_eq!(pp_line(&session), line_of(WAITS, "WaitDI"));
    // di1 is 0: the step over the WaitDI waits for it; a second of controller time
    // later the task still stands at the wait, the statement after it not run.
    assert!(session.step("T_ROB1", StepKind::Over).is_ok());
    assert_eq!(session.run_until(Until::Time(1.0), 1_000_000), RunOutcome::Running);
    assert!(matches!(session.program_state(), ProgramState::Stepping { .. }));
    assert_eq!(read(&mut session, "T_ROB1/MainModule/n"), "1");
    assert_eq!(pp_line(&session), line_of(WAITS, "WaitDI"));
    // di1 rises: the wait ends and the step stops at the next statement, not run.
    assert!(session.set_signal("di1", 1.0).is_ok());
    assert_eq!(session.run_until(Until::Stopped, 1_000_000), RunOutcome::Stopped);
    assert_eq!(pp_line(&session), line_of(WAITS, "n := 2"));
    assert_eq!(read(&mut session, "T_ROB1/MainModule/n"), "1");
    assert_eq!(session.program_state(), ProgramState::Stopped);
}

/// A wall clock that jumps: never paced.
struct Jumps;

impl WallClock for Jumps {
    fn wait(&mut self, _rate: Option<f64>, _from: f64, to: f64, _limit: f64) -> f64 {
        to
    }

    fn interrupted(&self) -> bool {
        false
    }
}

#[test]
fn a_closed_run_waiting_for_an_input_nothing_sets_is_stuck() {
    // Started, the task sets n and waits for di1, which nothing in the system sets.
    let mut session = api_common::with_signals(WAITS, &["di1"], &[]);
    assert!(session.start(StartFrom::Pointer).is_ok());
    let mut host = RecordingHost::default();
    let closed = RunBounds { closed: true, ..RunBounds::default() };
    assert_eq!(session.run_to_end(&mut host, &mut Jumps, closed), Some(Bound::Stuck));
    let waits = session.controller().stuck_waits();
    assert_eq!(waits.len(), 1);
    assert_eq!((waits[0].line, waits[0].since), (line_of(WAITS, "WaitDI"), 0.0));
    assert_eq!((waits[0].statement.as_str(), waits[0].why.as_str()), ("WaitDI di1, 1", "di1 is 0"));
    // A front end may still set di1: an open run is bounded by its time only, and
    // the clock stops at the bound, not at the wait's next look an hour later.
    let open = RunBounds { max_time: Some(10.0), ..RunBounds::default() };
    assert_eq!(session.run_to_end(&mut host, &mut Jumps, open), Some(Bound::Time(10.0)));
    assert_eq!(session.time(), 10.0);
    assert!(session.set_signal("di1", 1.0).is_ok());
    assert_eq!(session.run_to_end(&mut host, &mut Jumps, closed), None);
    assert_eq!(read(&mut session, "T_ROB1/MainModule/n"), "2");
}
