//! The data of SocketSend / SocketReceive and their UDP forms: `\Str`, `\RawData` or
//! `\Data` turned into the bytes to send, and received bytes stored back into them.
//!
//! Strings are Latin-1, one byte per character, with no terminator; a rawbytes holds
//! its valid bytes in `OpaqueState::RawBytes` (as in rawbytes.rs); a `byte` array holds
//! one byte per element.

use rapid_vm::ext::{present, Ctx, Err, OpaqueState, RapidError, Value, MAX_STRING_CHARS};

/// At most this many bytes are sent or received in one call (the manual's limit).
pub(super) const MAX_BYTES: usize = 1024;

/// Which of the three exclusive data arguments was passed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Str,
    RawData,
    Data,
}

/// The data argument of a call: its kind and where it is (`args[index]`).
#[derive(Debug, Clone, Copy)]
pub(super) struct Slot {
    pub kind: Kind,
    pub index: usize,
}

/// The one data argument passed among `\Str | \RawData | \Data`, which start at
/// `args[first]`.
pub(super) fn chosen(ctx: &Ctx<'_>, args: &[Value], first: usize) -> Result<Slot, RapidError> {
    let kinds = [Kind::Str, Kind::RawData, Kind::Data];
    kinds
        .iter()
        .enumerate()
        .find(|(i, _)| present(args.get(first + i)))
        .map(|(i, kind)| Slot { kind: *kind, index: first + i })
        .ok_or_else(|| ctx.error(Err::ArgValue, "one of \\Str, \\RawData or \\Data must be given"))
}

/// The bytes a send takes from `slot`, cut to `\NoOfBytes` when given.
pub(super) fn bytes_to_send(
    ctx: &Ctx<'_>,
    args: &[Value],
    slot: Slot,
    no_of_bytes: Option<f64>,
) -> Result<Vec<u8>, RapidError> {
    let value = ctx.value(&args[slot.index])?;
    let mut bytes = match slot.kind {
        Kind::Str => match value {
            Value::Str(s) => latin1_bytes(&s),
            _ => return Err(ctx.error(Err::ArgValue, "\\Str must be a string")),
        },
        Kind::RawData => raw_bytes(&value).ok_or_else(|| ctx.error(Err::ArgValue, "\\RawData must be a rawbytes"))?,
        Kind::Data => byte_array(&value).map_err(|(e, m)| ctx.error(e, m))?,
    };
    if let Some(n) = no_of_bytes {
        if n.fract() != 0.0 || n < 0.0 {
            return Err(ctx.error(Err::ArgValue, format!("\\NoOfBytes:={n} is not a number of bytes")));
        }
        // uncertain: the manual gives no error for \NoOfBytes beyond the data; the
        // index-style ERR_OUTOFBND is used.
        if n as usize > bytes.len() {
            return Err(ctx.error(
                Err::OutOfBounds,
                format!("\\NoOfBytes:={n} is more than the {} bytes of the data", bytes.len()),
            ));
        }
        bytes.truncate(n as usize);
    }
    // uncertain: the error for data over the 1024-byte limit is not documented.
    if bytes.len() > MAX_BYTES {
        return Err(
            ctx.error(Err::OutOfBounds, format!("{} bytes: at most {MAX_BYTES} bytes are sent at a time", bytes.len()))
        );
    }
    Ok(bytes)
}

/// How many bytes the receiving argument holds: 80 for a string, 1024 for a rawbytes,
/// the array's size (at most 1024) for a byte array.
pub(super) fn capacity(ctx: &Ctx<'_>, args: &[Value], slot: Slot) -> Result<usize, RapidError> {
    Ok(match slot.kind {
        Kind::Str => MAX_STRING_CHARS,
        Kind::RawData => MAX_BYTES,
        Kind::Data => match ctx.value(&args[slot.index])? {
            Value::Array(array) => array.elems.len().min(MAX_BYTES),
            _ => return Err(ctx.error(Err::ArgValue, "\\Data must be a byte array")),
        },
    })
}

/// `\ReadNoOfBytes`: a whole number from 1 to the receiving argument's capacity.
pub(super) fn read_count(ctx: &Ctx<'_>, n: f64, capacity: usize) -> Result<usize, RapidError> {
    if n.fract() != 0.0 || n < 1.0 {
        return Err(ctx.error(Err::ArgValue, format!("\\ReadNoOfBytes:={n} is not a number of bytes")));
    }
    // uncertain: the error for asking more than the data can hold is not documented.
    if n as usize > capacity {
        return Err(ctx.error(
            Err::OutOfBounds,
            format!("\\ReadNoOfBytes:={n} is more than the {capacity} bytes the data can hold"),
        ));
    }
    Ok(n as usize)
}

/// Stores received bytes into the data argument: the string becomes them, the
/// rawbytes holds exactly them, the array's first elements take them (the others keep
/// their values).
pub(super) fn store_received(ctx: &mut Ctx<'_>, args: &[Value], slot: Slot, bytes: &[u8]) -> Result<(), RapidError> {
    let target = &args[slot.index];
    let value = match slot.kind {
        Kind::Str => Value::Str(latin1_string(bytes).into()),
        Kind::RawData => match ctx.value(target)? {
            Value::Opaque(mut opaque) => {
                opaque.state = OpaqueState::RawBytes(bytes.to_vec());
                Value::Opaque(opaque)
            }
            _ => return Err(ctx.error(Err::ArgValue, "\\RawData must be a rawbytes")),
        },
        Kind::Data => match ctx.value(target)? {
            Value::Array(mut array) => {
                for (elem, byte) in array.elems.iter_mut().zip(bytes) {
                    *elem = Value::Num(f32::from(*byte));
                }
                Value::Array(array)
            }
            _ => return Err(ctx.error(Err::ArgValue, "\\Data must be a byte array")),
        },
    };
    ctx.store(target, value)
}

/// The Latin-1 bytes of a RAPID string (its characters are U+0000..U+00FF).
pub(super) fn latin1_bytes(s: &str) -> Vec<u8> {
    s.chars().map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?')).collect()
}

/// The RAPID string of Latin-1 bytes.
pub(super) fn latin1_string(bytes: &[u8]) -> String {
    bytes.iter().map(|&b| char::from(b)).collect()
}

/// The valid bytes of a rawbytes value (a fresh one is empty).
fn raw_bytes(value: &Value) -> Option<Vec<u8>> {
    match value {
        Value::Opaque(opaque) => match &opaque.state {
            OpaqueState::RawBytes(bytes) => Some(bytes.clone()),
            OpaqueState::None => Some(Vec::new()),
            _ => None,
        },
        _ => None,
    }
}

/// The bytes of a `byte` array, each element checked to be 0..255.
fn byte_array(value: &Value) -> Result<Vec<u8>, (Err, String)> {
    let Value::Array(array) = value else { return Err((Err::ArgValue, "\\Data must be a byte array".into())) };
    array
        .elems
        .iter()
        .map(|elem| match elem.as_f64() {
            Some(v) if v.fract() == 0.0 && (0.0..=255.0).contains(&v) => Ok(v as u8),
            _ => Err((Err::ArgValue, "a \\Data element is not a byte (0..255)".to_string())),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin1_round_trip_keeps_every_byte() {
        let all: Vec<u8> = (0..=255).collect();
        assert_eq!(latin1_bytes(&latin1_string(&all)), all);
        assert_eq!(latin1_bytes("Aé\u{ff}"), vec![0x41, 0xE9, 0xFF]);
    }

    #[test]
    fn byte_arrays_must_hold_bytes() {
        let array = |elems: Vec<Value>| Value::Array(Box::new(rapid_vm::ext::Array { dims: [3, 0, 0], elems }));
        let good = array(vec![Value::Num(0.0), Value::Num(255.0), Value::Num(7.0)]);
        assert_eq!(byte_array(&good), Ok(vec![0, 255, 7]));
        let bad = array(vec![Value::Num(256.0), Value::Num(1.5), Value::Num(-1.0)]);
        assert_eq!(byte_array(&bad).map_err(|(e, _)| e), Err(Err::ArgValue));
    }
}
