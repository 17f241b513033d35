//! The grammar of RAPID (manual §1.1–§1.5 EBNF), one file per area. Productions are
//! methods on `Parser`; a production named `opt_x` may produce nothing, a plain `x`
//! is called only when its first token is present.

mod args;
mod decl;
mod expr;
mod module;
mod routine;
mod stmt;

use crate::token::{TokenKind as T, TokenSet};

/// Tokens that start a module-level item.
pub(crate) const ITEM_START: TokenSet =
    TokenSet::new(&[T::Local, T::Task, T::Record, T::Alias, T::Var, T::Pers, T::Const, T::Proc, T::Func, T::Trap]);

/// Tokens that end a routine body (and so every statement list in it).
pub(crate) const ROUTINE_END: TokenSet = TokenSet::new(&[
    T::Endproc,
    T::Endfunc,
    T::Endtrap,
    T::Endmodule,
    T::Module,
    T::Proc,
    T::Func,
    T::Trap,
    T::Record,
    T::Alias,
    T::Eof,
]);

/// Tokens where a statement list inside a routine stops.
pub(crate) const STMT_LIST_END: TokenSet = ROUTINE_END.union(TokenSet::new(&[
    T::Endif,
    T::Else,
    T::Elseif,
    T::Endfor,
    T::Endwhile,
    T::Endtest,
    T::Case,
    T::Default,
    T::Backward,
    T::Error,
    T::Undo,
]));

/// Tokens that start a statement, where recovery after a broken statement may resume.
pub(crate) const STMT_START: TokenSet = TokenSet::new(&[
    T::If,
    T::For,
    T::While,
    T::Test,
    T::Goto,
    T::Return,
    T::Raise,
    T::Retry,
    T::Trynext,
    T::Exit,
    T::Connect,
    T::Percent,
]);
