//! Writing to the event log from RAPID: ErrLog and ErrRaise (ErrWrite, which also
//! shows its text on the pendant, lives with the pendant output).

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::events::{expand_errstr, Event, EventKind};
use crate::value::Value;

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[super::native("ErrLog", err_log), super::native("ErrRaise", err_raise)],
};

/// ErrLog and ErrRaise take event numbers 4800..4999 of the user domain. The public
/// record does not say which error an out-of-range number gives; we raise
/// ERR_ARGVALERR (uncertain).
fn event_number(ctx: &Ctx<'_>, arg: &Value) -> Result<u32, RapidError> {
    let id = ctx.num(arg)?;
    if id.fract() != 0.0 || !(4800.0..=4999.0).contains(&id) {
        return Err(ctx.error(Err::ArgValue, format!("ErrorId must be a whole number from 4800 to 4999, not {id}")));
    }
    Ok(id as u32)
}

/// Builds the entry from five errstr arguments: the first is the title, the others
/// the message lines (ERRSTR_UNUSED ones left out).
fn user_event(ctx: &Ctx<'_>, number: u32, kind: EventKind, texts: &[Value]) -> Result<Event, RapidError> {
    let mut expanded = Vec::with_capacity(texts.len());
    for text in texts {
        expanded.push(expand_errstr(&ctx.string(text)?, ctx.resources.tasks.name(), ctx.routine));
    }
    let mut expanded = expanded.into_iter();
    let title = expanded.next().flatten().unwrap_or_default();
    let lines = expanded.flatten().collect();
    Ok(Event::user(number, kind, ctx.time, title, lines))
}

/// `ErrLog ErrorId [\W] | [\I] Argument1 .. Argument5`: logs a user message; the
/// program goes on.
pub(super) fn err_log(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let number = event_number(ctx, &args[0])?;
    let kind = if present(args.get(1)) {
        EventKind::Warning
    } else if present(args.get(2)) {
        EventKind::Info
    } else {
        EventKind::Error
    };
    let event = user_event(ctx, number, kind, &args[3..])?;
    ctx.events.push(event);
    Ok(None)
}

/// `ErrRaise ErrorName ErrorId Argument1 .. Argument5`: logs the error, then raises
/// the error number held by the errnum data named `ErrorName`, which BookErrNo must
/// have booked. The name is looked up among module-level data (where BookErrNo's
/// errnum variables live); an unknown or unbooked name raises ERR_ARGVALERR
/// (the public record gives no error for it: uncertain).
pub(super) fn err_raise(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let name = ctx.string(&args[0])?;
    let number = event_number(ctx, &args[1])?;
    let errno = booked_number(ctx, &name)?;
    let event = user_event(ctx, number, EventKind::Error, &args[2..])?;
    let message = format!("{name}: {}", event.title);
    ctx.events.push(event);
    Err(RapidError { errno, name: "", message, fatal: false, event: None })
}

/// The booked error number held by the module-level errnum data called `name`.
fn booked_number(ctx: &Ctx<'_>, name: &str) -> Result<i32, RapidError> {
    let value = ctx
        .data_by_name
        .get(&name.to_lowercase())
        .and_then(|named| ctx.storage.globals.get(named.global))
        .and_then(Value::as_f64);
    let Some(value) = value else {
        return Err(ctx.error(Err::ArgValue, format!("ErrRaise: no errnum data named `{name}`")));
    };
    let errno = value as i32;
    if f64::from(errno) != value || !crate::exec::is_booked(errno, *ctx.next_booked) {
        return Err(
            ctx.error(Err::ArgValue, format!("ErrRaise: `{name}` holds {value}, not a number booked by BookErrNo"))
        );
    }
    Ok(errno)
}
