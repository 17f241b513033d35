//! The active system data of the task's robot (manual §1.17): the tool, work object
//! and payload the controller uses when nothing else is said. GetSysData copies one
//! into a persistent, SetSysData activates another, GripLoad activates a payload.
//!
//! The controller refers to the active object, it does not copy it: GetSysData reads
//! the object's value at the time of the call, so a program that changes `tool1`
//! after activating it gets the changed value. At PP to Main tool0, wobj0 and load0
//! are active again ([`crate::builtins::motion::MotionState::reset`]).

use std::rc::Rc;

use super::super::{argname, present, tasking, Ctx};
use super::Res;
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Place, Root, Value};

/// The kind of system data "payload": kinds are indices into `MotionState::active`,
/// `MotionLinks::sysdata` and [`DEFAULT_NAMES`] (tool 0, work object 1, payload 2).
pub const LOAD: usize = 2;

/// The objects active at PP to Main, by kind.
pub const DEFAULT_NAMES: [&str; 3] = ["tool0", "wobj0", "load0"];

/// An active object: its name (GetSysData \ObjectName) and where it lives.
pub type Active = (Rc<str>, Place);

/// The active object of a kind: the one activated last, else the default.
fn active(ctx: &Ctx<'_>, kind: usize) -> Option<Active> {
    if let Some(active) = &ctx.resources.motion.active[kind] {
        return Some(active.clone());
    }
    let global = ctx.resources.motion.links.sysdata[kind]?;
    Some((DEFAULT_NAMES[kind].into(), Place { root: Root::Global(global), path: Vec::new() }))
}

/// Which kind of system data a value is (by its type: that of tool0, wobj0, load0).
fn kind_of(ctx: &Ctx<'_>, value: &Value) -> Option<usize> {
    let Value::Record(record) = value else { return None };
    (0..DEFAULT_NAMES.len()).find(|&kind| {
        let default = ctx.resources.motion.links.sysdata[kind].and_then(|g| ctx.storage.globals.get(g as usize));
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
    let name = argname::original_name(ctx.chain, param).unwrap_or_else(|| "".into());
    ctx.resources.motion.active[kind] = Some((name, (**place).clone()));
}

/// The task a `\TaskRef | \TaskName` pair names must be this one, and this one must
/// move a robot: the active data of another task is not reachable yet.
fn check_task(ctx: &Ctx<'_>, args: &[Value]) -> Result<(), RapidError> {
    if present(args.first()) || present(args.get(1)) {
        let task = tasking::named_task(ctx, args)?;
        tasking::check_own_task(ctx, &task.name, "GetSysData")?;
    }
    let tasking = &ctx.resources.tasking;
    let me = tasking.shared.tasks.iter().find(|t| t.name.eq_ignore_ascii_case(tasking.name()));
    if me.is_some_and(|t| !t.motion) {
        // uncertain: a task without a robot gets the data of its connected motion
        // task on the controller; that task's state is not reachable here yet.
        return Err(RapidError::fatal(
            "GetSysData in a task without a robot (the motion task's data) is not supported by `rapid run` yet",
        ));
    }
    Ok(())
}

/// `GetSysData [\TaskRef | \TaskName] DestObject [\ObjectName]`: copies the active
/// tool, work object or payload (the type of DestObject says which) into DestObject,
/// and its name into ObjectName. A task name the system does not have is
/// ERR_TASKNAME (as for every built-in that takes one).
pub(crate) fn get_sys_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    check_task(ctx, args)?;
    let dest = ctx.value(&args[2])?;
    let kind = kind_of(ctx, &dest).ok_or_else(|| not_sysdata(ctx, "DestObject"))?;
    let Some((name, place)) = active(ctx, kind) else {
        return Err(ctx.error(Err::SymAccess, format!("the system has no {}", DEFAULT_NAMES[kind])));
    };
    let value = ctx.storage.get(&place).map_err(|(e, m)| ctx.error(e, m))?.clone();
    ctx.store(&args[2], value)?;
    if present(args.get(3)) {
        ctx.store(&args[3], Value::Str(name))?;
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
            super::super::motion::set_payload(ctx, &source)?;
        }
        activate_arg(ctx, &args[0], 0, kind);
        return Ok(None);
    }
    let name = ctx.string(&args[1])?;
    let global = named_global(ctx, &name, kind)?;
    let value = ctx.storage.globals.get(global as usize).cloned().unwrap_or(Value::Absent);
    if kind_of(ctx, &value) != Some(kind) {
        return Err(ctx.error(Err::SymbolType, format!("`{name}` is not a {}", type_name(kind))));
    }
    if kind == LOAD {
        super::super::motion::set_payload(ctx, &value)?;
    }
    let place = Place { root: Root::Global(global), path: Vec::new() };
    ctx.resources.motion.active[kind] = Some((name.into(), place));
    Ok(None)
}

/// The global of the module data (or the predefined default object) named `name`.
fn named_global(ctx: &Ctx<'_>, name: &str, kind: usize) -> Result<u32, RapidError> {
    if let Some(data) = ctx.data_by_name.get(&name.to_ascii_lowercase()) {
        return Ok(data.global);
    }
    let default = DEFAULT_NAMES.iter().position(|d| d.eq_ignore_ascii_case(name));
    match default.and_then(|k| ctx.resources.motion.links.sysdata[k]) {
        Some(global) => Ok(global),
        None => Err(ctx.error(Err::SymAccess, format!("no {} named `{name}`", type_name(kind)))),
    }
}

fn type_name(kind: usize) -> &'static str {
    ["tooldata", "wobjdata", "loaddata"].get(kind).copied().unwrap_or("system data")
}
