//! Laying out one statement on one or more lines.
//!
//! A statement that fits in `max_width` columns stays on one line. A longer one is
//! broken after commas of the outermost level that has commas (the arguments of a call,
//! else the elements of the outermost aggregate), filling each line as far as it goes;
//! a continuation line starts under the first character inside the bracket the break
//! is in (as the controller lays out `tool0` in BASE.sys), or after the instruction
//! name for arguments of a call, or two levels in when that column is too far right.
//! A comment inside a statement ends its line; the statement goes on below it.
//!
//! The layout depends on the tokens and comments alone, never on how the input was
//! broken, so formatting twice gives what formatting once gave.

use crate::Config;

/// What one atom of a statement is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum AtomKind {
    /// A token; `depth` is the number of brackets open before it.
    Token { depth: u32, comma: bool, opens: bool, closes: bool },
    /// A comment after a token on its line (its text includes the gap before it).
    Trailing,
    /// A comment on a line of its own inside the statement.
    OwnLine,
}

/// One token or comment, its text in the statement's scratch buffer. The scratch
/// buffer holds the statement laid out flat: each atom's text, after one space where
/// `space` says so (the space is at `start - 1`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Atom {
    /// Where its text starts (it ends where the next atom starts). Kept small: a
    /// CAM module has tens of millions of atoms.
    pub(crate) start: u32,
    /// Columns it takes, with the space before it.
    pub(crate) width: u32,
    pub(crate) space: bool,
    pub(crate) kind: AtomKind,
}

/// What the whole statement is like, gathered as its atoms are made.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Shape {
    /// Columns the statement takes on one line.
    pub(crate) width: usize,
    pub(crate) has_comment: bool,
    /// The shallowest depth at which the statement has commas.
    pub(crate) comma_depth: Option<u32>,
}

impl Shape {
    /// Takes an atom into account.
    pub(crate) fn add(&mut self, atom: &Atom) {
        self.width += atom.width as usize;
        match atom.kind {
            AtomKind::Token { depth, comma: true, .. } => {
                self.comma_depth = Some(self.comma_depth.map_or(depth, |d| d.min(depth)));
            }
            AtomKind::Token { .. } => {}
            AtomKind::Trailing | AtomKind::OwnLine => self.has_comment = true,
        }
    }
}

/// Where a statement starts and how its continuation lines are indented.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame<'n> {
    pub(crate) indent: usize,
    /// Continuation column outside any bracket (after a call's instruction name).
    pub(crate) outer: usize,
    pub(crate) nl: &'n str,
}

/// A statement ready to be written: its atoms, their text laid out flat, its shape.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Statement<'s> {
    pub(crate) atoms: &'s [Atom],
    pub(crate) scratch: &'s str,
    pub(crate) shape: Shape,
}

/// Writes the atoms of one statement at the end of `out` (the line is started and
/// indented already). `groups` is a recycled stack. The flat text is copied in runs,
/// from one line break to the next.
pub(crate) fn lay_out(
    out: &mut String,
    frame: Frame<'_>,
    stmt: Statement<'_>,
    groups: &mut Vec<usize>,
    config: &Config,
) {
    let Statement { atoms, scratch, shape } = stmt;
    let too_long = config.max_width > 0 && frame.indent + shape.width > config.max_width;
    if !shape.has_comment && !too_long {
        out.push_str(scratch);
        return;
    }
    let break_depth = if too_long { shape.comma_depth } else { None };
    let mut col = frame.indent;
    groups.clear();
    let mut pending: Option<usize> = None;
    // The flat text before `run` is written.
    let mut run = 0;
    for (idx, atom) in atoms.iter().enumerate() {
        let (start, width) = (atom.start as usize, atom.width as usize);
        match atom.kind {
            AtomKind::Token { depth, comma, opens, closes } => {
                if let Some(cont) = pending.take() {
                    // The new line replaces the space before the atom.
                    out.push_str(&scratch[run..start - usize::from(atom.space)]);
                    col = new_line(out, frame.nl, cont);
                    run = start;
                } else if atom.space {
                    col += 1;
                }
                col += width - usize::from(atom.space);
                if opens {
                    groups.push(col);
                }
                if closes {
                    groups.pop();
                }
                let at_break_depth = comma && break_depth == Some(depth);
                if at_break_depth && col + segment_width(&atoms[idx + 1..], depth) > config.max_width {
                    pending = Some(continuation(groups, frame, config));
                }
            }
            AtomKind::Trailing => {
                if let Some(cont) = pending.take() {
                    out.push_str(&scratch[run..start]);
                    col = new_line(out, frame.nl, cont);
                    run = start;
                }
                col += width;
                pending = Some(continuation(groups, frame, config));
            }
            AtomKind::OwnLine => {
                let cont = pending.take().unwrap_or_else(|| continuation(groups, frame, config));
                if idx > 0 {
                    out.push_str(&scratch[run..start]);
                    new_line(out, frame.nl, cont);
                    run = start;
                }
                pending = Some(cont);
            }
        }
    }
    out.push_str(&scratch[run..]);
}

fn new_line(out: &mut String, nl: &str, col: usize) -> usize {
    out.push_str(nl);
    push_spaces(out, col);
    col
}

/// Appends `n` spaces.
pub(crate) fn push_spaces(out: &mut String, n: usize) {
    const SPACES: &str = "                                                                ";
    let mut left = n;
    while left > 0 {
        let now = left.min(SPACES.len());
        out.push_str(&SPACES[..now]);
        left -= now;
    }
}
/// The width of what follows a comma up to the next comma at `depth` or shallower
/// (or the end), with the spaces before its atoms.
fn segment_width(rest: &[Atom], depth: u32) -> usize {
    let mut width = 0;
    for atom in rest {
        if let AtomKind::Token { depth: d, comma: true, .. } = atom.kind {
            if d <= depth {
                // The comma itself stays on this line.
                return width + 1;
            }
        }
        if matches!(atom.kind, AtomKind::Token { .. }) {
            width += atom.width as usize;
        }
    }
    width
}

/// Where a continuation line starts: inside the innermost open bracket, or at the
/// frame's outer column; two levels in when that is past half the width.
fn continuation(groups: &[usize], frame: Frame<'_>, config: &Config) -> usize {
    let col = groups.last().copied().unwrap_or(frame.outer);
    let limit = if config.max_width > 0 { config.max_width / 2 } else { 60 };
    if col > limit {
        frame.indent + 2 * config.indent_width
    } else {
        col
    }
}
