//! Controller backup folders, as RobotStudio and the FlexPendant write them:
//!
//! ```text
//! BACKUP/
//!   BACKINFO/backinfo.txt     `>>TASK1: (T_ROB1,,)` names the task of each folder,
//!                             and the lines after it its modules (`SYSMOD\user.sys @ `)
//!   HOME/
//!   RAPID/TASK1/PROGMOD/*.mod
//!   RAPID/TASK1/SYSMOD/*.sys
//!   SYSPAR/EIO.cfg SYS.cfg MOC.cfg …
//! ```
//!
//! and the other layouts public systems come in (docs/real-systems.md):
//!
//! - a system without task folders: `SYSPAR/*.cfg` and `HOME/`, whose tasks get their
//!   modules from HOME as SYS.cfg's `CAB_TASK_MODULES` says (a backup whose `RAPID`
//!   folder is empty is one too);
//! - a configuration folder: `SYS.cfg` and the other `.cfg` files at its root, HOME in
//!   it or beside it (`robot/config_params/SYS.cfg` with `robot/HOME/`), as programs
//!   that install themselves on a controller ship their configuration;
//! - a single task folder straight in `RAPID` (`RAPID/PROGMOD`, `RAPID/SYSMOD`), the
//!   task T_ROB1 of a system without configuration.
//!
//! The task checked and run first is T_ROB1 (the task SYS.cfg names so, else its first
//! task; the folder is found through backinfo.txt, else by the task's place in
//! SYS.cfg, else the first task folder). A task may have no folder: its modules are
//! then those of HOME that SYS.cfg loads into it. Names are matched without regard to
//! case: backups copied from Windows keep whatever case their files happen to have.

use std::fs;
use std::path::{Path, PathBuf};

use rapid_config::sys::Sys;

/// The task the backup's program is read from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TaskFolder {
    /// The task's name (`T_ROB1`), or the folder's when no configuration names it.
    pub name: String,
    pub folder: PathBuf,
    /// The routine the task starts in (`-Entry` in SYS.cfg), when SYS.cfg has the task.
    pub entry: Option<String>,
}

/// A child of `dir` named `name` in any letter case.
pub(crate) fn child(dir: &Path, name: &str) -> Option<PathBuf> {
    let direct = dir.join(name);
    if direct.exists() {
        return Some(direct);
    }
    fs::read_dir(dir)
        .ok()?
        .filter_map(Result::ok)
        .find(|entry| entry.file_name().to_str().is_some_and(|n| n.eq_ignore_ascii_case(name)))
        .map(|entry| entry.path())
}

/// The `RAPID/TASKn` folders of a backup, ordered by n; empty when `folder` has none. A
/// `RAPID` folder holding `PROGMOD` or `SYSMOD` itself (and no `TASKn`) is the one task
/// folder of its system, numbered 1.
pub(crate) fn task_folders(folder: &Path) -> Vec<(u32, PathBuf)> {
    let Some(rapid) = child(folder, "RAPID").filter(|p| p.is_dir()) else { return Vec::new() };
    let Ok(entries) = fs::read_dir(&rapid) else { return Vec::new() };
    let mut tasks: Vec<(u32, PathBuf)> = entries
        .filter_map(Result::ok)
        .filter(|e| e.path().is_dir())
        .filter_map(|e| {
            let name = e.file_name().to_str()?.to_ascii_uppercase();
            let n = name.strip_prefix("TASK")?.parse::<u32>().ok()?;
            Some((n, e.path()))
        })
        .collect();
    tasks.sort();
    if tasks.is_empty() && ["PROGMOD", "SYSMOD"].iter().any(|sub| child(&rapid, sub).is_some_and(|p| p.is_dir())) {
        tasks.push((1, rapid));
    }
    tasks
}

/// Whether `folder` is a system (a backup or one of the other layouts the module doc
/// lists) rather than a folder of modules.
pub(crate) fn is_system(folder: &Path) -> bool {
    !task_folders(folder).is_empty() || !config_files(folder).is_empty()
}

/// The folders in `folder` that are systems, sorted: what a user who named their parent
/// (a repository's `robot` folder holding `HOME` and several configuration folders)
/// may have meant.
pub(crate) fn system_subfolders(folder: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(folder) else { return Vec::new() };
    let mut found: Vec<PathBuf> = entries.filter_map(Result::ok).map(|e| e.path()).filter(|p| p.is_dir()).collect();
    found.retain(|p| is_system(p));
    found.sort();
    found
}

/// The configuration files of a system, sorted by name: `SYSPAR/*.cfg`, else the
/// `.cfg` files at its root when `SYS.cfg` is one of them.
pub(crate) fn config_files(folder: &Path) -> Vec<PathBuf> {
    match child(folder, "SYSPAR").filter(|p| p.is_dir()) {
        Some(syspar) => cfg_files(&syspar),
        None if child(folder, "SYS.cfg").is_some_and(|p| p.is_file()) => cfg_files(folder),
        None => Vec::new(),
    }
}

/// The `.cfg` files of a folder, sorted by name.
fn cfg_files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(dir) else { return Vec::new() };
    let mut files: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.is_file() && p.extension().and_then(|e| e.to_str()).is_some_and(|e| e.eq_ignore_ascii_case("cfg"))
        })
        .collect();
    files.sort();
    files
}

/// The system's HOME folder: its own `HOME`, else, for a configuration folder (its
/// `.cfg` files at its root, no `SYSPAR`), the `HOME` beside it. None when neither is.
pub(crate) fn home_folder(folder: &Path) -> Option<PathBuf> {
    if let Some(home) = child(folder, "HOME").filter(|p| p.is_dir()) {
        return Some(home);
    }
    if child(folder, "SYSPAR").is_some() {
        return None;
    }
    let parent = folder.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    child(parent, "HOME").filter(|p| p.is_dir())
}

/// The task to read: `wanted`, else T_ROB1, else SYS.cfg's first task, else the first
/// task folder. None when the system has neither a task folder nor a configured task.
/// The folder returned may be missing: a task without a folder has no program of its
/// own (the caller reports it, or loads the modules SYS.cfg gives the task).
pub(crate) fn choose_task(
    folder: &Path,
    tasks: &[(u32, PathBuf)],
    sys: Option<&Sys>,
    wanted: Option<&str>,
) -> Option<TaskFolder> {
    let names = backinfo_tasks(folder);
    let wanted = match wanted {
        Some(name) => Some(name.to_owned()),
        None => sys.and_then(|sys| sys.task("T_ROB1").or(sys.tasks.first())).map(|t| t.name.clone()),
    };
    let wanted =
        wanted.or_else(|| names.iter().find(|(_, n)| n.eq_ignore_ascii_case("T_ROB1")).map(|(_, n)| n.clone()));
    let Some(wanted) = wanted else {
        let first = tasks.first()?;
        let name = names.iter().find(|(n, _)| *n == first.0).map_or_else(|| folder_name(&first.1), |(_, n)| n.clone());
        return Some(TaskFolder { name, folder: first.1.clone(), entry: None });
    };
    // The folder of the task: backinfo.txt says; else the task's place in SYS.cfg; else
    // the folder of its name (a task named after its folder, as a system without
    // configuration has them).
    // uncertain: RobotWare numbers TASKn folders in CAB_TASKS order; backinfo.txt is
    // what backups we have seen use to say it.
    let number = names
        .iter()
        .find(|(_, n)| n.eq_ignore_ascii_case(&wanted))
        .map(|(n, _)| *n)
        .or_else(|| {
            let place = sys?.tasks.iter().position(|t| t.name.eq_ignore_ascii_case(&wanted))?;
            u32::try_from(place + 1).ok()
        })
        .or_else(|| tasks.iter().find(|(_, path)| folder_name(path).eq_ignore_ascii_case(&wanted)).map(|(n, _)| *n));
    // A task whose folder is missing has no program: never another task's.
    let found = match number {
        Some(n) => tasks.iter().find(|(m, _)| *m == n).map_or_else(|| rapid_task_folder(folder, n), |f| f.1.clone()),
        None => tasks.first().map_or_else(|| rapid_task_folder(folder, 1), |f| f.1.clone()),
    };
    let entry = sys.and_then(|sys| sys.task(&wanted)).map(|t| t.entry.clone());
    Some(TaskFolder { name: wanted, folder: found, entry })
}

/// The task folders of a system that no configured task uses, each with the name
/// backinfo.txt gives it (if any): with SYS.cfg, a folder is a configured task's by
/// backinfo.txt, else by the task's place in CAB_TASKS; without it, every folder
/// backinfo.txt names is used (when it names any).
pub(crate) fn unused_task_folders(
    folder: &Path,
    tasks: &[(u32, PathBuf)],
    sys: Option<&Sys>,
) -> Vec<(PathBuf, Option<String>)> {
    let names = backinfo_tasks(folder);
    let configured = sys.filter(|sys| !sys.tasks.is_empty());
    let used = |n: u32| match configured {
        Some(sys) => sys.tasks.iter().enumerate().any(|(place, task)| {
            let by_name = names.iter().find(|(_, name)| name.eq_ignore_ascii_case(&task.name)).map(|(k, _)| *k);
            by_name.or_else(|| u32::try_from(place + 1).ok()) == Some(n)
        }),
        None => names.is_empty() || names.iter().any(|(k, _)| *k == n),
    };
    tasks
        .iter()
        .filter(|(n, _)| !used(*n))
        .map(|(n, path)| (path.clone(), names.iter().find(|(k, _)| k == n).map(|(_, name)| name.clone())))
        .collect()
}

/// The name of each task folder of a system without a task configuration: backinfo.txt's,
/// else the folder's own.
pub(crate) fn folder_task_names(folder: &Path, tasks: &[(u32, PathBuf)]) -> Vec<String> {
    let names = backinfo_tasks(folder);
    tasks
        .iter()
        .map(|(n, path)| names.iter().find(|(k, _)| k == n).map_or_else(|| folder_name(path), |(_, name)| name.clone()))
        .collect()
}

/// The modules backinfo.txt lists for the task of folder number `n`, if any: a task
/// whose folder is missing had them when the backup was taken.
pub(crate) fn listed_modules(backup: &Path, task: &Path) -> usize {
    let number = task.file_name().and_then(|n| n.to_str()).and_then(task_number);
    number.and_then(|n| backinfo_modules(backup, n)).map_or(0, |listed| listed.len())
}

/// Where task folder `n` of a backup would be: `RAPID/TASKn`.
fn rapid_task_folder(folder: &Path, n: u32) -> PathBuf {
    child(folder, "RAPID").unwrap_or_else(|| folder.join("RAPID")).join(format!("TASK{n}"))
}

/// The name of a task known by its folder only: `TASKn`, or T_ROB1 for a `RAPID`
/// folder that is itself the one task folder (the name of a single robot's task).
fn folder_name(path: &Path) -> String {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("TASK");
    if name.eq_ignore_ascii_case("RAPID") {
        return "T_ROB1".to_owned();
    }
    name.to_owned()
}

/// `>>TASK1: (T_ROB1,,)` lines of `BACKINFO/backinfo.txt`: (1, "T_ROB1").
fn backinfo_tasks(folder: &Path) -> Vec<(u32, String)> {
    let Some(file) = child(folder, "BACKINFO").and_then(|dir| child(&dir, "backinfo.txt")) else { return Vec::new() };
    let Ok(bytes) = fs::read(file) else { return Vec::new() };
    String::from_utf8_lossy(&bytes).lines().filter_map(parse_backinfo_task).collect()
}

fn parse_backinfo_task(line: &str) -> Option<(u32, String)> {
    let rest = line.trim().strip_prefix(">>")?.trim_start();
    let (label, rest) = rest.split_once(':')?;
    let n = label.trim().to_ascii_uppercase().strip_prefix("TASK")?.parse::<u32>().ok()?;
    let inner = rest.trim().strip_prefix('(')?;
    let name = inner.split([',', ')']).next()?.trim();
    (!name.is_empty()).then(|| (n, name.to_owned()))
}

/// The modules of task folder `task` of backup `backup`: those backinfo.txt lists for
/// it, in its order (the controller saved exactly these; another file in the folder is
/// not part of the task), else every module file, `SYSMOD` then `PROGMOD`, each sorted
/// by name. A listed module the folder lacks is an error.
pub(crate) fn task_modules(backup: &Path, task: &Path) -> Result<Vec<PathBuf>, super::InputError> {
    let number = task.file_name().and_then(|n| n.to_str()).and_then(task_number);
    let Some(listed) = number.and_then(|n| backinfo_modules(backup, n)) else { return Ok(folder_modules(task)) };
    listed
        .iter()
        .map(|entry| {
            let found = entry.split(['\\', '/']).try_fold(task.to_path_buf(), |dir, part| child(&dir, part));
            found.filter(|p| p.is_file()).ok_or_else(|| {
                super::InputError::new(format!(
                    "backup `{}`: backinfo.txt lists module `{entry}` for `{}`, which the folder does not hold",
                    backup.display(),
                    task.display()
                ))
            })
        })
        .collect()
}

/// The module files of task folder `task` that are not among `modules` (those
/// backinfo.txt lists), which the task therefore leaves out.
pub(crate) fn unlisted_modules(task: &Path, modules: &[PathBuf]) -> Vec<PathBuf> {
    folder_modules(task).into_iter().filter(|file| !modules.contains(file)).collect()
}

/// `n` of a task folder named `TASKn`.
fn task_number(folder: &str) -> Option<u32> {
    folder.to_ascii_uppercase().strip_prefix("TASK")?.parse().ok()
}

/// The modules backinfo.txt lists for task folder `TASKn` (the lines after its
/// `>>TASKn:` header up to the next header: `SYSMOD\user.sys @ `); None when there is
/// no backinfo.txt or it lists none.
fn backinfo_modules(backup: &Path, n: u32) -> Option<Vec<String>> {
    let file = child(backup, "BACKINFO").and_then(|dir| child(&dir, "backinfo.txt"))?;
    let text = String::from_utf8_lossy(&fs::read(file).ok()?).into_owned();
    let mut lines = text.lines().skip_while(|line| parse_backinfo_task(line).is_none_or(|(k, _)| k != n)).skip(1);
    let listed: Vec<String> = lines
        .by_ref()
        .take_while(|line| !line.trim_start().starts_with(">>"))
        .filter_map(|line| line.split('@').next().map(str::trim).filter(|entry| !entry.is_empty()))
        .map(str::to_owned)
        .collect();
    (!listed.is_empty()).then_some(listed)
}

/// The module files of a task folder: `SYSMOD` then `PROGMOD`, each sorted by name.
fn folder_modules(task: &Path) -> Vec<PathBuf> {
    let mut modules = Vec::new();
    for sub in ["SYSMOD", "PROGMOD"] {
        let Some(dir) = child(task, sub).filter(|p| p.is_dir()) else { continue };
        let Ok(entries) = fs::read_dir(&dir) else { continue };
        let mut files: Vec<PathBuf> = entries
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| p.is_file() && super::file_kind(p) == Some(super::FileKind::Module))
            .collect();
        files.sort();
        modules.extend(files);
    }
    modules
}

/// Why task `task`, which SYS.cfg configures, has no program: no task folder (or an
/// empty one) and no module of HOME loaded into it.
pub(super) fn no_program(task: &TaskFolder, has_folder: bool) -> String {
    let folder = task.folder.display();
    let why = match has_folder {
        true => format!("its task folder `{folder}` holds no modules in PROGMOD or SYSMOD"),
        false => format!("it has no task folder `{folder}`"),
    };
    format!("task {} has no program: {why}, and SYS.cfg loads no module of HOME into it (CAB_TASK_MODULES)", task.name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backinfo_task_lines() {
        assert_eq!(parse_backinfo_task(">>TASK1: (T_ROB1,,)"), Some((1, "T_ROB1".into())));
        assert_eq!(parse_backinfo_task(">>TASK2: (T_BACK,BASE,)"), Some((2, "T_BACK".into())));
        assert_eq!(parse_backinfo_task(">>SYSPAR:"), None);
        assert_eq!(parse_backinfo_task("PROGMOD\\MainModule.mod @ "), None);
    }

    #[test]
    fn task_folder_numbers() {
        assert_eq!(task_number("TASK2"), Some(2));
        assert_eq!(task_number("task10"), Some(10));
        assert_eq!(task_number("PROGMOD"), None);
    }
}
