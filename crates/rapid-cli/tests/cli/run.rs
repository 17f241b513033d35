//! `rapid run` end to end: exit statuses, the unhandled-error report, safety bounds,
//! pendant answers, and Save Module of persistents.

use std::fs;

use crate::fixture::{rapid, scratch_in, Scratch};

/// A fresh, empty scratch folder for one test.
fn temp_dir(name: &str) -> Scratch {
    scratch_in("run", name)
}

#[test]
fn an_unhandled_error_names_the_error_routine_and_line_and_exits_1() {
    let dir = temp_dir("unhandled");
    let module = dir.join("m.mod");
    fs::write(&module, "MODULE m\nPROC main()\n  VAR num z := 0;\n  TPWrite \"before\";\n  reg1 := 1 / z;\n  TPWrite \"after\";\nENDPROC\nENDMODULE\n").unwrap();
    let out = rapid(&["run", module.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "before\n");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("ERR_DIVZERO"), "{stderr}");
    assert!(stderr.contains("in routine main"), "{stderr}");
    assert!(stderr.contains("m.mod:5:3"), "{stderr}");
}

#[test]
fn a_program_with_errors_is_not_run() {
    let dir = temp_dir("errors");
    let module = dir.join("m.mod");
    fs::write(&module, "MODULE m\nPROC main()\n  TPWrite undefined_thing;\nENDPROC\nENDMODULE\n").unwrap();
    let out = rapid(&["run", module.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("E0201"));
}

#[test]
fn max_steps_bounds_a_runaway_loop() {
    let dir = temp_dir("steps");
    let module = dir.join("m.mod");
    fs::write(&module, "MODULE m\nPROC main()\n  WHILE TRUE DO\n  ENDWHILE\nENDPROC\nENDMODULE\n").unwrap();
    let out = rapid(&["run", "--max-steps", "100000", module.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--max-steps"));
}

#[test]
fn max_time_bounds_virtual_waiting() {
    let dir = temp_dir("time");
    let module = dir.join("m.mod");
    fs::write(&module, "MODULE m\nPROC main()\n  WHILE TRUE DO\n    WaitTime 10;\n  ENDWHILE\nENDPROC\nENDMODULE\n")
        .unwrap();
    let out = rapid(&["run", "--max-time", "3600", module.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--max-time"));
}

#[test]
fn pendant_answers_come_from_tp_input() {
    let dir = temp_dir("tp");
    let module = dir.join("m.mod");
    let answers = dir.join("answers.txt");
    fs::write(&module, "MODULE m\nPROC main()\n  VAR num n;\n  VAR num k;\n  TPReadNum n, \"Parts?\";\n  TPReadFK k, \"Go?\", \"Yes\", \"No\", stEmpty, stEmpty, stEmpty;\n  TPWrite \"n=\" \\Num:=n;\n  TPWrite \"k=\" \\Num:=k;\nENDPROC\nENDMODULE\n").unwrap();
    fs::write(&answers, "# operator\n7\nNo\n").unwrap();
    let out = rapid(&["run", "--tp-input", answers.to_str().unwrap(), module.to_str().unwrap()]);
    assert_eq!(String::from_utf8_lossy(&out.stdout), "n=7\nk=2\n");
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn save_pers_writes_values_back_keeping_every_other_byte() {
    let dir = temp_dir("pers");
    let module = dir.join("m.mod");
    // CRLF line ends, a Latin-1 comment, a persistent without a value.
    let original: &[u8] = b"MODULE m\r\n  ! caf\xe9\r\n  PERS num count := 1;\r\n  PERS pos p := [1,2,3];\r\n  PERS bool seen;\r\n  PROC main()\r\n    Incr count;\r\n    p.y := 0.25;\r\n    seen := TRUE;\r\n  ENDPROC\r\nENDMODULE\r\n";
    fs::write(&module, original).unwrap();
    let out = rapid(&["run", "--save-pers", module.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let saved = fs::read(&module).unwrap();
    let expected: &[u8] = b"MODULE m\r\n  ! caf\xe9\r\n  PERS num count := 2;\r\n  PERS pos p := [1,0.25,3];\r\n  PERS bool seen := TRUE;\r\n  PROC main()\r\n    Incr count;\r\n    p.y := 0.25;\r\n    seen := TRUE;\r\n  ENDPROC\r\nENDMODULE\r\n";
    assert_eq!(saved, expected);
    // No temporary file is left behind.
    assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
}

#[test]
fn a_function_defined_nowhere_fails_only_when_it_is_called() {
    let dir = temp_dir("unknown_func");
    let module = dir.join("m.mod");
    // The controller links late: the program loads, runs past the call it skips, and
    // the call it makes raises ERR_REFUNKFUN, which an ERROR handler can take.
    let text = "MODULE m\nPROC main()\n  VAR num op := 1;\n  IF op = 5 TPWrite \"opt \" \\Bool:=optional_cmd(op);\n  \
                TPWrite \"skipped\";\n  reg1 := optional_cmd(op) + 1;\n  TPWrite \"not reached\";\nERROR\n  \
                IF ERRNO = ERR_REFUNKFUN TPWrite \"ERR_REFUNKFUN\";\n  RETURN;\nENDPROC\nENDMODULE\n";
    fs::write(&module, text).unwrap();
    let out = rapid(&["check", module.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    assert!(String::from_utf8_lossy(&out.stdout).contains("warning[W0203]"));
    let out = rapid(&["run", module.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "skipped\nERR_REFUNKFUN\n");
}
