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
    Token { depth: usize, comma: bool, opens: bool, closes: bool },
    /// A comment after a token on its line (its text includes the gap before it).
    Trailing,
    /// A comment on a line of its own inside the statement.
    OwnLine,
}

/// One token or comment, its text in the statement's scratch buffer.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Atom {
    pub(crate) start: usize,
    pub(crate) end: usize,
    /// Columns it takes, with the space before it.
    pub(crate) width: usize,
    pub(crate) space: bool,
    pub(crate) kind: AtomKind,
}

/// Where a statement starts and how its continuation lines are indented.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame<'n> {
    pub(crate) indent: usize,
    /// Continuation column outside any bracket (after a call's instruction name).
    pub(crate) outer: usize,
    pub(crate) nl: &'n str,
}

/// Writes the atoms of one statement at the end of `out` (the line is started and
/// indented already).
pub(crate) fn lay_out(out: &mut String, frame: Frame<'_>, atoms: &[Atom], scratch: &str, config: &Config) {
    let has_comment = atoms.iter().any(|a| !matches!(a.kind, AtomKind::Token { .. }));
    let flat: usize = frame.indent + atoms.iter().map(|a| a.width).sum::<usize>();
    let too_long = config.max_width > 0 && flat > config.max_width;
    if !has_comment && !too_long {
        for atom in atoms {
            write_atom(out, atom, scratch);
        }
        return;
    }
    let break_depth = if too_long { comma_depth(atoms) } else { None };
    let mut col = frame.indent;
    let mut groups: Vec<usize> = Vec::new();
    let mut pending: Option<usize> = None;
    for (idx, atom) in atoms.iter().enumerate() {
        match atom.kind {
            AtomKind::Token { depth, comma, opens, closes } => {
                if let Some(cont) = pending.take() {
                    col = new_line(out, frame.nl, cont);
                } else if atom.space {
                    out.push(' ');
                    col += 1;
                }
                out.push_str(&scratch[atom.start..atom.end]);
                col += atom.width - usize::from(atom.space);
                if opens {
                    groups.push(col);
                }
                if closes {
                    groups.pop();
                }
                let at_break_depth = comma && break_depth == Some(depth);
                if at_break_depth && col + segment_width(&atoms[idx + 1..], depth) > config.max_width {
                    pending = Some(continuation(&groups, frame, config));
                }
            }
            AtomKind::Trailing => {
                if let Some(cont) = pending.take() {
                    col = new_line(out, frame.nl, cont);
                }
                write_atom(out, atom, scratch);
                col += atom.width;
                pending = Some(continuation(&groups, frame, config));
            }
            AtomKind::OwnLine => {
                let cont = pending.take().unwrap_or_else(|| continuation(&groups, frame, config));
                if idx > 0 {
                    new_line(out, frame.nl, cont);
                }
                write_atom(out, atom, scratch);
                pending = Some(cont);
            }
        }
    }
}

fn write_atom(out: &mut String, atom: &Atom, scratch: &str) {
    if atom.space {
        out.push(' ');
    }
    out.push_str(&scratch[atom.start..atom.end]);
}

fn new_line(out: &mut String, nl: &str, col: usize) -> usize {
    out.push_str(nl);
    out.extend(std::iter::repeat_n(' ', col));
    col
}

/// The shallowest depth at which the statement has commas.
fn comma_depth(atoms: &[Atom]) -> Option<usize> {
    atoms
        .iter()
        .filter_map(|a| match a.kind {
            AtomKind::Token { depth, comma: true, .. } => Some(depth),
            _ => None,
        })
        .min()
}

/// The width of what follows a comma up to the next comma at `depth` or shallower
/// (or the end), with the spaces before its atoms.
fn segment_width(rest: &[Atom], depth: usize) -> usize {
    let mut width = 0;
    for atom in rest {
        if let AtomKind::Token { depth: d, comma: true, .. } = atom.kind {
            if d <= depth {
                // The comma itself stays on this line.
                return width + 1;
            }
        }
        if matches!(atom.kind, AtomKind::Token { .. }) {
            width += atom.width;
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
