//! rapid-fmt: the RAPID formatter. Text in, text out, plus a [`Config`].
//!
//! The formatter works on the lexer's token stream with the comments beside it, so it
//! can only change what lies between tokens: whitespace, line breaks, and the letter
//! case of reserved words and built-in names (RAPID compares both ignoring case).
//! Layout follows what RobotStudio's RAPID editor writes (`docs/fmt.md` gives the
//! rules and the evidence): one statement per line, four spaces per block level,
//! reserved words in upper case, built-in names spelled as the catalogue declares
//! them, long argument lists and aggregates wrapped at commas.
//!
//! A file with any syntax error is refused, never changed ([`Refusal::SyntaxErrors`]).
//! Every result is verified before it is returned: lexed again, it must give the same
//! tokens (reserved words and names equal ignoring case) and the same comments, in
//! order; otherwise the file is refused too ([`Refusal::Unsafe`]).
//!
//! Invariant: no IO, no diagnostics rendering, no knowledge of files or encodings
//! beyond the line ends found in the text.

mod layout;
mod names;
mod spacing;
mod syntax;
mod verify;
mod wrap;

use rapid_syntax::SyntaxError;

/// How to lay out RAPID (`rapid.toml` `[fmt]`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Config {
    /// Spaces per block level (RobotStudio: 4; modules saved by the controller use 2).
    pub indent_width: usize,
    /// Statements longer than this many characters are wrapped at commas; 0 never wraps.
    pub max_width: usize,
    /// Runs of blank lines are kept up to this many.
    pub max_blank_lines: usize,
    /// A space after each comma inside aggregates and array indexes (`[1, 0, 0, 0]`);
    /// RobotStudio writes none (`[1,0,0,0]`).
    pub aggregate_spaces: bool,
}

impl Default for Config {
    fn default() -> Config {
        Config { indent_width: 4, max_width: 120, max_blank_lines: 2, aggregate_spaces: false }
    }
}

/// Why a text was not formatted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Refusal {
    /// The text has syntax errors (sorted by position); formatting it could change
    /// what it means, so it is left as it is.
    SyntaxErrors(Vec<SyntaxError>),
    /// The layout would have changed a token or a comment (a formatter bug); the text
    /// is left as it is. `offset` is where the output first differs, in the input.
    Unsafe { offset: u32, message: String },
}

/// Formats one module's text. `Ok` holds the new text (equal to `text` when nothing
/// changes).
pub fn format(text: &str, config: &Config) -> Result<String, Refusal> {
    if text.len() >= PARALLEL_THRESHOLD {
        return format_long(text, config);
    }
    let outline = syntax::outline(text).map_err(Refusal::SyntaxErrors)?;
    let body_errors = syntax::body_errors(text, outline.bodies);
    if !body_errors.is_empty() {
        return Err(Refusal::SyntaxErrors(body_errors));
    }
    layout::format(text, config, outline.declared, layout::Threads::One)
}

/// A long file (CAM output) keeps two cores busy: one thread parses the outline, then
/// the routine bodies, for syntax errors, while the layout starts at once (with the
/// outline's names once they come, `layout::format_before_outline`). The refusals
/// are those of [`format`] on one thread, in the same order: the outline's errors,
/// then the bodies', then an unsafe layout.
fn format_long(text: &str, config: &Config) -> Result<String, Refusal> {
    let threads = layout::Threads::for_long_file();
    let (parsed, laid) = std::thread::scope(|scope| {
        let (send_names, names) = std::sync::mpsc::sync_channel(1);
        let parser = scope.spawn(move || {
            let outline = syntax::outline(text)?;
            // The layout may have stopped already: then it needs no names.
            let _ = send_names.send(outline.declared);
            match syntax::body_errors(text, outline.bodies) {
                errors if errors.is_empty() => Ok(()),
                errors => Err(errors),
            }
        });
        let laid = layout::format_before_outline(text, config, names, threads);
        let parsed = parser.join().unwrap_or_else(|_| {
            Err(vec![SyntaxError {
                kind: rapid_syntax::SyntaxErrorKind::UnexpectedToken,
                span: rapid_syntax::Span::new(0, 0),
                message: "the parser failed".into(),
            }])
        });
        (parsed, laid)
    });
    parsed.map_err(Refusal::SyntaxErrors)?;
    match laid {
        layout::Laid::Done(out) => out,
        layout::Laid::Again(declared) => layout::format(text, config, declared, threads),
    }
}

/// Files at least this long are parsed on a second thread.
const PARALLEL_THRESHOLD: usize = 1 << 20;

#[cfg(test)]
mod tests;
