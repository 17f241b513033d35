//! The binary form WriteAnyBin writes and ReadAnyBin reads.
//!
//! ABB's own format is not public: the manual only says the data is written with a
//! checksum, that only ReadAnyBin reads it back, and that ReadAnyBin raises
//! ERR_RANYBIN_CHK on a checksum error and ERR_RANYBIN_EOF when the file ends before
//! all bytes arrived. So this format is ours (uncertain: files are not exchangeable with
//! a real controller):
//!
//! ```text
//! frame   = 0xA5, length: u32 BE (bytes of value), value, checksum: u8
//! value   = 1 num f32 BE | 2 dnum f64 BE | 3 bool u8 | 4 string len:u8 Latin-1 bytes
//!         | 5 record count:u16 BE value* | 6 array dims:3 x u32 BE value*
//! checksum = the two's complement of the sum of the value's bytes (sum + checksum = 0)
//! ```
//!
//! ReadAnyBin rebuilds the value in the shape of its Data argument; data of another
//! shape (a num where a string is expected, an array of another size) is treated as a
//! corrupt transfer: ERR_RANYBIN_CHK (uncertain: the manual only says the types must
//! match).

use rapid_vm::ext::{Array, Err, Record, Value};

type Fault = (Err, String);

const MARKER: u8 = 0xA5;
const TAG_NUM: u8 = 1;
const TAG_DNUM: u8 = 2;
const TAG_BOOL: u8 = 3;
const TAG_STRING: u8 = 4;
const TAG_RECORD: u8 = 5;
const TAG_ARRAY: u8 = 6;

/// Bytes of the frame header: the marker and the length.
pub(super) const HEADER_LEN: usize = 5;

/// The frame WriteAnyBin writes for `value`.
pub(super) fn encode(value: &Value) -> Result<Vec<u8>, Fault> {
    let mut body = Vec::new();
    encode_value(value, &mut body)?;
    let mut frame = Vec::with_capacity(body.len() + HEADER_LEN + 1);
    frame.push(MARKER);
    frame.extend_from_slice(&(body.len() as u32).to_be_bytes());
    frame.extend_from_slice(&body);
    frame.push(checksum(&body));
    Ok(frame)
}

/// The length of the value that follows a frame header, or a checksum fault for bytes
/// that are no frame header.
pub(super) fn body_len(header: &[u8]) -> Result<usize, Fault> {
    match header {
        [MARKER, a, b, c, d] => Ok(u32::from_be_bytes([*a, *b, *c, *d]) as usize),
        _ => Err(corrupt("the data was not written by WriteAnyBin")),
    }
}

/// The value in `body` (checked against `sum`), in the shape of `like`.
pub(super) fn decode(body: &[u8], sum: u8, like: &Value) -> Result<Value, Fault> {
    if checksum(body) != sum {
        return Err(corrupt("checksum error in the data read"));
    }
    let mut at = 0;
    let value = decode_value(body, &mut at, like)?;
    if at != body.len() {
        return Err(corrupt("the data read is longer than the type of Data"));
    }
    Ok(value)
}

fn checksum(body: &[u8]) -> u8 {
    body.iter().fold(0u8, |acc, b| acc.wrapping_add(*b)).wrapping_neg()
}

fn corrupt(message: &str) -> Fault {
    (Err::AnyBinCheck, message.to_string())
}

fn encode_value(value: &Value, out: &mut Vec<u8>) -> Result<(), Fault> {
    match value {
        Value::Num(n) => {
            out.push(TAG_NUM);
            out.extend_from_slice(&n.to_be_bytes());
        }
        Value::Dnum(d) => {
            out.push(TAG_DNUM);
            out.extend_from_slice(&d.to_be_bytes());
        }
        Value::Bool(b) => out.extend_from_slice(&[TAG_BOOL, u8::from(*b)]),
        Value::Str(s) => {
            let bytes = super::text::bytes_of(s);
            out.push(TAG_STRING);
            // A RAPID string has at most 80 characters, so its length fits a byte.
            out.push(bytes.len().min(255) as u8);
            out.extend_from_slice(&bytes[..bytes.len().min(255)]);
        }
        Value::Record(r) => {
            out.push(TAG_RECORD);
            out.extend_from_slice(&(r.fields.len() as u16).to_be_bytes());
            for field in &r.fields {
                encode_value(field, out)?;
            }
        }
        Value::Array(a) => {
            out.push(TAG_ARRAY);
            for dim in a.dims {
                out.extend_from_slice(&dim.to_be_bytes());
            }
            for elem in &a.elems {
                encode_value(elem, out)?;
            }
        }
        _ => return Err((Err::ArgValue, "WriteAnyBin writes value data only (not iodev, clock, ...)".into())),
    }
    Ok(())
}

fn take<'a>(body: &'a [u8], at: &mut usize, n: usize) -> Result<&'a [u8], Fault> {
    let bytes = body.get(*at..*at + n).ok_or_else(|| corrupt("the data read is shorter than the type of Data"))?;
    *at += n;
    Ok(bytes)
}

fn tag(body: &[u8], at: &mut usize, expected: u8) -> Result<(), Fault> {
    if take(body, at, 1)?[0] != expected {
        return Err(corrupt("the data read is not of the type of Data"));
    }
    Ok(())
}

fn decode_value(body: &[u8], at: &mut usize, like: &Value) -> Result<Value, Fault> {
    match like {
        Value::Num(_) => {
            tag(body, at, TAG_NUM)?;
            let raw: [u8; 4] = take(body, at, 4)?.try_into().map_err(|_| corrupt("short num"))?;
            Ok(Value::Num(f32::from_be_bytes(raw)))
        }
        Value::Dnum(_) => {
            tag(body, at, TAG_DNUM)?;
            let raw: [u8; 8] = take(body, at, 8)?.try_into().map_err(|_| corrupt("short dnum"))?;
            Ok(Value::Dnum(f64::from_be_bytes(raw)))
        }
        Value::Bool(_) => {
            tag(body, at, TAG_BOOL)?;
            Ok(Value::Bool(take(body, at, 1)?[0] != 0))
        }
        Value::Str(_) => {
            tag(body, at, TAG_STRING)?;
            let len = usize::from(take(body, at, 1)?[0]);
            Ok(Value::Str(super::text::latin1(take(body, at, len)?).into()))
        }
        Value::Record(r) => {
            tag(body, at, TAG_RECORD)?;
            let count = u16::from_be_bytes([take(body, at, 1)?[0], take(body, at, 1)?[0]]);
            if usize::from(count) != r.fields.len() {
                return Err(corrupt("the record read has another number of components than Data"));
            }
            let fields = r.fields.iter().map(|f| decode_value(body, at, f)).collect::<Result<Vec<_>, _>>()?;
            Ok(Value::Record(std::rc::Rc::new(Record { ty: r.ty, fields })))
        }
        Value::Array(a) => {
            tag(body, at, TAG_ARRAY)?;
            let mut dims = [0u32; 3];
            for dim in &mut dims {
                let raw: [u8; 4] = take(body, at, 4)?.try_into().map_err(|_| corrupt("short array"))?;
                *dim = u32::from_be_bytes(raw);
            }
            if dims != a.dims {
                return Err(corrupt("the array read has other dimensions than Data"));
            }
            let elems = a.elems.iter().map(|e| decode_value(body, at, e)).collect::<Result<Vec<_>, _>>()?;
            Ok(Value::Array(Box::new(Array { dims, elems })))
        }
        _ => Err((Err::ArgValue, "ReadAnyBin reads value data only".into())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_sema::types::ANY;

    fn round_trip(value: &Value) -> Value {
        let frame = encode(value).unwrap();
        let len = body_len(&frame[..HEADER_LEN]).unwrap();
        assert_eq!(frame.len(), HEADER_LEN + len + 1);
        decode(&frame[HEADER_LEN..HEADER_LEN + len], frame[HEADER_LEN + len], value).unwrap()
    }

    fn record(fields: Vec<Value>) -> Value {
        Value::Record(std::rc::Rc::new(Record { ty: ANY, fields }))
    }

    #[test]
    fn values_read_back_identically() {
        let values = [
            Value::Num(-2.5),
            Value::Dnum(4294967296.125),
            Value::Bool(true),
            Value::Str("Latin-1 \u{e9}".into()),
            record(vec![Value::Num(1.0), Value::Str("x".into()), record(vec![Value::Bool(false)])]),
            Value::Array(Box::new(Array { dims: [2, 0, 0], elems: vec![Value::Num(1.0), Value::Num(2.0)] })),
        ];
        for value in &values {
            assert_eq!(&round_trip(value), value);
        }
    }

    #[test]
    fn corruption_and_mismatch() {
        let frame = encode(&Value::Num(1.0)).unwrap();
        let body = &frame[HEADER_LEN..frame.len() - 1];
        let sum = frame[frame.len() - 1];
        assert_eq!(decode(body, sum.wrapping_add(1), &Value::Num(0.0)).unwrap_err().0, Err::AnyBinCheck);
        assert_eq!(decode(body, sum, &Value::Str("".into())).unwrap_err().0, Err::AnyBinCheck);
        assert_eq!(body_len(b"abcde").unwrap_err().0, Err::AnyBinCheck);
    }
}
