//! Breakpoints as the client sets them, and what happens when the program reaches
//! one: its condition (a RAPID expression) and hit count decide whether it stops; a
//! log point writes its message and goes on.

use rapid_controller::api::{BreakpointHit, ErrorHit, StartFrom};
use serde_json::{json, Value};

use super::{Adapter, Failure};

/// One breakpoint of a file, as the client set it.
#[derive(Debug, Clone, Default)]
pub(super) struct Point {
    line: u32,
    /// A RAPID expression: the program stops only where it is TRUE.
    condition: Option<String>,
    /// The program stops from this hit on (where the condition holds).
    hit_condition: Option<u64>,
    /// A log point's message: `{expression}` parts are evaluated; it never stops.
    log: Option<String>,
    hits: u64,
}

impl Point {
    /// The breakpoint `b` of a setBreakpoints request.
    fn from_request(b: &Value) -> Result<Point, String> {
        let line = b["line"].as_u64().and_then(|l| u32::try_from(l).ok()).ok_or("a breakpoint needs a `line`")?;
        let text = |key: &str| b[key].as_str().filter(|c| !c.trim().is_empty()).map(str::to_owned);
        let hit_condition = match text("hitCondition") {
            Some(count) => Some(count.trim().parse::<u64>().map_err(|_| format!("hit count `{count}` is no number"))?),
            None => None,
        };
        Ok(Point { line, condition: text("condition"), hit_condition, log: text("logMessage"), hits: 0 })
    }
}

impl Adapter<'_> {
    pub(super) fn set_breakpoints(&mut self, args: &Value) -> Result<Value, Failure> {
        let given = args["source"]["path"].as_str().ok_or("setBreakpoints needs `source.path`")?.to_owned();
        let file = canonical(&given);
        self.session()?;
        for point in self.breakpoints.remove(&file).unwrap_or_default() {
            self.session()?.clear_breakpoint(&file, point.line);
        }
        let mut answered = Vec::new();
        let mut kept = Vec::new();
        for wanted in args["breakpoints"].as_array().map_or(&[][..], Vec::as_slice) {
            let line = wanted["line"].clone();
            let point = match Point::from_request(wanted) {
                Ok(point) => point,
                Err(why) => {
                    answered.push(json!({"verified": false, "line": line, "message": why}));
                    continue;
                }
            };
            match self.session()?.set_breakpoint(&file, point.line) {
                Ok(at) => {
                    let line = at.first().map_or(point.line, |l| l.line);
                    answered.push(json!({"verified": true, "line": line}));
                    kept.push(Point { line, ..point });
                }
                Err(why) => answered.push(json!({"verified": false, "line": line, "message": why.to_string()})),
            }
        }
        self.breakpoints.insert(file, kept);
        Ok(json!({"breakpoints": answered}))
    }

    /// The program stopped at a breakpoint: reported when its condition holds and
    /// its hit count is reached, else (and for a log point) the program goes on.
    pub(super) fn at_breakpoint(&mut self, hit: &BreakpointHit) {
        let task = self
            .session
            .as_ref()
            .map_or(0, |s| s.tasks().iter().position(|t| t.name.eq_ignore_ascii_case(&hit.at.task)).unwrap_or(0));
        if let Some(error) = &hit.error {
            return self.at_error(task, error.clone());
        }
        let point = self.breakpoints.get(&hit.file).and_then(|points| points.iter().find(|p| p.line == hit.line));
        let Some(point) = point.cloned() else { return self.stopped("breakpoint", task) };
        if let Some(condition) = &point.condition {
            match self.condition_holds(&hit.at.task, condition) {
                Some(false) => return self.go_on_past(task),
                Some(true) => {}
                // It cannot be evaluated: the program stops, and the output says why.
                None => return self.stopped("breakpoint", task),
            }
        }
        let hits = self.count_hit(&hit.file, hit.line);
        if point.hit_condition.is_some_and(|from| hits < from) {
            return self.go_on_past(task);
        }
        if let Some(message) = &point.log {
            let text = self.interpolate(&hit.at.task, message);
            self.output("console", format!("{text}\n"));
            return self.go_on_past(task);
        }
        self.stopped("breakpoint", task);
    }

    /// Whether `condition` holds in task `task`'s innermost frame; None (after an
    /// output saying why) when it is no bool or cannot be evaluated.
    fn condition_holds(&mut self, task: &str, condition: &str) -> Option<bool> {
        let value = self.session.as_mut()?.evaluate(task, 0, condition);
        match value {
            Ok(tree) if tree.value == "TRUE" => Some(true),
            Ok(tree) if tree.value == "FALSE" => Some(false),
            Ok(tree) => {
                self.output("stderr", format!("breakpoint condition `{condition}` is no bool: {}\n", tree.value));
                None
            }
            Err(why) => {
                self.output("stderr", format!("breakpoint condition `{condition}`: {why}\n"));
                None
            }
        }
    }

    /// Counts a hit of the breakpoint at `line` of `file`; the hits so far.
    fn count_hit(&mut self, file: &str, line: u32) -> u64 {
        let point = self.breakpoints.get_mut(file).and_then(|points| points.iter_mut().find(|p| p.line == line));
        point.map_or(0, |p| {
            p.hits += 1;
            p.hits
        })
    }

    /// A log point's message with each `{expression}` replaced by its value.
    fn interpolate(&mut self, task: &str, message: &str) -> String {
        let mut out = String::new();
        let mut rest = message;
        while let Some(open) = rest.find('{') {
            let Some(close) = rest[open..].find('}').map(|c| open + c) else { break };
            out.push_str(&rest[..open]);
            let expression = &rest[open + 1..close];
            let value = self.session.as_mut().map(|s| s.evaluate(task, 0, expression));
            match value {
                Some(Ok(tree)) => out.push_str(&tree.value),
                Some(Err(why)) => out.push_str(&format!("<{why}>")),
                None => {}
            }
            rest = &rest[close + 1..];
        }
        out.push_str(rest);
        out
    }

    /// A breakpoint that does not stop: a step under way ends there (the controller
    /// ended it at the breakpoint), else the program goes on.
    fn go_on_past(&mut self, task: usize) {
        if let Some(("step", stepped)) = self.stop_reason {
            return self.stopped("step", stepped);
        }
        let started = self.session().and_then(|s| s.start(StartFrom::Pointer).map_err(|e| e.to_string()));
        if let Err(why) = started {
            self.output("stderr", format!("the program cannot go on: {why}\n"));
            self.stopped("breakpoint", task);
        }
    }
}

/// The path a breakpoint's file is known by: the file's canonical path, as the
/// launcher loads modules (the text as given when the file cannot be found).
fn canonical(path: &str) -> String {
    std::fs::canonicalize(path).map_or_else(|_| path.to_owned(), |p| p.to_string_lossy().into_owned())
}

impl Adapter<'_> {
    /// `setExceptionBreakpoints {filters}`: "raised" and "uncaught" (docs/dap.md).
    pub(super) fn set_exception_breakpoints(&mut self, args: &Value) -> Result<Value, Failure> {
        let filters: Vec<&str> =
            args["filters"].as_array().map(|f| f.iter().filter_map(Value::as_str).collect()).unwrap_or_default();
        if let Some(unknown) = filters.iter().find(|f| !matches!(**f, "raised" | "uncaught")) {
            return Err(format!("no exception filter `{unknown}` (raised, uncaught)"));
        }
        let (raised, uncaught) = (filters.contains(&"raised"), filters.contains(&"uncaught"));
        self.session()?.set_error_breaks(raised, uncaught);
        let verified: Vec<Value> = filters.iter().map(|_| json!({"verified": true})).collect();
        Ok(json!({"breakpoints": verified}))
    }

    /// The program stopped at an error: a `stopped` event of reason `exception` whose
    /// text names the error; `exceptionInfo` tells the rest.
    fn at_error(&mut self, task: usize, error: ErrorHit) {
        let text = error_text(&error);
        let thread = task as i64 + 1;
        self.exception = Some((thread, error));
        self.running = false;
        self.stop_reason = None;
        self.handles.clear();
        self.event(
            "stopped",
            json!({"reason": "exception", "description": text, "text": text, "threadId": thread,
                "allThreadsStopped": true}),
        );
    }

    /// `exceptionInfo {threadId}`: the error the thread stands stopped at.
    pub(super) fn exception_info(&mut self, args: &Value) -> Result<Value, Failure> {
        let thread = args["threadId"].as_i64().ok_or("exceptionInfo needs `threadId`")?;
        let Some((_, error)) = self.exception.as_ref().filter(|(t, _)| *t == thread) else {
            return Err(format!("thread {thread} stands at no error"));
        };
        let id = if error.name.is_empty() { error.errno.to_string() } else { error.name.clone() };
        let break_mode = if error.uncaught { "unhandled" } else { "always" };
        Ok(json!({"exceptionId": id, "description": error_text(error), "breakMode": break_mode,
            "details": {"message": error.message, "typeName": "errnum", "fullTypeName": format!("ERRNO {}", error.errno)}}))
    }
}

/// How the stop names an error: `ERR_DIVZERO (41): Division by zero`, with
/// `uncaught` when no ERROR handler takes it.
fn error_text(error: &ErrorHit) -> String {
    let name = if error.name.is_empty() { format!("error {}", error.errno) } else { error.name.clone() };
    let handled = if error.uncaught { ", uncaught" } else { "" };
    format!("{name} ({}{handled}): {}", error.errno, error.message)
}
