//! Arguments of procedure calls (`Name arg, \opt:=x, \sw;`) and function calls
//! (`Name(arg, \opt)`), per the argument EBNF of §1.1.5 and §1.3.6: required arguments
//! are separated by commas; optional and conditional ones may or may not be.

use crate::ast::{Arg, ArgKind, ArgList, ExprKind};
use crate::error::SyntaxErrorKind;
use crate::parser::Parser;
use crate::token::{TokenKind as T, TokenSet};

impl Parser<'_, '_, '_> {
    /// Procedure call arguments up to and including the `;`.
    pub(crate) fn proc_args(&mut self) -> ArgList {
        let args = self.arg_list(T::Semi);
        self.end_of_simple_stmt();
        args
    }

    /// `name(args)` in an expression.
    pub(crate) fn call(&mut self) -> crate::ast::ExprId {
        let start = self.current().span.start;
        let name = self.name();
        self.bump();
        let args = if self.at(T::RParen) { ArgList::default() } else { self.arg_list(T::RParen) };
        self.expect(T::RParen);
        self.arena.alloc(ExprKind::Call { name: name.sym, args }, self.span_from(start))
    }

    /// Arguments until `close` (not consumed).
    fn arg_list(&mut self, close: T) -> ArgList {
        let stop = TokenSet::new(&[close]).union(super::STMT_LIST_END);
        let mark = self.scratch_args.len();
        while !self.at_set(stop) {
            let first = self.scratch_args.len() == mark;
            let after_comma = !first && self.eat(T::Comma);
            if self.at_set(stop) {
                self.error_expected("an argument after `,`");
                break;
            }
            let arg = self.arg(after_comma);
            if !first && !after_comma && arg.kind == ArgKind::Required {
                self.error(SyntaxErrorKind::UnexpectedToken, arg.span, "expected `,` before this argument".into());
            }
            let progressed = arg.span.end > arg.span.start;
            self.scratch_args.push(arg);
            if !progressed {
                self.bump();
                self.recover_until(stop.union(TokenSet::new(&[T::Comma, T::Backslash])));
            }
        }
        // Nested calls inside arguments stored their own argument runs first, so this
        // call's arguments are appended as one contiguous run now.
        let args = self.arena.alloc_args(&self.scratch_args[mark..]);
        self.scratch_args.truncate(mark);
        args
    }

    fn arg(&mut self, after_comma: bool) -> Arg {
        let start = self.current().span.start;
        match self.nth(0) {
            T::Backslash => {
                self.bump();
                let name = Some(self.name());
                let (kind, value) = match self.nth(0) {
                    T::Assign => {
                        self.bump();
                        (ArgKind::Optional, Some(self.expr()))
                    }
                    T::Question => {
                        self.bump();
                        (ArgKind::Conditional, Some(self.postfix_expr()))
                    }
                    _ => (ArgKind::Optional, None),
                };
                Arg { kind, name, value, span: self.span_from(start), after_comma }
            }
            T::Placeholder if self.current().span.text(self.text) == "<ARG>" => {
                self.bump();
                Arg { kind: ArgKind::Placeholder, name: None, value: None, span: self.span_from(start), after_comma }
            }
            T::Ident if self.nth(1) == T::Assign => {
                let name = Some(self.name());
                self.bump();
                let value = Some(self.expr());
                Arg { kind: ArgKind::Required, name, value, span: self.span_from(start), after_comma }
            }
            _ => {
                let value = Some(self.expr());
                Arg { kind: ArgKind::Required, name: None, value, span: self.span_from(start), after_comma }
            }
        }
    }
}
