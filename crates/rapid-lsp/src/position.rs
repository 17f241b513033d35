//! Byte offsets of the decoded text <-> LSP positions. The checker's spans are byte
//! offsets into the decoded (UTF-8) text, whatever the file's encoding on disk
//! (Latin-1 files are decoded first); LSP counts characters in UTF-16 code units, so
//! a Latin-1 letter such as `ä` is one unit and two bytes, and a character outside
//! the BMP is two units.

use lsp_types::{Position, Range};
use rapid_syntax::Span;

/// Where each line of one text starts, for converting positions both ways.
#[derive(Debug, Clone)]
pub(crate) struct LineMap {
    starts: Vec<u32>,
}

impl LineMap {
    pub(crate) fn new(text: &str) -> LineMap {
        let mut starts = vec![0];
        starts.extend(text.bytes().enumerate().filter(|&(_, b)| b == b'\n').map(|(i, _)| i as u32 + 1));
        LineMap { starts }
    }

    /// The LSP position of byte `offset` (clamped to the text, and to a character
    /// boundary).
    pub(crate) fn position(&self, text: &str, offset: u32) -> Position {
        let offset = (offset as usize).min(text.len());
        let line = match self.starts.binary_search(&(offset as u32)) {
            Ok(line) => line,
            Err(next) => next - 1,
        };
        let start = self.starts[line] as usize;
        let mut units = 0u32;
        for (idx, ch) in text[start..].char_indices() {
            if start + idx >= offset {
                break;
            }
            units += ch.len_utf16() as u32;
        }
        Position { line: line as u32, character: units }
    }

    /// The LSP range of a span.
    pub(crate) fn range(&self, text: &str, span: Span) -> Range {
        Range { start: self.position(text, span.start), end: self.position(text, span.end) }
    }

    /// The byte offset of an LSP position. A line past the end gives the text's end; a
    /// character past the line's end gives the line's end (before its line break), as
    /// the protocol asks.
    pub(crate) fn offset(&self, text: &str, pos: Position) -> usize {
        let Some(&start) = self.starts.get(pos.line as usize) else { return text.len() };
        let start = start as usize;
        let mut units = 0u32;
        for (idx, ch) in text[start..].char_indices() {
            if units >= pos.character || ch == '\n' || (ch == '\r' && text[start + idx..].starts_with("\r\n")) {
                return start + idx;
            }
            units += ch.len_utf16() as u32;
        }
        text.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pos(line: u32, character: u32) -> Position {
        Position { line, character }
    }

    #[test]
    fn latin1_letters_are_one_unit_and_two_bytes() {
        // "x ä y": `ä` is bytes 2..4, so `y` is byte 5 and UTF-16 unit 4.
        let text = "a\nx ä y\n";
        let map = LineMap::new(text);
        assert_eq!(map.position(text, 7), pos(1, 4));
        assert_eq!(map.offset(text, pos(1, 4)), 7);
        assert_eq!(map.position(text, 4), pos(1, 2));
    }

    #[test]
    fn astral_characters_are_two_units() {
        let text = "😀b";
        let map = LineMap::new(text);
        assert_eq!(map.position(text, 4), pos(0, 2));
        assert_eq!(map.offset(text, pos(0, 2)), 4);
    }

    #[test]
    fn past_the_line_end_is_clamped_before_crlf() {
        let text = "ab\r\ncd";
        let map = LineMap::new(text);
        assert_eq!(map.offset(text, pos(0, 10)), 2);
        assert_eq!(map.offset(text, pos(1, 1)), 5);
        assert_eq!(map.offset(text, pos(7, 0)), text.len());
        assert_eq!(map.position(text, 100), pos(1, 2));
    }
}
