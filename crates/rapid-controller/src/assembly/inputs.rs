//! Turning the PATHs of the command line into the files of one task: module files,
//! folders of modules, `.pgf` program files, controller backup folders (whose
//! `SYSPAR/*.cfg` configuration is read too) and `rapid.toml` project manifests (a
//! folder holding one is a project).
//!
//! A PATH that cannot be used at all (missing, unreadable, an unknown extension, a
//! folder without modules) is a tool failure. A module that a `.pgf` lists but that
//! cannot be read is a finding in the program file (E0130), so the user sees where the
//! entry is.

mod backup;
mod error;
mod glob;
pub mod manifest;
mod manifest_units;
mod options;
mod program_file;
mod system_outputs;

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

use rapid_config::{eio, sys, CfgError, CfgFile};
use rapid_sema::{Code, Diagnostic, PredefinedData, SourceInput};
use rapid_syntax::Span;
use rustc_hash::FxHashSet;

pub use self::backup::TaskFolder;
pub use self::error::InputError;
use self::error::{bail, describe_io_error, Context};
use self::program_file::{Entry, ProgramFile};
use crate::boot::cell::{TaskConveyor, TaskUnit};
use crate::boot::moc_units::read as read_moc_units;

/// Extensions of RAPID module files, compared without regard to case.
pub const MODULE_EXTENSIONS: &[&str] = &["mod", "modx", "sys", "sysx", "prg"];

/// The files of one task.
#[derive(Debug, Default)]
pub struct Inputs {
    /// The module files, in the order `check` receives them.
    pub modules: Vec<SourceInput>,
    /// Program files that list modules. They are not given to `check`; they are kept so
    /// that a diagnostic about one of their entries can show the entry.
    pub programs: Vec<SourceInput>,
    /// A backup's configuration files (`SYSPAR/*.cfg`), kept for their diagnostics.
    pub configs: Vec<SourceInput>,
    /// The parsed configuration files with their domains (`EIO`), for ReadCfgData.
    pub syspar: Vec<(String, CfgFile)>,
    /// The data the configuration declares: the signals of `EIO.cfg`.
    pub predefined: Vec<PredefinedData>,
    /// The task read from a backup, when a PATH was one.
    pub task: Option<TaskFolder>,
    /// The backup's task configuration (SYS.cfg), or the manifest's tasks.
    pub sys: Option<sys::Sys>,
    /// The file of [`Inputs::table`] that `sys` was read from (SYS.cfg or the manifest):
    /// the spans of `sys` are in its text.
    pub sys_file: Option<usize>,
    /// The controller root of a backup (the backup folder) or a manifest (the folder
    /// holding its HOME folder): the file devices are its subfolders.
    pub root: Option<PathBuf>,
    /// The robot model a manifest names (`[system] robot`).
    pub robot: Option<String>,
    /// A manifest's robot base frames by motion task (mm, quaternion).
    pub robot_bases: Vec<(String, [f64; 3], [f64; 4])>,
    /// A manifest's robot models by motion task; `None`: the task moves no robot.
    pub task_robots: Vec<(String, Option<String>)>,
    /// A manifest's `[system] start_joints`: where the robots stand at the start.
    pub start_joints: Option<[f64; 6]>,
    /// A manifest's `[system] controller_ip`: the controller's own address.
    pub controller_ip: Option<std::net::Ipv4Addr>,
    /// The external units a manifest configures (`[[unit]]`), with their tasks.
    pub units: Vec<TaskUnit>,
    /// The conveyors a manifest configures (`[[conveyor]]`), with their tasks.
    pub conveyors: Vec<TaskConveyor>,
    /// Which of `modules` are installed shared (one instance for every task).
    pub shared_modules: Vec<usize>,
    /// The software options the system has (system.xml, backinfo.txt, a manifest's
    /// `options`); `None` when nothing says (`rapid_sema::Options::system_options`).
    pub system_options: Option<Vec<String>>,
    /// Diagnostics found while reading the inputs. Their `file` indexes [`Inputs::table`].
    pub diagnostics: Vec<Diagnostic>,
    /// For each file of [`Inputs::table`], its place in the order the files were found,
    /// so output follows the command line even though modules come first in the table.
    pub rank: Vec<usize>,
    /// What the user should know about how the inputs were read (a backup's module
    /// left out): printed to stderr as notes.
    pub notes: Vec<String>,
    /// The other task folders of a backup that no SYS.cfg configures, by task name:
    /// `rapid check` checks each as a task of its own.
    pub unconfigured_tasks: Vec<String>,
}

impl Inputs {
    /// What sets the system's robots up (`crate::boot`).
    pub fn cell(&self) -> crate::boot::cell::Cell<'_> {
        crate::boot::cell::Cell {
            syspar: &self.syspar,
            robot: self.robot.as_deref(),
            robot_bases: &self.robot_bases,
            task_robots: &self.task_robots,
            units: &self.units,
            conveyors: &self.conveyors,
            start_joints: self.start_joints,
        }
    }

    /// Every file, modules first, then program files, then configuration files: the
    /// table diagnostics index.
    pub fn table(&self) -> Vec<&SourceInput> {
        self.modules.iter().chain(&self.programs).chain(&self.configs).collect()
    }

    /// The configuration findings of this task's inputs that `first` (another task of
    /// the same backup, whose configuration is the same files in the same order) does
    /// not have: those about this task alone (a module of HOME it loads), numbered
    /// as files of `first`'s table.
    pub fn task_config_findings(&self, first: &Inputs) -> Vec<Diagnostic> {
        self.config_findings(first)
            .filter(|d| {
                !first.diagnostics.iter().any(|f| f.file == d.file && f.span == d.span && f.message == d.message)
            })
            .collect()
    }

    /// Every finding in the configuration files of this task's inputs (those of
    /// `first`'s too, where `first`, another task of the same backup or `self`, has
    /// them), numbered as files of `first`'s table.
    pub fn config_findings<'a>(&'a self, first: &Inputs) -> impl Iterator<Item = Diagnostic> + 'a {
        let own_configs = self.modules.len() + self.programs.len();
        let first_configs = first.modules.len() + first.programs.len();
        self.diagnostics
            .iter()
            .filter(move |d| d.code == Code::ConfigFile && d.file >= own_configs)
            .map(move |d| Diagnostic { file: d.file - own_configs + first_configs, ..d.clone() })
    }
}

/// Reads every PATH. Fails, with a message naming the PATH, when one cannot be used.
pub fn collect(paths: &[PathBuf]) -> Result<Inputs, InputError> {
    collect_task(paths, None)
}

/// [`collect`], reading task `task` of a backup (T_ROB1 when none is named).
pub fn collect_task(paths: &[PathBuf], task: Option<&str>) -> Result<Inputs, InputError> {
    let mut collector = Collector { wanted_task: task.map(str::to_owned), ..Collector::default() };
    for path in paths {
        collector.add_path(path)?;
    }
    Ok(collector.finish())
}

/// What a file is, by its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum FileKind {
    Module,
    Program,
}

fn file_kind(path: &Path) -> Option<FileKind> {
    let ext = path.extension()?.to_str()?;
    if ext.eq_ignore_ascii_case("pgf") {
        return Some(FileKind::Program);
    }
    MODULE_EXTENSIONS.iter().any(|known| ext.eq_ignore_ascii_case(known)).then_some(FileKind::Module)
}

/// Where a file went: the module list or the program-file list.
#[derive(Debug, Clone, Copy)]
enum FileRef {
    Module(usize),
    Program(usize),
    Config(usize),
}

#[derive(Debug, Default)]
struct Collector {
    modules: Vec<SourceInput>,
    programs: Vec<SourceInput>,
    /// Every file in the order it was found.
    order: Vec<FileRef>,
    /// Diagnostics whose `file` is an index into `programs`.
    program_diagnostics: Vec<Diagnostic>,
    configs: Vec<SourceInput>,
    predefined: Vec<PredefinedData>,
    syspar: Vec<(String, CfgFile)>,
    task: Option<TaskFolder>,
    /// The backup task to read (T_ROB1 when none is named).
    wanted_task: Option<String>,
    /// The backup's SYS configuration, or the manifest's tasks.
    sys: Option<sys::Sys>,
    /// Index into `configs` of the file `sys` was read from.
    sys_config: Option<usize>,
    root: Option<PathBuf>,
    robot: Option<String>,
    robot_bases: Vec<(String, [f64; 3], [f64; 4])>,
    task_robots: Vec<(String, Option<String>)>,
    start_joints: Option<[f64; 6]>,
    controller_ip: Option<std::net::Ipv4Addr>,
    units: Vec<TaskUnit>,
    conveyors: Vec<TaskConveyor>,
    shared_modules: Vec<usize>,
    system_options: Option<Vec<String>>,
    /// Diagnostics whose `file` is an index into `configs`.
    config_diagnostics: Vec<Diagnostic>,
    /// Canonical paths already read, so a file named twice is checked once.
    seen: FxHashSet<PathBuf>,
    notes: Vec<String>,
    unconfigured_tasks: Vec<String>,
    /// For each file of `syspar`, its index in `configs`.
    syspar_configs: Vec<usize>,
}

impl Collector {
    fn add_path(&mut self, path: &Path) -> Result<(), InputError> {
        let shown = path.display();
        let meta = fs::metadata(path).with_context(|| format!("cannot read `{shown}`"))?;
        if let Some(file) = manifest::manifest_path(path) {
            return self.add_manifest(&file);
        }
        if meta.is_dir() {
            if backup::is_system(path) {
                return self.add_backup(path, &backup::task_folders(path));
            }
            return self.add_folder(path);
        }
        match file_kind(path) {
            Some(FileKind::Module) => self.add_module(path).with_context(|| format!("cannot read `{shown}`")),
            Some(FileKind::Program) => self.add_program(path),
            None => bail!(
                "`{shown}` is not a RAPID file: expected a module ({}), a program file (.pgf) or a folder",
                extension_list()
            ),
        }
    }

    /// Adds the module files of a folder (not of its subfolders), sorted by name.
    fn add_folder(&mut self, folder: &Path) -> Result<(), InputError> {
        let shown = folder.display();
        let mut files = Vec::new();
        for entry in fs::read_dir(folder).with_context(|| format!("cannot read folder `{shown}`"))? {
            let entry = entry.with_context(|| format!("cannot read folder `{shown}`"))?;
            let path = entry.path();
            if file_kind(&path) == Some(FileKind::Module) && path.is_file() {
                files.push((entry.file_name(), path));
            }
        }
        if files.is_empty() {
            let systems = backup::system_subfolders(folder);
            if !systems.is_empty() {
                bail!(
                    "folder `{shown}` holds no RAPID module files; these folders in it are systems (name one): {}",
                    systems.iter().map(|p| format!("`{}`", p.display())).collect::<Vec<_>>().join(", ")
                );
            }
            bail!("folder `{shown}` holds no RAPID module files ({})", extension_list());
        }
        files.sort();
        for (_, path) in files {
            let shown = path.display();
            self.add_module(&path).with_context(|| format!("cannot read `{shown}`"))?;
        }
        Ok(())
    }

    /// Adds a backup (or another system layout, `backup.rs`): its configuration, then
    /// the modules of its T_ROB1 task, from its task folder and from HOME.
    fn add_backup(&mut self, folder: &Path, tasks: &[(u32, PathBuf)]) -> Result<(), InputError> {
        let mut sys = None;
        for path in backup::config_files(folder) {
            if let (_, Some(view)) = self.add_config(&path)? {
                sys = Some(view);
                self.sys_config = Some(self.configs.len() - 1);
            }
        }
        let shown = folder.display();
        if let Some(sys) = &sys {
            self.add_task_ids(sys);
        }
        let Some(task) = backup::choose_task(folder, tasks, sys.as_ref(), self.wanted_task.as_deref()) else {
            bail!("`{shown}` holds no RAPID/TASKn folder, and no SYS.cfg configures a task");
        };
        if self.wanted_task.is_none() {
            self.note_task_folders(folder, tasks, sys.as_ref());
            self.note_other_devices(sys.as_ref());
        }
        let has_folder = task.folder.is_dir();
        let modules = if has_folder { backup::task_modules(folder, &task.folder)? } else { Vec::new() };
        for left_out in backup::unlisted_modules(&task.folder, &modules) {
            self.notes.push(format!(
                "`{}` is not among the modules backinfo.txt lists for task {}: it is not loaded",
                left_out.display(),
                task.name
            ));
        }
        for path in &modules {
            let shown = path.display();
            self.add_module(path).with_context(|| format!("cannot read `{shown}`"))?;
        }
        let home = backup::home_folder(folder);
        if let Some(sys) = &sys {
            self.add_home_modules(home.as_deref(), sys, &task.name, &modules);
            // The controller refuses a configuration that gives one robot two tasks.
            if let Err(found) = crate::boot::robots::numbers(sys, &self.syspar, &[]) {
                self.config_finding(found.domain, found.line, found.message);
            }
        }
        self.system_output_findings(sys.as_ref(), &task.name);
        // A task SYS.cfg configures that has no module cannot run: a finding at its
        // CAB_TASKS line, as `rapid run` refuses it (check and run agree).
        let line = sys.as_ref().and_then(|sys| sys.task(&task.name)).map(|t| t.line);
        let without_modules = self.modules.is_empty();
        match (without_modules, line) {
            (false, _) => {}
            (true, Some(line)) => self.sys_finding(line, backup::no_program(&task, has_folder)),
            (true, None) if !has_folder => bail!(
                "backup `{shown}`: task {} has no task folder `{}`, and SYS.cfg loads no module of HOME into it",
                task.name,
                task.folder.display()
            ),
            (true, None) => {
                bail!("backup `{shown}`: task folder `{}` holds no modules in PROGMOD or SYSMOD", task.folder.display())
            }
        }
        // Without any task folder every task is such a task: one note says so.
        if tasks.is_empty() && self.wanted_task.is_none() {
            self.notes.push(format!(
                "`{shown}` has no task folders (RAPID/TASKn): each task's modules are those SYS.cfg loads from HOME \
                 (CAB_TASK_MODULES), here `{}`",
                home.as_deref().map_or_else(|| "(none)".to_owned(), |h| h.display().to_string())
            ));
        }
        let noted = !without_modules && (!tasks.is_empty() || backup::listed_modules(folder, &task.folder) > 0);
        if !has_folder && noted {
            self.note_folderless_task(folder, &task);
        }
        if sys.as_ref().is_none_or(|sys| sys.tasks.is_empty()) && self.wanted_task.is_none() {
            let names = backup::folder_task_names(folder, tasks);
            self.unconfigured_tasks = names.into_iter().filter(|n| !n.eq_ignore_ascii_case(&task.name)).collect();
        }
        self.task = Some(task);
        self.sys = sys;
        // The controller root holds HOME: the backup, or the folder beside which a
        // configuration folder found its HOME.
        self.root = Some(home.and_then(|h| h.parent().map(Path::to_path_buf)).unwrap_or_else(|| folder.to_path_buf()));
        self.system_options = options::of_backup(folder);
        Ok(())
    }

    /// The findings of the system outputs whose task or robot the system lacks
    /// (`system_outputs.rs`), at their lines of EIO.cfg.
    fn system_output_findings(&mut self, sys: Option<&sys::Sys>, task: &str) {
        let found = system_outputs::findings(&self.syspar, sys, task, &self.task_robots, &self.units);
        for (line, message) in found {
            self.config_finding("EIO", line, message);
        }
    }

    /// Says which task folders of the system are not checked or run: those no
    /// configured task uses (named by backinfo.txt only, or by nothing), and, without a
    /// task configuration, those `rapid check` checks but `rapid run` does not run.
    fn note_task_folders(&mut self, folder: &Path, tasks: &[(u32, PathBuf)], sys: Option<&sys::Sys>) {
        let configured = sys.is_some_and(|sys| !sys.tasks.is_empty());
        for (path, name) in backup::unused_task_folders(folder, tasks, sys) {
            let shown = path.display();
            self.notes.push(match (configured, name) {
                (true, Some(name)) => format!(
                    "`{shown}` holds task {name} (backinfo.txt), which SYS.cfg does not configure: it is not checked \
                     or run"
                ),
                (true, None) => {
                    format!("`{shown}` is the folder of no task SYS.cfg configures: it is not checked or run")
                }
                (false, _) => format!(
                    "backinfo.txt names no task for `{shown}`: it is checked as task {} (no SYS.cfg says how it runs)",
                    path.file_name().and_then(|n| n.to_str()).unwrap_or("?")
                ),
            });
        }
        if !configured && tasks.len() > 1 {
            let names = backup::folder_task_names(folder, tasks);
            self.notes.push(format!(
                "no SYS.cfg configures the tasks of `{}` ({}): `rapid check` checks each; `rapid run` runs the first \
                 alone",
                folder.display(),
                names.join(", ")
            ));
        }
    }

    /// Says which task modules SYS.cfg loads from a device other than HOME
    /// (`RELEASE:/options/…`: RobotWare's own, which no backup holds): they are left out.
    fn note_other_devices(&mut self, sys: Option<&sys::Sys>) {
        let Some(sys) = sys else { return };
        let is_home = |file: &str| file.get(..5).is_some_and(|d| d.eq_ignore_ascii_case("HOME:"));
        for module in sys.modules.iter().filter(|m| !is_home(&m.file)) {
            self.notes.push(format!(
                "SYS.cfg (line {}) loads `{}`, which is outside HOME (RELEASE: holds RobotWare's own modules) and \
                 not in the backup: it is left out",
                module.line, module.file
            ));
        }
    }

    /// Says where a task without a task folder gets its program: the modules SYS.cfg
    /// loads from HOME (and what backinfo.txt listed for the folder, now missing).
    fn note_folderless_task(&mut self, folder: &Path, task: &TaskFolder) {
        let listed = backup::listed_modules(folder, &task.folder);
        let missing = match listed {
            0 => String::new(),
            n => format!("; backinfo.txt lists {n} module(s) of that folder, which the backup does not hold"),
        };
        self.notes.push(format!(
            "task {} has no task folder `{}`: its modules are those SYS.cfg loads from HOME (CAB_TASK_MODULES){missing}",
            task.name,
            task.folder.display()
        ));
    }

    /// The modules SYS.cfg loads from HOME (`CAB_TASK_MODULES`): a shared one
    /// (`-Shared`: one module every task sees), and one of task `task` (`-Task`, or
    /// `-AllTask`) that the task folder does not hold already (one installed with
    /// `-Install` is not saved in it), read from the backup's HOME folder. One of HOME
    /// that is missing is a finding in SYS.cfg; one on another device (RobotWare's own,
    /// `RELEASE:/…`) is not in a backup and is left out.
    // uncertain: shared modules of RobotWare itself (BASE_SHARED and the like) are not
    // modelled; their routines are in the catalogue.
    fn add_home_modules(&mut self, home: Option<&Path>, sys: &sys::Sys, task: &str, task_files: &[PathBuf]) {
        for module in sys.modules.iter().filter(|m| m.loads_into(task)) {
            let Some(rest) =
                module.file.get(..5).filter(|d| d.eq_ignore_ascii_case("HOME:")).map(|_| &module.file[5..])
            else {
                continue;
            };
            let rest = rest.trim_start_matches(['/', '\\']);
            let file_name = Path::new(rest).file_name().and_then(|n| n.to_str()).unwrap_or(rest).to_owned();
            let in_task = task_files
                .iter()
                .any(|p| p.file_name().and_then(|n| n.to_str()).is_some_and(|n| n.eq_ignore_ascii_case(&file_name)));
            if in_task {
                continue;
            }
            let path = home.map(|home| {
                let home = home.to_path_buf();
                rest.split(['/', '\\'])
                    .fold(home, |dir, part| backup::child(&dir, part).unwrap_or_else(|| dir.join(part)))
            });
            match path.filter(|p| p.is_file()) {
                Some(path) => {
                    let index = self.modules.len();
                    if self.add_module(&path).is_ok() && self.modules.len() > index && module.shared {
                        self.shared_modules.push(index);
                    }
                }
                None => {
                    let kind = if module.shared { "shared module" } else { "task module" };
                    let message = format!("{kind} `{}` is not in the backup's HOME folder", module.file);
                    self.sys_finding(module.line, message);
                }
            }
        }
    }

    /// Reads one configuration file: its findings, its signals (EIO) or its tasks
    /// (SYS, returned). Returns the file's domain too.
    fn add_config(&mut self, path: &Path) -> Result<(String, Option<sys::Sys>), InputError> {
        let shown = path.display();
        let bytes = fs::read(path).with_context(|| format!("cannot read `{shown}`"))?;
        let config_idx = self.configs.len();
        self.order.push(FileRef::Config(config_idx));
        self.configs.push(SourceInput::from_bytes(shown.to_string(), bytes));
        let parsed = rapid_config::parse(&self.configs[config_idx].text);
        let domain = domain(&parsed, path);
        if INTERPRETED_DOMAINS.contains(&domain.as_str()) {
            self.config_findings(config_idx, &parsed.errors);
        } else {
            self.uninterpreted_findings(config_idx, &domain, &parsed.errors);
        }
        let mut sys = None;
        match domain.as_str() {
            "EIO" => {
                let eio = eio::read(&parsed);
                self.config_findings(config_idx, &eio.errors);
                self.config_warnings(config_idx, &eio.warnings);
                self.predefined.extend(eio.signals.iter().map(|signal| PredefinedData {
                    name: signal.name.clone(),
                    type_name: signal.signal_type.rapid_type().to_owned(),
                }));
            }
            "MOC" => {
                // External units RobotWare's way. Every mechanical unit, read or not,
                // and every robot (ROB_L too) is known to programs by its name.
                let moc = read_moc_units(&parsed);
                let names = rapid_config::moc::unit_names(&parsed).into_iter();
                self.predefined.extend(names.map(|name| PredefinedData { name, type_name: "mecunit".to_owned() }));
                self.units.extend(moc.units);
            }
            "SYS" => {
                let view = sys::read(&parsed);
                self.config_findings(config_idx, &view.errors);
                self.config_warnings(config_idx, &view.warnings);
                sys = Some(view);
            }
            _ => {}
        }
        self.syspar.push((domain.clone(), parsed));
        self.syspar_configs.push(config_idx);
        Ok((domain, sys))
    }

    /// Every task of the system is known by a taskid `<name>Id` (GetTaskName, CRobT \\TaskRef).
    fn add_task_ids(&mut self, sys: &sys::Sys) {
        self.predefined.extend(
            sys.tasks
                .iter()
                .filter(|t| !t.name.eq_ignore_ascii_case("T_ROB1"))
                .map(|t| PredefinedData { name: format!("{}Id", t.name), type_name: "taskid".to_owned() }),
        );
    }

    /// Adds a project manifest: its findings, its I/O configuration, then the modules
    /// of the task asked for (the first task when none is named).
    fn add_manifest(&mut self, path: &Path) -> Result<(), InputError> {
        let shown = path.display();
        let bytes = fs::read(path).with_context(|| format!("cannot read `{shown}`"))?;
        let config_idx = self.configs.len();
        self.order.push(FileRef::Config(config_idx));
        self.configs.push(SourceInput::from_bytes(shown.to_string(), bytes));
        let manifest = manifest::read(path, &self.configs[config_idx].text);
        self.sys_config = Some(config_idx);
        let mut findings = manifest.findings.clone();
        if let Some((io, span)) = &manifest.io {
            let (domain, _) = self.add_config(io)?;
            if domain != "EIO" {
                let message = format!("`{}` is a {domain} configuration, not an I/O (EIO) one", io.display());
                findings.push(manifest::Finding { span: span.clone(), message });
            }
        }
        self.config_diagnostics.extend(findings.iter().map(|finding| {
            let span = Span::new(finding.span.start, finding.span.end);
            Diagnostic::new(config_idx, Code::ConfigFile, span, finding.message.clone())
        }));
        self.add_task_ids(&manifest.sys);
        self.root = Some(manifest.root.clone());
        self.system_options = manifest.options.clone();
        self.robot = manifest.robot.clone();
        self.robot_bases = manifest.robot_bases.clone();
        self.task_robots = manifest.task_robots.clone();
        self.start_joints = manifest.start_joints;
        self.controller_ip = manifest.controller_ip;
        self.units = manifest.units.clone();
        self.conveyors = manifest.conveyors.clone();
        // Each unit is known to programs by its name, a mecunit (ActUnit TRACK).
        self.predefined.extend(
            self.units
                .iter()
                .map(|u| u.unit.name.clone())
                .chain(self.conveyors.iter().map(|c| c.name.clone()))
                .map(|name| PredefinedData { name, type_name: "mecunit".to_owned() }),
        );
        let wanted = match &self.wanted_task {
            Some(name) => manifest.sys.tasks.iter().position(|t| t.name.eq_ignore_ascii_case(name)),
            None => (!manifest.sys.tasks.is_empty()).then_some(0),
        };
        let Some(idx) = wanted else {
            if let Some(name) = &self.wanted_task {
                bail!("manifest `{shown}` has no task `{name}`");
            }
            // The manifest's findings say why it has no task.
            self.sys = Some(manifest.sys);
            return Ok(());
        };
        let task_modules = manifest.modules.get(idx).map_or(&[][..], Vec::as_slice);
        for module in task_modules {
            let shown = module.display();
            self.add_module(module).with_context(|| format!("cannot read `{shown}`"))?;
        }
        // Shared modules come after the task's own; one the task lists itself is its own.
        for module in manifest.shared.iter().filter(|m| !task_modules.contains(m)) {
            let shown = module.display();
            let index = self.modules.len();
            self.add_module(module).with_context(|| format!("cannot read `{shown}`"))?;
            if self.modules.len() > index {
                self.shared_modules.push(index);
            }
        }
        let task = &manifest.sys.tasks[idx];
        self.system_output_findings(Some(&manifest.sys), &task.name);
        let folder = path.parent().map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        self.task = Some(TaskFolder { name: task.name.clone(), folder, entry: Some(task.entry.clone()) });
        self.sys = Some(manifest.sys);
        Ok(())
    }

    /// A finding at line `line` of the backup's SYS.cfg.
    fn sys_finding(&mut self, line: u32, message: String) {
        self.config_finding("SYS", line, message);
    }

    /// A finding at line `line` of the backup's configuration file of domain `domain`.
    fn config_finding(&mut self, domain: &str, line: u32, message: String) {
        let Some(at) = self.syspar.iter().position(|(d, _)| d == domain) else { return };
        // A manifest is a configuration file too, but not of `syspar`.
        let Some(&idx) = self.syspar_configs.get(at) else { return };
        let text = &self.configs[idx].text;
        let start: usize = text.split_inclusive('\n').take(line.saturating_sub(1) as usize).map(str::len).sum();
        let end = text[start.min(text.len())..].find('\n').map_or(text.len(), |n| start + n);
        let span = Span::new(start.min(text.len()), end);
        self.config_diagnostics.push(Diagnostic::new(idx, Code::ConfigFile, span, message));
    }

    fn config_findings(&mut self, config_idx: usize, errors: &[CfgError]) {
        self.config_diagnostics.extend(errors.iter().map(|error| {
            let span = Span::new(error.span.start, error.span.end);
            Diagnostic::new(config_idx, Code::ConfigFile, span, error.message.clone())
        }));
    }

    /// The lines a domain we do not interpret (MMC, PROC, SIO…) could not be read in:
    /// RobotWare accepts what it wrote, and nothing of the domain is used, so each is a
    /// warning at its line (W0702), never a reason to refuse the system.
    fn uninterpreted_findings(&mut self, config_idx: usize, domain: &str, errors: &[CfgError]) {
        let warnings: Vec<CfgError> = errors
            .iter()
            .map(|error| CfgError {
                message: format!(
                    "{} (the {domain} configuration is not interpreted: the line is ignored)",
                    error.message
                ),
                ..error.clone()
            })
            .collect();
        self.config_warnings(config_idx, &warnings);
    }

    /// Settings the configuration accepts but `rapid run` does not simulate (W0702).
    fn config_warnings(&mut self, config_idx: usize, warnings: &[CfgError]) {
        self.config_diagnostics.extend(warnings.iter().map(|warning| {
            let span = Span::new(warning.span.start, warning.span.end);
            Diagnostic::new(config_idx, Code::ConfigNotSimulated, span, warning.message.clone())
        }));
    }

    fn add_module(&mut self, path: &Path) -> io::Result<()> {
        if !self.first_sight(path) {
            return Ok(());
        }
        let bytes = fs::read(path)?;
        self.push_module(SourceInput::from_bytes(path.display().to_string(), bytes));
        Ok(())
    }

    /// Adds a `.pgf`: either the modules it lists, or the module it holds itself.
    fn add_program(&mut self, path: &Path) -> Result<(), InputError> {
        if !self.first_sight(path) {
            return Ok(());
        }
        let shown = path.display();
        let bytes = fs::read(path).with_context(|| format!("cannot read `{shown}`"))?;
        let source = SourceInput::from_bytes(shown.to_string(), bytes);
        let entries = match program_file::parse(&source) {
            ProgramFile::Module => {
                self.push_module(source);
                return Ok(());
            }
            ProgramFile::Listing(entries) => entries,
        };
        let program_idx = self.programs.len();
        self.programs.push(source);
        self.order.push(FileRef::Program(program_idx));

        let folder = path.parent().unwrap_or(Path::new(""));
        for Entry { name, span } in entries {
            if name.is_empty() {
                let message = "this <Module> entry names no module";
                self.program_diagnostics.push(entry_diagnostic(program_idx, span, message));
                continue;
            }
            let module_path = program_file::resolve(folder, &name);
            // A program lists modules; RobotWare has no nested programs, so a listed
            // `.pgf` is refused here rather than read (and parsed) as a module.
            if file_kind(&module_path) == Some(FileKind::Program) {
                let message = format!("`{name}` is a program file; a program file lists modules, not programs");
                self.program_diagnostics.push(entry_diagnostic(program_idx, span, message));
                continue;
            }
            if let Err(err) = self.add_module(&module_path) {
                let message =
                    format!("cannot read module `{}` listed here: {}", module_path.display(), describe_io_error(&err));
                self.program_diagnostics.push(entry_diagnostic(program_idx, span, message));
            }
        }
        Ok(())
    }

    fn push_module(&mut self, source: SourceInput) {
        self.order.push(FileRef::Module(self.modules.len()));
        self.modules.push(source);
    }

    /// Records that `path` is being read; false when it was read before.
    fn first_sight(&mut self, path: &Path) -> bool {
        match fs::canonicalize(path) {
            Ok(canonical) => self.seen.insert(canonical),
            // Reading will fail and say why.
            Err(_) => true,
        }
    }

    fn finish(self) -> Inputs {
        let n_modules = self.modules.len();
        let n_programs = self.programs.len();
        let table_idx = |file: FileRef| match file {
            FileRef::Module(idx) => idx,
            FileRef::Program(idx) => n_modules + idx,
            FileRef::Config(idx) => n_modules + n_programs + idx,
        };
        let mut rank = vec![0; n_modules + n_programs + self.configs.len()];
        for (order_idx, &file) in self.order.iter().enumerate() {
            rank[table_idx(file)] = order_idx;
        }
        let diagnostics = self
            .program_diagnostics
            .into_iter()
            .map(|diag| Diagnostic { file: table_idx(FileRef::Program(diag.file)), ..diag })
            .chain(
                self.config_diagnostics
                    .into_iter()
                    .map(|diag| Diagnostic { file: table_idx(FileRef::Config(diag.file)), ..diag }),
            )
            .collect();
        Inputs {
            modules: self.modules,
            programs: self.programs,
            configs: self.configs,
            predefined: self.predefined,
            syspar: self.syspar,
            task: self.task,
            sys: self.sys,
            sys_file: self.sys_config.map(|idx| table_idx(FileRef::Config(idx))),
            root: self.root,
            robot: self.robot,
            robot_bases: self.robot_bases,
            task_robots: self.task_robots,
            start_joints: self.start_joints,
            controller_ip: self.controller_ip,
            units: self.units,
            conveyors: self.conveyors,
            shared_modules: self.shared_modules,
            system_options: self.system_options,
            diagnostics,
            rank,
            notes: self.notes,
            unconfigured_tasks: self.unconfigured_tasks,
        }
    }
}

/// The configuration domains whose content `rapid` reads (signals, tasks, mechanical
/// units): a line of theirs that cannot be read is an error. The content of the
/// others (MMC, PROC, SIO, …) is kept for ReadCfgData only.
const INTERPRETED_DOMAINS: &[&str] = &["EIO", "SYS", "MOC"];

/// The domain of a configuration file: its header's, else its file name's (`EIO.cfg`).
fn domain(file: &CfgFile, path: &Path) -> String {
    match file.domain() {
        Some(domain) => domain.to_ascii_uppercase(),
        None => path.file_stem().and_then(|s| s.to_str()).unwrap_or("").to_ascii_uppercase(),
    }
}

fn entry_diagnostic(program_idx: usize, span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::new(program_idx, Code::ProgramFileEntry, span, message)
}

fn extension_list() -> String {
    let list: Vec<String> = MODULE_EXTENSIONS.iter().map(|ext| format!(".{ext}")).collect();
    list.join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_ignore_case() {
        assert_eq!(file_kind(Path::new("a/MAIN.MOD")), Some(FileKind::Module));
        assert_eq!(file_kind(Path::new("user.Sysx")), Some(FileKind::Module));
        assert_eq!(file_kind(Path::new("old.prg")), Some(FileKind::Module));
        assert_eq!(file_kind(Path::new("prog.PGF")), Some(FileKind::Program));
        assert_eq!(file_kind(Path::new("notes.txt")), None);
        assert_eq!(file_kind(Path::new("Makefile")), None);
    }
}
