//! Where `rapid run` reports an error that no ERROR handler handled: at the statement
//! that raised it last (manual §1.12: the system error handler "puts the program
//! pointer at the erroneous instruction"), not at the outermost call it propagated to.
//! That is the failing statement, however deep in calls, in a FUNC inside an
//! expression, in a trap, in a module loaded at run time; or the RAISE of a handler that
//! passed it on. The stderr report (single task and system) and the event log's entry
//! (`--elog`) name the same routine, file, line and column. Expected places are worked
//! out by hand from the programs below (their lines are numbered in comments).

use std::fs;
use std::path::Path;
use std::process::{Command, Output};

use insta_cmd::{assert_cmd_snapshot, get_cargo_bin};
use serde_json::{json, Value};

use crate::fixture::{rapid_cmd, rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("error_location", name)
}

/// `rapid run --elog log.jsonl m.mod` in `dir`, with `program` written to `m.mod`.
fn run_cmd(dir: &Path, program: &str) -> Command {
    fs::write(dir.join("m.mod"), program).expect("write module");
    rapid_cmd(dir, &["run", "--elog", "log.jsonl", "m.mod"])
}

fn run(dir: &Path, program: &str) -> Output {
    run_cmd(dir, program).output().expect("run rapid")
}

/// The program domain's entries of the event log (domain 4): (type, routine, file,
/// line, column).
fn program_errors(dir: &Path) -> Vec<Value> {
    let log = fs::read_to_string(dir.join("log.jsonl")).expect("the log was written");
    log.lines()
        .map(|l| serde_json::from_str::<Value>(l).expect("a JSON object per line"))
        .filter(|e| e["domain"] == 4)
        .map(|e| json!([e["type"], e["routine"], e["file"], e["line"], e["column"]]))
        .collect()
}

fn at(kind: &str, routine: &str, file: &str, line: u32, column: u32) -> Value {
    json!([kind, routine, file, line, column])
}

const TWO_DEEP: &str = "\
MODULE m
  PROC main()
    TPWrite \"start\";
    outer;
    TPWrite \"not reached\";
  ENDPROC
  PROC outer()
    inner;
  ENDPROC
  PROC inner()
    VAR string s := \"abc\";
    s := StrPart(s, 5, 2);
  ENDPROC
ENDMODULE
";

#[test]
fn an_error_two_calls_deep_is_reported_at_the_failing_statement() {
    // StrPart fails on line 12 in `inner`; neither `outer` (line 8) nor `main` (line 4)
    // has a handler, so the error goes up to the system error handler, which names
    // line 12, column 5 (`s := …`).
    let dir = scratch("two_deep");
    assert_cmd_snapshot!(run_cmd(&dir, TWO_DEEP));
    assert_eq!(program_errors(&dir), [at("error", "inner", "m.mod", 12, 5)]);
}

const FUNC_IN_EXPRESSION: &str = "\
MODULE m
  PROC main()
    VAR num n;
    n := 1 + ratio(4, 0);
    TPWrite \"not reached\";
  ENDPROC
  FUNC num ratio(num a, num b)
    RETURN a / b;
  ENDFUNC
ENDMODULE
";

#[test]
fn an_error_in_a_function_called_from_an_expression_names_the_function() {
    // The division on line 8 (in `ratio`) fails while main's assignment on line 4
    // evaluates its expression.
    let dir = scratch("func_in_expression");
    assert_cmd_snapshot!(run_cmd(&dir, FUNC_IN_EXPRESSION));
    assert_eq!(program_errors(&dir), [at("error", "ratio", "m.mod", 8, 5)]);
}

const IN_TRAP: &str = "\
MODULE m
  VAR intnum tick;
  PROC main()
    CONNECT tick WITH on_tick;
    ITimer \\Single, 0.5, tick;
    WaitTime 1;
    TPWrite \"not reached\";
  ERROR
    TPWrite \"main's handler is not asked\";
    TRYNEXT;
  ENDPROC
  TRAP on_tick
    TPWrite \"tick\";
    check 0;
  ENDTRAP
  PROC check(num z)
    reg1 := 1 / z;
  ENDPROC
ENDMODULE
";

#[test]
fn an_error_in_a_routine_a_trap_calls_names_that_routine() {
    // The trap runs during main's WaitTime and calls `check`, whose division on line 17
    // fails. An error out of a trap goes to the system error handler (§1.12), never to
    // the interrupted routine's handler.
    let dir = scratch("in_trap");
    assert_cmd_snapshot!(run_cmd(&dir, IN_TRAP));
    assert_eq!(program_errors(&dir), [at("error", "check", "m.mod", 17, 5)]);
}

#[test]
fn a_handler_that_raises_passes_the_error_on_from_its_raise() {
    // Line 7 fails; receive's handler takes it (a warning at line 7) and passes it on
    // with RAISE (line 9); main has no handler. The RAISE raised it last.
    let program =
        "MODULE m\n  PROC main()\n    receive;\n  ENDPROC\n  PROC receive()\n    VAR string s := \"abc\";\n    \
                   s := StrPart(s, 5, 2);\n  ERROR\n    RAISE;\n  ENDPROC\nENDMODULE\n";
    let dir = scratch("raise_in_handler");
    let out = run(&dir, program);
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("\n  in routine receive at m.mod:9:5\n"), "{stderr}");
    assert_eq!(program_errors(&dir), [at("warning", "receive", "m.mod", 7, 5), at("error", "receive", "m.mod", 9, 5)]);
}

#[test]
fn a_handler_that_ends_without_handling_leaves_the_place_where_the_error_was_raised() {
    // `outer`'s handler takes every error (a warning at its call, line 6) but handles
    // none but ERR_SOCK_CLOSED: it reaches its end, and the system error handler
    // reports the error where it was raised, line 12 in `inner`.
    let program = "MODULE m\n  PROC main()\n    outer;\n  ENDPROC\n  PROC outer()\n    inner;\n  ERROR\n    \
                   IF ERRNO = ERR_SOCK_CLOSED RETRY;\n  ENDPROC\n  PROC inner()\n    VAR string s := \"abc\";\n    \
                   s := StrPart(s, 5, 2);\n  ENDPROC\nENDMODULE\n";
    let dir = scratch("handler_ends");
    let out = run(&dir, program);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stderr),
        "error: ERR_OUTOFBND (1001): character position 5 is outside 1..4\n  in routine inner at m.mod:12:5\n  \
         the program stopped (no ERROR handler handled the error)\n"
    );
    assert_eq!(program_errors(&dir), [at("warning", "outer", "m.mod", 6, 5), at("error", "inner", "m.mod", 12, 5)]);
}

#[test]
fn raise_in_a_trap_handler_goes_to_the_system_error_handler() {
    // The trap's handler takes the division (line 14) and passes it on with RAISE
    // (line 16); only the system calls a trap, so the error goes to the system error
    // handler (§1.12), not to main's handler.
    let program = "MODULE m\n  VAR intnum tick;\n  PROC main()\n    CONNECT tick WITH on_tick;\n    \
                   ITimer \\Single, 0.5, tick;\n    WaitTime 1;\n    TPWrite \"not reached\";\n  ERROR\n    \
                   TPWrite \"main's handler is not asked\";\n    TRYNEXT;\n  ENDPROC\n  TRAP on_tick\n    \
                   VAR num z := 0;\n    reg1 := 1 / z;\n  ERROR\n    RAISE;\n  ENDTRAP\nENDMODULE\n";
    let dir = scratch("raise_in_trap");
    let out = run(&dir, program);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("\n  in routine on_tick at m.mod:16:5\n"), "{stderr}");
    assert_eq!(
        program_errors(&dir),
        [at("warning", "on_tick", "m.mod", 14, 5), at("error", "on_tick", "m.mod", 16, 5)]
    );
}

#[test]
fn an_error_in_a_module_loaded_at_run_time_and_called_late_names_its_rapid_path() {
    // main loads tool.mod and calls tool_use by late binding; line 4 of tool.mod fails.
    let dir = scratch("loaded");
    fs::create_dir_all(dir.join("home/HOME")).expect("HOME device");
    fs::write(
        dir.join("home/HOME/tool.mod"),
        "MODULE tool\n  PROC tool_use()\n    VAR string s := \"abc\";\n    s := StrPart(s, 5, 2);\n  ENDPROC\nENDMODULE\n",
    )
    .expect("write module");
    let program = "MODULE m\n  PROC main()\n    Load \"HOME:/tool.mod\";\n    %\"tool_use\"%;\n  ENDPROC\nENDMODULE\n";
    fs::write(dir.join("m.mod"), program).expect("write module");
    let out = Command::new(get_cargo_bin("rapid"))
        .current_dir(&dir)
        .args(["run", "--elog", "log.jsonl", "--home", "home", "m.mod"])
        .output()
        .expect("run rapid");
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("\n  in routine tool_use at HOME:/tool.mod:4:5\n"), "{stderr}");
    assert_eq!(program_errors(&dir), [at("error", "tool_use", "HOME:/tool.mod", 4, 5)]);
}

#[test]
fn a_system_reports_the_failing_statement_of_the_task() {
    // Two NORMAL tasks from a manifest: T_ROB1 fails two calls deep (TWO_DEEP, line
    // 12), T_PLC ends normally.
    let dir = scratch("system");
    let manifest = "[[task]]\nname = \"T_ROB1\"\ntype = \"NORMAL\"\nmodules = [\"rob/m.mod\"]\n\n\
                    [[task]]\nname = \"T_PLC\"\ntype = \"NORMAL\"\nmodules = [\"plc/p.mod\"]\n";
    fs::create_dir_all(dir.join("proj/rob")).expect("folder");
    fs::create_dir_all(dir.join("proj/plc")).expect("folder");
    fs::write(dir.join("proj/rapid.toml"), manifest).expect("manifest");
    fs::write(dir.join("proj/rob/m.mod"), TWO_DEEP).expect("module");
    fs::write(dir.join("proj/plc/p.mod"), "MODULE p\n  PROC main()\n    TPWrite \"plc\";\n  ENDPROC\nENDMODULE\n")
        .expect("module");
    let out = Command::new(get_cargo_bin("rapid"))
        .current_dir(&dir)
        .args(["run", "--elog", "log.jsonl", "proj"])
        .output()
        .expect("run rapid");
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    let report = "\n  in task T_ROB1, routine inner at proj/rob/m.mod:12:5\n  \
                  the task stopped (no ERROR handler handled the error)\n";
    assert!(stderr.contains(report), "{stderr}");
    assert_eq!(program_errors(&dir), [at("error", "inner", "proj/rob/m.mod", 12, 5)]);
}

/// Writes backup `sys` in `dir` with a START event routine `on_start` in T_ROB1 and
/// `tasks` (name, module) in RAPID/TASKn; returns the run's output.
fn run_with_start_hook(dir: &Path, tasks: &[(&str, &str)]) -> Output {
    let mut sys = String::from("SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n");
    for (n, (name, module)) in tasks.iter().enumerate() {
        sys.push_str(&format!("\n      -Name \"{name}\" -Type \"NORMAL\"\n"));
        let folder = dir.join(format!("sys/RAPID/TASK{}/PROGMOD", n + 1));
        fs::create_dir_all(&folder).expect("task folder");
        fs::write(folder.join("Main.mod"), module).expect("module");
    }
    sys.push_str("#\nCAB_EXEC_HOOKS:\n\n      -Routine \"on_start\" -Shelf \"START\" -Task \"T_ROB1\"\n");
    fs::create_dir_all(dir.join("sys/SYSPAR")).expect("syspar");
    fs::write(dir.join("sys/SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    rapid_in(dir, &["run", "sys"])
}

/// T_ROB1's module: the START event routine calls `inner`, which fails on line 9.
const START_HOOK: &str = "MODULE Main\n  PROC main()\n    TPWrite \"not reached\";\n  ENDPROC\n  PROC on_start()\n    \
                          inner;\n  ENDPROC\n  PROC inner()\n    reg1 := 1 / reg2;\n  ENDPROC\nENDMODULE\n";

#[test]
fn an_error_in_an_event_routine_names_the_failing_statement_and_the_event_routine() {
    // reg2 is 0 at the start: the division on line 9 (in `inner`, called by the START
    // event routine on_start) fails; main does not run.
    let dir = scratch("start_hook");
    let out = run_with_start_hook(&dir, &[("T_ROB1", START_HOOK)]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    let stderr = text(&out.stderr);
    let report = "\n  in routine inner at sys/RAPID/TASK1/PROGMOD/Main.mod:9:5\n  \
                  the event routine on_start stopped (no ERROR handler handled the error)\n";
    assert!(stderr.contains(report), "{stderr}");

    // In a system of two tasks, the same place.
    let dir = scratch("start_hook_system");
    let plc = "MODULE Main\n  PROC main()\n    TPWrite \"plc\";\n  ENDPROC\nENDMODULE\n";
    let out = run_with_start_hook(&dir, &[("T_ROB1", START_HOOK), ("T_PLC", plc)]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    let report = "in the START event routine on_start of task T_ROB1, \
                  raised in routine inner at sys/RAPID/TASK1/PROGMOD/Main.mod:9:5";
    assert!(stderr.contains(report), "{stderr}");
}
