//! Writing persistents back into their modules, the way the controller's Save Module
//! does (§1.2.2: "the initial value of a persistent declaration is updated when the
//! module is saved"): only the value text of each changed `PERS` declaration is
//! replaced; every other byte of the file stays as it was. The file itself is replaced
//! atomically (`crate::world::FileSystem::write_atomic`: in the std world,
//! `rapid_controller::host_std::atomic`), so no crash leaves a torn module.

use rapid_syntax::Span;

use crate::format::{aggregate_to_text, bool_to_text, string_to_literal};
use crate::value::Value;

/// Where a module-level persistent's value is written in its file.
#[derive(Debug, Clone, PartialEq)]
pub struct PersSite {
    /// The global holding its value.
    pub global: u32,
    pub file: usize,
    /// The span of the initial value, when the declaration has one.
    pub init: Option<Span>,
    /// Where ` := value` goes when it has none (just before the `;`).
    pub insert_at: u32,
}

/// `text` with the values of `sites` (all in this file) written in, or `None` when
/// every value is already what the file says.
pub fn rewrite(text: &str, sites: &[(&PersSite, &Value)]) -> Option<String> {
    let mut edits: Vec<(u32, u32, String)> = Vec::new();
    for (site, value) in sites {
        let literal = saved_literal(value);
        match site.init {
            Some(span) if span.text(text) == literal => {}
            Some(span) => edits.push((span.start, span.end, literal)),
            None => edits.push((site.insert_at, site.insert_at, format!(" := {literal}"))),
        }
    }
    if edits.is_empty() {
        return None;
    }
    edits.sort_by_key(|e| e.0);
    let mut out = String::with_capacity(text.len() + 64);
    let mut at = 0usize;
    for (start, end, new) in edits {
        out.push_str(text.get(at..start as usize)?);
        out.push_str(&new);
        at = end as usize;
    }
    out.push_str(text.get(at..)?);
    Some(out)
}

/// A value as saved modules write it: RAPID literal syntax, nums with up to six
/// significant digits in `%G` form (`0.00477736`, `4.08276E-07`, `9E+09`). The rule is
/// not published; it is read off modules real controllers saved: in eight public
/// RobotWare 5 and 6 systems we studied, 1,728 of the 1,756 num values of persistents have
/// at most six significant digits, values as small as 4E-07 keep their six digits in
/// exponent form (so the display format's snap to an integer does not apply), and the 28
/// longer ones sit in a few data typed by hand or written by a PC tool (15-digit doubles). Like the controller, saving therefore
/// rounds: a num saved and loaded again may differ in its seventh digit.
pub fn saved_literal(value: &Value) -> String {
    match value {
        Value::Num(n) => saved_num_value(*n),
        Value::Dnum(d) => saved_num(*d, 17),
        Value::Bool(b) => bool_to_text(*b).to_string(),
        Value::Str(s) => string_to_literal(s),
        Value::Record(r) => aggregate_to_text(&r.fields.iter().map(saved_literal).collect::<Vec<_>>()),
        Value::Array(a) => aggregate_to_text(&a.elems.iter().map(saved_literal).collect::<Vec<_>>()),
        _ => String::new(),
    }
}

/// A num as saved: whole numbers in the range the manual says num holds exactly
/// (±8388608) in full — `(?)` no public saved module shows a persistent at or above a
/// million either way, and writing a part counter of 1234567 as `1.23457E+06` would
/// corrupt it at every save, which users of real controllers would have met — anything
/// else with six significant digits.
fn saved_num_value(n: f32) -> String {
    if n.fract() == 0.0 && n.abs() <= 8_388_608.0 {
        // `+ 0.0` turns -0 into 0: the controller writes no negative zero.
        return format!("{:.0}", n + 0.0);
    }
    saved_num(f64::from(n), 6)
}

/// `%.{digits}G`: fixed notation unless the exponent is below -4 or at least
/// `digits`, trailing zeros dropped, exponent written `E+09`.
fn saved_num(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let sci = format!("{:.*e}", digits - 1, x);
    let (mantissa, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    if exp < -4 || exp >= digits as i32 {
        let mantissa = trim_zeros(mantissa);
        let sign = if exp < 0 { '-' } else { '+' };
        return format!("{mantissa}E{sign}{:02}", exp.abs());
    }
    let decimals = (digits as i32 - 1 - exp).max(0) as usize;
    trim_zeros(&format!("{x:.decimals$}")).to_string()
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nums_as_saved_modules_write_them() {
        assert_eq!(saved_num(9e9, 9), "9E+09");
        assert_eq!(saved_num(0.866025404, 9), "0.866025404");
        assert_eq!(saved_num(100.0, 9), "100");
        assert_eq!(saved_num(-0.5, 9), "-0.5");
        assert_eq!(saved_num(1.5e-7, 9), "1.5E-07");
    }

    #[test]
    fn nums_are_saved_with_six_significant_digits_as_controllers_save_them() {
        // Worked by hand with %.6G on the f32 value: f32 0.1 + f32 0.2 is 0.300000011920929
        // → "0.3"; f32 1/3 is 0.3333333432674408 → "0.333333"; 4.0827600e-07 keeps
        // six digits in exponent form (a saved wobjdata quaternion component), 9E9 is
        // the unused external axis, 1046.0549 rounds to "1046.05".
        let num = |x: f32| saved_literal(&Value::Num(x));
        assert_eq!(num(0.1 + 0.2), "0.3");
        assert_eq!(num(1.0 / 3.0), "0.333333");
        assert_eq!(num(4.082_76e-7), "4.08276E-07");
        assert_eq!(num(9e9), "9E+09");
        assert_eq!(num(1046.0549), "1046.05");
        assert_eq!(num(-0.0024257_6), "-0.00242576");
        assert_eq!(num(1_234_567.5), "1.23457E+06");
        assert_eq!(num(1_234_567.0), "1234567");
        assert_eq!(num(-8_388_608.0), "-8388608");
        assert_eq!(num(16_777_216.0), "1.67772E+07");
        assert_eq!(num(-0.0), "0");
    }

    #[test]
    fn only_changed_values_are_rewritten_byte_for_byte() {
        let text = "MODULE m\r\n  PERS num a := 1;\r\n  PERS num b := 2; ! keep\r\n  PERS num c;\r\nENDMODULE\r\n";
        let a = PersSite { global: 0, file: 0, init: Some(Span::new(26, 27)), insert_at: 27 };
        let b = PersSite { global: 1, file: 0, init: Some(Span::new(46, 47)), insert_at: 47 };
        let c = PersSite { global: 2, file: 0, init: None, insert_at: 69 };
        assert_eq!(&text[26..27], "1");
        assert_eq!(&text[46..47], "2");
        assert_eq!(&text[69..70], ";");
        let (one, five, seven) = (Value::Num(1.0), Value::Num(5.0), Value::Num(7.0));
        let out = rewrite(text, &[(&a, &one), (&b, &five), (&c, &seven)]).unwrap();
        assert_eq!(
            out,
            "MODULE m\r\n  PERS num a := 1;\r\n  PERS num b := 5; ! keep\r\n  PERS num c := 7;\r\nENDMODULE\r\n"
        );
        assert_eq!(rewrite(text, &[(&a, &one)]), None);
    }
}
