//! rawbytes (semantics 3.6): a container of up to 1024 bytes, of which the first
//! `RawBytesLen` are valid. ClearRawBytes, CopyRawBytes, PackRawBytes,
//! UnpackRawBytes, RawBytesLen.
//!
//! The valid bytes live in `OpaqueState::RawBytes`; a fresh rawbytes
//! (`OpaqueState::None`) is empty. The byte-level work is done by pure functions
//! (`pack_*`, `unpack_*`, `clear`, `copy`) so it can be tested without a machine.
//!
//! Errors: an index outside 1..1024, or a read past the valid bytes, raises
//! ERR_OUTOFBND (as for array indexes; ABB's manual names no rawbytes-specific
//! error we know of); a value that does not fit the chosen layout raises
//! ERR_ARGVALERR.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Opaque, OpaqueState, Value, MAX_STRING_CHARS};

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("ClearRawBytes", clear_raw_bytes),
        super::native("CopyRawBytes", copy_raw_bytes),
        super::native("PackRawBytes", pack_raw_bytes),
        super::native("UnpackRawBytes", unpack_raw_bytes),
        super::native("RawBytesLen", raw_bytes_len),
    ],
};

type Res = Result<Option<Value>, RapidError>;
type Fault = (Err, String);

/// How many bytes a rawbytes holds at most.
const RAWBYTES_CAPACITY: usize = 1024;

/// The layout a value is packed in or unpacked from.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Layout {
    /// `\Hex1`: one byte.
    Hex1,
    /// `\IntX`: an integer of `size` bytes, signed or not.
    Int { size: usize, signed: bool },
    /// `\Float4`: an IEEE single.
    Float4,
    /// `\ASCII`: characters (for unpacking, how many).
    Ascii(usize),
}

// ---- pure byte-level operations ---------------------------------------------------------

/// The `inttypes` value (USINT=1 .. ULINT=8, SINT=-1 .. LINT=-8) as a layout.
fn int_layout(inttype: f64) -> Result<Layout, Fault> {
    let code = if inttype.fract() == 0.0 && inttype.abs() <= 8.0 { inttype as i8 } else { 0 };
    let (size, signed) = match code {
        1 | 2 | 4 | 8 => (code as usize, false),
        -1 | -2 | -4 | -8 => (code.unsigned_abs() as usize, true),
        _ => return Err((Err::ArgValue, format!("{inttype} is not an inttypes value (USINT, UINT, ..., LINT)"))),
    };
    Ok(Layout::Int { size, signed })
}

/// A 1-based StartIndex as a 0-based offset, checked against the capacity.
fn start_offset(start: f64) -> Result<usize, Fault> {
    if start.fract() != 0.0 || !(1.0..=RAWBYTES_CAPACITY as f64).contains(&start) {
        return Err((Err::OutOfBounds, format!("the index {start} is outside 1..{RAWBYTES_CAPACITY}")));
    }
    Ok(start as usize - 1)
}

/// Writes `bytes` at 0-based `offset`, zero-filling any gap after the valid bytes and
/// extending the valid length to cover them.
fn write_at(data: &mut Vec<u8>, offset: usize, bytes: &[u8]) -> Result<(), Fault> {
    let end = offset + bytes.len();
    if end > RAWBYTES_CAPACITY {
        return Err((
            Err::OutOfBounds,
            format!(
                "{} bytes at index {} go past the {RAWBYTES_CAPACITY} bytes of a rawbytes",
                bytes.len(),
                offset + 1
            ),
        ));
    }
    if data.len() < end {
        data.resize(end, 0);
    }
    data[offset..end].copy_from_slice(bytes);
    Ok(())
}

/// The `len` valid bytes at 0-based `offset`.
fn read_at(data: &[u8], offset: usize, len: usize) -> Result<&[u8], Fault> {
    data.get(offset..offset + len).ok_or_else(|| {
        (Err::OutOfBounds, format!("{len} bytes at index {} go past the {} valid bytes", offset + 1, data.len()))
    })
}

/// An integer value checked for the layout: integral and within the type's range. A
/// num past 2^23 is packed as the integer it holds (the manual's 0..8388608 for a num
/// is a "limitation for storage", not a documented error).
fn checked_int(value: f64, size: usize, signed: bool) -> Result<i128, Fault> {
    if !value.is_finite() || value.fract() != 0.0 {
        return Err((Err::ArgValue, format!("{value} is not an integer")));
    }
    let bits = 8 * size as u32;
    let (min, max) =
        if signed { (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1) } else { (0, (1i128 << bits) - 1) };
    let v = value as i128;
    if v < min || v > max {
        let sign = if signed { "signed" } else { "unsigned" };
        return Err((Err::ArgValue, format!("{value} does not fit in a {sign} {size}-byte integer")));
    }
    Ok(v)
}

/// Little-endian (or big-endian with `network`) bytes of a two's complement integer.
fn int_bytes(v: i128, size: usize, network: bool) -> Vec<u8> {
    let mut bytes = v.to_le_bytes()[..size].to_vec();
    if network {
        bytes.reverse();
    }
    bytes
}

/// The integer `bytes` hold.
fn bytes_int(bytes: &[u8], signed: bool, network: bool) -> i128 {
    let mut le = bytes.to_vec();
    if network {
        le.reverse();
    }
    let fill = if signed && le.last().is_some_and(|b| b & 0x80 != 0) { 0xFF } else { 0 };
    let mut full = [fill; 16];
    full[..le.len()].copy_from_slice(&le);
    i128::from_le_bytes(full)
}

/// A byte value (0..255, integral).
fn checked_byte(value: f64) -> Result<u8, Fault> {
    if value.fract() != 0.0 || !(0.0..=255.0).contains(&value) {
        return Err((Err::ArgValue, format!("{value} is not a byte (0..255)")));
    }
    Ok(value as u8)
}

/// The bytes `value` packs to in `layout`.
fn pack_bytes(value: &Value, layout: Layout, network: bool) -> Result<Vec<u8>, Fault> {
    let number = value.as_f64();
    let need_number = || (Err::ArgValue, "a num, dnum or byte value was expected".to_string());
    match layout {
        Layout::Hex1 => Ok(vec![checked_byte(number.ok_or_else(need_number)?)?]),
        Layout::Int { size, signed } => {
            let v = checked_int(number.ok_or_else(need_number)?, size, signed)?;
            Ok(int_bytes(v, size, network))
        }
        Layout::Float4 => {
            let bits = (number.ok_or_else(need_number)? as f32).to_bits();
            Ok(if network { bits.to_be_bytes() } else { bits.to_le_bytes() }.to_vec())
        }
        Layout::Ascii(_) => match value {
            Value::Str(s) => {
                if s.is_empty() {
                    return Err((Err::ArgValue, "an empty string cannot be packed with \\ASCII".into()));
                }
                // Strings hold Latin-1 characters, each one byte.
                Ok(s.chars().map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?')).collect())
            }
            other => Ok(vec![checked_byte(other.as_f64().ok_or_else(need_number)?)?]),
        },
    }
}

/// The value `layout` reads from `bytes`, shaped like the target `like` (a string, a
/// num/byte or a dnum).
fn unpack_value(bytes: &[u8], layout: Layout, network: bool, like: &Value) -> Result<Value, Fault> {
    let number = |v: f64| -> Result<Value, Fault> {
        match like {
            Value::Dnum(_) => Ok(Value::Dnum(v)),
            // uncertain: an integer past 2^23 unpacked into a num becomes the nearest num
            // (the manual calls 0..8388608 a limitation for storage and documents no
            // error; a public ROS-Industrial driver fork unpacks its 0xFFFFFFFF
            // end-of-message marker into a num and compares it with 4294967295).
            Value::Num(_) => Ok(Value::Num(v as f32)),
            _ => Err((Err::ArgValue, "the value to unpack into must be a num, dnum or byte".into())),
        }
    };
    match layout {
        Layout::Hex1 => number(f64::from(bytes[0])),
        Layout::Int { signed, .. } => number(bytes_int(bytes, signed, network) as f64),
        Layout::Float4 => {
            let raw: [u8; 4] = bytes.try_into().expect("four bytes");
            let f = if network { f32::from_be_bytes(raw) } else { f32::from_le_bytes(raw) };
            match like {
                Value::Dnum(_) => Ok(Value::Dnum(f64::from(f))),
                Value::Num(_) => Ok(Value::Num(f)),
                _ => Err((Err::ArgValue, "the value to unpack into must be a num or dnum".into())),
            }
        }
        Layout::Ascii(_) => match like {
            Value::Str(_) => Ok(Value::Str(bytes.iter().map(|&b| char::from(b)).collect::<String>().into())),
            _ if bytes.len() == 1 => number(f64::from(bytes[0])),
            _ => Err((Err::ArgValue, "\\ASCII into a byte reads exactly 1 character".into())),
        },
    }
}

fn layout_len(layout: Layout) -> usize {
    match layout {
        Layout::Hex1 => 1,
        Layout::Int { size, .. } => size,
        Layout::Float4 => 4,
        Layout::Ascii(n) => n,
    }
}

/// PackRawBytes on the valid bytes.
fn pack(data: &mut Vec<u8>, value: &Value, start: f64, layout: Layout, network: bool) -> Result<(), Fault> {
    let offset = start_offset(start)?;
    let bytes = pack_bytes(value, layout, network)?;
    write_at(data, offset, &bytes)
}

/// UnpackRawBytes on the valid bytes.
fn unpack(data: &[u8], start: f64, layout: Layout, network: bool, like: &Value) -> Result<Value, Fault> {
    let offset = start_offset(start)?;
    let bytes = read_at(data, offset, layout_len(layout))?;
    unpack_value(bytes, layout, network, like)
}

/// ClearRawBytes: zero from FromIndex (default 1) on; the valid length becomes
/// FromIndex - 1.
fn clear(data: &mut Vec<u8>, from: Option<f64>) -> Result<(), Fault> {
    let offset = match from {
        None => 0,
        Some(f) => start_offset(f)?,
    };
    data.resize(offset, 0);
    Ok(())
}

/// CopyRawBytes: `count` bytes (default: all valid ones from `from_index`) from `from`
/// at `from_index` into `to` at `to_index`; `to`'s valid length grows to cover them.
/// Without `count`, a `from_index` just past the valid bytes copies nothing.
fn copy(from: &[u8], from_index: f64, to: &mut Vec<u8>, to_index: f64, count: Option<f64>) -> Result<(), Fault> {
    let src = start_offset(from_index)?;
    let dst = start_offset(to_index)?;
    // uncertain: the manual does not say what FromIndex = RawBytesLen + 1 does without
    // \NoOfBytes. Behavioural evidence: the ROS-Industrial driver copies the empty data
    // part of a header-only reply this way (FromIndex 1 of an empty rawbytes) and works
    // on real controllers, so it copies the zero bytes from there to the end and leaves
    // ToRawData as it is. Indexes further out stay ERR_OUTOFBND.
    if count.is_none() && src == from.len() {
        return Ok(());
    }
    if src >= from.len() {
        return Err((Err::OutOfBounds, format!("FromIndex {from_index} is past the {} valid bytes", from.len())));
    }
    let count = match count {
        None => from.len() - src,
        Some(n) if n.fract() == 0.0 && n >= 0.0 => n as usize,
        Some(n) => return Err((Err::ArgValue, format!("NoOfBytes {n} is not a whole number of bytes"))),
    };
    let bytes = read_at(from, src, count)?.to_vec();
    write_at(to, dst, &bytes)
}

// ---- the built-ins ------------------------------------------------------------------------

/// The valid bytes of the rawbytes an argument names, with its opaque shell.
fn raw_state(ctx: &Ctx<'_>, arg: &Value) -> Result<(Vec<u8>, Opaque), RapidError> {
    match ctx.value(arg)? {
        Value::Opaque(opaque) => match &opaque.state {
            OpaqueState::RawBytes(bytes) => Ok((bytes.clone(), *opaque)),
            OpaqueState::None => Ok((Vec::new(), *opaque)),
            _ => Err(ctx.error(Err::ArgValue, "a rawbytes was expected")),
        },
        _ => Err(ctx.error(Err::ArgValue, "a rawbytes was expected")),
    }
}

fn set_raw(ctx: &mut Ctx<'_>, arg: &Value, mut opaque: Opaque, bytes: Vec<u8>) -> Result<(), RapidError> {
    opaque.state = OpaqueState::RawBytes(bytes);
    ctx.store(arg, Value::Opaque(Box::new(opaque)))
}

fn fault(ctx: &Ctx<'_>, (err, message): Fault) -> RapidError {
    ctx.error(err, message)
}

/// The layout chosen by `\Hex1 | \IntX | \Float4 | \ASCII`, at the positions `at` (in that order);
/// `ascii_count` says whether \ASCII carries a character count (UnpackRawBytes).
fn chosen_layout(ctx: &Ctx<'_>, args: &[Value], at: [usize; 4], ascii_count: bool) -> Result<Layout, RapidError> {
    let [hex1, int_x, float4, ascii] = at;
    if present(args.get(hex1)) {
        return Ok(Layout::Hex1);
    }
    if let Some(t) = ctx.opt_num(args.get(int_x))? {
        return int_layout(t).map_err(|f| fault(ctx, f));
    }
    if present(args.get(float4)) {
        return Ok(Layout::Float4);
    }
    match args.get(ascii) {
        Some(a) if !a.is_absent() => {
            if !ascii_count {
                return Ok(Layout::Ascii(0));
            }
            let n = ctx.num(a)?;
            // uncertain: the manual gives 1..80 characters; \ASCII:=0 unpacks the empty
            // string, as real clients rely on (abb_motion_program_exec sends zero-length
            // strings, read with the length field as the count, and works on real robots).
            if n.fract() != 0.0 || !(0.0..=MAX_STRING_CHARS as f64).contains(&n) {
                return Err(ctx.error(Err::ArgValue, format!("\\ASCII:={n} is not a character count in 0..80")));
            }
            Ok(Layout::Ascii(n as usize))
        }
        _ => Err(ctx.error(Err::ArgValue, "one of \\Hex1, \\IntX, \\Float4 or \\ASCII must be given")),
    }
}

/// `ClearRawBytes RawData [\FromIndex]`.
pub(super) fn clear_raw_bytes(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (mut bytes, opaque) = raw_state(ctx, &args[0])?;
    let from = ctx.opt_num(args.get(1))?;
    clear(&mut bytes, from).map_err(|f| fault(ctx, f))?;
    set_raw(ctx, &args[0], opaque, bytes)?;
    Ok(None)
}

super::signature::layout! {
    static COPY: CopyArgs = "CopyRawBytes" { to: "ToRawData", to_index: "ToIndex", no_of_bytes: "NoOfBytes" }
    static PACK: PackArgs = "PackRawBytes" {
        network: "Network", start: "StartIndex", hex1: "Hex1", int_x: "IntX", float4: "Float4", ascii: "ASCII",
    }
    static UNPACK: UnpackArgs = "UnpackRawBytes" {
        network: "Network", start: "StartIndex", value: "Value", hex1: "Hex1", int_x: "IntX", float4: "Float4",
        ascii: "ASCII",
    }
}

/// `CopyRawBytes FromRawData FromIndex ToRawData ToIndex [\NoOfBytes]`.
pub(super) fn copy_raw_bytes(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *COPY;
    let (from, _) = raw_state(ctx, &args[0])?;
    let from_index = ctx.num(&args[1])?;
    let (mut to, opaque) = raw_state(ctx, &args[at.to])?;
    let to_index = ctx.num(&args[at.to_index])?;
    let count = ctx.opt_num(args.get(at.no_of_bytes))?;
    copy(&from, from_index, &mut to, to_index, count).map_err(|f| fault(ctx, f))?;
    set_raw(ctx, &args[at.to], opaque, to)?;
    Ok(None)
}

/// `PackRawBytes Value RawData [\Network] StartIndex [\Hex1]|[\IntX]|[\Float4]|[\ASCII]`.
pub(super) fn pack_raw_bytes(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *PACK;
    let value = ctx.value(&args[0])?;
    let (mut bytes, opaque) = raw_state(ctx, &args[1])?;
    let network = present(args.get(at.network));
    let start = ctx.num(&args[at.start])?;
    let layout = chosen_layout(ctx, args, [at.hex1, at.int_x, at.float4, at.ascii], false)?;
    pack(&mut bytes, &value, start, layout, network).map_err(|f| fault(ctx, f))?;
    set_raw(ctx, &args[1], opaque, bytes)?;
    Ok(None)
}

/// `UnpackRawBytes RawData [\Network] StartIndex Value [\Hex1]|[\IntX]|[\Float4]|[\ASCII:=n]`.
pub(super) fn unpack_raw_bytes(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *UNPACK;
    let (bytes, _) = raw_state(ctx, &args[0])?;
    let network = present(args.get(at.network));
    let start = ctx.num(&args[at.start])?;
    let like = ctx.value(&args[at.value])?;
    let layout = chosen_layout(ctx, args, [at.hex1, at.int_x, at.float4, at.ascii], true)?;
    let value = unpack(&bytes, start, layout, network, &like).map_err(|f| fault(ctx, f))?;
    ctx.store(&args[at.value], value)?;
    Ok(None)
}

/// `RawBytesLen(RawData)`: the number of valid bytes.
pub(super) fn raw_bytes_len(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (bytes, _) = raw_state(ctx, &args[0])?;
    Ok(Some(Value::Num(bytes.len() as f32)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn int(t: f64) -> Layout {
        int_layout(t).unwrap()
    }

    #[test]
    fn pack_layouts() {
        // (value, layout, network, expected bytes), worked out by hand.
        let cases: &[(Value, Layout, bool, &[u8])] = &[
            (Value::Num(258.0), int(2.0), false, &[0x02, 0x01]),
            (Value::Num(258.0), int(2.0), true, &[0x01, 0x02]),
            (Value::Num(-1.0), int(-2.0), false, &[0xFF, 0xFF]),
            (Value::Num(-2.0), int(-1.0), false, &[0xFE]),
            (Value::Num(255.0), int(1.0), false, &[0xFF]),
            (Value::Num(65536.0), int(4.0), false, &[0x00, 0x00, 0x01, 0x00]),
            (Value::Num(65536.0), int(4.0), true, &[0x00, 0x01, 0x00, 0x00]),
            (Value::Num(-256.0), int(-4.0), false, &[0x00, 0xFF, 0xFF, 0xFF]),
            (Value::Dnum(4294967296.0), int(8.0), false, &[0, 0, 0, 0, 1, 0, 0, 0]),
            (Value::Dnum(4294967296.0), int(8.0), true, &[0, 0, 0, 1, 0, 0, 0, 0]),
            (Value::Dnum(-1.0), int(-8.0), true, &[0xFF; 8]),
            (Value::Dnum(4294967295.0), int(4.0), false, &[0xFF; 4]),
            // 1.0f32 = 0x3F800000; -2.5f32 = 0xC0200000.
            (Value::Num(1.0), Layout::Float4, false, &[0x00, 0x00, 0x80, 0x3F]),
            (Value::Num(1.0), Layout::Float4, true, &[0x3F, 0x80, 0x00, 0x00]),
            (Value::Num(-2.5), Layout::Float4, true, &[0xC0, 0x20, 0x00, 0x00]),
            (Value::Num(171.0), Layout::Hex1, false, &[0xAB]),
            (Value::Str("AB1".into()), Layout::Ascii(0), false, &[0x41, 0x42, 0x31]),
            (Value::Num(65.0), Layout::Ascii(0), false, &[0x41]),
        ];
        for (value, layout, network, expected) in cases {
            assert_eq!(pack_bytes(value, *layout, *network).unwrap(), *expected, "{value:?} {layout:?} {network}");
        }
    }

    #[test]
    fn pack_rejects() {
        let cases: &[(Value, Layout, Err)] = &[
            (Value::Num(256.0), int(1.0), Err::ArgValue),
            (Value::Num(-1.0), int(2.0), Err::ArgValue),
            (Value::Num(128.0), int(-1.0), Err::ArgValue),
            (Value::Num(-129.0), int(-1.0), Err::ArgValue),
            (Value::Num(65536.0), int(2.0), Err::ArgValue),
            (Value::Num(1.5), int(4.0), Err::ArgValue),
            // The num literal 4294967295 is 4294967296, one past UDINT.
            (Value::Num(4294967295.0), int(4.0), Err::ArgValue),
            (Value::Dnum(4294967296.0), int(4.0), Err::ArgValue),
            (Value::Num(256.0), Layout::Hex1, Err::ArgValue),
            (Value::Num(-1.0), Layout::Hex1, Err::ArgValue),
            (Value::Str("".into()), Layout::Ascii(0), Err::ArgValue),
            (Value::Str("x".into()), Layout::Hex1, Err::ArgValue),
        ];
        for (value, layout, err) in cases {
            assert_eq!(pack_bytes(value, *layout, false).unwrap_err().0, *err, "{value:?} {layout:?}");
        }
        assert!(int_layout(3.0).is_err());
        // A num past 2^23 packs as the integer it holds.
        assert_eq!(pack_bytes(&Value::Num(16777216.0), int(4.0), false).unwrap(), [0, 0, 0, 1]);
    }

    #[test]
    fn unpack_layouts() {
        // (bytes, layout, network, target like, expected)
        let n = Value::Num(0.0);
        let d = Value::Dnum(0.0);
        let s = Value::Str("".into());
        let cases: &[(&[u8], Layout, bool, &Value, Value)] = &[
            (&[0x02, 0x01], int(2.0), false, &n, Value::Num(258.0)),
            (&[0x02, 0x01], int(2.0), true, &n, Value::Num(513.0)),
            (&[0xFF, 0xFF], int(-2.0), false, &n, Value::Num(-1.0)),
            (&[0xFF, 0xFF], int(2.0), false, &n, Value::Num(65535.0)),
            (&[0xFE], int(-1.0), false, &n, Value::Num(-2.0)),
            (&[0x00, 0xFF, 0xFF, 0xFF], int(-4.0), false, &n, Value::Num(-256.0)),
            (&[0xFF; 4], int(4.0), false, &d, Value::Dnum(4294967295.0)),
            (&[0, 0, 0, 1, 0, 0, 0, 0], int(8.0), true, &d, Value::Dnum(4294967296.0)),
            (&[0xFF; 8], int(-8.0), false, &d, Value::Dnum(-1.0)),
            (&[0x3F, 0x80, 0x00, 0x00], Layout::Float4, true, &n, Value::Num(1.0)),
            (&[0x00, 0x00, 0x20, 0xC0], Layout::Float4, false, &n, Value::Num(-2.5)),
            (&[0xAB], Layout::Hex1, false, &n, Value::Num(171.0)),
            (&[0x41, 0x42], Layout::Ascii(2), false, &s, Value::Str("AB".into())),
            (&[0x41], Layout::Ascii(1), false, &n, Value::Num(65.0)),
            (&[], Layout::Ascii(0), false, &s, Value::Str("".into())),
        ];
        for (bytes, layout, network, like, expected) in cases {
            assert_eq!(unpack_value(bytes, *layout, *network, like).unwrap(), *expected, "{bytes:?} {layout:?}");
        }
        // 0xFFFFFFFF into a num is the nearest num, 2^32.
        assert_eq!(unpack_value(&[0xFF; 4], int(4.0), false, &n).unwrap(), Value::Num(4294967296.0));
        // No character into a byte is no byte.
        assert_eq!(unpack_value(&[], Layout::Ascii(0), false, &n).unwrap_err().0, Err::ArgValue);
        // Zero characters are read at any index up to just past the valid bytes.
        let text = Value::Str("unchanged".into());
        assert_eq!(unpack(&[0x20; 4], 5.0, Layout::Ascii(0), false, &text).unwrap(), Value::Str("".into()));
        assert_eq!(unpack(&[], 1.0, Layout::Ascii(0), false, &text).unwrap(), Value::Str("".into()));
        assert_eq!(unpack(&[0x20; 4], 6.0, Layout::Ascii(0), false, &text).unwrap_err().0, Err::OutOfBounds);
    }

    #[test]
    fn pack_extends_and_unpack_bounds() {
        let mut data = Vec::new();
        pack(&mut data, &Value::Num(258.0), 1.0, int(2.0), false).unwrap();
        assert_eq!(data, [0x02, 0x01]);
        // Packing past the end zero-fills the gap.
        pack(&mut data, &Value::Num(7.0), 5.0, Layout::Hex1, false).unwrap();
        assert_eq!(data, [0x02, 0x01, 0, 0, 7]);
        // Overwriting inside keeps the length.
        pack(&mut data, &Value::Num(9.0), 1.0, Layout::Hex1, false).unwrap();
        assert_eq!(data, [9, 0x01, 0, 0, 7]);
        let n = Value::Num(0.0);
        assert_eq!(unpack(&data, 2.0, int(2.0), false, &n).unwrap(), Value::Num(1.0));
        assert_eq!(unpack(&data, 5.0, int(2.0), false, &n).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(unpack(&data, 0.0, Layout::Hex1, false, &n).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(pack(&mut data, &n, 1025.0, Layout::Hex1, false).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(pack(&mut data, &n, 1022.0, int(4.0), false).unwrap_err().0, Err::OutOfBounds);
        pack(&mut data, &n, 1021.0, int(4.0), false).unwrap();
        assert_eq!(data.len(), 1024);
    }

    #[test]
    fn clear_and_copy() {
        let mut data = vec![1, 2, 3, 4, 5];
        clear(&mut data, Some(3.0)).unwrap();
        assert_eq!(data, [1, 2]);
        clear(&mut data, Some(5.0)).unwrap();
        assert_eq!(data, [1, 2, 0, 0]);
        clear(&mut data, None).unwrap();
        assert!(data.is_empty());
        assert_eq!(clear(&mut data, Some(0.0)).unwrap_err().0, Err::OutOfBounds);

        let from = [10, 20, 30, 40];
        let mut to = vec![1, 2, 3, 4, 5, 6];
        copy(&from, 2.0, &mut to, 2.0, Some(2.0)).unwrap();
        assert_eq!(to, [1, 20, 30, 4, 5, 6]);
        copy(&from, 3.0, &mut to, 6.0, None).unwrap();
        assert_eq!(to, [1, 20, 30, 4, 5, 30, 40]);
        // Just past the valid bytes: without \NoOfBytes nothing is copied, `to` is left
        // as it is (also its length, ToIndex past its end); with it, or further out, the
        // index is out of bounds.
        copy(&from, 5.0, &mut to, 9.0, None).unwrap();
        assert_eq!(to, [1, 20, 30, 4, 5, 30, 40]);
        let mut empty_to = vec![7, 7, 7, 7];
        copy(&[], 1.0, &mut empty_to, 5.0, None).unwrap();
        assert_eq!(empty_to, [7, 7, 7, 7]);
        assert_eq!(copy(&[], 2.0, &mut empty_to, 5.0, None).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(copy(&from, 6.0, &mut to, 1.0, None).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(copy(&from, 5.0, &mut to, 1.0, Some(1.0)).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(copy(&from, 5.0, &mut to, 1025.0, None).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(copy(&from, 2.0, &mut to, 1.0, Some(4.0)).unwrap_err().0, Err::OutOfBounds);
        assert_eq!(copy(&from, 1.0, &mut to, 1023.0, None).unwrap_err().0, Err::OutOfBounds);
    }
}
