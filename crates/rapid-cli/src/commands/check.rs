//! `rapid check PATH…`: reads the task's files, checks them together and prints the
//! diagnostics.

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

    let table = inputs.table();
    sort(&mut diagnostics, &inputs.rank);
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

/// Orders diagnostics by file (in the order the files were found) and then by position.
/// The sort is stable, so diagnostics at one spot keep the checker's order.
fn sort(diagnostics: &mut [Diagnostic], rank: &[usize]) {
    let file_rank = |file: usize| rank.get(file).copied().unwrap_or(usize::MAX);
    diagnostics.sort_by_key(|diag| (file_rank(diag.file), diag.span.start, diag.span.end));
}
