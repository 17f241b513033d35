//! Pure built-in functions: those whose result depends on their IN arguments alone and
//! that touch no controller state. The fast loop calls them on the arguments where
//! they lie on the stack, without building a call context; they answer `None`
//! whenever anything is unusual (a wrong type, a value the function refuses), and the
//! call then takes the general path through the built-in's own implementation, which
//! raises the RAPID error. Each must give exactly what that implementation gives.

use super::BuiltinId;
use crate::value::Value;

/// A pure function on the arguments passed (optional ones not passed are left off
/// the end).
pub type PureFn = fn(&[Value]) -> Option<Value>;

/// The pure functions, by the catalogue's name; each mirrors the entry of the same
/// name in its family (`strings.rs`).
static PURE: &[(&str, PureFn)] =
    &[("StrLen", str_len), ("NumToStr", num_to_str), ("StrPart", str_part), ("StrFind", str_find), ("StrMap", str_map)];

static BY_ID: std::sync::LazyLock<Vec<Option<PureFn>>> = std::sync::LazyLock::new(|| {
    let mut table = Vec::new();
    for &(name, function) in PURE {
        if let Some(id) = super::lookup(name) {
            let at = id.0 as usize;
            if table.len() <= at {
                table.resize(at + 1, None);
            }
            table[at] = Some(function);
        }
    }
    table
});

/// The pure form of built-in `id`, if it has one.
#[inline]
pub fn pure(id: BuiltinId) -> Option<PureFn> {
    BY_ID.get(id.0 as usize).copied().flatten()
}

/// `StrLen(Str)`: characters, not bytes.
fn str_len(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s)] => Some(Value::Num(s.chars().count() as f32)),
        _ => None,
    }
}

/// `NumToStr(Val, Dec [\Exp])`.
fn num_to_str(args: &[Value]) -> Option<Value> {
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
fn str_part(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s), Value::Num(start), Value::Num(len)] => {
            super::strings::part(s, f64::from(*start), f64::from(*len)).ok()
        }
        _ => None,
    }
}

/// `StrFind(Str, ChPos, Set)` (with `\NotInSet` the call takes the general path).
fn str_find(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s), Value::Num(start), Value::Str(set)] => {
            super::strings::find(s, f64::from(*start), set, false).ok()
        }
        _ => None,
    }
}

/// `StrMap(Str, FromMap, ToMap)`.
fn str_map(args: &[Value]) -> Option<Value> {
    match args {
        [Value::Str(s), Value::Str(from), Value::Str(to)] => Some(super::strings::map(s, from, to)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(name: &str, args: &[Value]) -> Option<Value> {
        let id = super::super::lookup(name).expect("a built-in");
        pure(id).expect("a pure form")(args)
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
        assert!(pure(super::super::lookup("TPWrite").expect("TPWrite")).is_none());
    }
}
