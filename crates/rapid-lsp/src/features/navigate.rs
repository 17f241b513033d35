//! Go to definition, find references and rename, across the modules of a task.

use std::collections::HashMap;

use lsp_types::{Location, Position, TextEdit, Uri, WorkspaceEdit};

use super::{Target, TaskIndex};

/// What the name at `pos` of `file` denotes.
pub(crate) fn target_at(ti: &TaskIndex, file: usize, pos: Position) -> Option<Target<'static>> {
    let offset = ti.offset(file, pos);
    let ident = ti.files[file].ident_at(offset)?;
    ti.resolve(file, ident)
}

/// Where the name at `pos` is declared (built-ins and signals have no place in the
/// workspace).
pub(crate) fn definition(ti: &TaskIndex, file: usize, pos: Position) -> Option<Location> {
    match target_at(ti, file, pos)? {
        Target::User { file, decl } => Some(ti.location(file, ti.decl(file, decl).name_span)),
        Target::Signal(_) | Target::Builtin(_) | Target::BuiltinComponent { .. } => None,
    }
}

/// Every place the task names what the name at `pos` denotes.
pub(crate) fn references(ti: &TaskIndex, file: usize, pos: Position, with_declaration: bool) -> Vec<Location> {
    let Some(target) = target_at(ti, file, pos) else { return Vec::new() };
    let declared = match target {
        Target::User { file, decl } => Some((file, ti.decl(file, decl).name_span)),
        _ => None,
    };
    ti.references(target)
        .into_iter()
        .filter(|&place| with_declaration || Some(place) != declared)
        .map(|(file, span)| ti.location(file, span))
        .collect()
}

/// Renames a user declaration everywhere the task names it. Built-ins, signals and
/// names that are not RAPID identifiers are refused with a reason.
pub(crate) fn rename(ti: &TaskIndex, file: usize, pos: Position, new_name: &str) -> Result<WorkspaceEdit, String> {
    let Some(target) = target_at(ti, file, pos) else { return Err("no name here".into()) };
    if !matches!(target, Target::User { .. }) {
        return Err("only names this workspace declares can be renamed".into());
    }
    check_identifier(new_name)?;
    let mut changes: HashMap<Uri, Vec<TextEdit>> = HashMap::new();
    for (file, span) in ti.references(target) {
        let edit = TextEdit { range: ti.range(file, span), new_text: new_name.to_owned() };
        changes.entry(ti.task.uris[file].clone()).or_default().push(edit);
    }
    Ok(WorkspaceEdit { changes: Some(changes), ..WorkspaceEdit::default() })
}

/// A RAPID identifier (§1.1.2): a letter, then letters, digits and `_`, at most 32
/// characters, not a reserved word.
pub(crate) fn check_identifier(name: &str) -> Result<(), String> {
    let mut chars = name.chars();
    let first_ok = chars.next().is_some_and(rapid_syntax::lexer::is_letter);
    let rest_ok = chars.all(|c| rapid_syntax::lexer::is_letter(c) || c.is_ascii_digit() || c == '_');
    if !first_ok || !rest_ok {
        return Err(format!("`{name}` is not a RAPID name"));
    }
    if name.chars().count() > rapid_syntax::lexer::MAX_IDENT_CHARS {
        return Err(format!("`{name}` is longer than 32 characters"));
    }
    if rapid_syntax::token::keyword(name).is_some() {
        return Err(format!("`{name}` is a reserved word"));
    }
    Ok(())
}
