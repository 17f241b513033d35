//! The safety net: each stretch of output, lexed again as soon as it is written, must
//! hold exactly the input's tokens that were laid out into it (reserved words and names
//! equal ignoring ASCII case, everything else equal) with the same comments between
//! them. A formatter bug then costs a refusal, never a changed program. Lexing each
//! stretch right after writing it keeps the check cheap (the text is still in cache,
//! and the input's tokens are at hand).

use std::sync::mpsc;

use rapid_syntax::lexer::Lexer;
use rapid_syntax::token::TokenKind as T;
use rapid_syntax::Span;

use crate::Refusal;

/// A token (`kind`) or a comment (`None`) of the input.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Piece {
    pub(crate) kind: Option<T>,
    pub(crate) span: Span,
    /// Line ends between the previous piece and this one.
    pub(crate) newlines: u32,
}

/// Checks that `output[from..]` lexes to `pieces` of `input`, in order.
pub(crate) fn stretch(input: &str, pieces: &[Piece], output: &str, from: usize) -> Result<(), Refusal> {
    let mut lexer = Lexer::at(output, from);
    let mut expected = pieces.iter();
    loop {
        let token = lexer.next_token();
        for comment in lexer.comments.drain(..) {
            let Some(piece) = expected.next() else { return Err(unsafe_at(input.len(), "a comment would be added")) };
            if piece.kind.is_some() || piece.span.text(input) != comment.text(output) {
                return Err(unsafe_at(piece.span.start as usize, "a comment would change or move"));
            }
        }
        if token.kind == T::Eof {
            return match expected.next() {
                None => Ok(()),
                Some(piece) => Err(unsafe_at(piece.span.start as usize, "this token or comment would be lost")),
            };
        }
        let new_text = token.span.text(output);
        let Some(piece) = expected.next() else {
            return Err(unsafe_at(input.len(), &format!("`{new_text}` would be added")));
        };
        let old_text = piece.span.text(input);
        let same = match piece.kind {
            Some(kind) if kind != token.kind => false,
            Some(kind) if kind == T::Ident || kind.is_keyword() => old_text.eq_ignore_ascii_case(new_text),
            Some(_) => old_text == new_text,
            None => false,
        };
        if !same {
            return Err(unsafe_at(piece.span.start as usize, &format!("`{old_text}` would become `{new_text}`")));
        }
    }
}

/// Verifies the chunks a layout on another thread sends: each chunk of output must lex
/// as the stretch of input it was laid out from. Keeps receiving after a failure, so
/// the sender never blocks, and answers the first failure.
pub(crate) fn chunks(input: &str, received: mpsc::Receiver<crate::layout::Chunk>) -> Result<(), Refusal> {
    let mut result = Ok(());
    for (from, to, output) in received {
        if result.is_ok() {
            result = same(input, from, to, &output);
        }
    }
    result
}

/// Checks that `output` lexes as `input[from..to]`.
fn same(input: &str, from: usize, to: usize, output: &str) -> Result<(), Refusal> {
    let Some(stretch_text) = input.get(..to) else { return Err(unsafe_at(from, "a chunk is out of range")) };
    let mut before = Lexer::at(stretch_text, from);
    let mut after = Lexer::new(output);
    loop {
        let old = before.next_token();
        let new = after.next_token();
        let old_comments = before.comments.drain(..).map(|c| c.text(input));
        let new_comments: Vec<&str> = after.comments.drain(..).map(|c| c.text(output)).collect();
        if !old_comments.eq(new_comments.iter().copied()) {
            return Err(unsafe_at(old.span.start as usize, "a comment would change or move"));
        }
        let (old_text, new_text) = (old.span.text(input), new.span.text(output));
        let same_text = match old.kind {
            kind if kind == T::Ident || kind.is_keyword() => old_text.eq_ignore_ascii_case(new_text),
            _ => old_text == new_text,
        };
        if old.kind != new.kind || !same_text {
            return Err(unsafe_at(old.span.start as usize, &format!("`{old_text}` would become `{new_text}`")));
        }
        if old.kind == T::Eof {
            return Ok(());
        }
    }
}

fn unsafe_at(offset: usize, what: &str) -> Refusal {
    Refusal::Unsafe {
        offset: offset as u32,
        message: format!("formatting would change the program ({what}); left unformatted"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pieces(text: &str) -> Vec<Piece> {
        let mut lexer = Lexer::new(text);
        let mut out = Vec::new();
        loop {
            let token = lexer.next_token();
            out.extend(lexer.comments.drain(..).map(|span| Piece { kind: None, span, newlines: 0 }));
            if token.kind == T::Eof {
                return out;
            }
            out.push(Piece { kind: Some(token.kind), span: token.span, newlines: 0 });
        }
    }

    #[test]
    fn case_and_whitespace_may_change() {
        let input = "if A<>b then ! c\n";
        assert_eq!(stretch(input, &pieces(input), "IF a <> B THEN ! c", 0), Ok(()));
    }

    #[test]
    fn merged_lost_or_changed_tokens_are_caught() {
        let input = "a < > b; ! c\n";
        let expected = pieces(input);
        // `< >` glued is one `<>` token: refused.
        assert!(stretch(input, &expected, "a <> b; ! c", 0).is_err());
        assert!(stretch(input, &expected, "a < > b;", 0).is_err());
        assert!(stretch(input, &expected, "a < > b; ! C", 0).is_err());
        let strings = "x := \"a\";";
        assert!(stretch(strings, &pieces(strings), "x := \"A\";", 0).is_err());
    }

    #[test]
    fn chunks_compare_a_stretch_of_input() {
        let input = "x := 1;\nif A<>b then ! c\ny := 2;\n";
        let (from, to) = (input.find("if").unwrap() - 1, input.find("y :=").unwrap() - 1);
        assert_eq!(same(input, from, to, "\n    IF a <> B THEN ! c"), Ok(()));
        assert!(same(input, from, to, "\n    IF a<>B THEN").is_err());
        assert!(same(input, from, to, "\n    IF a < > B THEN ! c").is_err());
        assert!(same(input, from, to, "\n    IF a <> B THEN ! c\n    y := 2;").is_err());
    }
}
