//! StrFormat (§1.19, RobotWare 6.11): a text with numbered placeholders filled in.
//!
//! `StrFormat(Str [\Arg1] ... [\Arg10])` replaces each `{1}` ... `{10}` in Str with
//! the string passed as the argument of that number; a placeholder whose argument is
//! not passed, and any other brace, stays as written. A result longer than 80
//! characters is ERR_STRTOOLNG.
//!
//! uncertain: only `\Arg1` and `\Arg2` are in the public record (the RW6 manual
//! extract and programs such as abb-motion-program-exec); the catalogue accepts ten.
//! What happens to a placeholder without its argument is not documented.

use super::{native, present, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{string_len, Value, MAX_STRING_CHARS};

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family { file: file!(), builtins: &[native("StrFormat", str_format)] };

fn str_format(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let text = ctx.string(&args[0])?;
    let mut fills: Vec<Option<String>> = Vec::with_capacity(args.len().saturating_sub(1));
    for arg in &args[1..] {
        fills.push(if present(Some(arg)) { Some(ctx.string(arg)?) } else { None });
    }
    let result = fill(&text, &fills);
    if string_len(&result) > MAX_STRING_CHARS {
        return Err(ctx.error(Err::StringTooLong, "the formatted string is longer than 80 characters"));
    }
    Ok(Some(Value::Str(result.into())))
}

/// `text` with every `{n}` whose argument `fills[n - 1]` is passed replaced by it.
fn fill(text: &str, fills: &[Option<String>]) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        let replacement = after.find('}').and_then(|close| {
            let digits = &after[..close];
            if !digits.bytes().all(|c| c.is_ascii_digit()) {
                return None;
            }
            let number: usize = digits.parse().ok()?;
            let value = fills.get(number.checked_sub(1)?)?.as_deref()?;
            Some((value, close))
        });
        match replacement {
            Some((value, close)) => {
                out.push_str(value);
                rest = &after[close + 1..];
            }
            None => {
                out.push('{');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::fill;

    #[test]
    fn placeholders_are_filled_by_number() {
        let fills = [Some("a".to_string()), None, Some("c".to_string())];
        assert_eq!(fill("{3}-{1}-{2}-{1}", &fills), "c-a-{2}-a");
        assert_eq!(fill("{x} {} {0} {4} {+1} {1", &fills), "{x} {} {0} {4} {+1} {1");
    }
}
