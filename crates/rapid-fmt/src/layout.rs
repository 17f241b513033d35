//! The formatter proper: the token stream, with comments in their places, cut into
//! lines (one statement, declaration or block keyword each) and indented by block
//! level.
//!
//! A statement ends at its `;`; a block header at `THEN` or `DO`, at the `)` of a
//! routine's parameters or a module's attributes, after the name of a TRAP or RECORD,
//! or (TEST) before its first CASE. ELSE, ELSEIF, CASE, DEFAULT and the handler
//! keywords ERROR, UNDO and BACKWARD stand one level out of the block they divide, as
//! RobotStudio writes them. Comments on lines of their own are indented as the code
//! around them; a comment after code stays on that line, with the spaces it had
//! before it. Runs of blank lines between statements are kept, up to
//! `Config::max_blank_lines`; line ends are the text's own (`\r\n` or `\n`).
//!
//! Each stretch of output is checked against the input's pieces as soon as it is
//! written (`verify.rs`). Names declared inside routines (data, FOR variables) are
//! noted as their declarations go by: RAPID declares routine data before the
//! statements, so every use follows.

use std::sync::mpsc;

use rapid_syntax::lexer::Lexer;
use rapid_syntax::token::TokenKind as T;
use rapid_syntax::Span;

use crate::names::{spellings, Declared, Spellings};
use crate::spacing::Spacer;
use crate::verify::{self, Piece};
use crate::wrap::{lay_out, Atom, AtomKind, Frame};
use crate::{Config, Refusal};

/// Formats `text`, which has no syntax errors in its outline; `declared` holds the
/// names the outline declares. With `on_thread`, the output is verified on a thread of
/// its own, in chunks, while the layout goes on.
pub(crate) fn format(text: &str, config: &Config, declared: Declared, on_thread: bool) -> Result<String, Refusal> {
    if !on_thread {
        return lay_out_file(Formatter::new(text, config, declared, None));
    }
    let (chunks, received) = mpsc::sync_channel::<Chunk>(CHUNKS_IN_FLIGHT);
    std::thread::scope(|scope| {
        let checker = scope.spawn(move || verify::chunks(text, received));
        let out = lay_out_file(Formatter::new(text, config, declared, Some(chunks)));
        let checked =
            checker.join().unwrap_or_else(|_| Err(Refusal::Unsafe { offset: 0, message: "the check failed".into() }));
        checked.and(out)
    })
}

/// Output written since the last chunk was sent: it must lex as `input[from..to]`.
pub(crate) type Chunk = (usize, usize, String);

/// Chunks in the channel to the verifier; bounds memory whatever the file's size.
const CHUNKS_IN_FLIGHT: usize = 16;
/// A chunk is sent once this much output has gathered.
const CHUNK_BYTES: usize = 1 << 16;

fn lay_out_file(mut f: Formatter<'_>) -> Result<String, Refusal> {
    let text = f.text;
    let mut lexer = Lexer::new(text);
    let mut last_end = 0usize;
    loop {
        let token = lexer.next_token();
        for comment in lexer.comments.drain(..) {
            let newlines = count_newlines(&text[last_end..comment.start as usize]);
            f.piece(Piece { kind: None, span: comment, newlines });
            last_end = comment.end as usize;
        }
        if token.kind == T::Eof || f.failure.is_some() {
            break;
        }
        let newlines = count_newlines(&text[last_end..token.span.start as usize]);
        f.piece(Piece { kind: Some(token.kind), span: token.span, newlines });
        last_end = token.span.end as usize;
    }
    f.finish()
}

/// Columns a text takes: its characters.
fn width_of(text: &str) -> usize {
    if text.is_ascii() {
        text.len()
    } else {
        text.chars().count()
    }
}

fn count_newlines(gap: &str) -> u32 {
    gap.bytes().filter(|&b| b == b'\n').count().try_into().unwrap_or(u32::MAX)
}

/// What a line opened, to be closed by its END keyword.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Block {
    Module,
    Routine,
    Record,
    If,
    Loop,
    Test,
}

/// The statement being gathered.
#[derive(Debug, Default)]
struct Unit {
    pieces: Vec<Piece>,
    n_tokens: usize,
    /// The first token that is not LOCAL or TASK.
    head: Option<T>,
    last: Option<T>,
    depth: usize,
    /// The unit could end here (a following token may still continue it).
    complete: bool,
}

struct Formatter<'a> {
    text: &'a str,
    config: &'a Config,
    declared: Declared,
    spellings: &'static Spellings,
    nl: &'static str,
    out: String,
    blocks: Vec<Block>,
    unit: Unit,
    scratch: String,
    atoms: Vec<Atom>,
    /// The spacer's bracket stack, kept between statements.
    open: Vec<crate::spacing::Open>,
    /// How much of `out` is verified (or sent to the verifier).
    checked: usize,
    /// Where the input of the output not yet verified starts.
    input_checked: usize,
    chunks: Option<mpsc::SyncSender<Chunk>>,
    /// Where the input laid out so far ends.
    pending_end: usize,
    failure: Option<Refusal>,
}

impl<'a> Formatter<'a> {
    fn new(
        text: &'a str,
        config: &'a Config,
        declared: Declared,
        chunks: Option<mpsc::SyncSender<Chunk>>,
    ) -> Formatter<'a> {
        let nl = match text.find('\n') {
            Some(idx) if idx > 0 && text.as_bytes()[idx - 1] == b'\r' => "\r\n",
            _ => "\n",
        };
        Formatter {
            text,
            config,
            declared,
            spellings: spellings(),
            nl,
            out: String::with_capacity(text.len() + text.len() / 8),
            blocks: Vec::new(),
            unit: Unit::default(),
            scratch: String::new(),
            atoms: Vec::new(),
            open: Vec::new(),
            checked: 0,
            input_checked: 0,
            chunks,
            pending_end: 0,
            failure: None,
        }
    }

    /// Checks what was written since the last check against the pieces laid out, or
    /// sends it to the verifier once a chunk has gathered.
    fn verify(&mut self, pieces: &[Piece]) {
        if let Some(chunks) = &self.chunks {
            let input_end = pieces.last().map_or(self.input_checked, |p| p.span.end as usize);
            if self.out.len() - self.checked >= CHUNK_BYTES {
                let chunk = (self.input_checked, input_end, self.out[self.checked..].to_owned());
                if chunks.send(chunk).is_err() {
                    self.failure = Some(Refusal::Unsafe { offset: 0, message: "the check stopped".into() });
                }
                self.checked = self.out.len();
                self.input_checked = input_end;
            }
            self.pending_end = input_end;
            return;
        }
        if self.failure.is_none() {
            if let Err(refusal) = verify::stretch(self.text, pieces, &self.out, self.checked) {
                self.failure = Some(refusal);
            }
        }
        self.checked = self.out.len();
    }

    fn piece(&mut self, piece: Piece) {
        let Some(kind) = piece.kind else {
            if self.unit.pieces.is_empty() {
                // Only comments before the first token reach here.
                let level = self.blocks.len();
                self.comment_line(piece, level);
                self.verify(&[piece]);
            } else {
                self.unit.pieces.push(piece);
            }
            return;
        };
        if !self.unit.pieces.is_empty() && self.closes_before(kind, piece.newlines) {
            self.flush();
        }
        let unit = &mut self.unit;
        unit.pieces.push(piece);
        unit.n_tokens += 1;
        if unit.head.is_none() && !matches!(kind, T::Local | T::Task) {
            unit.head = Some(kind);
        }
        match kind {
            T::LParen | T::LBracket | T::LBrace => unit.depth += 1,
            T::RParen | T::RBracket | T::RBrace => unit.depth = unit.depth.saturating_sub(1),
            _ => {}
        }
        unit.last = Some(kind);
        unit.complete = ends_after(unit, kind);
    }

    /// Whether the gathered unit ends before a token of `kind`.
    fn closes_before(&self, kind: T, newlines: u32) -> bool {
        let unit = &self.unit;
        if unit.head == Some(T::Test) {
            return unit.depth == 0 && unit.n_tokens >= 2 && matches!(kind, T::Case | T::Default | T::Endtest);
        }
        if !unit.complete {
            return false;
        }
        let continues = match unit.head {
            // `MODULE m (SYSMODULE)`, `ERROR (ERR_A, ERR_B)`.
            Some(T::Module | T::Error) => kind == T::LParen && unit.last != Some(T::RParen),
            // An editor placeholder is a statement of its own unless code follows it on its line.
            Some(T::Placeholder) => newlines == 0 && unit.last != Some(T::Semi),
            _ => false,
        };
        !continues
    }

    fn finish(mut self) -> Result<String, Refusal> {
        if !self.unit.pieces.is_empty() && self.failure.is_none() {
            self.flush();
        }
        if let Some(chunks) = self.chunks.take() {
            let chunk = (self.input_checked, self.pending_end, self.out[self.checked..].to_owned());
            if chunks.send(chunk).is_err() && self.failure.is_none() {
                self.failure = Some(Refusal::Unsafe { offset: 0, message: "the check stopped".into() });
            }
        }
        if let Some(refusal) = self.failure {
            return Err(refusal);
        }
        if !self.out.is_empty() {
            self.out.push_str(self.nl);
        }
        Ok(self.out)
    }

    /// Starts a line at `indent` after `newlines` line ends in the input.
    fn start_line(&mut self, newlines: u32, indent: usize) {
        if !self.out.is_empty() {
            let blank = (newlines.saturating_sub(1) as usize).min(self.config.max_blank_lines);
            for _ in 0..=blank {
                self.out.push_str(self.nl);
            }
        }
        self.out.extend(std::iter::repeat_n(' ', indent));
    }

    fn comment_line(&mut self, piece: Piece, level: usize) {
        self.start_line(piece.newlines, level * self.config.indent_width);
        self.out.push_str(piece.span.text(self.text));
    }

    /// Writes the gathered unit and the comments after it.
    fn flush(&mut self) {
        let mut unit = std::mem::take(&mut self.unit);
        let last_token = unit.pieces.iter().rposition(|p| p.kind.is_some()).unwrap_or(0);
        let head = unit.head.unwrap_or(T::Eof);
        if is_end(head) {
            self.blocks.pop();
        }
        let level = self.blocks.len();
        let indent_level = match head {
            T::Else | T::Elseif | T::Case | T::Default | T::Error | T::Undo | T::Backward => level.saturating_sub(1),
            T::Header => 0,
            _ => level,
        };
        let indent = indent_level * self.config.indent_width;
        if self.blocks.contains(&Block::Routine) {
            self.note_local(&unit.pieces, head);
        }
        let first = unit.pieces[0];
        self.start_line(first.newlines, indent);
        // A comment on the unit's last line stays there.
        let mut tail = last_token + 1;
        if unit.pieces.get(tail).is_some_and(|p| p.newlines == 0) {
            tail += 1;
        }
        if head == T::Header {
            self.out.push_str(first.span.text(self.text));
        } else {
            self.write_unit(&unit.pieces[..tail], head, indent);
        }
        if let Some(block) = opened_block(head, unit.last) {
            self.blocks.push(block);
        }
        let after = self.blocks.len();
        for &piece in &unit.pieces[tail..] {
            self.comment_line(piece, after);
        }
        self.verify(&unit.pieces);
        unit.pieces.clear();
        self.unit = Unit { pieces: unit.pieces, ..Unit::default() };
    }

    /// Notes the name a routine's data declaration or FOR loop declares: it is the
    /// name before the first `{`, `:=` or `;` (data), or the one after FOR.
    fn note_local(&mut self, pieces: &[Piece], head: T) {
        let mut tokens = pieces.iter().filter(|p| p.kind.is_some());
        let name = match head {
            T::For => tokens.nth(1),
            T::Var | T::Pers | T::Const => {
                let mut name = None;
                for piece in tokens {
                    if matches!(piece.kind, Some(T::LBrace | T::Assign | T::Semi)) {
                        break;
                    }
                    name = Some(piece);
                }
                name
            }
            _ => None,
        };
        if let Some(piece) = name.filter(|p| p.kind == Some(T::Ident)) {
            self.declared.add(piece.span.text(self.text));
        }
    }

    /// Lays out a unit's tokens and inner comments.
    fn write_unit(&mut self, pieces: &[Piece], head: T, indent: usize) {
        self.scratch.clear();
        self.atoms.clear();
        let is_decl = matches!(head, T::Var | T::Pers | T::Const);
        let is_header = matches!(head, T::Proc | T::Func | T::Trap);
        let open = std::mem::take(&mut self.open);
        let mut spacer = Spacer::new(is_decl, head == T::Module, self.config.aggregate_spaces, open);
        let mut prev: Option<T> = None;
        let mut prev_end = pieces[0].span.start as usize;
        let mut first_width = 0;
        for piece in pieces {
            let start = self.scratch.len();
            let kind = match piece.kind {
                Some(kind) => {
                    let depth = spacer.open.len();
                    let space = spacer.push(kind);
                    self.token_text(kind, piece.span, prev, is_header);
                    if prev.is_none() {
                        first_width = width_of(&self.scratch[start..]);
                    }
                    prev = Some(kind);
                    let comma = kind == T::Comma;
                    let opens = matches!(kind, T::LParen | T::LBracket | T::LBrace);
                    let closes = matches!(kind, T::RParen | T::RBracket | T::RBrace);
                    let depth = if closes { depth.saturating_sub(1) } else { depth };
                    let end = self.scratch.len();
                    let width = width_of(&self.scratch[start..end]) + usize::from(space);
                    self.atoms.push(Atom {
                        start,
                        end,
                        width,
                        space,
                        kind: AtomKind::Token { depth, comma, opens, closes },
                    });
                    prev_end = piece.span.end as usize;
                    continue;
                }
                None if piece.newlines == 0 => {
                    let gap = &self.text[prev_end..piece.span.start as usize];
                    let gap = if !gap.is_empty() && gap.bytes().all(|b| b == b' ' || b == b'\t') { gap } else { " " };
                    self.scratch.push_str(gap);
                    AtomKind::Trailing
                }
                None => AtomKind::OwnLine,
            };
            self.scratch.push_str(piece.span.text(self.text));
            let end = self.scratch.len();
            let width = width_of(&self.scratch[start..end]);
            self.atoms.push(Atom { start, end, width, space: false, kind });
            prev_end = piece.span.end as usize;
        }
        let is_call = head == T::Ident && !is_decl;
        let outer = if is_call { indent + first_width + 1 } else { indent + 2 * self.config.indent_width };
        let frame = Frame { indent, outer, nl: self.nl };
        lay_out(&mut self.out, frame, &self.atoms, &self.scratch, self.config);
        self.open = spacer.open;
    }

    /// Appends a token's text as written out: reserved words in upper case, built-in
    /// names as the catalogue spells them, everything else as it was.
    fn token_text(&mut self, kind: T, span: Span, prev: Option<T>, is_header: bool) {
        let word = span.text(self.text);
        if kind.is_keyword() {
            let start = self.scratch.len();
            self.scratch.push_str(word);
            self.scratch[start..].make_ascii_uppercase();
            return;
        }
        if kind == T::Ident && prev != Some(T::Dot) {
            // In a routine header, `\` is followed by a parameter's type.
            let argument_name = prev == Some(T::Backslash) && !is_header;
            if let Some(spelled) = self.spellings.get(word, argument_name) {
                if !self.declared.contains(word) {
                    self.scratch.push_str(spelled);
                    return;
                }
            }
        }
        self.scratch.push_str(word);
    }
}

/// Whether a unit of this head is complete once `kind` is added.
fn ends_after(unit: &Unit, kind: T) -> bool {
    let head = unit.head.unwrap_or(kind);
    if kind == T::Semi && unit.depth == 0 {
        return true;
    }
    match head {
        T::If | T::Elseif => kind == T::Then && unit.depth == 0,
        T::While | T::For => kind == T::Do && unit.depth == 0,
        T::Module | T::Error => {
            (unit.n_tokens == 2 && head == T::Module)
                || (unit.n_tokens == 1 && head == T::Error)
                || (kind == T::RParen && unit.depth == 0)
        }
        T::Proc | T::Func => kind == T::RParen && unit.depth == 0,
        T::Trap | T::Record => unit.pieces.iter().filter(|p| p.kind.is_some()).count() >= 2 && kind == T::Ident,
        T::Case | T::Default => kind == T::Colon && unit.depth == 0,
        T::Ident => kind == T::Colon && unit.n_tokens == 2,
        T::Else | T::Undo | T::Backward | T::Header | T::Placeholder => unit.n_tokens == 1,
        _ => is_end(head),
    }
}

fn is_end(kind: T) -> bool {
    matches!(
        kind,
        T::Endmodule
            | T::Endproc
            | T::Endfunc
            | T::Endtrap
            | T::Endrecord
            | T::Endif
            | T::Endwhile
            | T::Endfor
            | T::Endtest
    )
}

/// The block a unit opens, if any.
fn opened_block(head: T, last: Option<T>) -> Option<Block> {
    match head {
        T::Module => Some(Block::Module),
        T::Proc | T::Func | T::Trap => Some(Block::Routine),
        T::Record => Some(Block::Record),
        T::If if last == Some(T::Then) => Some(Block::If),
        T::While | T::For if last == Some(T::Do) => Some(Block::Loop),
        T::Test => Some(Block::Test),
        _ => None,
    }
}
