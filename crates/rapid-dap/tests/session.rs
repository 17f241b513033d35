//! A whole debug session in-process: the adapter serves on a thread, a scripted
//! client speaks the protocol to it over channels, on a two-task program.

use std::collections::VecDeque;
use std::io::{self, Read, Write};
use std::sync::mpsc::{self, Receiver, Sender};
use std::time::Duration;

use rapid_controller::api::Session;
use rapid_controller::{Controller, TaskSpec};
use rapid_dap::{LaunchArgs, Launched, Launcher};
use rapid_sema::SourceInput;
use serde_json::{json, Value};

const ROBOT: &str = "MODULE MainModule
  RECORD part
    num id;
    string label;
  ENDRECORD
  VAR num count := 0;
  VAR part item := [7, \"bolt\"];
  PERS num total := 0;
  VAR num grid{2, 2} := [[1, 2], [3, 4]];
  PROC main()
    count := 1;
    Helper 5;
    count := count + 1;
    TPWrite \"count \" \\Num:=count;
    Bump;
    total := count;
  ENDPROC
  PROC Helper(num n)
    VAR num twice;
    twice := n * 2;
    count := count + twice;
  ENDPROC
  PROC Bump()
    count := count + 100;
  BACKWARD
    count := count - 100;
  ENDPROC
ENDMODULE
";

const OTHER: &str = "MODULE Other
  VAR num ticks := 0;
  PROC main()
    WHILE ticks < 5 DO
      ticks := ticks + 1;
      WaitTime 0.1;
    ENDWHILE
    TPWrite \"other done\";
  ENDPROC
ENDMODULE
";

/// The 1-based line of `text` holding `needle`.
fn line_of(text: &str, needle: &str) -> u64 {
    text.lines().position(|l| l.contains(needle)).map(|at| at as u64 + 1).expect("the line is in the module")
}

/// Boots its tasks (name, module path, module text) from texts: the launch's paths
/// are not read.
struct Program(Vec<(&'static str, &'static str, &'static str)>);

impl Launcher for Program {
    fn launch(&self, _args: &LaunchArgs) -> Result<Launched, String> {
        let options = rapid_sema::Options::default();
        let mut tasks = Vec::new();
        for (at, (name, path, text)) in self.0.iter().enumerate() {
            let loaded =
                rapid_controller::builtin_set::load_with(&[SourceInput::from_text(*path, *text)], "main", &options)
                    .map_err(|e| format!("{path}: {e:?}"))?;
            tasks.push((TaskSpec::normal(name, at == 0), loaded));
        }
        let controller = Controller::new(tasks, None).map_err(|e| format!("{e:?}"))?;
        Ok(Launched { session: Session::new(controller), answers: Vec::new() })
    }
}

fn two_tasks() -> Program {
    Program(vec![("T_ROB1", "/dap/T_ROB1/MainModule.mod", ROBOT), ("T_OTHER", "/dap/T_OTHER/Other.mod", OTHER)])
}

/// The client's end of the adapter's streams.
struct Client {
    to_adapter: Sender<Vec<u8>>,
    from_adapter: Receiver<Vec<u8>>,
    buffer: Vec<u8>,
    seq: i64,
    /// Events received and not yet looked at.
    events: VecDeque<Value>,
}

struct ChannelReader(Receiver<Vec<u8>>, VecDeque<u8>);

impl Read for ChannelReader {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        while self.1.is_empty() {
            match self.0.recv() {
                Ok(bytes) => self.1.extend(bytes),
                Err(_) => return Ok(0),
            }
        }
        let n = buf.len().min(self.1.len());
        for (slot, byte) in buf.iter_mut().zip(self.1.drain(..n)) {
            *slot = byte;
        }
        Ok(n)
    }
}

struct ChannelWriter(Sender<Vec<u8>>);

impl Write for ChannelWriter {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.0.send(buf.to_vec()).map_err(|_| io::Error::from(io::ErrorKind::BrokenPipe))?;
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

impl Client {
    fn start(program: Program) -> Client {
        let (to_adapter, adapter_in) = mpsc::channel();
        let (adapter_out, from_adapter) = mpsc::channel();
        std::thread::spawn(move || {
            let mut output = ChannelWriter(adapter_out);
            let _ = rapid_dap::serve(ChannelReader(adapter_in, VecDeque::new()), &mut output, &program);
        });
        Client { to_adapter, from_adapter, buffer: Vec::new(), seq: 0, events: VecDeque::new() }
    }

    /// The next message, at most 20 s away.
    fn next_message(&mut self) -> Value {
        loop {
            if let Some(end) = self.buffer.windows(4).position(|w| w == b"\r\n\r\n") {
                let header = String::from_utf8_lossy(&self.buffer[..end]).to_string();
                let length: usize = header.trim_start_matches("Content-Length: ").parse().expect("a length");
                if self.buffer.len() >= end + 4 + length {
                    let body: Vec<u8> = self.buffer.drain(..end + 4 + length).skip(end + 4).collect();
                    return serde_json::from_slice(&body).expect("JSON");
                }
            }
            let bytes = self.from_adapter.recv_timeout(Duration::from_secs(20)).expect("the adapter answers");
            self.buffer.extend(bytes);
        }
    }

    /// Sends a request and returns its response (events met meanwhile are kept).
    fn request(&mut self, command: &str, arguments: Value) -> Value {
        self.seq += 1;
        let body = json!({"seq": self.seq, "type": "request", "command": command, "arguments": arguments}).to_string();
        let framed = format!("Content-Length: {}\r\n\r\n{body}", body.len());
        self.to_adapter.send(framed.into_bytes()).expect("the adapter reads");
        loop {
            let message = self.next_message();
            match message["type"].as_str() {
                Some("response") if message["request_seq"] == self.seq => return message,
                Some("event") => self.events.push_back(message),
                _ => {}
            }
        }
    }

    /// A request that must succeed: its body.
    fn ok(&mut self, command: &str, arguments: Value) -> Value {
        let response = self.request(command, arguments);
        assert_eq!(response["success"], true, "{command}: {response}");
        response["body"].clone()
    }

    /// Waits for event `name`; the output events passed on the way are returned too.
    fn event(&mut self, name: &str) -> (Value, Vec<String>) {
        let mut output = Vec::new();
        loop {
            let event = match self.events.pop_front() {
                Some(event) => event,
                None => self.next_message(),
            };
            if event["event"] == "output" {
                output.push(event["body"]["output"].as_str().unwrap_or_default().to_owned());
            }
            if event["event"] == name {
                return (event["body"].clone(), output);
            }
        }
    }

    /// Waits for an output event holding `needle`.
    fn output_with(&mut self, needle: &str) {
        loop {
            let (event, _) = self.event("output");
            if event["output"].as_str().unwrap_or_default().contains(needle) {
                return;
            }
        }
    }

    /// The innermost frame of thread 1: (id, routine, line).
    fn top_frame(&mut self, thread: u64) -> (i64, String, u64) {
        let trace = self.ok("stackTrace", json!({"threadId": thread}));
        let top = &trace["stackFrames"][0];
        (top["id"].as_i64().unwrap(), top["name"].as_str().unwrap().to_owned(), top["line"].as_u64().unwrap())
    }

    fn evaluate(&mut self, frame: i64, expression: &str) -> String {
        let body = self.ok("evaluate", json!({"expression": expression, "frameId": frame}));
        body["result"].as_str().unwrap().to_owned()
    }

    /// The variables of `reference` as (name, value, reference).
    fn variables(&mut self, reference: i64) -> Vec<(String, String, i64)> {
        let body = self.ok("variables", json!({"variablesReference": reference}));
        body["variables"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| {
                let name = v["name"].as_str().unwrap().to_owned();
                (name, v["value"].as_str().unwrap().to_owned(), v["variablesReference"].as_i64().unwrap())
            })
            .collect()
    }

    fn launch_with_breakpoints(&mut self, file: &str, points: Value) -> Value {
        self.launch(json!({"program": "/dap"}), file, points)
    }

    fn launch(&mut self, arguments: Value, file: &str, points: Value) -> Value {
        let init = self.ok("initialize", json!({"adapterID": "rapid"}));
        assert_eq!(init["supportsStepBack"], true);
        self.ok("launch", arguments);
        self.event("initialized");
        let set = self.ok("setBreakpoints", json!({"source": {"path": file}, "breakpoints": points}));
        self.ok("configurationDone", json!({}));
        set
    }
}

fn value_of<'v>(vars: &'v [(String, String, i64)], name: &str) -> &'v (String, String, i64) {
    vars.iter().find(|v| v.0 == name).unwrap_or_else(|| panic!("no variable {name} in {vars:?}"))
}

#[test]
fn a_whole_session_on_two_tasks() {
    let mut client = Client::start(two_tasks());
    let at_call = line_of(ROBOT, "Helper 5;");
    let set = client.launch_with_breakpoints("/dap/T_ROB1/MainModule.mod", json!([{"line": at_call}]));
    assert_eq!(set["breakpoints"][0]["verified"], true);
    let (stopped, _) = client.event("stopped");
    assert_eq!((stopped["reason"].as_str(), stopped["threadId"].as_u64()), (Some("breakpoint"), Some(1)));

    let threads = client.ok("threads", json!({}));
    let names: Vec<&str> = threads["threads"].as_array().unwrap().iter().map(|t| t["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["T_ROB1", "T_OTHER"]);

    let trace = client.ok("stackTrace", json!({"threadId": 1}));
    let top = &trace["stackFrames"][0];
    assert_eq!((top["name"].as_str(), top["line"].as_u64()), (Some("main"), Some(at_call)));
    assert_eq!(top["source"]["path"], "/dap/T_ROB1/MainModule.mod");
    let frame = top["id"].as_i64().unwrap();

    // Module data: count is 1 (main's first statement ran), the record expands.
    let scopes = client.ok("scopes", json!({"frameId": frame}));
    let names: Vec<&str> = scopes["scopes"].as_array().unwrap().iter().map(|s| s["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["Locals", "Module data", "Persistents"]);
    let module_ref = scopes["scopes"][1]["variablesReference"].as_i64().unwrap();
    let data = client.variables(module_ref);
    assert_eq!(value_of(&data, "count").1, "1");
    let item = value_of(&data, "item").clone();
    assert_eq!(item.1, "[7,\"bolt\"]");
    let parts = client.variables(item.2);
    assert_eq!(parts, [("id".to_owned(), "7".to_owned(), 0), ("label".to_owned(), "\"bolt\"".to_owned(), 0)]);
    // A two-dimensional array expands row by row; an element is written and read back.
    let grid = value_of(&data, "grid").clone();
    assert_eq!(grid.1, "[[1,2],[3,4]]");
    let cells = client.variables(grid.2);
    let names: Vec<&str> = cells.iter().map(|c| c.0.as_str()).collect();
    assert_eq!(names, ["{1,1}", "{1,2}", "{2,1}", "{2,2}"]);
    assert_eq!(value_of(&cells, "{2,1}").1, "3");
    let set = client.ok("setVariable", json!({"variablesReference": grid.2, "name": "{2,1}", "value": "30"}));
    assert_eq!(set["value"], "30");
    let pers_ref = scopes["scopes"][2]["variablesReference"].as_i64().unwrap();
    assert_eq!(value_of(&client.variables(pers_ref), "total").1, "0");

    // Set a datum and a record's component; evaluate with both.
    let set = client.ok("setVariable", json!({"variablesReference": module_ref, "name": "count", "value": "41"}));
    assert_eq!(set["value"], "41");
    let set = client.ok("setVariable", json!({"variablesReference": item.2, "name": "id", "value": "9"}));
    assert_eq!(set["value"], "9");
    assert_eq!(client.evaluate(frame, "count + item.id"), "50");
    assert_eq!(client.evaluate(frame, "item.label + \"s\""), "\"bolts\"");
    assert_eq!(client.evaluate(frame, "grid{2, 1} + grid{1, 2}"), "32");
    let refused =
        client.request("setVariable", json!({"variablesReference": module_ref, "name": "count", "value": "\"x\""}));
    assert_eq!(refused["success"], false);

    // Into Helper: its parameter and routine data are the frame's locals.
    client.ok("stepIn", json!({"threadId": 1}));
    assert_eq!(client.event("stopped").0["reason"], "step");
    let (frame, routine, line) = client.top_frame(1);
    assert_eq!((routine.as_str(), line), ("Helper", line_of(ROBOT, "twice := n * 2;")));
    let scopes = client.ok("scopes", json!({"frameId": frame}));
    let locals = client.variables(scopes["scopes"][0]["variablesReference"].as_i64().unwrap());
    assert_eq!(value_of(&locals, "n").1, "5");
    assert_eq!(value_of(&locals, "twice").1, "0");
    assert_eq!(client.evaluate(frame, "n * 2 + count"), "51");

    client.ok("next", json!({"threadId": 1}));
    client.event("stopped");
    assert_eq!(client.top_frame(1).2, line_of(ROBOT, "count := count + twice;"));
    client.ok("stepOut", json!({"threadId": 1}));
    client.event("stopped");
    let (frame, routine, line) = client.top_frame(1);
    assert_eq!((routine.as_str(), line), ("main", line_of(ROBOT, "count := count + 1;")));
    assert_eq!(client.evaluate(frame, "count"), "51");

    // Over the TPWrite: its line comes out; over Bump, then back over it.
    client.ok("next", json!({"threadId": 1}));
    client.event("stopped");
    client.ok("next", json!({"threadId": 1}));
    let (_, output) = client.event("stopped");
    assert!(output.contains(&"count 52\n".to_owned()), "{output:?}");
    client.ok("next", json!({"threadId": 1}));
    client.event("stopped");
    let (frame, _, line) = client.top_frame(1);
    assert_eq!((line, client.evaluate(frame, "count")), (line_of(ROBOT, "total := count;"), "152".to_owned()));
    client.ok("stepBack", json!({"threadId": 1}));
    client.event("stopped");
    let (frame, _, line) = client.top_frame(1);
    assert_eq!((line, client.evaluate(frame, "count")), (line_of(ROBOT, "Bump;"), "52".to_owned()));

    client.ok("continue", json!({"threadId": 1}));
    let (_, output) = client.event("terminated");
    // T_OTHER stood stopped with the program: its loop ends only now.
    assert!(output.contains(&"other done\n".to_owned()), "{output:?}");
    client.event("exited");
    client.ok("disconnect", json!({}));
}

const OPTIONAL: &str = "MODULE Opt
  PROC main()
    Show 2.345;
    Show 2.345 \\Dec:=1;
  ENDPROC
  PROC Show(num x \\num Dec)
    TPWrite \"x \" \\Num:=x;
  ENDPROC
ENDMODULE
";

#[test]
fn evaluated_calls_take_named_optional_and_conditional_arguments() {
    let mut client = Client::start(Program(vec![("T_ROB1", "/dap/T_ROB1/Opt.mod", OPTIONAL)]));
    let line = line_of(OPTIONAL, "TPWrite");
    client.launch_with_breakpoints("/dap/T_ROB1/Opt.mod", json!([{"line": line}]));
    client.event("stopped");
    let (frame, _, _) = client.top_frame(1);
    // Round(Val \Dec): 2.345 to one decimal is 2.3; Trunc to two is 2.34.
    assert_eq!(client.evaluate(frame, "Round(x \\Dec:=1)"), "2.3");
    assert_eq!(client.evaluate(frame, "Trunc(x \\Dec:=2)"), "2.34");
    // Required arguments by name: characters 2 to 4 of "abcdef".
    assert_eq!(client.evaluate(frame, "StrPart(Str:=\"abcdef\", ChPos:=2, Len:=3)"), "\"bcd\"");
    // \Dec?Dec forwards the frame's Dec, not passed in the first call: no decimals.
    assert_eq!(client.evaluate(frame, "Round(x \\Dec?Dec)"), "2");
    // A later argument without the one before it is not evaluated.
    let failed = client.request("evaluate", json!({"expression": "Round(\\Dec:=1)", "frameId": frame}));
    assert!(failed["message"].as_str().unwrap_or_default().contains("without `Val`"), "{failed}");
    // StrFind's \NotInSet needs the built-in's general form.
    let failed =
        client.request("evaluate", json!({"expression": "StrFind(\"abc\", 1, \"c\" \\NotInSet)", "frameId": frame}));
    assert!(failed["message"].as_str().unwrap_or_default().contains("does not evaluate this form"), "{failed}");
    // A parameter the built-in does not have.
    let failed = client.request("evaluate", json!({"expression": "Round(x \\Digits:=1)", "frameId": frame}));
    assert!(failed["message"].as_str().unwrap_or_default().contains("no parameter `Digits`"), "{failed}");
    // The second call passes \Dec:=1, and \Dec?Dec forwards it.
    client.ok("continue", json!({"threadId": 1}));
    client.event("stopped");
    let (frame, _, _) = client.top_frame(1);
    assert_eq!(client.evaluate(frame, "Round(x \\Dec?Dec)"), "2.3");
    client.ok("disconnect", json!({}));
}

#[test]
fn a_conditional_breakpoint_stops_only_where_it_holds() {
    let mut client = Client::start(two_tasks());
    let line = line_of(OTHER, "ticks := ticks + 1;");
    client.launch_with_breakpoints("/dap/T_OTHER/Other.mod", json!([{"line": line, "condition": "ticks = 3"}]));
    let (stopped, _) = client.event("stopped");
    assert_eq!((stopped["reason"].as_str(), stopped["threadId"].as_u64()), (Some("breakpoint"), Some(2)));
    let (frame, _, at) = client.top_frame(2);
    assert_eq!((at, client.evaluate(frame, "ticks")), (line, "3".to_owned()));
    // Built-in functions without side effects are called: |3 - 10| = 7; 3 with one
    // decimal is "3.0"; "ab" + "c" has 3 characters.
    assert_eq!(client.evaluate(frame, "Abs(ticks - 10)"), "7");
    assert_eq!(client.evaluate(frame, "NumToStr(ticks, 1)"), "\"3.0\"");
    assert_eq!(client.evaluate(frame, "StrLen(\"ab\" + \"c\")"), "3");
    // Sqrt of a negative number raises an error: refused, not raised.
    let failed = client.request("evaluate", json!({"expression": "Sqrt(-ticks)", "frameId": frame}));
    assert!(failed["message"].as_str().unwrap_or_default().contains("raise an error"), "{failed}");
    // A built-in that reads the controller (the clock) has no pure form: refused.
    let failed = client.request("evaluate", json!({"expression": "CTime()", "frameId": frame}));
    assert!(failed["message"].as_str().unwrap_or_default().contains("without side effects"), "{failed}");
    client.ok("disconnect", json!({}));
}

const SPIN: &str = "MODULE Spin
  VAR num n := 0;
  VAR num answer := 0;
  PROC main()
    TPReadNum answer, \"How many?\";
    TPWrite \"got \" \\Num:=answer;
    WHILE TRUE DO
      n := n + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
";

#[test]
fn a_dialog_is_answered_from_the_console_and_pause_stops_a_loop() {
    let mut client = Client::start(Program(vec![("T_ROB1", "/dap/Spin.mod", SPIN)]));
    client.launch(json!({"program": "/dap", "stopOnEntry": true}), "/dap/Spin.mod", json!([]));
    let (stopped, _) = client.event("stopped");
    assert_eq!(stopped["reason"], "entry");
    let (frame, routine, line) = client.top_frame(1);
    assert_eq!((routine.as_str(), line), ("main", line_of(SPIN, "TPReadNum")));
    // Nothing precedes main's first statement: RAPID refuses the step backward.
    assert_eq!(client.request("stepBack", json!({"threadId": 1}))["success"], false);
    // main has no parameter or data `x`: writing it is refused, saying so.
    let scopes = client.ok("scopes", json!({"frameId": frame}));
    let locals = scopes["scopes"][0]["variablesReference"].as_i64().unwrap();
    let refused = client.request("setVariable", json!({"variablesReference": locals, "name": "x", "value": "1"}));
    assert!(refused["message"].as_str().unwrap_or_default().contains("no parameter or data `x`"), "{refused}");

    // A datum changed at the entry keeps its value when the program starts.
    let data = scopes["scopes"][1]["variablesReference"].as_i64().unwrap();
    client.ok("setVariable", json!({"variablesReference": data, "name": "n", "value": "100"}));
    client.ok("continue", json!({"threadId": 1}));
    client.output_with("How many?");
    // The task waits in its dialog, before the loop: n is still what was set.
    assert_eq!(client.evaluate(frame, "n"), "100");
    let answered = client.ok("evaluate", json!({"expression": ":answer 3", "context": "repl"}));
    assert_eq!(answered["result"], "answered \"How many?\"");
    client.output_with("got 3");

    client.ok("pause", json!({"threadId": 1}));
    let (stopped, _) = client.event("stopped");
    assert_eq!((stopped["reason"].as_str(), stopped["threadId"].as_u64()), (Some("pause"), Some(1)));
    let (frame, _, line) = client.top_frame(1);
    assert!(line == line_of(SPIN, "WHILE TRUE") || line == line_of(SPIN, "n := n + 1;"), "paused at line {line}");
    assert_eq!(client.evaluate(frame, "answer"), "3");
    assert_eq!(client.evaluate(frame, "n > 100"), "TRUE");
    client.ok("disconnect", json!({}));
}

#[test]
fn a_speed_must_be_positive() {
    let mut client = Client::start(two_tasks());
    client.ok("initialize", json!({"adapterID": "rapid"}));
    let refused = client.request("launch", json!({"program": "/dap", "speed": 0}));
    assert_eq!(refused["success"], false);
    assert!(refused["message"].as_str().unwrap_or_default().contains("speed"), "{refused}");
    client.ok("launch", json!({"program": "/dap", "speed": 4}));
    client.event("initialized");
    client.ok("disconnect", json!({}));
}

#[test]
fn a_log_point_writes_and_a_hit_count_stops_late() {
    let mut client = Client::start(two_tasks());
    let log = json!({"line": line_of(OTHER, "ticks := ticks + 1;"), "logMessage": "tick {ticks} of {5}"});
    let third = json!({"line": line_of(OTHER, "WaitTime 0.1;"), "hitCondition": "3"});
    let set = client.launch_with_breakpoints("/dap/T_OTHER/Other.mod", json!([log, third]));
    assert_eq!(
        (set["breakpoints"][0]["verified"].as_bool(), set["breakpoints"][1]["verified"].as_bool()),
        (Some(true), Some(true))
    );
    // The log point is passed before each increment: ticks is 0, 1, 2 before the
    // third WaitTime, where ticks is 3.
    let (stopped, output) = client.event("stopped");
    assert_eq!((stopped["reason"].as_str(), stopped["threadId"].as_u64()), (Some("breakpoint"), Some(2)));
    let logged: Vec<&str> = output.iter().filter(|o| o.starts_with("tick")).map(String::as_str).collect();
    assert_eq!(logged, ["tick 0 of 5\n", "tick 1 of 5\n", "tick 2 of 5\n"]);
    let (frame, _, _) = client.top_frame(2);
    assert_eq!(client.evaluate(frame, "ticks"), "3");
    client.ok("disconnect", json!({}));
}

const FRAMES: &str = "MODULE Frames
  VAR num total := 0;
  VAR pos where := [1, 2, 3];
  PROC main()
    VAR num mine := 5;
    Add total, 10, where;
    TPWrite \"total \" \\Num:=total;
    TPWrite \"mine \" \\Num:=mine;
  ENDPROC
  FUNC num Twice(num x)
    RETURN x * 2;
  ENDFUNC
  PROC Add(INOUT num sum, num inc, VAR pos p)
    CONST num limit := 99;
    VAR num scratch := 0;
    sum := sum + inc;
    scratch := inc;
  ENDPROC
ENDMODULE
";

#[test]
fn a_routines_data_and_parameters_are_written_in_any_frame() {
    let mut client = Client::start(Program(vec![("T_ROB1", "/dap/Frames.mod", FRAMES)]));
    let line = line_of(FRAMES, "sum := sum + inc;");
    client.launch_with_breakpoints("/dap/Frames.mod", json!([{"line": line}]));
    client.event("stopped");
    let trace = client.ok("stackTrace", json!({"threadId": 1}));
    let (add, main) =
        (trace["stackFrames"][0]["id"].as_i64().unwrap(), trace["stackFrames"][1]["id"].as_i64().unwrap());
    let locals_of = |client: &mut Client, frame: i64| {
        let scopes = client.ok("scopes", json!({"frameId": frame}));
        scopes["scopes"][0]["variablesReference"].as_i64().unwrap()
    };
    let add_locals = locals_of(&mut client, add);
    let set = |client: &mut Client, reference: i64, name: &str, value: &str| {
        client.request("setVariable", json!({"variablesReference": reference, "name": name, "value": value}))
    };
    // A parameter passed by value changes in the frame alone.
    assert_eq!(set(&mut client, add_locals, "inc", "7")["body"]["value"], "7");
    assert_eq!(client.evaluate(main, "total"), "0");
    // INOUT writes through to the argument, main's `total` (§1.5).
    assert_eq!(set(&mut client, add_locals, "sum", "100")["body"]["value"], "100");
    assert_eq!(client.evaluate(main, "total"), "100");
    // A component of a VAR parameter, expanded: main's `where` changes.
    let vars = client.variables(add_locals);
    let p = value_of(&vars, "p").2;
    assert!(p > 0, "p expands: {vars:?}");
    assert_eq!(set(&mut client, p, "y", "20")["body"]["value"], "20");
    assert_eq!(client.evaluate(main, "where.y"), "20");
    // Routine data can be written; a CONST and a literal of another type cannot.
    assert_eq!(set(&mut client, add_locals, "scratch", "-1")["body"]["value"], "-1");
    let refused = set(&mut client, add_locals, "limit", "1");
    assert_eq!(refused["success"], false);
    assert!(refused["message"].as_str().unwrap_or_default().contains("CONST"), "{refused}");
    assert_eq!(client.evaluate(add, "limit"), "99");
    let refused = set(&mut client, add_locals, "inc", "\"x\"");
    assert_eq!(refused["success"], false);
    assert_eq!(client.evaluate(add, "inc"), "7");
    // A function of the program could change the program's state: never run.
    let refused = client.request("evaluate", json!({"expression": "Twice(inc)", "frameId": add}));
    assert!(refused["message"].as_str().unwrap_or_default().contains("function of the program"), "{refused}");
    // The caller's frame: main's routine data.
    let main_locals = locals_of(&mut client, main);
    assert_eq!(set(&mut client, main_locals, "mine", "42")["body"]["value"], "42");
    // The program goes on with what was set: total = 100 + 7.
    client.ok("continue", json!({"threadId": 1}));
    client.output_with("total 107");
    client.output_with("mine 42");
    client.ok("disconnect", json!({}));
}

const ERRS: &str = "MODULE Errs
  VAR num zero := 0;
  VAR num result := 0;
  PROC main()
    Safe;
    result := 10 / zero;
    TPWrite \"not reached\";
  ENDPROC
  PROC Safe()
    result := 1 / zero;
  ERROR
    result := -1;
    TRYNEXT;
  ENDPROC
ENDMODULE
";

impl Client {
    /// Launches `ERRS` with the exception filters given.
    fn launch_with_filters(&mut self, filters: Value) {
        let init = self.ok("initialize", json!({"adapterID": "rapid"}));
        let offered: Vec<&str> = init["exceptionBreakpointFilters"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["filter"].as_str().unwrap())
            .collect();
        assert_eq!(offered, ["raised", "uncaught"]);
        self.ok("launch", json!({"program": "/dap"}));
        self.event("initialized");
        self.ok("setExceptionBreakpoints", json!({"filters": filters}));
        self.ok("configurationDone", json!({}));
    }
}

#[test]
fn errors_stop_where_raised_and_before_they_stop_the_task() {
    let mut client = Client::start(Program(vec![("T_ROB1", "/dap/Errs.mod", ERRS)]));
    client.launch_with_filters(json!(["raised", "uncaught"]));
    // Raised: the task stands at the first statement of Safe's ERROR handler, which
    // has not run yet.
    let (stopped, _) = client.event("stopped");
    assert_eq!(stopped["reason"], "exception");
    assert!(stopped["text"].as_str().unwrap_or_default().contains("ERR_DIVZERO"), "{stopped}");
    let (frame, routine, line) = client.top_frame(1);
    assert_eq!((routine.as_str(), line), ("Safe (ERROR)", line_of(ERRS, "result := -1;")));
    assert_eq!(client.evaluate(frame, "result"), "0");
    let info = client.ok("exceptionInfo", json!({"threadId": 1}));
    assert_eq!((info["exceptionId"].as_str(), info["breakMode"].as_str()), (Some("ERR_DIVZERO"), Some("always")));
    // Uncaught: main has no ERROR handler; the task stands at the failing statement,
    // after the handler ran (result -1) and TRYNEXT went on.
    client.ok("continue", json!({"threadId": 1}));
    let (stopped, _) = client.event("stopped");
    assert_eq!(stopped["reason"], "exception");
    assert!(stopped["text"].as_str().unwrap_or_default().contains("uncaught"), "{stopped}");
    let (frame, routine, line) = client.top_frame(1);
    assert_eq!((routine.as_str(), line), ("main", line_of(ERRS, "result := 10 / zero;")));
    assert_eq!(client.evaluate(frame, "result"), "-1");
    let info = client.ok("exceptionInfo", json!({"threadId": 1}));
    assert_eq!(info["breakMode"], "unhandled");
    // Going on, the task stops with the error: the statement after never runs.
    client.ok("continue", json!({"threadId": 1}));
    let (_, output) = client.event("terminated");
    assert!(output.iter().any(|o| o.contains("ERR_DIVZERO") || o.contains("ended")), "{output:?}");
    assert!(!output.iter().any(|o| o.contains("not reached")), "{output:?}");
    client.ok("disconnect", json!({}));
}

#[test]
fn without_the_uncaught_filter_only_raised_errors_stop() {
    let mut client = Client::start(Program(vec![("T_ROB1", "/dap/Errs.mod", ERRS)]));
    client.launch_with_filters(json!(["raised"]));
    let (stopped, _) = client.event("stopped");
    assert_eq!(stopped["reason"], "exception");
    client.ok("continue", json!({"threadId": 1}));
    // The next stop would be the uncaught error: none comes, the program ends.
    loop {
        let message = client.next_message();
        assert_ne!(message["event"], "stopped", "{message}");
        if message["event"] == "terminated" {
            break;
        }
    }
    let refused = client.request("setExceptionBreakpoints", json!({"filters": ["all"]}));
    assert_eq!(refused["success"], false);
    client.ok("disconnect", json!({}));
}
