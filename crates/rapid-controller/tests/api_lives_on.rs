//! A controller that lives on after the program's cycle (a served one,
//! `Session::set_lives_on`): the end of every NORMAL task stops the program, a
//! SEMISTATIC task runs on, and PP to Main and a start run the cycle again — as
//! abb-motion-program-exec's logger task needs. Without it (`rapid run`) the run ends
//! there and the static task is halted.

use rapid_controller::api::{Session, StartFrom, Until};
use rapid_controller::{Controller, ProgramState, TaskKind, TaskSpec};
use rapid_sema::SourceInput;

const ROBOT: &str = "MODULE MainModule\n  PROC main()\n    WaitTime 0.1;\n  ENDPROC\nENDMODULE\n";

/// Counts its loops for ever: one every 0.05 s of controller time.
const LOGGER: &str = "MODULE Logger
  PERS num loops := 0;
  PROC main()
    WHILE TRUE DO
      loops := loops + 1;
      WaitTime 0.05;
    ENDWHILE
  ENDPROC
ENDMODULE
";

fn session(lives_on: bool) -> Session {
    let options = rapid_sema::Options::default();
    let load = |path: &str, text: &str| match rapid_controller::builtin_set::load_with(
        &[SourceInput::from_text(path, text)],
        "main",
        &options,
    ) {
        Ok(loaded) => loaded,
        Err(err) => panic!("{path} does not load: {err:?}"),
    };
    let mut logger = TaskSpec::normal("LOGGER", false);
    logger.kind = TaskKind::SemiStatic;
    let tasks = vec![
        (TaskSpec::normal("T_ROB1", true), load("T_ROB1/MainModule.mod", ROBOT)),
        (logger, load("LOGGER/Logger.mod", LOGGER)),
    ];
    let mut s = match Controller::new(tasks, None) {
        Ok(controller) => Session::new(controller),
        Err(message) => panic!("{message}"),
    };
    s.set_lives_on(lives_on);
    s.set_cycles(1);
    s
}

fn state_of(s: &Session, task: &str) -> String {
    s.tasks().into_iter().find(|t| t.name == task).map(|t| t.state).unwrap_or_default()
}

fn loops(s: &mut Session) -> f64 {
    let value = s.read_data("LOGGER/Logger/loops").expect("loops").value;
    value.parse().unwrap_or_else(|_| panic!("loops = {value}"))
}

#[test]
fn the_cycle_end_stops_the_program_and_the_static_task_runs_on() {
    let mut s = session(true);
    s.start(StartFrom::Pointer).expect("starts");
    s.run_until(Until::Time(1.0), 1_000_000);
    assert!(s.all_normal_ended());
    assert_eq!(s.program_state(), ProgramState::Stopped);
    assert_eq!(state_of(&s, "LOGGER"), "active");
    // PP to Main and a start: the cycle runs again, the logger never stopped.
    let before = loops(&mut s);
    assert!(before >= 2.0, "the logger looped while T_ROB1 waited 0.1 s: {before}");
    s.pp_to_main().expect("PP to Main after the cycle");
    assert_eq!(state_of(&s, "T_ROB1"), "active");
    assert_eq!(s.program_state(), ProgramState::Stopped, "PP to Main does not start the program");
    s.start(StartFrom::Pointer).expect("starts again");
    assert_eq!(s.program_state(), ProgramState::Running);
    let started = s.time();
    s.run_until(Until::Time(started + 1.0), 1_000_000);
    assert!(s.all_normal_ended());
    assert_eq!(s.program_state(), ProgramState::Stopped);
    assert_eq!(state_of(&s, "LOGGER"), "active");
    // The second cycle (0.1 s) gave the logger at least two more loops.
    assert!(loops(&mut s) >= before + 2.0, "{} after {before}", loops(&mut s));
}

#[test]
fn without_it_the_run_ends_with_the_cycle_and_halts_the_static_task() {
    let mut s = session(false);
    s.start(StartFrom::Pointer).expect("starts");
    s.run_until(Until::Time(1.0), 1_000_000);
    assert!(s.all_normal_ended());
    assert_eq!(state_of(&s, "LOGGER"), "ended: halted");
}
