//! Routines compiled while the checker works through their bodies: the compiler is the
//! checker's `rapid_sema::BodySink`, so each body is parsed once (by the checker) and
//! compiled item by item as each item is checked, never held whole. The module data's
//! initial values come the same way, before the bodies, into the load code. Modules
//! linked at run time are compiled so too (`StreamCompiler::for_modules`): only the
//! modules asked for, each with load code of its own.
//!
//! The checker lends its tables for one call at a time, so the routine being compiled
//! is kept between items as its own state, without the tables
//! ([`RoutineState`]).

use rapid_sema::{BodySink, DataItem, ItemFacts, SourceInput, Tables};
use rapid_syntax::ast::{Arena, BodyItem, Routine};
use rustc_hash::FxHashMap;

use super::{CompileError, RoutineCompiler, RoutineState};
use crate::builtins::Builtins;
use crate::ir::Code;

/// What each routine compiled in the stream came to, by its index in the program.
#[derive(Default)]
pub struct Streamed {
    routines: FxHashMap<usize, Result<Code, Vec<CompileError>>>,
    /// The load code as far as the module data's initial values streamed, with the
    /// errors met compiling them.
    init: Option<(RoutineState, Vec<CompileError>)>,
    /// For modules linked at run time: each wanted module's load code of its own.
    module_inits: FxHashMap<usize, (RoutineState, Vec<CompileError>)>,
}

impl Streamed {
    /// How many routines were compiled in the stream.
    pub fn len(&self) -> usize {
        self.routines.len()
    }

    pub fn is_empty(&self) -> bool {
        self.routines.is_empty()
    }

    /// Whether the module data's initial values were compiled in the stream.
    pub fn has_init(&self) -> bool {
        self.init.is_some()
    }

    /// What routine `idx` came to, when it was compiled in the stream.
    pub(crate) fn take(&mut self, idx: usize) -> Option<Result<Code, Vec<CompileError>>> {
        self.routines.remove(&idx)
    }

    /// The load code compiled in the stream, when a module data's initial value was.
    pub(crate) fn take_init(&mut self) -> Option<(RoutineState, Vec<CompileError>)> {
        self.init.take()
    }

    /// The load code of module `module` compiled in the stream (modules linked at run
    /// time), when one of its data has an initial value.
    pub(crate) fn take_module_init(&mut self, module: usize) -> Option<(RoutineState, Vec<CompileError>)> {
        self.module_inits.remove(&module)
    }
}

/// Compiles the routines the checker hands over (see the module doc).
pub struct StreamCompiler<'a> {
    builtins: &'a Builtins,
    files: &'a [SourceInput],
    /// The index of each user routine by its declaration (module, item).
    by_origin: Option<FxHashMap<(usize, usize), usize>>,
    current: Option<Current>,
    done: Streamed,
    /// The modules whose code is wanted, each with load code of its own (modules
    /// linked at run time, `for_modules`); `None`: the whole task, with one load code.
    only: Option<&'a [usize]>,
}

/// The routine being compiled.
struct Current {
    idx: usize,
    file: usize,
    /// Taken out while an item is compiled.
    state: Option<RoutineState>,
    errors: Vec<CompileError>,
}

impl<'a> StreamCompiler<'a> {
    pub fn new(builtins: &'a Builtins, files: &'a [SourceInput]) -> StreamCompiler<'a> {
        StreamCompiler { builtins, files, by_origin: None, current: None, done: Streamed::default(), only: None }
    }

    /// Compiles modules `modules` (indices into the task's modules) of a task that is
    /// already running, each with its own load code (Load, WaitLoad).
    pub fn for_modules(builtins: &'a Builtins, files: &'a [SourceInput], modules: &'a [usize]) -> StreamCompiler<'a> {
        StreamCompiler { only: Some(modules), ..StreamCompiler::new(builtins, files) }
    }

    /// Whether module `module`'s code is wanted.
    fn wants(&self, module: usize) -> bool {
        self.only.is_none_or(|only| only.contains(&module))
    }

    /// The routines compiled so far.
    pub fn finish(self) -> Streamed {
        self.done
    }

    /// Runs `f` on the routine being compiled, lent the checker's tables for the call.
    fn with_current<'t, T>(
        &mut self,
        tables: Tables<'t>,
        facts: Option<&'t ItemFacts>,
        f: impl FnOnce(&mut RoutineCompiler<'_>, &mut Vec<CompileError>) -> T,
    ) -> Option<T> {
        let current = self.current.as_mut()?;
        let text = &self.files.get(current.file)?.text;
        let st = current.state.take()?;
        let file = current.file;
        let mut rc = RoutineCompiler { prog: tables, builtins: self.builtins, file, text, facts, st };
        let res = f(&mut rc, &mut current.errors);
        current.state = Some(rc.st);
        Some(res)
    }
}

impl BodySink for StreamCompiler<'_> {
    fn data(&mut self, tables: Tables<'_>, data: DataItem<'_>, facts: &ItemFacts) {
        let Some(value) = data.decl.init else { return };
        let Some(source) = self.files.get(data.file) else { return };
        if !self.wants(data.module) {
            return;
        }
        let init = match self.only {
            None => self.done.init.take(),
            Some(_) => self.done.module_inits.remove(&data.module),
        };
        let (st, mut errors) = init.unwrap_or_else(|| {
            let mut errors = Vec::new();
            let st = match self.only {
                // The task's load code starts with the catalogue's data.
                None => super::catalogue_init(tables, self.builtins, &mut errors),
                Some(_) => super::load_state(),
            };
            (st, errors)
        });
        let (file, text) = (data.file, source.text.as_str());
        let mut rc = RoutineCompiler { prog: tables, builtins: self.builtins, file, text, facts: Some(facts), st };
        rc.data_init(data.data, value, data.arena, &mut errors);
        match self.only {
            None => self.done.init = Some((rc.st, errors)),
            Some(_) => _ = self.done.module_inits.insert(data.module, (rc.st, errors)),
        }
    }

    /// A module linked at run time goes on past data and types that resolve to
    /// nothing, as `compile_module` did without the stream: a routine naming them does
    /// not compile, which refuses the module (`exec/modules.rs`).
    fn tolerated(&self) -> &'static [rapid_sema::Code] {
        match self.only {
            Some(_) => &[rapid_sema::Code::UndefinedData, rapid_sema::Code::UndefinedType],
            None => &[],
        }
    }

    fn begin(&mut self, tables: Tables<'_>, file: usize, module: usize, item: usize, routine: &Routine) {
        self.current = None;
        if !self.wants(module) {
            return;
        }
        let by_origin = self.by_origin.get_or_insert_with(|| {
            let origins = tables.routines.iter().enumerate().filter_map(|(idx, info)| match info.origin {
                rapid_sema::symbols::DeclOrigin::Module { module, item } => Some(((module, item), idx)),
                _ => None,
            });
            origins.collect()
        });
        let Some(&idx) = by_origin.get(&(module, item)) else { return };
        let Some(source) = self.files.get(file) else { return };
        let mut rc = RoutineCompiler::new(tables, self.builtins, file, &source.text);
        let info = &tables.routines[idx];
        rc.header(routine, info.ret);
        rc.declare_params(routine, &info.params);
        let state = Some(rc.st);
        self.current = Some(Current { idx, file, state, errors: Vec::new() });
    }

    fn item(&mut self, tables: Tables<'_>, item: &BodyItem, arena: &Arena, facts: &ItemFacts) {
        self.with_current(tables, Some(facts), |rc, errors| rc.body_item(item, arena, errors));
    }

    fn end(&mut self, tables: Tables<'_>, clean: bool) {
        let compiled = self.with_current(tables, None, |rc, errors| rc.finish_routine(std::mem::take(errors)));
        let Some(current) = self.current.take() else { return };
        if let (Some(compiled), true) = (compiled, clean) {
            self.done.routines.insert(current.idx, compiled);
        }
    }
}
