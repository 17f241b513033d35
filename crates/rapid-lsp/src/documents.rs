//! The documents the editor has open: their text as the editor holds it, kept in step
//! by incremental changes (`TextDocumentSyncKind::INCREMENTAL`).

use lsp_types::{TextDocumentContentChangeEvent, Uri};
use rustc_hash::FxHashMap;

use crate::position::LineMap;

/// One open document.
#[derive(Debug, Clone)]
pub(crate) struct Document {
    pub(crate) text: String,
    pub(crate) version: i32,
}

/// Every open document, by URI.
#[derive(Debug, Default)]
pub(crate) struct Documents {
    open: FxHashMap<Uri, Document>,
}

impl Documents {
    pub(crate) fn open(&mut self, uri: Uri, text: String, version: i32) {
        self.open.insert(uri, Document { text, version });
    }

    pub(crate) fn close(&mut self, uri: &Uri) {
        self.open.remove(uri);
    }

    pub(crate) fn iter(&self) -> impl Iterator<Item = (&Uri, &Document)> {
        self.open.iter()
    }

    /// Applies the changes of one `didChange`, in order. A change without a range
    /// replaces the whole text.
    pub(crate) fn change(&mut self, uri: &Uri, version: i32, changes: Vec<TextDocumentContentChangeEvent>) {
        let Some(doc) = self.open.get_mut(uri) else { return };
        for change in changes {
            apply(&mut doc.text, change);
        }
        doc.version = version;
    }
}

/// Applies one change to `text`.
pub(crate) fn apply(text: &mut String, change: TextDocumentContentChangeEvent) {
    let Some(range) = change.range else {
        *text = change.text;
        return;
    };
    let map = LineMap::new(text);
    let start = map.offset(text, range.start);
    let end = map.offset(text, range.end).max(start);
    text.replace_range(start..end, &change.text);
}

#[cfg(test)]
mod tests {
    use lsp_types::{Position, Range};

    use super::*;

    #[test]
    fn a_ranged_change_replaces_utf16_columns() {
        // Replace `ä` (UTF-16 column 2..3 of line 1) with `ae`.
        let mut text = String::from("x\nä ä\n");
        let range = Range { start: Position { line: 1, character: 2 }, end: Position { line: 1, character: 3 } };
        apply(&mut text, TextDocumentContentChangeEvent { range: Some(range), range_length: None, text: "ae".into() });
        assert_eq!(text, "x\nä ae\n");
    }
}
