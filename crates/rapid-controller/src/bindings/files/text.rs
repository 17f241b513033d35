//! How ReadNum and ReadStr cut a character-based file into fields (pure logic over a
//! byte source, so it is tested without files).
//!
//! Manual (ReadNum, ReadStr): line feed is always a delimiter, `\Delim` adds more; a
//! field is at most 80 characters and a longer one continues at the next read; the
//! delimiter that ends a field is read but not returned. ReadNum skips heading
//! delimiters; ReadStr does so only with `\DiscardHeaders` (otherwise a delimiter at the
//! current position gives an empty string). At end of file ReadNum returns EOF_NUM and
//! ReadStr the string "EOF" (both are values, not errors).

use std::io;

use rapid_vm::ext::MAX_STRING_CHARS;

/// Where the bytes of a field come from (an open file, or a slice in tests).
pub(super) trait ByteSource {
    fn peek_byte(&mut self) -> io::Result<Option<u8>>;
    fn next_byte(&mut self) -> io::Result<Option<u8>>;
}

const LINE_FEED: u8 = b'\n';

/// The delimiters in force: line feed plus the characters of `\Delim`.
pub(super) fn delimiters(delim: Option<&str>) -> Delimiters {
    let mut set = Delimiters { bytes: [LINE_FEED; MAX_STRING_CHARS + 1], len: 1 };
    for byte in delim.unwrap_or("").chars().filter_map(|c| u8::try_from(u32::from(c)).ok()) {
        if set.len < set.bytes.len() {
            set.bytes[set.len] = byte;
            set.len += 1;
        }
    }
    set
}

/// The bytes that end a field: the line feed and a `\Delim` string's (a RAPID string,
/// so at most 80); kept on the stack, as the read built-ins run in tight loops.
pub(super) struct Delimiters {
    bytes: [u8; MAX_STRING_CHARS + 1],
    len: usize,
}

impl std::ops::Deref for Delimiters {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

/// The next field: `None` at end of file. With `skip_headers`, delimiters before the
/// field are read and dropped first.
pub(super) fn read_field(src: &mut dyn ByteSource, delims: &[u8], skip_headers: bool) -> io::Result<Option<Vec<u8>>> {
    if skip_headers {
        while let Some(b) = src.peek_byte()? {
            if !delims.contains(&b) {
                break;
            }
            src.next_byte()?;
        }
    }
    if src.peek_byte()?.is_none() {
        return Ok(None);
    }
    let mut field = Vec::with_capacity(MAX_STRING_CHARS);
    while field.len() < MAX_STRING_CHARS {
        match src.next_byte()? {
            None => break,
            Some(b) if delims.contains(&b) => return Ok(Some(field)),
            Some(b) => field.push(b),
        }
    }
    // A field of exactly 80 characters: its delimiter belongs to it, so the next read
    // does not return an empty string.
    // uncertain: the manual only says the remainder of a longer field comes next.
    if field.len() == MAX_STRING_CHARS && src.peek_byte()?.is_some_and(|b| delims.contains(&b)) {
        src.next_byte()?;
    }
    Ok(Some(field))
}

/// Skips `lines` line feeds (ReadStr `\Line`: reading starts at that line, 1-based, of
/// the file). `false` when the file has fewer lines.
pub(super) fn skip_lines(src: &mut dyn ByteSource, lines: u64) -> io::Result<bool> {
    let mut left = lines;
    while left > 0 {
        match src.next_byte()? {
            None => return Ok(false),
            Some(LINE_FEED) => left -= 1,
            Some(_) => {}
        }
    }
    Ok(true)
}

/// Bytes as a RAPID string (Latin-1: each byte one character).
pub(super) fn latin1(bytes: &[u8]) -> String {
    bytes.iter().map(|&b| char::from(b)).collect()
}

/// The characters of a RAPID string as bytes (Latin-1; anything else becomes `?`).
pub(super) fn bytes_of(text: &str) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(text.len());
    push_latin1(&mut bytes, text);
    bytes
}

/// Appends `text` in Latin-1 (the controller's file encoding); a character beyond
/// Latin-1, which no RAPID string holds, becomes `?`.
pub(super) fn push_latin1(bytes: &mut Vec<u8>, text: &str) {
    if text.is_ascii() {
        bytes.extend_from_slice(text.as_bytes());
    } else {
        bytes.extend(text.chars().map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?')));
    }
}

/// The number ReadNum makes of a field: a decimal number as RAPID writes one (sign,
/// digits, point, exponent), blanks around it ignored. `None` is ERR_RCVDATA.
// uncertain: whether the controller accepts blanks around the number and hexadecimal
// or other forms; we accept the decimal literal forms of §1.1.2 only.
pub(super) fn parse_num(field: &[u8]) -> Option<f32> {
    let text = latin1(field);
    let text = text.trim_matches([' ', '\t', '\r']);
    let valid = !text.is_empty()
        && text.chars().all(|c| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E'))
        && text.chars().any(|c| c.is_ascii_digit());
    if !valid {
        return None;
    }
    text.parse::<f32>().ok().filter(|v| v.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Slice<'a>(&'a [u8], usize);

    impl ByteSource for Slice<'_> {
        fn peek_byte(&mut self) -> io::Result<Option<u8>> {
            Ok(self.0.get(self.1).copied())
        }
        fn next_byte(&mut self) -> io::Result<Option<u8>> {
            let b = self.0.get(self.1).copied();
            self.1 += usize::from(b.is_some());
            Ok(b)
        }
    }

    fn fields(text: &[u8], delim: Option<&str>, skip: bool) -> Vec<Option<String>> {
        let mut src = Slice(text, 0);
        let delims = delimiters(delim);
        let mut out = Vec::new();
        loop {
            let field = read_field(&mut src, &delims, skip).unwrap();
            let done = field.is_none();
            out.push(field.map(|f| latin1(&f)));
            if done {
                return out;
            }
        }
    }

    fn some(s: &str) -> Option<String> {
        Some(s.to_string())
    }

    #[test]
    fn lines_and_delimiters() {
        assert_eq!(fields(b"ab\ncd", None, false), [some("ab"), some("cd"), None]);
        assert_eq!(fields(b"ab\n\ncd\n", None, false), [some("ab"), some(""), some("cd"), None]);
        assert_eq!(fields(b"ab\n\ncd\n", None, true), [some("ab"), some("cd"), None]);
        assert_eq!(fields(b"1,2;3\n", Some(",;"), false), [some("1"), some("2"), some("3"), None]);
        assert_eq!(fields(b",,x", Some(","), true), [some("x"), None]);
        assert_eq!(fields(b"", None, false), [None]);
    }

    #[test]
    fn long_fields_continue() {
        let mut text = vec![b'a'; 85];
        text.push(b'\n');
        let out = fields(&text, None, false);
        assert_eq!(out, [some(&"a".repeat(80)), some("aaaaa"), None]);
        let mut exact = vec![b'b'; 80];
        exact.extend_from_slice(b"\nc");
        assert_eq!(fields(&exact, None, false), [some(&"b".repeat(80)), some("c"), None]);
    }

    #[test]
    fn numbers() {
        assert_eq!(parse_num(b"234.4"), Some(234.4));
        assert_eq!(parse_num(b" -12 \r"), Some(-12.0));
        assert_eq!(parse_num(b"1E3"), Some(1000.0));
        assert_eq!(parse_num(b"abc"), None);
        assert_eq!(parse_num(b""), None);
        assert_eq!(parse_num(b"1.2.3"), None);
        assert_eq!(parse_num(b"inf"), None);
    }

    #[test]
    fn line_skipping() {
        let mut src = Slice(b"a\nb\nc", 0);
        assert!(skip_lines(&mut src, 2).unwrap());
        assert_eq!(src.next_byte().unwrap(), Some(b'c'));
        let mut short = Slice(b"a\n", 0);
        assert!(!skip_lines(&mut short, 3).unwrap());
    }
}
