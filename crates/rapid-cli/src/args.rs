//! The command line, declared with clap.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

/// OpenRAPID: tools for ABB RAPID robot programs.
#[derive(Debug, Parser)]
#[command(name = "rapid", version)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Parse and check RAPID modules and report every error.
    Check(CheckArgs),
    /// Run a RAPID program (or every task of a backup) on the virtual controller.
    Run(Box<RunArgs>),
    /// Serve the virtual controller over Robot Web Services (RWS 1.0, RobotWare 6).
    Serve(ServeArgs),
    /// List every diagnostic code with its severity and meaning.
    Codes,
    /// Lay out RAPID modules as RobotStudio's editor does (every token and comment kept).
    Fmt(FmtArgs),
    /// Print the compiled form of every routine of a program (docs/dump-ir.md), without
    /// running it.
    DumpIr(DumpIrArgs),
    /// Serve the Language Server Protocol over stdin/stdout (for editors).
    Lsp(LspArgs),
    /// Serve the Debug Adapter Protocol over stdin/stdout (for debuggers).
    Dap(LspArgs),
}

#[derive(Debug, Args)]
pub(crate) struct DumpIrArgs {
    /// Module files, program files (.pgf) or folders of modules, compiled together as
    /// one task (as `rapid run` reads them).
    #[arg(required = true, value_name = "PATH")]
    pub(crate) paths: Vec<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct LspArgs {
    /// Accepted for editors that pass it: stdio is the only transport.
    #[arg(long)]
    pub(crate) stdio: bool,
}

#[derive(Debug, Args)]
pub(crate) struct FmtArgs {
    /// Write nothing: print the files that would change and exit 1 if there are any.
    #[arg(long)]
    pub(crate) check: bool,

    /// Module files or folders of modules (not their subfolders) to format in place;
    /// `-` formats stdin to stdout. Options come from the `[fmt]` table of the nearest
    /// rapid.toml at or above each file (docs/fmt.md).
    #[arg(required = true, value_name = "PATH")]
    pub(crate) paths: Vec<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct ServeArgs {
    /// Where to listen (default 127.0.0.1:80, RobotWare's port).
    #[arg(long, value_name = "HOST:PORT")]
    pub(crate) bind: Option<String>,

    /// The clock is the wall clock, computing included.
    #[arg(long, conflicts_with = "speed")]
    pub(crate) realtime: bool,

    /// Waits take 1/N of their wall-clock time (default 1: paced to the wall clock).
    #[arg(long, value_name = "N")]
    pub(crate) speed: Option<f64>,

    /// More users, one `name:password` a line, besides "Default User"/"robotics".
    #[arg(long, value_name = "FILE")]
    pub(crate) users: Option<PathBuf>,

    /// Where the robots stand at the start: as for `rapid run`.
    #[arg(long, value_name = "J1,...,J6", value_parser = parse_start_joints, allow_hyphen_values = true)]
    pub(crate) start_joints: Option<[f64; 6]>,

    /// The controller's own IP address in its cell, as for `rapid run`: a SocketBind
    /// to it, or to the service port's 192.168.125.1, binds the loopback instead. Wins
    /// over a manifest's `[system] controller_ip`.
    #[arg(long, value_name = "IPV4")]
    pub(crate) controller_ip: Option<std::net::Ipv4Addr>,

    /// The program: as for `rapid run`.
    #[arg(required = true)]
    pub(crate) paths: Vec<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct RunArgs {
    /// The routine to start (a PROC without parameters). Default: the task's `-Entry`
    /// in a backup's SYS.cfg or its `entry` in a rapid.toml manifest, else `main`.
    #[arg(long)]
    pub(crate) entry: Option<String>,

    /// Stop with an error after this many executed instructions (in a system of
    /// several tasks: statements, each up to 10,000 instructions).
    #[arg(long, value_name = "N")]
    pub(crate) max_steps: Option<u64>,

    /// Stop with an error when the virtual clock passes this many seconds.
    #[arg(long, value_name = "SECONDS")]
    pub(crate) max_time: Option<f64>,

    /// Run mode: the number of cycles to run. 1 (the default) is cycle mode: the end of
    /// the entry routine, or ExitCycle, ends the run. More is continuous mode: each
    /// starts the next cycle; 0 runs on until the program stops itself (Stop, EXIT) or
    /// --max-time / --max-steps ends it. In a system each NORMAL task runs its cycles.
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub(crate) cycles: u64,

    /// Wait in wall-clock time (WaitTime really waits).
    #[arg(long)]
    pub(crate) realtime: bool,

    /// When the program ends, write the persistents' values back into their module
    /// files, as the controller's Save Module does (atomically; other bytes kept).
    #[arg(long)]
    pub(crate) save_pers: bool,

    /// When the program ends, print the event log (ErrWrite, ErrLog, ErrRaise
    /// entries) to stderr, oldest first.
    #[arg(long)]
    pub(crate) event_log: bool,

    /// When the program ends (however it ends), write the event log to FILE as JSON
    /// lines: seq, time, task, domain, number, type, title, description, routine,
    /// file, line (see docs/elog.md).
    #[arg(long, value_name = "FILE")]
    pub(crate) elog: Option<PathBuf>,

    /// Operator answers for pendant dialogs (TPReadNum, TPReadFK, UINumEntry, ...),
    /// one per line, used in order; lines starting with `#` are comments.
    #[arg(long, value_name = "FILE")]
    pub(crate) tp_input: Option<PathBuf>,

    /// The controller's root folder: the file devices HOME:, TEMP:, RAMDISK: and BACKUP:
    /// are its subfolders HOME, TEMP, RAMDISK and BACKUP (made when first used). The
    /// program's files never leave it. Default: the backup folder itself when PATH is a
    /// backup (its HOME is the controller's HOME:), the folder holding a manifest's
    /// `home` (default: the manifest's own folder), else a folder `rapid-controller`
    /// beside the first PATH.
    #[arg(long, value_name = "DIR")]
    pub(crate) home: Option<PathBuf>,

    /// Input changes at given controller times ("at 1.5 set di1 1" per line), so
    /// programs waiting on inputs run unattended. Needs an I/O configuration (a backup's
    /// EIO.cfg or a manifest's `io`).
    #[arg(long, value_name = "FILE")]
    pub(crate) stimulus: Option<PathBuf>,

    /// When the program ends, write every signal change as CSV (time, signal, old,
    /// new, cause) to FILE.
    #[arg(long, value_name = "FILE")]
    pub(crate) io_log: Option<PathBuf>,

    /// Every signal an `AliasIO "NAME", var` names that the I/O configuration lacks
    /// (also a name computed at run time) is made a virtual signal of the variable's
    /// kind, and so is a name nothing declares that the program uses where a signal is
    /// wanted (`SetDO doGrip, 1;`); each is listed once on stderr (a simulation aid for
    /// modules run without their cell's EIO.cfg; a real controller raises
    /// ERR_ALIASIO_DEF).
    #[arg(long)]
    pub(crate) virtual_io: bool,

    /// The controller's own IP address in its cell (its LAN port). A SocketBind to it,
    /// or to the service port's 192.168.125.1, binds the loopback instead, as a virtual
    /// controller maps its addresses.
    #[arg(long, value_name = "IPV4")]
    pub(crate) controller_ip: Option<std::net::Ipv4Addr>,

    /// The robot model (`IRB120`, `IRB 4600-60/2.05`, a MOC.cfg robot type such as
    /// `ROB1_120_0.58`). Default: the backup's MOC.cfg robot type, else IRB 120-3/0.58.
    #[arg(long, value_name = "MODEL")]
    pub(crate) robot: Option<String>,

    /// The axis values in degrees every robot stands at when the run starts, six
    /// numbers separated by commas (`0,0,0,0,30,0`). Default: a manifest's
    /// `start_joints`, else the calibration position (all axes 0).
    #[arg(long, value_name = "J1,...,J6", value_parser = parse_start_joints, allow_hyphen_values = true)]
    pub(crate) start_joints: Option<[f64; 6]>,

    /// When the program ends, write the robot's trajectory to FILE, as JSON when FILE
    /// ends in `.json`, else CSV: time, axis values, TCP pose in the world frame and in
    /// the active work object, TCP speed, and the program line of the move (see
    /// docs/trace.md).
    #[arg(long, value_name = "FILE")]
    pub(crate) trace: Option<PathBuf>,

    /// When the program ends, write a run report to FILE: one self-contained HTML page
    /// with the 3D TCP path, joint and I/O plots and the table of moves (see
    /// docs/report.md).
    #[arg(long, value_name = "FILE.html")]
    pub(crate) report: Option<PathBuf>,

    /// The trace's sample period in milliseconds (the controller's is 4).
    #[arg(long, value_name = "MS", default_value_t = 4.0)]
    pub(crate) sample: f64,

    /// Do not print the cycle time of a program that moved the robot.
    #[arg(long)]
    pub(crate) quiet: bool,

    /// The operating mode key: OpMode() answers it; manual reduced speed limits the
    /// TCP to 250 mm/s.
    #[arg(long, value_enum, default_value_t = Mode::Auto)]
    pub(crate) mode: Mode,

    /// The operator's speed override in percent, 1 to 100 (CSpeedOverride).
    #[arg(long, value_name = "PERCENT", default_value_t = 100, value_parser = clap::value_parser!(u8).range(1..=100))]
    pub(crate) speed_override: u8,

    /// Module files, program files (.pgf) or folders, loaded together as one task; or a
    /// controller backup folder, or a rapid.toml manifest (or a folder holding one),
    /// whose tasks all run.
    #[arg(required = true, value_name = "PATH")]
    pub(crate) paths: Vec<PathBuf>,
}

/// The positions of the operating mode key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Mode {
    /// Automatic (OP_AUTO).
    Auto,
    /// Manual reduced speed (OP_MAN_PROG).
    ManualReduced,
    /// Manual full speed (OP_MAN_TEST).
    ManualFull,
}

impl RunArgs {
    /// The controller state the run starts in (`--mode`, `--speed-override`).
    pub(crate) fn controller_state(&self) -> rapid_vm::builtins::controller::ControllerState {
        use rapid_vm::builtins::controller::OpMode;
        let mode = match self.mode {
            Mode::Auto => OpMode::Auto,
            Mode::ManualReduced => OpMode::ManualReduced,
            Mode::ManualFull => OpMode::ManualFull,
        };
        rapid_vm::builtins::controller::ControllerState::new(mode, f64::from(self.speed_override))
    }
}

#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    /// Report lexical and syntax errors only.
    #[arg(long)]
    pub(crate) syntax_only: bool,

    /// As `rapid run --virtual-io`: a name nothing declares, used where a signal is
    /// wanted (`SetDO doGrip, 1;`), is a signal of the I/O configuration not at hand,
    /// not undefined data.
    #[arg(long)]
    pub(crate) virtual_io: bool,

    /// How to print the diagnostics.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub(crate) format: Format,

    /// Module files (.mod .modx .sys .sysx .prg), program files (.pgf) or folders of
    /// modules, checked together as one task; or a controller backup folder, or a
    /// rapid.toml manifest (or a folder holding one), whose tasks are each checked.
    #[arg(required = true, value_name = "PATH")]
    pub(crate) paths: Vec<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Format {
    /// Messages with source excerpts, like rustc.
    Human,
    /// One JSON array of diagnostics.
    Json,
    /// One SARIF 2.1.0 log, for code scanning (see docs/ci.md).
    Sarif,
}

/// `--start-joints`: six axis values in degrees, separated by commas.
fn parse_start_joints(text: &str) -> Result<[f64; 6], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>().ok().filter(|q| q.is_finite()))
        .collect::<Option<_>>()
        .ok_or_else(|| format!("`{text}` is not a list of numbers separated by commas"))?;
    <[f64; 6]>::try_from(values.as_slice())
        .map_err(|_| format!("six axis values are needed (axes 1 to 6), `{text}` has {}", values.len()))
}
