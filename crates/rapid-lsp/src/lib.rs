//! rapid-lsp: the RAPID language server. It speaks the Language Server Protocol over
//! a connection it is given (`rapid lsp` gives it stdio; tests give it
//! `lsp_server::Connection::memory()`), and shows in the editor what `rapid check`
//! finds, with navigation, hover, completion and the other editor features.
//!
//! Invariant: no IO of its own beyond the connection and reading the module files of
//! the workspace; how a workspace's files become a system (folders, backups,
//! manifests) is the embedder's [`WorkspaceLoader`], so this crate knows nothing of
//! the command line.

// lsp_types::Uri caches parts of itself in cells but hashes and compares its text
// only, so using it as a map key is sound (the lint cannot see that).
#![allow(clippy::mutable_key_type)]

mod analysis;
mod builtins;
mod documents;
mod features;
mod index;
mod position;
mod server;
mod uri;
mod workspace;

use std::path::Path;

use rapid_sema::{Diagnostic, Options, SourceInput};

pub use server::{capabilities, serve};

/// One task of the workspace: its modules (each `path` an absolute file path) and the
/// options its check runs with (the configuration's signals as predefined data).
#[derive(Debug, Clone, Default)]
pub struct Task {
    /// The task's name when the workspace is a system (`T_ROB1`); `None` for a folder.
    pub name: Option<String>,
    pub modules: Vec<SourceInput>,
    pub options: Options,
}

/// What the embedder read of the workspace: its tasks and the findings of its other
/// files (configuration, program files), which `rapid check` reports as well.
#[derive(Debug, Clone, Default)]
pub struct Workspace {
    pub tasks: Vec<Task>,
    /// Non-module files findings point into (`path` absolute, `text` decoded).
    pub other_files: Vec<SourceInput>,
    /// Findings in `other_files`: `Diagnostic::file` indexes that list.
    pub other_findings: Vec<Diagnostic>,
    /// The system the tasks make (a backup's SYS.cfg, a manifest), whose findings as a
    /// whole `rapid check` reports too (`rapid_sema::system`).
    pub system: Option<System>,
}

/// A workspace's system description.
#[derive(Debug, Clone)]
pub struct System {
    pub sys: rapid_config::sys::Sys,
    /// The file `sys` was read from (SYS.cfg or the manifest): an index into
    /// `Workspace::other_files`.
    pub file: Option<usize>,
}

/// Turns the workspace folder into its tasks, as `rapid check FOLDER` would read it.
pub trait WorkspaceLoader {
    /// Reads the workspace at `root`. An error is shown to the user once, and the
    /// server then treats each open module as a task of its own.
    fn load(&self, root: &Path) -> Result<Workspace, String>;

    /// The formatter's options for module `file` (`rapid fmt`'s: the `[fmt]` table of
    /// the nearest `rapid.toml`); an error is shown instead of formatting.
    fn fmt_config(&self, _file: &Path) -> Result<rapid_fmt::Config, String> {
        Ok(rapid_fmt::Config::default())
    }
}
