//! The multitasking built-ins in a system of two tasks, run in process through the
//! controller's API: T_ROB1 (a motion task with a robot) and T_OTHER (no motion task).
//! Each scenario is a pair of RAPID modules and a table of the data each task ends
//! with, worked out by hand from the manual's rules (§1.20; the instructions manual
//! for TestAndSet, WaitTestAndSet, WaitSyncTask, GetTaskName, TaskRunMec, TaskRunRob,
//! TaskIsExecuting, GetTSPStatus).

use rapid_controller::api::{Session, StartFrom, Until};
use rapid_controller::{Controller, TaskSpec};
use rapid_sema::SourceInput;

/// Seconds the controller clock may run past an event before a task notes the time:
/// the statements between, at the scheduler's nominal statement time.
const SLACK: f64 = 0.05;

/// A session on T_ROB1 (motion task) running `rob` and T_OTHER running `other`,
/// started and run until both ended (or 10 s of controller time).
fn run(rob: &str, other: &str) -> Session {
    let options = rapid_sema::Options::default();
    let load = |path: &str, text: &str| match rapid_controller::builtin_set::load_with(
        &[SourceInput::from_text(path, text)],
        "main",
        &options,
    ) {
        Ok(loaded) => loaded,
        Err(err) => panic!("{path} does not load: {err:?}"),
    };
    let tasks = vec![
        (TaskSpec::normal("T_ROB1", true), load("T_ROB1/Rob.mod", rob)),
        (TaskSpec::normal("T_OTHER", false), load("T_OTHER/Other.mod", other)),
    ];
    let mut session = match Controller::new(tasks, None) {
        Ok(controller) => Session::new(controller),
        Err(message) => panic!("{message}"),
    };
    session.start(StartFrom::Pointer).expect("the program starts");
    session.run_until(Until::Time(10.0), 1_000_000);
    assert!(session.all_normal_ended(), "both tasks end within 10 s");
    session
}

/// The value of `path` (`TASK/Module/name`) as a RAPID literal.
fn read(session: &mut Session, path: &str) -> String {
    match session.read_data(path) {
        Ok(data) => data.value,
        Err(err) => panic!("{path}: {err:?}"),
    }
}

/// Checks a table of (data path, literal) the tasks ended with.
fn check(session: &mut Session, table: &[(&str, &str)]) {
    for (path, want) in table {
        assert_eq!(read(session, path), *want, "{path}");
    }
}

/// A time (a num) a task noted, checked to be `at` up to [`SLACK`] later.
fn check_time(session: &mut Session, path: &str, at: f64) {
    let text = read(session, path);
    let Ok(time) = text.parse::<f64>() else { panic!("{path} = {text}, no number") };
    assert!((at..at + SLACK).contains(&time), "{path} = {time}, expected {at} (+ at most {SLACK})");
}

/// TestAndSet takes a free semaphore (a FALSE bool: it becomes TRUE, the answer is
/// TRUE) and refuses a taken one (FALSE, unchanged); WaitTestAndSet waits until the
/// holder frees it, then takes it. The semaphore is a global PERS: one object in both
/// tasks.
#[test]
fn a_semaphore_is_held_by_one_task_at_a_time() {
    let rob = "MODULE Rob
  PERS bool sem := FALSE;
  VAR bool first := FALSE;
  VAR bool again := TRUE;
  PROC main()
    first := TestAndSet(sem);
    again := TestAndSet(sem);
    WaitTime 0.5;
    sem := FALSE;
  ENDPROC
ENDMODULE
";
    let other = "MODULE Other
  PERS bool sem := FALSE;
  VAR bool early := TRUE;
  VAR num got_at := -1;
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitTime 0.1;
    early := TestAndSet(sem);
    WaitTestAndSet sem;
    got_at := ClkRead(c);
  ENDPROC
ENDMODULE
";
    let mut s = run(rob, other);
    check(
        &mut s,
        &[
            // Free at first: T_ROB1 takes it; its second try finds it taken.
            ("T_ROB1/Rob/first", "TRUE"),
            ("T_ROB1/Rob/again", "FALSE"),
            // At 0.1 s T_ROB1 holds it: T_OTHER is refused.
            ("T_OTHER/Other/early", "FALSE"),
            // T_OTHER took it when freed and holds it at the end.
            ("T_OTHER/Other/sem", "TRUE"),
        ],
    );
    // T_ROB1 frees it at 0.5 s: WaitTestAndSet returns then, not before.
    check_time(&mut s, "T_OTHER/Other/got_at", 0.5);
}

/// WaitSyncTask: each task waits at the sync point until every task of the list is
/// there, so both go on when the later one (T_OTHER, at 0.7 s) arrives.
#[test]
fn wait_sync_task_lets_both_tasks_go_on_when_the_last_arrives() {
    let rob = "MODULE Rob
  VAR syncident meet1;
  PERS tasks both{2} := [[\"T_ROB1\"], [\"T_OTHER\"]];
  VAR num passed := -1;
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitTime 0.2;
    WaitSyncTask meet1, both;
    passed := ClkRead(c);
  ENDPROC
ENDMODULE
";
    let other = "MODULE Other
  VAR syncident meet1;
  PERS tasks both{2} := [[\"T_ROB1\"], [\"T_OTHER\"]];
  VAR num passed := -1;
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitTime 0.7;
    WaitSyncTask meet1, both;
    passed := ClkRead(c);
  ENDPROC
ENDMODULE
";
    let mut s = run(rob, other);
    check_time(&mut s, "T_ROB1/Rob/passed", 0.7);
    check_time(&mut s, "T_OTHER/Other/passed", 0.7);
}

/// WaitSyncTask `\TimeOut`: the other task does not come within it (it is still
/// executing a long wait), so ERR_WAITSYNCTASK is raised after the time-out and the
/// handler runs; the task does not wait for the other.
#[test]
fn wait_sync_task_times_out_with_err_waitsynctask() {
    let rob = "MODULE Rob
  VAR syncident meet2;
  PERS tasks both{2} := [[\"T_ROB1\"], [\"T_OTHER\"]];
  VAR bool timed_out := FALSE;
  VAR num at := -1;
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitSyncTask meet2, both \\TimeOut:=0.3;
  ERROR
    IF ERRNO = ERR_WAITSYNCTASK THEN
      timed_out := TRUE;
      at := ClkRead(c);
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
";
    let other = "MODULE Other
  PERS tasks both{2} := [[\"T_ROB1\"], [\"T_OTHER\"]];
  PROC main()
    WaitTime 1;
  ENDPROC
ENDMODULE
";
    let mut s = run(rob, other);
    check(&mut s, &[("T_ROB1/Rob/timed_out", "TRUE")]);
    check_time(&mut s, "T_ROB1/Rob/at", 0.3);
}

/// What each task knows of itself and the other: its name and number (its place in
/// the configuration), whether it runs a mechanical unit (TaskRunMec) or a robot
/// (TaskRunRob), the motion task it is connected to (`\MecTaskNo`: T_ROB1, the only
/// one), whether the other executes (T_ROB1 ends at 0.2 s), and the other's place in
/// the task selection panel (a NORMAL task, selected: TSP_STATUS_ACT).
#[test]
fn each_task_knows_itself_and_the_other() {
    let rob = "MODULE Rob
  VAR string name := \"\";
  VAR num no := 0;
  VAR bool mec := FALSE;
  VAR bool rob := FALSE;
  PROC main()
    name := GetTaskName(\\TaskNo:=no);
    mec := TaskRunMec();
    rob := TaskRunRob();
    WaitTime 0.2;
  ENDPROC
ENDMODULE
";
    let other = "MODULE Other
  VAR string name := \"\";
  VAR num no := 0;
  VAR string motion := \"\";
  VAR num motion_no := 0;
  VAR bool mec := TRUE;
  VAR bool rob := TRUE;
  VAR bool rob1_then := FALSE;
  VAR bool rob1_later := TRUE;
  VAR bool tsp_act := FALSE;
  PROC main()
    name := GetTaskName(\\TaskNo:=no);
    motion := GetTaskName(\\MecTaskNo:=motion_no);
    mec := TaskRunMec();
    rob := TaskRunRob();
    rob1_then := TaskIsExecuting(\"T_ROB1\");
    tsp_act := GetTSPStatus(\"T_ROB1\") = TSP_STATUS_ACT;
    WaitTime 0.5;
    rob1_later := TaskIsExecuting(\"T_ROB1\");
  ENDPROC
ENDMODULE
";
    let mut s = run(rob, other);
    check(
        &mut s,
        &[
            ("T_ROB1/Rob/name", "\"T_ROB1\""),
            ("T_ROB1/Rob/no", "1"),
            ("T_ROB1/Rob/mec", "TRUE"),
            ("T_ROB1/Rob/rob", "TRUE"),
            ("T_OTHER/Other/name", "\"T_OTHER\""),
            ("T_OTHER/Other/no", "2"),
            ("T_OTHER/Other/motion", "\"T_ROB1\""),
            ("T_OTHER/Other/motion_no", "1"),
            ("T_OTHER/Other/mec", "FALSE"),
            ("T_OTHER/Other/rob", "FALSE"),
            ("T_OTHER/Other/rob1_then", "TRUE"),
            ("T_OTHER/Other/rob1_later", "FALSE"),
            ("T_OTHER/Other/tsp_act", "TRUE"),
        ],
    );
}
