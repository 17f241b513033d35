//! Document symbols (the outline: modules, routines, records, data) and workspace
//! symbols (every module-level declaration of every task).

use lsp_types::{DocumentSymbol, Location, SymbolInformation, SymbolKind};

use super::TaskIndex;
use crate::index::{Decl, FileIndex, Kind};
use crate::position::LineMap;

fn symbol_kind(kind: Kind) -> SymbolKind {
    match kind {
        Kind::Module => SymbolKind::MODULE,
        Kind::Record => SymbolKind::STRUCT,
        Kind::Alias => SymbolKind::TYPE_PARAMETER,
        Kind::Component => SymbolKind::FIELD,
        Kind::Var | Kind::Pers | Kind::Local | Kind::Param => SymbolKind::VARIABLE,
        Kind::Const => SymbolKind::CONSTANT,
        Kind::Proc => SymbolKind::METHOD,
        Kind::Func => SymbolKind::FUNCTION,
        Kind::Trap => SymbolKind::EVENT,
    }
}

fn detail(decl: &Decl) -> Option<String> {
    let word = match decl.kind {
        Kind::Module => return None,
        Kind::Record => "RECORD",
        Kind::Alias => "ALIAS",
        Kind::Component | Kind::Local | Kind::Param => "",
        Kind::Var => "VAR",
        Kind::Pers => "PERS",
        Kind::Const => "CONST",
        Kind::Proc => "PROC",
        Kind::Func => "FUNC",
        Kind::Trap => "TRAP",
    };
    let mut parts: Vec<&str> = Vec::new();
    if decl.local {
        parts.push("LOCAL");
    }
    if !word.is_empty() {
        parts.push(word);
    }
    parts.extend(decl.ty.as_deref());
    (!parts.is_empty()).then(|| parts.join(" "))
}

/// The outline of one file.
pub(crate) fn document(index: &FileIndex, text: &str) -> Vec<DocumentSymbol> {
    let map = LineMap::new(text);
    let symbol = |decl: &Decl| {
        #[allow(deprecated)]
        DocumentSymbol {
            name: decl.name.clone(),
            detail: detail(decl),
            kind: symbol_kind(decl.kind),
            tags: None,
            deprecated: None,
            range: map.range(text, decl.span.cover(decl.name_span)),
            selection_range: map.range(text, decl.name_span),
            children: None,
        }
    };
    let mut modules: Vec<DocumentSymbol> = Vec::new();
    let decls = &index.decls;
    for (at, decl) in decls.iter().enumerate() {
        if decl.name.is_empty() {
            continue;
        }
        let mut sym = symbol(decl);
        let children: Vec<DocumentSymbol> = match decl.kind {
            k if k.is_routine() => decls.iter().filter(|d| d.routine == Some(at)).map(symbol).collect(),
            Kind::Record => decls.iter().filter(|d| d.parent == Some(at)).map(symbol).collect(),
            _ => Vec::new(),
        };
        if !children.is_empty() {
            sym.children = Some(children);
        }
        match decl.kind {
            Kind::Module => modules.push(DocumentSymbol { children: Some(Vec::new()), ..sym }),
            Kind::Component | Kind::Param | Kind::Local => {}
            _ => {
                if let Some(module) = modules.get_mut(decl.module) {
                    module.children.get_or_insert_with(Vec::new).push(sym);
                }
            }
        }
    }
    modules
}

/// Module-level declarations of the task whose name holds `query` (any case).
/// `seen` holds the places already listed (a module several tasks load is listed once).
pub(crate) fn workspace(
    ti: &TaskIndex,
    query: &str,
    out: &mut Vec<SymbolInformation>,
    seen: &mut rustc_hash::FxHashSet<(String, u32, u32)>,
) {
    let query = crate::index::fold(query);
    for (file, index) in ti.files.iter().enumerate() {
        for decl in index.decls.iter().filter(|d| d.routine.is_none() && d.kind != Kind::Component) {
            if !decl.key.contains(&query) || decl.name.is_empty() {
                continue;
            }
            let container = index.decls.iter().find(|m| m.kind == Kind::Module && m.module == decl.module);
            let location: Location = ti.location(file, decl.name_span);
            let place = (location.uri.as_str().to_owned(), location.range.start.line, location.range.start.character);
            if !seen.insert(place) {
                continue;
            }
            #[allow(deprecated)]
            out.push(SymbolInformation {
                name: decl.name.clone(),
                kind: symbol_kind(decl.kind),
                tags: None,
                deprecated: None,
                location,
                container_name: container.filter(|_| decl.kind != Kind::Module).map(|m| m.name.clone()),
            });
        }
    }
}
