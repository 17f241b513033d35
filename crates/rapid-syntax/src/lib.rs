//! rapid-syntax: RAPID text to tokens to a syntax tree with spans and comments.
//!
//! Invariant: this crate knows no types, no built-ins and no execution. Parsing never
//! fails: every input gives a tree plus a list of errors.

pub mod ast;
pub mod dump;
pub mod error;
mod grammar;
pub mod intern;
pub mod items;
pub mod lexer;
pub mod literal;
mod parser;
pub mod source;
pub mod span;
pub mod token;

pub use error::{SyntaxError, SyntaxErrorKind};
pub use intern::{Interner, Symbol};
pub use items::for_each_body_item;
pub use parser::{cap_errors, parse, parse_body, parse_outline, BodySink, Parse, MAX_EXPR_DEPTH, MAX_STMT_DEPTH};
pub use span::{LineCol, LineIndex, Span};
