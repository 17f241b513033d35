//! Code actions for common findings: declare missing data with the type its first
//! assignment gives it (E0201), replace a misspelled name by the nearest one in scope
//! of the right sort (E0201, W0202, W0203, E0204), add a missing END keyword (E0121).

use std::collections::HashMap;

use lsp_types::{CodeAction, CodeActionKind, Diagnostic, NumberOrString, Position, Range, TextEdit, WorkspaceEdit};
use rapid_lib::catalogue::EntryKind;
use rapid_syntax::token::TokenKind;

use super::{Target, TaskIndex};
use crate::builtins;
use crate::index::{fold, Kind};

/// The sort of name a finding is about, for choosing replacements.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Sort {
    Data,
    Proc,
    Func,
    Type,
}

pub(crate) fn actions(ti: &TaskIndex, file: usize, diagnostics: &[Diagnostic]) -> Vec<CodeAction> {
    let mut out = Vec::new();
    for diag in diagnostics {
        let Some(NumberOrString::String(code)) = &diag.code else { continue };
        let sort = match code.as_str() {
            "E0201" => Sort::Data,
            "W0202" => Sort::Proc,
            "W0203" => Sort::Func,
            "E0204" => Sort::Type,
            "E0121" => {
                out.extend(close_block(ti, file, diag));
                continue;
            }
            _ => continue,
        };
        let start = ti.offset(file, diag.range.start);
        let end = ti.offset(file, diag.range.end);
        let name = ti.text(file).get(start as usize..end as usize).unwrap_or("").to_owned();
        if name.is_empty() {
            continue;
        }
        if sort == Sort::Data {
            out.extend(declare(ti, file, diag, &name, start));
        }
        if let Some(best) = nearest(ti, file, start, &name, sort) {
            let edit = TextEdit { range: diag.range, new_text: best.clone() };
            out.push(action(format!("Change to `{best}`"), ti, file, vec![edit], diag));
        }
    }
    out
}

fn action(title: String, ti: &TaskIndex, file: usize, edits: Vec<TextEdit>, diag: &Diagnostic) -> CodeAction {
    let changes = HashMap::from([(ti.task.uris[file].clone(), edits)]);
    CodeAction {
        title,
        kind: Some(CodeActionKind::QUICKFIX),
        diagnostics: Some(vec![diag.clone()]),
        edit: Some(WorkspaceEdit { changes: Some(changes), ..WorkspaceEdit::default() }),
        ..CodeAction::default()
    }
}

/// `VAR type name;` at the top of the routine the name is used in.
fn declare(ti: &TaskIndex, file: usize, diag: &Diagnostic, name: &str, offset: u32) -> Option<CodeAction> {
    let index = &ti.files[file];
    let routine = ti.decl(file, index.routine_at(offset)?);
    let text = ti.text(file);
    let ty = inferred_type(ti, file, offset).unwrap_or_else(|| "num".to_owned());
    // After the header's line, indented one level deeper than the header.
    let header = ti.range(file, routine.span).start;
    let line_start = ti.offset(file, Position { line: header.line, character: 0 }) as usize;
    let indent: String = text[line_start..].chars().take_while(|c| *c == ' ' || *c == '\t').collect();
    let at = Position { line: header.line + 1, character: 0 };
    let edit = TextEdit { range: Range { start: at, end: at }, new_text: format!("{indent}  VAR {ty} {name};\n") };
    Some(action(format!("Declare `VAR {ty} {name}`"), ti, file, vec![edit], diag))
}

/// The type of the value assigned to the name at `offset` (`name := value`): a
/// literal's, or a name's or function's as declared.
fn inferred_type(ti: &TaskIndex, file: usize, offset: u32) -> Option<String> {
    let index = &ti.files[file];
    let text = ti.text(file);
    let at = index.tokens.partition_point(|t| t.span.start < offset);
    if index.tokens.get(at + 1)?.kind != TokenKind::Assign {
        return None;
    }
    let value = index.tokens.get(at + 2)?;
    match value.kind {
        TokenKind::Num => Some("num".into()),
        TokenKind::Str => Some("string".into()),
        TokenKind::True | TokenKind::False => Some("bool".into()),
        TokenKind::Ident => match ti.lookup(file, value.span.start, &fold(value.span.text(text)))? {
            Target::User { file, decl } => ti.decl(file, decl).ty.clone(),
            Target::Signal(_) | Target::BuiltinComponent { .. } => None,
            Target::Builtin(b) => b.ty.clone(),
        },
        _ => None,
    }
}

/// The name in scope nearest to `name` (at most two edits away, and fewer than half
/// its letters), of the sort the finding wants.
fn nearest(ti: &TaskIndex, file: usize, offset: u32, name: &str, sort: Sort) -> Option<String> {
    let wanted = fold(name);
    let limit = 2.min(wanted.chars().count().saturating_sub(1) / 2).max(1);
    let mut best: Option<(usize, String)> = None;
    let mut consider = |candidate: &str| {
        let distance = edit_distance(&wanted, &fold(candidate));
        if distance > 0 && distance <= limit && best.as_ref().is_none_or(|(d, _)| distance < *d) {
            best = Some((distance, candidate.to_owned()));
        }
    };
    let index = &ti.files[file];
    if let Some(routine) = index.routine_at(offset) {
        for (_, decl) in index.locals(routine).filter(|(_, d)| d.visible_at(offset)) {
            if sort == Sort::Data {
                consider(&decl.name);
            }
        }
    }
    let module = index.module_at(offset);
    for (f, fi) in ti.files.iter().enumerate() {
        for decl in fi.decls.iter().filter(|d| d.routine.is_none()) {
            let visible = !decl.local || (f == file && Some(decl.module) == module);
            let fits = match sort {
                Sort::Data => matches!(decl.kind, Kind::Var | Kind::Pers | Kind::Const),
                Sort::Proc => decl.kind == Kind::Proc,
                Sort::Func => decl.kind == Kind::Func,
                Sort::Type => matches!(decl.kind, Kind::Record | Kind::Alias),
            };
            if visible && fits {
                consider(&decl.name);
            }
        }
    }
    if sort == Sort::Data {
        for signal in &ti.task.options.predefined {
            consider(&signal.name);
        }
    }
    for builtin in builtins::table().values() {
        let fits = match (sort, builtin.kind) {
            (Sort::Data, EntryKind::Data | EntryKind::ReadOnlyData) => true,
            (Sort::Proc, EntryKind::Routine) => !builtin.is_func,
            (Sort::Func, EntryKind::Routine) => builtin.is_func,
            (Sort::Type, kind) => !matches!(kind, EntryKind::Routine | EntryKind::Data | EntryKind::ReadOnlyData),
            _ => false,
        };
        if fits {
            consider(&builtin.name);
        }
    }
    best.map(|(_, name)| name)
}

/// Levenshtein distance over characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cost = usize::from(ca != cb);
            let next = (row[j + 1] + 1).min(row[j] + 1).min(prev + cost);
            prev = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// `ENDIF` (or ENDFOR, ENDWHILE, ENDTEST) for "IF has no ENDIF": on its own line
/// before the end of the routine, indented as the opening keyword.
fn close_block(ti: &TaskIndex, file: usize, diag: &Diagnostic) -> Option<CodeAction> {
    let word = diag.message.rsplit(' ').next()?;
    if !matches!(word, "ENDIF" | "ENDFOR" | "ENDWHILE" | "ENDTEST") {
        return None;
    }
    let offset = ti.offset(file, diag.range.start);
    let routine = ti.decl(file, ti.files[file].routine_at(offset)?);
    let text = ti.text(file);
    let opening_line = ti.offset(file, Position { line: diag.range.start.line, character: 0 }) as usize;
    let indent: String = text[opening_line..].chars().take_while(|c| *c == ' ' || *c == '\t').collect();
    // The line of the routine's END keyword.
    let end_line = ti.range(file, routine.span).end.line;
    let at = Position { line: end_line, character: 0 };
    let edit = TextEdit { range: Range { start: at, end: at }, new_text: format!("{indent}{word}\n") };
    Some(action(format!("Add the missing {word}"), ti, file, vec![edit], diag))
}

#[cfg(test)]
mod tests {
    use super::edit_distance;

    #[test]
    fn edit_distance_counts_single_character_edits() {
        assert_eq!(edit_distance("counter", "countr"), 1);
        assert_eq!(edit_distance("abc", "acb"), 2);
        assert_eq!(edit_distance("", "ab"), 2);
    }
}
