//! The controller API's data, signals, pendant and change stream: a persistent written
//! while the program runs is read by the other task, CONSTs are refused, records and
//! arrays are read and written by part as RAPID literals, a prompt waits for the
//! front end's answer, signals are read and set by name. Expected values come from
//! the RAPID rules (worked out in the comments).

mod api_common;

use api_common::{line_of, session, with_signals, OTHER};
use rapid_controller::api::{ApiError, Change, RunOutcome, Session, StartFrom, Until};

fn read(session: &mut Session, path: &str) -> String {
    match session.read_data(path) {
        Ok(data) => data.value,
        Err(err) => panic!("{path}: {err}"),
    }
}

/// Runs until the clock reaches `until`, sleeping as a paced clock asks (while a
/// prompt waits for the operator the clock is the wall clock).
fn run_to(session: &mut Session, until: f64) -> RunOutcome {
    loop {
        match session.run_until(Until::Time(until), 100_000) {
            RunOutcome::Sleep(wall) => std::thread::sleep(wall),
            other => return other,
        }
    }
}

fn pp_line(session: &Session, task: &str) -> u32 {
    match session.program_pointer(task) {
        Ok(Some(at)) => at.line,
        other => panic!("no program pointer for {task}: {other:?}"),
    }
}

#[test]
fn data_reads_and_writes_as_rapid_literals_by_name_and_part() {
    let mut session = session();
    let data = session.read_data("T_ROB1/MainModule/here");
    assert_eq!(data.as_ref().map(|d| (d.value.as_str(), d.type_name.as_str(), d.kind)), Ok(("[1,2,3]", "pos", "PERS")));
    assert_eq!(read(&mut session, "T_ROB1/name"), "\"abc\"");
    assert_eq!(read(&mut session, "t_rob1/mainmodule/ARR{2}"), "2");
    assert_eq!(read(&mut session, "T_ROB1/MainModule/p10.trans.x"), "300");
    // A component, an element, a string, a whole array.
    assert_eq!(session.write_data("T_ROB1/MainModule/here.y", "20"), Ok(()));
    assert_eq!(read(&mut session, "T_ROB1/MainModule/here"), "[1,20,3]");
    assert_eq!(session.write_data("T_ROB1/MainModule/arr{3}", "-4.5"), Ok(()));
    assert_eq!(session.write_data("T_ROB1/MainModule/name", "\"say \"\"hi\"\"\""), Ok(()));
    assert_eq!(read(&mut session, "T_ROB1/MainModule/name"), "\"say \"\"hi\"\"\"");
    assert_eq!(read(&mut session, "T_ROB1/MainModule/arr"), "[1,2,-4.5]");
    // RAPID's rules: a CONST is not written; a literal must be of the datum's type.
    assert!(matches!(session.write_data("T_ROB1/MainModule/limit", "4"), Err(ApiError::ReadOnly(_))));
    assert!(matches!(session.write_data("T_ROB1/MainModule/reg1", "\"abc\""), Err(ApiError::BadLiteral(_))));
    assert!(matches!(session.write_data("T_ROB1/MainModule/here", "[1,2]"), Err(ApiError::BadLiteral(_))));
    let long = format!("\"{}\"", "x".repeat(81));
    assert!(matches!(session.write_data("T_ROB1/MainModule/name", &long), Err(ApiError::BadLiteral(_))));
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "5");
    assert!(matches!(session.read_data("T_ROB1/MainModule/nothing"), Err(ApiError::NotFound(_))));
    assert!(matches!(session.read_data("T_ROB1/MainModule/arr{4}"), Err(ApiError::BadPath(_))));
    assert!(matches!(session.read_data("T_ROB1/MainModule/reg1.x"), Err(ApiError::BadPath(_))));
    assert!(matches!(session.read_data("T_NONE/reg1"), Err(ApiError::NotFound(_))));
    let listed = session.list_data("T_OTHER").unwrap_or_default();
    let names: Vec<(&str, &str)> = listed.iter().map(|d| (d.name.as_str(), d.kind)).collect();
    assert_eq!(names, [("shared", "PERS"), ("got", "VAR"), ("key", "VAR")]);
}

#[test]
fn a_persistent_written_while_running_is_read_by_the_other_task_and_a_prompt_waits_for_its_answer() {
    let mut session = session();
    let sub = session.subscribe();
    assert_eq!(session.start(StartFrom::Pointer), Ok(()));
    // T_OTHER waits until `shared` > 0; T_ROB1 moves meanwhile.
    assert_eq!(session.run_until(Until::Time(0.2), 100_000), RunOutcome::Running);
    assert_eq!(pp_line(&session, "T_OTHER"), line_of(OTHER, "WaitUntil"));
    assert_eq!(session.write_data("T_ROB1/MainModule/shared", "7"), Ok(()));
    // The other task declares the same global PERS: one object (§1.20).
    assert_eq!(read(&mut session, "T_OTHER/Other/shared"), "7");
    assert_eq!(run_to(&mut session, 0.5), RunOutcome::Running);
    assert_eq!(read(&mut session, "T_OTHER/Other/got"), "7");
    // Its TPReadFK now waits for the operator: a prompt; the task stands on it while
    // time passes and the other task runs on. With an operator in the loop the clock
    // is the wall clock: `run` asks the caller to sleep rather than blocking it.
    let prompts = session.prompts();
    assert_eq!(prompts.len(), 1);
    assert_eq!((prompts[0].task.as_str(), prompts[0].text.as_str()), ("T_OTHER", "Continue?"));
    assert!(matches!(session.run_until(Until::Time(1.6), 100_000), RunOutcome::Sleep(_)));
    let wall = std::time::Instant::now();
    let before = session.time();
    assert_eq!(run_to(&mut session, 1.6), RunOutcome::Running);
    // The clock moved no faster than the wall clock (50 ms of slack for the statements'
    // nominal time, which is not paced).
    let moved = session.time() - before;
    assert!(wall.elapsed().as_secs_f64() >= moved - 0.05, "{moved} s of clock in {:?}", wall.elapsed());
    assert_eq!(pp_line(&session, "T_OTHER"), line_of(OTHER, "TPReadFK"));
    assert_eq!(session.prompts().len(), 1, "one prompt, however often the dialog looks");
    // T_ROB1 ran to its end meanwhile: 5 * 2 + 100 + 1.
    assert_eq!(read(&mut session, "T_ROB1/MainModule/reg1"), "111");
    // Answered "No", the second function key: key = 2, written on the pendant.
    assert!(matches!(session.answer(prompts[0].id + 1, "No"), Err(ApiError::NotFound(_))));
    assert_eq!(session.answer(prompts[0].id, "No"), Ok(()));
    assert_eq!(session.run_until(Until::Steps(100), 100), RunOutcome::Ended);
    assert_eq!(read(&mut session, "T_OTHER/Other/key"), "2");
    assert_eq!(session.tp_screen(), ["key 2"]);
    assert!(session.prompts().is_empty());
    let changes = session.poll(sub).map(|b| b.changes).unwrap_or_default();
    let id = prompts[0].id;
    let expected = [
        Change::Execution { state: "Running".into() },
        Change::Persistent { name: "shared".into(), value: "7".into() },
        Change::PromptOpened { id, task: "T_OTHER".into(), text: "Continue?".into() },
        Change::PromptAnswered { id, answer: "No".into() },
        Change::TpWrite { text: "key 2".into() },
        Change::Task { task: "T_OTHER".into(), state: "ended".into() },
    ];
    // In this order, among the others (task states, event-log entries).
    let mut at = 0;
    for change in &changes {
        if at < expected.len() && *change == expected[at] {
            at += 1;
        }
    }
    assert_eq!(at, expected.len(), "{changes:?}");
}

#[test]
fn signals_are_read_and_set_by_name_and_streamed() {
    let program = "MODULE MainModule
  PROC main()
    WaitDI diStart, 1;
    SetDO doDone, 1;
  ENDPROC
ENDMODULE
";
    let mut session = with_signals(program, &["diStart"], &["doDone"]);
    let sub = session.subscribe();
    assert_eq!(session.start(StartFrom::Pointer), Ok(()));
    assert_eq!(session.run_until(Until::Time(1.0), 10_000), RunOutcome::Running);
    assert_eq!(session.signal("doDone"), Ok(0.0));
    assert_eq!(session.set_signal("diStart", 1.0), Ok(()));
    assert_eq!(session.run_until(Until::Steps(100), 100), RunOutcome::Ended);
    assert_eq!(session.signal("doDone"), Ok(1.0));
    assert!(matches!(session.signal("diNone"), Err(ApiError::NotFound(_))));
    // A digital input is 0 or 1 (an output order of 2 would be taken as 1, as SetDO does).
    assert!(matches!(session.set_signal("diStart", 2.0), Err(ApiError::Refused(_))));
    let signals: Vec<(String, f64)> = session
        .poll(sub)
        .map(|b| b.changes)
        .unwrap_or_default()
        .into_iter()
        .filter_map(|c| match c {
            Change::Signal { name, value, .. } => Some((name, value)),
            _ => None,
        })
        .collect();
    assert_eq!(signals, [("diStart".to_owned(), 1.0), ("doDone".to_owned(), 1.0)]);
}

#[test]
fn a_slow_subscriber_is_told_what_it_missed() {
    let mut session = session();
    let sub = session.subscribe();
    // Each write of a shared persistent is one change: 10 001 of them overflow the
    // stream's 10 000 places by one.
    for n in 1..=10_001 {
        assert_eq!(session.write_data("T_ROB1/MainModule/shared", &n.to_string()), Ok(()));
    }
    let batch = session.poll(sub).unwrap_or_default();
    assert_eq!(batch.dropped, 1);
    assert_eq!(batch.changes.len(), 10_000);
    assert_eq!(batch.changes.first(), Some(&Change::Persistent { name: "shared".into(), value: "2".into() }));
}

#[test]
fn a_prompt_nobody_answers_times_out_after_its_max_time() {
    let program = "MODULE MainModule
  VAR num n := 0;
  VAR bool timedout := FALSE;
  PROC main()
    TPReadNum n, \"How many?\" \\MaxTime:=0.2;
  ERROR
    timedout := ERRNO = ERR_TP_MAXTIME;
    TRYNEXT;
  ENDPROC
ENDMODULE
";
    let mut session = with_signals(program, &[], &[]);
    let sub = session.subscribe();
    assert_eq!(session.start(StartFrom::Pointer), Ok(()));
    assert!(matches!(session.run_until(Until::Time(1.0), 10_000), RunOutcome::Sleep(_)));
    assert_eq!(session.prompts().len(), 1);
    // \MaxTime 0.2 s from the dialog's start: ERR_TP_MAXTIME, which the handler takes.
    assert_eq!(run_to(&mut session, 1.0), RunOutcome::Ended);
    assert!(session.time() >= 0.2 && session.time() < 0.3, "{}", session.time());
    assert_eq!(read(&mut session, "T_ROB1/MainModule/timedout"), "TRUE");
    assert_eq!(read(&mut session, "T_ROB1/MainModule/n"), "0");
    assert!(session.prompts().is_empty());
    let changes = session.poll(sub).map(|b| b.changes).unwrap_or_default();
    assert!(changes.contains(&Change::PromptClosed { id: 1 }), "{changes:?}");
}
