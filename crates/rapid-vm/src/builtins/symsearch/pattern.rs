//! The controller's regular expressions for data names (SetDataSearch and SetAllDataVal
//! `\Object`): `.` any character, `[s]` / `[^s]` a character in / not in a set (ranges
//! `a-z`), `r*`, `r+`, `r?`, `(r)` and `r|r'`. A pattern must match the whole name,
//! letters in either case (RAPID names ignore case).
//!
//! We match by following every position a pattern can reach at once (a set of end
//! positions per sub-pattern), so no pattern takes time exponential in the name: the
//! work is bounded by pattern size times name length squared.

/// A parsed pattern: alternatives of sequences of repeated atoms.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Pattern(Alt);

#[derive(Debug, Clone, PartialEq, Eq)]
struct Alt(Vec<Vec<Piece>>);

#[derive(Debug, Clone, PartialEq, Eq)]
struct Piece {
    atom: Atom,
    /// How often the atom must occur: 0 (`*`, `?`) or 1.
    min: u8,
    /// Any number of further occurrences (`*`, `+`); else none beyond `min`, except
    /// that `?` (min 0) allows one.
    many: bool,
}

#[derive(Debug, Clone, PartialEq, Eq)]
enum Atom {
    Char(char),
    Any,
    Class { negated: bool, ranges: Vec<(char, char)> },
    Group(Alt),
}

/// Why a pattern is not one.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct PatternFault(pub(crate) String);

impl Pattern {
    // uncertain: the manual lists the operators above; `^` at the start and `$` at the
    // end are taken as the anchors they usually are (the match is anchored anyway), and
    // `\c` as the character c.
    pub(crate) fn parse(text: &str) -> Result<Pattern, PatternFault> {
        let body = text.strip_prefix('^').unwrap_or(text);
        let body = body.strip_suffix('$').filter(|b| !b.ends_with('\\')).unwrap_or(body);
        let chars: Vec<char> = body.chars().collect();
        let mut parser = Parser { chars: &chars, at: 0 };
        let alt = parser.alt()?;
        if parser.at < chars.len() {
            return Err(PatternFault(format!("unmatched `)` in `{text}`")));
        }
        Ok(Pattern(alt))
    }

    /// Whether the pattern matches all of `name`.
    pub(crate) fn matches(&self, name: &str) -> bool {
        let chars: Vec<char> = name.chars().collect();
        let mut start = vec![false; chars.len() + 1];
        start[0] = true;
        ends_alt(&self.0, &chars, &start)[chars.len()]
    }
}

struct Parser<'a> {
    chars: &'a [char],
    at: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<char> {
        self.chars.get(self.at).copied()
    }

    fn alt(&mut self) -> Result<Alt, PatternFault> {
        let mut branches = vec![self.seq()?];
        while self.peek() == Some('|') {
            self.at += 1;
            branches.push(self.seq()?);
        }
        Ok(Alt(branches))
    }

    fn seq(&mut self) -> Result<Vec<Piece>, PatternFault> {
        let mut pieces = Vec::new();
        while let Some(c) = self.peek() {
            if c == '|' || c == ')' {
                break;
            }
            let atom = self.atom()?;
            let (min, many) = match self.peek() {
                Some('*') => (0, true),
                Some('+') => (1, true),
                Some('?') => (0, false),
                _ => (1, false),
            };
            if matches!(self.peek(), Some('*' | '+' | '?')) {
                self.at += 1;
            }
            pieces.push(Piece { atom, min, many });
        }
        Ok(pieces)
    }

    fn atom(&mut self) -> Result<Atom, PatternFault> {
        let Some(c) = self.peek() else { return Err(PatternFault("the pattern ends too early".into())) };
        self.at += 1;
        match c {
            '.' => Ok(Atom::Any),
            '(' => {
                let inner = self.alt()?;
                if self.peek() != Some(')') {
                    return Err(PatternFault("a `(` is not closed".into()));
                }
                self.at += 1;
                Ok(Atom::Group(inner))
            }
            '[' => self.class(),
            '*' | '+' | '?' => Err(PatternFault(format!("`{c}` repeats nothing"))),
            '\\' => {
                let escaped = self.peek().ok_or_else(|| PatternFault("the pattern ends with `\\`".into()))?;
                self.at += 1;
                Ok(Atom::Char(escaped))
            }
            other => Ok(Atom::Char(other)),
        }
    }

    /// After `[`: the set up to `]` (a `]` first in the set is a member).
    fn class(&mut self) -> Result<Atom, PatternFault> {
        let negated = self.peek() == Some('^');
        if negated {
            self.at += 1;
        }
        let mut ranges = Vec::new();
        let mut first = true;
        loop {
            let Some(c) = self.peek() else { return Err(PatternFault("a `[` is not closed".into())) };
            self.at += 1;
            if c == ']' && !first {
                break;
            }
            first = false;
            let is_range = self.peek() == Some('-') && self.chars.get(self.at + 1).is_some_and(|&n| n != ']');
            if is_range {
                let hi = self.chars[self.at + 1];
                self.at += 2;
                ranges.push((c, hi));
            } else {
                ranges.push((c, c));
            }
        }
        if ranges.is_empty() {
            return Err(PatternFault("an empty set `[]`".into()));
        }
        Ok(Atom::Class { negated, ranges })
    }
}

// ---- matching: sets of end positions ----------------------------------------------------------

/// Every position an alternative can end at, starting from any position set in `start`.
fn ends_alt(alt: &Alt, name: &[char], start: &[bool]) -> Vec<bool> {
    let mut out = vec![false; start.len()];
    for branch in &alt.0 {
        let mut at = start.to_vec();
        for piece in branch {
            at = ends_piece(piece, name, &at);
        }
        or_into(&mut out, &at);
    }
    out
}

fn ends_piece(piece: &Piece, name: &[char], start: &[bool]) -> Vec<bool> {
    let mut reached = if piece.min == 0 { start.to_vec() } else { ends_atom(&piece.atom, name, start) };
    if !piece.many {
        if piece.min == 0 {
            or_into(&mut reached, &ends_atom(&piece.atom, name, start));
        }
        return reached;
    }
    // Repeat until no new position is reached: at most name length + 1 rounds.
    let mut frontier = reached.clone();
    while frontier.iter().any(|&b| b) {
        let next = ends_atom(&piece.atom, name, &frontier);
        frontier = next.iter().zip(&reached).map(|(&n, &r)| n && !r).collect();
        or_into(&mut reached, &next);
    }
    reached
}

fn ends_atom(atom: &Atom, name: &[char], start: &[bool]) -> Vec<bool> {
    if let Atom::Group(alt) = atom {
        return ends_alt(alt, name, start);
    }
    let mut out = vec![false; start.len()];
    for (pos, &c) in name.iter().enumerate() {
        if start[pos] && atom_takes(atom, c) {
            out[pos + 1] = true;
        }
    }
    out
}

/// Whether a one-character atom matches `c`, ignoring letter case.
fn atom_takes(atom: &Atom, c: char) -> bool {
    let (lower, upper) = cases(c);
    match atom {
        Atom::Char(p) => cases(*p).0 == lower,
        Atom::Any => true,
        Atom::Class { negated, ranges } => {
            let hit = ranges.iter().any(|&(lo, hi)| (lo..=hi).contains(&lower) || (lo..=hi).contains(&upper));
            hit != *negated
        }
        Atom::Group(_) => false,
    }
}

/// The lower- and upper-case forms of a (Latin-1) character, where it has exactly one.
fn cases(c: char) -> (char, char) {
    let lower = single(c.to_lowercase()).unwrap_or(c);
    let upper = single(c.to_uppercase()).unwrap_or(c);
    (lower, upper)
}

fn single(mut it: impl Iterator<Item = char>) -> Option<char> {
    let first = it.next()?;
    it.next().is_none().then_some(first)
}

fn or_into(into: &mut [bool], from: &[bool]) {
    for (a, &b) in into.iter_mut().zip(from) {
        *a |= b;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(pattern: &str, name: &str) -> bool {
        Pattern::parse(pattern).expect("a pattern").matches(name)
    }

    #[test]
    fn whole_name_any_case() {
        assert!(m("my.*", "my_flag"));
        assert!(m("my.*", "MYFLAG"));
        assert!(!m("my.*", "the_myflag"));
        assert!(m("reg1", "REG1"));
        assert!(!m("reg", "reg1"));
        assert!(m("^reg[0-9]$", "reg7"));
    }

    #[test]
    fn operators() {
        assert!(m("reg[0-9]+", "reg12"));
        assert!(!m("reg[0-9]+", "reg"));
        assert!(m("reg[^0-9]", "regx"));
        assert!(!m("reg[^0-9]", "reg5"));
        assert!(m("ab?c", "ac"));
        assert!(m("ab?c", "abc"));
        assert!(!m("ab?c", "abbc"));
        assert!(m("(p|q)x*", "qxxx"));
        assert!(m("p1|q2", "q2"));
        assert!(m("(ab)*", ""));
        assert!(m("(ab)*", "abab"));
        assert!(!m("(ab)*", "aba"));
        assert!(m("[a-c_]+", "a_B_c"));
        assert!(m("()*x", "x"));
    }

    #[test]
    fn no_blow_up_on_nested_stars() {
        let name = "a".repeat(32) + "b";
        assert!(!m("(a*)*c", &name));
        assert!(m("(a|aa)*b", &name));
    }

    #[test]
    fn faults() {
        assert!(Pattern::parse("(ab").is_err());
        assert!(Pattern::parse("ab)").is_err());
        assert!(Pattern::parse("*a").is_err());
        assert!(Pattern::parse("[ab").is_err());
    }
}
