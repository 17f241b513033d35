//! Completion: the names in scope at the cursor (routine data and parameters, the
//! module's items, the task's globals, the configuration's signals, the built-ins),
//! routines with their required arguments as a snippet, record components after `.`,
//! a call's optional arguments after `\`, and routine names inside a late-binding
//! string (`% "name" %`).

use lsp_types::{
    CompletionItem, CompletionItemKind, CompletionItemLabelDetails, Documentation, InsertTextFormat, MarkupContent,
    MarkupKind, Position,
};
use rapid_lib::catalogue::EntryKind;
use rapid_syntax::token::TokenKind;

use super::signature::{call_at, Signature};
use super::TaskIndex;
use crate::builtins::{self, Builtin};
use crate::index::{fold, Decl, Kind};

pub(crate) fn complete(ti: &TaskIndex, file: usize, pos: Position, snippets: bool) -> Vec<CompletionItem> {
    let index = &ti.files[file];
    let offset = ti.offset(file, pos);
    if index.comments.iter().any(|c| c.start < offset && offset <= c.end) {
        return Vec::new();
    }
    let tokens = &index.tokens;
    // The token the cursor is in or just after, and the one before the word typed.
    let at = tokens.partition_point(|t| t.span.end < offset);
    let in_word = tokens.get(at).filter(|t| t.span.start < offset || (t.span.start == offset && t.span.end > offset));
    if let Some(token) = in_word.filter(|t| t.kind == TokenKind::Str) {
        let late = at > 0 && tokens[at - 1].kind == TokenKind::Percent;
        return if late && token.span.start < offset { routine_names(ti) } else { Vec::new() };
    }
    let word_start = match in_word {
        Some(t) if t.kind == TokenKind::Ident || t.kind.is_keyword() => at,
        _ => tokens.partition_point(|t| t.span.end <= offset),
    };
    let before = word_start.checked_sub(1).map(|b| tokens[b]);
    match before.map(|t| t.kind) {
        Some(TokenKind::Dot) => components_after(ti, file, word_start - 1),
        Some(TokenKind::Backslash) => optional_args(ti, file, offset, snippets),
        _ => in_scope(ti, file, offset, snippets),
    }
    .into_iter()
    .filter(|item| !item.label.is_empty())
    .collect()
}

fn kind_of(kind: Kind) -> CompletionItemKind {
    match kind {
        Kind::Module => CompletionItemKind::MODULE,
        Kind::Record | Kind::Alias => CompletionItemKind::STRUCT,
        Kind::Component => CompletionItemKind::FIELD,
        Kind::Const => CompletionItemKind::CONSTANT,
        Kind::Var | Kind::Pers | Kind::Local | Kind::Param => CompletionItemKind::VARIABLE,
        Kind::Proc => CompletionItemKind::METHOD,
        Kind::Func => CompletionItemKind::FUNCTION,
        Kind::Trap => CompletionItemKind::EVENT,
    }
}

/// Every name visible at `offset` of `file`.
fn in_scope(ti: &TaskIndex, file: usize, offset: u32, snippets: bool) -> Vec<CompletionItem> {
    let index = &ti.files[file];
    let routine = index.routine_at(offset);
    let module = index.module_at(offset);
    let mut items = Vec::new();
    let mut seen = rustc_hash::FxHashSet::default();
    let mut add = |item: CompletionItem, key: String, items: &mut Vec<CompletionItem>| {
        if seen.insert(key) {
            items.push(item);
        }
    };
    if let Some(routine) = routine {
        // A FOR loop variable only inside its loop; an inner loop's before an outer one's.
        let visible = |d: &&Decl| d.routine == Some(routine) && d.visible_at(offset);
        let mut locals: Vec<&Decl> = index.decls.iter().filter(visible).collect();
        locals.sort_by_key(|d| std::cmp::Reverse(d.scope.map(|s| s.start)));
        for decl in locals {
            add(user_item(ti, file, decl), decl.key.clone(), &mut items);
        }
    }
    for (f, fi) in ti.files.iter().enumerate() {
        for (at, decl) in fi.decls.iter().enumerate() {
            let own_module = f == file && Some(decl.module) == module;
            if decl.routine.is_some() || decl.kind == Kind::Component || (decl.local && !own_module) {
                continue;
            }
            let mut item = user_item(ti, f, decl);
            if decl.kind.is_routine() {
                routine_snippet(&mut item, &Signature::of_user(ti, f, at), snippets);
            }
            add(item, decl.key.clone(), &mut items);
        }
    }
    for signal in &ti.task.options.predefined {
        let item = CompletionItem {
            label: signal.name.clone(),
            kind: Some(CompletionItemKind::VARIABLE),
            detail: Some(format!("{} (EIO signal)", signal.type_name)),
            ..CompletionItem::default()
        };
        add(item, fold(&signal.name), &mut items);
    }
    for (key, builtin) in builtins::table() {
        add(builtin_item(builtin, snippets), key.clone(), &mut items);
    }
    items
}

fn user_item(ti: &TaskIndex, file: usize, decl: &Decl) -> CompletionItem {
    CompletionItem {
        label: decl.name.clone(),
        kind: Some(kind_of(decl.kind)),
        detail: Some(super::header(ti.text(file), decl)),
        ..CompletionItem::default()
    }
}

fn builtin_item(builtin: &Builtin, snippets: bool) -> CompletionItem {
    let kind = match builtin.kind {
        EntryKind::Routine if builtin.is_func => CompletionItemKind::FUNCTION,
        EntryKind::Routine => CompletionItemKind::METHOD,
        EntryKind::Data => CompletionItemKind::CONSTANT,
        EntryKind::ReadOnlyData => CompletionItemKind::VARIABLE,
        _ => CompletionItemKind::STRUCT,
    };
    let mut item = CompletionItem {
        label: builtin.name.clone(),
        kind: Some(kind),
        detail: Some(builtin.signature()),
        documentation: Some(Documentation::MarkupContent(MarkupContent {
            kind: MarkupKind::Markdown,
            value: builtin.doc.to_owned(),
        })),
        ..CompletionItem::default()
    };
    if builtin.kind == EntryKind::Routine {
        routine_snippet(&mut item, &Signature::of_builtin(builtin), snippets);
    }
    item
}

/// Inserts a routine with its required arguments to fill in: `Name A, B` for a
/// procedure call, `Name(A, B)` for a function. Optional arguments are listed in the
/// label; `\` after the call offers them.
fn routine_snippet(item: &mut CompletionItem, sig: &Signature, snippets: bool) {
    let mut required: Vec<&str> = Vec::new();
    let mut optional: Vec<String> = Vec::new();
    for (at, p) in sig.params.iter().enumerate() {
        let alternative = at > 0 && sig.params[at - 1].group == p.group;
        if p.optional {
            optional.push(format!("\\{}", p.name));
        } else if !alternative {
            required.push(&p.name);
        }
    }
    item.label_details = Some(CompletionItemLabelDetails {
        detail: Some(format!(" {}", sig.params.iter().map(|p| p.label.as_str()).collect::<Vec<_>>().join(", "))),
        description: None,
    });
    if !snippets {
        return;
    }
    let args: Vec<String> = required.iter().enumerate().map(|(i, name)| format!("${{{}:{name}}}", i + 1)).collect();
    let text = match (sig.is_func, args.is_empty()) {
        (true, _) => format!("{}({})", sig.name, args.join(", ")),
        (false, true) => sig.name.clone(),
        (false, false) => format!("{} {}", sig.name, args.join(", ")),
    };
    item.insert_text = Some(text);
    item.insert_text_format = Some(InsertTextFormat::SNIPPET);
}

/// The components of the record the expression before the `.` at token `dot` has
/// (`p.trans.`, `arr{2}.`, `Offs(p, 0, 0, 10).`): by the expression's type, not by
/// the component's name.
fn components_after(ti: &TaskIndex, file: usize, dot: usize) -> Vec<CompletionItem> {
    let Some(ty) = dot.checked_sub(1).and_then(|last| ti.type_ending_at(file, last, 0)) else { return Vec::new() };
    components(ti, &ty)
        .into_iter()
        .map(|(name, ty)| CompletionItem {
            label: name,
            kind: Some(CompletionItemKind::FIELD),
            detail: Some(ty),
            ..CompletionItem::default()
        })
        .collect()
}

/// The components (name, type) of record type `ty`: a user RECORD or a built-in one,
/// through user ALIASes.
fn components(ti: &TaskIndex, ty: &str) -> Vec<(String, String)> {
    let key = ti.unalias(ty);
    if let Some((file, record)) = ti.record(&key) {
        return ti.files[file]
            .decls
            .iter()
            .filter(|d| d.parent == Some(record))
            .map(|d| (d.name.clone(), d.ty.clone().unwrap_or_default()))
            .collect();
    }
    builtins::table().get(&key).map_or_else(Vec::new, |b| b.components.clone())
}

/// The optional parameters of the call around `offset`, after a `\`.
fn optional_args(ti: &TaskIndex, file: usize, offset: u32, snippets: bool) -> Vec<CompletionItem> {
    let index = &ti.files[file];
    let Some(call) = call_at(index, offset) else { return Vec::new() };
    let name = index.tokens[call.name];
    let key = fold(name.span.text(ti.text(file)));
    let Some(sig) = ti.lookup(file, name.span.start, &key).and_then(|t| Signature::of(ti, t)) else {
        return Vec::new();
    };
    sig.params
        .iter()
        .filter(|p| p.optional)
        .map(|p| {
            let mut item = CompletionItem {
                label: p.name.clone(),
                kind: Some(CompletionItemKind::PROPERTY),
                detail: Some(p.label.clone()),
                ..CompletionItem::default()
            };
            if !p.switch {
                item.insert_text =
                    Some(if snippets { format!("{}:=${{1:{}}}", p.name, p.ty) } else { format!("{}:=", p.name) });
                item.insert_text_format =
                    Some(if snippets { InsertTextFormat::SNIPPET } else { InsertTextFormat::PLAIN_TEXT });
            }
            item
        })
        .collect()
}

/// The task's routines and modules, for a late-binding string.
fn routine_names(ti: &TaskIndex) -> Vec<CompletionItem> {
    let mut items: Vec<CompletionItem> = Vec::new();
    for index in &ti.files {
        for decl in
            index.decls.iter().filter(|d| d.routine.is_none() && (d.kind.is_routine() || d.kind == Kind::Module))
        {
            if !items.iter().any(|i| i.label == decl.name) {
                items.push(CompletionItem {
                    label: decl.name.clone(),
                    kind: Some(kind_of(decl.kind)),
                    ..CompletionItem::default()
                });
            }
        }
    }
    items
}
