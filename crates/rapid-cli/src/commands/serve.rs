//! `rapid serve`: boots a system and serves Robot Web Services (RWS 1.0, RobotWare 6)
//! for it until Ctrl-C, which saves the persistents as `--save-pers` would and exits 0.
//! The HTTP side is `rapid_serve`; this module only reads the command line, has the
//! controller assemble the system (on the controller thread: a session is not `Send`)
//! and binds.

// The CLI reports to the terminal.
#![allow(clippy::print_stderr)]

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use rapid_controller::api::{ClockPolicy, Session};
use rapid_controller::assembly::{self, LoadOptions};
use rapid_controller::Controller;
use rapid_sema::SourceInput;

use super::ExitStatus;
use crate::args::ServeArgs;

/// The port RobotWare serves on, and where to go when it is not ours to take.
const DEFAULT_BIND: &str = "127.0.0.1:80";
const FALLBACK_HINT: &str = "127.0.0.1:8080";

pub(crate) fn run(args: &ServeArgs) -> anyhow::Result<ExitStatus> {
    // Ctrl-C is caught from the start, so that one that comes while the system boots
    // still saves and exits 0 (a second one ends the process at once).
    crate::interrupt::install();
    let mut config = rapid_serve::Config::default();
    if let Some(file) = &args.users {
        let text = std::fs::read_to_string(file)
            .map_err(|e| anyhow::anyhow!("cannot read the users file `{}`: {e}", file.display()))?;
        let users = rapid_serve::Auth::parse_users(&text).map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
        config.users.extend(users);
    }
    let clock = match (args.realtime, args.speed) {
        (true, _) => ClockPolicy::Realtime,
        (false, Some(rate)) if rate > 0.0 && rate.is_finite() => ClockPolicy::Paced { rate },
        (false, Some(rate)) => anyhow::bail!("--speed {rate}: a positive number is needed"),
        (false, None) => ClockPolicy::Paced { rate: 1.0 },
    };
    let runtime = tokio::runtime::Builder::new_multi_thread().worker_threads(2).enable_all().build()?;
    let bind = args.bind.clone().unwrap_or_else(|| DEFAULT_BIND.to_owned());
    let listener = match runtime.block_on(tokio::net::TcpListener::bind(&bind)) {
        Ok(listener) => listener,
        Err(e) => {
            eprintln!("error: cannot listen on {bind}: {e}");
            if args.bind.is_none() {
                eprintln!("  port 80 needs privileges here: give another, e.g. `--bind {FALLBACK_HINT}`");
            }
            return Ok(ExitStatus::Error);
        }
    };
    let local: SocketAddr = listener.local_addr()?;
    let modules: Arc<Mutex<Vec<TaskFiles>>> = Arc::default();
    let boot = rapid_serve::Boot {
        session: boot_closure(args.paths.clone(), load_options(args), modules.clone()),
        clock,
        on_exit: Some(Box::new(move |session: &mut Session| save_persistents(session, &modules))),
        // The pendant's lines go to stdout, as `rapid run` writes them.
        on_tp_write: Some(Box::new(|line: &str| {
            use std::io::Write;
            let mut out = std::io::stdout().lock();
            // A closed stdout must not stop the controller.
            let _ = writeln!(out, "{line}").and_then(|()| out.flush());
        })),
    };
    let controller = match rapid_serve::Controller::start(boot) {
        Ok(controller) => controller,
        Err(message) => {
            eprintln!("error: {message}");
            eprintln!("the system has errors; it was not served");
            return Ok(ExitStatus::Failure);
        }
    };
    let router = rapid_serve::router(&controller, config);
    eprintln!("serving RWS on http://{local}/ (user \"Default User\", password \"robotics\"); Ctrl-C stops");
    let served = runtime.block_on(async move {
        tokio::select! {
            served = rapid_serve::serve(listener, router, std::future::pending()) => served,
            () = interrupted() => Ok(()),
        }
    });
    // Open websockets are let go with the runtime.
    runtime.shutdown_timeout(std::time::Duration::from_secs(1));
    let saved = controller.shutdown();
    served?;
    match saved {
        Ok(()) => Ok(ExitStatus::Success),
        Err(message) => {
            eprintln!("error: {message}");
            Ok(ExitStatus::Failure)
        }
    }
}

/// The command line's boot options as the controller's assembly takes them: a
/// client operates the program, which runs cycle after cycle.
fn load_options(args: &ServeArgs) -> LoadOptions {
    LoadOptions {
        operated: true,
        cycles: 0,
        start_joints: args.start_joints,
        // Wins over a manifest's `[system] controller_ip` (the assembly's rule).
        controller_ip: args.controller_ip,
        ..LoadOptions::default()
    }
}

/// Completes when the user presses Ctrl-C (polled: the handler only sets a flag).
async fn interrupted() {
    while !crate::interrupt::requested() {
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
}

/// Builds the session on the controller thread; each task's module files go to
/// `modules` for the save at the end.
fn boot_closure(
    paths: Vec<PathBuf>,
    options: LoadOptions,
    modules: Arc<Mutex<Vec<TaskFiles>>>,
) -> rapid_serve::BuildSession {
    Box::new(move || {
        let (controller, files) = assemble(&paths, &options)?;
        if let Ok(mut kept) = modules.lock() {
            *kept = files;
        }
        Ok(Session::new(controller))
    })
}

/// A task's name, the module files it was loaded from, and its persistents' values
/// at boot as RAPID literals (by index in `Loaded::persistents`).
pub(super) type TaskFiles = (String, Vec<SourceInput>, Vec<Option<String>>);

/// Each persistent's value now, as RAPID literal text.
fn pers_literals(loaded: &rapid_vm::Loaded) -> Vec<Option<String>> {
    let value =
        |s: &rapid_vm::persist::PersSite| loaded.vm.global(s.global).and_then(rapid_vm::builtins::value_literal);
    loaded.persistents.iter().map(value).collect()
}

/// The system of PATH (modules, a folder, a .pgf, a backup or a manifest; one task or
/// several) assembled by `rapid_controller::assembly` as `rapid run` assembles it, but
/// operated: standing stopped for the clients to start, the tasks' checked programs
/// kept (record components of data are read and written through them), continuous.
// Not configured as `rapid run` does: a stimulus, --virtual-io, --robot; the POWER_ON
// and START event routines do not run (the program is started by a client).
fn assemble(paths: &[PathBuf], options: &LoadOptions) -> Result<(Controller, Vec<TaskFiles>), String> {
    let assembled = assembly::assemble(paths, options).outcome.map_err(|e| e.message())?;
    let at_boot = assembled.controller.tasks.iter().map(|t| pers_literals(&t.loaded));
    let names = assembled.controller.tasks.iter().map(|t| t.spec.name.clone());
    let files = names.zip(assembled.inputs).zip(at_boot).map(|((name, inputs), pers)| (name, inputs.modules, pers));
    let files = files.collect();
    Ok((assembled.controller, files))
}

/// Ctrl-C: every task's persistents that changed since boot written back into their
/// module files, as `--save-pers` does (an untouched module stays byte for byte).
fn save_persistents(session: &mut Session, modules: &Mutex<Vec<TaskFiles>>) -> Result<(), String> {
    let files = modules.lock().map_err(|_| "the module list is unreadable".to_owned())?;
    let mut failures = Vec::new();
    let mut written = std::collections::HashSet::new();
    for (task, (name, task_files, at_boot)) in session.controller().tasks.iter().zip(files.iter()) {
        debug_assert_eq!(&task.spec.name, name);
        let now = pers_literals(&task.loaded);
        let changed = |idx: usize| now.get(idx) != at_boot.get(idx);
        if let Err(e) = crate::save::save_persistents_where(&task.loaded, task_files, &changed, &mut written) {
            failures.push(format!("{e:#}"));
        }
    }
    match failures.is_empty() {
        true => Ok(()),
        false => Err(failures.join("\n")),
    }
}
