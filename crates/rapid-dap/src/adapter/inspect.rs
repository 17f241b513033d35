//! What a stopped program shows: call stacks, scopes, variables (expanded and
//! written), expressions evaluated in a frame, and the debug console's commands
//! that answer the pendant's dialogs.

use std::path::Path;

use rapid_controller::api::{ApiError, ValueTree};
use serde_json::{json, Value};

use super::{Adapter, Failure, FRAMES_PER_TASK};
use crate::vars::{Handle, Place};

impl Adapter<'_> {
    pub(super) fn stack_trace(&mut self, args: &Value) -> Result<Value, Failure> {
        let thread = args["threadId"].as_i64().ok_or("stackTrace needs `threadId`")?;
        let task = self.task_of_thread(thread)?;
        let stack = self.session()?.call_stack(&task).map_err(|e| e.to_string())?;
        let start = args["startFrame"].as_u64().unwrap_or(0) as usize;
        let levels = args["levels"].as_u64().filter(|&n| n > 0).map_or(stack.len(), |n| n as usize);
        let frames: Vec<Value> = stack
            .iter()
            .enumerate()
            .skip(start)
            .take(levels)
            .map(|(depth, frame)| {
                let name = match frame.handler {
                    Some(handler) => format!("{} ({handler})", frame.at.routine),
                    None => frame.at.routine.clone(),
                };
                let file = absolute(&frame.at.file);
                let source_name =
                    Path::new(&file).file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
                json!({"id": thread * FRAMES_PER_TASK + depth as i64, "name": name,
                    "source": {"name": source_name, "path": file},
                    "line": frame.at.line, "column": frame.at.column})
            })
            .collect();
        Ok(json!({"stackFrames": frames, "totalFrames": stack.len()}))
    }

    pub(super) fn scopes(&mut self, args: &Value) -> Result<Value, Failure> {
        let (task, frame) = self.frame_of(args["frameId"].as_i64().ok_or("scopes needs `frameId`")?)?;
        let has_io = self.session()?.controller().io_system().is_some();
        let mut scopes = vec![
            ("Locals", self.handles.add(Handle::Locals { task: task.clone(), frame })),
            ("Module data", self.handles.add(Handle::ModuleData { task: task.clone() })),
            ("Persistents", self.handles.add(Handle::Persistents { task })),
        ];
        if has_io {
            scopes.push(("Signals", self.handles.add(Handle::Signals)));
        }
        let scopes: Vec<Value> = scopes
            .into_iter()
            .map(|(name, reference)| json!({"name": name, "variablesReference": reference, "expensive": false}))
            .collect();
        Ok(json!({"scopes": scopes}))
    }

    pub(super) fn variables(&mut self, args: &Value) -> Result<Value, Failure> {
        let reference = args["variablesReference"].as_i64().ok_or("variables needs `variablesReference`")?;
        let handle = self.handles.get(reference).cloned().ok_or_else(|| format!("no variables {reference}"))?;
        let mut variables = Vec::new();
        match handle {
            Handle::Locals { task, frame } => {
                for tree in self.session()?.frame_trees(&task, frame).map_err(|e| e.to_string())? {
                    let place = Place::Local { task: task.clone(), frame, path: tree.name.clone() };
                    variables.push(self.variable(tree, Some(place)));
                }
            }
            Handle::ModuleData { task } | Handle::Persistents { task } => {
                let persistents = matches!(self.handles.get(reference), Some(Handle::Persistents { .. }));
                let data = self.session()?.list_data(&task).map_err(|e| e.to_string())?;
                for datum in data.iter().filter(|d| (d.kind == "PERS") == persistents) {
                    let session = self.session()?;
                    let Ok(tree) = session.data_tree(&task, &datum.module, &datum.name) else { continue };
                    let place = Place::Data(format!("{task}/{}/{}", datum.module, datum.name));
                    variables.push(self.variable(tree, Some(place)));
                }
            }
            Handle::Signals => {
                let names: Vec<String> = self
                    .session()?
                    .controller()
                    .io_system()
                    .map(|io| io.defs().iter().map(|d| d.name.clone()).collect())
                    .unwrap_or_default();
                for name in names {
                    let value = self.session()?.signal(&name).map_err(|e| e.to_string())?;
                    variables.push(json!({"name": name, "value": number_text(value), "variablesReference": 0}));
                }
            }
            Handle::Tree { tree, path } => {
                for child in tree.children {
                    let place = path.as_ref().map(|p| p.child(&child.name));
                    variables.push(self.variable(child, place));
                }
            }
        }
        Ok(json!({"variables": variables}))
    }

    /// A variable of the response, expandable when its value has parts.
    fn variable(&mut self, tree: ValueTree, path: Option<Place>) -> Value {
        let (name, value, type_name) = (tree.name.clone(), tree.value.clone(), tree.type_name.clone());
        let reference = match tree.children.is_empty() {
            true => 0,
            false => self.handles.add(Handle::Tree { tree, path }),
        };
        json!({"name": name, "value": value, "type": type_name, "variablesReference": reference})
    }

    pub(super) fn set_variable(&mut self, args: &Value) -> Result<Value, Failure> {
        let reference = args["variablesReference"].as_i64().ok_or("setVariable needs `variablesReference`")?;
        let name = args["name"].as_str().ok_or("setVariable needs `name`")?.to_owned();
        let value = args["value"].as_str().ok_or("setVariable needs `value`")?.to_owned();
        let handle = self.handles.get(reference).cloned().ok_or_else(|| format!("no variables {reference}"))?;
        let place = match handle {
            Handle::Tree { path: None, .. } => {
                return Err(ApiError::Refused(
                    "a part of an evaluated expression cannot be set: set the data it names".into(),
                )
                .to_string())
            }
            Handle::Signals => {
                let number: f64 = value.trim().parse().map_err(|_| format!("`{value}` is no signal value"))?;
                self.session()?.set_signal(&name, number).map_err(|e| e.to_string())?;
                let now = self.session()?.signal(&name).map_err(|e| e.to_string())?;
                return Ok(json!({"value": number_text(now)}));
            }
            Handle::Locals { task, frame } => Place::Local { task, frame, path: name },
            Handle::ModuleData { task } | Handle::Persistents { task } => {
                let data = self.session()?.list_data(&task).map_err(|e| e.to_string())?;
                let datum = data.iter().find(|d| d.name.eq_ignore_ascii_case(&name)).ok_or("no such data")?;
                Place::Data(format!("{task}/{}/{}", datum.module, datum.name))
            }
            Handle::Tree { path: Some(path), .. } => path.child(&name),
        };
        let session = self.session()?;
        let now = match &place {
            Place::Data(path) => {
                session.write_data(path, &value).map_err(|e| e.to_string())?;
                session.read_data(path).map_err(|e| e.to_string())?.value
            }
            Place::Local { task, frame, path } => {
                session.write_local(task, *frame, path, &value).map_err(|e| e.to_string())?;
                // A local's path (`p.trans{2}`) is a RAPID expression naming it.
                session.evaluate(task, *frame, path).map_err(|e| e.to_string())?.value
            }
        };
        // What the client showed of the program's data is out of date.
        self.event("invalidated", json!({"areas": ["variables"]}));
        Ok(json!({"value": now}))
    }

    pub(super) fn evaluate(&mut self, args: &Value) -> Result<Value, Failure> {
        let expression = args["expression"].as_str().ok_or("evaluate needs `expression`")?.trim().to_owned();
        if let Some(command) = expression.strip_prefix(':') {
            return self.console_command(command.trim());
        }
        let (task, frame) = match args["frameId"].as_i64() {
            Some(id) => self.frame_of(id)?,
            None => (self.task_of_thread(1)?, 0),
        };
        let tree = self.session()?.evaluate(&task, frame, &expression).map_err(|e| e.to_string())?;
        let (value, type_name) = (tree.value.clone(), tree.type_name.clone());
        let reference = match tree.children.is_empty() {
            true => 0,
            false => self.handles.add(Handle::Tree { tree, path: None }),
        };
        Ok(json!({"result": value, "type": type_name, "variablesReference": reference}))
    }

    /// The debug console's commands (`:answer TEXT`, `:prompts`): a dialog of the
    /// pendant answered from the console.
    fn console_command(&mut self, command: &str) -> Result<Value, Failure> {
        let (word, rest) = command.split_once(char::is_whitespace).unwrap_or((command, ""));
        match word {
            "answer" => {
                let prompt = self.session()?.prompts().into_iter().next().ok_or("no pendant dialog waits")?;
                self.session()?.answer(prompt.id, rest.trim()).map_err(|e| e.to_string())?;
                Ok(json!({"result": format!("answered \"{}\"", prompt.text), "variablesReference": 0}))
            }
            "prompts" => {
                let prompts = self.session()?.prompts();
                let lines: Vec<String> = prompts.iter().map(|p| format!("{} [{}] {}", p.id, p.task, p.text)).collect();
                Ok(json!({"result": lines.join("\n"), "variablesReference": 0}))
            }
            _ => Err(format!("unknown console command `:{word}` (:answer TEXT, :prompts)")),
        }
    }

    /// `rapidAnswer {id?, text}`: answers a pendant dialog (the oldest without `id`).
    pub(super) fn answer(&mut self, args: &Value) -> Result<Value, Failure> {
        let text = args["text"].as_str().ok_or("rapidAnswer needs `text`")?.to_owned();
        let id = match args["id"].as_u64() {
            Some(id) => id,
            None => self.session()?.prompts().first().map(|p| p.id).ok_or("no pendant dialog waits")?,
        };
        self.session()?.answer(id, &text).map_err(|e| e.to_string())?;
        Ok(Value::Null)
    }
}

/// A loaded file's path made absolute for the client (relative to the adapter's
/// working folder).
fn absolute(path: &str) -> String {
    let given = Path::new(path);
    if given.is_absolute() {
        return path.to_owned();
    }
    std::env::current_dir().map_or_else(|_| path.to_owned(), |d| d.join(given).to_string_lossy().into_owned())
}

/// A signal's value as RAPID writes a number (integers without a fraction).
fn number_text(value: f64) -> String {
    if value.fract() == 0.0 && value.abs() < 1e15 {
        format!("{}", value as i64)
    } else {
        format!("{value}")
    }
}
