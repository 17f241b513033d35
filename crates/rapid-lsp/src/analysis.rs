//! Diagnostics: each task checked by `rapid_sema::analyze` exactly as `rapid check`
//! checks it, and a system's tasks then as a whole (`rapid_sema::system`), the
//! findings turned into LSP diagnostics per document. Checking runs on
//! a worker thread, so the editor's requests never wait for a large file's check;
//! edits that arrive while a check runs are checked together afterwards.

use std::sync::mpsc;
use std::thread;

use crossbeam_channel::Sender;
use lsp_server::{Message, Notification};
use lsp_types::notification::{Notification as _, PublishDiagnostics};
use lsp_types::{Diagnostic, DiagnosticSeverity, NumberOrString, PublishDiagnosticsParams, Uri};
use rapid_sema::system::{ConfigFile, TaskFacts, TaskProgram};
use rapid_sema::{Severity, SourceInput};
use rustc_hash::FxHashMap;

use crate::position::LineMap;
use crate::workspace::TaskView;
use crate::System;

/// Diagnostics by document.
pub(crate) type ByUri = FxHashMap<Uri, Vec<Diagnostic>>;

/// Everything one round of checking needs, owned so it can cross to the worker.
#[derive(Debug, Clone)]
pub(crate) struct Job {
    pub(crate) tasks: Vec<TaskView>,
    /// The workspace's other files with their URIs, and their findings.
    pub(crate) others: Vec<(Uri, SourceInput)>,
    pub(crate) other_findings: Vec<rapid_sema::Diagnostic>,
    /// The workspace's system, when it is one: its findings as a whole are made too.
    pub(crate) system: Option<System>,
    /// The version of each open document, published with its diagnostics.
    pub(crate) versions: FxHashMap<Uri, i32>,
}

/// Checks every task of `job` and returns the diagnostics of every file it covers
/// (an empty list for a file without findings). A finding several tasks make at one
/// place is given once.
pub(crate) fn diagnose(job: &Job) -> ByUri {
    let mut out = ByUri::default();
    let mut facts: Vec<(usize, TaskFacts)> = Vec::new();
    for (at, task) in job.tasks.iter().enumerate() {
        for u in &task.uris {
            out.entry(u.clone()).or_default();
        }
        let analysis = rapid_sema::analyze(&task.files, &task.options);
        // What the system findings need of a system's task, as `rapid check` takes it.
        if let (Some(_), Some(_), Some(program)) = (&job.system, &task.name, &analysis.program) {
            facts.push((at, rapid_sema::system::facts(program)));
        }
        let maps: Vec<LineMap> = task.files.iter().map(|f| LineMap::new(&f.text)).collect();
        for diag in &analysis.diagnostics {
            let file = &task.files[diag.file];
            let converted = convert(&maps[diag.file], &file.text, diag);
            push_once(out.entry(task.uris[diag.file].clone()).or_default(), converted);
        }
    }
    for (u, _) in &job.others {
        out.entry(u.clone()).or_default();
    }
    for diag in &job.other_findings {
        let Some((u, file)) = job.others.get(diag.file) else { continue };
        let converted = convert(&LineMap::new(&file.text), &file.text, diag);
        push_once(out.entry(u.clone()).or_default(), converted);
    }
    if let Some(system) = &job.system {
        system_findings(job, system, &facts, &mut out);
    }
    for list in out.values_mut() {
        list.sort_by_key(|d| (d.range.start.line, d.range.start.character, d.range.end.line, d.range.end.character));
    }
    out
}

/// The findings about the system as a whole, on the files they point at: the
/// configuration's lines (an entry or event routine a task lacks) and modules (a
/// persistent declared differently in two tasks).
fn system_findings(job: &Job, system: &System, facts: &[(usize, TaskFacts)], out: &mut ByUri) {
    // The findings index one table: the other files (the configuration among them),
    // then each task's modules.
    let mut table: Vec<(&Uri, &SourceInput)> = job.others.iter().map(|(u, f)| (u, f)).collect();
    let mut programs: Vec<TaskProgram<'_>> = Vec::with_capacity(facts.len());
    for (at, task_facts) in facts {
        let task = &job.tasks[*at];
        let Some(name) = &task.name else { continue };
        programs.push(TaskProgram { name, file_offset: table.len(), facts: task_facts, entry_given: false });
        table.extend(task.uris.iter().zip(&task.files));
    }
    let config = system.file.and_then(|file| Some(ConfigFile { file, text: &job.others.get(file)?.1.text }));
    for diag in rapid_sema::system::findings(&system.sys, config, &programs) {
        let Some(&(u, file)) = table.get(diag.file) else { continue };
        let converted = convert(&LineMap::new(&file.text), &file.text, &diag);
        push_once(out.entry(u.clone()).or_default(), converted);
    }
}

fn push_once(list: &mut Vec<Diagnostic>, diag: Diagnostic) {
    if !list.contains(&diag) {
        list.push(diag);
    }
}

/// One checker finding as an LSP diagnostic: the same code, message and span.
pub(crate) fn convert(map: &LineMap, text: &str, diag: &rapid_sema::Diagnostic) -> Diagnostic {
    Diagnostic {
        range: map.range(text, diag.span),
        severity: Some(match diag.severity() {
            Severity::Error => DiagnosticSeverity::ERROR,
            Severity::Warning => DiagnosticSeverity::WARNING,
        }),
        code: Some(NumberOrString::String(diag.code.as_str().to_owned())),
        source: Some("rapid".to_owned()),
        message: diag.message.clone(),
        ..Diagnostic::default()
    }
}

/// The worker thread that checks and publishes.
pub(crate) struct Worker {
    jobs: mpsc::Sender<Job>,
    handle: Option<thread::JoinHandle<()>>,
}

impl Worker {
    pub(crate) fn start(out: Sender<Message>) -> Worker {
        let (jobs, rx) = mpsc::channel::<Job>();
        let handle = thread::Builder::new()
            .name("rapid-lsp-check".into())
            .spawn(move || run(rx, out))
            .expect("the check worker thread starts");
        Worker { jobs, handle: Some(handle) }
    }

    pub(crate) fn submit(&self, job: Job) {
        // The worker ends only when the server drops it: a send cannot fail before.
        let _ = self.jobs.send(job);
    }

    /// Stops the worker once the jobs sent so far are done.
    pub(crate) fn stop(mut self) {
        let (jobs, _) = mpsc::channel();
        drop(std::mem::replace(&mut self.jobs, jobs));
        if let Some(handle) = self.handle.take() {
            let _ = handle.join();
        }
    }
}

fn run(rx: mpsc::Receiver<Job>, out: Sender<Message>) {
    let mut published: ByUri = ByUri::default();
    while let Ok(mut job) = rx.recv() {
        // Only the newest state matters: older jobs are skipped.
        while let Ok(newer) = rx.try_recv() {
            job = newer;
        }
        let found = diagnose(&job);
        for (u, old) in &published {
            if !found.contains_key(u) && !old.is_empty() {
                send(&out, u.clone(), Vec::new(), job.versions.get(u).copied());
            }
        }
        for (u, diags) in &found {
            let changed = published.get(u).map_or(!diags.is_empty(), |old| old != diags);
            if changed || job.versions.contains_key(u) {
                send(&out, u.clone(), diags.clone(), job.versions.get(u).copied());
            }
        }
        published = found;
    }
}

fn send(out: &Sender<Message>, uri: Uri, diagnostics: Vec<Diagnostic>, version: Option<i32>) {
    let params = PublishDiagnosticsParams { uri, diagnostics, version };
    let _ = out.send(Message::Notification(Notification::new(PublishDiagnostics::METHOD.to_owned(), params)));
}
