//! `rapid check PATH…`: reads the task's files, checks them together and prints the
//! diagnostics. A backup of several tasks (SYS.cfg) has every task checked, each on
//! its own (a task's modules see only that task's declarations), and then the system
//! as a whole (`system.rs`: what `rapid run` would refuse to start).
//!
//! When several tasks are checked, each finding of a task's check names the task, and
//! a finding several tasks make at one place of one file (a module each of them loads)
//! is reported once, naming them all. A configuration finding every task makes is the
//! configuration's, and names none.

use std::collections::hash_map::Entry;
use std::io::{self, BufWriter, Write};

use rapid_sema::{Code, Diagnostic, Options};
use rapid_syntax::Span;
use rustc_hash::FxHashMap;

use crate::args::{CheckArgs, Format};
use crate::commands::ExitStatus;
use crate::render::{self, Files, Reported, Summary};
use rapid_controller::assembly::inputs;
use rapid_sema::system::{self, ConfigFile, TaskFacts, TaskProgram};

pub(crate) fn run(args: &CheckArgs) -> anyhow::Result<ExitStatus> {
    let inputs = inputs::collect(&args.paths)?;
    let others = other_tasks(args, &inputs)?;
    for task in std::iter::once(&inputs).chain(&others) {
        super::run::print_notes(&task.notes);
    }
    // A task is named only where the check covers several.
    let names = |task: &inputs::Inputs| match (&task.task, others.is_empty()) {
        (Some(folder), false) => vec![folder.name.clone()],
        _ => Vec::new(),
    };
    let options = Options {
        syntax_only: args.syntax_only,
        predefined: inputs.predefined.clone(),
        virtual_signals: args.virtual_io,
        system_options: inputs.system_options.clone(),
    };
    let (found, facts) = check_task(&inputs, &options);
    let mut reported = tag(found, &names(&inputs));
    // The configuration is read again with each task: its findings are compared across
    // the tasks. Other findings of the inputs (`.pgf` entries) are the first task's only.
    let mut config_findings = tag(inputs.config_findings(&inputs).collect(), &names(&inputs));
    let first_configs = inputs.modules.len() + inputs.programs.len();
    let is_config = |d: &&Diagnostic| d.code == Code::ConfigFile && d.file >= first_configs;
    reported.extend(inputs.diagnostics.iter().filter(|d| !is_config(d)).cloned().map(Reported::from));

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
        let options = Options {
            syntax_only: args.syntax_only,
            predefined: other.predefined.clone(),
            virtual_signals: args.virtual_io,
            system_options: other.system_options.clone(),
        };
        let (found, facts) = check_task(other, &options);
        let found = found.into_iter().map(|d| Diagnostic { file: d.file + offset, ..d }).collect();
        reported.extend(tag(found, &names(other)));
        config_findings.extend(tag(other.config_findings(&inputs).collect(), &names(other)));
        table.extend(other.modules.iter());
        rank.extend((0..other.modules.len()).map(|i| offset + i));
        if let (Some(task), Some(facts)) = (&other.task, facts) {
            programs.push((&task.name, offset, facts));
        }
    }
    let files = Files::new(&table);
    for mut finding in merge(config_findings, &files) {
        if finding.tasks.len() == others.len() + 1 {
            finding.tasks.clear();
        }
        reported.push(finding);
    }
    if let Some(sys) = &inputs.sys {
        let tasks: Vec<TaskProgram<'_>> = programs
            .iter()
            .map(|(name, file_offset, facts)| TaskProgram {
                name,
                file_offset: *file_offset,
                facts,
                entry_given: false,
            })
            .collect();
        let found = system::findings(sys, ConfigFile::of(inputs.sys_file, &table), &tasks);
        reported.extend(found.into_iter().map(Reported::from));
    }
    sort(&mut reported, &rank_by_path(&files, &rank));
    let reported = merge(reported, &files);
    let summary = Summary::of(&reported, &files);

    let mut out = BufWriter::new(io::stdout().lock());
    match args.format {
        Format::Human => render::human::render(&mut out, &files, &reported, &summary)?,
        Format::Json => render::json::render(&mut out, &files, &reported)?,
        Format::Sarif => render::sarif::render(&mut out, &files, &reported)?,
    }
    out.flush()?;

    Ok(if summary.errors > 0 { ExitStatus::Failure } else { ExitStatus::Success })
}

/// Checks one task's modules: the diagnostics, and what the system findings need of its
/// program when the task belongs to a system (none when only the syntax was checked,
/// or when the task has no module: its configuration finding says so already).
fn check_task(inputs: &inputs::Inputs, options: &Options) -> (Vec<Diagnostic>, Option<TaskFacts>) {
    let analysis = rapid_sema::analyze(&inputs.modules, options);
    let in_system = inputs.sys.is_some() && !inputs.modules.is_empty();
    let facts = analysis.program.as_ref().filter(|_| in_system).map(system::facts);
    (analysis.diagnostics, facts)
}

/// The inputs of a backup's tasks other than the one `inputs` holds.
fn other_tasks(args: &CheckArgs, inputs: &inputs::Inputs) -> anyhow::Result<Vec<inputs::Inputs>> {
    // A backup's task folders that no SYS.cfg configures are each checked on their own.
    if inputs.sys.as_ref().is_none_or(|sys| sys.tasks.is_empty()) {
        let tasks = inputs.unconfigured_tasks.iter().map(|name| inputs::collect_task(&args.paths, Some(name)));
        return Ok(tasks.collect::<Result<_, _>>()?);
    }
    let (Some(sys), Some(read)) = (&inputs.sys, &inputs.task) else { return Ok(Vec::new()) };
    // System-wide limits first: a system over the task limit is refused by its
    // configuration finding (E0701, as `rapid run` refuses it), and its tasks are not
    // read one by one (1000 tasks would each read the whole backup again).
    if sys.tasks.len() > rapid_limits::TASKS {
        return Ok(Vec::new());
    }
    sys.tasks
        .iter()
        .filter(|task| !task.name.eq_ignore_ascii_case(&read.name))
        .map(|task| inputs::collect_task(&args.paths, Some(&task.name)))
        .collect::<Result<_, _>>()
        .map_err(Into::into)
}

/// Diagnostics a task's check found, naming the task (`names`, empty for a check of one
/// task).
fn tag(diagnostics: Vec<Diagnostic>, names: &[String]) -> Vec<Reported> {
    diagnostics.into_iter().map(|diag| Reported { diag, tasks: names.to_vec() }).collect()
}

/// Reports once what several tasks found at one place: the same code and message at the
/// same span of the same file, by path (a module several tasks load is in the table
/// once for each). The first report stays where it is and names every task, in the
/// order they were checked. Diagnostics that name no task are never merged, so a check
/// of one task reports what it always has.
fn merge(reported: Vec<Reported>, files: &Files<'_>) -> Vec<Reported> {
    let mut res: Vec<Reported> = Vec::with_capacity(reported.len());
    let mut first_at: FxHashMap<(&str, Span, Code, String), usize> = FxHashMap::default();
    for it in reported {
        if it.tasks.is_empty() {
            res.push(it);
            continue;
        }
        let key = (files.path(it.diag.file), it.diag.span, it.diag.code, it.diag.message.clone());
        match first_at.entry(key) {
            Entry::Occupied(entry) => {
                let kept = &mut res[*entry.get()];
                for task in it.tasks {
                    if !kept.tasks.contains(&task) {
                        kept.tasks.push(task);
                    }
                }
            }
            Entry::Vacant(entry) => {
                entry.insert(res.len());
                res.push(it);
            }
        }
    }
    res
}

/// Each file's rank, that of the first copy of its path: the copies of a module several
/// tasks load sort as one file, so its diagnostics come together in position order.
fn rank_by_path(files: &Files<'_>, rank: &[usize]) -> Vec<usize> {
    let mut first: FxHashMap<&str, usize> = FxHashMap::default();
    for (file, &place) in rank.iter().enumerate() {
        let kept = first.entry(files.path(file)).or_insert(place);
        *kept = place.min(*kept);
    }
    (0..rank.len()).map(|file| first[files.path(file)]).collect()
}

/// Orders diagnostics by file (in the order the files were found) and then by position.
/// The sort is stable, so diagnostics at one spot keep the checker's order.
fn sort(reported: &mut [Reported], rank: &[usize]) {
    let file_rank = |file: usize| rank.get(file).copied().unwrap_or(usize::MAX);
    reported.sort_by_key(|it| (file_rank(it.diag.file), it.diag.span.start, it.diag.span.end));
}
