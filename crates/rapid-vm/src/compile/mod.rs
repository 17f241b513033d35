//! From checked syntax trees to `Code`: names become slots, data references become
//! places, calls become call sites, statements become jumps (§1.1–§1.5).
//!
//! The compiler is the checker's `rapid_sema::BodySink` (`stream.rs`): each item comes
//! with what the checker resolved in it (`rapid_sema::ItemFacts`: what each name and
//! call denotes, the parameter of each argument, the type of each expression), and
//! the compiler resolves nothing itself. The program has no errors, so it trusts
//! types and arity; what it cannot run yet it refuses with a clear message.

mod body;
pub(crate) mod call;
mod expr;
mod kernel;
mod stmt;
mod stream;

pub use stream::{StreamCompiler, Streamed};

use rapid_sema::symbols::{DataKind, DeclOrigin, Def};
use rapid_sema::types::{Atomic, TypeId, TypeKind, Types};
use rapid_sema::{ItemFacts, Program, Tables};
use rapid_syntax::ast::{Arena, DataDecl, Item, Module, ParamMode, Routine, Section};
use rapid_syntax::{Span, Symbol};
use rustc_hash::FxHashMap;

use crate::ir::{Code, Instr};
use crate::value::{Array, Opaque, OpaqueState, Record, Value};

/// A construct the interpreter cannot run yet, or a program it cannot load.
#[derive(Debug, Clone, PartialEq)]
pub struct CompileError {
    pub file: usize,
    pub span: Span,
    pub message: String,
}

/// One module's syntax tree with the file it came from.
pub struct ModuleSource<'a> {
    pub file: usize,
    pub text: &'a str,
    pub module: &'a Module,
}

/// Everything compiled: one `Code` per user routine (indexed like
/// `Program::routines`, `None` for built-ins) and the code that gives every global
/// its initial value.
pub struct Compiled {
    pub routines: Vec<Option<Code>>,
    pub init: Code,
    pub global_defaults: Vec<Value>,
}

/// What a local slot holds.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Local {
    pub(crate) slot: u32,
    pub(crate) ty: TypeId,
    pub(crate) rank: u8,
    pub(crate) dims: [u32; 3],
    pub(crate) kind: LocalKind,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum LocalKind {
    Param { mode: ParamMode, optional: bool },
    Data,
    LoopVar,
    Temp,
}

/// Puts together every user routine and the global initialisers, as they were compiled
/// while the checker worked through the program (`streamed`, from a
/// [`StreamCompiler`]): the compiler resolves nothing itself.
pub fn compile(
    prog: &Program,
    modules: &[ModuleSource<'_>],
    builtins: &crate::builtins::Builtins,
    mut streamed: Streamed,
) -> Result<Compiled, Vec<CompileError>> {
    let mut errors = Vec::new();
    for data in &prog.datas {
        if let Some(n) = too_many_elements(&data.dims[..data.rank as usize]) {
            let span = match data.origin {
                DeclOrigin::Module { module, item } => {
                    modules.get(module).and_then(|m| m.module.items.get(item)).map(item_span)
                }
                _ => None,
            };
            let file = match data.origin {
                DeclOrigin::Module { module, .. } => modules.get(module).map_or(usize::MAX, |m| m.file),
                _ => usize::MAX,
            };
            errors.push(CompileError {
                file,
                span: span.unwrap_or_default(),
                message: array_too_large(&data.display, n),
            });
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let global_defaults: Vec<Value> =
        prog.datas.iter().map(|d| default_value(prog, d.ty, &d.dims[..d.rank as usize])).collect();
    let init = match streamed.take_init() {
        Some((state, mut init_errors)) => {
            errors.append(&mut init_errors);
            state
        }
        // No module data has an initial value: the catalogue's alone.
        None => catalogue_init(prog.tables(), builtins, &mut errors),
    };
    let init = finish_init(prog.tables(), builtins, init);
    let mut routines: Vec<Option<Code>> = vec![None; prog.routines.len()];
    for (idx, info) in prog.routines.iter().enumerate() {
        let DeclOrigin::Module { module, .. } = info.origin else { continue };
        match streamed.take(idx) {
            Some(Ok(code)) => routines[idx] = Some(code),
            Some(Err(mut errs)) => errors.append(&mut errs),
            None => errors.push(not_streamed(modules, module, &info.display)),
        }
    }
    if errors.is_empty() {
        Ok(Compiled { routines, init, global_defaults })
    } else {
        Err(errors)
    }
}

/// One module linked into a running task: its routines and data by their indices in
/// the program, and the code giving that data its initial values.
pub struct CompiledModule {
    pub routines: Vec<(u32, Code)>,
    pub init: Code,
    /// The data's values before `init` runs.
    pub defaults: Vec<(u32, Value)>,
}

/// Compiles module `module` (an index into `modules`) of a program that is already
/// running: only its routines and its data's initial values (Load, WaitLoad), as
/// the checker's stream compiled them ([`StreamCompiler::for_modules`]).
pub fn compile_module(
    prog: &Program,
    modules: &[ModuleSource<'_>],
    module: usize,
    builtins: &crate::builtins::Builtins,
    streamed: &mut Streamed,
) -> Result<CompiledModule, Vec<CompileError>> {
    let mut errors = Vec::new();
    let mine = |origin: DeclOrigin| matches!(origin, DeclOrigin::Module { module: m, .. } if m == module);
    let mut defaults = Vec::new();
    for (idx, data) in prog.datas.iter().enumerate().filter(|(_, d)| mine(d.origin)) {
        let dims = &data.dims[..data.rank as usize];
        if let Some(n) = too_many_elements(dims) {
            let span = modules.get(module).map_or(Span::default(), |m| m.module.span);
            let file = modules.get(module).map_or(usize::MAX, |m| m.file);
            errors.push(CompileError { file, span, message: array_too_large(&data.display, n) });
            continue;
        }
        defaults.push((idx as u32, default_value(prog, data.ty, dims)));
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let init = match streamed.take_module_init(module) {
        Some((state, mut init_errors)) => {
            errors.append(&mut init_errors);
            finish_init(prog.tables(), builtins, state)
        }
        None => finish_init(prog.tables(), builtins, load_state()),
    };
    let mut routines = Vec::new();
    for (idx, info) in prog.routines.iter().enumerate().filter(|(_, r)| mine(r.origin)) {
        match streamed.take(idx) {
            Some(Ok(code)) => routines.push((idx as u32, code)),
            Some(Err(mut errs)) => errors.append(&mut errs),
            None => errors.push(not_streamed(modules, module, &info.display)),
        }
    }
    if errors.is_empty() {
        Ok(CompiledModule { routines, init, defaults })
    } else {
        Err(errors)
    }
}

/// A routine the checker did not hand over: it stopped at an error before it (one
/// the stream does not go past), so the task does not load.
fn not_streamed(modules: &[ModuleSource<'_>], module: usize, name: &str) -> CompileError {
    CompileError {
        file: modules.get(module).map_or(usize::MAX, |m| m.file),
        span: Span::default(),
        message: format!("`{name}` was not compiled: the program does not check"),
    }
}

/// The load code before anything is compiled into it.
pub(crate) fn load_state() -> RoutineState {
    let mut st = RoutineState::new(usize::MAX);
    st.code.name = "<load>".into();
    st
}

/// The start of the code run at load: the initial values of predefined (catalogue)
/// data, in order. They are literals (the catalogue's declarations), so nothing in
/// them is resolved.
pub(crate) fn catalogue_init(
    prog: Tables<'_>,
    builtins: &crate::builtins::Builtins,
    errors: &mut Vec<CompileError>,
) -> RoutineState {
    let (_, catalogue) = rapid_sema::catalogue();
    let mut init = RoutineCompiler::new(prog, builtins, usize::MAX, &catalogue.text);
    init.st = load_state();
    for (idx, data) in prog.datas.iter().enumerate() {
        let DeclOrigin::Builtin(item) = data.origin else { continue };
        let Some(Item::Data(decl)) = catalogue.module.items.get(item) else { continue };
        let Some(value) = decl.init else { continue };
        init.data_init(idx as u32, value, &catalogue.module.arena, errors);
    }
    init.st
}

/// The code run at load, its initial values compiled in `init`.
fn finish_init(prog: Tables<'_>, builtins: &crate::builtins::Builtins, init: RoutineState) -> Code {
    let mut rc = RoutineCompiler { prog, builtins, file: usize::MAX, text: "", facts: None, st: init };
    rc.st.code.emit(Instr::Return);
    rc.finish_locals();
    rc.st.code
}

/// Arrays may hold at most this many elements (the one table of limits; the checker
/// refuses bigger ones first, E0313, so this guards programs that bypass it).
pub const MAX_ARRAY_ELEMENTS: u64 = rapid_limits::ARRAY_ELEMENTS;

/// The element count of an array with `dims` when it is over the limit.
fn too_many_elements(dims: &[u32]) -> Option<f64> {
    let sizes: Vec<f64> = dims.iter().map(|&d| f64::from(d.max(1))).collect();
    let n = rapid_limits::array_elements(&sizes);
    (n > MAX_ARRAY_ELEMENTS as f64).then_some(n)
}

fn array_too_large(name: &str, n: f64) -> String {
    rapid_limits::array_too_large(name, n)
}

fn item_span(item: &Item) -> Span {
    match item {
        Item::Data(decl) => decl.span,
        Item::Routine(routine) => routine.span,
        Item::Type(def) => def.span,
        Item::Placeholder(_, span) => *span,
    }
}

/// The value data of type `ty` has before anything is assigned (§1.2.2): 0, "",
/// FALSE, records of such values, arrays of them.
pub fn default_value(prog: &Program, ty: TypeId, dims: &[u32]) -> Value {
    default_of(&prog.types, ty, dims)
}

/// [`default_value`] with the program's types.
fn default_of(types: &Types, ty: TypeId, dims: &[u32]) -> Value {
    if let Some((&n, inner)) = dims.split_first() {
        let n = n.max(1);
        let elems = (0..n).map(|_| default_of(types, ty, inner)).collect();
        let mut all = [0u32; 3];
        all[..dims.len()].copy_from_slice(dims);
        return flatten_array(Array { dims: all, elems });
    }
    let canon = types.canonical(ty);
    match &types.info(canon).kind {
        TypeKind::Atomic(Atomic::Num) => Value::Num(0.0),
        TypeKind::Atomic(Atomic::Dnum) => Value::Dnum(0.0),
        TypeKind::Atomic(Atomic::Bool) => Value::Bool(false),
        TypeKind::Atomic(Atomic::String) => Value::Str("".into()),
        TypeKind::Record(fields) => Value::Record(std::rc::Rc::new(Record {
            ty: canon,
            fields: fields.iter().map(|f| default_of(types, f.ty, &[])).collect(),
        })),
        // Signal data: not connected to an I/O signal until AliasIO (or the I/O
        // configuration) connects it.
        TypeKind::SemiValue(_) => Value::Opaque(Box::new(Opaque { ty: canon, state: OpaqueState::None })),
        _ => Value::Opaque(Box::new(Opaque { ty: canon, state: OpaqueState::None })),
    }
}

/// Nested arrays (rows of rows) become one array with up to three dimensions.
pub fn flatten_array(array: Array) -> Value {
    let rows_are_arrays = array.elems.first().is_some_and(|e| matches!(e, Value::Array(_)));
    if !rows_are_arrays {
        return Value::Array(Box::new(array));
    }
    let mut dims = [array.elems.len() as u32, 0, 0];
    let mut elems = Vec::new();
    for row in array.elems {
        if let Value::Array(row) = row {
            dims[1] = row.dims[0];
            dims[2] = row.dims[1];
            elems.extend(row.elems);
        }
    }
    Value::Array(Box::new(Array { dims, elems }))
}

/// Compiles one routine.
pub(crate) struct RoutineCompiler<'p> {
    pub(crate) prog: Tables<'p>,
    /// The built-ins call sites are resolved in (the set the task runs with).
    pub(crate) builtins: &'p crate::builtins::Builtins,
    pub(crate) file: usize,
    pub(crate) text: &'p str,
    /// What the checker resolved in the body item being compiled, when it streams it.
    pub(crate) facts: Option<&'p ItemFacts>,
    /// Everything the compiler owns of the routine (kept whole while a streamed
    /// routine waits between items, `stream.rs`).
    pub(crate) st: RoutineState,
}

/// What a routine's compilation owns, apart from what it borrows of the program.
pub(crate) struct RoutineState {
    pub(crate) code: Code,
    /// The routine's own data (parameters, data declarations, FOR variables) in the
    /// order they are declared: the checker's numbering (`rapid_sema::Denotes::Local`).
    pub(crate) own_data: Vec<Local>,
    pub(crate) labels: FxHashMap<Symbol, u32>,
    pub(crate) gotos: Vec<(u32, Symbol, Span)>,
    pub(crate) n_locals: u32,
    pub(crate) local_types: Vec<(TypeId, [u32; 3], u8)>,
    pub(crate) ret_ty: Option<TypeId>,
    /// Nesting depth of the statement being compiled.
    pub(crate) stmt_depth: u16,
    /// Jumps to the end of the construct being compiled (patched when it ends).
    pub(crate) exits: Vec<u32>,
    /// Signal data is being passed to a parameter that takes the signal itself (a
    /// signal parameter, AliasIO): load it without reading the signal's value.
    pub(crate) signal_as_data: bool,
    /// The FOR and WHILE loops around the statement being compiled, innermost last
    /// (Break and Continue jump out of or back into the innermost one).
    pub(crate) loops: Vec<LoopJumps>,
    /// The part of the routine being compiled: the body or one of its handlers.
    pub(crate) section: Section,
    /// The shapes of the packed constant aggregates, each stored once.
    pub(crate) shapes: FxHashMap<Box<[crate::packed::Node]>, u32>,
    /// The call sites made so far, with what their arguments name (ArgName): an
    /// identical call reuses its site.
    pub(crate) sites_seen: FxHashMap<SiteKey, u32>,
}

impl RoutineState {
    /// Nothing compiled yet, of a routine in file `file`.
    fn new(file: usize) -> RoutineState {
        RoutineState {
            code: Code { file, ..Code::default() },
            own_data: Vec::new(),
            labels: FxHashMap::default(),
            gotos: Vec::new(),
            n_locals: 0,
            local_types: Vec::new(),
            ret_ty: None,
            stmt_depth: 0,
            exits: Vec::new(),
            signal_as_data: false,
            loops: Vec::new(),
            section: Section::Body,
            shapes: FxHashMap::default(),
            sites_seen: FxHashMap::default(),
        }
    }
}

/// A call site with the origins of its arguments (ArgName), when recorded.
pub(crate) type SiteKey = (crate::ir::CallSite, Option<Box<[crate::ir::ArgOrigin]>>);

/// A loop's Break and Continue jumps, patched when the loop's code is complete.
#[derive(Debug, Default)]
pub(crate) struct LoopJumps {
    pub(crate) breaks: Vec<u32>,
    pub(crate) continues: Vec<u32>,
}

impl<'p> RoutineCompiler<'p> {
    pub(crate) fn new(
        prog: Tables<'p>,
        builtins: &'p crate::builtins::Builtins,
        file: usize,
        text: &'p str,
    ) -> RoutineCompiler<'p> {
        RoutineCompiler { prog, builtins, file, text, facts: None, st: RoutineState::new(file) }
    }

    pub(crate) fn error(&self, span: Span, message: impl Into<String>) -> CompileError {
        CompileError { file: self.file, span, message: message.into() }
    }

    pub(crate) fn unsupported(&self, span: Span, what: &str) -> CompileError {
        self.error(span, format!("{what} is not supported by `rapid run` yet"))
    }

    /// A fresh local slot of the given type.
    pub(crate) fn new_local(&mut self, ty: TypeId, dims: [u32; 3], rank: u8, kind: LocalKind) -> Local {
        let slot = self.st.n_locals;
        self.st.n_locals += 1;
        self.st.local_types.push((ty, dims, rank));
        Local { slot, ty, rank, dims, kind }
    }

    /// Fills in the slot count and the default values of non-parameter locals.
    pub(crate) fn finish_locals(&mut self) {
        self.st.code.n_locals = self.st.n_locals;
        let n_params = self.st.code.n_params as usize;
        self.st.code.local_defaults = self.st.local_types[n_params..]
            .iter()
            .map(|(ty, dims, rank)| default_of(self.prog.types, *ty, &dims[..*rank as usize]))
            .collect();
    }

    /// What name expression `id` denotes: what the checker found (nothing when it
    /// found nothing, or compiled no facts: the catalogue's literals).
    pub(crate) fn name(&self, id: rapid_syntax::ast::ExprId) -> Option<Resolved> {
        self.facts.and_then(|facts| facts.name(id)).and_then(|denotes| self.denoted(denotes))
    }

    /// What the checker's `denotes` is here.
    pub(crate) fn denoted(&self, denotes: rapid_sema::Denotes) -> Option<Resolved> {
        match denotes {
            rapid_sema::Denotes::Nothing => None,
            rapid_sema::Denotes::Local(n) => self.st.own_data.get(n as usize).map(|local| Resolved::Local(*local)),
            rapid_sema::Denotes::Decl(Def::Data(idx)) => Some(Resolved::Global(idx)),
            rapid_sema::Denotes::Decl(Def::Routine(idx)) => Some(Resolved::Routine(idx)),
            rapid_sema::Denotes::Decl(Def::Type(_)) => Some(Resolved::Type),
        }
    }

    /// The routine's parameters, `params` as the checker declared them (placeholders
    /// left out, as here).
    pub(crate) fn declare_params(&mut self, routine: &Routine, params: &[rapid_sema::symbols::ParamInfo]) {
        let declared = routine.params.iter().filter(|p| p.placeholder.is_none());
        for (param, info) in declared.zip(params) {
            // A type that resolves to nothing is taken as a switch (what the compiler
            // did when it looked the name up itself); such a routine does not check.
            let ty = if info.ty == rapid_sema::types::ERROR { rapid_sema::types::SWITCH } else { info.ty };
            let kind = LocalKind::Param { mode: param.mode, optional: param.optional };
            let local = self.new_local(ty, [0; 3], param.rank, kind);
            self.st.own_data.push(local);
            self.st.code.local_names.push((param.name.span.text(self.text).to_owned(), local.slot));
            let by_ref = param.mode != ParamMode::In;
            self.st.code.param_by_ref.push(by_ref);
            self.st.code.param_meta.push(crate::ir::ParamMeta {
                name: param.name.span.text(self.text).to_ascii_lowercase().into(),
                optional: param.optional,
                switch: ty == rapid_sema::types::SWITCH,
                group: param.group,
            });
            self.st.code.param_likes.push(if by_ref { None } else { numeric_like(self.prog.types, ty, param.rank) });
        }
        self.st.code.n_params = self.st.n_locals;
    }

    fn routine_data(&mut self, decl: &DataDecl, arena: &Arena) -> Result<(), CompileError> {
        let Some(ty) = self.facts.and_then(|facts| facts.declared()) else {
            return Err(self.error(decl.ty.span, "unknown data type"));
        };
        let mut dims = [0u32; 3];
        for (slot, &dim) in dims.iter_mut().zip(&decl.dims) {
            *slot = self.const_dim(arena, dim)?;
        }
        let rank = decl.dims.len().min(3) as u8;
        if let Some(n) = too_many_elements(&dims[..rank as usize]) {
            return Err(self.error(decl.span, array_too_large(decl.name.span.text(self.text), n)));
        }
        let local = self.new_local(ty, dims, rank, LocalKind::Data);
        self.st.own_data.push(local);
        self.st.code.local_names.push((decl.name.span.text(self.text).to_owned(), local.slot));
        if decl.storage == rapid_syntax::ast::Storage::Const {
            self.st.code.const_locals.push(local.slot);
        }
        if let Some(init) = decl.init {
            self.expr(arena, init, Some((ty, dims)))?;
            self.st.code.emit(Instr::StoreLocal(local.slot));
        }
        Ok(())
    }

    /// Code storing the initial value `value` (in `arena`) of global data `data`
    /// into it, in the load code being compiled.
    pub(crate) fn data_init(
        &mut self,
        data: u32,
        value: rapid_syntax::ast::ExprId,
        arena: &Arena,
        errors: &mut Vec<CompileError>,
    ) {
        self.st.code.file = self.file;
        let Some(info) = self.prog.data(data) else { return };
        match self.expr(arena, value, Some((info.ty, info.dims))) {
            Ok(()) => {
                self.st.code.emit(Instr::StoreGlobal(data));
            }
            Err(e) => errors.push(e),
        }
    }

    fn const_dim(&self, arena: &Arena, dim: rapid_syntax::ast::ExprId) -> Result<u32, CompileError> {
        let expr = arena.expr(dim);
        let value = match expr.kind {
            rapid_syntax::ast::ExprKind::Num => rapid_syntax::literal::num_value(expr.span.text(self.text)),
            rapid_syntax::ast::ExprKind::Name(_) => match self.name(dim) {
                Some(Resolved::Global(idx)) => self.prog.data(idx).and_then(|d| d.const_value),
                _ => None,
            },
            _ => None,
        };
        match value {
            Some(v) if v >= 1.0 && v.fract() == 0.0 => Ok(v as u32),
            _ => Err(self.unsupported(expr.span, "an array dimension computed from an expression")),
        }
    }

    pub(crate) fn handler_number(&self, arena: &Arena, id: rapid_syntax::ast::ExprId) -> Option<i32> {
        let expr = arena.expr(id);
        match expr.kind {
            rapid_syntax::ast::ExprKind::Num => {
                rapid_syntax::literal::num_value(expr.span.text(self.text)).map(|v| v as i32)
            }
            rapid_syntax::ast::ExprKind::Name(_) => match self.name(id) {
                Some(Resolved::Global(idx)) => {
                    let data = self.prog.data(idx)?;
                    if data.kind == DataKind::Const {
                        data.const_value.map(|v| v as i32).or(Some(-(idx as i32) - 1))
                    } else {
                        Some(-(idx as i32) - 1)
                    }
                }
                _ => None,
            },
            _ => None,
        }
    }

    pub(crate) fn resolve_gotos(&mut self, errors: &mut Vec<CompileError>) {
        for (at, label, span) in std::mem::take(&mut self.st.gotos) {
            match self.st.labels.get(&label) {
                Some(&target) => self.st.code.patch(at, target),
                None => errors.push(self.error(span, "GOTO to an undefined label")),
            }
        }
    }
}

/// A zero of type `ty` when it is num or dnum (the kind arguments convert to).
fn numeric_like(types: &Types, ty: TypeId, rank: u8) -> Option<Value> {
    if rank > 0 {
        return None;
    }
    match types.atomic(ty) {
        Some(Atomic::Num) => Some(Value::Num(0.0)),
        Some(Atomic::Dnum) => Some(Value::Dnum(0.0)),
        _ => None,
    }
}

/// What a name resolves to while compiling a routine.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Resolved {
    Local(Local),
    Global(u32),
    Routine(u32),
    Type,
}
