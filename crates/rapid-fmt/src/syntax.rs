//! The parse a file must pass before it is formatted: every syntax error of the file
//! (outline and every routine body, as `rapid check --syntax-only` finds them), and
//! the names it declares, which keep their spelling.

use rapid_syntax::ast::{BodyItem, Item};
use rapid_syntax::{parse_body, parse_outline, Interner, SyntaxError};

use crate::names::Declared;

/// The names `text` declares, or its syntax errors (sorted by position).
pub(crate) fn declared_names(text: &str) -> Result<Declared, Vec<SyntaxError>> {
    let mut interner = Interner::default();
    let outline = parse_outline(text, &mut interner);
    let mut errors = outline.errors;
    let mut declared = Declared::default();
    for module in &outline.file.modules {
        declared.add_outline(module, text);
        for item in &module.items {
            let Item::Routine(routine) = item else { continue };
            let mut sink = |item: BodyItem, arena: &mut rapid_syntax::ast::Arena| {
                if let BodyItem::Decl(decl) = &item {
                    declared.add(decl.name.span.text(text));
                }
                arena.clear();
            };
            errors.extend(parse_body(text, routine.body_span, &mut interner, Some(&mut sink)));
        }
    }
    if errors.is_empty() {
        Ok(declared)
    } else {
        errors.sort_by_key(|e| e.span.start);
        Err(errors)
    }
}
