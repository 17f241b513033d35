//! The abstract syntax tree. Every node has a span. Expressions and arguments of one
//! routine body (or of one module's declarations) live in an [`Arena`] and are named
//! by index, which keeps nodes small and lets a checker drop a statement's nodes as
//! soon as it has looked at them (see `parser::BodyMode`).

use crate::intern::Symbol;
use crate::span::Span;
pub use crate::token::Placeholder;

/// A name as written: its interned symbol and where it stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Name {
    pub sym: Symbol,
    pub span: Span,
    /// The name is the placeholder `<ID>` (or is missing after an error).
    pub is_placeholder: bool,
}

/// One parsed file: an optional `%%%` header and its modules (normally exactly one).
#[derive(Debug, Default)]
pub struct SourceFile {
    pub header: Option<Span>,
    pub modules: Vec<Module>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ModuleAttr {
    Sysmodule,
    Noview,
    Nostepin,
    Viewonly,
    Readonly,
}

#[derive(Debug)]
pub struct Module {
    pub name: Name,
    pub attrs: Vec<(ModuleAttr, Span)>,
    pub items: Vec<Item>,
    /// Expressions of the module-level declarations.
    pub arena: Arena,
    pub span: Span,
}

#[derive(Debug)]
pub enum Item {
    Type(TypeDef),
    Data(DataDecl),
    Routine(Routine),
    /// `<TDN>`, `<DDN>` or `<RDN>`.
    Placeholder(Placeholder, Span),
}

#[derive(Debug)]
pub struct TypeDef {
    pub local: bool,
    pub kind: TypeDefKind,
    pub span: Span,
}

#[derive(Debug)]
pub enum TypeDefKind {
    Record { name: Name, components: Vec<Component> },
    Alias { base: Name, name: Name },
}

impl TypeDef {
    pub fn name(&self) -> Name {
        match &self.kind {
            TypeDefKind::Record { name, .. } | TypeDefKind::Alias { name, .. } => *name,
        }
    }
}

#[derive(Debug, Clone, Copy)]
pub struct Component {
    pub ty: Name,
    pub name: Name,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DeclScope {
    Global,
    Local,
    Task,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Storage {
    Var,
    Pers,
    Const,
}

#[derive(Debug, Clone)]
pub struct DataDecl {
    pub scope: DeclScope,
    pub scope_span: Option<Span>,
    pub storage: Storage,
    pub ty: Name,
    pub name: Name,
    /// Dimension expressions: empty for scalars, 1..3 for arrays.
    pub dims: Vec<ExprId>,
    pub init: Option<ExprId>,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RoutineKind {
    Proc,
    Func,
    Trap,
}

#[derive(Debug)]
pub struct Routine {
    pub local: bool,
    pub kind: RoutineKind,
    /// The return type of a FUNC.
    pub ret_ty: Option<Name>,
    pub name: Name,
    pub params: Vec<Param>,
    /// Where the body starts (just after the header) and ends (before the END keyword).
    pub body_span: Span,
    /// The body, when the file was parsed with `BodyMode::Keep`.
    pub body: Option<Box<Body>>,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamMode {
    In,
    Var,
    Pers,
    Inout,
}

#[derive(Debug, Clone, Copy)]
pub struct Param {
    pub mode: ParamMode,
    /// The type (`switch` is a type name here, checked by rapid-sema).
    pub ty: Name,
    pub name: Name,
    /// Rank of an array parameter (`{*}` = 1 ... `{*,*,*}` = 3), 0 for scalars.
    pub rank: u8,
    /// Written with `\` (or in an alternative group opened by `\`).
    pub optional: bool,
    /// Parameters with the same group are mutually exclusive alternatives (`|`).
    pub group: u16,
    /// `<PAR>`, `<ALT>` or `<DIM>` stands here instead of a declaration.
    pub placeholder: Option<Placeholder>,
    pub span: Span,
}

/// A routine body with its handlers.
#[derive(Debug, Default)]
pub struct Body {
    pub decls: Vec<DataDecl>,
    pub stmts: Vec<Stmt>,
    pub backward: Option<Handler>,
    pub error: Option<Handler>,
    pub undo: Option<Handler>,
    pub arena: Arena,
}

#[derive(Debug)]
pub struct Handler {
    /// The keyword's span.
    pub keyword: Span,
    /// `ERROR (n1, n2)`: the error numbers the handler takes; empty means all.
    pub error_numbers: Vec<ExprId>,
    pub stmts: Vec<Stmt>,
}

/// Which part of a routine a body item belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Section {
    Body,
    Backward,
    Error,
    Undo,
}

/// One top-level item of a routine body as the parser streams it.
#[derive(Debug)]
pub enum BodyItem {
    Decl(DataDecl),
    Stmt(Stmt),
    /// A handler keyword starts a new section.
    Section {
        section: Section,
        keyword: Span,
        error_numbers: Vec<ExprId>,
    },
    /// The body is complete (streamed bodies only): a sink that batches items flushes.
    End,
}

#[derive(Debug, Clone)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

#[derive(Debug, Clone)]
pub enum StmtKind {
    Assign {
        target: ExprId,
        value: ExprId,
    },
    Call {
        name: Name,
        args: ArgList,
    },
    /// `% expr % args;`
    LateCall {
        callee: ExprId,
        args: ArgList,
    },
    If {
        cond: ExprId,
        then: Vec<Stmt>,
        elifs: Vec<ElseIf>,
        els: Option<Vec<Stmt>>,
    },
    CompactIf {
        cond: ExprId,
        stmt: Box<Stmt>,
    },
    For {
        var: Name,
        from: ExprId,
        to: ExprId,
        step: Option<ExprId>,
        body: Vec<Stmt>,
    },
    While {
        cond: ExprId,
        body: Vec<Stmt>,
    },
    Test {
        subject: ExprId,
        cases: Vec<Case>,
        default: Option<Vec<Stmt>>,
    },
    Goto(Name),
    Label(Name),
    Return(Option<ExprId>),
    Raise(Option<ExprId>),
    Retry,
    TryNext,
    Exit,
    Connect {
        target: ExprId,
        trap: Name,
    },
    /// `<SMT>` (or `<EIT>`/`<CSE>` left where they stand in for a clause).
    Placeholder(Placeholder),
    /// A statement that could not be parsed (the error is reported).
    Error,
}

#[derive(Debug, Clone)]
pub struct ElseIf {
    /// `None` for the `<EIT>` placeholder.
    pub cond: Option<ExprId>,
    pub body: Vec<Stmt>,
    pub span: Span,
}

#[derive(Debug, Clone)]
pub struct Case {
    /// Values of `CASE v1, v2:`; empty for the `<CSE>` placeholder.
    pub values: Vec<ExprId>,
    pub body: Vec<Stmt>,
    pub span: Span,
}

/// Index of an expression in its [`Arena`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ExprId(pub u32);

/// A run of expressions or arguments stored in an [`Arena`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ListRange {
    pub start: u32,
    pub len: u32,
}

/// The arguments of one call.
pub type ArgList = ListRange;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Plus,
    Not,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinaryOp {
    Mul,
    Div,
    IntDiv,
    Mod,
    Add,
    Sub,
    Lt,
    Le,
    Eq,
    Gt,
    Ge,
    Ne,
    And,
    Or,
    Xor,
}

impl BinaryOp {
    pub fn text(self) -> &'static str {
        match self {
            BinaryOp::Mul => "*",
            BinaryOp::Div => "/",
            BinaryOp::IntDiv => "DIV",
            BinaryOp::Mod => "MOD",
            BinaryOp::Add => "+",
            BinaryOp::Sub => "-",
            BinaryOp::Lt => "<",
            BinaryOp::Le => "<=",
            BinaryOp::Eq => "=",
            BinaryOp::Gt => ">",
            BinaryOp::Ge => ">=",
            BinaryOp::Ne => "<>",
            BinaryOp::And => "AND",
            BinaryOp::Or => "OR",
            BinaryOp::Xor => "XOR",
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExprKind {
    /// A num literal; its value is `literal::num_value` of the span's text.
    Num,
    /// A string literal; its characters are `literal::string_value` of the span's text.
    Str,
    Bool(bool),
    /// A data name (variable, persistent, constant or parameter).
    Name(Symbol),
    /// `base{i, j}`.
    Index {
        base: ExprId,
        indices: ListRange,
    },
    /// `base.component`; the component name ends the expression's span.
    Field {
        base: ExprId,
        field: Symbol,
    },
    /// `name(args)`.
    Call {
        name: Symbol,
        args: ArgList,
    },
    Unary {
        op: UnaryOp,
        operand: ExprId,
    },
    Binary {
        op: BinaryOp,
        lhs: ExprId,
        rhs: ExprId,
    },
    Paren(ExprId),
    /// `[e1, e2, ...]`.
    Aggregate(ListRange),
    /// `<EXP>`, `<VAR>` or `<ID>`.
    Placeholder(Placeholder),
    /// A missing or unparsable expression (the error is reported).
    Error,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArgKind {
    /// A required argument, positional or named (`Name := expr`).
    Required,
    /// `\Name` or `\Name := expr`.
    Optional,
    /// `\Name ? param`.
    Conditional,
    /// `<ARG>`.
    Placeholder,
}

#[derive(Debug, Clone, Copy)]
pub struct Arg {
    pub kind: ArgKind,
    /// The parameter name, when written.
    pub name: Option<Name>,
    /// The value: the expression, or for a conditional argument the parameter it
    /// forwards (a `Name` expression).
    pub value: Option<ExprId>,
    pub span: Span,
    /// A comma stood before this argument.
    pub after_comma: bool,
}

/// Storage for the expressions and arguments of one body or one module.
#[derive(Debug, Default, Clone)]
pub struct Arena {
    pub exprs: Vec<Expr>,
    pub lists: Vec<ExprId>,
    pub args: Vec<Arg>,
}

impl Arena {
    pub fn expr(&self, id: ExprId) -> &Expr {
        &self.exprs[id.0 as usize]
    }

    pub fn list(&self, range: ListRange) -> &[ExprId] {
        &self.lists[range.start as usize..(range.start + range.len) as usize]
    }

    pub fn args(&self, range: ArgList) -> &[Arg] {
        &self.args[range.start as usize..(range.start + range.len) as usize]
    }

    pub fn alloc(&mut self, kind: ExprKind, span: Span) -> ExprId {
        self.exprs.push(Expr { kind, span });
        ExprId(self.exprs.len() as u32 - 1)
    }

    pub fn alloc_list(&mut self, items: &[ExprId]) -> ListRange {
        let start = self.lists.len() as u32;
        self.lists.extend_from_slice(items);
        ListRange { start, len: items.len() as u32 }
    }

    pub fn alloc_args(&mut self, args: &[Arg]) -> ArgList {
        let start = self.args.len() as u32;
        self.args.extend_from_slice(args);
        ListRange { start, len: args.len() as u32 }
    }

    /// Drops everything, keeping the allocations for reuse.
    pub fn clear(&mut self) {
        self.exprs.clear();
        self.lists.clear();
        self.args.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hot_node_sizes_are_pinned() {
        assert_eq!(std::mem::size_of::<Expr>(), 24);
        assert_eq!(std::mem::size_of::<Arg>(), 36);
    }
}
