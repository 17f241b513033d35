//! Data found by name at run time (§1.6 "数据搜索"): GetDataVal and SetDataVal.
//! `rapid run` runs one task, so the names are the task's module-level data; routine
//! data is not reached by name (whether the controller reaches the calling
//! routine's own data is not in the public record: uncertain). With `\Block` (a datapos
//! from GetNextSym) the name is looked up as seen from that module: its LOCAL data too.

use super::tasks::{Reply, Request};
use super::{present, Ctx, NamedData};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{OpaqueState, Value};

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[super::native("GetDataVal", get_data_val), super::native("SetDataVal", set_data_val)],
};

type Res = Result<Option<Value>, RapidError>;

/// Finds `Object` in this task (with `\Block`, as seen from that module).
fn lookup(ctx: &Ctx<'_>, args: &[Value]) -> Result<NamedData, RapidError> {
    if present(args.get(1)) {
        return in_block(ctx, &args[0], &args[1]);
    }
    let name = ctx.string(&args[0])?;
    ctx.data_by_name
        .get(&name.to_lowercase())
        .copied()
        .ok_or_else(|| ctx.error(Err::SymAccess, format!("no module-level data named `{name}`")))
}

/// `Object` as seen from the module a datapos names (ERR_SYM_ACCESS if not found, or
/// if the datapos was never set by GetNextSym).
fn in_block(ctx: &Ctx<'_>, object: &Value, block: &Value) -> Result<NamedData, RapidError> {
    let name = ctx.string(object)?;
    let handle = match ctx.value(block)? {
        Value::Opaque(shell) => match shell.state {
            OpaqueState::Handle(h) => Some(h),
            _ => None,
        },
        _ => None,
    };
    handle
        .and_then(|h| ctx.resources.symsearch.in_block(h, &name))
        .ok_or_else(|| ctx.error(Err::SymAccess, format!("no data named `{name}` in the block of the datapos")))
}

/// Whether two values have the same data type and shape (array sizes included).
pub fn same_type(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Num(_), Value::Num(_))
        | (Value::Dnum(_), Value::Dnum(_))
        | (Value::Bool(_), Value::Bool(_))
        | (Value::Str(_), Value::Str(_)) => true,
        (Value::Record(x), Value::Record(y)) => x.ty == y.ty,
        (Value::Array(x), Value::Array(y)) => {
            x.dims == y.dims && x.elems.first().zip(y.elems.first()).is_none_or(|(p, q)| same_type(p, q))
        }
        _ => false,
    }
}

fn type_error(ctx: &Ctx<'_>, name: &str) -> RapidError {
    ctx.error(Err::SymbolType, format!("`{name}` is not of the type of the Value argument"))
}

super::signature::layout! {
    /// `\TaskRef | \TaskName`: `other_task` reads the pair from the first.
    static DATA_VAL: DataValArgs = "GetDataVal" | "SetDataVal" { task_ref: "TaskRef", value: "Value" }
}

/// `GetDataVal Object [\Block]|[\TaskRef]|[\TaskName] Value`: copies the named data
/// into Value, which must be of the same type (else ERR_SYMBOL_TYPE).
pub(super) fn get_data_val(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *DATA_VAL;
    let found = match super::tasks::other_task(ctx, args, at.task_ref)? {
        Some(task) => {
            let name = ctx.string(&args[0])?;
            match super::tasks::ask(ctx, Request::ReadData { task, name: name.clone() }) {
                None => return Ok(None),
                Some(Reply::Value(value)) => value,
                Some(_) => return Err(ctx.error(Err::SymAccess, format!("the task has no module data named `{name}`"))),
            }
        }
        None => {
            let named = lookup(ctx, args)?;
            ctx.storage.globals.get(named.global).cloned().ok_or_else(|| RapidError::fatal("a data slot is missing"))?
        }
    };
    let target = &args[at.value];
    if !same_type(&found, &ctx.value(target)?) {
        return Err(type_error(ctx, &ctx.string(&args[0])?));
    }
    ctx.store(target, found)?;
    Ok(None)
}

/// `SetDataVal Object [\Block]|[\TaskRef]|[\TaskName] Value`: writes Value into the
/// named data. A constant cannot be written (ERR_SYM_ACCESS).
pub(super) fn set_data_val(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *DATA_VAL;
    if let Some(task) = super::tasks::other_task(ctx, args, at.task_ref)? {
        return set_in_other_task(ctx, args, task);
    }
    let named = lookup(ctx, args)?;
    let name = ctx.string(&args[0])?;
    if named.constant {
        return Err(ctx.error(Err::SymAccess, format!("`{name}` is a constant")));
    }
    let value = ctx.value(&args[at.value])?;
    let current = ctx.storage.globals.get(named.global).ok_or_else(|| RapidError::fatal("a data slot is missing"))?;
    if !same_type(current, &value) {
        return Err(type_error(ctx, &name));
    }
    if let Some(slot) = ctx.storage.globals.get_mut(named.global) {
        *slot = value;
    }
    Ok(None)
}

/// SetDataVal in another task, through the controller.
fn set_in_other_task(ctx: &mut Ctx<'_>, args: &[Value], task: usize) -> Res {
    let name = ctx.string(&args[0])?;
    let value = ctx.value(&args[DATA_VAL.value])?;
    match super::tasks::ask(ctx, Request::WriteData { task, name: name.clone(), value }) {
        None | Some(Reply::Done) => Ok(None),
        Some(Reply::Constant) => Err(ctx.error(Err::SymAccess, format!("`{name}` is a constant"))),
        Some(Reply::WrongType) => Err(type_error(ctx, &name)),
        Some(_) => Err(ctx.error(Err::SymAccess, format!("the task has no module data named `{name}`"))),
    }
}
