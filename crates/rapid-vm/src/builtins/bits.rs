//! Bit functions (manual §1.15, semantics 3.2) and the byte/digit-string conversions
//! (semantics 3.1): BitAnd ... BitCheck on bytes (0..255, bit positions 1..8, 1 = least
//! significant), their `...Dnum` forms on unsigned integer dnums (0..2^52-1, positions
//! 1..52), the instructions BitSet/BitClear, ByteToStr/StrToByte, DecToHex/HexToDec.
//!
//! Errors: the manual gives the valid ranges (byte 0-255, bit position 1-8 or 1-52,
//! shift steps 1-8 or 1-52, dnum data 0-4503599627370495) but the public material does not
//! name the error raised outside them, nor for badly formed text given to StrToByte,
//! DecToHex or HexToDec. All of these raise ERR_ARGVALERR (argument value error) here.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("BitAnd", bit_and),
        super::native("BitOr", bit_or),
        super::native("BitXOr", bit_xor),
        super::native("BitNeg", bit_neg),
        super::native("BitLSh", bit_lsh),
        super::native("BitRSh", bit_rsh),
        super::native("BitCheck", bit_check),
        super::native("BitSet", bit_set),
        super::native("BitClear", bit_clear),
        super::native("BitAndDnum", bit_and_dnum),
        super::native("BitOrDnum", bit_or_dnum),
        super::native("BitXOrDnum", bit_xor_dnum),
        super::native("BitNegDnum", bit_neg_dnum),
        super::native("BitLShDnum", bit_lsh_dnum),
        super::native("BitRShDnum", bit_rsh_dnum),
        super::native("BitCheckDnum", bit_check_dnum),
        super::native("ByteToStr", byte_to_str),
        super::native("StrToByte", str_to_byte),
        super::native("DecToHex", dec_to_hex),
        super::native("HexToDec", hex_to_dec),
    ],
};

type Res = Result<Option<Value>, RapidError>;

/// The largest integer the dnum bit functions take: 2^52 - 1.
const DNUM_BITS_MAX: u64 = (1 << 52) - 1;

/// The largest value DecToHex/HexToDec convert: 2^63 - 1 (semantics 3.1 marks it `(?)`).
const DIGITS_MAX: u64 = i64::MAX as u64;

/// An integer argument in `lo..=hi`; `what` names it in the error message.
fn int_in(ctx: &Ctx<'_>, arg: &Value, lo: u64, hi: u64, what: &str) -> Result<u64, RapidError> {
    let x = ctx.num(arg)?;
    if x.fract() == 0.0 && x >= lo as f64 && x <= hi as f64 {
        Ok(x as u64)
    } else {
        Err(ctx.error(Err::ArgValue, format!("{what} {x} is outside {lo}..{hi} or not an integer")))
    }
}

fn byte(ctx: &Ctx<'_>, arg: &Value) -> Result<u8, RapidError> {
    int_in(ctx, arg, 0, 255, "byte value").map(|b| b as u8)
}

fn dnum(ctx: &Ctx<'_>, arg: &Value) -> Result<u64, RapidError> {
    int_in(ctx, arg, 0, DNUM_BITS_MAX, "dnum bit data")
}

/// A bit position or shift count in `1..=max`.
fn steps(ctx: &Ctx<'_>, arg: &Value, max: u64, what: &str) -> Result<u32, RapidError> {
    int_in(ctx, arg, 1, max, what).map(|n| n as u32)
}

/// Mask of the lowest `bits` bits.
fn mask(bits: u32) -> u64 {
    (1u64 << bits) - 1
}

/// The optional `\Size` of the dnum forms: 1..52 bits, 52 without it.
fn size(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<u32, RapidError> {
    match arg {
        Some(a) if present(Some(a)) => steps(ctx, a, 52, "Size"),
        _ => Ok(52),
    }
}

fn byte_value(b: u64) -> Res {
    Ok(Some(Value::Num(b as f32)))
}

fn dnum_value(d: u64) -> Res {
    Ok(Some(Value::Dnum(d as f64)))
}

// --- bytes -----------------------------------------------------------------------------

fn byte_pair(ctx: &Ctx<'_>, args: &[Value], op: fn(u8, u8) -> u8) -> Res {
    let (a, b) = (byte(ctx, &args[0])?, byte(ctx, &args[1])?);
    byte_value(u64::from(op(a, b)))
}

pub(super) fn bit_and(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    byte_pair(ctx, args, |a, b| a & b)
}

pub(super) fn bit_or(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    byte_pair(ctx, args, |a, b| a | b)
}

pub(super) fn bit_xor(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    byte_pair(ctx, args, |a, b| a ^ b)
}

pub(super) fn bit_neg(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    byte_value(u64::from(!byte(ctx, &args[0])?))
}

/// BitLSh: 1..8 steps; bits pushed past bit 8 are lost.
pub(super) fn bit_lsh(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let b = u64::from(byte(ctx, &args[0])?);
    let n = steps(ctx, &args[1], 8, "ShiftSteps")?;
    byte_value((b << n) & 0xFF)
}

pub(super) fn bit_rsh(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let b = u64::from(byte(ctx, &args[0])?);
    let n = steps(ctx, &args[1], 8, "ShiftSteps")?;
    byte_value(b >> n)
}

pub(super) fn bit_check(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let b = u64::from(byte(ctx, &args[0])?);
    let pos = steps(ctx, &args[1], 8, "BitPos")?;
    Ok(Some(Value::Bool(b >> (pos - 1) & 1 == 1)))
}

// --- dnums -----------------------------------------------------------------------------

fn dnum_pair(ctx: &Ctx<'_>, args: &[Value], op: fn(u64, u64) -> u64) -> Res {
    let (a, b) = (dnum(ctx, &args[0])?, dnum(ctx, &args[1])?);
    dnum_value(op(a, b))
}

pub(super) fn bit_and_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    dnum_pair(ctx, args, |a, b| a & b)
}

pub(super) fn bit_or_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    dnum_pair(ctx, args, |a, b| a | b)
}

pub(super) fn bit_xor_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    dnum_pair(ctx, args, |a, b| a ^ b)
}

/// BitNegDnum(Value \Size): one's complement over Size bits (52 without it).
pub(super) fn bit_neg_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let d = dnum(ctx, &args[0])?;
    let bits = size(ctx, args.get(1))?;
    dnum_value(!d & mask(bits))
}

/// BitLShDnum(Value ShiftSteps \Size): bits pushed past Size (52 without it) are lost.
pub(super) fn bit_lsh_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let d = dnum(ctx, &args[0])?;
    let n = steps(ctx, &args[1], 52, "ShiftSteps")?;
    let bits = size(ctx, args.get(2))?;
    dnum_value((d << n) & mask(bits))
}

pub(super) fn bit_rsh_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let d = dnum(ctx, &args[0])?;
    let n = steps(ctx, &args[1], 52, "ShiftSteps")?;
    dnum_value(d >> n)
}

pub(super) fn bit_check_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let d = dnum(ctx, &args[0])?;
    let pos = steps(ctx, &args[1], 52, "BitPos")?;
    Ok(Some(Value::Bool(d >> (pos - 1) & 1 == 1)))
}

// --- BitSet / BitClear -------------------------------------------------------------------

crate::builtins::signature::layout! {
    static SET_BIT: SetBitArgs = "BitSet" | "BitClear" { bit_data: "BitData", dnum_data: "DnumData", bit_pos: "BitPos" }
}

/// `BitSet BitData | DnumData, BitPos` (and BitClear): args are BitData, DnumData, BitPos.
/// A dnum gets bit positions 1..52, a byte 1..8.
fn set_bit(ctx: &mut Ctx<'_>, args: &[Value], on: bool) -> Res {
    let at = *SET_BIT;
    let target = if present(args.get(at.bit_data)) { &args[at.bit_data] } else { &args[at.dnum_data] };
    // The kind of the data itself decides: a dnum variable may arrive in either position.
    let is_dnum = matches!(ctx.value(target)?, Value::Dnum(_));
    let (value, max) = if is_dnum { (dnum(ctx, target)?, 52) } else { (u64::from(byte(ctx, target)?), 8) };
    let pos = steps(ctx, &args[at.bit_pos], max, "BitPos")?;
    let bit = 1u64 << (pos - 1);
    let new = if on { value | bit } else { value & !bit };
    let new = if is_dnum { Value::Dnum(new as f64) } else { Value::Num(new as f32) };
    ctx.store(target, new)?;
    Ok(None)
}

pub(super) fn bit_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    set_bit(ctx, args, true)
}

pub(super) fn bit_clear(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    set_bit(ctx, args, false)
}

// --- ByteToStr / StrToByte ---------------------------------------------------------------

/// The text form of a byte: the switch after BitData/ConStr (\Hex \Okt \Bin \Char).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Form {
    Dec,
    Hex,
    Okt,
    Bin,
    Char,
}

fn form(args: &[Value]) -> Form {
    [Form::Hex, Form::Okt, Form::Bin, Form::Char]
        .into_iter()
        .zip(1..)
        .find(|&(_, i)| present(args.get(i)))
        .map_or(Form::Dec, |(f, _)| f)
}

/// Decimal without leading zeros; hex 2, octal 3 and binary 8 digits with them; a
/// character is the Latin-1 one with that code.
fn format_byte(b: u8, form: Form) -> String {
    match form {
        Form::Dec => b.to_string(),
        Form::Hex => format!("{b:02X}"),
        Form::Okt => format!("{b:03o}"),
        Form::Bin => format!("{b:08b}"),
        Form::Char => char::from(b).to_string(),
    }
}

/// The reverse of [`format_byte`]. Digits only (hex in either case), at most as many as
/// the longest form has (3 decimal, 2 hex, 3 octal, 8 binary), at most 255; a character
/// form is exactly one character.
fn parse_byte(text: &str, form: Form) -> Option<u8> {
    let (radix, width) = match form {
        Form::Char => {
            let mut chars = text.chars();
            let c = chars.next()?;
            return if chars.next().is_none() { u8::try_from(u32::from(c)).ok() } else { None };
        }
        Form::Dec => (10, 3),
        Form::Hex => (16, 2),
        Form::Okt => (8, 3),
        Form::Bin => (2, 8),
    };
    if text.is_empty() || text.len() > width || !text.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    u8::try_from(u32::from_str_radix(text, radix).ok()?).ok()
}

pub(super) fn byte_to_str(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let b = byte(ctx, &args[0])?;
    Ok(Some(Value::Str(format_byte(b, form(args)).into())))
}

pub(super) fn str_to_byte(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let text = ctx.string(&args[0])?;
    let form = form(args);
    match parse_byte(&text, form) {
        Some(b) => byte_value(u64::from(b)),
        None => Err(ctx.error(Err::ArgValue, format!("\"{text}\" is not a byte in {form:?} form"))),
    }
}

// --- DecToHex / HexToDec -----------------------------------------------------------------

/// Parses digits of `radix` only (no sign, no blanks) up to [`DIGITS_MAX`].
fn parse_digits(text: &str, radix: u32) -> Option<u64> {
    if text.is_empty() || !text.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    u64::from_str_radix(text, radix).ok().filter(|&v| v <= DIGITS_MAX)
}

fn dec_to_hex_text(text: &str) -> Option<String> {
    parse_digits(text, 10).map(|v| format!("{v:X}"))
}

fn hex_to_dec_text(text: &str) -> Option<String> {
    parse_digits(text, 16).map(|v| v.to_string())
}

fn digits(ctx: &mut Ctx<'_>, args: &[Value], convert: fn(&str) -> Option<String>, what: &str) -> Res {
    let text = ctx.string(&args[0])?;
    match convert(&text) {
        Some(s) => Ok(Some(Value::Str(s.into()))),
        None => Err(ctx.error(Err::ArgValue, format!("\"{text}\" is not a {what} number in 0..{DIGITS_MAX}"))),
    }
}

pub(super) fn dec_to_hex(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    digits(ctx, args, dec_to_hex_text, "decimal")
}

pub(super) fn hex_to_dec(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    digits(ctx, args, hex_to_dec_text, "hexadecimal")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{load, Exit, RecordingHost};
    use rapid_sema::SourceInput;

    #[test]
    fn byte_forms_both_ways() {
        let cases: &[(u8, Form, &str)] = &[
            (0, Form::Dec, "0"),
            (7, Form::Dec, "7"),
            (255, Form::Dec, "255"),
            (0, Form::Hex, "00"),
            (10, Form::Hex, "0A"),
            (255, Form::Hex, "FF"),
            (0, Form::Okt, "000"),
            (8, Form::Okt, "010"),
            (255, Form::Okt, "377"),
            (0, Form::Bin, "00000000"),
            (5, Form::Bin, "00000101"),
            (255, Form::Bin, "11111111"),
            (65, Form::Char, "A"),
            (32, Form::Char, " "),
            (233, Form::Char, "\u{e9}"),
        ];
        for &(b, form, text) in cases {
            assert_eq!(format_byte(b, form), text, "{b} {form:?}");
            assert_eq!(parse_byte(text, form), Some(b), "{text:?} {form:?}");
        }
    }

    #[test]
    fn str_to_byte_lenient_and_refused() {
        let good: &[(&str, Form, u8)] = &[
            ("ff", Form::Hex, 255),
            ("A", Form::Hex, 10),
            ("7", Form::Okt, 7),
            ("101", Form::Bin, 5),
            ("007", Form::Dec, 7),
        ];
        for &(text, form, b) in good {
            assert_eq!(parse_byte(text, form), Some(b), "{text:?} {form:?}");
        }
        let bad: &[(&str, Form)] = &[
            ("", Form::Dec),
            ("256", Form::Dec),
            ("1000", Form::Dec),
            ("-1", Form::Dec),
            ("+1", Form::Dec),
            (" 1", Form::Dec),
            ("1.5", Form::Dec),
            ("G0", Form::Hex),
            ("100", Form::Hex),
            ("400", Form::Okt),
            ("8", Form::Okt),
            ("2", Form::Bin),
            ("111111111", Form::Bin),
            ("", Form::Char),
            ("AB", Form::Char),
        ];
        for &(text, form) in bad {
            assert_eq!(parse_byte(text, form), None, "{text:?} {form:?}");
        }
    }

    #[test]
    fn digit_strings() {
        let cases: &[(&str, &str)] = &[
            ("0", "0"),
            ("10", "A"),
            ("255", "FF"),
            ("99999999", "5F5E0FF"),
            ("9223372036854775807", "7FFFFFFFFFFFFFFF"),
        ];
        for &(dec, hex) in cases {
            assert_eq!(dec_to_hex_text(dec).as_deref(), Some(hex), "{dec}");
            assert_eq!(hex_to_dec_text(hex).as_deref(), Some(dec), "{hex}");
        }
        assert_eq!(hex_to_dec_text("ff").as_deref(), Some("255"));
        assert_eq!(dec_to_hex_text("0010").as_deref(), Some("A"));
        for bad in ["", "-1", "+1", "1A", " 1", "9223372036854775808", "99999999999999999999"] {
            assert_eq!(dec_to_hex_text(bad), None, "{bad:?}");
        }
        for bad in ["", "G", "-1", "0x10", "8000000000000000"] {
            assert_eq!(hex_to_dec_text(bad), None, "{bad:?}");
        }
    }

    /// Runs `body` in main; the TPWrite lines or the name of the unhandled error.
    fn run(body: &str) -> Result<Vec<String>, String> {
        let src = format!(
            "MODULE t\nPROC main()\n  VAR byte b;\n  VAR dnum d;\n  VAR bool t;\n  VAR string s;\n{body}\nENDPROC\nENDMODULE\n"
        );
        let mut loaded = load(&[SourceInput::from_text("t.mod", &src)], "main")
            .unwrap_or_else(|err| panic!("load failed: {err:?}\n{src}"));
        let mut host = RecordingHost::default();
        match loaded.vm.run(&mut host, 100_000) {
            Exit::Done => Ok(host.lines),
            Exit::Unhandled(u) => Err(u.error.name.to_string()),
            other => panic!("unexpected exit {other:?}"),
        }
    }

    #[test]
    fn byte_functions_in_programs() {
        let cases: &[(&str, &str)] = &[
            ("BitAnd(12, 10)", "8"),
            ("BitOr(12, 10)", "14"),
            ("BitXOr(12, 10)", "6"),
            ("BitNeg(0)", "255"),
            ("BitNeg(170)", "85"),
            ("BitLSh(129, 1)", "2"),
            ("BitLSh(1, 7)", "128"),
            ("BitLSh(1, 8)", "0"),
            ("BitRSh(129, 1)", "64"),
            ("BitRSh(255, 8)", "0"),
        ];
        for &(expr, want) in cases {
            let body = format!("  b := {expr};\n  TPWrite \"\" \\Num:=b;");
            assert_eq!(run(&body), Ok(vec![want.to_string()]), "{expr}");
        }
    }

    #[test]
    fn dnum_functions_in_programs() {
        let cases: &[(&str, &str)] = &[
            ("BitAndDnum(4294967295, 65535)", "65535"),
            ("BitOrDnum(65536, 1)", "65537"),
            ("BitXOrDnum(255, 15)", "240"),
            ("BitNegDnum(38 \\Size:=8)", "217"),
            ("BitNegDnum(4503599627370495)", "0"),
            ("BitLShDnum(1, 20)", "1048576"),
            ("BitLShDnum(129, 1 \\Size:=8)", "2"),
            ("BitRShDnum(1048576, 20)", "1"),
        ];
        for &(expr, want) in cases {
            let body = format!("  d := {expr};\n  TPWrite \"\" \\Dnum:=d;");
            assert_eq!(run(&body), Ok(vec![want.to_string()]), "{expr}");
        }
    }

    #[test]
    fn set_clear_and_check() {
        let body = "  b := 0;\n  BitSet b, 8;\n  BitSet b, 1;\n  TPWrite \"\" \\Num:=b;\n  BitClear b, 8;\n  TPWrite \"\" \\Num:=b;\n  t := BitCheck(b, 1);\n  TPWrite \"\" \\Bool:=t;\n  t := BitCheck(b, 2);\n  TPWrite \"\" \\Bool:=t;\n  d := 0;\n  BitSet d, 52;\n  t := BitCheckDnum(d, 52);\n  TPWrite \"\" \\Bool:=t;\n  BitClear d, 52;\n  BitSet d, 3;\n  TPWrite \"\" \\Dnum:=d;";
        assert_eq!(run(body), Ok(["129", "1", "TRUE", "FALSE", "TRUE", "4"].map(String::from).to_vec()));
    }

    #[test]
    fn out_of_range_arguments_raise_argvalerr() {
        let bodies = [
            "  b := BitAnd(256, 1);",
            "  b := BitNeg(1.5);",
            "  b := BitLSh(1, 9);",
            "  b := BitRSh(1, 0);",
            "  t := BitCheck(1, 9);",
            "  t := BitCheck(1, 0);",
            "  BitSet b, 9;",
            "  BitClear d, 53;",
            "  d := BitAndDnum(-1, 1);",
            "  d := BitOrDnum(4503599627370496, 1);",
            "  d := BitNegDnum(1 \\Size:=53);",
            "  d := BitRShDnum(1, 53);",
            "  t := BitCheckDnum(1, 53);",
            "  s := ByteToStr(300);",
            "  b := StrToByte(\"256\");",
            "  b := StrToByte(\"FG\" \\Hex);",
            "  s := DecToHex(\"12a\");",
            "  s := HexToDec(\"8000000000000000\");",
        ];
        for body in bodies {
            assert_eq!(run(body), Err("ERR_ARGVALERR".to_string()), "{body}");
        }
    }
}
