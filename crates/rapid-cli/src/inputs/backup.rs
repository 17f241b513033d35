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
//! A folder holding `RAPID/TASKn` is a backup. The task checked and run is T_ROB1 (the
//! task SYS.cfg names so, else its first task; the folder is found through
//! backinfo.txt, else by the task's place in SYS.cfg, else the first task folder).
//! Names are matched without regard to case: backups copied from Windows keep
//! whatever case their files happen to have.

use std::fs;
use std::path::{Path, PathBuf};

use rapid_config::sys::Sys;

/// The task the backup's program is read from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct TaskFolder {
    /// The task's name (`T_ROB1`), or the folder's when no configuration names it.
    pub(crate) name: String,
    pub(crate) folder: PathBuf,
    /// The routine the task starts in (`-Entry` in SYS.cfg), when SYS.cfg has the task.
    pub(crate) entry: Option<String>,
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

/// The `RAPID/TASKn` folders of a backup, ordered by n; empty when `folder` is no backup.
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
    tasks
}

/// The `SYSPAR/*.cfg` files of a backup, sorted by name.
pub(crate) fn config_files(folder: &Path) -> Vec<PathBuf> {
    let Some(syspar) = child(folder, "SYSPAR").filter(|p| p.is_dir()) else { return Vec::new() };
    let Ok(entries) = fs::read_dir(&syspar) else { return Vec::new() };
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

/// The task to read: `wanted`, else T_ROB1, else SYS.cfg's first task, else the first
/// task folder.
pub(crate) fn choose_task(
    folder: &Path,
    tasks: &[(u32, PathBuf)],
    sys: Option<&Sys>,
    wanted: Option<&str>,
) -> Option<TaskFolder> {
    let first = tasks.first()?;
    let names = backinfo_tasks(folder);
    let wanted = match wanted {
        Some(name) => Some(name.to_owned()),
        None => sys.and_then(|sys| sys.task("T_ROB1").or(sys.tasks.first())).map(|t| t.name.clone()),
    };
    let wanted =
        wanted.or_else(|| names.iter().find(|(_, n)| n.eq_ignore_ascii_case("T_ROB1")).map(|(_, n)| n.clone()));
    let Some(wanted) = wanted else {
        let name = names.iter().find(|(n, _)| *n == first.0).map_or_else(|| folder_name(&first.1), |(_, n)| n.clone());
        return Some(TaskFolder { name, folder: first.1.clone(), entry: None });
    };
    // The folder of the task: backinfo.txt says; else the task's place in SYS.cfg.
    // uncertain: RobotWare numbers TASKn folders in CAB_TASKS order; backinfo.txt is
    // what backups we have seen use to say it.
    let number = names.iter().find(|(_, n)| n.eq_ignore_ascii_case(&wanted)).map(|(n, _)| *n).or_else(|| {
        let place = sys?.tasks.iter().position(|t| t.name.eq_ignore_ascii_case(&wanted))?;
        u32::try_from(place + 1).ok()
    });
    // A task whose folder is missing has no program: never another task's (the caller
    // reports the missing folder).
    let folder = match number {
        Some(n) => tasks.iter().find(|(m, _)| *m == n).map_or_else(|| rapid_task_folder(folder, n), |f| f.1.clone()),
        None => first.1.clone(),
    };
    let entry = sys.and_then(|sys| sys.task(&wanted)).map(|t| t.entry.clone());
    Some(TaskFolder { name: wanted, folder, entry })
}

/// Where task folder `n` of a backup would be: `RAPID/TASKn`.
fn rapid_task_folder(folder: &Path, n: u32) -> PathBuf {
    child(folder, "RAPID").unwrap_or_else(|| folder.join("RAPID")).join(format!("TASK{n}"))
}

fn folder_name(path: &Path) -> String {
    path.file_name().and_then(|n| n.to_str()).unwrap_or("TASK").to_owned()
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
pub(crate) fn task_modules(backup: &Path, task: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let number = task.file_name().and_then(|n| n.to_str()).and_then(task_number);
    let Some(listed) = number.and_then(|n| backinfo_modules(backup, n)) else { return Ok(folder_modules(task)) };
    listed
        .iter()
        .map(|entry| {
            let found = entry.split(['\\', '/']).try_fold(task.to_path_buf(), |dir, part| child(&dir, part));
            found.filter(|p| p.is_file()).ok_or_else(|| {
                anyhow::anyhow!(
                    "backup `{}`: backinfo.txt lists module `{entry}` for `{}`, which the folder does not hold",
                    backup.display(),
                    task.display()
                )
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
