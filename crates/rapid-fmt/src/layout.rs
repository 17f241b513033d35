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

use std::sync::mpsc::{self, TryRecvError};

use rapid_syntax::lexer::Lexer;
use rapid_syntax::token::TokenKind as T;
use rapid_syntax::Span;
use rustc_hash::FxHashSet;

use crate::names::{spellings, Declared, Spellings};
use crate::spacing::Spacer;
use crate::verify::{self, Piece};
use crate::wrap::{lay_out, Atom, AtomKind, Frame, Shape, Statement};
use crate::{Config, Refusal};

/// Formats `text`, which has no syntax errors in its outline; `declared` holds the
/// names the outline declares, `threads` how the work is shared.
pub(crate) fn format(text: &str, config: &Config, declared: Declared, threads: Threads) -> Result<String, Refusal> {
    if threads == Threads::One {
        let mut f = Formatter::new(text, config, declared, None);
        lex(text, |piece| {
            f.piece(piece);
            f.failure.is_none()
        });
        return f.finish().into_result();
    }
    on_threads(text, config, declared, None, threads).into_result()
}

/// How a layout shares its work with other threads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Threads {
    /// None: each statement is verified as soon as it is written.
    One,
    /// The output is verified on a second thread, in chunks.
    Verifier,
    /// The text is also lexed on a third thread, which hands its pieces over in batches.
    LexerAndVerifier,
}

impl Threads {
    /// For a long file, which also has its bodies parsed on a thread of their own: the
    /// lexer gets a thread only where there are more than two cores. On two, the body
    /// parser, the layout and the verifier keep both busy already, and handing the
    /// pieces over in batches costs more than it spreads (about 7 % of the CPU time on
    /// the CAM module, mostly in writing and reading back the batches); with more cores
    /// the lexer's thread takes its part off the layout's, which bounds the run.
    pub(crate) fn for_long_file() -> Threads {
        match std::thread::available_parallelism() {
            Ok(cores) if cores.get() > 2 => Threads::LexerAndVerifier,
            _ => Threads::Verifier,
        }
    }
}

/// What a layout that started before the outline was parsed came to.
pub(crate) enum Laid {
    Done(Result<String, Refusal>),
    /// A name the layout respelled before the outline came turned out to be declared
    /// by the file: the layout must be done again, with the outline's names (here).
    Again(Declared),
}

impl Laid {
    fn into_result(self) -> Result<String, Refusal> {
        match self {
            Laid::Done(result) => result,
            // Only a layout waiting for the outline starts again.
            Laid::Again(_) => Err(Refusal::Unsafe { offset: 0, message: "the layout stopped".into() }),
        }
    }
}

/// Formats a long `text` on threads while its outline is still being parsed: the
/// outline's names come through `outline` (it hangs up when the outline has errors).
/// Until they come, built-in names are respelled as if the file declared none of
/// them, and each name respelled is noted; when the outline comes, the layout goes
/// on with its names if it declares none of the noted ones, and answers
/// [`Laid::Again`] if it does. Either way the output is what the layout would have
/// written with the outline's names from the start.
pub(crate) fn format_before_outline(
    text: &str,
    config: &Config,
    outline: mpsc::Receiver<Declared>,
    threads: Threads,
) -> Laid {
    on_threads(text, config, Declared::default(), Some(outline), threads)
}

/// The text laid out on this thread and verified on another, in chunks; lexed on a
/// third with [`Threads::LexerAndVerifier`].
fn on_threads(
    text: &str,
    config: &Config,
    declared: Declared,
    outline: Option<mpsc::Receiver<Declared>>,
    threads: Threads,
) -> Laid {
    // Each channel has a way back for the emptied buffers: they are used again, so
    // memory stays small and warm.
    let (chunks, received) = mpsc::sync_channel::<Chunk>(CHUNKS_IN_FLIGHT);
    let (used_chunks, spare_chunks) = mpsc::channel::<Chunk>();
    std::thread::scope(|scope| {
        let checker = scope.spawn(move || verify::chunks(text, received, &used_chunks));
        let to_verifier = ToVerifier { chunks, spare: spare_chunks };
        let mut f = Formatter::new(text, config, declared, Some(to_verifier));
        f.outline = outline;
        if threads == Threads::LexerAndVerifier {
            let (lexed, pieces) = mpsc::sync_channel::<Vec<Piece>>(CHUNKS_IN_FLIGHT);
            let (used_batches, spare_batches) = mpsc::channel::<Vec<Piece>>();
            scope.spawn(move || lex_in_batches(text, &lexed, &spare_batches));
            'batches: for mut batch in pieces {
                for &piece in &batch {
                    f.piece(piece);
                    if f.failure.is_some() {
                        break 'batches;
                    }
                }
                batch.clear();
                // The lexer may be done already: then the buffer is not needed.
                let _ = used_batches.send(batch);
            }
            // Dropping `pieces` (moved into the loop) stops the lexer early on a failure.
        } else {
            lex(text, |piece| {
                f.piece(piece);
                f.failure.is_none()
            });
        }
        let out = f.finish();
        let checked =
            checker.join().unwrap_or_else(|_| Err(Refusal::Unsafe { offset: 0, message: "the check failed".into() }));
        match out {
            Laid::Done(out) => Laid::Done(checked.and(out)),
            again => again,
        }
    })
}

/// Output written since the last chunk was sent, and the input's pieces laid out into
/// it: the output must lex as those pieces.
pub(crate) type Chunk = (Vec<Piece>, String);

/// The way to the verifier thread, and back for its emptied chunks.
struct ToVerifier {
    chunks: mpsc::SyncSender<Chunk>,
    spare: mpsc::Receiver<Chunk>,
}

/// Chunks in a channel between threads; bounds memory whatever the file's size.
const CHUNKS_IN_FLIGHT: usize = 16;
/// A chunk is sent to the verifier once this much output has gathered.
const CHUNK_BYTES: usize = 1 << 16;
/// Pieces per batch from the lexer thread.
const BATCH_PIECES: usize = 1 << 13;

/// Hands `emit` the text's tokens and comments in order, each with the line ends
/// before it, until the end or until `emit` answers false.
fn lex(text: &str, mut emit: impl FnMut(Piece) -> bool) {
    let mut lexer = Lexer::new(text);
    let bytes = text.as_bytes();
    let mut last_end = 0usize;
    loop {
        let token = lexer.next_token();
        if !lexer.comments.is_empty() {
            for comment in lexer.comments.drain(..) {
                let newlines = count_newlines(&bytes[last_end..comment.start as usize]);
                if !emit(Piece { kind: None, span: comment, newlines }) {
                    return;
                }
                last_end = comment.end as usize;
            }
        }
        if token.kind == T::Eof {
            return;
        }
        let newlines = count_newlines(&bytes[last_end..token.span.start as usize]);
        if !emit(Piece { kind: Some(token.kind), span: token.span, newlines }) {
            return;
        }
        last_end = token.span.end as usize;
    }
}

/// The lexer thread: sends the pieces in batches, in buffers the layout gave back
/// where it can; stops when the layout hangs up.
fn lex_in_batches(text: &str, lexed: &mpsc::SyncSender<Vec<Piece>>, spare: &mpsc::Receiver<Vec<Piece>>) {
    let new_batch = || spare.try_recv().unwrap_or_else(|_| Vec::with_capacity(BATCH_PIECES));
    let mut batch = new_batch();
    let mut open = true;
    lex(text, |piece| {
        batch.push(piece);
        if batch.len() == BATCH_PIECES {
            let full = std::mem::replace(&mut batch, new_batch());
            open = lexed.send(full).is_ok();
        }
        open
    });
    if open && !batch.is_empty() {
        // A hung-up layout needs nothing more.
        let _ = lexed.send(batch);
    }
}

/// Columns a text takes: its characters.
fn width_of(text: &str) -> usize {
    if text.is_ascii() {
        text.len()
    } else {
        text.chars().count()
    }
}

/// Offsets and widths inside one statement: the text is at most `u32::MAX` bytes, as
/// its spans are.
fn to_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// Line ends in the gap between two pieces (mostly empty or one space).
fn count_newlines(gap: &[u8]) -> u32 {
    let n: usize = gap.iter().map(|&b| usize::from(b == b'\n')).sum();
    u32::try_from(n).unwrap_or(u32::MAX)
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
    /// The statement being written, laid out flat, and its atoms.
    scratch: String,
    atoms: Vec<Atom>,
    /// The wrapper's stack of bracket columns, kept between statements.
    groups: Vec<usize>,
    /// The text is ASCII: every character takes one byte.
    ascii: bool,
    /// The spacer's bracket stack, kept between statements.
    open: Vec<crate::spacing::Open>,
    /// How much of `out` is verified (or sent to the verifier).
    checked: usize,
    chunks: Option<ToVerifier>,
    /// The pieces laid out into `out[checked..]`, for the verifier.
    chunk_pieces: Vec<Piece>,
    failure: Option<Refusal>,
    /// The outline's names, while they are still to come (`format_before_outline`).
    outline: Option<mpsc::Receiver<Declared>>,
    /// The names respelled while the outline was still to come.
    respelled: FxHashSet<&'static str>,
    /// The outline came and declares a name in `respelled`.
    again: Option<Declared>,
    /// Spellings decided lately (a CAM module spells the same few names on every line).
    recent: Recent<'a>,
}

/// Names as written, each with the spelling it gets (`None`: kept as written), in
/// slots picked by length and first and last letters; a name meets only its own slot,
/// and a slot holds the last name that met it. Emptied whenever the declared names
/// grow, so a spelling here is always the one the catalogue and `declared` give.
struct Recent<'a> {
    slots: [Option<(&'a str, bool, Option<&'static str>)>; RECENT_SLOTS],
}

const RECENT_SLOTS: usize = 64;

impl<'a> Recent<'a> {
    fn new() -> Recent<'a> {
        Recent { slots: [None; RECENT_SLOTS] }
    }

    fn slot(word: &str) -> usize {
        let bytes = word.as_bytes();
        let (first, last) = (bytes.first().copied().unwrap_or(0), bytes.last().copied().unwrap_or(0));
        (bytes.len() ^ usize::from(first).wrapping_mul(7) ^ usize::from(last).wrapping_mul(31)) % RECENT_SLOTS
    }

    /// The spelling decided for `word` (after `\` or not), if it is here.
    fn get(&self, word: &str, after_backslash: bool) -> Option<Option<&'static str>> {
        match self.slots[Recent::slot(word)] {
            Some((seen, after, spelled)) if after == after_backslash && seen == word => Some(spelled),
            _ => None,
        }
    }

    fn put(&mut self, word: &'a str, after_backslash: bool, spelled: Option<&'static str>) {
        self.slots[Recent::slot(word)] = Some((word, after_backslash, spelled));
    }

    fn clear(&mut self) {
        self.slots = [None; RECENT_SLOTS];
    }
}

impl<'a> Formatter<'a> {
    fn new(text: &'a str, config: &'a Config, declared: Declared, chunks: Option<ToVerifier>) -> Formatter<'a> {
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
            groups: Vec::new(),
            ascii: text.is_ascii(),
            open: Vec::new(),
            checked: 0,
            chunks,
            chunk_pieces: Vec::new(),
            failure: None,
            outline: None,
            respelled: FxHashSet::default(),
            again: None,
            recent: Recent::new(),
        }
    }

    /// Checks what was written since the last check against the pieces laid out, or
    /// sends it to the verifier once a chunk has gathered.
    fn verify(&mut self, pieces: &[Piece]) {
        if self.chunks.is_some() {
            self.chunk_pieces.extend_from_slice(pieces);
            if self.out.len() - self.checked >= CHUNK_BYTES {
                self.send_chunk();
            }
            return;
        }
        if self.failure.is_none() {
            if let Err(refusal) = verify::stretch(self.text, pieces, &self.out, self.checked) {
                self.failure = Some(refusal);
            }
        }
        self.checked = self.out.len();
    }

    /// Sends the output not yet verified, with its pieces, to the verifier.
    fn send_chunk(&mut self) {
        let Some(to) = &self.chunks else { return };
        let (spare_pieces, mut output) = to.spare.try_recv().unwrap_or_default();
        output.push_str(&self.out[self.checked..]);
        let pieces = std::mem::replace(&mut self.chunk_pieces, spare_pieces);
        if to.chunks.send((pieces, output)).is_err() && self.failure.is_none() {
            self.failure = Some(Refusal::Unsafe { offset: 0, message: "the check stopped".into() });
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

    fn finish(mut self) -> Laid {
        if !self.unit.pieces.is_empty() && self.failure.is_none() {
            self.flush();
        }
        if self.failure.is_none() {
            self.take_outline(true);
        }
        if self.chunks.is_some() {
            self.send_chunk();
            self.chunks = None;
        }
        if let Some(declared) = self.again {
            return Laid::Again(declared);
        }
        if let Some(refusal) = self.failure {
            return Laid::Done(Err(refusal));
        }
        if !self.out.is_empty() {
            self.out.push_str(self.nl);
        }
        Laid::Done(Ok(self.out))
    }

    /// Takes the outline's names if they have come (or, with `wait`, once they come).
    fn take_outline(&mut self, wait: bool) {
        let Some(outline) = &self.outline else { return };
        let received = if wait { outline.recv().map_err(|_| TryRecvError::Disconnected) } else { outline.try_recv() };
        let mut declared = match received {
            Ok(declared) => declared,
            Err(TryRecvError::Empty) => return,
            Err(TryRecvError::Disconnected) => {
                // The outline has errors: the file is refused for them.
                self.outline = None;
                self.failure = Some(Refusal::Unsafe { offset: 0, message: "the outline failed".into() });
                return;
            }
        };
        self.outline = None;
        if self.respelled.iter().any(|name| declared.contains(name)) {
            self.again = Some(declared);
            self.failure = Some(Refusal::Unsafe { offset: 0, message: "the layout starts again".into() });
            return;
        }
        self.respelled = FxHashSet::default();
        // The routines' names noted so far, and the outline's.
        declared.merge(std::mem::take(&mut self.declared));
        self.declared = declared;
        self.recent.clear();
    }

    /// Starts a line at `indent` after `newlines` line ends in the input.
    fn start_line(&mut self, newlines: u32, indent: usize) {
        if !self.out.is_empty() {
            let blank = (newlines.saturating_sub(1) as usize).min(self.config.max_blank_lines);
            for _ in 0..=blank {
                self.out.push_str(self.nl);
            }
        }
        crate::wrap::push_spaces(&mut self.out, indent);
    }

    fn comment_line(&mut self, piece: Piece, level: usize) {
        self.start_line(piece.newlines, level * self.config.indent_width);
        self.out.push_str(piece.span.text(self.text));
    }

    /// Writes the gathered unit and the comments after it.
    fn flush(&mut self) {
        if self.outline.is_some() {
            self.take_outline(false);
        }
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
            self.recent.clear();
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
        let mut shape = Shape::default();
        let mut prev: Option<T> = None;
        let mut prev_end = pieces[0].span.start as usize;
        let mut first_width = 0;
        for piece in pieces {
            let atom = match piece.kind {
                Some(kind) => {
                    let depth = to_u32(spacer.open.len());
                    let space = spacer.push(kind);
                    if space {
                        self.scratch.push(' ');
                    }
                    let start = self.scratch.len();
                    self.token_text(kind, piece.span, prev, is_header);
                    let end = self.scratch.len();
                    let text_width = if self.ascii { end - start } else { width_of(&self.scratch[start..end]) };
                    if prev.is_none() {
                        first_width = text_width;
                    }
                    prev = Some(kind);
                    let (comma, opens, closes) = match kind {
                        T::Comma => (true, false, false),
                        T::LParen | T::LBracket | T::LBrace => (false, true, false),
                        T::RParen | T::RBracket | T::RBrace => (false, false, true),
                        _ => (false, false, false),
                    };
                    let depth = if closes { depth.saturating_sub(1) } else { depth };
                    let kind = AtomKind::Token { depth, comma, opens, closes };
                    Atom { start: to_u32(start), width: to_u32(text_width + usize::from(space)), space, kind }
                }
                None => {
                    let start = self.scratch.len();
                    let kind = if piece.newlines == 0 {
                        let gap = &self.text[prev_end..piece.span.start as usize];
                        let gap =
                            if !gap.is_empty() && gap.bytes().all(|b| b == b' ' || b == b'\t') { gap } else { " " };
                        self.scratch.push_str(gap);
                        AtomKind::Trailing
                    } else {
                        AtomKind::OwnLine
                    };
                    self.scratch.push_str(piece.span.text(self.text));
                    let end = self.scratch.len();
                    Atom { start: to_u32(start), width: to_u32(self.width(start, end)), space: false, kind }
                }
            };
            shape.add(&atom);
            self.atoms.push(atom);
            prev_end = piece.span.end as usize;
        }
        let is_call = head == T::Ident && !is_decl;
        let outer = if is_call { indent + first_width + 1 } else { indent + 2 * self.config.indent_width };
        let frame = Frame { indent, outer, nl: self.nl };
        let stmt = Statement { atoms: &self.atoms, scratch: &self.scratch, shape };
        lay_out(&mut self.out, frame, stmt, &mut self.groups, self.config);
        self.open = spacer.open;
    }

    /// Columns `scratch[start..end]` takes.
    fn width(&self, start: usize, end: usize) -> usize {
        if self.ascii {
            end - start
        } else {
            width_of(&self.scratch[start..end])
        }
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
            let spelled = match self.recent.get(word, argument_name) {
                Some(spelled) => spelled,
                None => {
                    let spelled = self.spellings.get(word, argument_name).filter(|_| !self.declared.contains(word));
                    self.recent.put(word, argument_name, spelled);
                    spelled
                }
            };
            if let Some(spelled) = spelled {
                if self.outline.is_some() {
                    self.respelled.insert(spelled);
                }
                self.scratch.push_str(spelled);
                return;
            }
        }
        match word.as_bytes() {
            // Most tokens are one byte of punctuation (a one-byte text is ASCII): pushed
            // as a character, not copied by a call.
            &[byte] => self.scratch.push(char::from(byte)),
            _ => self.scratch.push_str(word),
        }
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
