//! PackDNHeader (§1.10, Fieldbus Command Interface): packs the header of a DeviceNet
//! explicit message into a rawbytes, which is then sent to an FCI device with
//! WriteRawBytes. The message data follows from index `RawBytesLen(raw) + 1`.
//!
//! Layout (ABB's RAPID reference manual, PackDNHeader, "Format DeviceNet Header"):
//!
//! | byte | field        | content                                   |
//! |------|--------------|-------------------------------------------|
//! | 1    | format       | the controller's internal code for DeviceNet |
//! | 2    | service      | the Service argument's two hex digits     |
//! | 3    | size of path | the number of path bytes that follow      |
//! | 4..  | path         | the Path argument's characters, as written |
//!
//! The path is kept as the text the program gives, in the long form of an EDS file
//! (`"6,20 1D 24 01 30 64,8,1"`) or the short one (`"20 1D 24 01 30 64"`): the
//! manual accepts both and stores characters, not parsed numbers. RawData is cleared
//! first, so the header always starts at index 1.

use super::{native, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Opaque, OpaqueState, Value};

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family { file: file!(), builtins: &[native("PackDNHeader", pack_dn_header)] };

/// The format byte.
// uncertain: the manual calls it an "internal IRC5 code for DeviceNet" and does not
// give its value; only the controller's FCI driver reads it. Ours is 1.
const DEVICENET_FORMAT: u8 = 1;

/// The header for `service` (two hex digits) and `path`, or why it cannot be made.
fn header(service: &str, path: &str) -> Result<Vec<u8>, String> {
    let code = service_code(service).ok_or_else(|| format!("the service `{service}` is not two hex digits"))?;
    // Strings are Latin-1, so every character is one byte; at most 80 fit one byte of
    // size.
    let path_bytes: Vec<u8> = path.chars().map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?')).collect();
    let size = u8::try_from(path_bytes.len()).map_err(|_| "the path is too long".to_string())?;
    let mut bytes = vec![DEVICENET_FORMAT, code, size];
    bytes.extend_from_slice(&path_bytes);
    Ok(bytes)
}

/// `"0E"` → 0x0E: exactly two hex digits, either letter case (manual: "00" - "FF").
fn service_code(service: &str) -> Option<u8> {
    if service.len() != 2 || !service.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    u8::from_str_radix(service, 16).ok()
}

crate::builtins::signature::layout! {
    static PACK: PackArgs = "PackDNHeader" { path: "Path", raw_data: "RawData" }
}

/// `PackDNHeader Service Path RawData`: clears RawData and packs the header into it.
// uncertain: the manual names no error for a malformed Service; ERR_ARGVALERR is the
// controller's error for an argument value it cannot use.
fn pack_dn_header(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let service = ctx.string(&args[0])?;
    let path = ctx.string(&args[PACK.path])?;
    let bytes = header(&service, &path).map_err(|why| ctx.error(Err::ArgValue, why))?;
    let shell = match ctx.value(&args[PACK.raw_data])? {
        Value::Opaque(opaque) if matches!(opaque.state, OpaqueState::RawBytes(_) | OpaqueState::None) => *opaque,
        _ => return Err(ctx.error(Err::ArgValue, "PackDNHeader needs a rawbytes for RawData")),
    };
    let packed = Opaque { ty: shell.ty, state: OpaqueState::RawBytes(bytes) };
    ctx.store(&args[PACK.raw_data], Value::Opaque(Box::new(packed)))?;
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn manual_examples() {
        let long = header("0E", "6,20 1D 24 01 30 64,8,1").expect("valid");
        assert_eq!(&long[..3], &[DEVICENET_FORMAT, 0x0E, 23]);
        assert_eq!(&long[3..], b"6,20 1D 24 01 30 64,8,1");
        let short = header("10", "20 1D 24 01 30 64").expect("valid");
        assert_eq!(short.len(), 3 + 17);
        assert_eq!(short[1], 0x10);
    }

    #[test]
    fn service_is_two_hex_digits() {
        assert_eq!(service_code("ff"), Some(0xFF));
        assert_eq!(service_code("1F"), Some(0x1F));
        assert_eq!(service_code("F"), None);
        assert_eq!(service_code("0x1"), None);
        assert_eq!(service_code("G0"), None);
        assert!(header("1", "20").is_err());
    }
}
