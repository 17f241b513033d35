//! `rapid serve`: boots a system and serves Robot Web Services (RWS 1.0, RobotWare 6)
//! for it until Ctrl-C, which saves the persistents as `--save-pers` would and exits 0.
//! The HTTP side is `rapid_serve`; this module only reads the command line, boots
//! the system (on the controller thread: a session is not `Send`) and binds.

// The CLI reports to the terminal.
#![allow(clippy::print_stderr)]

use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use rapid_controller::api::{ClockPolicy, Session};
use rapid_controller::{Controller, TaskKind, TaskSpec, TrustLevel};
use rapid_sema::{Options, SourceInput};

use super::ExitStatus;
use crate::args::ServeArgs;
use crate::inputs;

/// The port RobotWare serves on, and where to go when it is not ours to take.
const DEFAULT_BIND: &str = "127.0.0.1:80";
const FALLBACK_HINT: &str = "127.0.0.1:8080";

pub(crate) fn run(args: &ServeArgs) -> anyhow::Result<ExitStatus> {
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
    let modules: Arc<Mutex<Vec<SourceInput>>> = Arc::default();
    let boot = rapid_serve::Boot {
        session: boot_closure(args.paths.clone(), modules.clone()),
        clock,
        on_exit: Some(Box::new(move |session: &mut Session| save_persistents(session, &modules))),
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
            _ = tokio::signal::ctrl_c() => Ok(()),
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

/// Builds the session on the controller thread; the module files go to `modules` for
/// the save at the end.
fn boot_closure(paths: Vec<PathBuf>, modules: Arc<Mutex<Vec<SourceInput>>>) -> rapid_serve::BuildSession {
    Box::new(move || {
        let (controller, files) = assemble_one_task(&paths)?;
        if let Ok(mut kept) = modules.lock() {
            *kept = files;
        }
        Ok(Session::new(controller))
    })
}

/// A one-task system from PATH (modules, a folder, a .pgf, a backup or a manifest of
/// one task): its program, its file devices' folder and its EIO.cfg signals.
// This is the CLI's own small assembly, kept apart until rapid-controller offers one
// entry point from inputs to a booted system (systems of several tasks, the robot
// model and base of MOC.cfg, event routines): those are refused or left at their
// defaults here.
fn assemble_one_task(paths: &[PathBuf]) -> Result<(Controller, Vec<SourceInput>), String> {
    let inputs = inputs::collect(paths).map_err(|e| format!("{e:#}"))?;
    if let Some(d) = inputs.diagnostics.iter().find(|d| d.severity() == rapid_sema::Severity::Error) {
        return Err(format!("the configuration has errors: {}", d.message));
    }
    if inputs.sys.as_ref().is_some_and(|sys| sys.tasks.len() > 1) {
        return Err("`rapid serve` does not serve systems of several tasks yet (use `rapid run` for them)".into());
    }
    let entry = inputs.task.as_ref().and_then(|t| t.entry.clone()).unwrap_or_else(|| "main".to_owned());
    let options = Options { predefined: inputs.predefined.clone(), ..Options::default() };
    let mut loaded = rapid_vm::load_with(&inputs.modules, &entry, &options)
        .map_err(|e| format!("the program cannot start: {e:?} (`rapid check` shows why)"))?;
    let root = inputs.root.clone().unwrap_or_else(|| default_home(paths));
    loaded.vm.resources_mut().files.set_root(root);
    loaded.vm.resources_mut().sockets.set_cooperative(true);
    loaded.vm.resources_mut().cfgdata.set_config(inputs.syspar.clone());
    loaded.vm.resources_mut().tasking.shared.number_robots(vec![Some(1)])?;
    let eio = inputs.syspar.iter().find(|(domain, _)| domain.eq_ignore_ascii_case("EIO"));
    let io = match eio {
        Some((_, eio)) => Some(rapid_vm::builtins::io_config::io_system(&rapid_config::eio::read(eio))?),
        None => None,
    };
    let name = inputs.task.as_ref().map_or("T_ROB1", |t| t.name.as_str()).to_owned();
    let spec = TaskSpec {
        name,
        kind: TaskKind::Normal,
        trust: TrustLevel::SysFail,
        foreground: None,
        motion: true,
        robot: true,
        rmq: rapid_config::sys::Rmq::default(),
        shared_files: Vec::new(),
        robot_of: None,
    };
    let controller = Controller::new(vec![(spec, loaded)], io)?;
    Ok((controller, inputs.modules))
}

/// `rapid-controller` beside the first PATH, as `rapid run` defaults it.
fn default_home(paths: &[PathBuf]) -> PathBuf {
    let first = paths.first().map_or(Path::new("."), |p| p.as_path());
    match first.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.join("rapid-controller"),
        _ => PathBuf::from("rapid-controller"),
    }
}

/// Ctrl-C: the persistents written back into their module files, as `--save-pers`.
fn save_persistents(session: &mut Session, modules: &Mutex<Vec<SourceInput>>) -> Result<(), String> {
    let files = modules.lock().map_err(|_| "the module list is unreadable".to_owned())?;
    let Some(task) = session.controller().tasks.first() else { return Ok(()) };
    crate::save::save_persistents(&task.loaded, &files).map_err(|e| format!("{e:#}"))
}
