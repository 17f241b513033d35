//! Folding ranges: modules, routines, records, the compound statements (IF … ENDIF,
//! FOR/WHILE … ENDFOR/ENDWHILE, TEST … ENDTEST) and runs of comment lines.

use lsp_types::{FoldingRange, FoldingRangeKind};
use rapid_syntax::token::TokenKind;
use rapid_syntax::Span;

use crate::index::{FileIndex, Kind};
use crate::position::LineMap;

pub(crate) fn folding(index: &FileIndex, text: &str) -> Vec<FoldingRange> {
    let map = LineMap::new(text);
    let line = |offset: u32| map.position(text, offset).line;
    let mut out = Vec::new();
    let mut push = |span: Span, kind: Option<FoldingRangeKind>| {
        let (start, end) = (line(span.start), line(span.end));
        if end > start {
            out.push(FoldingRange { start_line: start, end_line: end, kind, ..FoldingRange::default() });
        }
    };
    for decl in &index.decls {
        if decl.kind == Kind::Module || decl.kind == Kind::Record || decl.kind.is_routine() {
            push(decl.span, None);
        }
    }
    for span in blocks(index) {
        push(span, None);
    }
    for span in comment_runs(index, text) {
        push(span, Some(FoldingRangeKind::Comment));
    }
    out.sort_by_key(|r| (r.start_line, std::cmp::Reverse(r.end_line)));
    out
}

/// Compound statements, from their opening keyword to their END keyword. A compact
/// IF (no THEN) opens nothing; ELSEIF's THEN continues its IF.
fn blocks(index: &FileIndex) -> Vec<Span> {
    let mut open: Vec<(TokenKind, u32)> = Vec::new();
    let mut out = Vec::new();
    let mut in_elseif = false;
    for token in &index.tokens {
        let start = token.span.start;
        match token.kind {
            TokenKind::If => open.push((TokenKind::If, start)),
            TokenKind::Elseif => in_elseif = true,
            TokenKind::Then if in_elseif => in_elseif = false,
            TokenKind::Then => {
                // The IF is a block: keep it open (it was pushed at IF).
                if let Some(last) = open.last_mut().filter(|(k, _)| *k == TokenKind::If) {
                    last.0 = TokenKind::Then;
                }
            }
            // A compact IF ends with its statement.
            TokenKind::Semi if open.last().is_some_and(|(k, _)| *k == TokenKind::If) => {
                open.pop();
            }
            TokenKind::For | TokenKind::While | TokenKind::Test => open.push((token.kind, start)),
            TokenKind::Endif | TokenKind::Endfor | TokenKind::Endwhile | TokenKind::Endtest => {
                let opener = match token.kind {
                    TokenKind::Endif => TokenKind::Then,
                    TokenKind::Endfor => TokenKind::For,
                    TokenKind::Endwhile => TokenKind::While,
                    _ => TokenKind::Test,
                };
                if let Some(at) = open.iter().rposition(|(k, _)| *k == opener) {
                    out.push(Span { start: open[at].1, end: token.span.end });
                    open.truncate(at);
                }
            }
            _ => {}
        }
    }
    out
}

/// Runs of two or more comment lines in a row.
fn comment_runs(index: &FileIndex, text: &str) -> Vec<Span> {
    let map = LineMap::new(text);
    let mut out: Vec<Span> = Vec::new();
    let mut run: Option<(Span, u32)> = None;
    for &comment in &index.comments {
        let line = map.position(text, comment.start).line;
        run = match run {
            Some((span, last)) if last + 1 == line => Some((span.cover(comment), line)),
            Some((span, _)) => {
                out.push(span);
                Some((comment, line))
            }
            None => Some((comment, line)),
        };
    }
    out.extend(run.map(|(span, _)| span));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folds_routines_blocks_and_comment_runs() {
        let text = "MODULE M\n  ! one\n  ! two\n  PROC p()\n    IF TRUE THEN\n      IF TRUE x := 1;\n    ELSEIF FALSE THEN\n    ENDIF\n    FOR i FROM 1 TO 2 DO\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
        let index = FileIndex::build(text);
        let ranges: Vec<(u32, u32)> = folding(&index, text).iter().map(|r| (r.start_line, r.end_line)).collect();
        assert_eq!(ranges, [(0, 11), (1, 2), (3, 10), (4, 7), (8, 9)]);
    }
}
