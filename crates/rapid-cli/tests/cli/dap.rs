//! `rapid dap` end to end with a real DAP client: VS Code's adapter test library
//! (`@vscode/debugadapter-testsupport`, pinned, from npm, installed once per target
//! folder) drives `dap_client.cjs` through a whole session on a two-task manifest. A
//! scripted client of our own checks a backup's signals and a stimulus, and a launch
//! that cannot boot.
//!
//! Without node, npm or the registry the test is skipped loudly; under CI (`CI=true`
//! or `OPENRAPID_REQUIRE_DAP_CLIENT=1`) it fails instead.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use std::io::{BufRead, BufReader, Read, Write};

use serde_json::{json, Value};

use crate::fixture::{copy_dir, repo_root, scratch_in, system, text, TaskDef};

/// The client library the test installs.
const PACKAGE: &str = "@vscode/debugadapter-testsupport@1.68.0";

fn required() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true")
        || std::env::var("OPENRAPID_REQUIRE_DAP_CLIENT").is_ok_and(|v| v == "1")
}

/// Runs `cmd` to its end, at most `limit` (killed after).
fn output_bounded(cmd: &mut Command, limit: Duration) -> Option<Output> {
    let child = cmd.stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().ok()?;
    let id = child.id();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(child.wait_with_output());
    });
    let deadline = Instant::now() + limit;
    match rx.recv_timeout(deadline.saturating_duration_since(Instant::now())) {
        Ok(out) => out.ok(),
        Err(_) => {
            let _ = Command::new("kill").args(["-9", &id.to_string()]).status();
            None
        }
    }
}

/// The folder holding `node_modules` with the pinned client; None (after a loud
/// note) when this machine cannot install it and CI does not require it.
fn client_modules() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("dap-client");
    let marker = dir.join(format!("installed {}", PACKAGE.replace('/', "+")));
    if marker.exists() {
        return Some(dir.join("node_modules"));
    }
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("client folder");
    let mut npm = Command::new("npm");
    npm.args(["install", "--no-audit", "--no-fund", "--silent", "--prefix"]).arg(&dir).arg(PACKAGE);
    let out = output_bounded(&mut npm, Duration::from_secs(600));
    if !out.as_ref().is_some_and(|o| o.status.success()) {
        let why = out.map_or("npm did not start or took too long".to_owned(), |o| text(&o.stderr));
        assert!(!required(), "npm install {PACKAGE} failed (CI requires the DAP client test): {why}");
        #[allow(clippy::print_stderr)]
        {
            eprintln!(
                "*** skipped: npm install {PACKAGE} failed, rapid dap was not tried with a real client: {why} ***"
            );
        }
        return None;
    }
    std::fs::write(&marker, "").expect("marker");
    Some(dir.join("node_modules"))
}

#[test]
fn a_real_dap_client_debugs_a_two_task_program() {
    let node_found = Command::new("node").arg("--version").output().is_ok_and(|o| o.status.success());
    if !node_found {
        assert!(!required(), "node is not installed and CI requires the DAP client test");
        #[allow(clippy::print_stderr)]
        {
            eprintln!("*** skipped: node not installed (rapid dap was not tried with a real client) ***");
        }
        return;
    }
    let Some(modules) = client_modules() else { return };
    let dir = scratch_in("dap", "two_tasks");
    let project = dir.join("project");
    copy_dir(&repo_root().join("crates/rapid-cli/tests/cli/fixtures/dap_project"), &project);
    let script = repo_root().join("crates/rapid-cli/tests/cli/dap_client.cjs");
    let mut node = Command::new("node");
    node.arg(&script).arg(env!("CARGO_BIN_EXE_rapid")).arg(&project).env("NODE_PATH", &modules);
    let out = output_bounded(&mut node, Duration::from_secs(120)).expect("the client finishes within 120 s");
    assert!(out.status.success(), "the DAP session failed:\n{}\n{}", text(&out.stdout), text(&out.stderr));
    assert!(text(&out.stdout).contains("dap session passed"), "{}", text(&out.stdout));
}

/// `rapid dap` as a process, spoken to by a scripted client.
struct Adapter {
    child: std::process::Child,
    messages: std::sync::mpsc::Receiver<Value>,
    seq: i64,
}

impl Adapter {
    fn start() -> Adapter {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rapid"))
            .arg("dap")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("start rapid dap");
        let stdout = child.stdout.take().expect("stdout");
        let (tx, messages) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(stdout);
            loop {
                let mut header = String::new();
                if reader.read_line(&mut header).unwrap_or(0) == 0 {
                    return;
                }
                let Some(length) = header.trim().strip_prefix("Content-Length: ").and_then(|n| n.parse().ok()) else {
                    continue;
                };
                let mut blank = String::new();
                let _ = reader.read_line(&mut blank);
                let mut body = vec![0; length];
                if reader.read_exact(&mut body).is_err() {
                    return;
                }
                if tx.send(serde_json::from_slice(&body).expect("JSON")).is_err() {
                    return;
                }
            }
        });
        Adapter { child, messages, seq: 0 }
    }

    /// The next message that `pick` accepts, at most 20 s away.
    fn wait_for(&mut self, pick: impl Fn(&Value) -> bool) -> Value {
        loop {
            let message = self.messages.recv_timeout(Duration::from_secs(20)).expect("rapid dap answers");
            if pick(&message) {
                return message;
            }
        }
    }

    fn request(&mut self, command: &str, arguments: Value) -> Value {
        self.seq += 1;
        let body = json!({"seq": self.seq, "type": "request", "command": command, "arguments": arguments}).to_string();
        let stdin = self.child.stdin.as_mut().expect("stdin");
        write!(stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).expect("write");
        stdin.flush().expect("flush");
        let seq = self.seq;
        self.wait_for(|m| m["type"] == "response" && m["request_seq"] == seq)
    }

    fn ok(&mut self, command: &str, arguments: Value) -> Value {
        let response = self.request(command, arguments);
        assert_eq!(response["success"], true, "{command}: {response}");
        response["body"].clone()
    }

    fn event(&mut self, name: &str) -> Value {
        self.wait_for(|m| m["type"] == "event" && m["event"] == name)["body"].clone()
    }

    /// Disconnects; the process must end by itself.
    fn finish(mut self) {
        self.ok("disconnect", json!({}));
        drop(self.child.stdin.take());
        let deadline = Instant::now() + Duration::from_secs(10);
        while Instant::now() < deadline {
            if let Ok(Some(status)) = self.child.try_wait() {
                assert!(status.success(), "rapid dap ended with {status}");
                return;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = self.child.kill();
        panic!("rapid dap did not end after disconnect");
    }
}

const WAITER: &str = "MODULE Main
  VAR num seen := 0;
  PROC main()
    WaitDI diPart, 1;
    seen := 1;
    SetDO doGrip, 1;
    seen := 2;
  ENDPROC
ENDMODULE
";

#[test]
fn a_backup_runs_with_its_stimulus_and_shows_its_signals() {
    let dir = scratch_in("dap", "signals");
    let signals = "\n      -Name \"diPart\" -SignalType \"DI\"\n\n      -Name \"doGrip\" -SignalType \"DO\"\n";
    let root = system(
        dir.path(),
        &[TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: WAITER }],
        signals,
    );
    let stimulus = dir.join("part.stimulus");
    std::fs::write(&stimulus, "at 0.5 set diPart 1\n").expect("stimulus");
    let module = root.join("RAPID/TASK1/PROGMOD/Main.mod");
    let line = WAITER.lines().position(|l| l.contains("seen := 2;")).map(|at| at + 1).expect("line");

    let mut dap = Adapter::start();
    dap.ok("initialize", json!({"adapterID": "rapid"}));
    dap.ok("launch", json!({"program": root, "stimulus": stimulus}));
    dap.event("initialized");
    let set = dap.ok("setBreakpoints", json!({"source": {"path": module}, "breakpoints": [{"line": line}]}));
    assert_eq!(set["breakpoints"][0]["verified"], true, "{set}");
    dap.ok("configurationDone", json!({}));
    let stopped = dap.event("stopped");
    assert_eq!(stopped["reason"], "breakpoint");

    let trace = dap.ok("stackTrace", json!({"threadId": 1}));
    let frame = trace["stackFrames"][0]["id"].clone();
    // The stimulus set diPart, so WaitDI let the task on, and it set doGrip.
    let scopes = dap.ok("scopes", json!({"frameId": frame}));
    let signals_scope = scopes["scopes"].as_array().and_then(|s| s.iter().find(|s| s["name"] == "Signals")).cloned();
    let reference = signals_scope.expect("a Signals scope")["variablesReference"].clone();
    let vars = dap.ok("variables", json!({"variablesReference": reference}));
    let value = |vars: &Value, name: &str| {
        vars["variables"].as_array().and_then(|v| v.iter().find(|v| v["name"] == name)).map(|v| v["value"].clone())
    };
    assert_eq!(value(&vars, "diPart"), Some(json!("1")), "{vars}");
    assert_eq!(value(&vars, "doGrip"), Some(json!("1")), "{vars}");
    let set = dap.ok("setVariable", json!({"variablesReference": reference, "name": "doGrip", "value": "0"}));
    assert_eq!(set["value"], "0");
    let seen = dap.ok("evaluate", json!({"expression": "seen", "frameId": frame}));
    assert_eq!(seen["result"], "1");

    dap.ok("continue", json!({"threadId": 1}));
    dap.event("terminated");
    assert_eq!(dap.event("exited")["exitCode"], 0);
    dap.finish();
}

#[test]
fn a_launch_that_cannot_boot_says_why() {
    let dir = scratch_in("dap", "no_program");
    let mut dap = Adapter::start();
    dap.ok("initialize", json!({"adapterID": "rapid"}));
    let missing = dir.join("missing.mod");
    let response = dap.request("launch", json!({"program": missing}));
    assert_eq!(response["success"], false);
    let message = response["message"].as_str().unwrap_or_default();
    assert!(message.contains("missing.mod"), "{message}");
    dap.finish();
}

const FAILING: &str = "MODULE Main
  VAR num zero := 0;
  VAR num total := 0;
  PROC main()
    Add total, 5;
    total := total / zero;
    total := -1;
  ENDPROC
  PROC Add(INOUT num sum, num inc)
    sum := sum + inc;
  ENDPROC
ENDMODULE
";

#[test]
fn a_routines_data_is_set_and_an_uncaught_error_stops_before_the_task_does() {
    let dir = scratch_in("dap", "errors");
    let module = dir.join("Main.mod");
    std::fs::write(&module, FAILING).expect("module");
    let line_of = |needle: &str| FAILING.lines().position(|l| l.contains(needle)).map(|at| at + 1).expect("line");

    let mut dap = Adapter::start();
    let init = dap.ok("initialize", json!({"adapterID": "rapid"}));
    assert_eq!(init["supportsExceptionInfoRequest"], true);
    dap.ok("launch", json!({"program": module}));
    dap.event("initialized");
    dap.ok(
        "setBreakpoints",
        json!({"source": {"path": module}, "breakpoints": [{"line": line_of("sum := sum + inc;")}]}),
    );
    dap.ok("setExceptionBreakpoints", json!({"filters": ["uncaught"]}));
    dap.ok("configurationDone", json!({}));
    assert_eq!(dap.event("stopped")["reason"], "breakpoint");

    // In Add: INOUT `sum` writes through to main's `total`; `inc` changes in Add only.
    let trace = dap.ok("stackTrace", json!({"threadId": 1}));
    let (add, main) = (trace["stackFrames"][0]["id"].clone(), trace["stackFrames"][1]["id"].clone());
    let scopes = dap.ok("scopes", json!({"frameId": add}));
    let locals = scopes["scopes"][0]["variablesReference"].clone();
    dap.ok("setVariable", json!({"variablesReference": locals, "name": "sum", "value": "10"}));
    dap.ok("setVariable", json!({"variablesReference": locals, "name": "inc", "value": "2"}));
    assert_eq!(dap.ok("evaluate", json!({"expression": "total", "frameId": main}))["result"], "10");

    // total = 10 + 2 = 12; then 12 / 0 reaches no handler: the task stands at it.
    dap.ok("continue", json!({"threadId": 1}));
    let stopped = dap.event("stopped");
    assert_eq!(stopped["reason"], "exception");
    let trace = dap.ok("stackTrace", json!({"threadId": 1}));
    assert_eq!(trace["stackFrames"][0]["line"], line_of("total := total / zero;"));
    let frame = trace["stackFrames"][0]["id"].clone();
    assert_eq!(dap.ok("evaluate", json!({"expression": "total", "frameId": frame}))["result"], "12");
    let info = dap.ok("exceptionInfo", json!({"threadId": 1}));
    assert_eq!((info["exceptionId"].as_str(), info["breakMode"].as_str()), (Some("ERR_DIVZERO"), Some("unhandled")));

    // Going on, the task stops with the error; `total := -1` never runs.
    dap.ok("continue", json!({"threadId": 1}));
    dap.event("terminated");
    dap.finish();
}
