//! `rapid check PATH…`: reads the task's files, checks them together and prints the
//! diagnostics. A backup of several tasks (SYS.cfg) has every task checked, each on
//! its own (a task's modules see only that task's declarations), and then the system
//! as a whole (`system.rs`: what `rapid run` would refuse to start).

use std::io::{self, BufWriter, Write};

use rapid_sema::{Diagnostic, Options};

use crate::args::{CheckArgs, Format};
use crate::commands::system::{self, ConfigFile, TaskFacts, TaskProgram};
use crate::commands::ExitStatus;
use crate::inputs;
use crate::render::{self, Files, Summary};

pub(crate) fn run(args: &CheckArgs) -> anyhow::Result<ExitStatus> {
    let inputs = inputs::collect(&args.paths)?;
    let options = Options { syntax_only: args.syntax_only, predefined: inputs.predefined.clone() };
    let (mut diagnostics, facts) = check_task(&inputs, &options);
    diagnostics.extend(inputs.diagnostics.iter().cloned());
    let others = other_tasks(args, &inputs)?;

    let mut table = inputs.table();
    let mut rank = inputs.rank.clone();
    // Each task's name, where its modules start in `table`, and its program's facts.
    let mut programs: Vec<(&str, usize, TaskFacts)> = Vec::new();
    if let (Some(task), Some(facts)) = (&inputs.task, facts) {
        programs.push((&task.name, 0, facts));
    }
    for other in &others {
        // The other tasks add their modules only: the configuration was read once.
        let offset = table.len();
        let options = Options { syntax_only: args.syntax_only, predefined: other.predefined.clone() };
        let (found, facts) = check_task(other, &options);
        diagnostics.extend(found.into_iter().map(|d| Diagnostic { file: d.file + offset, ..d }));
        diagnostics.extend(other.task_config_findings(&inputs));
        table.extend(other.modules.iter());
        rank.extend((0..other.modules.len()).map(|i| offset + i));
        if let (Some(task), Some(facts)) = (&other.task, facts) {
            programs.push((&task.name, offset, facts));
        }
    }
    if let Some(sys) = &inputs.sys {
        let tasks: Vec<TaskProgram<'_>> = programs
            .iter()
            .map(|(name, file_offset, facts)| TaskProgram { name, file_offset: *file_offset, facts })
            .collect();
        diagnostics.extend(system::findings(sys, ConfigFile::of(inputs.sys_file, &table), &tasks));
    }
    sort(&mut diagnostics, &rank);
    let files = Files::new(&table);
    let summary = Summary::of(&diagnostics, table.len());

    let mut out = BufWriter::new(io::stdout().lock());
    match args.format {
        Format::Human => render::human::render(&mut out, &files, &diagnostics, &summary)?,
        Format::Json => render::json::render(&mut out, &files, &diagnostics)?,
    }
    out.flush()?;

    Ok(if summary.errors > 0 { ExitStatus::Failure } else { ExitStatus::Success })
}

/// Checks one task's modules: the diagnostics, and what the system findings need of its
/// program when the task belongs to a system (none when only the syntax was checked).
fn check_task(inputs: &inputs::Inputs, options: &Options) -> (Vec<Diagnostic>, Option<TaskFacts>) {
    let analysis = rapid_sema::analyze(&inputs.modules, options);
    let facts = analysis.program.as_ref().filter(|_| inputs.sys.is_some()).map(system::facts);
    (analysis.diagnostics, facts)
}

/// The inputs of a backup's tasks other than the one `inputs` holds.
fn other_tasks(args: &CheckArgs, inputs: &inputs::Inputs) -> anyhow::Result<Vec<inputs::Inputs>> {
    let (Some(sys), Some(read)) = (&inputs.sys, &inputs.task) else { return Ok(Vec::new()) };
    sys.tasks
        .iter()
        .filter(|task| !task.name.eq_ignore_ascii_case(&read.name))
        .map(|task| inputs::collect_task(&args.paths, Some(&task.name)))
        .collect()
}

/// Orders diagnostics by file (in the order the files were found) and then by position.
/// The sort is stable, so diagnostics at one spot keep the checker's order.
fn sort(diagnostics: &mut [Diagnostic], rank: &[usize]) {
    let file_rank = |file: usize| rank.get(file).copied().unwrap_or(usize::MAX);
    diagnostics.sort_by_key(|diag| (file_rank(diag.file), diag.span.start, diag.span.end));
}
