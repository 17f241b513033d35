//! `file:` URIs <-> paths. Only the file scheme is served: an editor buffer with
//! another scheme (an unsaved buffer) is still served, keyed by its URI text.

use std::path::{Path, PathBuf};
use std::str::FromStr;

use lsp_types::Uri;

/// The `file:` URI of an absolute path, percent-encoding what a URI path may not hold.
pub(crate) fn from_path(path: &Path) -> Option<Uri> {
    let text = path.to_str()?;
    let mut out = String::from("file://");
    if !text.starts_with('/') {
        out.push('/');
    }
    for byte in text.bytes() {
        match byte {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => out.push(byte as char),
            b'\\' => out.push('/'),
            _ => out.push_str(&format!("%{byte:02X}")),
        }
    }
    Uri::from_str(&out).ok()
}

/// The path a `file:` URI names.
pub(crate) fn to_path(uri: &Uri) -> Option<PathBuf> {
    let rest = uri.as_str().strip_prefix("file://")?;
    // Skip an authority (`file://host/path`): only local paths are served.
    let path = &rest[rest.find('/')?..];
    let mut bytes = Vec::with_capacity(path.len());
    let raw = path.as_bytes();
    let mut idx = 0;
    while idx < raw.len() {
        if raw[idx] == b'%' && idx + 2 < raw.len() {
            if let Ok(byte) = u8::from_str_radix(&path[idx + 1..idx + 3], 16) {
                bytes.push(byte);
                idx += 3;
                continue;
            }
        }
        bytes.push(raw[idx]);
        idx += 1;
    }
    let text = String::from_utf8(bytes).ok()?;
    // `file:///C:/x` on Windows.
    let text = match text.as_bytes() {
        [b'/', drive, b':', ..] if drive.is_ascii_alphabetic() => text[1..].to_owned(),
        _ => text,
    };
    Some(PathBuf::from(text))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_spaces_and_latin1() {
        let path = Path::new("/tmp/my progs/Räder.mod");
        let uri = from_path(path).unwrap();
        assert_eq!(uri.as_str(), "file:///tmp/my%20progs/R%C3%A4der.mod");
        assert_eq!(to_path(&uri).unwrap(), path);
    }
}
