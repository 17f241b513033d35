//! The active system data of the task's robot (manual §1.17): the tool, work object
//! and payload the controller uses when nothing else is said. GetSysData copies one
//! into a persistent, SetSysData activates another, GripLoad activates a payload.
//!
//! The controller refers to the active object, it does not copy it: GetSysData reads
//! the object's value at the time of the call, so a program that changes `tool1`
//! after activating it gets the changed value. At PP to Main tool0, wobj0 and load0
//! are active again ([`super::MotionState::reset`]).
//!
//! Each activation is also published, by name, in the state the tasks share, so
//! GetSysData \TaskName in another task (or in a task without a robot, which reads
//! its motion task's data) finds the object: a global PERS is one object in every
//! task that declares it.

use crate::RobotResources;
use std::rc::Rc;

use rapid_tasks::TaskingAccess;
use rapid_vm::ext::{ask, native, present, Ctx, Err, Family, Place, RapidError, Reply, Request, Root, Value};

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("GetSysData", get_sys_data),
        native("SetSysData", set_sys_data),
        native("CTool", c_tool),
        native("CWObj", c_wobj),
    ],
};

/// The kind of system data "payload": kinds are indices into `MotionState::active`,
/// `MotionLinks::sysdata` and [`DEFAULT_NAMES`] (tool 0, work object 1, payload 2).
pub const LOAD: usize = 2;

/// The objects active at PP to Main, by kind.
pub const DEFAULT_NAMES: [&str; 3] = ["tool0", "wobj0", "load0"];

/// An active object: its name (GetSysData \ObjectName) and where it lives.
pub type Active = (Rc<str>, Place);

/// The active object of a kind: the one activated last, else the default.
fn active(ctx: &Ctx<'_>, kind: usize) -> Option<Active> {
    if let Some(active) = &ctx.resources.motion().active[kind] {
        return Some(active.clone());
    }
    let global = ctx.resources.motion().links.sysdata[kind]?;
    Some((DEFAULT_NAMES[kind].into(), Place { root: Root::Global(global), path: Vec::new() }))
}

/// Which kind of system data a value is (by its type: that of tool0, wobj0, load0).
fn kind_of(ctx: &Ctx<'_>, value: &Value) -> Option<usize> {
    let Value::Record(record) = value else { return None };
    (0..DEFAULT_NAMES.len()).find(|&kind| {
        let default = ctx.resources.motion().links.sysdata[kind].and_then(|g| ctx.storage.globals.get(g));
        matches!(default, Some(Value::Record(d)) if d.ty == record.ty)
    })
}

fn not_sysdata(ctx: &Ctx<'_>, what: &str) -> RapidError {
    ctx.error(Err::ArgValue, format!("{what} must be a tooldata, wobjdata or loaddata"))
}

/// Makes the data object an argument refers to the active one of its kind (GripLoad,
/// SetSysData): `param` is the argument's place among the built-in's parameters.
/// An argument that is no persistent of the program activates nothing.
pub(crate) fn activate_arg(ctx: &mut Ctx<'_>, arg: &Value, param: usize, kind: usize) {
    let Value::Ref(place) = arg else { return };
    if !matches!(place.root, Root::Global(_)) {
        return;
    }
    // The active object again (a program's moves mostly name one tool): nothing changes.
    if ctx.resources.motion_mut().active[kind].as_ref().is_some_and(|(_, active)| active == &**place) {
        return;
    }
    let name = ctx.arg_name(param).unwrap_or_else(|| "".into());
    activate(ctx, kind, name, (**place).clone());
}

/// Makes `name` at `place` the active object of its kind, and tells the other tasks.
fn activate(ctx: &mut Ctx<'_>, kind: usize, name: Rc<str>, place: Place) {
    let me = ctx.resources.tasks.name().to_ascii_lowercase();
    ctx.resources.tasking_mut().shared.sysdata.entry(me).or_default()[kind] = Some(std::sync::Arc::from(&*name));
    ctx.resources.motion_mut().active[kind] = Some((name, place));
}

/// Whose active data GetSysData reads: `None` for this task's own, else the name of
/// another task. `\TaskRef | \TaskName` name a task (ERR_TASKNAME when the system
/// has none of that name); a task without a robot reads the data of the motion task
/// it is connected to.
// uncertain: a task without a robot is taken to be connected to the first motion
// task (as GetTaskName \MecTaskNo does); in a system where no task is configured
// with -MotionTask every task keeps its own data.
fn data_owner(ctx: &Ctx<'_>, args: &[Value]) -> Result<Option<String>, RapidError> {
    let me = ctx.resources.tasks.name();
    let named = if present(args.first()) || present(args.get(1)) {
        rapid_tasks::named_task(ctx, args)?.name
    } else {
        me.to_string()
    };
    let tasks = &ctx.resources.tasking().shared.tasks;
    let owner = match tasks.iter().find(|t| t.name.eq_ignore_ascii_case(&named)) {
        Some(task) if !task.motion => tasks.iter().find(|t| t.motion).map_or(named, |t| t.name.clone()),
        _ => named,
    };
    Ok(Some(owner).filter(|owner| !owner.eq_ignore_ascii_case(me)))
}

/// The name of the active object of a kind in another task.
fn active_name_in(ctx: &Ctx<'_>, task: &str, kind: usize) -> Rc<str> {
    let listed = ctx.resources.tasking().shared.sysdata.get(&task.to_ascii_lowercase());
    listed.and_then(|names| names[kind].as_deref().map(Rc::from)).unwrap_or_else(|| DEFAULT_NAMES[kind].into())
}

/// The global of this task that is the object `name` of another task: a global PERS
/// is one object in every task that declares it (or it is the predefined default).
fn shared_global(ctx: &Ctx<'_>, name: &str) -> Option<u32> {
    let global = ctx.data_by_name.get(&name.to_ascii_lowercase()).map(|d| d.global).or_else(|| {
        let default = DEFAULT_NAMES.iter().position(|d| d.eq_ignore_ascii_case(name))?;
        ctx.resources.motion().links.sysdata[default]
    });
    global.filter(|&g| ctx.pers_globals.get(g as usize).copied().unwrap_or(false))
}

/// The value of the active object of a kind in another task: read here when it is a
/// persistent this task shares, else asked of that task through the controller
/// (`None`: the answer comes when the instruction runs again).
fn value_in(ctx: &mut Ctx<'_>, task: &str, kind: usize) -> Result<Option<(Rc<str>, Value)>, RapidError> {
    let name = active_name_in(ctx, task, kind);
    if let Some(global) = shared_global(ctx, &name) {
        let place = Place { root: Root::Global(global), path: Vec::new() };
        let value = ctx.storage.get(&place).map_err(|(e, m)| ctx.error(e, m))?.clone();
        return Ok(Some((name, value)));
    }
    let tasks = &ctx.resources.tasking().shared.tasks;
    let Some(index) = tasks.iter().position(|t| t.name.eq_ignore_ascii_case(task)) else {
        return Err(ctx.error(Err::TaskName, format!("the system has no task {task}")));
    };
    match ask(ctx, Request::ReadData { task: index, name: name.to_string() }) {
        None => Ok(None),
        Some(Reply::Value(value)) => Ok(Some((name, value))),
        Some(_) => Err(ctx.error(Err::SymAccess, format!("task {task} has no data `{name}` to read"))),
    }
}

rapid_vm::ext::layout! {
    static GET_SYS_DATA: GetSysDataArgs = "GetSysData" { dest: "DestObject", object_name: "ObjectName" }
}

/// `GetSysData [\TaskRef | \TaskName] DestObject [\ObjectName]`: copies the active
/// tool, work object or payload (the type of DestObject says which) into DestObject,
/// and its name into ObjectName.
pub(crate) fn get_sys_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *GET_SYS_DATA;
    let owner = data_owner(ctx, args)?;
    let dest = ctx.value(&args[at.dest])?;
    let kind = kind_of(ctx, &dest).ok_or_else(|| not_sysdata(ctx, "DestObject"))?;
    let (name, value) = match owner {
        Some(task) => match value_in(ctx, &task, kind)? {
            Some(found) => found,
            None => return Ok(None),
        },
        None => {
            let (name, place) = active(ctx, kind)
                .ok_or_else(|| ctx.error(Err::SymAccess, format!("the system has no {}", DEFAULT_NAMES[kind])))?;
            (name, ctx.storage.get(&place).map_err(|(e, m)| ctx.error(e, m))?.clone())
        }
    };
    ctx.store(&args[at.dest], value)?;
    if present(args.get(at.object_name)) {
        ctx.store(&args[at.object_name], Value::Str(name))?;
    }
    Ok(None)
}

/// `SetSysData SourceObject [\ObjectName]`: activates SourceObject (or the data object
/// of its type named ObjectName) as the tool, work object or payload; no data value
/// changes. A payload is also what GripLoad sets, so the motion settings take its
/// value.
// uncertain: ObjectName naming no module data is ERR_SYM_ACCESS and naming data of
// another type ERR_SYMBOL_TYPE, as GetDataVal and SetDataVal report them.
pub(crate) fn set_sys_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let source = ctx.value(&args[0])?;
    let kind = kind_of(ctx, &source).ok_or_else(|| not_sysdata(ctx, "SourceObject"))?;
    if !present(args.get(1)) {
        if kind == LOAD {
            super::set_payload(ctx, &source)?;
        }
        activate_arg(ctx, &args[0], 0, kind);
        return Ok(None);
    }
    let name = ctx.string(&args[1])?;
    let global = named_global(ctx, &name, kind)?;
    let value = ctx.storage.globals.get(global).cloned().unwrap_or(Value::Absent);
    if kind_of(ctx, &value) != Some(kind) {
        return Err(ctx.error(Err::SymbolType, format!("`{name}` is not a {}", type_name(kind))));
    }
    if kind == LOAD {
        super::set_payload(ctx, &value)?;
    }
    let place = Place { root: Root::Global(global), path: Vec::new() };
    activate(ctx, kind, name.into(), place);
    Ok(None)
}

/// The global of the module data (or the predefined default object) named `name`.
fn named_global(ctx: &Ctx<'_>, name: &str, kind: usize) -> Result<u32, RapidError> {
    if let Some(data) = ctx.data_by_name.get(&name.to_ascii_lowercase()) {
        return Ok(data.global);
    }
    let default = DEFAULT_NAMES.iter().position(|d| d.eq_ignore_ascii_case(name));
    match default.and_then(|k| ctx.resources.motion().links.sysdata[k]) {
        Some(global) => Ok(global),
        None => Err(ctx.error(Err::SymAccess, format!("no {} named `{name}`", type_name(kind)))),
    }
}

fn type_name(kind: usize) -> &'static str {
    ["tooldata", "wobjdata", "loaddata"].get(kind).copied().unwrap_or("system data")
}

/// `CTool([\TaskRef] | [\TaskName])` and `CWObj(…)`: the value of the active tool or
/// work object (of another task as GetSysData reads it).
fn current(ctx: &mut Ctx<'_>, args: &[Value], kind: usize) -> Res {
    let owner = data_owner(ctx, args)?;
    if let Some(task) = owner {
        if let Some((_, value)) = value_in(ctx, &task, kind)? {
            return Ok(Some(value));
        }
        // No answer yet: the instruction runs again and this task's own value, of the
        // right type, is not used.
    }
    let (_, place) = active(ctx, kind)
        .ok_or_else(|| ctx.error(Err::SymAccess, format!("the system has no {}", DEFAULT_NAMES[kind])))?;
    let value = ctx.storage.get(&place).map_err(|(e, m)| ctx.error(e, m))?.clone();
    Ok(Some(value))
}

pub(crate) fn c_tool(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    current(ctx, args, 0)
}

pub(crate) fn c_wobj(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    current(ctx, args, 1)
}
