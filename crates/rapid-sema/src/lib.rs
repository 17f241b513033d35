//! rapid-sema: name resolution, type checking and the diagnostics of `rapid check`.
//!
//! Invariant: no IO. Files arrive as bytes with a display path; diagnostics leave as
//! data (code, span, message) and are rendered by rapid-cli.
//!
//! Checking runs in two passes so memory stays proportional to declarations, not to
//! code: every file is parsed as an outline (bodies are parsed for their syntax errors
//! and dropped), all declarations are collected, then each routine body is parsed
//! again and checked one top-level item at a time.

pub mod bind;
mod body;
mod calls;
mod checker;
pub mod codes;
mod collect;
mod consteval;
mod decls;
mod diagnostic;
mod expr;
pub mod facts;
mod memory;
mod options;
mod scope;
pub mod symbols;
mod syntax;
pub mod system;
pub mod types;

use std::sync::OnceLock;

use rapid_syntax::ast::{Arena, BodyItem, DataDecl, Item, Routine};
use rapid_syntax::{cap_errors, for_each_body_item, parse_body, parse_outline, Interner, Parse, Span, SyntaxError};

pub use codes::{Code, Severity};
pub use diagnostic::{Diagnostic, SourceInput};
pub use facts::{Denotes, ExprType, ItemFacts};

use checker::Checker;
use collect::ModuleRef;

/// What `check` should do.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Stop after parsing: report lexical and syntax errors only.
    pub syntax_only: bool,
    /// Data the system's configuration declares beyond the catalogue (the I/O signals
    /// of `EIO.cfg`), known in the task like predefined data.
    pub predefined: Vec<PredefinedData>,
    /// `--virtual-io`: a name that nothing declares, used where a signal is wanted
    /// (`SetDO doGrip, 1;`, `WaitDI diStart, 1;`, `DInput(diPart)`), is signal data
    /// of the configuration (of the type its place wants), as it would be on the cell
    /// whose I/O configuration is not at hand. The analysis lists them
    /// ([`Program::virtual_signals`]).
    pub virtual_signals: bool,
    /// The software options the system has, as its backup or manifest names them
    /// (`689-1 Externally Guided Motion (EGM)`, `Arc`); names of the catalogue's
    /// options it lacks are E0217. `None`: nothing says (a loose module), and every
    /// option's names are known.
    pub system_options: Option<Vec<String>>,
}

/// One configured data object: a name and the name of its (built-in) type, such as
/// `diPartReady` of `signaldi`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PredefinedData {
    pub name: String,
    pub type_name: String,
}

/// Checks the modules of one task (one program) together and returns every
/// diagnostic, ordered by file and position.
pub fn check(files: &[SourceInput], options: &Options) -> Vec<Diagnostic> {
    analyze(files, options).diagnostics
}

/// What checking a task found: its diagnostics and, unless only the syntax was
/// checked, the resolved tables the interpreter builds on.
#[derive(Debug)]
pub struct Analysis {
    pub diagnostics: Vec<Diagnostic>,
    pub program: Option<Program>,
    /// Each file's outline as the check parsed it (routine bodies left out; `None`
    /// for an unreadable file), spelled with the program's interner: a compiler goes
    /// on from these instead of parsing every file again.
    pub outlines: Vec<Option<Parse>>,
}

/// The task's declarations, resolved: every type, data object (built-in and
/// module-level; routine data is the interpreter's business) and routine, with the
/// scopes that resolve names and the interner that spelled them.
#[derive(Debug)]
pub struct Program {
    pub interner: Interner,
    pub types: types::Types,
    pub core: types::CoreTypes,
    pub datas: Vec<symbols::DataInfo>,
    pub routines: Vec<symbols::RoutineInfo>,
    /// Built-in, task-global and module-local names (`Scopes::routine` is empty).
    pub scopes: symbols::Scopes,
    /// The file of each module, in module order (the order of `DeclOrigin::Module`).
    pub module_files: Vec<usize>,
    /// The signal data [`Options::virtual_signals`] declared: (name, type name).
    pub virtual_signals: Vec<PredefinedData>,
}

impl Program {
    /// Whether the analysis found errors (warnings allowed).
    pub fn has_errors(diagnostics: &[Diagnostic]) -> bool {
        diagnostics.iter().any(|d| d.severity() == Severity::Error)
    }
}

impl Program {
    /// The declarations a compiler reads.
    pub fn tables(&self) -> Tables<'_> {
        Tables {
            types: &self.types,
            core: &self.core,
            datas: &self.datas,
            pending: &[],
            routines: &self.routines,
            scopes: &self.scopes,
        }
    }
}

/// A task's declarations as a compiler reads them: borrowed from a [`Program`], or
/// from the checker while it works through the routine bodies (a [`BodySink`]).
#[derive(Debug, Clone, Copy)]
pub struct Tables<'a> {
    pub types: &'a types::Types,
    pub core: &'a types::CoreTypes,
    /// Built-in and module-level data (a routine's own data is the compiler's business).
    pub datas: &'a [symbols::DataInfo],
    /// Global data declared once the routine being checked ends, numbered after
    /// `datas`: the signals `--virtual-io` took from it so far
    /// ([`Options::virtual_signals`]). Empty in a finished program's tables.
    pub pending: &'a [symbols::DataInfo],
    pub routines: &'a [symbols::RoutineInfo],
    pub scopes: &'a symbols::Scopes,
}

impl<'a> Tables<'a> {
    /// Global data number `idx`: built-in or module-level data, or a pending one.
    pub fn data(&self, idx: u32) -> Option<&'a symbols::DataInfo> {
        let idx = idx as usize;
        match self.datas.get(idx) {
            Some(data) => Some(data),
            None => self.pending.get(idx - self.datas.len()),
        }
    }
}

/// Receives each routine body while the checker works through it, one top-level item
/// at a time, so that a compiler can compile it then and no body is parsed twice nor
/// held whole. Only bodies checked without error reach it: after the first error
/// (in this body or anywhere before it) no more are handed over.
pub trait BodySink {
    /// A module-level data declaration, checked without error, with what the checker
    /// resolved in it (its initial value). Every one comes before any routine body,
    /// in declaration order (the order of their global numbers).
    fn data(&mut self, _tables: Tables<'_>, _data: DataItem<'_>, _facts: &ItemFacts) {}
    /// Errors that do not stop the stream: what the sink can take with them (a name
    /// that resolves to nothing is `Denotes::Nothing` in the facts). None by default.
    fn tolerated(&self) -> &'static [Code] {
        &[]
    }
    /// The body of the routine declared by item `item` of module `module` (the
    /// indices of [`symbols::DeclOrigin::Module`]), in file `file`, starts.
    fn begin(&mut self, tables: Tables<'_>, file: usize, module: usize, item: usize, routine: &Routine);
    /// One top-level item (declaration, statement, handler keyword) of that body,
    /// checked without error, with what the checker resolved in it.
    fn item(&mut self, tables: Tables<'_>, item: &BodyItem, arena: &Arena, facts: &ItemFacts);
    /// The body ends; `clean` is false when an error was found in it (what the sink
    /// made of it is then to be dropped).
    fn end(&mut self, tables: Tables<'_>, clean: bool);
}

/// A module-level data declaration handed to a [`BodySink`].
#[derive(Debug, Clone, Copy)]
pub struct DataItem<'a> {
    /// The file and module (index of [`symbols::DeclOrigin::Module`]) declaring it.
    pub file: usize,
    pub module: usize,
    /// Its global data number (an index into [`Tables::datas`]).
    pub data: u32,
    pub decl: &'a DataDecl,
    /// The module's arena, which holds its initial value.
    pub arena: &'a Arena,
}

/// Checks a task like [`check`] and keeps the resolved declarations.
pub fn analyze(files: &[SourceInput], options: &Options) -> Analysis {
    analyze_with(files, options, None)
}

/// [`analyze`], handing each routine body to `sink` as it is checked.
pub fn analyze_with(files: &[SourceInput], options: &Options, sink: Option<&mut dyn BodySink>) -> Analysis {
    // The built-in scope is declared once per thread and option set; a syntax check
    // needs only the catalogue's names.
    let scope = (!options.syntax_only).then(|| scope::builtin_scope(options.system_options.as_deref()));
    let mut interner = scope.as_ref().map_or_else(|| catalogue().0.clone(), |scope| scope.interner.clone());
    let mut diags: Vec<Diagnostic> =
        memory::program_memory(files, rapid_limits::PROGRAM_MEMORY_BYTES).into_iter().collect();
    // An encrypted module beside readable ones is part of a task the controller
    // loads whole: it is loaded unread (W0131) and the names it may define are not
    // errors (W0218). Alone, there is nothing to check: E0109.
    let in_task = files.iter().any(|f| f.unreadable.is_none());
    let parses: Vec<Option<Parse>> = files
        .iter()
        .enumerate()
        .map(|(file, input)| match input.unreadable {
            Some(_) if in_task => {
                diags.push(Diagnostic::new(
                    file,
                    Code::EncryptedModuleOpaque,
                    Span::default(),
                    "this is an ABB-encrypted module: it is loaded unread, so the names it defines are unknown here",
                ));
                None
            }
            Some(_) => {
                diags.push(Diagnostic::new(
                    file,
                    Code::EncryptedModule,
                    Span::default(),
                    "this is an ABB-encrypted module; it cannot be read or checked",
                ));
                None
            }
            None => Some(parse_outline(&input.text, &mut interner)),
        })
        .collect();
    let mut syntax_errors: Vec<Vec<SyntaxError>> =
        parses.iter().map(|p| p.as_ref().map_or(Vec::new(), |p| p.errors.clone())).collect();
    let modules: Vec<ModuleRef<'_>> = parses
        .iter()
        .enumerate()
        .filter_map(|(file, parse)| parse.as_ref().map(|p| (file, p)))
        .flat_map(|(file, parse)| parse.file.modules.iter().map(move |module| ModuleRef { file, module }))
        .collect();
    let mut program = None;
    if options.syntax_only {
        for m in &modules {
            for (_, routine) in routines(m) {
                let errors = parse_body(&files[m.file].text, routine.body_span, &mut interner, None);
                syntax_errors[m.file].extend(errors);
            }
        }
    } else if let Some(scope) = scope {
        let mut run = BodyPass { interner: &mut interner, syntax_errors: &mut syntax_errors, sink };
        let ck = check_semantics(files, &modules, &scope, options, &mut run, &mut diags);
        program = Some(Program {
            interner,
            types: ck.types,
            core: ck.core,
            datas: ck.datas,
            routines: ck.routines,
            scopes: ck.scopes,
            module_files: ck.module_files,
            virtual_signals: ck.virtual_found,
        });
    }
    for (file, errors) in syntax_errors.into_iter().enumerate() {
        diags.extend(cap_errors(errors).iter().map(|e| syntax::to_diagnostic(file, e)));
    }
    diags.sort_by_key(|d| (d.file, d.span.start, d.span.end));
    drop(modules);
    Analysis { diagnostics: diags, program, outlines: parses }
}

/// The catalogue, parsed once per process, with the interner that holds its names
/// (frozen: a clone shares them); each check starts from a copy of that interner, so
/// the catalogue's symbols hold.
pub fn catalogue() -> &'static (Interner, rapid_lib::LoadedCatalogue) {
    static BASE: OnceLock<(Interner, rapid_lib::LoadedCatalogue)> = OnceLock::new();
    BASE.get_or_init(|| {
        let mut interner = Interner::default();
        let catalogue = rapid_lib::load(&mut interner);
        (interner.freeze(), catalogue)
    })
}

/// The routines of a module with their item indices.
fn routines<'m>(m: &ModuleRef<'m>) -> impl Iterator<Item = (usize, &'m Routine)> {
    m.module.items.iter().enumerate().filter_map(|(idx, item)| match item {
        Item::Routine(routine) => Some((idx, routine)),
        _ => None,
    })
}

/// What the body pass works with besides the checker.
struct BodyPass<'p, 's> {
    interner: &'p mut Interner,
    syntax_errors: &'p mut [Vec<SyntaxError>],
    sink: Option<&'s mut dyn BodySink>,
}

fn check_semantics<'a>(
    files: &'a [SourceInput],
    modules: &[ModuleRef<'_>],
    scope: &scope::BuiltinScope,
    options: &Options,
    pass: &mut BodyPass<'_, '_>,
    diags: &mut Vec<Diagnostic>,
) -> Checker<'a> {
    let interner = &mut *pass.interner;
    let mut ck = Checker::with_builtins(files, scope);
    ck.unknowns.encrypted = files.iter().filter(|f| f.unreadable.is_some()).map(|f| f.path.clone()).collect();
    ck.declare_predefined(&options.predefined, interner);
    ck.virtual_signals = options.virtual_signals;
    ck.declare_modules(modules);
    // Items go to the sink while nothing so far is an error. A virtual signal is
    // declared when the routine that first names it ends; until then its uses denote
    // it by the number it will have (`Tables::pending`).
    let mut looked = 0;
    let tolerated = pass.sink.as_deref().map_or(&[][..], |sink| sink.tolerated());
    let mut clean =
        !diags.iter().any(|d| d.severity() == Severity::Error) && pass.syntax_errors.iter().all(Vec::is_empty);
    let mut seen = Seen { count: &mut looked, tolerated };
    check_module_items(&mut ck, modules, pass.sink.as_deref_mut(), &mut clean, &mut seen);
    for (idx, m) in modules.iter().enumerate() {
        ck.enter(m.file, idx);
        for (item, routine) in routines(m) {
            ck.begin_routine(routine);
            clean = clean && !seen.errors_in(&ck);
            let mut sink = pass.sink.as_deref_mut().filter(|_| clean);
            if let Some(sink) = sink.as_deref_mut() {
                sink.begin(ck.tables(), m.file, idx, item, routine);
            }
            let text = &files[m.file].text;
            let streamed = sink.is_some();
            let errors = for_each_body_item(text, routine.body_span, pass.interner, |item, arena| {
                // What the item resolves is recorded only for a sink that takes it.
                ck.facts.recording = streamed && clean;
                ck.body_item(item, arena);
                clean = clean && !seen.errors_in(&ck);
                if let Some(sink) = sink.as_deref_mut().filter(|_| clean) {
                    sink.item(ck.tables(), item, arena, &ck.facts);
                }
            });
            ck.facts.recording = false;
            clean = clean && errors.is_empty();
            pass.syntax_errors[m.file].extend(errors);
            ck.end_routine();
            clean = clean && !seen.errors_in(&ck);
            if let Some(sink) = sink {
                sink.end(ck.tables(), clean);
            }
        }
    }
    ck.declare_virtual_signals();
    diags.append(&mut ck.diags);
    ck
}

/// The number of the data item `item` of module `module` declares, searched from
/// `from` on (moved past it): module data is numbered in declaration order.
fn own_data(datas: &[symbols::DataInfo], from: &mut usize, module: usize, item: usize) -> Option<u32> {
    for (idx, data) in datas.iter().enumerate().skip(*from) {
        let symbols::DeclOrigin::Module { module: m, item: i } = data.origin else { continue };
        if (m, i) == (module, item) {
            *from = idx + 1;
            return Some(idx as u32);
        }
        if (m, i) > (module, item) {
            return None;
        }
    }
    None
}

/// The diagnostics the stream has looked at, and the errors it goes on past.
struct Seen<'a> {
    count: &'a mut usize,
    tolerated: &'static [Code],
}

impl Seen<'_> {
    /// Whether `ck` reported an error since the last look, one not tolerated.
    fn errors_in(&mut self, ck: &Checker<'_>) -> bool {
        ck.errors_since(self.count, self.tolerated)
    }
}

/// Module-level declarations: data initialisers and routine headers. Each data
/// declaration checked while nothing so far is an error goes to `sink` with its facts.
fn check_module_items(
    ck: &mut Checker<'_>,
    modules: &[ModuleRef<'_>],
    mut sink: Option<&mut (dyn BodySink + '_)>,
    clean: &mut bool,
    seen: &mut Seen<'_>,
) {
    // The data declared by each item, found going forward: declared in this order.
    let mut own = 0;
    for (idx, m) in modules.iter().enumerate() {
        ck.enter(m.file, idx);
        for (item_idx, item) in m.module.items.iter().enumerate() {
            match item {
                Item::Data(decl) => {
                    let Some(symbols::Def::Data(data)) = ck.scopes.lookup_module_level(idx, decl.name.sym) else {
                        continue;
                    };
                    // A global PERS declared before in the task is what its name
                    // finds; the sink compiles the declaration's own data.
                    let declared = own_data(&ck.datas, &mut own, idx, item_idx);
                    let arena = &m.module.arena;
                    *clean = *clean && !seen.errors_in(ck);
                    let streamed = sink.is_some() && *clean;
                    if streamed {
                        ck.facts.recording = true;
                        ck.facts.start(arena.exprs.len(), arena.args.len());
                    }
                    ck.check_data_decl(decl, arena, data, false);
                    ck.facts.recording = false;
                    *clean = *clean && !seen.errors_in(ck);
                    if let (Some(sink), Some(data)) = (sink.as_deref_mut().filter(|_| streamed && *clean), declared) {
                        let item = DataItem { file: m.file, module: idx, data, decl, arena };
                        sink.data(ck.tables(), item, &ck.facts);
                    }
                }
                Item::Routine(routine) => ck.check_routine_header(routine),
                _ => {}
            }
        }
    }
    // Sized for a module's arena, the largest: not kept for the bodies' items.
    if sink.is_some() {
        ck.facts = Default::default();
    }
}
