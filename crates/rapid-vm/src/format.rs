//! How the controller turns values into text (TPWrite, NumToStr, ValToStr, Write).
//!
//! Pure functions, no IO. Every rule here is listed with its source in
//! docs/semantics.md, section "Number and value formatting"; rules marked `(?)` there
//! are our choice where the public record is silent.
//!
//! * [`num_to_text`] / [`dnum_to_text`]: the "standard RAPID format" used by
//!   `TPWrite \Num`, `Write \Num`, `ValToStr` and every aggregate.
//! * [`num_to_str`] / [`dnum_to_str`]: `NumToStr` / `DnumToStr` (fixed decimals, `\Exp`).
//! * [`bool_to_text`], [`aggregate_to_text`], [`string_to_literal`]: the rest of
//!   `ValToStr`'s literal syntax.

mod digits;
#[cfg(test)]
mod tests;

use digits::Digits;
use std::fmt;

/// A RAPID string holds at most this many characters.
pub const MAX_STRING_LEN: usize = rapid_limits::STRING_CHARS;
/// Significant digits of the standard format for `num`.
pub const NUM_SIGNIFICANT_DIGITS: usize = 6;
/// Significant digits of the standard format for `dnum` `(?)`.
pub const DNUM_SIGNIFICANT_DIGITS: usize = 15;
/// Largest `Dec` that `NumToStr` accepts `(?)`.
pub const NUM_MAX_DECIMALS: i32 = 15;
/// Largest `Dec` that `DnumToStr` accepts.
pub const DNUM_MAX_DECIMALS: i32 = 15;
/// A `num` whose fractional part is below this (or above `1 - SNAP`) prints as an integer.
const SNAP: f64 = 0.000005;

/// Why a conversion to text failed, and which RAPID error it raises.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FormatError {
    /// `Dec` of NumToStr/DnumToStr is negative, not an integer, or above the maximum.
    BadDecimals,
    /// The text would be longer than [`MAX_STRING_LEN`] characters.
    StringTooLong,
}

impl FormatError {
    /// The name of the RAPID error (`ERRNO` constant) this failure raises.
    pub fn errno_name(self) -> &'static str {
        match self {
            FormatError::BadDecimals => "ERR_ARGVALERR",
            FormatError::StringTooLong => "ERR_STRTOOLNG",
        }
    }
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FormatError::BadDecimals => write!(f, "number of decimals out of range"),
            FormatError::StringTooLong => write!(f, "string longer than {MAX_STRING_LEN} characters"),
        }
    }
}

impl std::error::Error for FormatError {}

/// Text for a value that is not finite. The controller should never hold one; if it
/// does, we print C's upper-case spelling `(?)`.
fn non_finite(v: f64) -> Option<String> {
    if v.is_nan() {
        Some("NAN".to_string())
    } else if v.is_infinite() {
        Some(if v < 0.0 { "-INF" } else { "INF" }.to_string())
    } else {
        None
    }
}

fn signed(negative: bool, magnitude: String) -> String {
    if negative {
        format!("-{magnitude}")
    } else {
        magnitude
    }
}

/// The standard RAPID format of a `num` (docs/semantics.md N1–N10): at most 6
/// significant digits, no trailing zeros.
///
/// * A fractional part below 0.000005 or above 0.999995 rounds the value to an integer.
/// * Then C `%.6G`: exponent form (`1.67772E+07`, `9E+09`, `5E-05`) when the decimal
///   exponent is below -4 or at least 6, plain decimals otherwise.
/// * A value that shows as zero has no sign `(?)`.
pub fn num_to_text(v: f32) -> String {
    let x = f64::from(v);
    if let Some(text) = non_finite(x) {
        return text;
    }
    let magnitude = x.abs();
    let whole = magnitude.floor();
    // Exact: both operands carry at most 24 significant bits.
    let fraction = magnitude - whole;
    let snapped = if fraction < SNAP {
        Some(whole)
    } else if fraction > 1.0 - SNAP {
        Some(whole + 1.0)
    } else {
        None
    };
    // An integer of at most six digits prints as itself under %.6G: written directly,
    // without the exact digit machinery (the common case; perf on bench/interp/fileio).
    if let Some(integer) = snapped.filter(|&i| i < 1e6) {
        let mut buf = [0u8; INTEGER_TEXT_MAX];
        if let Some(text) = integer_fixed_into(integer, 0, false, &mut buf) {
            return signed(x < 0.0 && integer != 0.0, text.to_string());
        }
    }
    let digits = match snapped {
        Some(integer) => Digits::exact_f64(integer),
        None => Digits::exact_f32(v),
    };
    let text = digits.general(NUM_SIGNIFICANT_DIGITS);
    signed(x < 0.0 && text != "0", text)
}

/// The standard RAPID format of a `dnum` (docs/semantics.md D1–D3): C `%.15G` without
/// trailing zeros, so integers of up to 15 digits print in full (`4294967295`). The digit
/// count and the absence of the num's snap-to-integer rule are `(?)`.
pub fn dnum_to_text(v: f64) -> String {
    if let Some(text) = non_finite(v) {
        return text;
    }
    let text = Digits::exact_f64(v).general(DNUM_SIGNIFICANT_DIGITS);
    signed(v < 0.0 && text != "0", text)
}

fn check_decimals(dec: i32, max: i32) -> Result<usize, FormatError> {
    if (0..=max).contains(&dec) {
        Ok(dec as usize)
    } else {
        Err(FormatError::BadDecimals)
    }
}

/// Shared body of NumToStr and DnumToStr on the exact digits of the value.
fn to_str(negative: bool, digits: &Digits, dec: usize, exp: bool) -> Result<String, FormatError> {
    let text =
        if exp { digits.round_significant(dec + 1).scientific(dec) } else { digits.round_decimals(dec).fixed(dec) };
    // printf semantics: a negative value keeps its sign even if it rounds to zero `(?)`.
    check_length(signed(negative, text))
}

/// `NumToStr(Val Dec [\Exp])` (docs/semantics.md S1–S9).
///
/// `value` is the `num` argument; it is narrowed to f32 first, since a num holds no more.
/// Without `\Exp`: fixed-point with exactly `dec` decimals, no decimal point when `dec`
/// is 0. With `\Exp`: one digit, `dec` decimals, `E`, signed two-digit exponent
/// (`NumToStr(0.38521,2\Exp)` = `"3.85E-01"`). Rounding uses the exact binary value,
/// ties away from zero `(?)`.
///
/// Errors: `dec` outside `0..=NUM_MAX_DECIMALS` → [`FormatError::BadDecimals`]
/// (`ERR_ARGVALERR` `(?)`); a result over 80 characters → `ERR_STRTOOLNG`.
pub fn num_to_str(value: f64, dec: i32, exp: bool) -> Result<String, FormatError> {
    let dec = check_decimals(dec, NUM_MAX_DECIMALS)?;
    let v = value as f32;
    if let Some(text) = non_finite(f64::from(v)) {
        return Ok(text);
    }
    if let Some(text) = integer_fixed(f64::from(v), dec, exp) {
        return Ok(text);
    }
    to_str(v.is_sign_negative(), &Digits::exact_f32(v), dec, exp)
}

/// The common case of an integer value in fixed notation, written without the exact
/// digit machinery: the same text it would produce (`42` with 2 decimals: `42.00`).
fn integer_fixed(value: f64, dec: usize, exp: bool) -> Option<String> {
    let mut buf = [0u8; INTEGER_TEXT_MAX];
    integer_fixed_into(value, dec, exp, &mut buf).map(str::to_string)
}

/// The longest text `integer_fixed_into` writes: sign, 15 digits, point, 15 decimals.
const INTEGER_TEXT_MAX: usize = 40;

/// [`integer_fixed`] written into `buf` (no allocation). Digits are written by hand:
/// the formatting machinery costs more than the rest of NumToStr on the common integer
/// case (measured with perf on bench/interp/strings).
fn integer_fixed_into(value: f64, dec: usize, exp: bool, buf: &mut [u8; INTEGER_TEXT_MAX]) -> Option<&str> {
    if exp || value.fract() != 0.0 || value.abs() >= 1e15 || value == 0.0 && value.is_sign_negative() || dec > 15 {
        return None;
    }
    let int = value as i64;
    let mut digits = [0u8; 20];
    let mut at = digits.len();
    let mut rest = int.unsigned_abs();
    loop {
        at -= 1;
        digits[at] = b'0' + (rest % 10) as u8;
        rest /= 10;
        if rest == 0 {
            break;
        }
    }
    let mut len = 0;
    let mut put = |b: u8| {
        buf[len] = b;
        len += 1;
    };
    if int < 0 {
        put(b'-');
    }
    digits[at..].iter().for_each(|&d| put(d));
    if dec > 0 {
        put(b'.');
        (0..dec).for_each(|_| put(b'0'));
    }
    std::str::from_utf8(&buf[..len]).ok()
}

/// [`num_to_str`] as a string value, with one allocation on the integer path.
pub fn num_to_str_value(value: f64, dec: i32, exp: bool) -> Result<std::rc::Rc<str>, FormatError> {
    let dec_checked = check_decimals(dec, NUM_MAX_DECIMALS)?;
    let v = value as f32;
    let mut buf = [0u8; INTEGER_TEXT_MAX];
    if v.is_finite() {
        if let Some(text) = integer_fixed_into(f64::from(v), dec_checked, exp, &mut buf) {
            return Ok(text.into());
        }
    }
    num_to_str(value, dec, exp).map(|s| s.into())
}

/// `DnumToStr(Val Dec [\Exp])`: [`num_to_str`] for a `dnum` (f64), `dec` up to 15.
pub fn dnum_to_str(value: f64, dec: i32, exp: bool) -> Result<String, FormatError> {
    let dec = check_decimals(dec, DNUM_MAX_DECIMALS)?;
    if let Some(text) = non_finite(value) {
        return Ok(text);
    }
    to_str(value.is_sign_negative(), &Digits::exact_f64(value), dec, exp)
}

/// Converts the RAPID `Dec` argument (a num) to the `dec` that [`num_to_str`] takes.
/// A value that is not an integer is refused like an out-of-range one `(?)`.
pub fn decimals_argument(dec: f64) -> Result<i32, FormatError> {
    if dec.fract() == 0.0 && dec >= f64::from(i32::MIN) && dec <= f64::from(i32::MAX) {
        Ok(dec as i32)
    } else {
        Err(FormatError::BadDecimals)
    }
}

/// `TRUE` or `FALSE`, as TPWrite `\Bool` and ValToStr print a bool.
pub fn bool_to_text(b: bool) -> &'static str {
    if b {
        "TRUE"
    } else {
        "FALSE"
    }
}

/// An aggregate: the parts' texts between brackets, separated by commas, no spaces.
/// Used for records (pos, orient, robtarget, user records) and arrays alike.
pub fn aggregate_to_text(parts: &[String]) -> String {
    let mut out = String::from("[");
    for (i, part) in parts.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push_str(part);
    }
    out.push(']');
    out
}

/// `TPWrite \Pos` / `ValToStr` of a pos `[x,y,z]`.
pub fn pos_to_text(pos: [f32; 3]) -> String {
    aggregate_to_text(&pos.map(num_to_text))
}

/// `TPWrite \Orient` / `ValToStr` of an orient `[q1,q2,q3,q4]`.
pub fn orient_to_text(orient: [f32; 4]) -> String {
    aggregate_to_text(&orient.map(num_to_text))
}

/// A string value written as a RAPID string literal, as ValToStr shows a string and as
/// a string component appears inside an aggregate: between double quotes, with `"` and
/// `\` doubled. Control characters (codes 0–31 and 127) are written as `\hh` with two
/// upper-case hex digits `(?)`; every other character is kept as is.
pub fn string_to_literal(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\"\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 || c as u32 == 0x7F => out.push_str(&format!("\\{:02X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Number of RAPID characters in `s` (each char is one Latin-1 code).
pub fn char_len(s: &str) -> usize {
    s.chars().count()
}

/// Passes `s` through if it fits in a RAPID string, else `ERR_STRTOOLNG`. ValToStr and
/// the string functions end with this check; a robtarget, for example, is usually too
/// long for ValToStr.
pub fn check_length(s: String) -> Result<String, FormatError> {
    if char_len(&s) > MAX_STRING_LEN {
        Err(FormatError::StringTooLong)
    } else {
        Ok(s)
    }
}
