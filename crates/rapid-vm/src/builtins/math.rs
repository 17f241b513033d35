//! Arithmetic built-ins (§1.15): functions return the numeric kind of their argument
//! (the `...Dnum` forms get dnums); trigonometry works in degrees.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("Max", max),
        super::native("Min", min),
        super::native("Abs", abs).with_pure(super::pure::abs),
        super::native("AbsDnum", abs).with_pure(super::pure::abs),
        super::native("Sqrt", sqrt).with_pure(super::pure::sqrt),
        super::native("SqrtDnum", sqrt).with_pure(super::pure::sqrt),
        super::native("Pow", pow),
        super::native("PowDnum", pow),
        super::native("Exp", exp),
        super::native("Round", round).with_pure(super::pure::round),
        super::native("RoundDnum", round).with_pure(super::pure::round),
        super::native("Trunc", trunc).with_pure(super::pure::trunc),
        super::native("TruncDnum", trunc).with_pure(super::pure::trunc),
        super::native("Sin", sin).with_pure(super::pure::sin),
        super::native("Cos", cos).with_pure(super::pure::cos),
        super::native("Tan", tan).with_pure(super::pure::tan),
        super::native("ASin", asin),
        super::native("ACos", acos),
        super::native("ATan", atan),
        super::native("ATan2", atan2).with_pure(super::pure::atan2),
        super::native("SinDnum", sin_dnum),
        super::native("CosDnum", cos_dnum),
        super::native("TanDnum", tan_dnum),
        super::native("ASinDnum", asin_dnum),
        super::native("ACosDnum", acos_dnum),
        super::native("ATanDnum", atan_dnum),
        super::native("ATan2Dnum", atan2_dnum),
        super::native("TryInt", try_int),
        super::native("Incr", incr),
        super::native("Decr", decr),
        super::native("Add", add),
        super::native("Clear", clear),
        super::native("DotProd", dot_prod),
        super::native("CrossProd", cross_prod),
        super::native("VectMagn", vect_magn),
        super::native("NumToDnum", num_to_dnum),
        super::native("DnumToNum", dnum_to_num),
    ],
};

type Res = Result<Option<Value>, RapidError>;

/// A result of the same numeric kind as `like`.
pub(super) fn same_kind(like: &Value, x: f64) -> Value {
    match like {
        Value::Dnum(_) => Value::Dnum(x),
        _ => Value::Num(x as f32),
    }
}

fn unary(ctx: &mut Ctx<'_>, args: &[Value], f: impl Fn(f64) -> f64) -> Res {
    let value = ctx.value(&args[0])?;
    let x = ctx.num(&value)?;
    Ok(Some(same_kind(&value, f(x))))
}

pub(super) fn abs(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    unary(ctx, args, f64::abs)
}

pub(super) fn sqrt(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if ctx.num(&args[0])? < 0.0 {
        return Err(ctx.error(Err::ArgValue, "Sqrt of a negative number"));
    }
    unary(ctx, args, f64::sqrt)
}

pub(super) fn exp(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    unary(ctx, args, f64::exp)
}

pub(super) fn pow(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let base_value = ctx.value(&args[0])?;
    let (base, exponent) = (ctx.num(&base_value)?, ctx.num(&args[1])?);
    if (base < 0.0 && exponent.fract() != 0.0) || (base == 0.0 && exponent <= 0.0) {
        return Err(ctx.error(Err::ArgValue, format!("Pow({base}, {exponent}) is not defined")));
    }
    Ok(Some(same_kind(&base_value, base.powf(exponent))))
}

/// Round half away from zero to `\Dec` decimals (0 without it).
pub(super) fn round(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let dec = decimals(ctx, args.get(1))?;
    unary(ctx, args, |x| round_to(x, dec))
}

/// Cut (toward zero) to `\Dec` decimals.
pub(super) fn trunc(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let dec = decimals(ctx, args.get(1))?;
    unary(ctx, args, |x| trunc_to(x, dec))
}

pub(super) fn round_to(x: f64, dec: i32) -> f64 {
    let scale = 10f64.powi(dec);
    (x * scale).round() / scale
}

pub(super) fn trunc_to(x: f64, dec: i32) -> f64 {
    let scale = 10f64.powi(dec);
    (x * scale).trunc() / scale
}

fn decimals(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<i32, RapidError> {
    match ctx.opt_num(arg)? {
        None => Ok(0),
        Some(d) => {
            valid_decimals(d).ok_or_else(|| ctx.error(Err::ArgValue, format!("{d} is not a number of decimals")))
        }
    }
}

/// `\Dec` of Round and Trunc: a whole number 0..=15.
pub(super) fn valid_decimals(d: f64) -> Option<i32> {
    (d >= 0.0 && d.fract() == 0.0 && d <= 15.0).then_some(d as i32)
}

/// A trigonometric result: num for Sin/Cos/..., dnum for the `...Dnum` forms.
pub(super) fn trig_result(dnum: bool, x: f64) -> Value {
    if dnum {
        Value::Dnum(x)
    } else {
        Value::Num(x as f32)
    }
}

fn degrees(ctx: &mut Ctx<'_>, args: &[Value], dnum: bool, f: impl Fn(f64) -> f64) -> Res {
    let x = ctx.num(&args[0])?;
    Ok(Some(trig_result(dnum, f(x.to_radians()))))
}

pub(super) fn sin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    degrees(ctx, args, false, f64::sin)
}

pub(super) fn cos(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    degrees(ctx, args, false, f64::cos)
}

pub(super) fn tan(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    degrees(ctx, args, false, f64::tan)
}

pub(super) fn sin_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    degrees(ctx, args, true, f64::sin)
}

pub(super) fn cos_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    degrees(ctx, args, true, f64::cos)
}

pub(super) fn tan_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    degrees(ctx, args, true, f64::tan)
}

fn inverse(ctx: &mut Ctx<'_>, args: &[Value], unit_range: bool, dnum: bool, f: impl Fn(f64) -> f64) -> Res {
    let x = ctx.num(&args[0])?;
    if unit_range && !(-1.0..=1.0).contains(&x) {
        return Err(ctx.error(Err::ArgValue, format!("{x} is outside -1..1")));
    }
    Ok(Some(trig_result(dnum, f(x).to_degrees())))
}

pub(super) fn asin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    inverse(ctx, args, true, false, f64::asin)
}

pub(super) fn acos(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    inverse(ctx, args, true, false, f64::acos)
}

pub(super) fn atan(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    inverse(ctx, args, false, false, f64::atan)
}

pub(super) fn asin_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    inverse(ctx, args, true, true, f64::asin)
}

pub(super) fn acos_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    inverse(ctx, args, true, true, f64::acos)
}

pub(super) fn atan_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    inverse(ctx, args, false, true, f64::atan)
}

pub(super) fn atan2(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (y, x) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    Ok(Some(trig_result(false, y.atan2(x).to_degrees())))
}

pub(super) fn atan2_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (y, x) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    Ok(Some(trig_result(true, y.atan2(x).to_degrees())))
}

/// `TryInt DataObj | DataObj2`: a num must hold an integer of at most 8388608 in
/// magnitude, a dnum one of at most 4503599627370496 (the exact-integer ranges,
/// docs/semantics.md). Which of ERR_INT_NOTVAL / ERR_INT_MAXVAL the controller
/// raises for a too-large integer is our reading of their names (uncertain).
pub(super) fn try_int(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let value = ctx.value(first_present(&args[..2]))?;
    let (x, limit) = match value {
        Value::Dnum(d) => (d, 4_503_599_627_370_496.0),
        other => (ctx.num(&other)?, 8_388_608.0),
    };
    if x.fract() != 0.0 || !x.is_finite() {
        return Err(ctx.error(Err::IntNotValue, format!("{x} is not an integer")));
    }
    if x.abs() > limit {
        return Err(ctx.error(Err::IntMaxValue, format!("{x} is beyond the exact integers ({limit})")));
    }
    Ok(None)
}

/// The first argument of a required `Name | Dname` pair that was passed.
fn first_present(args: &[Value]) -> &Value {
    args.iter().find(|a| present(Some(a))).unwrap_or(&Value::Absent)
}

fn update(ctx: &mut Ctx<'_>, target: &Value, f: impl Fn(f64) -> f64) -> Res {
    let current = ctx.value(target)?;
    let x = ctx.num(&current)?;
    ctx.store(target, same_kind(&current, f(x)))?;
    Ok(None)
}

pub(super) fn incr(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    update(ctx, first_present(&args[..2]), |x| x + 1.0)
}

pub(super) fn decr(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    update(ctx, first_present(&args[..2]), |x| x - 1.0)
}

pub(super) fn clear(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    update(ctx, first_present(&args[..2]), |_| 0.0)
}

pub(super) fn add(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let amount = ctx.num(first_present(&args[2..4]))?;
    update(ctx, first_present(&args[..2]), |x| x + amount)
}

fn pos_parts(ctx: &Ctx<'_>, arg: &Value) -> Result<[f64; 3], RapidError> {
    match ctx.value(arg)? {
        Value::Record(r) => {
            let get = |i: usize| r.fields.get(i).and_then(Value::as_f64).unwrap_or(0.0);
            Ok([get(0), get(1), get(2)])
        }
        _ => Err(ctx.error(Err::ArgValue, "a pos argument was expected")),
    }
}

pub(super) fn dot_prod(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (a, b) = (pos_parts(ctx, &args[0])?, pos_parts(ctx, &args[1])?);
    Ok(Some(Value::Num((a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) as f32)))
}

pub(super) fn cross_prod(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (a, b) = (pos_parts(ctx, &args[0])?, pos_parts(ctx, &args[1])?);
    let c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    Ok(Some(ctx.pos(c[0] as f32, c[1] as f32, c[2] as f32)))
}

pub(super) fn vect_magn(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let a = pos_parts(ctx, &args[0])?;
    Ok(Some(Value::Num((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt() as f32)))
}

pub(super) fn num_to_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(Some(Value::Dnum(ctx.num(&args[0])?)))
}

/// `DnumToNum(Value [\Integer])`: the value as a num; with \Integer it must be an
/// integer that a num holds exactly.
pub(super) fn dnum_to_num(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let x = ctx.num(&args[0])?;
    if present(args.get(1)) && (x.fract() != 0.0 || x.abs() > 8_388_608.0) {
        return Err(ctx.error(Err::NumLimit, format!("{x} is not an integer a num holds exactly")));
    }
    if x.abs() > f64::from(f32::MAX) {
        return Err(ctx.error(Err::NumLimit, format!("{x} does not fit in a num")));
    }
    Ok(Some(Value::Num(x as f32)))
}

pub(super) fn max(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (a, b) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    Ok(Some(Value::Num(a.max(b) as f32)))
}

pub(super) fn min(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (a, b) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    Ok(Some(Value::Num(a.min(b) as f32)))
}
