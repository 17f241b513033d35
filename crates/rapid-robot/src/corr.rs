//! Path correction (§1.8 "路径校正", option Path Offset): CorrCon, CorrWrite, CorrDiscon,
//! CorrClear, CorrRead, the `corrdescr` data and the `\Corr` argument of MoveL, MoveC,
//! TriggL, TriggC and TriggLIOs.
//!
//! Model: the robot keeps a time line of the total correction (the sum of what every
//! connected generator has delivered), a step at the controller time of each
//! CorrWrite, CorrDiscon and CorrClear. A move made with `\Corr` follows its planned
//! path shifted by the total in force at each instant, in the path coordinate system
//! (`rapid_motion::plan::path_frame`); the axis values are solved near the planned
//! ones. The planner never sees the correction, so timing is the planned one. The
//! first move without `\Corr` after corrected ones goes from where the correction left
//! the robot to its programmed point: the offset fades out over it.
// uncertain: the controller filters a correction into the path; here it takes effect
// at once (a step), and the fade over the next uncorrected move is linear in time.

use crate::RobotResources;
use nalgebra::{Rotation3, Vector3};
use rapid_motion::kinematics::Opw;
use rapid_motion::plan::{PlannedMove, Sample};
use rapid_motion::MotionError;

use rapid_vm::ext::{Ctx, Opaque, OpaqueState, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// How many correction generators may be connected at once (manual, CorrCon
/// limitations: "a maximum number of 5").
pub const MAX_GENERATORS: usize = 5;

/// How long the time line is kept behind the robot when no trace is recorded, s.
const KEEP_PAST: f64 = 1.0;

/// A move made with `\Corr`: when the robot is on it and the path coordinate system
/// at its end (what the correction in force there means when the next move fades it).
#[derive(Debug, Clone, Copy)]
struct Span {
    start: f64,
    end: f64,
    exit: Rotation3<f64>,
}

/// What a sample gets: an offset in the path coordinate system where it is (a move
/// made with `\Corr`; where the path does not move, as during a pause, the frame at
/// the move's end), or a shift already in the frame of the path pose (the fade).
enum Shift {
    Path(Vector3<f64>, Rotation3<f64>),
    Fixed(Vector3<f64>),
}

/// The task robot's path correction.
#[derive(Debug, Clone, Default)]
pub struct CorrState {
    /// The number the next CorrCon gives its generator (a corrdescr holds it).
    next_id: u32,
    /// The connected generators: their number and the offset they delivered so far.
    generators: Vec<(u32, Vector3<f64>)>,
    /// The total correction from each time on, times growing.
    timeline: Vec<(f64, Vector3<f64>)>,
    /// When the robot is on a move made with `\Corr`, in time order.
    spans: Vec<Span>,
    /// The move instruction about to be given has `\Corr` (set just before
    /// `RobotState::push`).
    pub(super) next: bool,
    /// The move the planner holds (waiting for its successor) has `\Corr`.
    pub(super) pending: bool,
    /// A corrected move that became final cannot be followed: where the correction
    /// first puts the robot out of reach.
    pub(super) violation: Option<MotionError>,
}

impl CorrState {
    /// The sum of what the connected generators delivered (what CorrRead returns).
    pub fn total(&self) -> Vector3<f64> {
        self.generators.iter().map(|(_, offset)| offset).sum()
    }

    /// Whether any move was made with `\Corr` (nothing to correct otherwise).
    pub fn active(&self) -> bool {
        !self.spans.is_empty()
    }

    /// The total correction in force at time `t`.
    fn offset_at(&self, t: f64) -> Vector3<f64> {
        let after = self.timeline.partition_point(|&(at, _)| at <= t);
        after.checked_sub(1).map_or_else(Vector3::zeros, |i| self.timeline[i].1)
    }

    /// The total changed at `now`: a step in the time line.
    fn changed(&mut self, now: f64) {
        let total = self.total();
        match self.timeline.last_mut() {
            // Controller time only grows; a second change at one instant replaces the first.
            Some((at, offset)) if *at >= now => *offset = total,
            _ => self.timeline.push((now, total)),
        }
    }

    /// The corrected span holding `t` that overlaps `planned`, if any (spans follow
    /// each other in time; where two meet, the later one).
    fn span_on(&self, planned: &PlannedMove, t: f64) -> Option<&Span> {
        let after = self.spans.partition_point(|s| s.start <= t);
        let span = self.spans[..after].last()?;
        (t <= span.end && span.start < planned.end && planned.start < span.end).then_some(span)
    }

    /// The corrected span that ends where `planned` starts, if any.
    fn span_before(&self, planned: &PlannedMove) -> Option<&Span> {
        let at = self.spans.partition_point(|s| s.end < planned.start - 1e-9);
        self.spans.get(at).filter(|s| (s.end - planned.start).abs() < 1e-9)
    }

    /// What the robot gets at `t` on `planned`: the total in force, on a move made with
    /// `\Corr`; on the move right after corrected ones, the shift the correction had
    /// where they ended, fading to nothing at its end. None where there is nothing.
    fn shift_on(&self, planned: &PlannedMove, t: f64) -> Option<Shift> {
        if self.spans.is_empty() {
            return None;
        }
        if let Some(span) = self.span_on(planned, t) {
            let offset = self.offset_at(t);
            return (offset.norm() > 1e-9).then_some(Shift::Path(offset, span.exit));
        }
        // Until the robot stands at a stop point (its settle time not counted), or
        // through the corner path of a fly-by point.
        let arrive = if planned.corner_time > 0.0 { planned.end } else { planned.zone_entry };
        let length = arrive - planned.start;
        let before = self.span_before(planned)?;
        if length <= 0.0 {
            return None;
        }
        let left = 1.0 - ((t - planned.start) / length).clamp(0.0, 1.0);
        let shift = before.exit * self.offset_at(before.end) * left;
        (shift.norm() > 1e-9).then_some(Shift::Fixed(shift))
    }

    /// The robot at `sample` of `planned` with its correction, or why no axis values
    /// reach it.
    fn try_correct(&self, kin: &Opw, planned: &PlannedMove, sample: &Sample) -> Result<Option<Sample>, MotionError> {
        Ok(match self.shift_on(planned, sample.time) {
            Some(Shift::Path(offset, still)) => {
                let frame = planned.travel_frame_at(kin, sample.time).unwrap_or(still);
                Some(planned.shifted(kin, sample, &(frame * offset))?)
            }
            Some(Shift::Fixed(shift)) => Some(planned.shifted(kin, sample, &shift)?),
            None => None,
        })
    }

    /// The robot at `sample` of `planned`, corrected. Where no axis values reach the
    /// corrected point the planned sample stands (the error is reported where the
    /// program meets it: [`CorrState::check`]), so no sample is ever a NaN.
    pub fn correct(&self, kin: &Opw, planned: &PlannedMove, sample: Sample) -> Sample {
        match self.try_correct(kin, planned, &sample) {
            Ok(Some(corrected)) => corrected,
            _ => sample,
        }
    }

    /// A move became final: when it was given with `\Corr`, its time is corrected from
    /// now on. What the current correction makes of it (or of the move after corrected
    /// ones, which fades it out) must be reachable.
    pub(super) fn on_final(&mut self, kin: &Opw, planned: &PlannedMove) {
        if std::mem::take(&mut self.pending) {
            let exit = planned.path_frame_at(kin, planned.end);
            self.spans.push(Span { start: planned.start, end: planned.end, exit });
        } else if self.span_before(planned).is_none() {
            return;
        }
        if let Err(err) = self.check(kin, planned, planned.start) {
            self.violation.get_or_insert(err);
        }
    }

    /// Whether the corrected path of `planned` from `from` on is reachable, at the
    /// controller's path resolution.
    fn check(&self, kin: &Opw, planned: &PlannedMove, from: f64) -> Result<(), MotionError> {
        if self.timeline.iter().all(|(_, offset)| offset.norm() <= 1e-9) {
            return Ok(());
        }
        for sample in planned.samples(kin, rapid_motion::plan::DEFAULT_STEP).filter(|s| s.time >= from) {
            self.try_correct(kin, planned, &sample)?;
        }
        Ok(())
    }

    /// The robot stops for good at `t` (a search hit): nothing corrected after it.
    pub(super) fn stop_at(&mut self, t: f64) {
        self.spans.retain(|s| s.start <= t);
        if let Some(last) = self.spans.last_mut() {
            last.end = last.end.min(t);
        }
        self.pending = false;
    }

    /// StartMove: what was planned after `since` comes `dt` later.
    pub(super) fn delay_from(&mut self, since: f64, dt: f64) {
        for span in &mut self.spans {
            if span.start >= since {
                span.start += dt;
            }
            if span.end > since {
                span.end += dt;
            }
        }
    }

    /// Forgets what lies before `t` (no trace is recorded): the last step in force
    /// and the spans the robot may still be on stay.
    pub(super) fn forget_before(&mut self, t: f64) {
        let t = t - KEEP_PAST;
        let old = self.timeline.partition_point(|&(at, _)| at <= t);
        if old > 1 {
            self.timeline.drain(..old - 1);
        }
        let done = self.spans.partition_point(|s| s.end < t);
        if done > 1 {
            self.spans.drain(..done - 1);
        }
    }
}

impl super::robot::RobotState {
    /// The robot at `sample` of `planned` with its path correction (for the trace and
    /// the report, which sample the recorded moves).
    pub fn corrected(&self, planned: &PlannedMove, sample: Sample) -> Sample {
        self.corr.correct(&self.kin, planned, sample)
    }
}

/// The generator a corrdescr argument names, if it is connected.
fn connected(ctx: &Ctx<'_>, arg: &Value) -> Result<Option<(usize, u32)>, RapidError> {
    let (_, handle) = ctx.handle_arg(arg, "a corrdescr")?;
    let generators = &ctx.resources.robot().corr.generators;
    Ok(handle.and_then(|id| generators.iter().position(|&(g, _)| g == id).map(|i| (i, id))))
}

/// The error for a corrdescr that names no connected generator.
// uncertain: the manual names no recoverable error for it; execution stops.
fn not_connected(what: &str) -> RapidError {
    RapidError::fatal(format!("{what}: the corrdescr is not connected to a correction generator (CorrCon first)"))
}

/// `CorrCon Descr`: connects a new correction generator, delivering nothing yet.
// uncertain: CorrCon on a descriptor still connected keeps that generator as it is.
pub(crate) fn corr_con(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if connected(ctx, &args[0])?.is_some() {
        return Ok(None);
    }
    let corr = &mut ctx.resources.robot_mut().corr;
    if corr.generators.len() >= MAX_GENERATORS {
        // uncertain: the manual states the limit but not the error; execution stops.
        return Err(RapidError::fatal(format!(
            "CorrCon: at most {MAX_GENERATORS} correction generators can be connected at once"
        )));
    }
    let id = corr.next_id;
    corr.next_id = corr.next_id.wrapping_add(1);
    corr.generators.push((id, Vector3::zeros()));
    let (opaque, _) = ctx.handle_arg(&args[0], "a corrdescr")?;
    let descr = Opaque { ty: opaque.ty, state: OpaqueState::Handle(id) };
    ctx.store(&args[0], Value::Opaque(Box::new(descr)))?;
    Ok(None)
}

/// `CorrWrite Descr, Data`: the generator delivers the offset Data (pos, mm, path
/// coordinate system); it adds to what it delivered before, and the total takes
/// effect on the path now.
// uncertain: offsets add up (each CorrWrite is an increment): CorrRead returns "the
// total absolute offsets delivered so far", and the manual's example writes a sensor
// error times a gain of 0.5 every 0.2 s, which only converges when writes accumulate.
pub(crate) fn corr_write(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let Some((i, _)) = connected(ctx, &args[0])? else { return Err(not_connected("CorrWrite")) };
    let data = ctx.value(&args[1])?;
    let Value::Record(pos) = &data else { return Err(RapidError::fatal("CorrWrite: Data must be a pos")) };
    let mut xyz = [0.0; 3];
    for (k, field) in pos.fields.iter().take(3).enumerate() {
        xyz[k] = ctx.num(field)?;
    }
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    robot.corr.generators[i].1 += Vector3::from(xyz);
    robot.corr.changed(now);
    check_ahead(ctx, now)
}

/// The corrected moves the robot is on or will be on from `now` must stay reachable
/// with the new total; else execution stops with the motion error.
// uncertain: the real robot stops where the corrected path leaves its reach; here the
// instruction that made it so stops the program.
fn check_ahead(ctx: &mut Ctx<'_>, now: f64) -> Res {
    let robot = ctx.resources.robot_mut();
    for planned in robot.ahead.iter().filter(|m| m.end >= now) {
        robot.corr.check(&robot.kin, planned, now).map_err(super::moves::motion_error)?;
    }
    Ok(None)
}

/// `CorrDiscon Descr`: disconnects the generator; what it delivered leaves the path.
// uncertain: the manual says CorrDiscon "can be used to remove corrections given
// earlier": the generator's offsets leave the total at once.
pub(crate) fn corr_discon(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let Some((i, _)) = connected(ctx, &args[0])? else { return Err(not_connected("CorrDiscon")) };
    let now = ctx.time;
    let corr = &mut ctx.resources.robot_mut().corr;
    corr.generators.remove(i);
    corr.changed(now);
    check_ahead(ctx, now)
}

/// `CorrClear`: removes every connected generator, and with them all corrections.
pub(crate) fn corr_clear(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let now = ctx.time;
    let corr = &mut ctx.resources.robot_mut().corr;
    if corr.generators.is_empty() {
        return Ok(None);
    }
    corr.generators.clear();
    corr.changed(now);
    check_ahead(ctx, now)
}

/// `CorrRead()`: the total offset all connected generators delivered so far (a pos).
pub(crate) fn corr_read(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let total = ctx.resources.robot_mut().corr.total();
    let pose = nalgebra::Isometry3::translation(total.x, total.y, total.z);
    Ok(Some(super::data::pos_value(ctx, &pose)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_time_line_steps_at_each_change() {
        let mut corr = CorrState::default();
        corr.generators.push((0, Vector3::new(0.0, 5.0, 0.0)));
        corr.changed(1.0);
        corr.generators[0].1 += Vector3::new(0.0, 2.0, 0.0);
        corr.changed(2.0);
        // A second change at one instant replaces the first.
        corr.generators.push((1, Vector3::new(1.0, 0.0, 0.0)));
        corr.changed(2.0);
        assert_eq!(corr.offset_at(0.5), Vector3::zeros());
        assert_eq!(corr.offset_at(1.0), Vector3::new(0.0, 5.0, 0.0));
        assert_eq!(corr.offset_at(1.99), Vector3::new(0.0, 5.0, 0.0));
        assert_eq!(corr.offset_at(2.5), Vector3::new(1.0, 7.0, 0.0));
        assert_eq!(corr.timeline.len(), 2);
        // Forgetting keeps the step in force.
        corr.forget_before(10.0);
        assert_eq!(corr.timeline.len(), 1);
        assert_eq!(corr.offset_at(12.0), Vector3::new(1.0, 7.0, 0.0));
    }
}
