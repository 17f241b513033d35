//! The hand-written lexer: text in, tokens out, comments and lexical errors on the
//! side. It never fails: bad input becomes an error plus the best token it can make.

use crate::error::{SyntaxError, SyntaxErrorKind};
use crate::span::Span;
use crate::token::{keyword, Placeholder, Token, TokenKind};

/// Identifiers may have at most this many characters (§1.1.2).
pub const MAX_IDENT_CHARS: usize = rapid_limits::IDENT_CHARS;
/// String values may have at most this many characters (§1.1.2).
pub const MAX_STRING_CHARS: usize = rapid_limits::STRING_CHARS;

/// Streams tokens out of a text.
pub struct Lexer<'t> {
    text: &'t str,
    bytes: &'t [u8],
    pos: usize,
    /// Comments seen so far (`!` to the end of the line).
    pub comments: Vec<Span>,
    /// Lexical errors seen so far.
    pub errors: Vec<SyntaxError>,
    /// Where unterminated strings end: the `;` they swallowed is not reported again.
    pub unterminated_string_ends: Vec<u32>,
}

/// Whether `c` is a letter of the manual's `<letter>` table (ASCII and Latin-1).
pub fn is_letter(c: char) -> bool {
    c.is_ascii_alphabetic() || matches!(c, '\u{C0}'..='\u{D6}' | '\u{D8}'..='\u{F6}' | '\u{F8}'..='\u{FF}')
}

fn is_ident_continue(c: char) -> bool {
    is_letter(c) || c.is_ascii_digit() || c == '_'
}

/// The tokens that are always one byte, whatever follows (`.`, `%`, `:`, `<` and `>`
/// may start something longer and are left to [`Lexer::other_token`]).
static SINGLE_BYTE_TOKENS: [Option<TokenKind>; 256] = {
    let mut table = [None; 256];
    table[b'(' as usize] = Some(TokenKind::LParen);
    table[b')' as usize] = Some(TokenKind::RParen);
    table[b'[' as usize] = Some(TokenKind::LBracket);
    table[b']' as usize] = Some(TokenKind::RBracket);
    table[b'{' as usize] = Some(TokenKind::LBrace);
    table[b'}' as usize] = Some(TokenKind::RBrace);
    table[b',' as usize] = Some(TokenKind::Comma);
    table[b';' as usize] = Some(TokenKind::Semi);
    table[b'\\' as usize] = Some(TokenKind::Backslash);
    table[b'|' as usize] = Some(TokenKind::Pipe);
    table[b'?' as usize] = Some(TokenKind::Question);
    table[b'+' as usize] = Some(TokenKind::Plus);
    table[b'-' as usize] = Some(TokenKind::Minus);
    table[b'*' as usize] = Some(TokenKind::Star);
    table[b'/' as usize] = Some(TokenKind::Slash);
    table[b'=' as usize] = Some(TokenKind::Eq);
    table
};

/// How many bytes at the start of `bytes` are ASCII letters, digits or `_`.
fn ascii_word_len(bytes: &[u8]) -> usize {
    bytes.iter().position(|&b| !(b.is_ascii_alphanumeric() || b == b'_')).unwrap_or(bytes.len())
}

/// The length of the well-formed decimal number at the start of `bytes` (digits,
/// `.` and digits, an exponent of one or two digits) when nothing glued follows it
/// and it has at most 200 integer digits, so it is finite without converting it;
/// `None` for anything else. Matches [`Lexer::number_checked`] on those numbers.
fn plain_decimal_len(bytes: &[u8]) -> Option<usize> {
    let int_digits = decimal_run(bytes);
    let mut len = int_digits;
    if bytes.get(len) == Some(&b'.') {
        len += 1;
        len += decimal_run(&bytes[len..]);
    }
    if int_digits > 200 || len == 0 || (len == 1 && int_digits == 0) {
        return None;
    }
    if matches!(bytes.get(len), Some(b'e' | b'E')) {
        let mut exp_end = len + 1;
        if matches!(bytes.get(exp_end), Some(b'+' | b'-')) {
            exp_end += 1;
        }
        let exp_digits = decimal_run(&bytes[exp_end..]);
        if !(1..=2).contains(&exp_digits) {
            return None;
        }
        len = exp_end + exp_digits;
    }
    match bytes.get(len) {
        Some(&b) if b.is_ascii_alphanumeric() || b == b'_' || b >= 0x80 => None,
        _ => Some(len),
    }
}

/// How many bytes at the start of `bytes` are decimal digits.
fn decimal_run(bytes: &[u8]) -> usize {
    bytes.iter().position(|b| !b.is_ascii_digit()).unwrap_or(bytes.len())
}

impl<'t> Lexer<'t> {
    pub fn new(text: &'t str) -> Lexer<'t> {
        Lexer {
            text,
            bytes: text.as_bytes(),
            pos: 0,
            comments: Vec::new(),
            errors: Vec::new(),
            unterminated_string_ends: Vec::new(),
        }
    }

    /// Starts lexing at byte `pos` (used to re-lex one routine body).
    pub fn at(text: &'t str, pos: usize) -> Lexer<'t> {
        Lexer { pos, ..Lexer::new(text) }
    }

    /// The next token; `Eof` forever at the end.
    pub fn next_token(&mut self) -> Token {
        loop {
            self.skip_whitespace();
            let start = self.pos;
            let Some(&byte) = self.bytes.get(start) else {
                return self.token(TokenKind::Eof, start);
            };
            // Letters, digits and one-byte punctuation are nearly every token: they are
            // told apart with two range tests and a table load, not a jump over every
            // byte value, whose indirect branch the CPU mispredicts at most tokens.
            let kind = if byte.is_ascii_alphabetic() {
                self.ident()
            } else if byte.is_ascii_digit() {
                self.number()
            } else if let Some(kind) = SINGLE_BYTE_TOKENS[byte as usize] {
                self.single(kind)
            } else {
                match self.other_token(byte, start) {
                    Some(kind) => kind,
                    None => continue,
                }
            };
            return self.token(kind, start);
        }
    }

    /// The tokens [`SINGLE_BYTE_TOKENS`] leaves out: comments (`None`, recorded),
    /// strings, headers, numbers starting with `.`, two-byte operators, placeholders,
    /// non-ASCII letters and invalid characters (`None`, reported).
    #[inline(never)]
    fn other_token(&mut self, byte: u8, start: usize) -> Option<TokenKind> {
        Some(match byte {
            b'!' => {
                self.skip_line();
                self.comments.push(Span::new(start, self.pos));
                return None;
            }
            b'.' if self.peek_byte(1).is_some_and(|b| b.is_ascii_digit()) => self.number(),
            b'.' => self.single(TokenKind::Dot),
            b'"' => self.string(),
            b'%' if self.text[start..].starts_with("%%%") => self.header(),
            b'%' => self.single(TokenKind::Percent),
            b'<' => self.less_or_placeholder(),
            b'>' => self.one_or_two(TokenKind::Gt, b'=', TokenKind::Ge),
            b':' => self.one_or_two(TokenKind::Colon, b'=', TokenKind::Assign),
            _ => {
                let c = self.current_char();
                if !is_letter(c) {
                    self.invalid_character(c);
                    return None;
                }
                self.ident()
            }
        })
    }

    /// Moves to the next token of a kind in `stop` without building the tokens in
    /// between (the outline's scan over routine bodies), and returns it. Token
    /// boundaries are exactly those of [`Lexer::next_token`]: strings, comments,
    /// headers and numbers with glued letters are stepped over whole, so a keyword
    /// inside them is never seen. Lexical errors found on the way are kept.
    pub fn skip_to(&mut self, stop: crate::token::TokenSet) -> Token {
        loop {
            self.skip_whitespace();
            let start = self.pos;
            let Some(&byte) = self.bytes.get(start) else {
                return self.token(TokenKind::Eof, start);
            };
            match byte {
                b'a'..=b'z' | b'A'..=b'Z' => {
                    if let Some(kind) = self.word_in(stop) {
                        return self.token(kind, start);
                    }
                }
                b'!' => self.skip_line(),
                b'"' => {
                    self.string();
                }
                b'0'..=b'9' => self.skip_number(),
                b'.' if self.peek_byte(1).is_some_and(|b| b.is_ascii_digit()) => self.skip_number(),
                b'%' if self.text[start..].starts_with("%%%") => {
                    self.header();
                }
                0x80.. => {
                    let c = self.current_char();
                    if is_letter(c) {
                        if let Some(kind) = self.word_in(stop) {
                            return self.token(kind, start);
                        }
                    } else {
                        self.pos += c.len_utf8();
                    }
                }
                _ => self.pos += 1,
            }
        }
    }

    /// Steps over a number exactly as [`Lexer::number`] consumes it, without checks.
    fn skip_number(&mut self) {
        if let Some(len) = plain_decimal_len(&self.bytes[self.pos..]) {
            self.pos += len;
            return;
        }
        let radix = self.number_radix();
        if radix != 10 {
            self.pos += 2;
            self.eat_digits(radix);
        } else {
            self.eat_decimal_digits();
            if self.peek_byte(0) == Some(b'.') {
                self.pos += 1;
                self.eat_decimal_digits();
            }
            self.eat_exponent();
        }
        self.eat_glued();
    }

    /// Lexes an identifier or keyword; returns its kind when it is in `stop`.
    fn word_in(&mut self, stop: crate::token::TokenSet) -> Option<TokenKind> {
        let start = self.pos;
        let kind = self.ident();
        if stop.contains(kind) {
            return Some(kind);
        }
        // Identifier errors (too long) are reported again when the body is parsed.
        if kind == TokenKind::Ident && self.errors.last().is_some_and(|e| e.span.start as usize == start) {
            self.errors.pop();
        }
        None
    }

    fn token(&self, kind: TokenKind, start: usize) -> Token {
        Token { kind, span: Span::new(start, self.pos) }
    }

    fn error(&mut self, kind: SyntaxErrorKind, span: Span, message: String) {
        self.errors.push(SyntaxError { kind, span, message });
    }

    fn peek_byte(&self, ahead: usize) -> Option<u8> {
        self.bytes.get(self.pos + ahead).copied()
    }

    fn current_char(&self) -> char {
        self.text[self.pos..].chars().next().unwrap_or('\0')
    }

    fn skip_whitespace(&mut self) {
        while let Some(&b) = self.bytes.get(self.pos) {
            match b {
                b' ' | b'\t' | b'\n' | b'\r' | 0x0C => self.pos += 1,
                // Latin-1 no-break space (U+00A0) shows up in pasted code; treat as blank.
                0xC2 if self.peek_byte(1) == Some(0xA0) => self.pos += 2,
                _ => break,
            }
        }
    }

    fn skip_line(&mut self) {
        match memchr_newline(&self.bytes[self.pos..]) {
            Some(offset) => self.pos += offset,
            None => self.pos = self.bytes.len(),
        }
        if self.pos > 0 && self.bytes[self.pos - 1] == b'\r' {
            self.pos -= 1;
        }
    }

    fn single(&mut self, kind: TokenKind) -> TokenKind {
        self.pos += 1;
        kind
    }

    fn one_or_two(&mut self, one: TokenKind, second: u8, two: TokenKind) -> TokenKind {
        self.pos += 1;
        if self.peek_byte(0) == Some(second) {
            self.pos += 1;
            return two;
        }
        one
    }

    fn less_or_placeholder(&mut self) -> TokenKind {
        let rest = &self.text[self.pos..];
        if let Some(close) = rest.as_bytes().iter().take(6).position(|&b| b == b'>') {
            if Placeholder::from_text(&rest[..=close]).is_some() {
                self.pos += close + 1;
                return TokenKind::Placeholder;
            }
        }
        self.pos += 1;
        match self.peek_byte(0) {
            Some(b'=') => self.single(TokenKind::Le),
            Some(b'>') => self.single(TokenKind::Ne),
            _ => TokenKind::Lt,
        }
    }

    fn invalid_character(&mut self, c: char) {
        let start = self.pos;
        self.pos += c.len_utf8().max(1);
        let shown = if c.is_control() { format!("U+{:04X}", c as u32) } else { format!("`{c}`") };
        self.error(
            SyntaxErrorKind::InvalidCharacter,
            Span::new(start, self.pos),
            format!("invalid character {shown}: it cannot start any RAPID token"),
        );
    }

    fn ident(&mut self) -> TokenKind {
        let start = self.pos;
        // ASCII fast path: one scan over the slice; a Latin-1 letter (two bytes in
        // UTF-8) sends the rest of the word to the character loop below.
        let ascii = ascii_word_len(&self.bytes[start..]);
        self.pos += ascii;
        let mut n_chars = ascii;
        while let Some(&b) = self.bytes.get(self.pos) {
            if b.is_ascii_alphanumeric() || b == b'_' {
                self.pos += 1;
                n_chars += 1;
            } else if b < 0x80 {
                break;
            } else {
                let c = self.current_char();
                if !is_ident_continue(c) {
                    break;
                }
                self.pos += c.len_utf8();
                n_chars += 1;
            }
        }
        let word = &self.text[start..self.pos];
        if let Some(kw) = keyword(word) {
            return kw;
        }
        if n_chars > MAX_IDENT_CHARS {
            self.error(
                SyntaxErrorKind::IdentifierTooLong,
                Span::new(start, self.pos),
                format!("identifier has {n_chars} characters; RAPID allows at most {MAX_IDENT_CHARS}"),
            );
        }
        TokenKind::Ident
    }

    fn eat_digits(&mut self, radix: u32) -> usize {
        let start = self.pos;
        while self.peek_byte(0).is_some_and(|b| (b as char).is_digit(radix)) {
            self.pos += 1;
        }
        self.pos - start
    }

    fn eat_decimal_digits(&mut self) -> usize {
        let n_digits = decimal_run(&self.bytes[self.pos..]);
        self.pos += n_digits;
        n_digits
    }

    /// `e[+-]digits`; returns whether an exponent was well formed (or absent), and
    /// how many digits it has.
    fn eat_exponent(&mut self) -> (bool, usize) {
        if !matches!(self.peek_byte(0), Some(b'e' | b'E')) {
            return (true, 0);
        }
        self.pos += 1;
        if matches!(self.peek_byte(0), Some(b'+' | b'-')) {
            self.pos += 1;
        }
        let n_digits = self.eat_decimal_digits();
        (n_digits > 0, n_digits)
    }

    /// Letters or digits glued to a number; returns whether there were none.
    #[inline]
    fn eat_glued(&mut self) -> bool {
        let start = self.pos;
        self.pos += ascii_word_len(&self.bytes[start..]);
        loop {
            match self.bytes.get(self.pos) {
                Some(b) if b.is_ascii_alphanumeric() || *b == b'_' => self.pos += 1,
                Some(b) if *b >= 0x80 && is_ident_continue(self.current_char()) => {
                    self.pos += self.current_char().len_utf8()
                }
                _ => break,
            }
        }
        self.pos == start
    }

    fn number_radix(&self) -> u32 {
        match (self.peek_byte(0), self.peek_byte(1).map(|b| b.to_ascii_lowercase())) {
            (Some(b'0'), Some(b'x')) => 16,
            (Some(b'0'), Some(b'o')) => 8,
            (Some(b'0'), Some(b'b')) => 2,
            _ => 10,
        }
    }

    /// Lexes a number. Most numbers are plain decimals (`0.99969`, `9E9`) that need
    /// none of the checks below: a fast path takes those in one pass and leaves
    /// every other form (other radixes, glued letters, possible overflow, errors) to
    /// [`Lexer::number_checked`], which reads the number again from its start.
    #[inline]
    fn number(&mut self) -> TokenKind {
        match plain_decimal_len(&self.bytes[self.pos..]) {
            Some(len) => {
                self.pos += len;
                TokenKind::Num
            }
            None => self.number_checked(),
        }
    }

    #[inline(never)]
    fn number_checked(&mut self) -> TokenKind {
        let start = self.pos;
        let radix = self.number_radix();
        let mut well_formed = true;
        // Only a number with an exponent or hundreds of digits can leave the f64 range.
        let may_overflow;
        if radix != 10 {
            self.pos += 2;
            let n_digits = self.eat_digits(radix);
            well_formed = n_digits > 0;
            may_overflow = n_digits > 200;
        } else {
            let int_digits = self.eat_decimal_digits();
            let mut frac_digits = 0;
            if self.peek_byte(0) == Some(b'.') {
                self.pos += 1;
                frac_digits = self.eat_decimal_digits();
            }
            well_formed &= int_digits + frac_digits > 0;
            let (exponent_ok, exponent_digits) = self.eat_exponent();
            well_formed &= exponent_ok;
            // Below 10^(200 + 99) a number is finite: only more integer digits or an
            // exponent of three digits or more can leave the f64 range (CAM output
            // writes `9E9` six times a line, which needs no conversion).
            may_overflow = int_digits > 200 || exponent_digits > 2;
        }
        // Letters or digits glued to a number (`1.5E`, `0x1G`, `12abc`) make it malformed.
        well_formed &= self.eat_glued();
        let span = Span::new(start, self.pos);
        if !well_formed {
            let text = span.text(self.text).to_owned();
            self.error(SyntaxErrorKind::MalformedNumber, span, format!("malformed number `{text}`"));
        } else if may_overflow && crate::literal::num_value(span.text(self.text)).is_none_or(|v| !v.is_finite()) {
            let text = span.text(self.text).to_owned();
            self.error(
                SyntaxErrorKind::NumberOutOfRange,
                span,
                format!("number `{text}` is outside the range of IEEE 754 numbers"),
            );
        }
        TokenKind::Num
    }

    fn string(&mut self) -> TokenKind {
        let start = self.pos;
        self.pos += 1;
        let mut n_chars = 0usize;
        loop {
            let Some(c) = self.text[self.pos..].chars().next() else {
                return self.unterminated_string(start);
            };
            match c {
                '\n' | '\r' => return self.unterminated_string(start),
                '"' if self.peek_byte(1) == Some(b'"') => self.pos += 2,
                '"' => {
                    self.pos += 1;
                    break;
                }
                '\\' => self.string_escape(),
                _ => {
                    if c as u32 > 0xFF {
                        let span = Span::new(self.pos, self.pos + c.len_utf8());
                        self.error(
                            SyntaxErrorKind::NonLatin1Character,
                            span,
                            format!(
                                "character `{c}` is not in ISO 8859-1 (Latin-1), the character set of RAPID strings"
                            ),
                        );
                    }
                    self.pos += c.len_utf8();
                }
            }
            n_chars += 1;
        }
        if n_chars > MAX_STRING_CHARS {
            self.error(
                SyntaxErrorKind::StringTooLong,
                Span::new(start, self.pos),
                format!("string has {n_chars} characters; RAPID allows at most {MAX_STRING_CHARS}"),
            );
        }
        TokenKind::Str
    }

    fn string_escape(&mut self) {
        let start = self.pos;
        self.pos += 1;
        if self.peek_byte(0) == Some(b'\\') {
            self.pos += 1;
            return;
        }
        let hex = |b: Option<u8>| b.is_some_and(|b| b.is_ascii_hexdigit());
        if hex(self.peek_byte(0)) && hex(self.peek_byte(1)) {
            self.pos += 2;
            return;
        }
        self.error(
            SyntaxErrorKind::InvalidStringEscape,
            Span::new(start, self.pos),
            "a backslash in a string must be written `\\\\` or start a character code `\\hh`".into(),
        );
    }

    fn unterminated_string(&mut self, start: usize) -> TokenKind {
        self.error(
            SyntaxErrorKind::UnterminatedString,
            Span::new(start, self.pos),
            "string literal has no closing `\"` on its line".into(),
        );
        self.unterminated_string_ends.push(self.pos as u32);
        TokenKind::Str
    }

    fn header(&mut self) -> TokenKind {
        let start = self.pos;
        self.pos += 3;
        match self.text[self.pos..].find("%%%") {
            Some(offset) => self.pos += offset + 3,
            None => {
                // Without its closing `%%%`, the header runs to the MODULE line.
                self.pos = find_module_line(self.text, self.pos).unwrap_or(self.text.len());
                self.error(
                    SyntaxErrorKind::UnterminatedHeader,
                    Span::new(start, start + 3),
                    "file header `%%%` is never closed by a second `%%%`".into(),
                );
            }
        }
        TokenKind::Header
    }
}

/// The offset of the first line at or after `from` whose first word is MODULE.
fn find_module_line(text: &str, from: usize) -> Option<usize> {
    let mut offset = from;
    for line in text[from..].split_inclusive('\n') {
        let trimmed = line.trim_start();
        if trimmed.get(..6).is_some_and(|word| word.eq_ignore_ascii_case("module")) {
            return Some(offset + (line.len() - trimmed.len()));
        }
        offset += line.len();
    }
    None
}

fn memchr_newline(bytes: &[u8]) -> Option<usize> {
    bytes.iter().position(|&b| b == b'\n')
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> (Vec<TokenKind>, Vec<SyntaxErrorKind>) {
        let mut lexer = Lexer::new(text);
        let mut kinds = Vec::new();
        loop {
            let token = lexer.next_token();
            if token.kind == TokenKind::Eof {
                break;
            }
            kinds.push(token.kind);
        }
        (kinds, lexer.errors.iter().map(|e| e.kind).collect())
    }

    use TokenKind as T;

    #[test]
    fn numbers_of_every_form() {
        for text in ["3", "3E2", "3.5", "-245E-2", ".5", "3.", "0x1F", "0o17", "0b1011", "9E9", "1e+3"] {
            let (toks, errs) = kinds(text);
            assert!(errs.is_empty(), "{text}: {errs:?}");
            assert_eq!(*toks.last().unwrap(), T::Num, "{text}");
        }
        for text in ["0x", "1.5E", "12abc", "0b102", "0o8"] {
            assert_eq!(kinds(text).1, vec![SyntaxErrorKind::MalformedNumber], "{text}");
        }
        assert_eq!(kinds("1E400").1, vec![SyntaxErrorKind::NumberOutOfRange]);
    }

    #[test]
    fn strings_and_escapes() {
        assert_eq!(kinds(r#""a ""q"" \\ \07""#), (vec![T::Str], vec![]));
        assert_eq!(kinds(r#""bad \q""#).1, vec![SyntaxErrorKind::InvalidStringEscape]);
        assert_eq!(kinds("\"open\nx").1, vec![SyntaxErrorKind::UnterminatedString]);
        let long = format!("\"{}\"", "a".repeat(81));
        assert_eq!(kinds(&long).1, vec![SyntaxErrorKind::StringTooLong]);
        let exact = format!("\"{}\"", "a".repeat(80));
        assert!(kinds(&exact).1.is_empty());
        // `""` counts as one character.
        let quotes = format!("\"{}\"", "\"\"".repeat(80));
        assert!(kinds(&quotes).1.is_empty());
        assert_eq!(kinds("\"中\"").1, vec![SyntaxErrorKind::NonLatin1Character]);
    }

    #[test]
    fn identifiers_keywords_and_limits() {
        assert_eq!(kinds("MoveL endproc Ärger").0, vec![T::Ident, T::Endproc, T::Ident]);
        assert!(kinds(&"a".repeat(32)).1.is_empty());
        assert_eq!(kinds(&"a".repeat(33)).1, vec![SyntaxErrorKind::IdentifierTooLong]);
        assert_eq!(kinds("a_1 _x").1, vec![SyntaxErrorKind::InvalidCharacter]);
    }

    #[test]
    fn operators_placeholders_comments() {
        let (toks, errs) = kinds("a:=b<>c<=d>=e<f ! comment\n<SMT> <ID> <x");
        assert!(errs.is_empty());
        assert_eq!(
            toks,
            vec![
                T::Ident,
                T::Assign,
                T::Ident,
                T::Ne,
                T::Ident,
                T::Le,
                T::Ident,
                T::Ge,
                T::Ident,
                T::Lt,
                T::Ident,
                T::Placeholder,
                T::Placeholder,
                T::Lt,
                T::Ident
            ]
        );
    }

    #[test]
    fn header_and_invalid_bytes() {
        let (toks, errs) = kinds("%%%\n VERSION:1\n LANGUAGE:ENGLISH\n%%%\nMODULE");
        assert_eq!((toks, errs), (vec![T::Header, T::Module], vec![]));
        assert_eq!(kinds("a \0 b").1, vec![SyntaxErrorKind::InvalidCharacter]);
        assert_eq!(kinds("%%% open").1, vec![SyntaxErrorKind::UnterminatedHeader]);
        // Found by the fuzzer: a non-ASCII letter where the scan for MODULE looks.
        assert_eq!(kinds("%%%\n  LAN-1\u{df}x\nMODULE m").0, vec![T::Header, T::Module, T::Ident]);
        assert_eq!(kinds("%%%\nModu\u{df}\n").1, vec![SyntaxErrorKind::UnterminatedHeader]);
        assert_eq!(kinds("%%%\n VERSION:1\n%%\nMODULE m").0, vec![T::Header, T::Module, T::Ident]);
    }
}
