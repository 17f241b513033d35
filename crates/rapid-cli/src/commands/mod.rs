//! One module per subcommand, and the exit status they all return.

mod check;
mod codes;
mod dap;
mod dump_ir;
mod fmt;
mod fmt_config;
mod lsp;
mod run;
mod run_system;
mod serve;

use std::process::ExitCode;

use crate::args::{Cli, Command};

/// How a run ended, as the shell sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ExitStatus {
    /// Nothing to report, or warnings only (exit 0).
    Success,
    /// The checked program has errors (exit 1).
    Failure,
    /// Bad usage or a tool failure such as an unreadable path (exit 2).
    Error,
    /// The user ended the run with Ctrl-C (exit 130, as a shell reports SIGINT).
    Interrupted,
    /// The run can no longer progress: every NORMAL task waits for a change only the
    /// outside world could make (exit 3).
    Stuck,
}

impl From<ExitStatus> for ExitCode {
    fn from(status: ExitStatus) -> ExitCode {
        match status {
            ExitStatus::Success => ExitCode::from(0),
            ExitStatus::Failure => ExitCode::from(1),
            ExitStatus::Error => ExitCode::from(2),
            ExitStatus::Interrupted => ExitCode::from(130),
            ExitStatus::Stuck => ExitCode::from(3),
        }
    }
}

/// Runs the subcommand the user asked for.
pub(crate) fn run(cli: Cli) -> anyhow::Result<ExitStatus> {
    match cli.command {
        Command::Check(args) => check::run(&args),
        Command::Run(args) => {
            crate::interrupt::install();
            run::run(&args)
        }
        Command::Serve(args) => serve::run(&args),
        Command::Codes => codes::run(),
        Command::Lsp(_) => lsp::run(),
        Command::Dap(_) => dap::run(),
        Command::Fmt(args) => fmt::run(&args),
        Command::DumpIr(args) => dump_ir::run(&args),
    }
}
