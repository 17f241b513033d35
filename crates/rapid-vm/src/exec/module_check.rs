//! The task's program checked again while it runs (Load, UnLoad, EraseModule, Save,
//! CheckProgRef; `exec/modules.rs`): its diagnostics, the outline of each file, and the
//! code of the modules asked for, compiled as the checker goes through them.

use rapid_sema::{analyze_with, Diagnostic, Options, Program, SourceInput};

use crate::compile::{self, ModuleSource};

/// A program checked, with the outline of each file (as the checker parsed it) and
/// the code of the modules asked for, compiled while the checker went through them.
pub(super) struct Checked {
    pub(super) prog: Program,
    pub(super) diagnostics: Vec<Diagnostic>,
    pub(super) files: Vec<SourceInput>,
    pub(super) parses: Vec<(usize, rapid_syntax::Parse)>,
    pub(super) streamed: compile::Streamed,
}

impl Checked {
    pub(super) fn modules(&self) -> Vec<ModuleSource<'_>> {
        crate::module_sources(&self.files, &self.parses)
    }
}

/// What to compile while checking: modules (indices into the task's modules) against
/// a set of built-ins.
pub(super) type Wanted<'a> = Option<(&'a crate::builtins::Builtins, &'a [usize])>;

/// Checks `files` as one task, compiling the modules `wanted` names as it goes
/// (`compile::StreamCompiler::for_modules`); `Err` when the checker gave up.
pub(super) fn check(
    files: Vec<SourceInput>,
    options: &Options,
    wanted: Wanted<'_>,
) -> Result<Checked, Vec<Diagnostic>> {
    let (analysis, streamed) = match wanted {
        Some((builtins, modules)) => {
            let mut sink = compile::StreamCompiler::for_modules(builtins, &files, modules);
            let analysis = analyze_with(&files, options, Some(&mut sink));
            (analysis, sink.finish())
        }
        None => (analyze_with(&files, options, None), compile::Streamed::default()),
    };
    let Some(prog) = analysis.program else { return Err(analysis.diagnostics) };
    let parses = crate::indexed(analysis.outlines);
    Ok(Checked { prog, diagnostics: analysis.diagnostics, files, parses, streamed })
}
