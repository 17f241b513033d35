//! ArgName: the name of the original data object behind a parameter or a datum,
//! followed out through the callers when a parameter was itself passed a parameter.
//!
//! The compiler records, at every call of a user routine and at ArgName itself,
//! where each argument came from (`ir::ArgOrigin`); this walks those records from
//! the innermost frame outwards, one caller per parameter hop.

use std::rc::Rc;

use super::{native, present, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::exec::Frame;
use crate::ir::{ArgOrigin, Instr};
use crate::value::Value;

pub(super) static FAMILY: Family =
    Family { file: file!(), builtins: &[native("ArgName", arg_name).compiled_as(super::Compiled::ArgName)] };

/// `ArgName(Parameter [\ErrorNumber])`: the name of the whole data object (constant,
/// variable or persistent) the argument stands for. An expression, an optional
/// argument that was not passed, or a switch gives ERR_ARGNAME; with `\ErrorNumber`
/// the error number goes there instead (it is set to 0 first) and no error is raised.
// uncertain: the manual does not say what ArgName returns when it stores the error in
// \ErrorNumber; it returns an empty string here.
fn arg_name(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let error_number = args.get(1).filter(|arg| present(Some(arg)));
    if let Some(var) = error_number {
        ctx.store(var, Value::Num(0.0))?;
    }
    if let Some(name) = original_name(ctx.chain, 0) {
        return Ok(Some(Value::Str(name)));
    }
    let err = ctx.error(Err::ArgName, "the argument is not a data object (an expression, a switch or not present)");
    match error_number {
        Some(var) => {
            ctx.store(var, Value::Num(err.errno as f32))?;
            Ok(Some(Value::Str("".into())))
        }
        None => Err(err),
    }
}

/// The data object passed for parameter `param` of the built-in being called, followed
/// through each parameter to the argument the caller passed for it. At most one step
/// per frame, so it ends.
pub(crate) fn original_name(chain: &[Frame], param: usize) -> Option<Rc<str>> {
    let (innermost, callers) = chain.split_last()?;
    let mut origin = site_origins(innermost)?.get(param)?.clone();
    for caller in callers.iter().rev() {
        match origin {
            ArgOrigin::Param(n) => origin = site_origins(caller)?.get(n as usize)?.clone(),
            ArgOrigin::Data(name) => return Some(name),
            ArgOrigin::None => return None,
        }
    }
    match origin {
        ArgOrigin::Data(name) => Some(name),
        _ => None,
    }
}

/// The argument origins of the call a frame is making (a caller waits at its call).
fn site_origins(frame: &Frame) -> Option<&[ArgOrigin]> {
    let (code, pc) = frame.position();
    match code.instrs.get(pc as usize)? {
        Instr::Call(site) | Instr::LateCall(site) => code.arg_origins(*site),
        _ => None,
    }
}
