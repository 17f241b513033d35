//! Turning the bytes of a file into text. Controllers write Latin-1; editors write
//! UTF-8 (sometimes with a BOM). ABB-encrypted modules are recognised, not decoded.

/// How the bytes of a file were read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Encoding {
    Utf8,
    Latin1,
    Utf16,
}

/// Why a file's bytes are not RAPID text at all.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unreadable {
    /// The file starts with the marker byte of an ABB-encrypted module.
    Encrypted,
}

/// Decoded source text.
#[derive(Debug, Clone)]
pub struct SourceText {
    pub text: String,
    pub encoding: Encoding,
}

/// Decodes a file: UTF-8 (a BOM is dropped) when the bytes are valid UTF-8, UTF-16
/// when they start with its BOM, otherwise Latin-1, where every byte is one character.
/// Takes the buffer by value so valid UTF-8 is not copied.
pub fn decode(bytes: Vec<u8>) -> Result<SourceText, Unreadable> {
    match bytes.as_slice() {
        [0xFF, 0xFE, ..] => return Ok(decode_utf16(&bytes[2..], u16::from_le_bytes)),
        [0xFE, 0xFF, ..] => return Ok(decode_utf16(&bytes[2..], u16::from_be_bytes)),
        // ABB's encryption tool writes modules whose first byte is 0xFC or 0xFE.
        [0xFC | 0xFE, ..] => return Err(Unreadable::Encrypted),
        _ => {}
    }
    let has_bom = bytes.starts_with(&[0xEF, 0xBB, 0xBF]);
    match String::from_utf8(bytes) {
        Ok(mut text) => {
            if has_bom {
                text.drain(..3);
            }
            Ok(SourceText { text, encoding: Encoding::Utf8 })
        }
        Err(err) => {
            let bytes = err.into_bytes();
            let text = bytes.iter().map(|&b| b as char).collect();
            Ok(SourceText { text, encoding: Encoding::Latin1 })
        }
    }
}

fn decode_utf16(bytes: &[u8], unit: fn([u8; 2]) -> u16) -> SourceText {
    let units = bytes.chunks_exact(2).map(|pair| unit([pair[0], pair[1]]));
    let text = char::decode_utf16(units).map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER)).collect();
    SourceText { text, encoding: Encoding::Utf16 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_with_bom_is_stripped() {
        let src = decode(b"\xEF\xBB\xBFMODULE m".to_vec()).unwrap();
        assert_eq!(src.text, "MODULE m");
        assert_eq!(src.encoding, Encoding::Utf8);
    }

    #[test]
    fn invalid_utf8_falls_back_to_latin1() {
        let src = decode(b"! caf\xE9\nMODULE m".to_vec()).unwrap();
        assert_eq!(src.text, "! caf\u{e9}\nMODULE m");
        assert_eq!(src.encoding, Encoding::Latin1);
    }

    #[test]
    fn encrypted_marker_is_recognised() {
        assert_eq!(decode(vec![0xFC, 1, 2]).unwrap_err(), Unreadable::Encrypted);
        assert_eq!(decode(vec![0xFE, 1, 2]).unwrap_err(), Unreadable::Encrypted);
    }
}
