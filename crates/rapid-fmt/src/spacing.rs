//! Where one space goes between two tokens of a statement, and where none does.
//!
//! The rules follow RobotStudio's RAPID editor (docs/fmt.md): operators and `:=` of an
//! assignment spaced (`a := b + 1`), `:=` of a declaration and of a named argument
//! tight (`p10:=[…]`, `\WObj:=wobj0`), a space after commas of argument lists but none
//! inside aggregates and indexes (`[[0,0,0],[1,0,0,0]]`), nothing inside brackets, none
//! before `(` or `{` after a name (`Offs(p,0,0,10)`, `a{2}`), none after a sign
//! (`-1`), none before `\` unless it follows the instruction name (`ConfL \Off`,
//! `tool0\WObj:=wobj0`); late binding spaced as the manual writes it (`% "p" + n % x`).

use rapid_syntax::token::TokenKind as T;

/// The brackets a statement has open.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Open {
    Paren,
    Bracket,
    Brace,
}

/// The spacing state of one statement, fed its tokens in order.
#[derive(Debug)]
pub(crate) struct Spacer {
    pub(crate) open: Vec<Open>,
    prev: Option<T>,
    prev2: Option<T>,
    n_tokens: usize,
    after_sign: bool,
    assign_spaced: bool,
    /// `:=` of a declaration is tight.
    is_decl: bool,
    /// `MODULE m (SYSMODULE)`: a space before the attribute list.
    is_module: bool,
    aggregate_spaces: bool,
}

impl Spacer {
    /// A spacer for one statement; `open` is a recycled (cleared) stack.
    pub(crate) fn new(is_decl: bool, is_module: bool, aggregate_spaces: bool, mut open: Vec<Open>) -> Spacer {
        open.clear();
        Spacer {
            open,
            prev: None,
            prev2: None,
            n_tokens: 0,
            after_sign: false,
            assign_spaced: true,
            is_decl,
            is_module,
            aggregate_spaces,
        }
    }

    /// Whether a space goes before `next`; then takes `next` as the latest token.
    pub(crate) fn push(&mut self, next: T) -> bool {
        if next == T::Assign {
            let named_arg = self.prev == Some(T::Ident) && self.prev2 == Some(T::Backslash);
            self.assign_spaced = !named_arg && !self.is_decl;
        }
        let space = self.space_before(next);
        let sign = matches!(next, T::Plus | T::Minus) && !self.prev.is_some_and(|p| self.ends_operand(p));
        match next {
            T::LParen => self.open.push(Open::Paren),
            T::LBracket => self.open.push(Open::Bracket),
            T::LBrace => self.open.push(Open::Brace),
            T::RParen | T::RBracket | T::RBrace => {
                self.open.pop();
            }
            _ => {}
        }
        self.after_sign = sign;
        self.prev2 = self.prev;
        self.prev = Some(next);
        self.n_tokens += 1;
        space
    }

    fn space_before(&self, next: T) -> bool {
        let Some(prev) = self.prev else { return false };
        if self.after_sign {
            return false;
        }
        if matches!(next, T::Comma | T::Semi | T::RParen | T::RBracket | T::RBrace | T::Dot | T::Colon | T::Question) {
            return false;
        }
        if matches!(prev, T::LParen | T::LBracket | T::LBrace | T::Dot | T::Backslash | T::Question) {
            return false;
        }
        if prev == T::Comma {
            let in_aggregate = matches!(self.open.last(), Some(Open::Bracket | Open::Brace));
            return !in_aggregate || self.aggregate_spaces;
        }
        if next == T::Assign || prev == T::Assign {
            return self.assign_spaced;
        }
        match next {
            T::LParen => prev != T::Ident || (self.is_module && self.n_tokens == 2),
            T::LBrace => prev != T::Ident,
            T::Backslash => self.n_tokens == 1 || prev.is_keyword(),
            _ => true,
        }
    }

    /// Whether `prev` ends an operand, so that a following `+`/`-` is binary. The
    /// instruction name of a call is no operand: `Foo -1;` passes minus one.
    fn ends_operand(&self, prev: T) -> bool {
        match prev {
            T::Ident => self.n_tokens != 1,
            T::Num | T::Str | T::Placeholder | T::RParen | T::RBracket | T::RBrace | T::True | T::False => true,
            // A closing `%` of a late-bound call is followed by arguments.
            _ => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use rapid_syntax::lexer::Lexer;

    use super::*;

    /// Lays out one statement with single spaces where the rules put one.
    fn spaced(text: &str, is_decl: bool) -> String {
        let mut lexer = Lexer::new(text);
        let mut spacer = Spacer::new(is_decl, false, false, Vec::new());
        let mut out = String::new();
        loop {
            let token = lexer.next_token();
            if token.kind == T::Eof {
                return out;
            }
            if spacer.push(token.kind) {
                out.push(' ');
            }
            out.push_str(token.span.text(text));
        }
    }

    #[test]
    fn assignments_and_declarations() {
        assert_eq!(spaced("reg1:=reg1+1;", false), "reg1 := reg1 + 1;");
        assert_eq!(spaced("VAR num  n  :=  - 1 ;", true), "VAR num n:=-1;");
        assert_eq!(spaced("x := a * - b - ( - c );", false), "x := a * -b - (-c);");
        assert_eq!(
            spaced("CONST robtarget p := [ [ 1 , 2 , 3 ] , [ 1,0,0,0 ] ];", true),
            "CONST robtarget p:=[[1,2,3],[1,0,0,0]];"
        );
    }

    #[test]
    fn calls_and_arguments() {
        assert_eq!(
            spaced("MoveL p10,v1000,z50,tool0 \\WObj := wobj0;", false),
            "MoveL p10, v1000, z50, tool0\\WObj:=wobj0;"
        );
        assert_eq!(spaced("ConfL\\Off;", false), "ConfL \\Off;");
        assert_eq!(spaced("MoveL *,v100,fine,tool0;", false), "MoveL *, v100, fine, tool0;");
        assert_eq!(spaced("Foo -1, a{ i , 2 };", false), "Foo -1, a{i,2};");
        assert_eq!(spaced("x := Offs ( p , 0 , 0 , 10 ) . trans . z;", false), "x := Offs(p, 0, 0, 10).trans.z;");
        // Late binding as the manual writes it (§1.5.2's example): `% "proc" + n % x, y;`.
        assert_eq!(spaced("%\"proc\"+n% a , b;", false), "% \"proc\" + n % a, b;");
        assert_eq!(spaced("Opt \\sw ? sw;", false), "Opt \\sw?sw;");
    }

    #[test]
    fn conditions() {
        assert_eq!(spaced("IF a>1 AND NOT(b) THEN", false), "IF a > 1 AND NOT (b) THEN");
        assert_eq!(spaced("WHILE i<=n DO", false), "WHILE i <= n DO");
        assert_eq!(spaced("CASE 1,2 :", false), "CASE 1, 2:");
    }
}
