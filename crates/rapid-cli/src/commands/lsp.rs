//! `rapid lsp`: the language server (crate rapid-lsp) over stdio. This file gives it
//! the one thing it must not know: how a workspace folder becomes the tasks `rapid
//! check FOLDER` would check (a loose folder, a backup, a manifest).

use std::path::Path;

use rapid_lsp::{System, Task, Workspace, WorkspaceLoader};
use rapid_sema::Options;

use crate::commands::ExitStatus;
use rapid_controller::assembly::inputs::{self, Inputs};

pub(crate) fn run() -> anyhow::Result<ExitStatus> {
    let (connection, io_threads) = lsp_server::Connection::stdio();
    rapid_lsp::serve(connection, &FolderLoader).map_err(|e| anyhow::anyhow!("language server: {e}"))?;
    io_threads.join()?;
    Ok(ExitStatus::Success)
}

/// Reads a workspace folder as `rapid check FOLDER` reads it.
struct FolderLoader;

impl WorkspaceLoader for FolderLoader {
    fn load(&self, root: &Path) -> Result<Workspace, String> {
        let paths = [root.to_path_buf()];
        let first = inputs::collect(&paths).map_err(|e| format!("{e:#}"))?;
        let mut workspace = Workspace {
            tasks: vec![task(&first)],
            other_files: first.table().into_iter().cloned().collect(),
            other_findings: first.diagnostics.clone(),
            // SYS.cfg's index in `table()`, as `rapid check` finds its system findings.
            system: first.sys.clone().map(|sys| System { sys, file: first.sys_file }),
        };
        // The other tasks of a backup or manifest; their configuration findings are
        // numbered in the first task's files, as `rapid check` reports them.
        if let (Some(sys), Some(read)) = (&first.sys, &first.task) {
            for other in sys.tasks.iter().filter(|t| !t.name.eq_ignore_ascii_case(&read.name)) {
                let inputs = inputs::collect_task(&paths, Some(&other.name)).map_err(|e| format!("{e:#}"))?;
                workspace.other_findings.extend(inputs.task_config_findings(&first));
                workspace.tasks.push(task(&inputs));
            }
        }
        Ok(workspace)
    }

    fn fmt_config(&self, file: &Path) -> Result<rapid_fmt::Config, String> {
        let folder = file.parent().unwrap_or(Path::new("."));
        super::fmt_config::Configs::default().for_folder(folder).map_err(|e| format!("{e:#}"))
    }
}

fn task(inputs: &Inputs) -> Task {
    Task {
        name: inputs.task.as_ref().map(|t| t.name.clone()),
        modules: inputs.modules.clone(),
        options: Options {
            predefined: inputs.predefined.clone(),
            system_options: inputs.system_options.clone(),
            ..Options::default()
        },
    }
}
