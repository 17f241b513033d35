//! System outputs (`SYSSIG_OUT`) that name what the assembled system lacks: a task
//! (`-Arg2`) that is not one of its tasks, or a mechanical unit (`-Arg1`) that is no
//! robot a task moves. `rapid run` refuses to start such a system
//! (`crate::ops`); these findings let `rapid check` report the same, at the
//! output's line, before anything runs.

use crate::boot::cell::TaskUnit;
use crate::boot::robots;
use rapid_config::eio::syssig::{status_name, SysStatus};
use rapid_config::{eio, sys, CfgFile};

/// The (line, message) of each such output of the EIO configuration in `syspar`. The
/// tasks are `sys`'s (or the one task `task` when it configures none); the robots are
/// those the tasks move (`robots::numbers`, with a manifest's `task_robots`); an
/// external unit (`units`) is refused as `rapid run` refuses it: robots only for now.
pub(super) fn findings(
    syspar: &[(String, CfgFile)],
    sys: Option<&sys::Sys>,
    task: &str,
    task_robots: &[(String, Option<String>)],
    units: &[TaskUnit],
) -> Vec<(u32, String)> {
    let Some(eio) = syspar.iter().find(|(d, _)| d == "EIO").map(|(_, file)| eio::read(file)) else {
        return Vec::new();
    };
    let configured = sys.filter(|sys| !sys.tasks.is_empty());
    let tasks: Vec<&str> = match configured {
        Some(sys) => sys.tasks.iter().map(|t| t.name.as_str()).collect(),
        None => vec![task],
    };
    let moved: Vec<usize> = match configured {
        // A configuration that numbers the robots wrongly is a finding of its own.
        Some(sys) => robots::numbers(sys, syspar, task_robots).map(|n| n.into_iter().flatten().collect()),
        None => Ok(vec![robots::of_single_task(sys, syspar, task_robots)]),
    }
    .unwrap_or_default();
    // The statuses not simulated are never set, so never looked at (ops.rs).
    let simulated = eio.sys_outputs.iter().filter(|out| !matches!(out.status, SysStatus::NotSimulated(_)));
    simulated
        .filter_map(|out| {
            let signal = &out.signal;
            if let Some(unit) = &out.unit {
                let number = unit.to_ascii_uppercase().strip_prefix("ROB_").and_then(|n| n.parse::<usize>().ok());
                if number.is_some_and(|n| moved.contains(&n)) {
                    return None;
                }
                let status = status_name(out.status);
                let message = if units.iter().any(|u| u.unit.name.eq_ignore_ascii_case(unit)) {
                    format!("system output `{signal}`: {status} of external unit `{unit}` is not supported yet (robots only)")
                } else {
                    format!("system output `{signal}` names mechanical unit `{unit}`, which the system does not have")
                };
                return Some((out.line, message));
            }
            let name = out.task.as_deref()?;
            let known = tasks.iter().any(|t| t.eq_ignore_ascii_case(name));
            let message = format!("system output `{signal}` names task `{name}`, which the system does not have");
            (!known).then_some((out.line, message))
        })
        .collect()
}
