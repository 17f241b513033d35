//! Token kinds, the reserved words of §1.1.2, placeholders and token sets.

use crate::span::Span;

macro_rules! keywords {
    ($( $variant:ident = $text:literal, )*) => {
        /// The kind of a token.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        #[repr(u8)]
        pub enum TokenKind {
            Ident, Num, Str, Placeholder, Header, Eof,
            LParen, RParen, LBracket, RBracket, LBrace, RBrace,
            Comma, Semi, Colon, Assign, Dot, Backslash, Pipe, Question, Percent,
            Plus, Minus, Star, Slash, Lt, Le, Eq, Gt, Ge, Ne,
            $( $variant, )*
        }

        /// The reserved word spelled `upper` (already in upper case), if any.
        fn keyword_from_upper(upper: &[u8]) -> Option<TokenKind> {
            match upper {
                $( t if t == $text.as_bytes() => Some(TokenKind::$variant), )*
                _ => None,
            }
        }

        impl TokenKind {
            /// How the token is written, for messages.
            pub fn describe(self) -> &'static str {
                match self {
                    TokenKind::Ident => "a name",
                    TokenKind::Num => "a number",
                    TokenKind::Str => "a string",
                    TokenKind::Placeholder => "a placeholder",
                    TokenKind::Header => "a %%% header",
                    TokenKind::Eof => "the end of the file",
                    TokenKind::LParen => "`(`", TokenKind::RParen => "`)`",
                    TokenKind::LBracket => "`[`", TokenKind::RBracket => "`]`",
                    TokenKind::LBrace => "`{`", TokenKind::RBrace => "`}`",
                    TokenKind::Comma => "`,`", TokenKind::Semi => "`;`",
                    TokenKind::Colon => "`:`", TokenKind::Assign => "`:=`",
                    TokenKind::Dot => "`.`", TokenKind::Backslash => "`\\`",
                    TokenKind::Pipe => "`|`", TokenKind::Question => "`?`",
                    TokenKind::Percent => "`%`", TokenKind::Plus => "`+`",
                    TokenKind::Minus => "`-`", TokenKind::Star => "`*`",
                    TokenKind::Slash => "`/`", TokenKind::Lt => "`<`",
                    TokenKind::Le => "`<=`", TokenKind::Eq => "`=`",
                    TokenKind::Gt => "`>`", TokenKind::Ge => "`>=`",
                    TokenKind::Ne => "`<>`",
                    $( TokenKind::$variant => concat!("`", $text, "`"), )*
                }
            }

            /// Whether this is a reserved word.
            pub fn is_keyword(self) -> bool {
                self as u8 >= TokenKind::Alias as u8
            }
        }
    };
}

keywords! {
    Alias = "ALIAS", And = "AND", Backward = "BACKWARD", Case = "CASE",
    Connect = "CONNECT", Const = "CONST", Default = "DEFAULT", Div = "DIV",
    Do = "DO", Else = "ELSE", Elseif = "ELSEIF", Endfor = "ENDFOR",
    Endfunc = "ENDFUNC", Endif = "ENDIF", Endmodule = "ENDMODULE", Endproc = "ENDPROC",
    Endrecord = "ENDRECORD", Endtest = "ENDTEST", Endtrap = "ENDTRAP", Endwhile = "ENDWHILE",
    Error = "ERROR", Exit = "EXIT", False = "FALSE", For = "FOR",
    From = "FROM", Func = "FUNC", Goto = "GOTO", If = "IF",
    Inout = "INOUT", Local = "LOCAL", Mod = "MOD", Module = "MODULE",
    Nostepin = "NOSTEPIN", Not = "NOT", Noview = "NOVIEW", Or = "OR",
    Pers = "PERS", Proc = "PROC", Raise = "RAISE", Readonly = "READONLY",
    Record = "RECORD", Retry = "RETRY", Return = "RETURN", Step = "STEP",
    Sysmodule = "SYSMODULE", Task = "TASK", Test = "TEST", Then = "THEN",
    To = "TO", Trap = "TRAP", True = "TRUE", Trynext = "TRYNEXT",
    Undo = "UNDO", Var = "VAR", Viewonly = "VIEWONLY", While = "WHILE",
    With = "WITH", Xor = "XOR",
}

/// The reserved word `word` spells, ignoring case.
pub fn keyword(word: &str) -> Option<TokenKind> {
    const LONGEST: usize = 9;
    if word.len() > LONGEST || word.len() < 2 {
        return None;
    }
    // Reserved words are letters only: names with digits or `_` (`p10`, `tool0`,
    // `Target_10`) are never one, and need no comparison.
    if !word.bytes().all(|b| b.is_ascii_alphabetic()) {
        return None;
    }
    let mut upper = [0u8; LONGEST];
    for (slot, byte) in upper.iter_mut().zip(word.bytes()) {
        *slot = byte.to_ascii_uppercase();
    }
    keyword_from_upper(&upper[..word.len()])
}

/// The editor placeholders of §1.1.2 (`<SMT>` and friends).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Placeholder {
    Tdn,
    Ddn,
    Rdn,
    Par,
    Alt,
    Dim,
    Smt,
    Var,
    Eit,
    Cse,
    Exp,
    Arg,
    Id,
}

impl Placeholder {
    /// The placeholder spelled `<text>` (upper case only, as the editor writes them).
    pub fn from_text(text: &str) -> Option<Placeholder> {
        Some(match text {
            "<TDN>" => Placeholder::Tdn,
            "<DDN>" => Placeholder::Ddn,
            "<RDN>" => Placeholder::Rdn,
            "<PAR>" => Placeholder::Par,
            "<ALT>" => Placeholder::Alt,
            "<DIM>" => Placeholder::Dim,
            "<SMT>" => Placeholder::Smt,
            "<VAR>" => Placeholder::Var,
            "<EIT>" => Placeholder::Eit,
            "<CSE>" => Placeholder::Cse,
            "<EXP>" => Placeholder::Exp,
            "<ARG>" => Placeholder::Arg,
            "<ID>" => Placeholder::Id,
            _ => return None,
        })
    }
}

/// One token: its kind and where it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Token {
    pub kind: TokenKind,
    pub span: Span,
}

/// A set of token kinds, as a bitset (for lookahead and error recovery).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TokenSet(u128);

impl TokenSet {
    pub const EMPTY: TokenSet = TokenSet(0);

    pub const fn new(kinds: &[TokenKind]) -> TokenSet {
        let mut bits = 0u128;
        let mut idx = 0;
        while idx < kinds.len() {
            bits |= 1u128 << kinds[idx] as u8;
            idx += 1;
        }
        TokenSet(bits)
    }

    pub const fn union(self, other: TokenSet) -> TokenSet {
        TokenSet(self.0 | other.0)
    }

    pub const fn contains(self, kind: TokenKind) -> bool {
        self.0 & (1u128 << kind as u8) != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keywords_ignore_case() {
        assert_eq!(keyword("endproc"), Some(TokenKind::Endproc));
        assert_eq!(keyword("EndModule"), Some(TokenKind::Endmodule));
        assert_eq!(keyword("MoveL"), None);
        assert_eq!(keyword("switch"), None);
        assert!(TokenKind::With.is_keyword());
        assert!(!TokenKind::Ne.is_keyword());
    }

    #[test]
    fn every_kind_fits_the_token_set() {
        assert!((TokenKind::Xor as u8) < 128);
    }
}
