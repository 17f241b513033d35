//! Pendant dialogs that wait for the operator: TPReadNum, TPReadDnum, TPReadFK,
//! UINumEntry, UIDnumEntry, UIAlphaEntry, UIClientExist. Answers come from the host
//! (`rapid run --tp-input FILE`); with none left, the dialog fails as it does when no
//! pendant is connected (ERR_TP_NO_CLIENT), or with \MaxTime as a timeout
//! (ERR_TP_MAXTIME). With \BreakFlag the error number is stored there instead.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

type Res = Result<Option<Value>, RapidError>;

/// Parameter positions in the catalogue's signatures (see the doc of each function).
const READ_NUM_MAX_TIME: usize = 2;
const READ_NUM_BREAK_FLAG: usize = 9;
const READ_FK_KEYS: std::ops::Range<usize> = 2..7;
const READ_FK_MAX_TIME: usize = 7;
const READ_FK_BREAK_FLAG: usize = 14;

/// The next answer, or the error (stored in \BreakFlag when given) of a dialog that
/// gets none.
fn answer(
    ctx: &mut Ctx<'_>,
    prompt: &str,
    max_time: Option<&Value>,
    break_flag: Option<&Value>,
) -> Result<Option<String>, RapidError> {
    if let Some(text) = ctx.host.tp_answer(prompt) {
        return Ok(Some(text.trim().to_string()));
    }
    let err = if present(max_time) { Err::TpMaxTime } else { Err::TpNoClient };
    let error = ctx.error(err, "no operator answered the pendant dialog (see --tp-input)");
    match break_flag.filter(|f| present(Some(f))) {
        Some(flag) => {
            ctx.store(flag, Value::Num(error.errno as f32))?;
            Ok(None)
        }
        None => Err(error),
    }
}

fn parse_num(ctx: &Ctx<'_>, text: &str) -> Result<f64, RapidError> {
    let (negative, body) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text),
    };
    match rapid_syntax::literal::num_value(body) {
        Some(v) => Ok(if negative { -v } else { v }),
        None => Err(ctx.error(Err::ArgValue, format!("the operator's answer `{text}` is not a number"))),
    }
}

/// `TPReadNum TPAnswer, TPText [\MaxTime] ... [\BreakFlag]` (and TPReadDnum).
pub(super) fn tp_read_num(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = ctx.string(&args[1])?;
    if let Some(text) = answer(ctx, &prompt, args.get(READ_NUM_MAX_TIME), args.get(READ_NUM_BREAK_FLAG))? {
        let value = parse_num(ctx, &text)?;
        ctx.store(&args[0], Value::Dnum(value))?;
    }
    Ok(None)
}

/// `TPReadFK TPAnswer, TPText, FK1, ..., FK5 ...`: the answer is the key number 1..5
/// or the text of a key.
pub(super) fn tp_read_fk(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = ctx.string(&args[1])?;
    let Some(text) = answer(ctx, &prompt, args.get(READ_FK_MAX_TIME), args.get(READ_FK_BREAK_FLAG))? else {
        return Ok(None);
    };
    let mut keys = Vec::new();
    for idx in READ_FK_KEYS {
        keys.push(ctx.string(&args[idx])?);
    }
    let key = match text.parse::<usize>() {
        Ok(n) if (1..=5).contains(&n) && !keys[n - 1].is_empty() => n,
        _ => match keys.iter().position(|k| !k.is_empty() && k.eq_ignore_ascii_case(&text)) {
            Some(idx) => idx + 1,
            None => return Err(ctx.error(Err::ArgValue, format!("`{text}` is none of the function keys"))),
        },
    };
    ctx.store(&args[0], Value::Num(key as f32))?;
    Ok(None)
}

/// `UINumEntry(...)` / `UIDnumEntry(...)`: the operator's number, checked against
/// \MinValue and \MaxValue (parameters 6 and 7).
pub(super) fn ui_num_entry(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = match args.get(1) {
        Some(v) if present(Some(v)) => ctx.string(v)?,
        _ => String::new(),
    };
    let Some(text) = answer(ctx, &prompt, args.get(9), None)? else { return Ok(None) };
    let value = parse_num(ctx, &text)?;
    let (min, max) = (ctx.opt_num(args.get(6))?, ctx.opt_num(args.get(7))?);
    if min.is_some_and(|m| value < m) || max.is_some_and(|m| value > m) {
        return Err(ctx.error(Err::ArgValue, format!("the operator's answer {value} is outside the allowed range")));
    }
    Ok(Some(Value::Num(value as f32)))
}

/// `UIDnumEntry(...)`: [`ui_num_entry`] giving a dnum.
pub(super) fn ui_dnum_entry(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(ui_num_entry(ctx, args)?.map(|v| Value::Dnum(v.as_f64().unwrap_or(0.0))))
}

/// `UIAlphaEntry(...)`: the operator's text.
pub(super) fn ui_alpha_entry(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = match args.get(1) {
        Some(v) if present(Some(v)) => ctx.string(v)?,
        _ => String::new(),
    };
    let Some(text) = answer(ctx, &prompt, args.get(6), None)? else { return Ok(None) };
    if text.chars().count() > crate::value::MAX_STRING_CHARS {
        return Err(ctx.error(Err::StringTooLong, "the operator's answer is longer than 80 characters"));
    }
    Ok(Some(Value::Str(text.into_boxed_str())))
}

/// `UIClientExist()`: a pendant is connected when the host can answer dialogs.
pub(super) fn ui_client_exist(_ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    // The virtual controller always has its (scripted) pendant.
    Ok(Some(Value::Bool(true)))
}
