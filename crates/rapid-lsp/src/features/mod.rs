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
use rapid_syntax::token::TokenKind;
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
    /// Component `at` of the built-in record type `record` (`trans` of `robtarget`).
    BuiltinComponent {
        record: &'a Builtin,
        at: usize,
    },
}

impl PartialEq for Target<'_> {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Target::User { file: f1, decl: d1 }, Target::User { file: f2, decl: d2 }) => f1 == f2 && d1 == d2,
            (Target::Signal(a), Target::Signal(b)) => a == b,
            (Target::Builtin(a), Target::Builtin(b)) => std::ptr::eq(*a, *b),
            (Target::BuiltinComponent { record: r1, at: a1 }, Target::BuiltinComponent { record: r2, at: a2 }) => {
                std::ptr::eq(*r1, *r2) && a1 == a2
            }
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
            let index = &self.files[file];
            let at = index.tokens.partition_point(|t| t.span.start < ident.span.start);
            let base = self.type_ending_at(file, at.checked_sub(2)?, 0)?;
            return self.component(&base, &ident.key);
        }
        if let Some(decl) = self.files[file].component_named_at(ident.span) {
            return Some(Target::User { file, decl });
        }
        self.lookup(file, ident.span.start, &ident.key)
    }

    /// Resolves the folded name `key` as written at `offset` of `file`.
    pub(crate) fn lookup(&self, file: usize, offset: u32, key: &str) -> Option<Target<'static>> {
        let index = &self.files[file];
        if let Some(routine) = index.routine_at(offset) {
            if let Some(decl) = index.local_at(routine, offset, key) {
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

    /// Component `key` of the record type `ty` (a user RECORD or a built-in one).
    fn component(&self, ty: &str, key: &str) -> Option<Target<'static>> {
        let ty = self.unalias(ty);
        if let Some((file, record)) = self.record(&ty) {
            let decl = self.files[file].decls.iter().position(|d| d.parent == Some(record) && d.key == key)?;
            return Some(Target::User { file, decl });
        }
        let record = builtins::table().get(&ty)?;
        let at = record.components.iter().position(|(name, _)| crate::index::fold(name) == key)?;
        Some(Target::BuiltinComponent { record, at })
    }

    /// The folded type `ty` names once user ALIASes are followed (a few steps at most:
    /// an alias of an alias is rare, and a cycle is the checker's to report).
    pub(crate) fn unalias(&self, ty: &str) -> String {
        let mut key = crate::index::fold(ty);
        for _ in 0..8 {
            let alias = self.by_key.get(&key).and_then(|c| {
                c.iter().map(|&(f, d)| self.decl(f, d)).find(|d| d.kind == Kind::Alias).and_then(|d| d.ty.clone())
            });
            match alias {
                Some(base) => key = crate::index::fold(&base),
                None => break,
            }
        }
        key
    }

    /// The data type of the expression whose last token is `last` of `file`, when it
    /// is a name, an array element (`a{i}`), a function call (`f(x)`) or a component
    /// of one of those (`p.trans`): what a `.` after it selects from.
    pub(crate) fn type_ending_at(&self, file: usize, last: usize, depth: u32) -> Option<String> {
        // Each step is one `.` of the chain; a longer chain is not real RAPID.
        if depth > 32 {
            return None;
        }
        let tokens = &self.files[file].tokens;
        let name = match tokens.get(last)?.kind {
            TokenKind::RBrace => opening(tokens, last, TokenKind::LBrace, TokenKind::RBrace)?.checked_sub(1)?,
            TokenKind::RParen => opening(tokens, last, TokenKind::LParen, TokenKind::RParen)?.checked_sub(1)?,
            _ => last,
        };
        let called = tokens.get(last)?.kind == TokenKind::RParen;
        let token = tokens.get(name).filter(|t| t.kind == TokenKind::Ident)?;
        let key = crate::index::fold(token.span.text(self.text(file)));
        if name >= 2 && tokens[name - 1].kind == TokenKind::Dot {
            let base = self.type_ending_at(file, name - 2, depth + 1)?;
            return match self.component(&base, &key)? {
                Target::User { file, decl } => self.decl(file, decl).ty.clone(),
                Target::BuiltinComponent { record, at } => Some(record.components[at].1.clone()),
                _ => None,
            };
        }
        match self.lookup(file, token.span.start, &key)? {
            Target::User { file, decl } => {
                let decl = self.decl(file, decl);
                let fits = if called { decl.kind == Kind::Func } else { decl.kind.is_data() };
                fits.then(|| decl.ty.clone()).flatten()
            }
            Target::Signal(at) => (!called).then(|| self.task.options.predefined[at].type_name.clone()),
            Target::Builtin(b) => {
                let fits = if called { b.is_func } else { b.kind != rapid_lib::catalogue::EntryKind::Routine };
                fits.then(|| b.ty.clone()).flatten()
            }
            Target::BuiltinComponent { .. } => None,
        }
    }

    /// Every place the task names `target`, declaration included.
    pub(crate) fn references(&self, target: Target<'_>) -> Vec<(usize, rapid_syntax::Span)> {
        let key = match target {
            Target::User { file, decl } => self.decl(file, decl).key.clone(),
            Target::Signal(at) => crate::index::fold(&self.task.options.predefined[at].name),
            Target::Builtin(builtin) => crate::index::fold(&builtin.name),
            Target::BuiltinComponent { record, at } => crate::index::fold(&record.components[at].0),
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

/// The opening bracket (`open`) of the closing one at token `close`, nested pairs
/// skipped; looked for a bounded distance back, as an argument list is short.
fn opening(tokens: &[rapid_syntax::token::Token], close: usize, open: TokenKind, shut: TokenKind) -> Option<usize> {
    let mut depth = 0u32;
    for k in (close.saturating_sub(4096)..=close).rev() {
        let kind = tokens[k].kind;
        if kind == shut {
            depth += 1;
        } else if kind == open {
            depth -= 1;
            if depth == 0 {
                return Some(k);
            }
        }
    }
    None
}

/// The first line of a declaration's text (a routine's header), trimmed.
pub(crate) fn header(text: &str, decl: &Decl) -> String {
    let full = decl.span.text(text);
    let line = full.lines().next().unwrap_or("").trim();
    line.chars().take(300).collect()
}
