//! What the editor features need of one file: every declaration with its scope and
//! every name written, in source order. Built from the full syntax tree and the
//! tokens of the file's current text; nothing here resolves across files (that is
//! `features::resolve`).

use rapid_syntax::ast::{Arena, DataDecl, Item, Module, RoutineKind, Stmt, StmtKind, Storage, TypeDefKind};
use rapid_syntax::lexer::Lexer;
use rapid_syntax::token::{Token, TokenKind};
use rapid_syntax::{parse, Interner, Span};

/// What a declaration declares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    Module,
    Record,
    Alias,
    /// A component of the RECORD `Decl::parent`.
    Component,
    Var,
    Pers,
    Const,
    Proc,
    Func,
    Trap,
    Param,
    /// Routine data, or a FOR loop variable.
    Local,
}

impl Kind {
    pub(crate) fn is_routine(self) -> bool {
        matches!(self, Kind::Proc | Kind::Func | Kind::Trap)
    }

    pub(crate) fn is_data(self) -> bool {
        matches!(self, Kind::Var | Kind::Pers | Kind::Const | Kind::Param | Kind::Local)
    }
}

/// One declaration of the file.
#[derive(Debug, Clone)]
pub(crate) struct Decl {
    /// The name as written.
    pub(crate) name: String,
    /// The name folded as RAPID compares names (ASCII and Latin-1 capitals lowered).
    pub(crate) key: String,
    pub(crate) kind: Kind,
    pub(crate) name_span: Span,
    /// The whole declaration (a routine from PROC to ENDPROC).
    pub(crate) span: Span,
    /// The module of the file it belongs to (index into `FileIndex::modules`).
    pub(crate) module: usize,
    /// The routine it is declared in (a declaration index), for parameters and
    /// routine data.
    pub(crate) routine: Option<usize>,
    /// Declared LOCAL: visible in its module only.
    pub(crate) local: bool,
    /// The data type of data and parameters, the return type of a FUNC, the base of
    /// an ALIAS, the type of a component.
    pub(crate) ty: Option<String>,
    /// The record of a component (a declaration index).
    pub(crate) parent: Option<usize>,
    /// An optional parameter (`\name`).
    pub(crate) optional: bool,
    /// Where a FOR loop variable is visible: the loop after its header, to `ENDFOR`
    /// (the FROM, TO and STEP values are read before the variable exists). `None`
    /// for every other declaration.
    pub(crate) scope: Option<Span>,
}

impl Decl {
    /// The declaration is visible at `offset` of its routine (a FOR loop variable
    /// only inside its loop, and at its own name).
    pub(crate) fn visible_at(&self, offset: u32) -> bool {
        self.scope.is_none_or(|s| (s.start <= offset && offset <= s.end) || self.name_span.start == offset)
    }
}

/// A name written in the file.
#[derive(Debug, Clone)]
pub(crate) struct Ident {
    pub(crate) span: Span,
    pub(crate) key: String,
    /// Written after `.`: a record component.
    pub(crate) after_dot: bool,
    /// Written after `\`: an optional parameter's name in a call.
    pub(crate) after_backslash: bool,
}

/// The index of one file.
#[derive(Debug, Default)]
pub(crate) struct FileIndex {
    pub(crate) decls: Vec<Decl>,
    /// Every identifier token, in source order.
    pub(crate) idents: Vec<Ident>,
    /// Every token but the end, in source order.
    pub(crate) tokens: Vec<Token>,
    pub(crate) comments: Vec<Span>,
    /// The routines' spans with their declaration index, in source order (routines
    /// never nest), for finding the routine at an offset by binary search.
    routines: Vec<(Span, usize)>,
    /// Where each routine's body starts, by declaration index.
    body_starts: Vec<(usize, u32)>,
    /// Where each record component's name starts, with its declaration index, in
    /// source order: a component's own name resolves to it.
    component_names: Vec<(u32, usize)>,
}

/// Folds a name the way RAPID compares names.
pub(crate) fn fold(name: &str) -> String {
    name.chars().map(rapid_syntax::intern::fold_char).collect()
}

impl FileIndex {
    pub(crate) fn build(text: &str) -> FileIndex {
        let mut interner = Interner::default();
        let parsed = parse(text, &mut interner);
        let mut index = FileIndex { comments: parsed.comments.clone(), ..FileIndex::default() };
        for (module_idx, module) in parsed.file.modules.iter().enumerate() {
            index.add_module(text, module_idx, module);
        }
        index.add_tokens(text);
        index.routines =
            index.decls.iter().enumerate().filter(|(_, d)| d.kind.is_routine()).map(|(at, d)| (d.span, at)).collect();
        index.routines.sort_by_key(|(span, _)| span.start);
        index.component_names = index
            .decls
            .iter()
            .enumerate()
            .filter(|(_, d)| d.kind == Kind::Component)
            .map(|(at, d)| (d.name_span.start, at))
            .collect();
        index.component_names.sort_unstable();
        index
    }

    /// The record component whose declared name is the identifier at `span`.
    pub(crate) fn component_named_at(&self, span: Span) -> Option<usize> {
        let at = self.component_names.partition_point(|&(start, _)| start < span.start);
        let &(start, decl) = self.component_names.get(at)?;
        (start == span.start && self.decls[decl].name_span == span).then_some(decl)
    }

    fn push(&mut self, text: &str, decl: DeclParts) -> usize {
        let name = decl.name_span.text(text).to_owned();
        self.decls.push(Decl {
            key: fold(&name),
            name,
            kind: decl.kind,
            name_span: decl.name_span,
            span: decl.span,
            module: decl.module,
            routine: decl.routine,
            local: decl.local,
            ty: decl.ty.map(|span| span.text(text).to_owned()),
            parent: decl.parent,
            optional: decl.optional,
            scope: decl.scope,
        });
        self.decls.len() - 1
    }

    fn add_module(&mut self, text: &str, module_idx: usize, module: &Module) {
        let base = DeclParts { module: module_idx, ..DeclParts::new(Kind::Module, module.name.span, module.span) };
        self.push(text, base);
        for item in &module.items {
            match item {
                Item::Type(def) => {
                    let (kind, name, ty) = match &def.kind {
                        TypeDefKind::Record { name, .. } => (Kind::Record, name, None),
                        TypeDefKind::Alias { base, name } => (Kind::Alias, name, Some(base.span)),
                    };
                    let record =
                        self.push(text, DeclParts { local: def.local, ty, ..base.with(kind, name.span, def.span) });
                    if let TypeDefKind::Record { components, .. } = &def.kind {
                        for comp in components {
                            let parts = base.with(Kind::Component, comp.name.span, comp.span);
                            self.push(text, DeclParts { ty: Some(comp.ty.span), parent: Some(record), ..parts });
                        }
                    }
                }
                Item::Data(decl) => {
                    self.push(text, data_parts(&base, decl, None));
                }
                Item::Routine(routine) => {
                    let kind = match routine.kind {
                        RoutineKind::Proc => Kind::Proc,
                        RoutineKind::Func => Kind::Func,
                        RoutineKind::Trap => Kind::Trap,
                    };
                    let parts = base.with(kind, routine.name.span, routine.span);
                    let ty = routine.ret_ty.map(|n| n.span);
                    let at = self.push(text, DeclParts { local: routine.local, ty, ..parts });
                    self.body_starts.push((at, routine.body_span.start));
                    for param in &routine.params {
                        let parts = base.with(Kind::Param, param.name.span, param.span);
                        self.push(
                            text,
                            DeclParts { routine: Some(at), ty: Some(param.ty.span), optional: param.optional, ..parts },
                        );
                    }
                    if let Some(body) = &routine.body {
                        for decl in &body.decls {
                            self.push(text, data_parts(&base, decl, Some(at)));
                        }
                        let mut loops = Vec::new();
                        for_vars(&body.arena, &body.stmts, &mut loops);
                        for handler in [&body.backward, &body.error, &body.undo].into_iter().flatten() {
                            for_vars(&body.arena, &handler.stmts, &mut loops);
                        }
                        for (name, span, scope) in loops {
                            let parts = base.with(Kind::Local, name, span);
                            self.push(text, DeclParts { routine: Some(at), scope: Some(scope), ..parts });
                        }
                    }
                }
                Item::Placeholder(..) => {}
            }
        }
    }

    fn add_tokens(&mut self, text: &str) {
        let mut lexer = Lexer::new(text);
        let mut prev = TokenKind::Eof;
        loop {
            let token = lexer.next_token();
            if token.kind == TokenKind::Eof {
                break;
            }
            if token.kind == TokenKind::Ident {
                self.idents.push(Ident {
                    span: token.span,
                    key: fold(token.span.text(text)),
                    after_dot: prev == TokenKind::Dot,
                    after_backslash: prev == TokenKind::Backslash,
                });
            }
            self.tokens.push(token);
            prev = token.kind;
        }
    }

    /// The identifier whose span holds `offset` (or ends there: the cursor just after
    /// a name is on it).
    pub(crate) fn ident_at(&self, offset: u32) -> Option<&Ident> {
        let at = self.idents.partition_point(|id| id.span.end < offset);
        self.idents.get(at).filter(|id| id.span.start <= offset)
    }

    /// The innermost routine declaration holding `offset`.
    pub(crate) fn routine_at(&self, offset: u32) -> Option<usize> {
        let after = self.routines.partition_point(|(span, _)| span.start <= offset);
        let (span, at) = *self.routines.get(after.checked_sub(1)?)?;
        (offset <= span.end).then_some(at)
    }

    /// Where the body of the routine holding `offset` starts.
    pub(crate) fn body_start(&self, offset: u32) -> Option<u32> {
        let routine = self.routine_at(offset)?;
        self.body_starts.iter().find(|(at, _)| *at == routine).map(|(_, start)| *start)
    }

    /// The parameters and data of routine `routine` (declarations follow their
    /// routine's, in one run), FOR loop variables of every loop included.
    pub(crate) fn locals(&self, routine: usize) -> impl Iterator<Item = (usize, &Decl)> {
        self.decls.iter().enumerate().skip(routine + 1).take_while(move |(_, d)| d.routine == Some(routine))
    }

    /// The local declaration of routine `routine` the folded name `key` written at
    /// `offset` denotes, as the checker resolves it: the loop variable of the
    /// innermost FOR around `offset`, then the routine's data and parameters.
    pub(crate) fn local_at(&self, routine: usize, offset: u32, key: &str) -> Option<usize> {
        let mut loop_var: Option<(usize, u32)> = None;
        let mut data = None;
        for (at, decl) in self.locals(routine).filter(|(_, d)| d.key == key) {
            if decl.name_span.start == offset {
                return Some(at);
            }
            match decl.scope {
                // Loops nest: the innermost holding `offset` starts last.
                Some(scope) if decl.visible_at(offset) => {
                    if loop_var.is_none_or(|(_, start)| scope.start > start) {
                        loop_var = Some((at, scope.start));
                    }
                }
                Some(_) => {}
                None => data = data.or(Some(at)),
            }
        }
        loop_var.map(|(at, _)| at).or(data)
    }

    /// The module holding `offset`.
    pub(crate) fn module_at(&self, offset: u32) -> Option<usize> {
        self.decls
            .iter()
            .find(|d| d.kind == Kind::Module && d.span.start <= offset && offset <= d.span.end)
            .map(|d| d.module)
    }
}

/// The fields of a declaration before its name is read from the text.
#[derive(Debug, Clone, Copy)]
struct DeclParts {
    kind: Kind,
    name_span: Span,
    span: Span,
    module: usize,
    routine: Option<usize>,
    local: bool,
    ty: Option<Span>,
    parent: Option<usize>,
    optional: bool,
    scope: Option<Span>,
}

impl DeclParts {
    fn new(kind: Kind, name_span: Span, span: Span) -> DeclParts {
        DeclParts {
            kind,
            name_span,
            span,
            module: 0,
            routine: None,
            local: false,
            ty: None,
            parent: None,
            optional: false,
            scope: None,
        }
    }

    /// Another declaration of the same module.
    fn with(&self, kind: Kind, name_span: Span, span: Span) -> DeclParts {
        DeclParts { module: self.module, ..DeclParts::new(kind, name_span, span) }
    }
}

fn data_parts(base: &DeclParts, decl: &DataDecl, routine: Option<usize>) -> DeclParts {
    let kind = match (routine, decl.storage) {
        (Some(_), _) => Kind::Local,
        (None, Storage::Var) => Kind::Var,
        (None, Storage::Pers) => Kind::Pers,
        (None, Storage::Const) => Kind::Const,
    };
    let local = matches!(decl.scope, rapid_syntax::ast::DeclScope::Local);
    DeclParts { routine, local, ty: Some(decl.ty.span), ..base.with(kind, decl.name.span, decl.span) }
}

/// The FOR loop variables of a statement list, nested ones included: each name, its
/// FOR statement, and where it is visible (after the header's last value to ENDFOR).
fn for_vars(arena: &Arena, stmts: &[Stmt], out: &mut Vec<(Span, Span, Span)>) {
    for stmt in stmts {
        match &stmt.kind {
            StmtKind::For { var, from, to, step, body } => {
                let values = [Some(*from), Some(*to), *step];
                let header_end = values.iter().flatten().map(|&e| arena.expr(e).span.end).max().unwrap_or(var.span.end);
                out.push((
                    var.span,
                    stmt.span,
                    Span::new(header_end.max(var.span.end) as usize, stmt.span.end as usize),
                ));
                for_vars(arena, body, out);
            }
            StmtKind::If { then, elifs, els, .. } => {
                for_vars(arena, then, out);
                for elif in elifs {
                    for_vars(arena, &elif.body, out);
                }
                for_vars(arena, els.as_deref().unwrap_or(&[]), out);
            }
            StmtKind::While { body, .. } => for_vars(arena, body, out),
            StmtKind::Test { cases, default, .. } => {
                for case in cases {
                    for_vars(arena, &case.body, out);
                }
                for_vars(arena, default.as_deref().unwrap_or(&[]), out);
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "MODULE M\n  RECORD pt\n    num x;\n  ENDRECORD\n  LOCAL VAR num n := 1;\n  PROC main(num a)\n    VAR pt p;\n    FOR i FROM 1 TO 2 DO\n      p.x := a + n;\n    ENDFOR\n  ENDPROC\nENDMODULE\n";

    #[test]
    fn collects_declarations_with_their_scopes() {
        let index = FileIndex::build(TEXT);
        let names: Vec<(&str, Kind)> = index.decls.iter().map(|d| (d.name.as_str(), d.kind)).collect();
        assert_eq!(
            names,
            [
                ("M", Kind::Module),
                ("pt", Kind::Record),
                ("x", Kind::Component),
                ("n", Kind::Var),
                ("main", Kind::Proc),
                ("a", Kind::Param),
                ("p", Kind::Local),
                ("i", Kind::Local),
            ]
        );
        assert!(index.decls[3].local);
        assert_eq!(index.decls[5].routine, Some(4));
        assert_eq!(index.decls[2].parent, Some(1));
        assert_eq!(index.decls[6].ty.as_deref(), Some("pt"));
    }

    #[test]
    fn a_loop_variable_is_visible_in_its_loop_only() {
        let text = "MODULE M\n  PROC main()\n    VAR num i;\n    FOR i FROM i TO 2 DO\n      i2 := i;\n    ENDFOR\n    i := 0;\n  ERROR\n    FOR i FROM 1 TO 2 DO\n      i3 := i;\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
        let index = FileIndex::build(text);
        let keys: Vec<(&str, bool)> = index.decls.iter().map(|d| (d.name.as_str(), d.scope.is_some())).collect();
        // main's data `i`, then the body's loop variable and the ERROR handler's.
        assert_eq!(keys, [("M", false), ("main", false), ("i", false), ("i", true), ("i", true)]);
        let at = |needle: &str, skip: usize| (text.find(needle).unwrap() + skip) as u32;
        // The loop's own name, its body, and after it: main's `i` again. The FROM value
        // is read before the loop variable exists.
        assert_eq!(index.local_at(1, at("FOR i", 4), "i"), Some(3));
        assert_eq!(index.local_at(1, at("FROM i", 5), "i"), Some(2));
        assert_eq!(index.local_at(1, at("i2 := i", 6), "i"), Some(3));
        assert_eq!(index.local_at(1, at("    i := 0", 4), "i"), Some(2));
        assert_eq!(index.local_at(1, at("i3 := i", 6), "i"), Some(4));
    }

    #[test]
    fn marks_component_names() {
        let index = FileIndex::build(TEXT);
        let x = TEXT.find("p.x").unwrap() as u32 + 2;
        let ident = index.ident_at(x).unwrap();
        assert_eq!(ident.key, "x");
        assert!(ident.after_dot);
        assert_eq!(index.routine_at(x), Some(4));
    }
}
