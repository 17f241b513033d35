//! String built-ins (§1.19). Positions are 1-based; "not found" is the length + 1.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::format::dnum_to_str as dnum_text;
use crate::value::{Value, MAX_STRING_CHARS};

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("StrOrder", str_order),
        super::native("StrToVal", str_to_val),
        super::native("StrLen", str_len).with_pure(super::pure::str_len),
        super::native("StrPart", str_part).with_pure(super::pure::str_part),
        super::native("StrFind", str_find).with_pure(super::pure::str_find),
        super::native("StrMatch", str_match),
        super::native("StrMemb", str_memb),
        super::native("StrMap", str_map).with_pure(super::pure::str_map),
        super::native("NumToStr", num_to_str).with_pure(super::pure::num_to_str),
        super::native("DnumToStr", dnum_to_str),
        super::native("ValToStr", val_to_str),
    ],
};

type Res = Result<Option<Value>, RapidError>;

fn chars(s: &str) -> Vec<char> {
    s.chars().collect()
}

fn text(s: String) -> Option<Value> {
    Some(Value::Str(s.into()))
}

/// Runs `f` on the characters of `s`, kept on the stack: a RAPID string never holds
/// more than 80 (longer text, which no RAPID value has, goes to the heap). The string
/// functions run in tight loops; this keeps them from allocating.
fn with_chars<R>(s: &str, f: impl FnOnce(&[char]) -> R) -> R {
    let mut buf = ['\0'; MAX_STRING_CHARS];
    let mut n = 0;
    for c in s.chars() {
        if n == buf.len() {
            return f(&chars(s));
        }
        buf[n] = c;
        n += 1;
    }
    f(&buf[..n])
}

/// A string value made of `chars` with one allocation (the value's own).
fn text_of(chars: impl Iterator<Item = char>) -> Value {
    // Latin-1 characters take at most 2 bytes in UTF-8.
    let mut buf = [0u8; 2 * MAX_STRING_CHARS];
    let mut len = 0;
    let mut chars = chars.peekable();
    while let Some(&c) = chars.peek() {
        if len + c.len_utf8() > buf.len() {
            // Longer than any RAPID string: build it on the heap.
            let mut long = String::from(std::str::from_utf8(&buf[..len]).unwrap_or_default());
            long.extend(chars);
            return Value::Str(long.into());
        }
        len += c.encode_utf8(&mut buf[len..]).len();
        chars.next();
    }
    Value::Str(std::str::from_utf8(&buf[..len]).unwrap_or_default().into())
}

/// Why a string function refuses its arguments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum StrError {
    /// A character position outside 1..=max.
    Position { pos: f64, max: usize },
    /// StrPart's part runs past the end (or its length is no whole number).
    PartLength(f64),
}

fn str_error(ctx: &Ctx<'_>, err: StrError) -> RapidError {
    match err {
        StrError::Position { pos, max } => {
            ctx.error(Err::OutOfBounds, format!("character position {pos} is outside 1..{max}"))
        }
        StrError::PartLength(len) => ctx.error(Err::OutOfBounds, format!("the part of length {len} runs past the end")),
    }
}

/// A character position 1..=len+1 (len+1 only where the manual allows it).
fn position(pos: f64, len: usize, allow_end: bool) -> Result<usize, StrError> {
    let max = if allow_end { len + 1 } else { len };
    if pos.fract() != 0.0 || pos < 1.0 || pos > max as f64 {
        return Err(StrError::Position { pos, max });
    }
    Ok(pos as usize)
}

pub(super) fn str_len(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    match ctx.value(&args[0])? {
        Value::Str(s) => Ok(Some(Value::Num(s.chars().count() as f32))),
        _ => Err(ctx.error(Err::ArgValue, "a string argument was expected")),
    }
}

super::signature::layout! {
    static PART: PartArgs = "StrPart" { ch_pos: "ChPos", len: "Len" }
    static FIND: FindArgs = "StrFind" { ch_pos: "ChPos", set: "Set", not_in_set: "NotInSet" }
    static MATCH: MatchArgs = "StrMatch" { ch_pos: "ChPos", pattern: "Pattern" }
    static MEMB: MembArgs = "StrMemb" { ch_pos: "ChPos", set: "Set" }
    static MAP: MapArgs = "StrMap" { from: "FromMap", to: "ToMap" }
    static ORDER: OrderArgs = "StrOrder" { str2: "Str2", order: "Order" }
}

pub(super) fn str_part(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *PART;
    let source = ctx.str_arg(&args[0])?;
    let (start, len) = (ctx.num(&args[at.ch_pos])?, ctx.num(&args[at.len])?);
    part(&source, start, len).map(Some).map_err(|e| str_error(ctx, e))
}

/// `StrPart(Str, ChPos, Len)` on plain values.
pub(super) fn part(source: &str, start: f64, len: f64) -> Result<Value, StrError> {
    with_chars(source, |s| {
        let start = position(start, s.len(), true)?;
        if len.fract() != 0.0 || len < 0.0 || start - 1 + len as usize > s.len() {
            return Err(StrError::PartLength(len));
        }
        Ok(text_of(s[start - 1..start - 1 + len as usize].iter().copied()))
    })
}

pub(super) fn str_find(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *FIND;
    let (source, set) = (ctx.str_arg(&args[0])?, ctx.str_arg(&args[at.set])?);
    let start = ctx.num(&args[at.ch_pos])?;
    find(&source, start, &set, present(args.get(at.not_in_set))).map(Some).map_err(|e| str_error(ctx, e))
}

/// `StrFind(Str, ChPos, Set [\NotInSet])` on plain values.
pub(super) fn find(source: &str, start: f64, set: &str, not_in_set: bool) -> Result<Value, StrError> {
    with_chars(source, |s| {
        let start = position(start, s.len(), true)?;
        let found = s.iter().enumerate().skip(start - 1).find(|(_, c)| set.contains(**c) != not_in_set);
        Ok(Value::Num(found.map_or(s.len() + 1, |(i, _)| i + 1) as f32))
    })
}

pub(super) fn str_match(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *MATCH;
    let (source, pattern) = (ctx.str_arg(&args[0])?, ctx.str_arg(&args[at.pattern])?);
    with_chars(&source, |s| {
        let start = position(ctx.num(&args[at.ch_pos])?, s.len(), true).map_err(|e| str_error(ctx, e))?;
        with_chars(&pattern, |pattern| {
            let found = (start - 1..s.len()).find(|&i| s[i..].starts_with(pattern)).map(|i| i + 1);
            Ok(Some(Value::Num(found.unwrap_or(s.len() + 1) as f32)))
        })
    })
}

pub(super) fn str_memb(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *MEMB;
    let (source, set) = (ctx.str_arg(&args[0])?, ctx.str_arg(&args[at.set])?);
    with_chars(&source, |s| {
        let pos = position(ctx.num(&args[at.ch_pos])?, s.len(), false).map_err(|e| str_error(ctx, e))?;
        Ok(Some(Value::Bool(set.contains(s[pos - 1]))))
    })
}

pub(super) fn str_map(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *MAP;
    let (source, from, to) = (ctx.str_arg(&args[0])?, ctx.str_arg(&args[at.from])?, ctx.str_arg(&args[at.to])?);
    Ok(Some(map(&source, &from, &to)))
}

/// `StrMap(Str, FromMap, ToMap)` on plain values.
pub(super) fn map(source: &str, from: &str, to: &str) -> Value {
    with_chars(from, |from| {
        with_chars(to, |to| {
            let map = |c: char| from.iter().position(|&f| f == c).and_then(|i| to.get(i).copied()).unwrap_or(c);
            text_of(source.chars().map(map))
        })
    })
}

pub(super) fn num_to_str(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (value, dec) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    // A Dec that is not a whole number is refused like one out of range (S7).
    let s = crate::format::decimals_argument(dec)
        .and_then(|dec| crate::format::num_to_str_value(value, dec, present(args.get(2))))
        .map_err(|e| ctx.error(Err::ArgValue, e.to_string()))?;
    Ok(Some(Value::Str(s)))
}

pub(super) fn dnum_to_str(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (value, dec) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    let s = crate::format::decimals_argument(dec)
        .and_then(|dec| dnum_text(value, dec, present(args.get(2))))
        .map_err(|e| ctx.error(Err::ArgValue, e.to_string()))?;
    Ok(text(s))
}

/// `ValToStr(Val)`: the value in RAPID literal syntax.
pub(super) fn val_to_str(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let value = ctx.value(&args[0])?;
    let s = literal(&value);
    if s.chars().count() > crate::value::MAX_STRING_CHARS {
        return Err(ctx.error(Err::StringTooLong, "the text of the value is longer than 80 characters"));
    }
    Ok(text(s))
}

/// A value as RAPID literal text (ValToStr's syntax: records and arrays as
/// aggregates), for front ends that read data; `None` for a value of a non-value
/// type (clock, iodev…), which has no literal.
pub fn value_literal(value: &Value) -> Option<String> {
    match value {
        Value::Num(_) | Value::Dnum(_) | Value::Bool(_) | Value::Str(_) => Some(literal(value)),
        Value::Record(r) => r.fields.iter().all(|f| value_literal(f).is_some()).then(|| literal(value)),
        Value::Array(a) => a.elems.iter().all(|e| value_literal(e).is_some()).then(|| literal(value)),
        _ => None,
    }
}

/// Reads RAPID literal text shaped like `template` (StrToVal's reader): the value, or
/// `None` when the text is no literal of the template's type (or has more after it).
pub fn read_literal(text: &str, template: &Value) -> Option<Value> {
    let mut reader = LiteralReader { chars: text.chars().collect(), pos: 0 };
    reader.value_like(template).filter(|_| reader.at_end())
}

fn literal(value: &Value) -> String {
    use crate::format::{aggregate_to_text, bool_to_text, dnum_to_text, num_to_text, string_to_literal};
    match value {
        Value::Num(n) => num_to_text(*n),
        Value::Dnum(d) => dnum_to_text(*d),
        Value::Bool(b) => bool_to_text(*b).to_string(),
        Value::Str(s) => string_to_literal(s),
        Value::Record(r) => aggregate_to_text(&r.fields.iter().map(literal).collect::<Vec<_>>()),
        Value::Array(a) => aggregate_to_text(&a.elems.iter().map(literal).collect::<Vec<_>>()),
        _ => String::new(),
    }
}

/// `StrOrder(Str1, Str2, Order)`: whether Str1 comes before or equals Str2 when
/// characters sort by their position in Order (characters missing from Order sort
/// after all listed ones, by code); a prefix sorts first.
pub(super) fn str_order(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ORDER;
    let (a, b) = (chars(&ctx.string(&args[0])?), chars(&ctx.string(&args[at.str2])?));
    let order = chars(&ctx.string(&args[at.order])?);
    let rank = |c: char| order.iter().position(|&o| o == c).map_or(order.len() + c as usize, |p| p);
    for (x, y) in a.iter().zip(&b) {
        if x != y {
            return Ok(Some(Value::Bool(rank(*x) < rank(*y))));
        }
    }
    Ok(Some(Value::Bool(a.len() <= b.len())))
}

/// `StrToVal(Str, Val)`: reads a RAPID literal of Val's type into Val; FALSE (and Val
/// unchanged) when the text is not such a literal.
pub(super) fn str_to_val(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let text = ctx.string(&args[0])?;
    let template = ctx.value(&args[1])?;
    let mut reader = LiteralReader { chars: text.chars().collect(), pos: 0 };
    let parsed = reader.value_like(&template).filter(|_| reader.at_end());
    match parsed {
        Some(value) => {
            ctx.store(&args[1], value)?;
            Ok(Some(Value::Bool(true)))
        }
        None => Ok(Some(Value::Bool(false))),
    }
}

/// Reads literals shaped like a template value.
struct LiteralReader {
    chars: Vec<char>,
    pos: usize,
}

impl LiteralReader {
    fn skip_blanks(&mut self) {
        while self.chars.get(self.pos).is_some_and(|c| c.is_whitespace()) {
            self.pos += 1;
        }
    }

    fn at_end(&mut self) -> bool {
        self.skip_blanks();
        self.pos == self.chars.len()
    }

    fn eat(&mut self, c: char) -> bool {
        self.skip_blanks();
        if self.chars.get(self.pos) == Some(&c) {
            self.pos += 1;
            return true;
        }
        false
    }

    fn value_like(&mut self, template: &Value) -> Option<Value> {
        self.skip_blanks();
        match template {
            Value::Num(_) => self.number().map(|n| Value::Num(n as f32)),
            Value::Dnum(_) => self.number().map(Value::Dnum),
            Value::Bool(_) => self.word().and_then(|w| match w.to_ascii_uppercase().as_str() {
                "TRUE" => Some(Value::Bool(true)),
                "FALSE" => Some(Value::Bool(false)),
                _ => None,
            }),
            Value::Str(_) => self.string().map(|s| Value::Str(s.into())),
            Value::Record(record) => {
                let fields = self.list(&record.fields)?;
                Some(Value::Record(std::rc::Rc::new(crate::value::Record { ty: record.ty, fields })))
            }
            Value::Array(array) => {
                let elems = self.list(&array.elems)?;
                Some(Value::Array(Box::new(crate::value::Array { dims: array.dims, elems })))
            }
            _ => None,
        }
    }

    fn list(&mut self, templates: &[Value]) -> Option<Vec<Value>> {
        if !self.eat('[') {
            return None;
        }
        let mut out = Vec::with_capacity(templates.len());
        for (idx, template) in templates.iter().enumerate() {
            if idx > 0 && !self.eat(',') {
                return None;
            }
            out.push(self.value_like(template)?);
        }
        self.eat(']').then_some(out)
    }

    fn number(&mut self) -> Option<f64> {
        let start = self.pos;
        while self.chars.get(self.pos).is_some_and(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '+' | '-')) {
            self.pos += 1;
        }
        let text: String = self.chars[start..self.pos].iter().collect();
        let (negative, body) = match text.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, text.strip_prefix('+').unwrap_or(&text)),
        };
        let value = rapid_syntax::literal::num_value(body).filter(|v| v.is_finite())?;
        Some(if negative { -value } else { value })
    }

    fn word(&mut self) -> Option<String> {
        let start = self.pos;
        while self.chars.get(self.pos).is_some_and(|c| c.is_ascii_alphabetic()) {
            self.pos += 1;
        }
        (self.pos > start).then(|| self.chars[start..self.pos].iter().collect())
    }

    fn string(&mut self) -> Option<String> {
        if !self.eat('"') {
            return None;
        }
        let start = self.pos;
        loop {
            match self.chars.get(self.pos)? {
                '"' if self.chars.get(self.pos + 1) == Some(&'"') => self.pos += 2,
                '"' => break,
                _ => self.pos += 1,
            }
        }
        let raw: String = self.chars[start..self.pos].iter().collect();
        self.pos += 1;
        Some(rapid_syntax::literal::string_value(&format!("\"{raw}\"")))
    }
}
