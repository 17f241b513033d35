//! Teach pendant output: TPWrite (with one of \Num, \Bool, \Pos, \Orient, \Dnum
//! appended in the controller's format), TPErase, ErrWrite.

use super::{present, Ctx};
use crate::error::RapidError;
use crate::events::{Event, EventKind};
use crate::format::{bool_to_text, dnum_to_text, num_to_text, orient_to_text, pos_to_text};
use crate::value::Value;

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("TPWrite", tp_write),
        super::native("TPErase", tp_erase),
        super::native("TPShow", tp_show),
        super::native("ErrWrite", err_write),
    ],
};

/// `TPWrite String [\Num] | [\Bool] | [\Pos] | [\Orient] | [\Dnum]` (parameter order
/// as the catalogue declares it).
pub(super) fn tp_write(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let mut line = ctx.string(&args[0])?;
    let value = args[1..].iter().find(|a| present(Some(a)));
    if let Some(value) = value {
        line.push_str(&value_text(ctx, &ctx.value(value)?));
    }
    ctx.host.tp_write(&line);
    Ok(None)
}

/// A value appended by TPWrite: numbers in the standard format, bools as TRUE/FALSE,
/// pos and orient as aggregates.
pub fn value_text(ctx: &Ctx<'_>, value: &Value) -> String {
    match value {
        Value::Num(n) => num_to_text(*n),
        Value::Dnum(d) => dnum_to_text(*d),
        Value::Bool(b) => bool_to_text(*b).to_string(),
        Value::Record(r) => {
            let comps: Vec<f32> = r.fields.iter().map(|f| if let Value::Num(n) = f { *n } else { 0.0 }).collect();
            match comps.as_slice() {
                [x, y, z] if r.ty == ctx.types.pos => pos_to_text([*x, *y, *z]),
                [a, b, c, d] => orient_to_text([*a, *b, *c, *d]),
                _ => String::new(),
            }
        }
        _ => String::new(),
    }
}

pub(super) fn tp_erase(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    ctx.host.tp_erase();
    Ok(None)
}

/// `ErrWrite [\W] | [\I] Header Reason [\RL2] [\RL3] [\RL4]`: shown on the pendant
/// as its header and reason lines, and logged as user event 80001 (error), 80002
/// (`\W`) or 80003 (`\I`).
pub(super) fn err_write(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let (number, kind) = if present(args.first()) {
        (2, EventKind::Warning)
    } else if present(args.get(1)) {
        (3, EventKind::Info)
    } else {
        (1, EventKind::Error)
    };
    let mut texts = Vec::new();
    for arg in args[2..].iter().filter(|a| present(Some(a))) {
        texts.push(ctx.string(arg)?);
    }
    for text in &texts {
        ctx.host.tp_write(text);
    }
    let mut texts = texts.into_iter();
    let title = texts.next().unwrap_or_default();
    let lines = texts.collect();
    let event = Event::user(number, kind, ctx.time, title, lines);
    ctx.events.push(event);
    Ok(None)
}

/// `TPShow Window`: brings a pendant window to the front (TP_PROGRAM, TP_LATEST,
/// TP_SCREENVIEWER). The host decides what that means; `rapid run`'s pendant is
/// stdout, with one window.
// uncertain: the manual names no error for a Window that is no tpnum value; we raise
// ERR_ARGVALERR rather than ignore it.
pub(super) fn tp_show(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let window = ctx.num(&args[0])?;
    if !(1.0..=3.0).contains(&window) || window.fract() != 0.0 {
        return Err(ctx.error(crate::errnames::Err::ArgValue, format!("{window} is not a pendant window (tpnum)")));
    }
    ctx.host.tp_show(window as i32);
    Ok(None)
}
