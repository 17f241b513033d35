//! `rapid check PATH…`: reads the task's files, checks them together and prints the
//! diagnostics. A backup of several tasks (SYS.cfg) has every task checked, each on
//! its own (a task's modules see only that task's declarations).

use std::io::{self, BufWriter, Write};

use rapid_sema::{Diagnostic, Options};

use crate::args::{CheckArgs, Format};
use crate::commands::ExitStatus;
use crate::inputs;
use crate::render::{self, Files, Summary};

pub(crate) fn run(args: &CheckArgs) -> anyhow::Result<ExitStatus> {
    let inputs = inputs::collect(&args.paths)?;
    let options = Options { syntax_only: args.syntax_only, predefined: inputs.predefined.clone() };
    let mut diagnostics = rapid_sema::check(&inputs.modules, &options);
    diagnostics.extend(inputs.diagnostics.iter().cloned());
    let others = other_tasks(args, &inputs)?;

    let mut table = inputs.table();
    let mut rank = inputs.rank.clone();
    for other in &others {
        // The other tasks add their modules only: the configuration was read once.
        let offset = table.len();
        let options = Options { syntax_only: args.syntax_only, predefined: other.predefined.clone() };
        let found = rapid_sema::check(&other.modules, &options);
        diagnostics.extend(found.into_iter().map(|d| Diagnostic { file: d.file + offset, ..d }));
        diagnostics.extend(other.task_config_findings(&inputs));
        table.extend(other.modules.iter());
        rank.extend((0..other.modules.len()).map(|i| offset + i));
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
