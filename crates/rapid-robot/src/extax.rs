//! The task's external axes (§2.1 extjoint): the mechanical units besides the arm
//! that the configuration gives the motion task, which of them are active, and what
//! a move's `extax` asks of them.
//!
//! A target's value for an axis moves it when the axis exists and its unit is active;
//! values for axes the system does not have are ignored, as on the controller. An
//! active axis given 9E9 stays where it is.
// uncertain: the controller's reaction to 9E9 for an active axis is not in our notes;
// it is taken to leave the axis where it stands.

use crate::RobotResources;
use rapid_motion::external::{is_unused, Eax, ExternalAxis, ExternalMove, ExternalUnit};
use rapid_motion::MotionError;

/// A unit and whether it is active now (ActUnit/DeactUnit).
#[derive(Debug, Clone, PartialEq)]
pub struct UnitState {
    pub unit: ExternalUnit,
    pub active: bool,
    /// MechUnitLoad's payload mass (kg) by axis number (from 1).
    pub loads: std::collections::BTreeMap<usize, f64>,
}

/// The external units of a motion task.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ExternalUnits {
    pub units: Vec<UnitState>,
    /// Where this task's external axes go, published for the other motion tasks when
    /// one of its units carries work objects (`foreign.rs`).
    pub publication: Option<super::foreign::SharedPath>,
    /// The units of other motion tasks that carry work objects.
    pub foreign: Vec<super::foreign::ForeignUnit>,
    /// Every unit of another motion task, with its task: (unit, task).
    pub others: Vec<(String, String)>,
    /// A 7-axis arm's axis 7, carried as eax_a (`arm7.rs`): part of the robot, no unit.
    pub arm7: Option<ExternalAxis>,
}

impl ExternalUnits {
    pub fn new(units: Vec<ExternalUnit>) -> ExternalUnits {
        let units = units
            .into_iter()
            .map(|unit| UnitState { active: unit.active_at_start, unit, loads: Default::default() })
            .collect();
        ExternalUnits { units, ..ExternalUnits::default() }
    }

    /// Adds a unit (a conveyor's, which has no axes the moves drive).
    pub fn add_unit(&mut self, unit: ExternalUnit) {
        self.units.push(UnitState { active: unit.active_at_start, unit, loads: Default::default() });
    }

    /// Whether the unit of this name is active; `None` when the task has no such unit.
    pub fn is_active(&self, name: &str) -> Option<bool> {
        self.find(name).map(|i| self.units[i].active)
    }

    /// Whether the task has any external axis (a 7-axis arm's axis 7 counts).
    pub fn any(&self) -> bool {
        self.arm7.is_some() || self.units.iter().any(|u| !u.unit.axes.is_empty())
    }

    /// The unit of this name (case as the configuration spells it, compared without).
    pub fn find(&self, name: &str) -> Option<usize> {
        self.units.iter().position(|u| u.unit.name.eq_ignore_ascii_case(name))
    }

    /// The unit of another task of this name that carries work objects.
    pub fn find_foreign(&self, name: &str) -> Option<usize> {
        self.foreign.iter().position(|u| u.name.eq_ignore_ascii_case(name))
    }

    /// The axis at `extjoint` index `j` and whether its unit is active.
    fn axis(&self, j: usize) -> Option<(&ExternalAxis, bool)> {
        if let Some(arm7) = self.arm7.as_ref().filter(|a| a.index() == j) {
            return Some((arm7, true));
        }
        self.units.iter().find_map(|u| u.unit.axes.iter().find(|a| a.index() == j).map(|a| (a, u.active)))
    }

    /// Where every axis stands when the system starts (0 for an axis not configured).
    pub fn start(&self) -> Eax {
        std::array::from_fn(|j| self.axis(j).map_or(0.0, |(a, _)| a.start))
    }

    /// The external axes' part of a move from `from` to `target` (an `extjoint`), with
    /// `offsets` (EOffs) added to the values used. An active axis asked to leave its
    /// working range is the controller's joint-limit error, with its logical number.
    /// Axes in independent mode (`independent`) are left alone.
    pub fn plan(
        &self,
        from: Eax,
        target: &[f64; 6],
        offsets: Option<&Eax>,
        independent: [bool; 6],
    ) -> Result<ExternalMove, MotionError> {
        let mut ext = ExternalMove { from, to: from, max_speed: [0.0; 6], acc: [0.0; 6], linear: [false; 6] };
        for j in 0..6 {
            let Some((axis, true)) = self.axis(j) else { continue };
            (ext.max_speed[j], ext.acc[j], ext.linear[j]) = (axis.max_speed, axis.acc, axis.linear);
            if is_unused(target[j]) || independent[j] {
                continue;
            }
            let value = target[j] + offsets.map_or(0.0, |o| o[j]);
            if !axis.in_range(value) {
                return Err(MotionError::JointLimit { axis: usize::from(axis.logical) });
            }
            ext.to[j] = value;
        }
        Ok(ext)
    }

    /// An `extjoint` as read back (CJointT, CRobT): the axes' values, 9E9 where the
    /// system has no axis or its unit is not active.
    // uncertain: a deactivated unit's axes are read as 9E9.
    pub fn read(&self, at: &Eax) -> [f64; 6] {
        std::array::from_fn(|j| match self.axis(j) {
            Some((_, true)) => at[j],
            _ => super::data::UNUSED_AXIS,
        })
    }
}

impl super::robot::RobotState {
    /// Gives the robot's task these external units, standing at their start values.
    pub fn configure_external(&mut self, units: Vec<ExternalUnit>) {
        self.external = ExternalUnits::new(units);
        self.external.arm7 = self.arm_axis7();
        let start = self.external.any().then(|| self.external.start());
        self.planner.set_eax(start);
    }

    /// The external axes' part of the next move to `target` (an `extjoint`), or `None`
    /// when the task has no external axes.
    pub(super) fn external_move(
        &self,
        target: &[f64; 6],
        offsets: Option<&Eax>,
    ) -> Result<Option<ExternalMove>, MotionError> {
        let Some(from) = self.planner.end_eax() else { return Ok(None) };
        let mut target = *target;
        if let Some(q7) = self.next_axis7 {
            // A robtarget move of a 7-axis arm: eax_a is the arm angle; axis 7 goes
            // where the target's arm angle puts it (`arm7.rs`).
            target[0] = q7;
        }
        self.external.plan(from, &target, offsets, self.independent.external_mask()).map(Some)
    }

    /// Where the external axes are at controller time `t` (as `joints_at` for the
    /// arm), or `None` when the task has none.
    pub fn eax_at(&self, t: f64) -> Option<Eax> {
        let end = self.planner.end_eax()?;
        let t = self.pause.as_ref().map_or(t, |p| t.min(p.since));
        if self.planner.has_pending() && t > self.planner.time() {
            return self.planner.provisional().and_then(|(planned, _)| planned.eax_at(t)).or(Some(end));
        }
        // From the end of the last move on, the axes stand where the planner has them
        // (also where an IndReset left one).
        let on = self.ahead.iter().find(|m| t < m.end);
        let mut eax = on.and_then(|m| m.eax_at(t.max(m.start))).unwrap_or(end);
        // Axes in independent mode are where their own motion has taken them.
        self.independent.apply_eax(&mut eax, t);
        Some(eax)
    }

    /// External axis `j` leaves independent mode at `position` (IndReset): the moves
    /// take it on from there once the robot stands still.
    pub(super) fn take_over_external(&mut self, j: usize, position: f64, now: f64) {
        self.flush();
        if let Some(mut eax) = self.planner.end_eax() {
            eax[j] = position;
            self.planner.set_eax(Some(eax));
        }
        self.planner.idle_until(now);
        self.publish_tail();
    }

    /// External axis values as zones see them: the active units' axes, 9E9 for the
    /// others (which no bound limits).
    pub(super) fn extax_of(&self, eax: Option<Eax>) -> Option<[f64; 6]> {
        eax.map(|at| self.external.read(&at))
    }

    /// The `extjoint` read back at time `t`: 9E9 for axes the system lacks.
    pub fn extax_read(&mut self, t: f64) -> [f64; 6] {
        match self.eax_at(t) {
            Some(at) => self.external.read(&at),
            None => [super::data::UNUSED_AXIS; 6],
        }
    }
}

/// MoveExtJ: `[\Conc] ToJointPos [\ID] [\UseEOffs] Speed [\T] Zone [\Inpos]`.
static MOVE_EXT_J: std::sync::LazyLock<super::moves::Layout> =
    std::sync::LazyLock::new(|| super::moves::Layout::of("MoveExtJ"));

/// `MoveExtJ`: the external axes move to ToJointPos's `extax` while the arm stands
/// (its `robax` is not used); `v_leax`/`v_reax` and the axes' maxima set the pace.
// A fly-by point between two moves of the axes alone blends in the axes' zones; next to a
// move of the TCP it is a stop point (§2.2.3; `rapid_motion::plan::corner`).
pub(crate) fn move_ext_j(
    ctx: &mut rapid_vm::ext::Ctx<'_>,
    args: &[rapid_vm::ext::Value],
) -> Result<Option<rapid_vm::ext::Value>, rapid_vm::ext::RapidError> {
    super::moves::require_motion_task(ctx)?;
    ctx.resources.robot_mut().next_axis7 = None;
    let robot = ctx.resources.robot_mut();
    let (mut chain, joints) = (robot.active, robot.end_joints());
    super::moves::on_track(ctx, args, MOVE_EXT_J.to, MOVE_EXT_J.eoffs, &mut chain)?;
    super::moves::go_with(ctx, args, &MOVE_EXT_J, rapid_motion::plan::Target::Joints(joints), chain, Vec::new())
}
