//! Document formatting: `rapid fmt`'s layout (crate rapid-fmt) with the options the
//! embedder finds for the file, as one edit of the whole text. A module `rapid fmt`
//! refuses (syntax errors) is refused here too, with its reason.

use lsp_types::{Position, Range, TextEdit};

use crate::position::LineMap;

/// The edits that format `text`: none when it is formatted already.
pub(crate) fn edits(text: &str, config: &rapid_fmt::Config) -> Result<Vec<TextEdit>, String> {
    let formatted = rapid_fmt::format(text, config).map_err(|why| match why {
        rapid_fmt::Refusal::SyntaxErrors(errors) => {
            format!("not formatted: the module has {} syntax error(s); rapid fmt leaves it as it is", errors.len())
        }
        rapid_fmt::Refusal::Unsafe { message, .. } => format!("not formatted: {message}"),
    })?;
    if formatted == text {
        return Ok(Vec::new());
    }
    let end = LineMap::new(text).position(text, text.len() as u32);
    Ok(vec![TextEdit { range: Range { start: Position { line: 0, character: 0 }, end }, new_text: formatted }])
}
