//! The parse a file must pass before it is formatted: every syntax error of the file
//! (outline and every routine body, as `rapid check --syntax-only` finds them), and
//! the names its outline declares, which keep their spelling. Routine-local names are
//! found by the layout as it goes (`layout.rs`), so the bodies can be parsed on
//! another thread meanwhile.

use rapid_syntax::ast::Item;
use rapid_syntax::{parse_body, parse_outline, Interner, Span, SyntaxError};

use crate::names::Declared;

/// A file's outline: the names it declares and where its routine bodies are.
pub(crate) struct Outline {
    pub(crate) declared: Declared,
    pub(crate) bodies: Bodies,
}

/// The routine bodies still to parse, with the interner of the outline.
pub(crate) struct Bodies {
    interner: Interner,
    spans: Vec<Span>,
}

/// Parses the outline; its syntax errors (sorted) refuse the file.
pub(crate) fn outline(text: &str) -> Result<Outline, Vec<SyntaxError>> {
    let mut interner = Interner::default();
    let outline = parse_outline(text, &mut interner);
    if !outline.errors.is_empty() {
        let mut errors = outline.errors;
        errors.sort_by_key(|e| e.span.start);
        return Err(errors);
    }
    let mut declared = Declared::default();
    let mut spans = Vec::new();
    for module in &outline.file.modules {
        declared.add_outline(module, text);
        for item in &module.items {
            if let Item::Routine(routine) = item {
                spans.push(routine.body_span);
            }
        }
    }
    Ok(Outline { declared, bodies: Bodies { interner, spans } })
}

/// Every syntax error of the routine bodies, sorted by position.
pub(crate) fn body_errors(text: &str, bodies: Bodies) -> Vec<SyntaxError> {
    let Bodies { mut interner, spans } = bodies;
    let mut errors = Vec::new();
    for span in spans {
        errors.extend(parse_body(text, span, &mut interner, None));
    }
    errors.sort_by_key(|e| e.span.start);
    errors
}
