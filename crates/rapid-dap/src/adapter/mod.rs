//! Requests, responses and events: the adapter's state between messages and how
//! each request maps onto the session (threads are the controller's tasks, their
//! ids the task's position plus one; a frame id packs the task and the frame's
//! depth; variables references are handles valid while the program stands still).
//!
//! The program runs in slices ([`Adapter::advance`]) between requests; what the
//! session reports (a breakpoint, a step done, the end) becomes a `stopped` or
//! `terminated` event, and the change stream's pendant lines and dialogs become
//! `output` events.

mod breakpoints;
mod inspect;

use std::collections::{HashMap, VecDeque};
use std::path::PathBuf;
use std::time::Duration;

use rapid_controller::api::{Change, ClockPolicy, ErrorHit, RunOutcome, Session, StartFrom, StepKind, Subscription};
use rapid_controller::StopKind;
use serde_json::{json, Value};

use crate::vars::Handles;
use crate::{LaunchArgs, Launcher};

/// Statements one slice of [`Adapter::advance`] runs (all tasks together).
const SLICE: u64 = 5_000;

/// Frames per task a frame id can tell apart.
const FRAMES_PER_TASK: i64 = 100_000;

/// A request's failure, shown to the user.
type Failure = String;

/// The debug session's state.
pub(crate) struct Adapter<'l> {
    launcher: &'l dyn Launcher,
    session: Option<Session>,
    subscription: Option<Subscription>,
    seq: i64,
    outgoing: Vec<Value>,
    /// The program runs (or a step is carried out): the loop advances it.
    running: bool,
    /// The paced clock asked the loop to wait this long before the next slice.
    idle: Option<Duration>,
    /// Why the program will have stopped when it next stands still, and in which task.
    stop_reason: Option<(&'static str, usize)>,
    /// The program was started once (the first start is from Main).
    started: bool,
    stop_on_entry: bool,
    /// Breakpoints by file (as the client named it): their lines and conditions.
    breakpoints: HashMap<String, Vec<breakpoints::Point>>,
    handles: Handles,
    answers: VecDeque<String>,
    done: bool,
    /// The error the program stands stopped at (an exception breakpoint), by thread.
    exception: Option<(i64, ErrorHit)>,
}

impl<'l> Adapter<'l> {
    pub(crate) fn new(launcher: &'l dyn Launcher) -> Adapter<'l> {
        Adapter {
            launcher,
            session: None,
            subscription: None,
            seq: 0,
            outgoing: Vec::new(),
            running: false,
            idle: None,
            stop_reason: None,
            started: false,
            stop_on_entry: false,
            breakpoints: HashMap::new(),
            handles: Handles::default(),
            answers: VecDeque::new(),
            done: false,
            exception: None,
        }
    }

    pub(crate) fn is_running(&self) -> bool {
        self.running
    }

    /// How long the loop may wait for a request before the next slice (the clock
    /// is paced: nothing runs before then).
    pub(crate) fn take_idle(&mut self) -> Option<Duration> {
        self.idle.take()
    }

    /// The client disconnected: the loop ends.
    pub(crate) fn is_done(&self) -> bool {
        self.done
    }

    /// The messages to write, in order.
    pub(crate) fn take_outgoing(&mut self) -> Vec<Value> {
        std::mem::take(&mut self.outgoing)
    }

    /// Handles one message from the client (only requests are expected).
    pub(crate) fn handle(&mut self, message: &Value) {
        if message["type"] != "request" {
            return;
        }
        let command = message["command"].as_str().unwrap_or_default().to_owned();
        let args = &message["arguments"];
        let outcome = self.request(&command, args);
        let request_seq = message["seq"].as_i64().unwrap_or(0);
        let response = match outcome {
            Ok(body) => json!({"type": "response", "request_seq": request_seq, "success": true,
                "command": command, "body": body}),
            Err(why) => json!({"type": "response", "request_seq": request_seq, "success": false,
                "command": command, "message": why, "body": {"error": {"id": 1, "format": why}}}),
        };
        self.send(response);
        self.after(&command);
    }

    fn request(&mut self, command: &str, args: &Value) -> Result<Value, Failure> {
        match command {
            "initialize" => Ok(capabilities()),
            "launch" => self.launch(args),
            "setBreakpoints" => self.set_breakpoints(args),
            "setExceptionBreakpoints" => self.set_exception_breakpoints(args),
            "exceptionInfo" => self.exception_info(args),
            "configurationDone" => Ok(Value::Null),
            "threads" => self.threads(),
            "stackTrace" => self.stack_trace(args),
            "scopes" => self.scopes(args),
            "variables" => self.variables(args),
            "setVariable" => self.set_variable(args),
            "evaluate" => self.evaluate(args),
            "continue" => self.resume().map(|()| json!({"allThreadsContinued": true})),
            "next" => self.step(args, StepKind::Over),
            "stepIn" => self.step(args, StepKind::Into),
            "stepOut" => self.step(args, StepKind::Out),
            "stepBack" => self.step_back(args),
            "pause" => self.pause(args),
            "rapidAnswer" => self.answer(args),
            "terminate" | "disconnect" => {
                self.running = false;
                Ok(Value::Null)
            }
            other => Err(format!("the request `{other}` is not supported")),
        }
    }

    /// What follows a request's response: the `initialized` event after launch, the
    /// program's start after the configuration, the end after a disconnect.
    fn after(&mut self, command: &str) {
        match command {
            "launch" if self.session.is_some() => self.event("initialized", Value::Null),
            "configurationDone" if self.session.is_some() => self.configured(),
            "terminate" => {
                self.event("terminated", Value::Null);
            }
            "disconnect" => self.done = true,
            _ => {}
        }
    }

    fn send(&mut self, mut message: Value) {
        self.seq += 1;
        message["seq"] = json!(self.seq);
        self.outgoing.push(message);
    }

    fn event(&mut self, event: &str, body: Value) {
        self.send(json!({"type": "event", "event": event, "body": body}));
    }

    fn output(&mut self, category: &str, text: String) {
        self.event("output", json!({"category": category, "output": text}));
    }

    fn session(&mut self) -> Result<&mut Session, Failure> {
        self.session.as_mut().ok_or_else(|| "no program is launched".to_owned())
    }

    fn launch(&mut self, args: &Value) -> Result<Value, Failure> {
        let program: Vec<PathBuf> = match &args["program"] {
            Value::String(path) => vec![PathBuf::from(path)],
            Value::Array(paths) => paths.iter().filter_map(Value::as_str).map(PathBuf::from).collect(),
            _ => Vec::new(),
        };
        if program.is_empty() {
            return Err("launch needs `program`: a module, folder, backup or manifest".to_owned());
        }
        let path = |key: &str| args[key].as_str().map(PathBuf::from);
        let launch = LaunchArgs {
            program,
            stimulus: path("stimulus"),
            tp_input: path("tpInput"),
            stop_on_entry: args["stopOnEntry"].as_bool().unwrap_or(false),
        };
        let speed = match &args["speed"] {
            Value::Null => 1.0,
            speed => speed.as_f64().filter(|s| *s > 0.0 && s.is_finite()).ok_or("`speed` must be a positive number")?,
        };
        let launched = self.launcher.launch(&launch)?;
        let mut session = launched.session;
        // The controller's clock follows the wall clock (`speed` times as fast), as
        // on the controller and in `rapid serve`: a program waiting without end then
        // waits, rather than racing a virtual clock on.
        session.set_clock(ClockPolicy::Paced { rate: speed });
        self.subscription = Some(session.subscribe());
        self.session = Some(session);
        self.answers = launched.answers.into();
        self.stop_on_entry = launch.stop_on_entry;
        Ok(Value::Null)
    }

    /// The configuration is done: the program starts (or stands at its entry).
    fn configured(&mut self) {
        if self.stop_on_entry {
            // The program pointers stand at the entry routines already; going on from
            // them keeps what the user changes meanwhile (a start from Main would
            // give the data its initial values again).
            self.started = true;
            self.stopped("entry", 0);
            return;
        }
        if let Err(why) = self.resume() {
            self.output("stderr", format!("the program cannot start: {why}\n"));
        }
    }

    fn threads(&mut self) -> Result<Value, Failure> {
        let tasks = self.session()?.tasks();
        let threads: Vec<Value> =
            tasks.iter().enumerate().map(|(at, t)| json!({"id": at + 1, "name": t.name})).collect();
        Ok(json!({"threads": threads}))
    }

    /// The name of the task thread `id` stands for.
    fn task_of_thread(&mut self, id: i64) -> Result<String, Failure> {
        let tasks = self.session()?.tasks();
        let at = usize::try_from(id - 1).map_err(|_| format!("no thread {id}"))?;
        tasks.get(at).map(|t| t.name.clone()).ok_or_else(|| format!("no thread {id}"))
    }

    /// The task and frame a frame id names.
    fn frame_of(&mut self, id: i64) -> Result<(String, usize), Failure> {
        let task = self.task_of_thread(id / FRAMES_PER_TASK)?;
        Ok((task, (id % FRAMES_PER_TASK) as usize))
    }

    /// Continues the stopped program (from Main the first time, as `rapid run` starts).
    fn resume(&mut self) -> Result<(), Failure> {
        let from = if self.started { StartFrom::Pointer } else { StartFrom::Main };
        self.session()?.start(from).map_err(|e| e.to_string())?;
        self.started = true;
        self.go_on("pause", 0);
        Ok(())
    }

    /// The program runs on: handles are forgotten, a stop is reported as `reason`.
    fn go_on(&mut self, reason: &'static str, task: usize) {
        self.handles.clear();
        self.exception = None;
        self.running = true;
        self.stop_reason = Some((reason, task));
    }

    fn step(&mut self, args: &Value, kind: StepKind) -> Result<Value, Failure> {
        let thread = args["threadId"].as_i64().ok_or("a step needs `threadId`")?;
        let task = self.task_of_thread(thread)?;
        self.session()?.step(&task, kind).map_err(|e| e.to_string())?;
        self.started = true;
        self.go_on("step", (thread - 1) as usize);
        Ok(Value::Null)
    }

    /// One step backward (§1.21), done at once: the program stands stopped after it.
    fn step_back(&mut self, args: &Value) -> Result<Value, Failure> {
        let thread = args["threadId"].as_i64().ok_or("stepBack needs `threadId`")?;
        let task = self.task_of_thread(thread)?;
        let done = self.session()?.step_backward(&task).map_err(|e| e.to_string())?;
        if let rapid_vm::BackStep::RanBackwardHandler(routine) = done {
            self.output("console", format!("{routine}'s BACKWARD handler ran\n"));
        }
        self.handles.clear();
        self.forward_changes();
        self.stopped("step", (thread - 1) as usize);
        Ok(Value::Null)
    }

    fn pause(&mut self, args: &Value) -> Result<Value, Failure> {
        let thread = args["threadId"].as_i64().unwrap_or(1);
        if !self.running {
            return Ok(Value::Null);
        }
        self.session()?.stop(StopKind::Stop).map_err(|e| e.to_string())?;
        self.stop_reason = Some(("pause", usize::try_from(thread - 1).unwrap_or(0)));
        Ok(Value::Null)
    }

    /// Runs one slice of the program and reports what became of it.
    pub(crate) fn advance(&mut self) {
        let Some(session) = self.session.as_mut() else {
            self.running = false;
            return;
        };
        let outcome = session.run(SLICE);
        self.forward_changes();
        match outcome {
            RunOutcome::Running => {}
            RunOutcome::Sleep(wait) => self.idle = Some(wait),
            RunOutcome::Breakpoint(hit) => self.at_breakpoint(&hit),
            RunOutcome::Stopped => {
                let (reason, task) = self.stop_reason.unwrap_or(("pause", 0));
                self.stopped(reason, task);
            }
            RunOutcome::Ended => {
                self.running = false;
                self.event("terminated", Value::Null);
                self.event("exited", json!({"exitCode": 0}));
            }
        }
    }

    pub(super) fn stopped(&mut self, reason: &str, task: usize) {
        self.running = false;
        self.stop_reason = None;
        self.handles.clear();
        self.event("stopped", json!({"reason": reason, "threadId": task + 1, "allThreadsStopped": true}));
    }

    /// The pendant's lines and dialogs, and tasks that failed, as output events; a
    /// dialog is answered from the launch's answers while they last.
    fn forward_changes(&mut self) {
        let (Some(session), Some(sub)) = (self.session.as_mut(), self.subscription) else { return };
        let Ok(batch) = session.poll(sub) else { return };
        for change in batch.changes {
            match change {
                Change::TpWrite { text } => self.output("stdout", format!("{text}\n")),
                Change::PromptOpened { id, task, text } => self.prompt_opened(id, &task, &text),
                Change::Task { task, state } if state.starts_with("ended: ") && state != "ended: cycle" => {
                    self.output("stderr", format!("task {task} {state}\n"));
                }
                _ => {}
            }
        }
    }

    fn prompt_opened(&mut self, id: u64, task: &str, text: &str) {
        if let Some(answer) = self.answers.pop_front() {
            self.output("console", format!("[pendant {task}] {text} -> {answer} (from tpInput)\n"));
            if let Some(session) = self.session.as_mut() {
                let _ = session.answer(id, &answer);
            }
            return;
        }
        self.output(
            "console",
            format!("[pendant {task}] {text}\n  answer in the debug console with `:answer TEXT` (dialog {id})\n"),
        );
    }
}

/// What the adapter can do (the `initialize` response).
fn capabilities() -> Value {
    json!({
        "supportsConfigurationDoneRequest": true,
        "supportsConditionalBreakpoints": true,
        "supportsHitConditionalBreakpoints": true,
        "supportsLogPoints": true,
        "supportsSetVariable": true,
        "supportsEvaluateForHovers": true,
        "supportsStepBack": true,
        "supportsExceptionInfoRequest": true,
        "exceptionBreakpointFilters": [
            {"filter": "raised", "label": "Raised errors", "default": false,
             "description": "Stop when a RAPID error is raised, before the ERROR handler that takes it runs"},
            {"filter": "uncaught", "label": "Uncaught errors", "default": false,
             "description": "Stop when a RAPID error reaches no ERROR handler, before it stops the task"},
        ],
        "supportsTerminateRequest": true,
        "supportsSingleThreadExecutionRequests": false,
    })
}
