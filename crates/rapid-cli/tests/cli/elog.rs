//! `rapid run --elog FILE`: the event log as JSON lines (docs/elog.md), written when
//! the run ends however it ends. The expected entries are worked out by hand from the
//! program: what each instruction logs (ErrWrite, ErrLog, ErrRaise, a handled error's
//! warning, SkipWarn, the system error handler's entry), at which controller time and
//! at which statement.

use std::fs;
use std::path::Path;
use std::process::Output;

use serde_json::{json, Value};

use crate::fixture::{rapid_in, scratch_in, Scratch};

/// A fresh, empty scratch folder for one test.
fn fresh_dir(name: &str) -> Scratch {
    scratch_in("elog", name)
}

/// Runs `rapid run --elog log.jsonl ARGS… m.mod` in `dir` (so entries name `m.mod`).
fn run(dir: &Path, program: &str, args: &[&str]) -> Output {
    fs::write(dir.join("m.mod"), program).expect("write module");
    let mut all = vec!["run", "--elog", "log.jsonl"];
    all.extend_from_slice(args);
    all.push("m.mod");
    rapid_in(dir, &all)
}

/// The file's lines, each parsed; every line must be one JSON object.
fn entries(dir: &Path) -> Vec<Value> {
    let text = fs::read_to_string(dir.join("log.jsonl")).expect("the log was written");
    assert!(text.is_empty() || text.ends_with('\n'), "the last line is not ended");
    text.lines().map(|l| serde_json::from_str::<Value>(l).expect("a JSON object per line")).collect()
}

/// The entries the program logged: all but the controller's own state changes
/// (operational domain 1: the program started and stopped, seq 0, 1 and the last).
fn program_entries(dir: &Path) -> Vec<Value> {
    entries(dir).into_iter().filter(|e| e["domain"] != 1).collect()
}

/// `entry` without its title (compared separately: the program domain's titles are
/// the VM's error messages).
fn without_title(entry: &Value) -> Value {
    let mut entry = entry.clone();
    entry.as_object_mut().expect("an object").remove("title");
    entry
}

const PROGRAM: &str = "\
MODULE m
  VAR errnum ERR_GRIP := -1;
  PROC main()
    VAR num z := 0;
    BookErrNo ERR_GRIP;
    TPWrite \"\" \\Num:=ERR_DIVZERO;
    TPWrite \"\" \\Num:=ERR_GRIP;
    ErrWrite \"Gripper\", \"no part\" \\RL2:=\"line 2\";
    WaitTime 1.5;
    ErrLog 4800 \\I, \"Cycle\", \"started\", ERRSTR_TASK, ERRSTR_UNUSED, ERRSTR_UNUSED;
    check;
    WaitTime 0.25;
    reg1 := 1 / z;
  ENDPROC
  PROC check()
    VAR num z := 0;
    reg2 := 2 / z;
    ErrRaise \"ERR_GRIP\", 4801, \"Grip lost\", \"at station 3\", ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
  ERROR
    IF ERRNO = ERR_GRIP SkipWarn;
    TRYNEXT;
  ENDPROC
ENDMODULE
";

#[test]
fn every_entry_with_time_task_routine_and_place() {
    let dir = fresh_dir("entries");
    let out = run(&dir, PROGRAM, &[]);
    // The unhandled division by zero stops the program: exit 1, and the log is written.
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    // The first two pendant lines are the error numbers (ErrWrite's lines follow).
    let numbers: Vec<u64> = stdout.lines().take(2).map(|l| l.trim().parse().expect("a number")).collect();
    let [divzero, grip] = numbers[..] else { panic!("two numbers expected: {stdout}") };

    let place = |routine: &str, line: u32| json!({"routine": routine, "file": "m.mod", "line": line, "column": 5});
    let entry = |seq: u64, time: f64, domain: u64, number: u64, kind: &str, description: Value, at: Value| {
        let mut e = json!({
            "seq": seq, "time": time, "task": "T_ROB1", "domain": domain, "number": number,
            "code": domain * 10_000 + number, "type": kind, "description": description,
        });
        let fields = e.as_object_mut().expect("an object");
        for (k, v) in at.as_object().expect("an object") {
            fields.insert(k.clone(), v.clone());
        }
        e
    };
    let expected = [
        // ErrWrite: user domain (8), number 1 for an error; header as title.
        // (seq 0 and 1 are the controller's: program pointer reset, program started.)
        entry(2, 0.0, 8, 1, "error", json!(["no part", "line 2"]), place("main", 8)),
        // ErrLog \I after 1.5 s: ERRSTR_TASK is the task's name, unused arguments dropped.
        entry(3, 1.5, 8, 4800, "info", json!(["started", "T_ROB1"]), place("main", 10)),
        // The division by zero check's handler takes: a warning in the program domain (4).
        entry(4, 1.5, 4, divzero, "warning", json!(["routine check"]), place("check", 17)),
        // ErrRaise logs its message, then raises ERR_GRIP ...
        entry(5, 1.5, 8, 4801, "error", json!(["at station 3"]), place("check", 18)),
        // ... whose warning (seq 6) SkipWarn takes out of the log; then main's division
        // by zero after another 0.25 s reaches the system error handler: an error.
        entry(7, 1.75, 4, divzero, "error", json!(["routine main"]), place("main", 13)),
    ];
    let got = program_entries(&dir);
    assert_eq!(got.len(), expected.len(), "{got:#?}");
    for (got, expected) in got.iter().zip(&expected) {
        assert_eq!(&without_title(got), expected);
    }
    let titles: Vec<&str> = got.iter().map(|e| e["title"].as_str().expect("a title")).collect();
    assert_eq!(titles[0], "Gripper");
    assert_eq!(titles[1], "Cycle");
    assert!(titles[2].contains("ERR_DIVZERO"), "{}", titles[2]);
    assert_eq!(titles[3], "Grip lost");
    assert!(titles[4].contains("ERR_DIVZERO"), "{}", titles[4]);
    assert_ne!(grip, divzero);
    // --elog leaves --event-log alone: nothing on stderr but the error report.
    assert!(!String::from_utf8_lossy(&out.stderr).contains("event "));
}

#[test]
fn written_when_the_run_is_stopped_by_max_steps() {
    let dir = fresh_dir("max-steps");
    let program = "MODULE m\n  PROC main()\n    ErrWrite \\W, \"Looping\", \"forever\";\n    WHILE TRUE DO\n      reg1 := reg1 + 1;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n";
    let out = run(&dir, program, &["--max-steps", "1000"]);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let expected = json!({
        "seq": 2, "time": 0.0, "task": "T_ROB1", "domain": 8, "number": 2, "code": 80002, "type": "warning",
        "title": "Looping", "description": ["forever"], "routine": "main", "file": "m.mod", "line": 3, "column": 5,
    });
    assert_eq!(program_entries(&dir), [expected]);
}

#[test]
fn a_quiet_run_logs_its_start_and_stop_and_nothing_else_is_left() {
    let dir = fresh_dir("empty");
    let out = run(&dir, "MODULE m\n  PROC main()\n    TPWrite \"quiet\";\n  ENDPROC\nENDMODULE\n", &[]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(program_entries(&dir).is_empty());
    // The controller's state changes (operational domain 1): PP to main, started, stopped.
    let state = |seq: u64, number: u64, title: &str, line: &str| {
        json!({"seq": seq, "time": 0.0, "task": "T_ROB1", "domain": 1, "number": number, "code": 10_000 + number,
               "type": "info", "title": title, "description": [line], "routine": null, "file": null, "line": null,
               "column": null})
    };
    assert_eq!(
        entries(&dir),
        [
            state(
                0,
                2,
                "Program pointer has been reset",
                "The program pointer of task T_ROB1 was set to its entry routine."
            ),
            state(1, 150, "Program started", "Program execution in task T_ROB1 has been started."),
            state(2, 151, "Program stopped", "Program execution in task T_ROB1 has stopped: the program ended."),
        ]
    );
    let mut names: Vec<String> = fs::read_dir(&dir)
        .expect("read")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["log.jsonl", "m.mod"]);
}

#[test]
fn an_entry_from_a_module_loaded_at_run_time_names_its_rapid_path() {
    let dir = fresh_dir("loaded");
    fs::create_dir_all(dir.join("home").join("HOME")).expect("HOME device");
    fs::write(
        dir.join("home").join("HOME").join("tool.mod"),
        "MODULE tool\n  PROC tool_use()\n    WaitTime 0.5;\n    ErrWrite \\I, \"Tool used\", \"again\";\n  ENDPROC\nENDMODULE\n",
    )
    .expect("write module");
    let program = "MODULE m\n  PROC main()\n    Load \"HOME:/tool.mod\";\n    %\"tool_use\"%;\n  ENDPROC\nENDMODULE\n";
    let out = run(&dir, program, &["--home", "home"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // ErrWrite \I: user domain, number 3, at line 4 of the loaded module, after 0.5 s.
    let expected = json!({
        "seq": 2, "time": 0.5, "task": "T_ROB1", "domain": 8, "number": 3, "code": 80003, "type": "info",
        "title": "Tool used", "description": ["again"], "routine": "tool_use", "file": "HOME:/tool.mod",
        "line": 4, "column": 5,
    });
    assert_eq!(program_entries(&dir), [expected]);
}

#[test]
fn corner_path_failures_are_logged_at_their_moves_unless_warnings_are_off() {
    // Line 4's fly-by point waits through WaitTime: it is run as a stop point, and the
    // next move (line 6) finds it so: a warning at line 4. Line 6's point fails the
    // same way while CornerPathWarning is FALSE: counted, not logged. Line 9's point is
    // met in time. The program ends on line 11's fly-by point: a warning at line 11.
    let program = "MODULE m\n  PROC main()\n    MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    \
                   MoveL Offs(CRobT(), 0, 50, 0), v1000, z10, tool0;\n    WaitTime 0.5;\n    \
                   MoveL Offs(CRobT(), 0, 50, 0), v1000, z10, tool0;\n    CornerPathWarning FALSE;\n    \
                   WaitTime 0.5;\n    MoveL Offs(CRobT(), 0, -50, 0), v1000, z10, tool0;\n    \
                   CornerPathWarning TRUE;\n    MoveL Offs(CRobT(), 0, -50, 0), v1000, z10, tool0;\n  ENDPROC\nENDMODULE\n";
    let dir = fresh_dir("corner_path_failures");
    let out = run(&dir, program, &[]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("3 corner path failure(s)"));
    let logged: Vec<Value> = program_entries(&dir).into_iter().filter(|e| e["code"] == 50024).collect();
    let places: Vec<(Value, Value, Value, Value)> = logged
        .iter()
        .map(|e| (e["type"].clone(), e["title"].clone(), e["routine"].clone(), e["line"].clone()))
        .collect();
    let warning = |line: u64| (json!("warning"), json!("Corner path failure"), json!("main"), json!(line));
    assert_eq!(places, vec![warning(4), warning(11)]);
    // Line 4's failure is found when line 6 gives the next move, after the 0.5 s wait.
    assert!(logged[0]["time"].as_f64().expect("time") > 0.5);
}

#[test]
fn a_motion_error_is_logged_in_the_motion_domain() {
    let dir = fresh_dir("motion_domain");
    // 2.4 m away is beyond the IRB 120's reach: the motion system reports 50050
    // "Position outside reach" (domain 5, number 50), not a program error 4xxxx.
    let program = "MODULE M\n  PROC main()\n    \
                   MoveL [[2400,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v500, fine, tool0;\n  \
                   ENDPROC\nENDMODULE\n";
    let out = run(&dir, program, &["--quiet"]);
    assert_eq!(out.status.code(), Some(1));
    let found: Vec<Value> = program_entries(&dir);
    let reach = found.iter().find(|e| e["code"] == json!(50050)).unwrap_or_else(|| panic!("{found:?}"));
    assert_eq!((&reach["domain"], &reach["number"]), (&json!(5), &json!(50)), "{reach}");
    assert!(reach["title"].as_str().is_some_and(|t| t.contains("Position outside reach")), "{reach}");
}
