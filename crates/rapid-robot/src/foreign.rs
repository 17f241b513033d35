//! Units another motion task moves (MultiMove): a robot may work in a work object that
//! rides an external unit of another task (`ufprog` FALSE, `ufmec` the unit's name), a
//! positioner in its own task being the usual case.
//!
//! The unit's task publishes where its external axes go ([`UnitPath`]: its final moves,
//! the move waiting for its successor, where its axes end), and the robots of the other
//! tasks read the unit's position at any time from it. The MultiMove manual describes
//! two ways to work in such an object:
//! - **semi-coordinated**: the unit moves the object only while no robot works in it,
//!   and robots work in it only while it stands; the tasks synchronize in between
//!   (WaitSyncTask). A robot's moves are planned in the object where the unit stands.
//! - **synchronized** (SyncMoveOn of both tasks): the robot follows the object as it
//!   follows a unit of its own (`conveyor.rs` spans), wherever the unit's task moves it.
//!
//! Breaking the semi-coordinated rule (a robot moving in the object while its unit moves,
//! outside synchronized movement of both tasks) stops execution, in whichever task comes
//! second: the robot's move, or the unit's.
// uncertain: the controller's own reaction to a unit moving under a semi-coordinated
// robot is not in our sources; execution stops with a message.

use crate::RobotResources;
use std::sync::{Arc, RwLock, RwLockReadGuard};

use rapid_motion::external::{Eax, UnitChain};
use rapid_motion::plan::PlannedMove;

use rapid_tasks::TaskingAccess;
use rapid_vm::ext::{Ctx, RapidError};

/// How far apart two axis values may be and still be one position.
const SAME_POSITION: f64 = 1e-9;

/// How long (s) the history of a task that keeps no record stays published: the
/// readers only look back as far as their own moves reach.
const KEEP_PAST: f64 = 600.0;

/// The motion of a task's external axes, as its task has planned it.
#[derive(Debug)]
pub struct UnitPath {
    /// Where the axes stood before the first move published.
    start: Eax,
    /// The task's final moves, oldest first (only their external axes are read).
    moves: Vec<PlannedMove>,
    /// The move waiting for its successor, with its stop plan.
    provisional: Option<PlannedMove>,
    /// Where the planned motion leaves the axes.
    end: Eax,
    /// The axes in independent mode: their own motion is not published.
    independent: [bool; 6],
    /// The task's path stands since then (StopMove) until it goes on (StartMove, which
    /// publishes the rest of the path later).
    paused_since: Option<f64>,
    /// The tasks whose robots work in the work object of a unit.
    busy: Vec<Busy>,
}

/// A robot of task `task` works in a work object unit `unit` carries: it has `open`
/// moves there that are not final, and its final ones end by `until`.
#[derive(Debug, Clone, PartialEq)]
pub struct Busy {
    pub unit: String,
    pub task: String,
    open: usize,
    until: f64,
}

impl Busy {
    /// Whether the robot may still move in the object at or after `t`.
    fn after(&self, t: f64) -> bool {
        self.open > 0 || self.until > t
    }
}

impl UnitPath {
    fn new(start: Eax) -> UnitPath {
        UnitPath {
            start,
            moves: Vec::new(),
            provisional: None,
            end: start,
            independent: [false; 6],
            paused_since: None,
            busy: Vec::new(),
        }
    }

    /// Where the axes are at time `t`.
    pub fn eax_at(&self, t: f64) -> Eax {
        let t = self.paused_since.map_or(t, |since| t.min(since));
        if let Some(waiting) = self.provisional.as_ref().filter(|p| t >= p.start) {
            return waiting.eax_at(t).unwrap_or(self.end);
        }
        let on = self.moves.partition_point(|m| m.start <= t);
        match on.checked_sub(1).map(|k| &self.moves[k]) {
            Some(last) if on == self.moves.len() && t >= last.end && self.provisional.is_none() => self.end,
            Some(m) => m.eax_at(t).unwrap_or(self.end),
            // Before the first move published: where it starts (no move: where it stands).
            None => self.moves.first().map_or(self.end, |m| m.eax_at(m.start).unwrap_or(self.start)),
        }
    }

    /// Whether any of `axes` moves at or after time `t`.
    fn moves_after(&self, t: f64, axes: &[usize]) -> bool {
        let differ = |a: &Eax, b: &Eax| axes.iter().any(|&j| (a[j] - b[j]).abs() > SAME_POSITION);
        let moving = |m: &PlannedMove| {
            let from = m.eax_at(m.start.max(t)).unwrap_or(self.end);
            m.eax_end().is_some_and(|to| differ(&from, &to))
        };
        let later = self.moves.iter().rev().take_while(|m| m.end > t);
        later.chain(self.provisional.iter()).any(moving) || differ(&self.eax_at(t), &self.end)
    }

    /// The robot of another task that works in `unit`'s object at or after `t`.
    pub fn busy_after(&self, unit: &str, t: f64) -> Option<&Busy> {
        self.busy.iter().find(|b| b.unit.eq_ignore_ascii_case(unit) && b.after(t))
    }

    fn busy_mut(&mut self, unit: &str, task: &str) -> &mut Busy {
        let same = |b: &Busy| b.unit.eq_ignore_ascii_case(unit) && b.task.eq_ignore_ascii_case(task);
        let at = self.busy.iter().position(same);
        let at = at.unwrap_or_else(|| {
            let busy = Busy { unit: unit.to_owned(), task: task.to_owned(), open: 0, until: f64::NEG_INFINITY };
            self.busy.push(busy);
            self.busy.len() - 1
        });
        &mut self.busy[at]
    }
}

/// A task's published [`UnitPath`], shared with the tasks that read it.
#[derive(Debug, Clone)]
pub struct SharedPath(Arc<RwLock<UnitPath>>);

impl PartialEq for SharedPath {
    fn eq(&self, other: &SharedPath) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl SharedPath {
    fn new(start: Eax) -> SharedPath {
        SharedPath(Arc::new(RwLock::new(UnitPath::new(start))))
    }

    /// The path to read. A writer that panicked left it as it was: still readable.
    pub fn read(&self) -> RwLockReadGuard<'_, UnitPath> {
        self.0.read().unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    fn write(&self, change: impl FnOnce(&mut UnitPath)) {
        change(&mut self.0.write().unwrap_or_else(|poisoned| poisoned.into_inner()));
    }
}

/// An external unit of another motion task that carries work objects.
#[derive(Debug, Clone, PartialEq)]
pub struct ForeignUnit {
    pub name: String,
    /// The task that moves it, and the task reading it (this one).
    pub owner: String,
    pub reader: String,
    pub chain: UnitChain,
    /// Its axes' `extjoint` indexes (in its own task's external axes).
    pub axes: Vec<usize>,
    pub path: SharedPath,
}

/// A motion task as [`link`] sees it: its name and its robot.
pub struct LinkedTask<'a> {
    pub name: &'a str,
    pub robot: &'a mut super::robot::RobotState,
}

/// Lets every motion task work in the work objects the other tasks' units carry: each
/// task with such a unit publishes its external axes' motion, and the others read it.
pub fn link(tasks: &mut [LinkedTask<'_>]) {
    let names: Vec<(String, String)> = tasks
        .iter()
        .flat_map(|t| t.robot.external.units.iter().map(|u| (u.unit.name.clone(), t.name.to_owned())))
        .collect();
    for task in tasks.iter_mut() {
        let others = names.iter().filter(|(_, owner)| !owner.eq_ignore_ascii_case(task.name));
        task.robot.external.others = others.cloned().collect();
    }
    let mut offered = Vec::new();
    for task in tasks.iter_mut() {
        let external = &mut task.robot.external;
        let carriers: Vec<_> = external
            .units
            .iter()
            .filter(|u| !u.unit.carries_robot)
            .filter_map(|u| {
                Some((u.unit.name.clone(), u.unit.chain()?, u.unit.axes.iter().map(|a| a.index()).collect()))
            })
            .collect();
        if carriers.is_empty() {
            continue;
        }
        let path = SharedPath::new(external.start());
        external.publication = Some(path.clone());
        offered.push((task.name.to_owned(), carriers, path));
    }
    for task in tasks.iter_mut() {
        for (owner, carriers, path) in &offered {
            if owner.eq_ignore_ascii_case(task.name) {
                continue;
            }
            for (name, chain, axes) in carriers {
                task.robot.external.foreign.push(ForeignUnit {
                    name: name.clone(),
                    owner: owner.clone(),
                    reader: task.name.to_owned(),
                    chain: *chain,
                    axes: Vec::clone(axes),
                    path: path.clone(),
                });
            }
        }
    }
}

impl super::robot::RobotState {
    /// Publishes a move that became final (see [`UnitPath`]).
    pub(super) fn publish_final(&self, planned: &PlannedMove) {
        let Some(path) = &self.external.publication else { return };
        let keep_all = self.recorded.is_some();
        path.write(|p| {
            p.moves.push(planned.clone());
            if !keep_all {
                let old = p.moves.iter().take_while(|m| m.end < planned.start - KEEP_PAST).count();
                p.moves.drain(..old);
            }
        });
    }

    /// Publishes the move waiting for its successor and where the axes end.
    pub(super) fn publish_tail(&self) {
        let Some(path) = &self.external.publication else { return };
        let provisional = self.planner.provisional().map(|(planned, _)| planned);
        let end = self.planner.end_eax().unwrap_or(self.external.start());
        let independent = self.independent.external_mask();
        path.write(|p| {
            p.provisional = provisional;
            p.end = end;
            p.independent = independent;
        });
    }

    /// Publishes whether the path stands (StopMove); after every built-in, so that every
    /// way to stop or go on is seen.
    pub fn publish_pause(&self) {
        let Some(path) = &self.external.publication else { return };
        let since = self.pause.as_ref().map(|p| p.since);
        if path.read().paused_since != since {
            path.write(|p| p.paused_since = since);
        }
    }

    /// Publishes the whole path again after it changed in the past (a stop, a pause).
    pub(super) fn republish(&self) {
        let Some(path) = &self.external.publication else { return };
        let kept: Vec<PlannedMove> = match &self.recorded {
            Some(recorded) => recorded.clone(),
            None => self.ahead.iter().cloned().collect(),
        };
        path.write(|p| {
            let from = kept.first().map_or(f64::INFINITY, |m| m.start);
            p.moves.retain(|m| m.start < from);
            p.moves.extend(kept);
        });
        self.publish_tail();
    }

    /// Where foreign unit `f`'s axes are at `t`.
    pub(super) fn foreign_eax_at(&self, f: usize, t: f64) -> Option<Eax> {
        self.external.foreign.get(f).map(|unit| unit.path.read().eax_at(t))
    }

    /// The robot is given a move in foreign unit `f`'s work object: its unit's task
    /// sees it busy there until the move is final and over.
    pub(super) fn busy_in(&self, f: usize) {
        let Some(unit) = self.external.foreign.get(f) else { return };
        unit.path.write(|p| p.busy_mut(&unit.name, &unit.reader).open += 1);
    }

    /// A move in foreign unit `f`'s work object ended at `end` (final, or cut by a stop).
    pub(super) fn busy_until(&self, f: usize, end: f64) {
        let Some(unit) = self.external.foreign.get(f) else { return };
        unit.path.write(|p| {
            let busy = p.busy_mut(&unit.name, &unit.reader);
            busy.open = busy.open.saturating_sub(1);
            busy.until = busy.until.max(end);
        });
    }
}

/// Whether this task moves synchronized with task `other` now (both after SyncMoveOn
/// with each other in the task list, neither suspended).
fn synchronized_with(ctx: &Ctx<'_>, other: &str) -> bool {
    let tasking = ctx.resources.tasking();
    let Some(mode) = tasking.sync_move.as_ref().filter(|m| !m.suspended) else { return false };
    mode.members.iter().any(|m| m.eq_ignore_ascii_case(other))
        && tasking.shared.in_sync.iter().any(|t| t.eq_ignore_ascii_case(other))
}

/// Whether the robot follows foreign unit `f` in its next move (synchronized movement
/// with the unit's task), rather than working in its object where it stands
/// (semi-coordinated). Semi-coordinated, the unit must stand from now on; either way
/// none of its axes may be independent.
pub(super) fn follows(ctx: &Ctx<'_>, f: usize) -> Result<bool, RapidError> {
    let unit = &ctx.resources.robot().external.foreign[f];
    let path = unit.path.read();
    if unit.axes.iter().any(|&j| path.independent[j]) {
        return Err(RapidError::fatal(format!(
            "the work object's unit {} (task {}) has an axis in independent mode: working in it from another task is \
             not supported yet",
            unit.name, unit.owner
        )));
    }
    if synchronized_with(ctx, &unit.owner) {
        return Ok(true);
    }
    // The move starts once the robot's moves given before it are under way, at the
    // earliest (the program runs ahead of the robot).
    let start = ctx.resources.robot().planner.time().max(ctx.time);
    if path.moves_after(start, &unit.axes) {
        return Err(RapidError::fatal(format!(
            "the work object's unit {} (task {}) moves: outside synchronized movement with that task (SyncMoveOn) a \
             robot works in the object only while the unit stands (semi-coordinated movement: synchronize the tasks \
             after the unit's stop point, e.g. WaitSyncTask)",
            unit.name, unit.owner
        )));
    }
    Ok(false)
}

/// Before this task moves its external axes from `from` to `to`: no robot of another
/// task may still move in the object of a unit that moves, unless both tasks move
/// synchronized.
pub(super) fn check_unit_move(ctx: &Ctx<'_>, from: &Eax, to: &Eax) -> Result<(), RapidError> {
    let external = &ctx.resources.robot().external;
    let Some(path) = &external.publication else { return Ok(()) };
    let path = path.read();
    // The move starts once this task's moves given before it are under way, at the earliest.
    let start = ctx.resources.robot().planner.time().max(ctx.time);
    for state in &external.units {
        let moves = state.unit.axes.iter().any(|a| (to[a.index()] - from[a.index()]).abs() > SAME_POSITION);
        let Some(busy) = path.busy_after(&state.unit.name, start).filter(|_| moves) else { continue };
        if synchronized_with(ctx, &busy.task) {
            continue;
        }
        return Err(RapidError::fatal(format!(
            "unit {} would move while the robot of task {} moves in a work object it carries: outside synchronized \
             movement (SyncMoveOn) the unit moves the object only while the robots working in it stand \
             (semi-coordinated movement: their stop point, then e.g. WaitSyncTask)",
            state.unit.name, busy.task
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn busy_counts_open_moves_and_keeps_the_latest_end() {
        let mut path = UnitPath::new([0.0; 6]);
        path.busy_mut("STN1", "T_ROB1").open += 2;
        assert!(path.busy_after("stn1", 100.0).is_some(), "moves not final keep it busy");
        for end in [3.0, 2.0] {
            let busy = path.busy_mut("STN1", "T_ROB1");
            busy.open -= 1;
            busy.until = busy.until.max(end);
        }
        assert!(path.busy_after("STN1", 2.5).is_some(), "the later move ends at 3 s");
        assert!(path.busy_after("STN1", 3.0).is_none());
        assert!(path.busy_after("STN2", 0.0).is_none());
    }

    #[test]
    fn a_path_without_moves_stands_where_it_started_and_ends() {
        let mut path = UnitPath::new([10.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert_eq!(path.eax_at(5.0)[0], 10.0);
        assert!(!path.moves_after(0.0, &[0]));
        // An IndReset left the axis elsewhere: it stands there, and does not move.
        path.end[0] = 20.0;
        assert_eq!(path.eax_at(5.0)[0], 20.0);
        assert!(!path.moves_after(0.0, &[0]));
    }
}
