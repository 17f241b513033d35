//! The parser's machinery: token lookahead, consuming, error reporting, recovery and
//! nesting limits. The grammar itself lives in `grammar/`, one file per area.
//!
//! Parsing never fails: a missing piece becomes an `Error` node or a placeholder name,
//! the error is recorded, and the parser resynchronises at the next token of a
//! recovery set, so one run reports every error in a file.

use crate::ast::{Arena, Body, BodyItem, Name, Section, SourceFile, Stmt};
use crate::error::{SyntaxError, SyntaxErrorKind, MAX_ERRORS_PER_FILE};
use crate::intern::Interner;
use crate::lexer::Lexer;
use crate::span::Span;
use crate::token::{Token, TokenKind, TokenSet};

/// Expressions nested deeper than this are refused (E0122), not recursed into.
pub const MAX_EXPR_DEPTH: u32 = rapid_limits::EXPR_DEPTH;
/// Statements nested deeper than this are refused (E0122), not recursed into.
pub const MAX_STMT_DEPTH: u32 = rapid_limits::STMT_DEPTH;

/// The result of parsing one file: always a tree, plus what went wrong.
#[derive(Debug)]
pub struct Parse {
    pub file: SourceFile,
    /// Lexical and syntax errors, in source order.
    pub errors: Vec<SyntaxError>,
    /// Every comment (`!` to the end of the line), in source order.
    pub comments: Vec<Span>,
}

/// Receives routine body items one at a time with the arena holding their
/// expressions (see [`parse_body`]). The sink owns the arena's contents: it clears
/// the arena when done with an item, or takes it whole to keep a batch of items.
pub type BodySink<'s> = dyn FnMut(BodyItem, &mut Arena) + 's;

/// What to do with routine bodies.
pub(crate) enum BodyMode<'s> {
    /// Keep them in the tree.
    Keep,
    /// Only find where they end (an outline); [`parse_body`] parses them later.
    Skip,
    /// Parse them for their errors and drop each item at once.
    Discard,
    /// Hand each top-level item to a sink, then drop it.
    Stream(&'s mut BodySink<'s>),
}

/// Parses a whole file, bodies included.
pub fn parse(text: &str, interner: &mut Interner) -> Parse {
    Parser::new(text, 0, interner, BodyMode::Keep).source_file()
}

/// Parses a file's declarations and routine headers, only scanning over routine
/// bodies (`Routine::body_span` says where each is), so memory stays proportional to
/// the declarations. Errors inside bodies are found by [`parse_body`].
pub fn parse_outline(text: &str, interner: &mut Interner) -> Parse {
    Parser::new(text, 0, interner, BodyMode::Skip).source_file()
}

/// Parses the body of a routine found by [`parse_outline`] and returns its syntax
/// errors. With a sink, each top-level item (declaration, statement, handler keyword)
/// is handed to it together with the arena holding its expressions, and a final
/// `BodyItem::End`; a sink that clears the arena after each item keeps memory bounded
/// by the largest statement.
pub fn parse_body<'s>(
    text: &str,
    body_span: Span,
    interner: &mut Interner,
    sink: Option<&'s mut BodySink<'s>>,
) -> Vec<SyntaxError> {
    let mode = match sink {
        Some(sink) => BodyMode::Stream(sink),
        None => BodyMode::Discard,
    };
    let mut parser = Parser::new(text, body_span.start as usize, interner, mode);
    parser.routine_body_items();
    if let BodyMode::Stream(sink) = &mut parser.body_mode {
        sink(BodyItem::End, &mut parser.arena);
    }
    let mut errors = std::mem::take(&mut parser.lexer.errors);
    errors.append(&mut parser.errors);
    // Lookahead may have lexed past the body; those errors belong to the outline.
    errors.retain(|e| e.span.start < body_span.end || (body_span.is_empty() && e.span.start == body_span.end));
    errors.sort_by_key(|e| e.span.start);
    errors
}

/// Caps a file's errors at [`MAX_ERRORS_PER_FILE`], ending with one that says so.
pub fn cap_errors(mut errors: Vec<SyntaxError>) -> Vec<SyntaxError> {
    errors.sort_by_key(|e| e.span.start);
    if errors.len() > MAX_ERRORS_PER_FILE {
        let span = errors[MAX_ERRORS_PER_FILE].span;
        errors.truncate(MAX_ERRORS_PER_FILE);
        errors.push(SyntaxError {
            kind: SyntaxErrorKind::TooManyErrors,
            span,
            message: format!(
                "more than {MAX_ERRORS_PER_FILE} errors; this does not look like RAPID, so reporting stopped here"
            ),
        });
    }
    errors
}

pub(crate) struct Parser<'t, 'i, 's> {
    pub(crate) text: &'t str,
    lexer: Lexer<'t>,
    ahead: Lookahead,
    prev_end: u32,
    pub(crate) interner: &'i mut Interner,
    errors: Vec<SyntaxError>,
    pub(crate) arena: Arena,
    /// Stacks for building lists without a fresh Vec per list (nested lists push
    /// above their parent's mark and pop back before it continues).
    pub(crate) scratch_exprs: Vec<crate::ast::ExprId>,
    pub(crate) scratch_args: Vec<crate::ast::Arg>,
    pub(crate) expr_depth: u32,
    pub(crate) stmt_depth: u32,
    pub(crate) body_mode: BodyMode<'s>,
    /// Where the last error was reported, to avoid cascades at one spot.
    last_error_at: Option<u32>,
}

impl<'t, 'i, 's> Parser<'t, 'i, 's> {
    pub(crate) fn new(text: &'t str, pos: usize, interner: &'i mut Interner, body_mode: BodyMode<'s>) -> Self {
        Parser {
            text,
            lexer: Lexer::at(text, pos),
            ahead: Lookahead::default(),
            prev_end: pos as u32,
            interner,
            errors: Vec::new(),
            arena: Arena::default(),
            scratch_exprs: Vec::new(),
            scratch_args: Vec::new(),
            expr_depth: 0,
            stmt_depth: 0,
            body_mode,
            last_error_at: None,
        }
    }

    /// Collects the tree and all errors (lexical ones included), capped per file.
    pub(crate) fn finish(mut self, file: SourceFile) -> Parse {
        let mut errors = std::mem::take(&mut self.lexer.errors);
        errors.append(&mut self.errors);
        Parse { file, errors: cap_errors(errors), comments: std::mem::take(&mut self.lexer.comments) }
    }

    /// How many errors were found so far.
    pub(crate) fn error_count(&self) -> usize {
        self.errors.len() + self.lexer.errors.len()
    }

    // ---- lookahead -------------------------------------------------------------

    fn fill(&mut self, n: usize) {
        while self.ahead.len() <= n {
            let token = self.lexer.next_token();
            self.ahead.push_back(token);
        }
    }

    /// The token `n` places ahead (0 = current); the grammar looks at most three ahead.
    pub(crate) fn nth_token(&mut self, n: usize) -> Token {
        self.fill(n);
        self.ahead.get(n)
    }

    pub(crate) fn nth(&mut self, n: usize) -> TokenKind {
        self.nth_token(n).kind
    }

    pub(crate) fn current(&mut self) -> Token {
        self.nth_token(0)
    }

    pub(crate) fn at(&mut self, kind: TokenKind) -> bool {
        self.nth(0) == kind
    }

    pub(crate) fn at_set(&mut self, set: TokenSet) -> bool {
        let kind = self.nth(0);
        set.contains(kind)
    }

    pub(crate) fn at_eof(&mut self) -> bool {
        self.at(TokenKind::Eof)
    }

    // ---- consuming ---------------------------------------------------------------

    pub(crate) fn bump(&mut self) -> Token {
        self.fill(0);
        let token = self.ahead.pop_front();
        if token.kind != TokenKind::Eof {
            self.prev_end = token.span.end;
        }
        token
    }

    pub(crate) fn eat(&mut self, kind: TokenKind) -> bool {
        if self.at(kind) {
            self.bump();
            return true;
        }
        false
    }

    /// Consumes `kind` or reports that it is missing.
    pub(crate) fn expect(&mut self, kind: TokenKind) -> bool {
        if self.eat(kind) {
            return true;
        }
        self.error_expected(kind.describe());
        false
    }

    /// Consumes the `;` that ends a declaration or statement; when it is missing,
    /// reports it right after the last token, where it belongs.
    pub(crate) fn expect_semi(&mut self) -> bool {
        if self.eat(TokenKind::Semi) {
            return true;
        }
        let at = self.prev_end;
        let found = self.current();
        let found_text = self.describe_token(found);
        self.error(
            SyntaxErrorKind::UnexpectedToken,
            Span { start: at, end: at },
            format!("expected `;`, found {found_text}"),
        );
        false
    }

    /// A span from `start` to the end of the last consumed token.
    pub(crate) fn span_from(&self, start: u32) -> Span {
        Span { start, end: self.prev_end.max(start) }
    }

    // ---- errors and recovery -------------------------------------------------------

    pub(crate) fn error(&mut self, kind: SyntaxErrorKind, span: Span, message: String) {
        if kind == SyntaxErrorKind::UnexpectedToken
            && (self.last_error_at == Some(span.start)
                || self.lexer.unterminated_string_ends.last() == Some(&span.start))
        {
            return;
        }
        self.last_error_at = Some(span.start);
        if self.errors.len() <= MAX_ERRORS_PER_FILE {
            self.errors.push(SyntaxError { kind, span, message });
        }
    }

    /// Reports "expected X, found Y" at the current token.
    pub(crate) fn error_expected(&mut self, what: &str) {
        let token = self.current();
        let found = self.describe_token(token);
        self.error(SyntaxErrorKind::UnexpectedToken, token.span, format!("expected {what}, found {found}"));
    }

    pub(crate) fn describe_token(&self, token: Token) -> String {
        match token.kind {
            TokenKind::Ident | TokenKind::Num | TokenKind::Placeholder => {
                let text: String = token.span.text(self.text).chars().take(40).collect();
                format!("{} `{text}`", token.kind.describe())
            }
            _ => token.kind.describe().to_string(),
        }
    }

    /// Skips tokens until one in `stop` (not consumed) or the end of the file.
    pub(crate) fn recover_until(&mut self, stop: TokenSet) {
        while !self.at_eof() && !self.at_set(stop) {
            self.bump();
        }
    }

    /// Skips a run of nested brackets and blocks too deep to parse, without recursion:
    /// from the current token to the end of the construct it opens.
    pub(crate) fn skip_nested(&mut self) {
        let mut depth: u32 = 0;
        let mut pending_if = false;
        loop {
            let kind = self.nth(0);
            match kind {
                TokenKind::Eof => return,
                TokenKind::LParen | TokenKind::LBracket | TokenKind::LBrace => depth += 1,
                TokenKind::RParen | TokenKind::RBracket | TokenKind::RBrace => depth = depth.saturating_sub(1),
                TokenKind::If => pending_if = true,
                TokenKind::Then if pending_if => {
                    pending_if = false;
                    depth += 1;
                }
                TokenKind::Semi => pending_if = false,
                TokenKind::For | TokenKind::While | TokenKind::Test => depth += 1,
                TokenKind::Endif | TokenKind::Endfor | TokenKind::Endwhile | TokenKind::Endtest => {
                    depth = depth.saturating_sub(1)
                }
                kind if crate::grammar::ROUTINE_END.contains(kind) => return,
                _ => {}
            }
            self.bump();
            if depth == 0 && !pending_if {
                return;
            }
        }
    }

    /// Reports nesting past a limit once, at the current token.
    pub(crate) fn error_too_deep(&mut self, what: &str, limit: u32) {
        let span = self.current().span;
        self.error(
            SyntaxErrorKind::NestingTooDeep,
            span,
            format!("{what} nested more than {limit} levels deep; simplify the code"),
        );
    }

    // ---- names ---------------------------------------------------------------------

    /// A placeholder name for a missing identifier.
    pub(crate) fn missing_name(&mut self) -> Name {
        let at = self.current().span.start;
        Name { sym: self.interner.intern("<ID>"), span: Span { start: at, end: at }, is_placeholder: true }
    }

    pub(crate) fn name_from(&mut self, token: Token) -> Name {
        let sym = self.interner.intern(token.span.text(self.text));
        Name { sym, span: token.span, is_placeholder: token.kind == TokenKind::Placeholder }
    }

    // ---- streaming routine bodies ------------------------------------------------

    /// Hands one top-level body item on, as the body mode says.
    pub(crate) fn emit_body_item(&mut self, item: BodyItem, body: &mut Body, section: &mut Section) {
        match &mut self.body_mode {
            BodyMode::Keep => keep_body_item(item, body, section),
            BodyMode::Skip | BodyMode::Discard => self.arena.clear(),
            BodyMode::Stream(sink) => sink(item, &mut self.arena),
        }
    }

    pub(crate) fn keeps_bodies(&self) -> bool {
        matches!(self.body_mode, BodyMode::Keep)
    }

    pub(crate) fn skips_bodies(&self) -> bool {
        matches!(self.body_mode, BodyMode::Skip)
    }

    /// Scans over a routine body without parsing it (outline mode): to the first token
    /// that ends a routine, exactly where `routine_body_items` stops. Lexical errors in
    /// the body are left for `parse_body` to report.
    pub(crate) fn skip_body(&mut self, stop: TokenSet) {
        let start = self.current().span.start;
        while !self.ahead.is_empty() && !stop.contains(self.ahead.get(0).kind) {
            self.bump();
        }
        // Straight through the lexer's scanner: no token is built on the way.
        if self.ahead.is_empty() {
            let token = self.lexer.skip_to(stop);
            self.ahead.push_back(token);
        }
        let end = self.current().span.start;
        self.lexer.errors.retain(|e| e.span.start < start || e.span.start >= end);
        self.lexer.unterminated_string_ends.retain(|&pos| pos < start || pos >= end);
    }
}

/// A ring of the next few tokens (the grammar needs at most three of lookahead).
#[derive(Default)]
struct Lookahead {
    tokens: [Token; LOOKAHEAD],
    head: usize,
    len: usize,
}

const LOOKAHEAD: usize = 4;

impl Default for Token {
    fn default() -> Token {
        Token { kind: TokenKind::Eof, span: Span::default() }
    }
}

impl Lookahead {
    fn len(&self) -> usize {
        self.len
    }

    fn is_empty(&self) -> bool {
        self.len == 0
    }

    fn get(&self, n: usize) -> Token {
        self.tokens[(self.head + n) % LOOKAHEAD]
    }

    fn push_back(&mut self, token: Token) {
        // `fill` never asks for more than LOOKAHEAD tokens; past that the oldest is
        // overwritten, which the grammar's fixed lookahead never reaches.
        self.tokens[(self.head + self.len) % LOOKAHEAD] = token;
        self.len = (self.len + 1).min(LOOKAHEAD);
    }

    fn pop_front(&mut self) -> Token {
        if self.len == 0 {
            return Token::default();
        }
        let token = self.tokens[self.head];
        self.head = (self.head + 1) % LOOKAHEAD;
        self.len -= 1;
        token
    }
}

fn keep_body_item(item: BodyItem, body: &mut Body, section: &mut Section) {
    match item {
        BodyItem::Decl(decl) => body.decls.push(decl),
        BodyItem::Stmt(stmt) => push_stmt(body, *section, stmt),
        BodyItem::End => {}
        BodyItem::Section { section: new, keyword, error_numbers } => {
            *section = new;
            let handler = crate::ast::Handler { keyword, error_numbers, stmts: Vec::new() };
            match new {
                Section::Body => {}
                Section::Backward => body.backward = Some(handler),
                Section::Error => body.error = Some(handler),
                Section::Undo => body.undo = Some(handler),
            }
        }
    }
}

fn push_stmt(body: &mut Body, section: Section, stmt: Stmt) {
    let handler = match section {
        Section::Body => return body.stmts.push(stmt),
        Section::Backward => &mut body.backward,
        Section::Error => &mut body.error,
        Section::Undo => &mut body.undo,
    };
    if let Some(handler) = handler {
        handler.stmts.push(stmt);
    }
}
