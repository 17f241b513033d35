//! Independent axes (manual §1.8 "独立轴"): IndAMove, IndCMove, IndDMove, IndRMove,
//! IndReset, IndInpos, IndSpeed. An axis in independent mode leaves the path planner:
//! it moves on its own (to a position, by a distance, or turning continuously) at its
//! own speed, while the other axes follow the program's moves; where the robot is at
//! any time (read-backs, the trace) has the independent axis's own position.
//!
//! Modelled: the robot's wrist axes 4 and 6 (the axes robots carry the independent
//! option for), positions given as numbers (degrees); and the axes of the task's
//! external units (a turntable turning on its own), whose positions may also come from
//! a robtarget's external axis values.

use super::units::{external_index as external_unit, own_only, unit_arg};
use crate::RobotResources;
use rapid_motion::{Joints, Kinematics};
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// The time every axis takes to reach full speed at a ramp of 100 %, s (the timing
/// model's, `rapid-motion/src/plan/limits.rs`).
// uncertain: the controller's independent-axis acceleration is not published.
const RAMP_TIME: f64 = 0.15;

/// Earlier independent motions kept for the trace.
const MAX_HISTORY: usize = 100_000;

/// How far from its target an axis counts as in position, degrees.
const INPOS_DEG: f64 = 1e-6;

/// What an independent axis does.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Goal {
    /// Moves to this position and stops.
    To(f64),
    /// Turns at this signed speed (deg/s) until told otherwise.
    Turn(f64),
}

/// One axis in independent mode: where and when its present motion began.
#[derive(Debug, Clone, Copy, PartialEq)]
struct IndAxis {
    t0: f64,
    p0: f64,
    goal: Goal,
    /// Cruise speed (deg/s, positive) and acceleration (deg/s²).
    speed: f64,
    acc: f64,
}

impl IndAxis {
    /// Position and speed (signed) at time `t`.
    fn at(&self, t: f64) -> (f64, f64) {
        let tau = (t - self.t0).max(0.0);
        match self.goal {
            Goal::Turn(v) => {
                let (s, t_acc) = (v.signum(), v.abs() / self.acc);
                if tau < t_acc {
                    (self.p0 + s * 0.5 * self.acc * tau * tau, s * self.acc * tau)
                } else {
                    (self.p0 + s * (0.5 * self.acc * t_acc * t_acc + v.abs() * (tau - t_acc)), v)
                }
            }
            Goal::To(target) => {
                let (d, s) = ((target - self.p0).abs(), (target - self.p0).signum());
                let peak = self.speed.min((self.acc * d).sqrt());
                let t_acc = peak / self.acc;
                let cruise = if peak > 0.0 { (d - peak * t_acc) / peak } else { 0.0 };
                let total = 2.0 * t_acc + cruise;
                if tau >= total {
                    (target, 0.0)
                } else if tau < t_acc {
                    (self.p0 + s * 0.5 * self.acc * tau * tau, s * self.acc * tau)
                } else if tau < t_acc + cruise {
                    (self.p0 + s * (0.5 * peak * t_acc + peak * (tau - t_acc)), s * peak)
                } else {
                    let left = total - tau;
                    (target - s * 0.5 * self.acc * left * left, s * self.acc * left)
                }
            }
        }
    }

    /// When a move to a position is done (`None` for a turning axis).
    fn done_at(&self) -> Option<f64> {
        let Goal::To(target) = self.goal else { return None };
        let d = (target - self.p0).abs();
        let peak = self.speed.min((self.acc * d).sqrt());
        let t_acc = peak / self.acc;
        let cruise = if peak > 0.0 { (d - peak * t_acc) / peak } else { 0.0 };
        Some(self.t0 + 2.0 * t_acc + cruise)
    }
}

/// Slots of the axes that can be independent: the robot's six (0..6), then the
/// external axes `eax_a` … `eax_f` (6..12).
const SLOTS: usize = 12;
const FIRST_EXTERNAL: usize = 6;

/// The axes in independent mode, by slot (see [`SLOTS`]).
#[derive(Debug, Clone, Default)]
pub struct Independent {
    axes: [Option<IndAxis>; SLOTS],
    /// Earlier independent motions, for the trace: (axis, motion, when it ended).
    history: Vec<(usize, IndAxis, f64)>,
}

impl Independent {
    /// Puts the independent robot axes' positions at time `t` into `joints`; `true`
    /// when any.
    pub fn apply(&self, joints: &mut Joints, t: f64) -> bool {
        self.apply_slots(joints, 0, t)
    }

    /// Puts the independent external axes' positions at time `t` into `eax`.
    pub fn apply_eax(&self, eax: &mut [f64; 6], t: f64) -> bool {
        self.apply_slots(eax, FIRST_EXTERNAL, t)
    }

    /// Which external axes (`extjoint` index) are in independent mode now: the program's
    /// moves leave them alone.
    pub fn external_mask(&self) -> [bool; 6] {
        std::array::from_fn(|j| self.axes[FIRST_EXTERNAL + j].is_some())
    }

    fn apply_slots(&self, values: &mut [f64; 6], first: usize, t: f64) -> bool {
        let mut any = false;
        for (i, value) in values.iter_mut().enumerate() {
            let slot = first + i;
            let now = self.axes[slot].filter(|ind| t >= ind.t0);
            let earlier = || {
                let past = self.history.iter().rev().find(|(a, ind, until)| *a == slot && ind.t0 <= t && t < *until);
                past.map(|(_, ind, _)| *ind)
            };
            if let Some(ind) = now.or_else(earlier) {
                *value = ind.at(t).0;
                any = true;
            }
        }
        any
    }

    /// Sets (or with `None` ends) the independent motion of `axis` at time `t`.
    fn set(&mut self, axis: usize, motion: Option<IndAxis>, t: f64) {
        if let Some(old) = self.axes[axis].take() {
            // Bounded like the trace itself: the oldest are dropped past a limit.
            if self.history.len() >= MAX_HISTORY {
                self.history.remove(0);
            }
            self.history.push((axis, old, t));
        }
        self.axes[axis] = motion;
    }

    /// Whether any axis is in independent mode.
    pub fn any(&self) -> bool {
        self.axes.iter().any(Option::is_some)
    }
}

/// The axis argument as a slot: 4 or 6 of this task's robot, or an axis of one of its
/// active external units (not a track carrying the robot).
// uncertain: which axes carry the independent option depends on the robot's
// configuration; the wrist axes 4 and 6 are taken to, others raise ERR_AXIS_PAR.
fn axis(ctx: &Ctx<'_>, args: &[Value]) -> Result<usize, RapidError> {
    let unit = unit_arg(ctx, args, 0)?;
    let axis = ctx.num(&args[1])?;
    if let Some(i) = external_unit(ctx, unit) {
        return external_slot(ctx, i, axis);
    }
    own_only(ctx, unit)?;
    if axis == 4.0 || axis == 6.0 {
        return Ok(axis as usize - 1);
    }
    Err(ctx.error(Err::AxisPar, format!("axis {axis} cannot move independently (axes 4 and 6 can)")))
}

/// The slot of axis number `axis` (from 1) of external unit `i`.
fn external_slot(ctx: &Ctx<'_>, i: usize, axis: f64) -> Result<usize, RapidError> {
    let state = &ctx.resources.robot().external.units[i];
    let name = &state.unit.name;
    if state.unit.carries_robot {
        return Err(RapidError::fatal(format!(
            "{name} carries the robot: independent mode on it is not supported yet"
        )));
    }
    if !state.active {
        return Err(RapidError::fatal(format!("{name} is not active (ActUnit): its axes cannot move")));
    }
    let publication = ctx.resources.robot().external.publication.as_ref();
    if let Some(busy) = publication.and_then(|p| p.read().busy_after(name, ctx.time).map(|b| b.task.clone())) {
        return Err(RapidError::fatal(format!(
            "the robot of task {busy} works in a work object {name} carries: independent mode on it is not supported \
             yet"
        )));
    }
    let n = state.unit.axes.len();
    match state.unit.axes.get((axis as usize).wrapping_sub(1)).filter(|_| axis.fract() == 0.0) {
        Some(a) => Ok(FIRST_EXTERNAL + a.index()),
        None => Err(ctx.error(Err::AxisPar, format!("axis {axis} is not an axis of {name} (1..{n})"))),
    }
}

/// The external axis (configuration) in `slot`, if the slot is an external one.
fn external_axis<'c>(ctx: &'c Ctx<'_>, slot: usize) -> Option<&'c rapid_motion::external::ExternalAxis> {
    let j = slot.checked_sub(FIRST_EXTERNAL)?;
    ctx.resources.robot().external.units.iter().flat_map(|u| &u.unit.axes).find(|a| a.index() == j)
}

/// Speed (deg/s, at most the axis's maximum) and acceleration from `\Ramp` (percent).
fn speed_and_acc(ctx: &Ctx<'_>, axis: usize, speed: f64, ramp: Option<&Value>) -> Result<(f64, f64), RapidError> {
    let (max, acc) = match external_axis(ctx, axis) {
        Some(a) => (a.max_speed, a.acc),
        None => {
            (ctx.resources.robot().model.max_speeds[axis], ctx.resources.robot().model.max_speeds[axis] / RAMP_TIME)
        }
    };
    if !speed.is_finite() || speed == 0.0 {
        return Err(ctx.error(Err::ArgValue, "the speed of an independent axis must not be 0"));
    }
    let ramp = match ctx.opt_num(ramp)? {
        Some(r) if (1.0..=100.0).contains(&r) => r,
        Some(r) => return Err(ctx.error(Err::ArgValue, format!("Ramp {r} % is not 1..100"))),
        None => 100.0,
    };
    // uncertain: a speed above the axis's maximum is capped at it.
    Ok((speed.abs().min(max), acc * ramp / 100.0))
}

/// Where the axis is now: its independent position, or the robot's.
fn position_now(ctx: &mut Ctx<'_>, axis: usize) -> f64 {
    let now = ctx.time;
    match ctx.resources.robot_mut().independent.axes[axis] {
        Some(ind) => ind.at(now).0,
        None if axis >= FIRST_EXTERNAL => {
            ctx.resources.robot_mut().eax_at(now).map_or(0.0, |eax| eax[axis - FIRST_EXTERNAL])
        }
        None => ctx.resources.robot_mut().joints_at(now)[axis],
    }
}

/// Starts an independent motion of `axis` from where it is now.
// uncertain: a new independent move of a moving axis starts from its position at that
// instant as if from standstill (the change of speed is not ramped).
fn start(ctx: &mut Ctx<'_>, axis: usize, goal: Goal, speed: f64, acc: f64) {
    let p0 = position_now(ctx, axis);
    let ind = IndAxis { t0: ctx.time, p0, goal, speed, acc };
    ctx.resources.robot_mut().independent.set(axis, Some(ind), ind.t0);
    // Another task working in a unit's work object must know its axis left the moves.
    ctx.resources.robot_mut().publish_tail();
}

rapid_vm::ext::layout! {
    static IND_A: AbsArgs = "IndAMove" { to_pos: "ToAbsPos", to_num: "ToAbsNum", speed: "Speed", ramp: "Ramp" }
    static IND_C: TurnArgs = "IndCMove" { speed: "Speed", ramp: "Ramp" }
    static IND_D: DeltaArgs = "IndDMove" { delta: "Delta", speed: "Speed", ramp: "Ramp" }
    static IND_R: RelArgs = "IndRMove" {
        to_pos: "ToRelPos", to_num: "ToRelNum", fwd: "Fwd", bwd: "Bwd", speed: "Speed", ramp: "Ramp",
    }
    static IND_RESET: ResetArgs = "IndReset" {
        ref_pos: "RefPos", ref_num: "RefNum", short: "Short", fwd: "Fwd", bwd: "Bwd",
    }
    static IND_SPEED: SpeedArgs = "IndSpeed" { zero_speed: "ZeroSpeed" }
}

/// `IndAMove MecUnit, Axis, \ToAbsNum, Speed [\Ramp]`: to an absolute position.
pub(crate) fn ind_a_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let axis = axis(ctx, args)?;
    let at = *IND_A;
    let target = position_arg(ctx, args, (at.to_pos, at.to_num), "ToAbsPos", axis)?;
    let (speed, acc) = speed_and_acc(ctx, axis, ctx.num(&args[at.speed])?, args.get(at.ramp))?;
    start(ctx, axis, Goal::To(target), speed, acc);
    Ok(None)
}

/// `IndCMove MecUnit, Axis, Speed [\Ramp]`: turns continuously (the speed's sign is
/// the direction).
pub(crate) fn ind_c_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let axis = axis(ctx, args)?;
    let signed = ctx.num(&args[IND_C.speed])?;
    let (speed, acc) = speed_and_acc(ctx, axis, signed, args.get(IND_C.ramp))?;
    start(ctx, axis, Goal::Turn(speed * signed.signum()), speed, acc);
    Ok(None)
}

/// `IndDMove MecUnit, Axis, Delta, Speed [\Ramp]`: by a distance from where it is.
pub(crate) fn ind_d_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let axis = axis(ctx, args)?;
    let at = *IND_D;
    let delta = ctx.num(&args[at.delta])?;
    let (speed, acc) = speed_and_acc(ctx, axis, ctx.num(&args[at.speed])?, args.get(at.ramp))?;
    let target = position_now(ctx, axis) + delta;
    start(ctx, axis, Goal::To(target), speed, acc);
    Ok(None)
}

/// `IndRMove MecUnit, Axis, \ToRelNum, [\Short | \Fwd | \Bwd], Speed [\Ramp]`: to a
/// position within one turn (0..360), the shortest way, forwards or backwards.
pub(crate) fn ind_r_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let axis = axis(ctx, args)?;
    let at = *IND_R;
    let within = position_arg(ctx, args, (at.to_pos, at.to_num), "ToRelPos", axis)?.rem_euclid(360.0);
    let (speed, acc) = speed_and_acc(ctx, axis, ctx.num(&args[at.speed])?, args.get(at.ramp))?;
    let here = position_now(ctx, axis);
    let ahead = (within - here).rem_euclid(360.0);
    let delta = if present(args.get(at.fwd)) {
        ahead
    } else if present(args.get(at.bwd)) {
        ahead - if ahead > 0.0 { 360.0 } else { 0.0 }
    } else if ahead > 180.0 {
        ahead - 360.0
    } else {
        ahead
    };
    start(ctx, axis, Goal::To(here + delta), speed, acc);
    Ok(None)
}

/// A position argument: the `\ToAbsNum`-like number at `num`. The robtarget form at
/// `pos` names the axis's value in the target's external axes (`extax`); for robot
/// axes the manual asks for the number form, so it raises ERR_ARGVALERR here.
// uncertain: the manual says only that robot axes use the number form; that the
// controller answers the robtarget form on a robot axis with ERR_ARGVALERR is our choice.
fn position_arg(
    ctx: &Ctx<'_>,
    args: &[Value],
    (pos, num): (usize, usize),
    robtarget: &str,
    slot: usize,
) -> Result<f64, RapidError> {
    if present(args.get(pos)) {
        return robtarget_position(ctx, &args[pos], robtarget, slot);
    }
    ctx.num(&args[num])
}

/// An external axis's value in a robtarget (`\ToAbsPos`, `\ToRelPos`, `\RefPos`);
/// for a robot axis ERR_ARGVALERR.
fn robtarget_position(ctx: &Ctx<'_>, target: &Value, robtarget: &str, slot: usize) -> Result<f64, RapidError> {
    let Some(j) = slot.checked_sub(FIRST_EXTERNAL) else { return Err(robtarget_on_robot_axis(ctx, robtarget)) };
    let value = super::data::target_extax(ctx, &ctx.value(target)?)?[j];
    if rapid_motion::external::is_unused(value) {
        return Err(ctx.error(Err::ArgValue, format!("\\{robtarget}: the robtarget leaves this axis unused (9E9)")));
    }
    Ok(value)
}

/// The error for a robtarget position (`\ToAbsPos`, `\ToRelPos`, `\RefPos`) given
/// for a robot axis.
fn robtarget_on_robot_axis(ctx: &Ctx<'_>, robtarget: &str) -> RapidError {
    ctx.error(
        Err::ArgValue,
        format!("\\{robtarget} takes a robtarget's external axis value; a robot axis needs the number form"),
    )
}

/// How IndReset moves the axis's measuring system by whole turns.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Reset {
    /// `\Old` (the default): the position stays as it is.
    Old,
    /// `\Short`: within ±180 degrees of the reference.
    Short(f64),
    /// `\Fwd`: in [reference, reference + 360).
    Fwd(f64),
    /// `\Bwd`: in (reference - 360, reference].
    Bwd(f64),
}

impl Reset {
    /// The axis position after the reset, from `position`.
    fn apply(self, position: f64) -> f64 {
        match self {
            Reset::Old => position,
            Reset::Short(reference) => reference + (position - reference + 180.0).rem_euclid(360.0) - 180.0,
            Reset::Fwd(reference) => reference + (position - reference).rem_euclid(360.0),
            Reset::Bwd(reference) => reference - (reference - position).rem_euclid(360.0),
        }
    }
}

/// IndReset's optional arguments: `\RefPos | \RefNum` at 2/3, `\Short | \Fwd | \Bwd
/// | \Old` at 4..=7.
// uncertain: the manual allows a reference only with \Short, \Fwd or \Bwd, never with
// \Old, and wants it inside the axis's working range; those faults raise ERR_ARGVALERR
// here. \Short, \Fwd or \Bwd without a reference take 0 as the reference.
fn reset_kind(ctx: &Ctx<'_>, args: &[Value], axis: usize) -> Result<Reset, RapidError> {
    let at = *IND_RESET;
    let reference = match args.get(at.ref_pos).filter(|a| present(Some(a))) {
        Some(target) => Some(robtarget_position(ctx, target, "RefPos", axis)?),
        None => ctx.opt_num(args.get(at.ref_num))?,
    };
    let (short, fwd, bwd) = (present(args.get(at.short)), present(args.get(at.fwd)), present(args.get(at.bwd)));
    let Some(reference) = reference else {
        return Ok(if short {
            Reset::Short(0.0)
        } else if fwd {
            Reset::Fwd(0.0)
        } else if bwd {
            Reset::Bwd(0.0)
        } else {
            Reset::Old
        });
    };
    if !(short || fwd || bwd) {
        return Err(ctx.error(Err::ArgValue, "IndReset \\RefNum needs \\Short, \\Fwd or \\Bwd"));
    }
    let (lo, hi) = limits(ctx, axis);
    if !reference.is_finite() || reference < lo || reference > hi {
        return Err(ctx.error(
            Err::ArgValue,
            format!("IndReset \\RefNum {reference} is outside axis {}'s working range {lo}..{hi}", axis + 1),
        ));
    }
    Ok(if short {
        Reset::Short(reference)
    } else if fwd {
        Reset::Fwd(reference)
    } else {
        Reset::Bwd(reference)
    })
}

/// `IndReset MecUnit, Axis [\RefPos | \RefNum] [\Short | \Fwd | \Bwd | \Old]`: the
/// axis goes back to normal mode where it stands, its measuring system moved by whole
/// turns as the switch says (`\Old`, the default, keeps it); the program's moves take
/// it on from there.
// uncertain: the axis must stand still (a turning or moving axis stops execution), and
// a position outside the working range after the reset stops execution.
pub(crate) fn ind_reset(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let axis = axis(ctx, args)?;
    let kind = reset_kind(ctx, args, axis)?;
    let now = ctx.time;
    let Some(ind) = ctx.resources.robot_mut().independent.axes[axis] else { return Ok(None) };
    if ind.done_at().is_none_or(|done| done > now + 1e-9) {
        return Err(RapidError::fatal(format!("IndReset: axis {} still moves; it must stand still", axis + 1)));
    }
    let position = kind.apply(ind.at(now).0);
    let (lo, hi) = limits(ctx, axis);
    let robot = ctx.resources.robot_mut();
    if position < lo - 1e-9 || position > hi + 1e-9 {
        return Err(RapidError::fatal(format!(
            "IndReset: axis {} at {position:.2} degrees is outside its working range {lo}..{hi}; \\Short, \\Fwd or \\Bwd bring it in",
            axis + 1
        )));
    }
    robot.independent.set(axis, None, now);
    match axis.checked_sub(FIRST_EXTERNAL) {
        Some(j) => robot.take_over_external(j, position, now),
        None => robot.take_over_axis(axis, position, now),
    }
    Ok(None)
}

/// The working range of the axis in `slot`.
fn limits(ctx: &Ctx<'_>, slot: usize) -> (f64, f64) {
    match external_axis(ctx, slot) {
        Some(a) => (a.min, a.max),
        None => ctx.resources.robot().kin.limits()[slot.min(5)],
    }
}

/// `IndInpos(MecUnit, Axis)`: the independent axis stands at its target.
pub(crate) fn ind_inpos(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let axis = axis(ctx, args)?;
    let now = ctx.time;
    let Some(ind) = ctx.resources.robot_mut().independent.axes[axis] else {
        return Err(ctx.error(Err::AxisInd, format!("axis {} is not in independent mode", axis + 1)));
    };
    let at = ind.done_at().is_some_and(|done| now >= done - INPOS_DEG);
    Ok(Some(Value::Bool(at)))
}

/// `IndSpeed(MecUnit, Axis, \InSpeed | \ZeroSpeed)`: the axis has reached its set
/// speed, or stands still.
pub(crate) fn ind_speed(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let axis = axis(ctx, args)?;
    let now = ctx.time;
    let Some(ind) = ctx.resources.robot_mut().independent.axes[axis] else {
        return Err(ctx.error(Err::AxisInd, format!("axis {} is not in independent mode", axis + 1)));
    };
    let (_, v) = ind.at(now);
    let answer = if present(args.get(IND_SPEED.zero_speed)) {
        v.abs() < 1e-9
    } else {
        let set = match ind.goal {
            Goal::Turn(speed) => speed.abs(),
            Goal::To(_) => ind.speed,
        };
        (v.abs() - set).abs() < 1e-6
    };
    Ok(Some(Value::Bool(answer)))
}
