//! Findings about a system of tasks as a whole, which no one task's check can see:
//! a global persistent declared differently in two tasks (E0703), an event routine a
//! task it runs in lacks (E0704), a task's entry routine the task lacks (E0705; the
//! first task's too, unless `rapid run --entry` gives it another).
//!
//! `rapid check` reports them with the other diagnostics; `rapid run` refuses to start
//! a system with any of them and shows the same diagnostics, so both name one place.
//! Each task's part is taken from its checked program ([`facts`]) and then dropped.

use crate::symbols::{DataKind, DeclOrigin, Def};
use crate::types::ERROR;
use crate::{Code, Diagnostic, Program, SourceInput};
use rapid_config::sys::{Sys, Task};
use rapid_syntax::ast::RoutineKind;
use rapid_syntax::Span;
use rustc_hash::FxHashMap;

/// What the system findings need of one task's checked program.
#[derive(Debug, Default)]
pub struct TaskFacts {
    /// The lower-case names of the task's procedures, of any scope: an event routine
    /// may be any of them (the interpreter finds a procedure of any scope by name).
    procedures: Vec<String>,
    /// The lower-case names of the task's global procedures: an entry routine is looked
    /// up among the task's global names (`rapid_vm::load_with`).
    entries: Vec<String>,
    /// The task's global persistents (neither LOCAL nor TASK), the first declaration of
    /// each name, in the order of the files.
    persistents: Vec<Persistent>,
}

/// One global persistent as a task declares it.
#[derive(Debug)]
struct Persistent {
    name: String,
    type_name: String,
    /// Array sizes, all 0 for a scalar (as `rapid_vm::SharedPers` has them).
    dims: [u32; 3],
    /// The task's file (an index into its modules) and the name's place in it.
    file: usize,
    span: Span,
}

/// One task of the system with its program's facts.
pub struct TaskProgram<'a> {
    pub name: &'a str,
    /// Where the task's modules start in the table the diagnostics index.
    pub file_offset: usize,
    pub facts: &'a TaskFacts,
    /// The command line gave the task its entry routine (`rapid run --entry`, the first
    /// task's): the configured one is not looked for.
    pub entry_given: bool,
}

/// Where the system's description is: its index in the diagnostics' table and its text
/// (SYS.cfg or the manifest; the spans of [`Sys`] are in it).
#[derive(Clone, Copy)]
pub struct ConfigFile<'a> {
    pub file: usize,
    pub text: &'a str,
}

impl<'a> ConfigFile<'a> {
    /// The file `sys` was read from, found in `table`.
    pub fn of(sys_file: Option<usize>, table: &[&'a SourceInput]) -> Option<ConfigFile<'a>> {
        let file = sys_file?;
        Some(ConfigFile { file, text: &table.get(file)?.text })
    }
}

/// The facts of a task's checked program.
pub fn facts(program: &Program) -> TaskFacts {
    let user_procs = program.routines.iter().filter(|r| r.chapter.is_none() && r.kind == RoutineKind::Proc);
    let procedures = user_procs.map(|r| r.display.to_lowercase()).collect();
    let mut entries = Vec::new();
    let mut persistents = Vec::new();
    for origin in program.scopes.globals.values() {
        match origin.def {
            Def::Routine(idx) => {
                let Some(routine) = program.routines.get(idx as usize) else { continue };
                if routine.kind == RoutineKind::Proc {
                    entries.push(routine.display.to_lowercase());
                }
            }
            Def::Data(idx) => {
                let Some(data) = program.datas.get(idx as usize) else { continue };
                // A type the check could not resolve is reported there; comparing it
                // with another task's would only repeat that.
                if data.kind != DataKind::Pers || !data.system_global || data.ty == ERROR {
                    continue;
                }
                let DeclOrigin::Module { module, .. } = data.origin else { continue };
                let Some(&file) = program.module_files.get(module) else { continue };
                persistents.push(Persistent {
                    name: data.display.clone(),
                    type_name: program.types.name(data.ty).to_string(),
                    dims: data.dims,
                    file,
                    span: origin.span,
                });
            }
            Def::Type(_) => {}
        }
    }
    persistents.sort_by_key(|p| (p.file, p.span.start));
    TaskFacts { procedures, entries, persistents }
}

/// Every finding about the system `sys` of the tasks `tasks` (in any order; a task
/// without a program, such as one not checked, is left out).
pub fn findings(sys: &Sys, config: Option<ConfigFile<'_>>, tasks: &[TaskProgram<'_>]) -> Vec<Diagnostic> {
    // In configuration order: the first task is the one `--entry` reaches, and a
    // persistent is the object of the first task declaring it.
    let ordered: Vec<(usize, &Task, &TaskProgram<'_>)> = sys
        .tasks
        .iter()
        .enumerate()
        .filter_map(|(idx, task)| Some((idx, task, tasks.iter().find(|t| t.name.eq_ignore_ascii_case(&task.name))?)))
        .collect();
    let mut found = Vec::new();
    if let Some(config) = config {
        // Every task the configuration names, the first too: without its entry routine
        // it cannot start, which the controller shows at its configuration. Only an
        // entry given on the command line (`rapid run --entry`) replaces it.
        let configured = ordered.iter().filter(|(_, _, program)| !program.entry_given);
        let without_entry =
            configured.filter(|(_, task, program)| !program.facts.entries.contains(&task.entry.to_lowercase()));
        found.extend(without_entry.map(|(_, task, _)| entry_finding(task, config)));
        // Every task given, also when SYS.cfg configures none (the hooks then run in T_ROB1).
        for program in tasks {
            found.extend(missing_event_routines(sys, program.name, program.facts, config));
        }
    }
    found.extend(persistent_mismatches(&ordered));
    found
}

/// The task `task` has no procedure to start: found at its entry routine (at the
/// task's line when the entry is `main` by default).
pub fn entry_finding(task: &Task, config: ConfigFile<'_>) -> Diagnostic {
    let (span, why) = match &task.entry_span {
        Some(span) => (Span::new(span.start, span.end), "its entry routine must be a global procedure of the task"),
        None => (line_span(config.text, task.line), "no entry routine is configured, so it starts in `main`"),
    };
    let message = format!("task {} has no procedure `{}` to start: {why}", task.name, task.entry);
    Diagnostic::new(config.file, Code::EntryRoutineMissing, span, message)
}

/// The event routines configured for `task` that it does not have, at their `-Routine`.
// uncertain: RobotWare reports a missing event routine in its event log; whether the
// controller then refuses to start is not known to us. `rapid run` refuses (a clear
// refusal beats running without the routine), so `rapid check` reports it as an error.
fn missing_event_routines<'s>(
    sys: &'s Sys,
    task: &'s str,
    facts: &'s TaskFacts,
    config: ConfigFile<'s>,
) -> impl Iterator<Item = Diagnostic> + 's {
    sys.hooks.iter().filter(move |hook| sys.runs_hook(hook, task)).filter_map(move |hook| {
        let name = hook.routine.to_lowercase();
        if facts.procedures.contains(&name) {
            return None;
        }
        let span = Span::new(hook.routine_span.start, hook.routine_span.end);
        let message = format!("task {task} has no procedure `{}` for its {} event routine", hook.routine, hook.shelf);
        Some(Diagnostic::new(config.file, Code::EventRoutineMissing, span, message))
    })
}

/// Global persistents of one name whose type or size differs from the first declaring
/// task's (§1.20): found at the later task's declaration.
fn persistent_mismatches(ordered: &[(usize, &Task, &TaskProgram<'_>)]) -> Vec<Diagnostic> {
    let mut first: FxHashMap<String, (&str, &Persistent)> = FxHashMap::default();
    let mut found = Vec::new();
    for (_, task, program) in ordered {
        for pers in &program.facts.persistents {
            let Some((other_task, other)) = first.get(&pers.name.to_lowercase()).copied() else {
                first.insert(pers.name.to_lowercase(), (&task.name, pers));
                continue;
            };
            if pers.type_name.eq_ignore_ascii_case(&other.type_name) && pers.dims == other.dims {
                continue;
            }
            let message = format!(
                "persistent `{}` is declared `{}` here and `{}` in task {other_task}: global persistents of one name \
                 must have the same type and size in every task",
                pers.name,
                shape(&pers.type_name, pers.dims),
                shape(&other.type_name, other.dims)
            );
            found.push(Diagnostic::new(program.file_offset + pers.file, Code::SharedPersMismatch, pers.span, message));
        }
    }
    found
}

/// The text of line `line` (1-based) of `text`, without its indentation and line break.
fn line_span(text: &str, line: u32) -> Span {
    let start: usize = text.split_inclusive('\n').take(line.saturating_sub(1) as usize).map(str::len).sum();
    let start = start.min(text.len());
    let end = text[start..].find(['\r', '\n']).map_or(text.len(), |n| start + n);
    let indent = text[start..end].len() - text[start..end].trim_start().len();
    Span::new(start + indent, end)
}

/// A persistent's type with its array sizes, as declared: `num{2,3}`.
pub fn shape(type_name: &str, dims: [u32; 3]) -> String {
    let sizes: Vec<String> = dims.iter().take_while(|&&d| d > 0).map(u32::to_string).collect();
    if sizes.is_empty() {
        type_name.to_owned()
    } else {
        format!("{type_name}{{{}}}", sizes.join(","))
    }
}
