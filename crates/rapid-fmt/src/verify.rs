//! The safety net: the output, lexed again, must hold the input's tokens (reserved
//! words and names equal ignoring ASCII case, everything else equal) and the same
//! comments between the same tokens, in order. A formatter bug then costs a refusal,
//! never a changed program.

use rapid_syntax::lexer::Lexer;
use rapid_syntax::token::TokenKind as T;

use crate::Refusal;

pub(crate) fn same_tokens(input: &str, output: &str) -> Result<(), Refusal> {
    let mut before = Lexer::new(input);
    let mut after = Lexer::new(output);
    loop {
        let old = before.next_token();
        let new = after.next_token();
        let at = old.span.start;
        let old_comments = before.comments.drain(..).map(|c| c.text(input));
        let new_comments: Vec<&str> = after.comments.drain(..).map(|c| c.text(output)).collect();
        if !old_comments.eq(new_comments.iter().copied()) {
            return Err(unsafe_at(at, "the comments before this token would change"));
        }
        let (old_text, new_text) = (old.span.text(input), new.span.text(output));
        let same_text = match old.kind {
            T::Ident => old_text.eq_ignore_ascii_case(new_text),
            kind if kind.is_keyword() => old_text.eq_ignore_ascii_case(new_text),
            _ => old_text == new_text,
        };
        if old.kind != new.kind || !same_text {
            return Err(unsafe_at(at, &format!("`{old_text}` would become `{new_text}`")));
        }
        if old.kind == T::Eof {
            return Ok(());
        }
    }
}

fn unsafe_at(offset: u32, what: &str) -> Refusal {
    Refusal::Unsafe { offset, message: format!("formatting would change the program ({what}); left unformatted") }
}
