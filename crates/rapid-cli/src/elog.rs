//! `rapid run --elog FILE`: the controller's event log as JSON lines, one entry per
//! line, oldest first (the format is described in `docs/elog.md`):
//!
//! ```text
//! {"seq":0,"time":0.5,"task":"T_ROB1","domain":8,"number":1,"code":80001,"type":"error",
//!  "title":"Gripper","description":["no part"],"routine":"main","file":"m.mod","line":4,"column":3}
//! ```
//!
//! (one line in the file). The file is written atomically when the run ends, however it
//! ends, so a reader never sees half a log.

use std::path::Path;

use rapid_sema::SourceInput;
use rapid_syntax::LineIndex;
use rapid_vm::events::{Event, EventKind};
use rustc_hash::FxHashMap;
use serde::Serialize;

/// The task of a program run alone (a backup of several tasks names each).
pub(crate) const MAIN_TASK: &str = "T_ROB1";

/// One task's log and the files its entries point into.
pub(crate) struct TaskEvents<'a> {
    pub(crate) task: &'a str,
    pub(crate) vm: &'a rapid_vm::Vm,
    /// The task's program files, by the VM's file index (modules loaded at run time
    /// are asked of the VM).
    pub(crate) files: &'a [SourceInput],
}

/// Writes the logs of `tasks` to `path` as JSON lines, atomically.
pub(crate) fn write(path: &Path, tasks: &[TaskEvents<'_>]) -> anyhow::Result<()> {
    crate::save::write_new(path, render(tasks).as_bytes())
}

/// One line of the file.
#[derive(Serialize)]
struct Line<'a> {
    seq: u64,
    time: f64,
    task: &'a str,
    domain: u32,
    number: u32,
    /// What the pendant shows: domain × 10000 + number.
    code: u32,
    #[serde(rename = "type")]
    kind: &'static str,
    title: std::borrow::Cow<'a, str>,
    description: &'a [String],
    routine: Option<&'a str>,
    file: Option<&'a str>,
    line: Option<u32>,
    column: Option<u32>,
}

/// The JSON lines of every task's entries, in the order they were logged: by
/// controller time, then task (in the order given), then sequence number.
pub(crate) fn render(tasks: &[TaskEvents<'_>]) -> String {
    let mut all: Vec<(usize, &Event)> =
        tasks.iter().enumerate().flat_map(|(t, task)| task.vm.event_log().iter().map(move |e| (t, e))).collect();
    all.sort_by(|a, b| a.1.time.total_cmp(&b.1.time).then(a.0.cmp(&b.0)).then(a.1.seq.cmp(&b.1.seq)));
    let mut places = Places::default();
    let mut out = String::new();
    for (t, event) in all {
        let task = &tasks[t];
        let (file, line, column) = match &event.place {
            Some(place) => places.locate(task, t, place.file, place.span.start),
            None => (None, None, None),
        };
        let line = Line {
            seq: event.seq,
            time: event.time,
            task: task.task,
            domain: event.domain,
            number: event.number,
            code: event.code(),
            kind: kind_name(event.kind),
            title: full_title(event),
            description: &event.lines,
            routine: event.place.as_ref().map(|p| p.routine.as_str()),
            file,
            line,
            column,
        };
        // Serialising plain strings and numbers cannot fail; an entry that somehow
        // did would be left out rather than end the run.
        if let Ok(json) = serde_json::to_string(&line) {
            out.push_str(&json);
            out.push('\n');
        }
    }
    out
}

/// The title with a system error's detail after it (the event keeps them apart, as
/// the controller does; the file gives the whole message in one place).
fn full_title(event: &Event) -> std::borrow::Cow<'_, str> {
    if event.details.is_empty() {
        return std::borrow::Cow::Borrowed(&event.title);
    }
    std::borrow::Cow::Owned(format!("{}: {}", event.title, event.details.join(" ")))
}

fn kind_name(kind: EventKind) -> &'static str {
    match kind {
        EventKind::Error => "error",
        EventKind::Warning => "warning",
        EventKind::Info => "info",
    }
}

/// Line indexes of the files entries point into, made once per file.
#[derive(Default)]
struct Places {
    indexes: FxHashMap<(usize, usize), LineIndex>,
}

impl Places {
    /// The path, line and column (1-based) of `offset` in file `file` of task `t`.
    fn locate<'a>(
        &mut self,
        task: &TaskEvents<'a>,
        t: usize,
        file: usize,
        offset: u32,
    ) -> (Option<&'a str>, Option<u32>, Option<u32>) {
        let Some(input) = task.files.get(file).or_else(|| task.vm.program_source(file)) else {
            return (None, None, None);
        };
        let index = self.indexes.entry((t, file)).or_insert_with(|| LineIndex::new(&input.text));
        let at = index.line_col(&input.text, offset);
        (Some(input.path.as_str()), Some(at.line), Some(at.column))
    }
}
