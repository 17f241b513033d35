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
    // Texts are compared as bytes: spans of the lexer fall on character boundaries, so
    // byte slices hold the same texts without the checks a `str` slice makes.
    let (old_bytes, new_bytes) = (input.as_bytes(), output.as_bytes());
    loop {
        let token = lexer.next_token();
        if !lexer.comments.is_empty() {
            for comment in lexer.comments.drain(..) {
                let Some(piece) = expected.next() else {
                    return Err(unsafe_at(input.len(), "a comment would be added"));
                };
                if piece.kind.is_some() || bytes_of(old_bytes, piece.span) != bytes_of(new_bytes, comment) {
                    return Err(unsafe_at(piece.span.start as usize, "a comment would change or move"));
                }
            }
        }
        if token.kind == T::Eof {
            return match expected.next() {
                None => Ok(()),
                Some(piece) => Err(unsafe_at(piece.span.start as usize, "this token or comment would be lost")),
            };
        }
        let new_text = bytes_of(new_bytes, token.span);
        let Some(piece) = expected.next() else {
            let new_text = token.span.text(output);
            return Err(unsafe_at(input.len(), &format!("`{new_text}` would be added")));
        };
        let old_text = bytes_of(old_bytes, piece.span);
        let same = match piece.kind {
            Some(kind) if kind != token.kind => false,
            Some(kind) if kind == T::Ident || kind.is_keyword() => old_text.eq_ignore_ascii_case(new_text),
            Some(_) => same_bytes(old_text, new_text),
            None => false,
        };
        if !same {
            let (old_text, new_text) = (piece.span.text(input), token.span.text(output));
            return Err(unsafe_at(piece.span.start as usize, &format!("`{old_text}` would become `{new_text}`")));
        }
    }
}

/// The bytes of a span (none when it lies outside `text`).
fn bytes_of(text: &[u8], span: Span) -> &[u8] {
    text.get(span.start as usize..span.end as usize).unwrap_or(&[])
}

/// Verifies the chunks a layout on another thread sends: each chunk of output must lex
/// as the pieces of input laid out into it ([`stretch`]). Keeps receiving after a
/// failure, so the sender never blocks, and answers the first failure. Each chunk's
/// buffers go back emptied through `used`, to be filled again.
pub(crate) fn chunks(
    input: &str,
    received: mpsc::Receiver<crate::layout::Chunk>,
    used: &mpsc::Sender<crate::layout::Chunk>,
) -> Result<(), Refusal> {
    let mut result = Ok(());
    for (mut pieces, mut output) in received {
        if result.is_ok() {
            result = stretch(input, &pieces, &output, 0);
        }
        pieces.clear();
        output.clear();
        // The layout may have finished: then the buffers are not needed.
        let _ = used.send((pieces, output));
    }
    result
}

/// `a == b`: most tokens are one byte of punctuation, compared without a call into
/// the C library.
fn same_bytes(a: &[u8], b: &[u8]) -> bool {
    match (a, b) {
        ([x], [y]) => x == y,
        _ => a == b,
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
        let all = pieces(input);
        // The pieces of the middle line: `if A <> b then` and the comment.
        let middle = all[4..10].to_vec();
        let check = |output: &str| {
            let (send, received) = mpsc::sync_channel(1);
            send.send((middle.clone(), output.to_owned())).unwrap();
            drop(send);
            let (used, _spare) = mpsc::channel();
            chunks(input, received, &used)
        };
        assert_eq!(check("\n    IF a <> B THEN ! c"), Ok(()));
        assert!(check("\n    IF a<>B THEN").is_err());
        assert!(check("\n    IF a < > B THEN ! c").is_err());
        assert!(check("\n    IF a <> B THEN ! c\n    y := 2;").is_err());
    }
}
