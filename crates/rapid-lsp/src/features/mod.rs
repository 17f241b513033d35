//! The editor features, one module each, over [`TaskIndex`]: a task's files indexed,
//! and names resolved the way the checker resolves them (§1.1.5, §1.2.2): routine
//! data and parameters, then the module's own items (LOCAL ones too), then the task's
//! global items, then the configuration's signals, then the built-ins.

pub(crate) mod actions;
pub(crate) mod complete;
pub(crate) mod folding;
pub(crate) mod format;
pub(crate) mod hover;
pub(crate) mod navigate;
pub(crate) mod semantic;
pub(crate) mod signature;
pub(crate) mod symbols;

use std::rc::Rc;

use lsp_types::{Location, Position, Range, Uri};
use rustc_hash::FxHashMap;

use crate::builtins::{self, Builtin};
use crate::index::{Decl, FileIndex, Ident, Kind};
use crate::position::LineMap;
use crate::workspace::{State, TaskView};

/// What a name denotes.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Target<'a> {
    /// Declaration `decl` of file `file` of the task.
    User {
        file: usize,
        decl: usize,
    },
    /// A signal of the configuration: index into `Options::predefined`.
    Signal(usize),
    Builtin(&'a Builtin),
}

impl PartialEq for Target<'_> {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Target::User { file: f1, decl: d1 }, Target::User { file: f2, decl: d2 }) => f1 == f2 && d1 == d2,
            (Target::Signal(a), Target::Signal(b)) => a == b,
            (Target::Builtin(a), Target::Builtin(b)) => std::ptr::eq(*a, *b),
            _ => false,
        }
    }
}

/// One task's files, indexed, with line maps for positions.
pub(crate) struct TaskIndex {
    pub(crate) task: TaskView,
    pub(crate) files: Vec<Rc<FileIndex>>,
    pub(crate) maps: Vec<LineMap>,
    /// Module-level declarations (and modules) by folded name: (file, decl).
    by_key: FxHashMap<String, Vec<(usize, usize)>>,
}

impl TaskIndex {
    pub(crate) fn new(state: &State, task: TaskView) -> TaskIndex {
        let files: Vec<Rc<FileIndex>> =
            task.files.iter().zip(&task.uris).map(|(f, u)| state.index(u, &f.text)).collect();
        let maps = task.files.iter().map(|f| LineMap::new(&f.text)).collect();
        let mut by_key: FxHashMap<String, Vec<(usize, usize)>> = FxHashMap::default();
        for (file, index) in files.iter().enumerate() {
            for (at, decl) in index.decls.iter().enumerate() {
                if decl.routine.is_none() && decl.kind != Kind::Component {
                    by_key.entry(decl.key.clone()).or_default().push((file, at));
                }
            }
        }
        TaskIndex { task, files, maps, by_key }
    }

    /// The task holding `uri` (the first, when several load it), indexed.
    pub(crate) fn of(state: &State, uri: &Uri) -> Option<(TaskIndex, usize)> {
        let task = state.tasks_of(uri).into_iter().next()?;
        let file = task.file_of(uri)?;
        Some((TaskIndex::new(state, task), file))
    }

    pub(crate) fn text(&self, file: usize) -> &str {
        &self.task.files[file].text
    }

    pub(crate) fn decl(&self, file: usize, decl: usize) -> &Decl {
        &self.files[file].decls[decl]
    }

    pub(crate) fn offset(&self, file: usize, pos: Position) -> u32 {
        self.maps[file].offset(self.text(file), pos) as u32
    }

    pub(crate) fn range(&self, file: usize, span: rapid_syntax::Span) -> Range {
        self.maps[file].range(self.text(file), span)
    }

    pub(crate) fn location(&self, file: usize, span: rapid_syntax::Span) -> Location {
        Location { uri: self.task.uris[file].clone(), range: self.range(file, span) }
    }

    /// What the name `ident` of `file` denotes.
    pub(crate) fn resolve(&self, file: usize, ident: &Ident) -> Option<Target<'static>> {
        if ident.after_backslash {
            return None;
        }
        if ident.after_dot {
            return self.component(&ident.key);
        }
        self.lookup(file, ident.span.start, &ident.key)
    }

    /// Resolves the folded name `key` as written at `offset` of `file`.
    pub(crate) fn lookup(&self, file: usize, offset: u32, key: &str) -> Option<Target<'static>> {
        let index = &self.files[file];
        if let Some(routine) = index.routine_at(offset) {
            if let Some((decl, _)) = index.locals(routine).find(|(_, d)| d.key == key) {
                return Some(Target::User { file, decl });
            }
        }
        let module = index.module_at(offset);
        let candidates = self.by_key.get(key).map_or(&[][..], Vec::as_slice);
        let own = candidates.iter().find(|&&(f, d)| f == file && Some(self.decl(f, d).module) == module);
        let global = || candidates.iter().find(|&&(f, d)| !self.decl(f, d).local);
        if let Some(&(file, decl)) = own.or_else(global) {
            return Some(Target::User { file, decl });
        }
        let predefined = &self.task.options.predefined;
        if let Some(at) = predefined.iter().position(|p| crate::index::fold(&p.name) == key) {
            return Some(Target::Signal(at));
        }
        builtins::table().get(key).map(Target::Builtin)
    }

    /// A record component named `key`: the first user RECORD that has one.
    fn component(&self, key: &str) -> Option<Target<'static>> {
        self.files.iter().enumerate().find_map(|(file, index)| {
            let decl = index.decls.iter().position(|d| d.kind == Kind::Component && d.key == key)?;
            Some(Target::User { file, decl })
        })
    }

    /// Every place the task names `target`, declaration included.
    pub(crate) fn references(&self, target: Target<'_>) -> Vec<(usize, rapid_syntax::Span)> {
        let key = match target {
            Target::User { file, decl } => self.decl(file, decl).key.clone(),
            Target::Signal(at) => crate::index::fold(&self.task.options.predefined[at].name),
            Target::Builtin(builtin) => crate::index::fold(&builtin.name),
        };
        let mut out = Vec::new();
        for (file, index) in self.files.iter().enumerate() {
            for ident in index.idents.iter().filter(|id| id.key == key) {
                if self.resolve(file, ident) == Some(target) {
                    out.push((file, ident.span));
                }
            }
        }
        out
    }

    /// The user record type named `ty` (folded), if the task declares one.
    pub(crate) fn record(&self, ty_key: &str) -> Option<(usize, usize)> {
        let candidates = self.by_key.get(ty_key)?;
        candidates.iter().copied().find(|&(f, d)| self.decl(f, d).kind == Kind::Record)
    }
}

/// The first line of a declaration's text (a routine's header), trimmed.
pub(crate) fn header(text: &str, decl: &Decl) -> String {
    let full = decl.span.text(text);
    let line = full.lines().next().unwrap_or("").trim();
    line.chars().take(300).collect()
}
