//! Data and signals by name, for front ends: a datum is named as RWS names it,
//! `TASK/MODULE/NAME` (or `TASK/NAME` for the task's global data), optionally with
//! record components and array elements after the name (`pos1.trans.x`, `reg{2}`,
//! `grid{1,3}`). Values go in and out as RAPID literal text: out through the
//! formatter ValToStr uses, in through StrToVal's reader, shaped by the value the
//! datum holds (so a literal of another type is refused).
//!
//! RAPID's rules for who may change what (§1.2 data kinds): a CONST is never written;
//! VAR and PERS are. A global PERS written here is written in the shared store at once,
//! so every task declaring it reads the new value at its next statement.
// Routine data (a frame's locals) is read through `Session::frame_locals`.

use rapid_signals::SharedIoAccess;
use rapid_vm::builtins::symsearch::{SymData, SymKind};
use rapid_vm::value::{Record, Value};

use super::{ApiError, Session};

/// A step from a datum into a part of it.
#[derive(Debug, Clone, PartialEq)]
enum Step {
    Component(String),
    /// 1-based indices.
    Element(Vec<f64>),
}

/// A datum named by a front end.
#[derive(Debug, Clone, PartialEq)]
struct DataPath {
    task: String,
    module: Option<String>,
    name: String,
    steps: Vec<Step>,
}

/// What a front end reads of a datum.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DataValue {
    /// RAPID literal text of the value (or of the part named).
    pub value: String,
    /// The datum's declared type (of the whole datum, not of a part).
    pub type_name: String,
    /// `VAR`, `PERS` or `CONST`.
    pub kind: &'static str,
    /// The module that declares it.
    pub module: String,
}

/// A datum of a task's modules, as listed for a front end.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DataInfo {
    pub name: String,
    pub module: String,
    pub type_name: String,
    pub kind: &'static str,
    pub local: bool,
}

fn kind_name(kind: SymKind) -> &'static str {
    match kind {
        SymKind::Var => "VAR",
        SymKind::Pers => "PERS",
        SymKind::Const => "CONST",
    }
}

fn is_ident_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

impl DataPath {
    /// `TASK/MODULE/NAME…` or `TASK/NAME…`.
    fn parse(text: &str) -> Result<DataPath, ApiError> {
        let bad = |why: &str| ApiError::BadPath(format!("`{text}`: {why}"));
        let parts: Vec<&str> = text.split('/').map(str::trim).collect();
        let (task, module, tail) = match parts.as_slice() {
            [task, name] => (*task, None, *name),
            [task, module, name] => (*task, Some((*module).to_owned()), *name),
            _ => return Err(bad("expected TASK/MODULE/NAME or TASK/NAME")),
        };
        let name_len = tail.find(|c: char| !is_ident_char(c)).unwrap_or(tail.len());
        let name = &tail[..name_len];
        if task.is_empty() || name.is_empty() || !name.starts_with(|c: char| c.is_ascii_alphabetic()) {
            return Err(bad("a task and a data name are needed"));
        }
        let steps = parse_steps(&tail[name_len..]).map_err(|why| bad(&why))?;
        Ok(DataPath { task: task.to_owned(), module, name: name.to_owned(), steps })
    }
}

/// `.component` and `{i, j}` steps.
fn parse_steps(mut rest: &str) -> Result<Vec<Step>, String> {
    let mut steps = Vec::new();
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix('.') {
            let len = after.find(|c: char| !is_ident_char(c)).unwrap_or(after.len());
            if len == 0 {
                return Err("a component name must follow `.`".to_owned());
            }
            steps.push(Step::Component(after[..len].to_owned()));
            rest = &after[len..];
        } else if let Some(after) = rest.strip_prefix('{') {
            let Some(end) = after.find('}') else { return Err("`{` without `}`".to_owned()) };
            let mut indices = Vec::new();
            for index in after[..end].split(',') {
                match index.trim().parse::<u32>() {
                    Ok(n) => indices.push(f64::from(n)),
                    Err(_) => return Err(format!("`{}` is no array index", index.trim())),
                }
            }
            steps.push(Step::Element(indices));
            rest = &after[end + 1..];
        } else {
            return Err(format!("unexpected `{rest}`"));
        }
    }
    Ok(steps)
}

/// The part of `value` that `steps` name; `fields` gives a record type's component
/// names.
fn part_mut<'v>(
    value: &'v mut Value,
    steps: &[Step],
    fields: &dyn Fn(&Record) -> Option<Vec<String>>,
) -> Result<&'v mut Value, ApiError> {
    let Some((step, rest)) = steps.split_first() else { return Ok(value) };
    let next = match (step, value) {
        (Step::Component(name), Value::Record(record)) => {
            let names = fields(record).ok_or_else(|| {
                ApiError::Unsupported("record components need the task's checked program (Loaded::analysis)".into())
            })?;
            let Some(at) = names.iter().position(|n| n.eq_ignore_ascii_case(name)) else {
                return Err(ApiError::BadPath(format!("the record has no component `{name}`")));
            };
            let record = std::rc::Rc::make_mut(record);
            &mut record.fields[at]
        }
        (Step::Element(indices), Value::Array(array)) => {
            let at = rapid_vm::exec::storage::element_index(array.dims, indices)
                .map_err(|(_, why)| ApiError::BadPath(why))?;
            &mut array.elems[at as usize]
        }
        (Step::Component(name), _) => return Err(ApiError::BadPath(format!("`.{name}` of a value that is no record"))),
        (Step::Element(_), _) => return Err(ApiError::BadPath("an index of a value that is no array".into())),
    };
    part_mut(next, rest, fields)
}

/// Whether every string in `value` fits RAPID's 80 characters.
fn strings_fit(value: &Value) -> bool {
    match value {
        Value::Str(s) => s.chars().count() <= rapid_vm::value::MAX_STRING_CHARS,
        Value::Record(r) => r.fields.iter().all(strings_fit),
        Value::Array(a) => a.elems.iter().all(strings_fit),
        _ => true,
    }
}

/// Parameter or routine datum `name` of frame `at` (0: the outermost) to write.
fn frame_local<'v>(vm: &'v mut rapid_vm::Vm, at: usize, name: &str) -> Result<&'v mut Value, ApiError> {
    match vm.frame_local_mut(at, name) {
        None => Err(ApiError::NotFound(format!("the routine has no parameter or data `{name}`"))),
        Some(Err(why)) => Err(ApiError::ReadOnly(why)),
        Some(Ok(value)) => Ok(value),
    }
}

impl Session {
    /// The module-level data of task `task`.
    pub fn list_data(&self, task: &str) -> Result<Vec<DataInfo>, ApiError> {
        let idx = self.task_index(task)?;
        let symbols = &self.controller.tasks[idx].loaded.vm.resources().symsearch;
        let module = |d: &SymData| symbols.modules().get(d.module as usize).cloned().unwrap_or_default();
        Ok(symbols
            .data()
            .iter()
            .map(|d| DataInfo {
                name: d.name.clone(),
                module: module(d),
                type_name: d.ty.clone(),
                kind: kind_name(d.kind),
                local: d.local,
            })
            .collect())
    }

    /// Reads a datum (or a part of it) as RAPID literal text.
    pub fn read_data(&mut self, path: &str) -> Result<DataValue, ApiError> {
        let path = DataPath::parse(path)?;
        let (idx, datum, module) = self.find_data(&path)?;
        let mut whole = self.global_now(idx, datum.global)?;
        let fields = self.field_names(idx);
        let part = part_mut(&mut whole, &path.steps, &fields)?;
        let value = rapid_vm::builtins::value_literal(part).ok_or_else(|| {
            ApiError::Unsupported(format!(
                "`{}` is of a non-value type ({}), which has no literal",
                path.name, datum.ty
            ))
        })?;
        Ok(DataValue { value, type_name: datum.ty.clone(), kind: kind_name(datum.kind), module })
    }

    /// Writes a datum (or a part of it) from RAPID literal text of its type. A CONST
    /// is refused; so is text that is no literal of the value's type.
    pub fn write_data(&mut self, path: &str, literal: &str) -> Result<(), ApiError> {
        let path = DataPath::parse(path)?;
        let (idx, datum, _) = self.find_data(&path)?;
        if datum.kind == SymKind::Const {
            return Err(ApiError::ReadOnly(format!("`{}` is a CONST", datum.name)));
        }
        let mut whole = self.global_now(idx, datum.global)?;
        {
            let fields = self.field_names(idx);
            let part = part_mut(&mut whole, &path.steps, &fields)?;
            *part = rapid_vm::builtins::read_literal(literal, part).filter(strings_fit).ok_or_else(|| {
                ApiError::BadLiteral(format!("`{literal}` is no {} literal for `{}`", datum.ty, path.name))
            })?;
        }
        let global = datum.global;
        self.controller.with_task(idx, &mut self.pendant, |vm, _| vm.set_global(global, whole));
        self.gather();
        Ok(())
    }

    /// Writes a parameter or routine datum of frame `frame` (0: the innermost) of task
    /// `task`, or a part of it (`name`, `name.comp`, `name{2}`), from RAPID literal
    /// text of its type: a parameter passed by value and routine data change in the
    /// frame alone; a VAR, INOUT or PERS parameter writes through to its argument, as
    /// assigning it in the routine would (§1.5). A CONST is refused; so is text that
    /// is no literal of the value's type.
    pub fn write_local(&mut self, task: &str, frame: usize, path: &str, literal: &str) -> Result<(), ApiError> {
        let path = DataPath::parse(&format!("{task}/{path}"))?;
        let idx = self.task_index(task)?;
        let at = self.controller.tasks[idx]
            .loaded
            .vm
            .depth()
            .checked_sub(frame + 1)
            .ok_or_else(|| ApiError::NotFound(format!("task {task} has no frame {frame}")))?;
        let name = path.name.as_str();
        // Shared persistents an INOUT or PERS parameter may name are brought in first.
        let mut whole =
            self.controller.with_task(idx, &mut self.pendant, |vm, _| frame_local(vm, at, name).map(|v| v.clone()))?;
        {
            let fields = self.field_names(idx);
            let part = part_mut(&mut whole, &path.steps, &fields)?;
            *part = rapid_vm::builtins::read_literal(literal, part).filter(strings_fit).ok_or_else(|| {
                ApiError::BadLiteral(format!("`{literal}` is no literal of the type of `{}`", path.name))
            })?;
        }
        self.controller
            .with_task(idx, &mut self.pendant, |vm, _| frame_local(vm, at, name).map(|slot| *slot = whole))?;
        self.gather();
        Ok(())
    }

    /// A datum of the path's task: the task, the datum and its module's name. Without
    /// a module, the task's global (non-LOCAL) datum of that name.
    fn find_data(&self, path: &DataPath) -> Result<(usize, SymData, String), ApiError> {
        let idx = self.task_index(&path.task)?;
        let symbols = &self.controller.tasks[idx].loaded.vm.resources().symsearch;
        let module_idx = match &path.module {
            Some(name) => Some(
                symbols
                    .modules()
                    .iter()
                    .position(|m| m.eq_ignore_ascii_case(name))
                    .ok_or_else(|| ApiError::NotFound(format!("task {} has no module `{name}`", path.task)))?,
            ),
            None => None,
        };
        let found = symbols.data().iter().find(|d| {
            d.name.eq_ignore_ascii_case(&path.name)
                && match module_idx {
                    Some(m) => d.module as usize == m,
                    None => !d.local,
                }
        });
        let datum = found.cloned().ok_or_else(|| {
            let place = path.module.as_deref().map_or(format!("task {}", path.task), |m| format!("module {m}"));
            ApiError::NotFound(format!("{place} has no data `{}`", path.name))
        })?;
        let module = symbols.modules().get(datum.module as usize).cloned().unwrap_or_default();
        Ok((idx, datum, module))
    }

    /// Global `global` of task `idx` as it is now (a shared persistent another task
    /// changed is brought in first).
    fn global_now(&mut self, idx: usize, global: u32) -> Result<Value, ApiError> {
        self.controller
            .with_task(idx, &mut self.pendant, |vm, _| vm.global(global).cloned())
            .ok_or_else(|| ApiError::NotFound(format!("no value for data slot {global}")))
    }

    /// How task `idx` names the components of a record value.
    fn field_names(&self, idx: usize) -> impl Fn(&Record) -> Option<Vec<String>> + '_ {
        let program = self.controller.tasks[idx].loaded.analysis.as_deref();
        move |record: &Record| {
            let fields = program?.types.record_fields(record.ty)?;
            Some(fields.iter().map(|f| f.display.clone()).collect())
        }
    }

    /// The value of signal `name`.
    pub fn signal(&self, name: &str) -> Result<f64, ApiError> {
        let io = self.controller.io_system().ok_or_else(|| ApiError::NotFound("the system has no I/O".into()))?;
        io.value_by_name(name).ok_or_else(|| ApiError::NotFound(format!("no signal `{name}`")))
    }

    /// Sets signal `name` now: an input as its device would (a cross-connected input
    /// cannot be set), an output as a program order (its access level applies).
    pub fn set_signal(&mut self, name: &str, value: f64) -> Result<(), ApiError> {
        let time = self.controller.time;
        let io = self
            .controller
            .shared_mut()
            .io_mut()
            .system
            .as_mut()
            .ok_or_else(|| ApiError::NotFound("the system has no I/O".into()))?;
        let id = io.id(name).ok_or_else(|| ApiError::NotFound(format!("no signal `{name}`")))?;
        let input = io.def(id).is_some_and(|d| d.kind.is_input());
        let outcome = if input { io.set_input(id, value, time).map(|_| ()) } else { io.set(id, value, time) };
        outcome.map_err(|e| ApiError::Refused(format!("signal `{name}`: {e}")))?;
        self.gather();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::{DataPath, Step};

    #[test]
    fn paths_name_task_module_datum_and_parts() {
        let path = DataPath::parse("T_ROB1/MainModule/reg1.trans.x").ok();
        let steps = vec![Step::Component("trans".into()), Step::Component("x".into())];
        assert_eq!(
            path,
            Some(DataPath { task: "T_ROB1".into(), module: Some("MainModule".into()), name: "reg1".into(), steps })
        );
        let path = DataPath::parse("T_ROB1/grid{2, 3}").ok();
        let steps = vec![Step::Element(vec![2.0, 3.0])];
        assert_eq!(path, Some(DataPath { task: "T_ROB1".into(), module: None, name: "grid".into(), steps }));
        assert!(DataPath::parse("reg1").is_err());
        assert!(DataPath::parse("T/M/reg1{x}").is_err());
        assert!(DataPath::parse("T/M/reg1.").is_err());
    }
}
