//! The checker's state: tables, scopes, the file and routine being checked, and the
//! one place diagnostics are pushed.

use rapid_syntax::ast::{Arena, ExprId, ExprKind};
use rapid_syntax::{Span, Symbol};

use crate::body::RoutineCtx;
use crate::codes::{Code, Severity};
use crate::diagnostic::{Diagnostic, SourceInput};
use crate::facts::Denotes;
use crate::symbols::{DataInfo, Def, RoutineInfo, Scopes};
use crate::types::{CoreTypes, TypeId, Types};

/// Diagnostics per file past which a file is reported as hopeless.
pub(crate) const MAX_DIAGNOSTICS_PER_FILE: usize = 500;

/// Names the checker needs to recognise, interned before checking starts.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WellKnown {
    pub(crate) switch: Symbol,
    pub(crate) anytype: Symbol,
    pub(crate) placeholder_id: Symbol,
}

pub(crate) struct Checker<'a> {
    pub(crate) files: &'a [SourceInput],
    pub(crate) types: Types,
    pub(crate) core: CoreTypes,
    pub(crate) known: WellKnown,
    pub(crate) scopes: Scopes,
    pub(crate) datas: Vec<DataInfo>,
    pub(crate) routines: Vec<RoutineInfo>,
    pub(crate) diags: Vec<Diagnostic>,
    /// The file and module (index into all modules) being checked.
    pub(crate) file: usize,
    pub(crate) module: usize,
    pub(crate) ctx: Option<RoutineCtx>,
    /// Reused by each call check: which parameter group each argument filled.
    pub(crate) filled_scratch: Vec<Option<usize>>,
    /// The file of each module.
    pub(crate) module_files: Vec<usize>,
    /// Names of options the system lacks, opaque option types, encrypted modules.
    pub(crate) unknowns: crate::options::Unknowns,
    diags_in_file: usize,
    /// Whether an error has been reported in the current file (the cap's severity).
    errors_in_file: bool,
    /// Whether the cap was told as an error (E0111) in the current file.
    cap_error_told: bool,
    /// `--virtual-io`: a name no declaration defines, where a signal is wanted,
    /// becomes configured signal data of that type ([`crate::Options::virtual_signals`]).
    pub(crate) virtual_signals: bool,
    /// The signal data it declared so, in order.
    pub(crate) virtual_found: Vec<crate::PredefinedData>,
    /// Such names met in the routine being checked: declared when it ends (its own
    /// data is dropped from `datas` then, so global data cannot be added before).
    pub(crate) virtual_pending: Vec<rapid_syntax::Symbol>,
    /// What each of `virtual_pending` will be declared as, in the same order: global
    /// data number `data_mark + k` (the k-th pending), as a compiler sees it already
    /// ([`crate::Tables::data`]).
    pub(crate) virtual_datas: Vec<DataInfo>,
    /// What the body item being checked resolved, for a [`crate::BodySink`].
    pub(crate) facts: crate::facts::ItemFacts,
}

impl<'a> Checker<'a> {
    pub(crate) fn new(files: &'a [SourceInput], known: WellKnown) -> Checker<'a> {
        let error = crate::types::ERROR;
        Checker {
            files,
            types: Types::new(),
            core: CoreTypes {
                num: error,
                dnum: error,
                bool_: error,
                string: error,
                pos: error,
                orient: error,
                errnum: error,
                intnum: error,
            },
            known,
            scopes: Scopes::default(),
            datas: Vec::new(),
            routines: Vec::new(),
            diags: Vec::new(),
            file: 0,
            module: 0,
            ctx: None,
            module_files: Vec::new(),
            filled_scratch: Vec::new(),
            unknowns: Default::default(),
            diags_in_file: 0,
            errors_in_file: false,
            cap_error_told: false,
            virtual_signals: false,
            virtual_found: Vec::new(),
            virtual_pending: Vec::new(),
            virtual_datas: Vec::new(),
            facts: Default::default(),
        }
    }

    /// Switches to another file.
    pub(crate) fn enter(&mut self, file: usize, module: usize) {
        if file != self.file {
            self.diags_in_file = 0;
            self.errors_in_file = false;
            self.cap_error_told = false;
        }
        self.file = file;
        self.module = module;
    }

    /// The text of `span` in the current file.
    pub(crate) fn text(&self, span: Span) -> &'a str {
        span.text(&self.files[self.file].text)
    }

    pub(crate) fn diag(&mut self, code: Code, span: Span, message: String) {
        self.diags_in_file += 1;
        let error = code.severity() == Severity::Error;
        self.errors_in_file |= error;
        if self.diags_in_file < MAX_DIAGNOSTICS_PER_FILE {
            self.diags.push(Diagnostic::new(self.file, code, span, message));
        } else if self.errors_in_file && !self.cap_error_told {
            // The cap is an error only when an error is among what it holds back or
            // shows: a file of many warnings must not fail the check for their number.
            self.cap_error_told = true;
            let message = match self.diags_in_file {
                MAX_DIAGNOSTICS_PER_FILE => {
                    format!("{MAX_DIAGNOSTICS_PER_FILE} diagnostics in this file; reporting stopped here")
                }
                _ => format!("an error beyond the first {MAX_DIAGNOSTICS_PER_FILE} diagnostics of this file"),
            };
            self.diags.push(Diagnostic::new(self.file, Code::TooManyErrors, span, message));
        } else if self.diags_in_file == MAX_DIAGNOSTICS_PER_FILE {
            let message = format!("{MAX_DIAGNOSTICS_PER_FILE} warnings in this file; reporting stopped here");
            self.diags.push(Diagnostic::new(self.file, Code::TooManyWarnings, span, message));
        }
    }

    /// Runs `f` and drops the diagnostics it reports (for work done twice).
    pub(crate) fn with_diagnostics_muted<T>(&mut self, f: impl FnOnce(&mut Self) -> T) -> T {
        let (n_diags, n_in_file) = (self.diags.len(), self.diags_in_file);
        let (errors, told) = (self.errors_in_file, self.cap_error_told);
        let res = f(self);
        self.diags.truncate(n_diags);
        self.diags_in_file = n_in_file;
        (self.errors_in_file, self.cap_error_told) = (errors, told);
        res
    }

    /// Whether an error other than `tolerated` ones was reported since `seen`
    /// diagnostics (moved to the end).
    pub(crate) fn errors_since(&self, seen: &mut usize, tolerated: &[Code]) -> bool {
        let from = (*seen).min(self.diags.len());
        *seen = self.diags.len();
        self.diags[from..].iter().any(|d| d.severity() == Severity::Error && !tolerated.contains(&d.code))
    }

    /// The declarations as a compiler reads them (module-level data only: the data
    /// of the routine being checked is left out).
    pub(crate) fn tables(&self) -> crate::Tables<'_> {
        let globals = self.ctx.as_ref().map_or(self.datas.len(), |ctx| ctx.data_mark);
        crate::Tables {
            types: &self.types,
            core: &self.core,
            datas: &self.datas[..globals],
            pending: &self.virtual_datas,
            routines: &self.routines,
            scopes: &self.scopes,
        }
    }

    pub(crate) fn lookup(&self, sym: Symbol) -> Option<Def> {
        self.scopes.lookup(self.module, sym)
    }

    /// What `def`, found for a name, denotes as the compiler counts: the routine's
    /// own data by its index from the routine's first parameter.
    pub(crate) fn denotes(&self, def: Option<Def>) -> Denotes {
        let mark = self.ctx.as_ref().map_or(usize::MAX, |ctx| ctx.data_mark);
        match def {
            Some(Def::Data(idx)) if idx as usize >= mark => Denotes::Local((idx as usize - mark) as u32),
            Some(def) => Denotes::Decl(def),
            None => Denotes::Nothing,
        }
    }

    /// The global data number pending virtual signal `k` will have: after the
    /// module-level data and the virtual signals declared so far, where the routine's
    /// own data starts now (it is dropped before they are declared).
    pub(crate) fn virtual_data(&self, k: usize) -> Denotes {
        let mark = self.ctx.as_ref().map_or(self.datas.len(), |ctx| ctx.data_mark);
        Denotes::Decl(Def::Data((mark + k) as u32))
    }

    /// Records what name (or call) expression `id` denotes, when facts are recorded.
    pub(crate) fn note_name(&mut self, id: ExprId, def: Option<Def>) {
        if self.facts.recording {
            let denotes = self.denotes(def);
            self.facts.set_name(id, denotes);
        }
    }

    pub(crate) fn data(&self, idx: u32) -> &DataInfo {
        &self.datas[idx as usize]
    }

    pub(crate) fn routine(&self, idx: u32) -> &RoutineInfo {
        &self.routines[idx as usize]
    }

    pub(crate) fn type_name(&self, ty: TypeId) -> String {
        self.types.name(ty).to_string()
    }

    /// The data object at the root of a data reference (`a`, `a{i}`, `a.b{j}.c`), and
    /// whether the reference is the entire object.
    pub(crate) fn reference_root(&self, arena: &Arena, id: ExprId) -> Option<(u32, bool)> {
        let mut cur = id;
        let mut entire = true;
        loop {
            match arena.expr(cur).kind {
                ExprKind::Name(sym) => {
                    return match self.lookup(sym) {
                        Some(Def::Data(data)) => Some((data, entire)),
                        _ => None,
                    };
                }
                ExprKind::Index { base, .. } | ExprKind::Field { base, .. } => {
                    entire = false;
                    cur = base;
                }
                ExprKind::Paren(inner) => cur = inner,
                _ => return None,
            }
        }
    }
}
