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

        /// Every reserved word with its spelling.
        const KEYWORDS: &[(&str, TokenKind)] = &[ $( ($text, TokenKind::$variant), )* ];

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
///
/// The lexer asks this for every name, so it is one hash and one comparison: the
/// word is packed into an integer with its case folded, a multiplicative hash
/// picks the one reserved word it could be, and the packed spellings are compared.
pub fn keyword(word: &str) -> Option<TokenKind> {
    if word.len() > LONGEST_KEYWORD || word.len() < 2 {
        return None;
    }
    // Reserved words are letters only: names with digits or `_` (`p10`, `tool0`,
    // `Target_10`) are never one, and need no comparison.
    if !word.bytes().all(|b| b.is_ascii_alphabetic()) {
        return None;
    }
    let packed = pack_upper(word.as_bytes());
    let entry = KEYWORD_TABLE.slots[keyword_slot(packed, KEYWORD_TABLE.multiplier)];
    let idx = entry.checked_sub(1)? as usize;
    (KEYWORD_TABLE.packed[idx] == packed).then_some(KEYWORDS[idx].1)
}

const LONGEST_KEYWORD: usize = 9;
/// log2 of the hash table's size: 512 slots for 58 words leaves few collisions for
/// the search in [`build_keyword_table`] to step over.
const KEYWORD_SLOT_BITS: u32 = 9;

/// The ASCII letters of `word` (at most 16) in one integer, folded to upper case
/// (clearing bit 5 upper-cases a letter; callers pass letters only).
const fn pack_upper(word: &[u8]) -> u128 {
    let mut packed = 0u128;
    let mut idx = 0;
    while idx < word.len() {
        packed |= ((word[idx] & !0x20) as u128) << (8 * idx);
        idx += 1;
    }
    packed
}

const fn keyword_slot(packed: u128, multiplier: u64) -> usize {
    let mixed = (packed as u64) ^ ((packed >> 64) as u64).rotate_left(32);
    (mixed.wrapping_mul(multiplier) >> (64 - KEYWORD_SLOT_BITS)) as usize
}

/// A collision-free hash table of the reserved words: 1 + the index into
/// [`KEYWORDS`] in each used slot, 0 in the others.
struct KeywordTable {
    multiplier: u64,
    /// The packed spelling of each of [`KEYWORDS`].
    packed: [u128; KEYWORDS.len()],
    slots: [u8; 1 << KEYWORD_SLOT_BITS],
}

/// Built at compile time: tries odd multipliers until no two reserved words share a
/// slot (a word list without one fails the build, never a run).
static KEYWORD_TABLE: KeywordTable = build_keyword_table();

const fn build_keyword_table() -> KeywordTable {
    let mut multiplier: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut attempt = 0;
    while attempt < 10_000 {
        let mut slots = [0u8; 1 << KEYWORD_SLOT_BITS];
        let mut packed = [0u128; KEYWORDS.len()];
        let mut idx = 0;
        let mut collided = false;
        while idx < KEYWORDS.len() && !collided {
            packed[idx] = pack_upper(KEYWORDS[idx].0.as_bytes());
            let slot = keyword_slot(packed[idx], multiplier);
            collided = slots[slot] != 0;
            slots[slot] = idx as u8 + 1;
            idx += 1;
        }
        if !collided {
            return KeywordTable { multiplier, packed, slots };
        }
        // The next candidate: a step of a 64-bit LCG, made odd.
        multiplier = multiplier.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407) | 1;
        attempt += 1;
    }
    panic!("no collision-free multiplier for the reserved words");
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
        // Every reserved word is found in any case, and a near miss is not.
        for &(spelling, kind) in KEYWORDS {
            assert_eq!(keyword(spelling), Some(kind));
            assert_eq!(keyword(&spelling.to_ascii_lowercase()), Some(kind));
            assert_eq!(keyword(&spelling[..spelling.len() - 1]), None, "{spelling}");
            assert_eq!(keyword(&format!("{spelling}X")), None, "{spelling}");
        }
        assert_eq!(keyword("ENDMODULEX"), None);
        assert_eq!(keyword("Ärger"), None);
        assert!(TokenKind::With.is_keyword());
        assert!(!TokenKind::Ne.is_keyword());
    }

    #[test]
    fn every_kind_fits_the_token_set() {
        assert!((TokenKind::Xor as u8) < 128);
    }
}
