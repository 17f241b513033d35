//! `rapid dap`: the debug adapter (crate rapid-dap) over stdio. This file gives it
//! what it must not know: how a launch request's paths become a booted system (as
//! `rapid serve` boots one, with `rapid run`'s stimulus and pendant answers).

use std::path::{Path, PathBuf};

use rapid_controller::api::Session;
use rapid_controller::assembly::{self, LoadOptions};
use rapid_dap::{LaunchArgs, Launched, Launcher};

use super::ExitStatus;

pub(crate) fn run() -> anyhow::Result<ExitStatus> {
    let mut stdout = std::io::stdout();
    rapid_dap::serve(std::io::stdin(), &mut stdout, &SystemLauncher)
        .map_err(|e| anyhow::anyhow!("debug adapter: {e}"))?;
    Ok(ExitStatus::Success)
}

/// Boots a module, folder, backup or manifest through the controller's assembly as
/// `rapid serve` does, in cycle mode (one cycle, as `rapid run` runs by default: the
/// session ends when the program does).
struct SystemLauncher;

impl Launcher for SystemLauncher {
    fn launch(&self, args: &LaunchArgs) -> Result<Launched, String> {
        // Canonical paths: the client names breakpoints' files by absolute paths.
        let paths: Vec<PathBuf> = args.program.iter().map(|p| canonical(p)).collect::<Result<_, _>>()?;
        let options =
            LoadOptions { operated: true, cycles: 1, stimulus: args.stimulus.clone(), ..LoadOptions::default() };
        let assembled = assembly::assemble(&paths, &options).outcome.map_err(|e| e.message())?;
        let answers = match &args.tp_input {
            Some(path) => pendant_answers(path)?,
            None => Vec::new(),
        };
        Ok(Launched { session: Session::new(assembled.controller), answers })
    }
}

fn canonical(path: &Path) -> Result<PathBuf, String> {
    std::fs::canonicalize(path).map_err(|e| format!("cannot read `{}`: {e}", path.display()))
}

/// The operator's answers of a `--tp-input` file: one per line, `#` lines skipped.
fn pendant_answers(path: &Path) -> Result<Vec<String>, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the pendant answers `{}`: {e}", path.display()))?;
    Ok(text.lines().filter(|l| !l.starts_with('#')).map(str::to_owned).collect())
}
