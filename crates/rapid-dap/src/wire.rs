//! The protocol's framing: each message is a `Content-Length: N` header, a blank
//! line and N bytes of JSON (the same base protocol as LSP's).

use std::io::{self, BufRead, Write};

use serde_json::Value;

/// The largest message accepted (a launch configuration or a breakpoint list is far
/// smaller): a bad length must not make the adapter allocate without bound.
const MAX_MESSAGE: usize = 16 * 1024 * 1024;

/// Reads the next message; None at the end of the input.
pub(crate) fn read_message(input: &mut dyn BufRead) -> io::Result<Option<Value>> {
    let mut length = None;
    let mut headers = 0;
    let mut line = String::new();
    loop {
        line.clear();
        if input.read_line(&mut line)? == 0 {
            return Ok(None);
        }
        let header = line.trim_end_matches(['\r', '\n']);
        if header.is_empty() {
            // Blank lines between messages are skipped; one after headers ends them.
            if headers > 0 {
                break;
            }
            continue;
        }
        headers += 1;
        if let Some((name, value)) = header.split_once(':') {
            if name.trim().eq_ignore_ascii_case("Content-Length") {
                length = value.trim().parse::<usize>().ok();
            }
        }
    }
    let length = length.filter(|&n| n <= MAX_MESSAGE).ok_or_else(|| bad("a message without a valid Content-Length"))?;
    let mut body = vec![0; length];
    input.read_exact(&mut body)?;
    serde_json::from_slice(&body).map(Some).map_err(|e| bad(&format!("a message that is no JSON: {e}")))
}

/// Writes one message, flushed.
pub(crate) fn write_message(output: &mut dyn Write, message: &Value) -> io::Result<()> {
    let body = message.to_string();
    write!(output, "Content-Length: {}\r\n\r\n{body}", body.len())?;
    output.flush()
}

fn bad(why: &str) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, why.to_owned())
}

#[cfg(test)]
mod tests {
    use super::{read_message, write_message};

    #[test]
    fn a_message_goes_out_and_comes_back() {
        let mut out = Vec::new();
        let message = serde_json::json!({"seq": 1, "type": "request", "command": "threads"});
        assert!(write_message(&mut out, &message).is_ok());
        assert!(out.starts_with(b"Content-Length: 46\r\n\r\n"), "{}", String::from_utf8_lossy(&out));
        let mut input = std::io::Cursor::new(out);
        assert_eq!(read_message(&mut input).ok().flatten(), Some(message));
        assert!(matches!(read_message(&mut input), Ok(None)));
    }

    #[test]
    fn a_missing_length_is_an_error() {
        let mut input = std::io::Cursor::new(b"X-Other: 3\r\n\r\n{}".to_vec());
        assert!(read_message(&mut input).is_err());
    }
}
