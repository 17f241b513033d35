//! TriggDataCopy, TriggDataReset and TriggDataValid (RobotWare 6.02): triggdata
//! handled as a whole. A copy gets its own definition slot, so redefining either one
//! later leaves the other as it was.

use super::{define, Res};
use crate::RobotResources;
use rapid_vm::ext::{Ctx, Opaque, OpaqueState, Value};

/// The definition slot a triggdata argument holds, if it holds one.
fn slot(ctx: &Ctx<'_>, arg: &Value) -> Result<(Opaque, Option<usize>), rapid_vm::ext::RapidError> {
    let (opaque, handle) = ctx.handle_arg(arg, "a triggdata")?;
    let len = ctx.resources.robot().triggers.len();
    Ok((opaque, handle.map(|h| h as usize).filter(|&h| h < len)))
}

/// `TriggDataCopy Source, Destination`: Destination holds the same trigger as Source.
// uncertain: copying an empty (never defined or reset) triggdata empties Destination.
pub(crate) fn trigg_data_copy(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, source) = slot(ctx, &args[0])?;
    let Some(h) = source else { return trigg_data_reset(ctx, &args[1..]) };
    let event = ctx.resources.robot_mut().triggers[h];
    let special = ctx.resources.robot_mut().trigg.def(h).cloned();
    let (_, destination) = slot(ctx, &args[1])?;
    if destination == Some(h) {
        return Ok(None);
    }
    define(ctx, &args[1], event, special)
}

/// `TriggDataReset TriggData`: the triggdata holds no trigger any more.
pub(crate) fn trigg_data_reset(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (opaque, _) = ctx.handle_arg(&args[0], "a triggdata")?;
    let empty = Opaque { ty: opaque.ty, state: OpaqueState::None };
    ctx.store(&args[0], Value::Opaque(Box::new(empty)))?;
    Ok(None)
}

/// `TriggDataValid(TriggData)`: whether the triggdata holds a trigger definition.
pub(crate) fn trigg_data_valid(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, held) = slot(ctx, &args[0])?;
    Ok(Some(Value::Bool(held.is_some())))
}
