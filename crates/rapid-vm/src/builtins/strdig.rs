//! Digit strings (§1.15, `stringdig`): StrDigCmp and StrDigCalc compare and compute
//! with non-negative integers written as strings of digits, beyond num's exact range.
//!
//! A stringdig holds only the digits 0-9 (leading zeros allowed) and a value of at most
//! 4294967295 (2^32 - 1). Errors: a string that is empty or holds anything but digits is
//! ERR_INT_NOTVAL, a value above the limit ERR_INT_MAXVAL; StrDigCalc raises ERR_CALC_NEG
//! for a negative difference, ERR_CALC_OVERFLOW for a result above the limit and
//! ERR_CALC_DIVZERO for division or remainder by zero. OpDiv divides as DIV does (the
//! integer part); results have no leading zeros.
//!
//! uncertain: the range and the errnos are recalled from ABB's manual (3HAC050917), not
//! confirmed from a public copy; so is the handling of the empty string.

use super::{native, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family =
    Family { file: file!(), builtins: &[native("StrDigCmp", str_dig_cmp), native("StrDigCalc", str_dig_calc)] };

/// The largest value a stringdig may hold.
const STRDIG_MAX: u64 = 4_294_967_295;

// The values of the opnum and opcalc constants (catalogue data.rs).
const LT: f64 = 1.0;
const LTEQ: f64 = 2.0;
const EQ: f64 = 3.0;
const NOTEQ: f64 = 4.0;
const GTEQ: f64 = 5.0;
const GT: f64 = 6.0;
const OP_ADD: f64 = 1.0;
const OP_SUB: f64 = 2.0;
const OP_MULT: f64 = 3.0;
const OP_DIV: f64 = 4.0;
const OP_MOD: f64 = 5.0;

super::signature::layout! {
    static STR_DIG_CMP: StrDigCmpArgs = "StrDigCmp" { relation: "Relation", b: "StrDig2" }
    static STR_DIG_CALC: StrDigCalcArgs = "StrDigCalc" { operation: "Operation", b: "StrDig2" }
}

/// `StrDigCmp(StrDig1, Relation, StrDig2)`: StrDig1 Relation StrDig2, as integers.
fn str_dig_cmp(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *STR_DIG_CMP;
    let a = digits(ctx, &args[0])?;
    let relation = ctx.num(&args[at.relation])?;
    let b = digits(ctx, &args[at.b])?;
    let result = match relation {
        LT => a < b,
        LTEQ => a <= b,
        EQ => a == b,
        NOTEQ => a != b,
        GTEQ => a >= b,
        GT => a > b,
        _ => return Err(ctx.error(Err::ArgValue, format!("{relation} is not an opnum relation"))),
    };
    Ok(Some(Value::Bool(result)))
}

/// `StrDigCalc(StrDig1, Operation, StrDig2)`: the result of the operation, as digits.
fn str_dig_calc(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *STR_DIG_CALC;
    let a = digits(ctx, &args[0])?;
    let operation = ctx.num(&args[at.operation])?;
    let b = digits(ctx, &args[at.b])?;
    let result = match operation {
        OP_ADD => a + b,
        OP_SUB => a.checked_sub(b).ok_or_else(|| ctx.error(Err::CalcNeg, format!("{a} - {b} is negative")))?,
        OP_MULT => a * b,
        OP_DIV | OP_MOD if b == 0 => return Err(ctx.error(Err::CalcDivZero, "division by zero in StrDigCalc")),
        OP_DIV => a / b,
        OP_MOD => a % b,
        _ => return Err(ctx.error(Err::ArgValue, format!("{operation} is not an opcalc operation"))),
    };
    if result > STRDIG_MAX {
        return Err(ctx.error(Err::CalcOverflow, format!("the result {result} is above {STRDIG_MAX}")));
    }
    Ok(Some(Value::Str(result.to_string().into())))
}

/// The value of a stringdig argument. Both operands fit in 32 bits, so sums and
/// products fit in a u64 and are checked against the limit afterwards.
fn digits(ctx: &Ctx<'_>, arg: &Value) -> Result<u64, RapidError> {
    let text = ctx.string(arg)?;
    if text.is_empty() || !text.bytes().all(|c| c.is_ascii_digit()) {
        return Err(ctx.error(Err::IntNotValue, format!("\"{text}\" is not a string of digits")));
    }
    let significant = text.trim_start_matches('0');
    // More than 10 significant digits is above the limit whatever they are.
    let value = match significant.len() {
        0 => Some(0),
        1..=10 => significant.parse::<u64>().ok(),
        _ => None,
    };
    match value {
        Some(v) if v <= STRDIG_MAX => Ok(v),
        _ => Err(ctx.error(Err::IntMaxValue, format!("\"{text}\" is above {STRDIG_MAX}"))),
    }
}
