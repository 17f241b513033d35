//! `rapid dap`: the debug adapter (crate rapid-dap) over stdio. This file gives it
//! what it must not know: how a launch request's paths become a booted system (as
//! `rapid serve` boots one, with `rapid run`'s stimulus and pendant answers).

use std::path::{Path, PathBuf};

use rapid_controller::api::Session;
use rapid_dap::{LaunchArgs, Launched, Launcher};

use super::ExitStatus;

pub(crate) fn run() -> anyhow::Result<ExitStatus> {
    let mut stdout = std::io::stdout();
    rapid_dap::serve(std::io::stdin(), &mut stdout, &SystemLauncher)
        .map_err(|e| anyhow::anyhow!("debug adapter: {e}"))?;
    Ok(ExitStatus::Success)
}

/// Boots a module, folder, backup or manifest as `rapid serve` does, in cycle mode
/// (one cycle, as `rapid run` runs by default: the session ends when the program does).
struct SystemLauncher;

impl Launcher for SystemLauncher {
    fn launch(&self, args: &LaunchArgs) -> Result<Launched, String> {
        // Canonical paths: the client names breakpoints' files by absolute paths.
        let paths: Vec<PathBuf> = args.program.iter().map(|p| canonical(p)).collect::<Result<_, _>>()?;
        let mut read_stimulus = |io: Option<&rapid_io::IoSystem>| read_stimulus(args.stimulus.as_deref(), io);
        let (controller, _files) = super::serve::assemble_with(&paths, None, &mut read_stimulus, 1)?;
        let answers = match &args.tp_input {
            Some(path) => pendant_answers(path)?,
            None => Vec::new(),
        };
        Ok(Launched { session: Session::new(controller), answers })
    }
}

fn canonical(path: &Path) -> Result<PathBuf, String> {
    std::fs::canonicalize(path).map_err(|e| format!("cannot read `{}`: {e}", path.display()))
}

/// The stimulus file read against the system's I/O, as `rapid run --stimulus`.
fn read_stimulus(
    path: Option<&Path>,
    io: Option<&rapid_io::IoSystem>,
) -> Result<Option<rapid_controller::boot::system::Stimulus>, String> {
    let Some(path) = path else { return Ok(None) };
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read the stimulus `{shown}`: {e}"))?;
    let io = io.ok_or_else(|| {
        format!("`{shown}`: a stimulus needs an I/O configuration (SYSPAR/EIO.cfg in a backup, `io` in a manifest)")
    })?;
    rapid_controller::assembly::stimulus::parse(&shown, &text, io).map(Some)
}

/// The operator's answers of a `--tp-input` file: one per line, `#` lines skipped.
fn pendant_answers(path: &Path) -> Result<Vec<String>, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the pendant answers `{}`: {e}", path.display()))?;
    Ok(text.lines().filter(|l| !l.starts_with('#')).map(str::to_owned).collect())
}
