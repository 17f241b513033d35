//! Which robot (`ROB_n`) each motion task of a system moves. A task's mechanical unit
//! group (SYS.cfg `-UseMechanicalUnitGroup`) names it: the group's
//! `MECHANICAL_UNIT_GROUP -Robot`, written in SYS.cfg (RobotWare 6) or MOC.cfg (found in
//! a real MultiMove backup). A real backup may list T_ROB2 before T_ROB1 in CAB_TASKS,
//! so the robots are numbered by their groups, not by the tasks' order. A motion task
//! whose group names no robot, or that has no group (manifests, a backup without
//! groups), gets the lowest number no group names, in configuration order: without
//! groups the n-th motion task with a robot moves ROB_n. A group without a robot is a
//! positioner's: its task moves external units only.

use rapid_config::sys::{Sys, Task};
use rapid_config::CfgFile;

/// A mechanical unit group as the configuration writes it.
pub struct Group {
    /// `-Robot`; none for a positioner's group.
    pub robot: Option<String>,
    /// Where it is written: the file's domain (`SYS`, `MOC`) and the line.
    pub domain: &'static str,
    pub line: u32,
}

/// What the configuration says wrong about the robots: at `line` of the file of
/// configuration domain `domain`.
#[derive(Debug)]
pub struct Finding {
    pub domain: &'static str,
    pub line: u32,
    pub message: String,
}

/// The mechanical unit group task `task` uses, looked for in SYS.cfg, then MOC.cfg;
/// `None` when the task names none or no file has it.
pub fn group(syspar: &[(String, CfgFile)], task: &Task) -> Option<Group> {
    let name = task.mechanical_unit_group.as_deref()?;
    ["SYS", "MOC"].into_iter().find_map(|domain| {
        let file = config(syspar, domain)?;
        let found = rapid_config::moc::group(file, name)?;
        Some(Group { robot: found.robot, domain, line: found.line })
    })
}

/// Whether motion task `task` moves a robot: not when a manifest gives it `robot =
/// false`, nor when its group has no robot (a positioner's task).
pub fn has_robot(syspar: &[(String, CfgFile)], task_robots: &[(String, Option<String>)], task: &Task) -> bool {
    let own = task_robots.iter().find(|(t, _)| t.eq_ignore_ascii_case(&task.name)).map(|(_, m)| m);
    let robotless = group(syspar, task).is_some_and(|g| g.robot.is_none());
    task.motion_task && !matches!(own, Some(None)) && !robotless
}

/// The `n` of the robot ROB_n each task of `sys` moves, in the order of `sys.tasks`;
/// `None` for a task without a robot. Fails on a group naming a robot MOC.cfg does not
/// have (or, without MOC.cfg's robots, a name that is no ROB_n), and on two tasks moving
/// one robot.
pub fn numbers(
    sys: &Sys,
    syspar: &[(String, CfgFile)],
    task_robots: &[(String, Option<String>)],
) -> Result<Vec<Option<usize>>, Finding> {
    let known: Vec<String> =
        config(syspar, "MOC").map(rapid_config::moc::robots).unwrap_or_default().into_iter().map(|r| r.name).collect();
    let mut numbers: Vec<Option<usize>> = vec![None; sys.tasks.len()];
    // The robots the groups name first, so that the others take the numbers left.
    let mut unnamed = Vec::new();
    for (idx, task) in sys.tasks.iter().enumerate() {
        if !has_robot(syspar, task_robots, task) {
            continue;
        }
        let Some((robot, group)) = group(syspar, task).and_then(|g| Some((g.robot.clone()?, g))) else {
            unnamed.push(idx);
            continue;
        };
        let n = robot_number(&robot, &known).map_err(|why| Finding {
            domain: group.domain,
            line: group.line,
            message: format!(
                "mechanical unit group `{}` (of task {}) names robot `{robot}`, {why}",
                task.mechanical_unit_group.as_deref().unwrap_or_default(),
                task.name
            ),
        })?;
        if let Some(other) = numbers.iter().position(|&m| m == Some(n)) {
            return Err(Finding {
                domain: "SYS",
                line: task.line,
                message: format!(
                    "task {} moves robot ROB_{n} (mechanical unit group `{}`), which task {} moves already: \
                     a robot is moved by one task",
                    task.name,
                    task.mechanical_unit_group.as_deref().unwrap_or_default(),
                    sys.tasks[other].name
                ),
            });
        }
        numbers[idx] = Some(n);
    }
    for idx in unnamed {
        let free = (1..).find(|n| !numbers.contains(&Some(*n))).unwrap_or(1);
        numbers[idx] = Some(free);
    }
    Ok(numbers)
}

/// The `n` of the robot ROB_n a program run alone (one task) moves: its group's, else 1.
pub fn of_single_task(
    sys: Option<&Sys>,
    syspar: &[(String, CfgFile)],
    task_robots: &[(String, Option<String>)],
) -> usize {
    let Some(sys) = sys else { return 1 };
    let numbers = numbers(sys, syspar, task_robots).unwrap_or_default();
    numbers.into_iter().flatten().next().unwrap_or(1)
}

/// The `n` the run numbers robot `name` by: n for `ROB_n`; a robot named otherwise
/// (`ROB_L`, `ROB_R` of a two-arm system) takes its place among MOC.cfg's robots
/// (`known`, in configuration order) plus one. With MOC.cfg's robots, the name must be
/// one of them. Fails with why not.
// uncertain: RobotWare numbers motion planners by the mechanical unit groups; a system
// mixing ROB_n names with others could number them differently.
fn robot_number(name: &str, known: &[String]) -> Result<usize, String> {
    let place = known.iter().position(|k| k.eq_ignore_ascii_case(name));
    if !known.is_empty() && place.is_none() {
        return Err(format!("which MOC.cfg does not have (its robots: {})", known.join(", ")));
    }
    match (numbered(name), place) {
        (Some(n), _) => Ok(n),
        (None, Some(i)) => Ok(i + 1),
        (None, None) => Err("which is no ROB_n, and the system has no MOC.cfg naming its robots".to_owned()),
    }
}

/// The n of a robot named `ROB_n` (n ≥ 1).
fn numbered(name: &str) -> Option<usize> {
    let upper = name.to_ascii_uppercase();
    upper.strip_prefix("ROB_").and_then(|n| n.parse::<usize>().ok()).filter(|&n| n >= 1)
}

/// MOC.cfg's `ROBOT` instance the run numbers `n` (`ROB_n`, or the n-th robot named
/// otherwise), if the system has a MOC.cfg naming it.
pub fn moc_robot(syspar: &[(String, CfgFile)], n: usize) -> Option<rapid_config::moc::Robot> {
    let robots = rapid_config::moc::robots(config(syspar, "MOC")?);
    let known: Vec<String> = robots.iter().map(|r| r.name.clone()).collect();
    robots.into_iter().find(|r| robot_number(&r.name, &known) == Ok(n))
}

/// The configuration file of domain `domain`, if the system has one.
fn config<'a>(syspar: &'a [(String, CfgFile)], domain: &str) -> Option<&'a CfgFile> {
    syspar.iter().find(|(d, _)| d.eq_ignore_ascii_case(domain)).map(|(_, file)| file)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn syspar(sys: &str, moc: &str) -> Vec<(String, CfgFile)> {
        vec![("SYS".to_owned(), rapid_config::parse(sys)), ("MOC".to_owned(), rapid_config::parse(moc))]
    }

    fn numbered(sys: &str, moc: &str) -> Result<Vec<Option<usize>>, Finding> {
        let syspar = syspar(sys, moc);
        let view = rapid_config::sys::read(&syspar[0].1);
        numbers(&view, &syspar, &[])
    }

    const TASKS: &str = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB2\" -UseMechanicalUnitGroup \"rob2\" \
                         -MotionTask\n\n      -Name \"T_PLC\"\n\n      -Name \"T_ROB1\" -UseMechanicalUnitGroup \"rob1\" \
                         -MotionTask\n";

    #[test]
    fn the_groups_number_the_robots() {
        let groups = "#\nMECHANICAL_UNIT_GROUP:\n\n      -Name \"rob1\" -Robot \"ROB_1\"\n\n      -Name \"rob2\" -Robot \"ROB_2\"\n";
        assert_eq!(
            numbered(&format!("{TASKS}{groups}"), "MOC:CFG_1.0:6:0::\n").expect("numbered"),
            [Some(2), None, Some(1)]
        );
    }

    #[test]
    fn tasks_without_a_named_robot_take_the_numbers_left() {
        // T_ROB2's group names ROB_1; T_ROB1 has no group: it gets ROB_2.
        let sys = TASKS.replace(" -UseMechanicalUnitGroup \"rob1\"", "")
            + "#\nMECHANICAL_UNIT_GROUP:\n\n      -Name \"rob2\" -Robot \"ROB_1\"\n";
        assert_eq!(numbered(&sys, "").expect("numbered"), [Some(1), None, Some(2)]);
        // Without groups, the tasks' order.
        let plain =
            TASKS.replace(" -UseMechanicalUnitGroup \"rob1\"", "").replace(" -UseMechanicalUnitGroup \"rob2\"", "");
        assert_eq!(numbered(&plain, "").expect("numbered"), [Some(1), None, Some(2)]);
    }

    #[test]
    fn two_tasks_moving_one_robot_are_refused_at_the_second() {
        let groups = "#\nMECHANICAL_UNIT_GROUP:\n\n      -Name \"rob1\" -Robot \"ROB_2\"\n\n      -Name \"rob2\" -Robot \"ROB_2\"\n";
        let found = numbered(&format!("{TASKS}{groups}"), "").expect_err("refused");
        // T_ROB1's CAB_TASKS instance is on line 9.
        assert_eq!((found.domain, found.line), ("SYS", 9));
        assert!(found.message.contains("task T_ROB1 moves robot ROB_2"), "{}", found.message);
        assert!(found.message.contains("which task T_ROB2 moves already"), "{}", found.message);
    }

    #[test]
    fn a_group_naming_a_robot_moc_cfg_lacks_is_refused_at_the_group() {
        let groups = "#\nMECHANICAL_UNIT_GROUP:\n\n      -Name \"rob1\" -Robot \"ROB_1\"\n\n      -Name \"rob2\" -Robot \"ROB_3\"\n";
        let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\"\n\n      -name \"ROB_2\"\n";
        let found = numbered(&format!("{TASKS}{groups}"), moc).expect_err("refused");
        // The group rob2 is on line 15 of SYS.cfg.
        assert_eq!((found.domain, found.line), ("SYS", 15));
        assert!(found.message.contains("names robot `ROB_3`, which MOC.cfg does not have"), "{}", found.message);
        // Without MOC.cfg's robots, a name that is no ROB_n.
        let odd = groups.replace("ROB_3", "ARM_B");
        let found = numbered(&format!("{TASKS}{odd}"), "").expect_err("refused");
        assert!(found.message.contains("which is no ROB_n"), "{}", found.message);
    }

    #[test]
    fn robots_named_otherwise_take_their_place_in_moc_cfg() {
        // A two-arm system: ROB_L first in MOC.cfg, so ROB_1's number; ROB_R second.
        let groups = "#\nMECHANICAL_UNIT_GROUP:\n\n      -Name \"rob1\" -Robot \"ROB_R\"\n\n      -Name \"rob2\" -Robot \"ROB_L\"\n";
        let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_L\" -use_robot_type \"T_L\"\n\n      -name \"ROB_R\" -use_robot_type \"T_R\"\n";
        // T_ROB2 uses rob2 (ROB_L, 1), T_ROB1 uses rob1 (ROB_R, 2).
        assert_eq!(numbered(&format!("{TASKS}{groups}"), moc).expect("numbered"), [Some(1), None, Some(2)]);
        let syspar = syspar("", moc);
        assert_eq!(moc_robot(&syspar, 2).map(|r| r.name), Some("ROB_R".to_owned()));
        assert_eq!(moc_robot(&syspar, 3).map(|r| r.name), None);
    }
}
