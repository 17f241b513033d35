//! Ctrl-C ends `rapid run` as a bound does: the run's trace and cycle time are still
//! written, and the exit status is 130 (as a shell reports SIGINT).

use std::io::{BufRead, BufReader};
use std::process::Command;

use crate::fixture::{scratch_in, spawn_in, text};

#[test]
fn ctrl_c_ends_a_run_and_keeps_its_trace() {
    let dir = scratch_in("interrupt", "realtime_wait");
    // With --realtime the hour's wait is a real one: only Ctrl-C ends it. The robot has
    // moved by then, so the trace has rows and ends where the MoveAbsJ put axis 1.
    let module = "MODULE Wait\n  PROC main()\n    MoveAbsJ [[20,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    \
                  TPWrite \"moved\";\n    WaitTime 3600;\n    TPWrite \"not reached\";\n  ENDPROC\nENDMODULE\n";
    std::fs::write(dir.join("Wait.mod"), module).expect("module");
    let mut child = spawn_in(&dir, &["run", "--realtime", "--trace", "t.csv", "Wait.mod"]);
    let mut lines = BufReader::new(child.stdout.take().expect("stdout")).lines();
    assert_eq!(lines.next().and_then(Result::ok).as_deref(), Some("moved"));
    let killed = Command::new("kill").args(["-INT", &child.id().to_string()]).status().expect("kill");
    assert!(killed.success());
    let rest: Vec<String> = lines.map_while(Result::ok).collect();
    let out = child.wait_with_output().expect("rapid ends");
    assert_eq!(out.status.code(), Some(130), "{}", text(&out.stderr));
    assert!(rest.is_empty(), "{rest:?}");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("interrupted (Ctrl-C) at") && stderr.contains("cycle time"), "{stderr}");
    let trace = std::fs::read_to_string(dir.join("t.csv")).expect("the trace is written");
    let header: Vec<&str> = trace.lines().next().expect("header").split(',').collect();
    let j1 = header.iter().position(|h| *h == "j1").expect("a j1 column");
    let last: Vec<&str> = trace.lines().last().expect("rows").split(',').collect();
    assert_eq!(last[j1].parse::<f64>().expect("j1").round(), 20.0, "{}", trace.lines().last().unwrap_or_default());
}
