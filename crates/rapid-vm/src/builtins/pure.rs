//! Pure built-in functions: those whose result depends on their IN arguments alone and
//! that touch no controller state. The fast loop calls them on the arguments where
//! they lie on the stack, without building a call context; they answer `None`
//! whenever anything is unusual (a wrong type, a value the function refuses), and the
//! call then takes the general path through the built-in's own implementation, which
//! raises the RAPID error. Each must give exactly what that implementation gives.
//! A family registers a pure form beside the built-in's implementation
//! (`native("Abs", abs).with_pure(pure::abs)`).

use super::math;
use crate::value::Value;

/// A pure function on the arguments passed (optional ones not passed are left off
/// the end).
pub type PureFn = fn(&[Value]) -> Option<Value>;

/// `StrLen(Str)`: characters, not bytes.
pub(super) fn str_len(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s)] => Some(Value::Num(s.chars().count() as f32)),
        _ => None,
    }
}

/// `NumToStr(Val, Dec [\Exp])`.
pub(super) fn num_to_str(args: &[Value]) -> Option<Value> {
    let (value, dec, exp) = match args {
        [Value::Num(v), Value::Num(d)] => (*v, *d, false),
        [Value::Num(v), Value::Num(d), Value::SwitchOn] => (*v, *d, true),
        _ => return None,
    };
    let dec = crate::format::decimals_argument(f64::from(dec)).ok()?;
    let text = crate::format::num_to_str_value(f64::from(value), dec, exp).ok()?;
    Some(Value::Str(text))
}

/// `StrPart(Str, ChPos, Len)`.
pub(super) fn str_part(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s), Value::Num(start), Value::Num(len)] => {
            super::strings::part(s, f64::from(*start), f64::from(*len)).ok()
        }
        _ => None,
    }
}

/// `StrFind(Str, ChPos, Set)` (with `\NotInSet` the call takes the general path).
pub(super) fn str_find(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s), Value::Num(start), Value::Str(set)] => {
            super::strings::find(s, f64::from(*start), set, false).ok()
        }
        _ => None,
    }
}

/// `StrMap(Str, FromMap, ToMap)`.
pub(super) fn str_map(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s), Value::Str(from), Value::Str(to)] => Some(super::strings::map(s, from, to)),
        _ => None,
    }
}

/// A number as the general path reads it (`Ctx::num`).
fn number(value: &Value) -> Option<f64> {
    match value {
        Value::Num(n) => Some(f64::from(*n)),
        Value::Dnum(d) => Some(*d),
        _ => None,
    }
}

/// `Abs(Input)`, `AbsDnum`.
pub(super) fn abs(args: &[Value]) -> Option<Value> {
    let [v] = args else { return None };
    Some(math::same_kind(v, number(v)?.abs()))
}

/// `Sqrt(Value)`, `SqrtDnum`: a negative value takes the general path (its error).
pub(super) fn sqrt(args: &[Value]) -> Option<Value> {
    let [v] = args else { return None };
    let x = number(v).filter(|x| *x >= 0.0)?;
    Some(math::same_kind(v, x.sqrt()))
}

/// The value and `\Dec` of Round and Trunc (0 without it).
fn value_and_decimals(args: &[Value]) -> Option<(&Value, f64, i32)> {
    match args {
        [v] => Some((v, number(v)?, 0)),
        [v, d] => Some((v, number(v)?, math::valid_decimals(number(d)?)?)),
        _ => None,
    }
}

pub(super) fn round(args: &[Value]) -> Option<Value> {
    let (v, x, dec) = value_and_decimals(args)?;
    Some(math::same_kind(v, math::round_to(x, dec)))
}

pub(super) fn trunc(args: &[Value]) -> Option<Value> {
    let (v, x, dec) = value_and_decimals(args)?;
    Some(math::same_kind(v, math::trunc_to(x, dec)))
}

/// Sin, Cos, Tan of a num in degrees.
fn degrees(args: &[Value], f: fn(f64) -> f64) -> Option<Value> {
    let [v] = args else { return None };
    Some(math::trig_result(false, f(number(v)?.to_radians())))
}

pub(super) fn sin(args: &[Value]) -> Option<Value> {
    degrees(args, f64::sin)
}

pub(super) fn cos(args: &[Value]) -> Option<Value> {
    degrees(args, f64::cos)
}

pub(super) fn tan(args: &[Value]) -> Option<Value> {
    degrees(args, f64::tan)
}

/// `ATan2(Y, X)` in degrees.
pub(super) fn atan2(args: &[Value]) -> Option<Value> {
    let [y, x] = args else { return None };
    Some(math::trig_result(false, number(y)?.atan2(number(x)?).to_degrees()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(name: &str, args: &[Value]) -> Option<Value> {
        let core = super::super::Builtins::core();
        let id = core.lookup(name).expect("a built-in");
        core.pure_form(id).unwrap_or_else(|| panic!("no pure form of {name}"))(args)
    }

    #[test]
    fn pure_forms_answer_the_usual_and_leave_the_rest() {
        let s = |t: &str| Value::Str(t.into());
        assert_eq!(call("StrLen", &[s("héllo")]), Some(Value::Num(5.0)));
        assert_eq!(call("NumToStr", &[Value::Num(7.0), Value::Num(0.0)]), Some(s("7")));
        assert_eq!(call("NumToStr", &[Value::Num(0.12345), Value::Num(3.0)]), Some(s("0.123")));
        // Out-of-range decimals: the general path raises ERR_ARGVALUE.
        assert_eq!(call("NumToStr", &[Value::Num(1.0), Value::Num(-1.0)]), None);
        assert_eq!(call("StrLen", &[Value::Num(1.0)]), None);
        assert_eq!(call("StrPart", &[s("abcdef"), Value::Num(2.0), Value::Num(3.0)]), Some(s("bcd")));
        // Past the end: the general path raises ERR_OUTOFBND.
        assert_eq!(call("StrPart", &[s("abc"), Value::Num(2.0), Value::Num(3.0)]), None);
        assert_eq!(call("StrFind", &[s("abcabc"), Value::Num(3.0), s("ab")]), Some(Value::Num(4.0)));
        assert_eq!(call("StrFind", &[s("abc"), Value::Num(9.0), s("a")]), None);
        assert_eq!(call("StrMap", &[s("abc"), s("ab"), s("AB")]), Some(s("ABc")));
        assert_eq!(call("Abs", &[Value::Num(-2.5)]), Some(Value::Num(2.5)));
        assert_eq!(call("AbsDnum", &[Value::Dnum(-2.5)]), Some(Value::Dnum(2.5)));
        assert_eq!(call("Sqrt", &[Value::Num(-1.0)]), None);
        assert_eq!(call("Round", &[Value::Num(2.5)]), Some(Value::Num(3.0)));
        assert_eq!(call("Round", &[Value::Num(-1.25), Value::Num(1.0)]), Some(Value::Num(-1.3)));
        assert_eq!(call("Trunc", &[Value::Num(1.99), Value::Num(1.0)]), Some(Value::Num(1.9)));
        assert_eq!(call("Round", &[Value::Num(1.0), Value::Num(16.0)]), None);
        assert_eq!(call("Cos", &[Value::Num(0.0)]), Some(Value::Num(1.0)));
        assert_eq!(call("ATan2", &[Value::Num(1.0), Value::Num(0.0)]), Some(Value::Num(90.0)));
        let core = super::super::Builtins::core();
        assert!(core.pure_form(core.lookup("TPWrite").expect("TPWrite")).is_none());
    }
}
