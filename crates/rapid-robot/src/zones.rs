//! World zones (§2.9): WZBoxDef, WZCylDef, WZSphDef, WZHomeJointDef, WZLimJointDef
//! define a shape; WZDOSet makes a zone that sets an output while the TCP (or the
//! axes) is inside, WZLimSup one the robot may not enter; WZEnable, WZDisable and
//! WZFree act on temporary zones. Zones are supervised along every planned move at
//! the controller's 4 ms path resolution (`robot.rs`), at most 20 at a time.

use crate::RobotResources;
use nalgebra::Vector3;

use super::data;
use super::frame;
use rapid_vm::ext::{present, Ctx, Err, Opaque, OpaqueState, RapidError, Record, Value};

type Res = Result<Option<Value>, RapidError>;

/// At most this many world zones at a time.
const MAX_ZONES: usize = rapid_limits::WORLD_ZONES;

/// A zone's volume: in world coordinates (mm) or in axis values (degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Box {
        low: [f64; 3],
        high: [f64; 3],
    },
    Cylinder {
        centre: [f64; 3],
        radius: f64,
        height: f64,
    },
    Sphere {
        centre: [f64; 3],
        radius: f64,
    },
    /// The robot's six axes, then the external axes `eax_a` … `eax_f` (unbounded where
    /// the zone does not limit an axis).
    Joints {
        low: [f64; 12],
        high: [f64; 12],
    },
}

/// Whether external axis `j` is absent (no external axes, or 9E9).
fn e_unused(eax: Option<&[f64; 6]>, j: usize) -> bool {
    eax.is_none_or(|e| rapid_motion::external::is_unused(e[j]))
}

/// A shape and whether the zone is its inside or its outside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapeData {
    pub shape: Shape,
    pub outside: bool,
}

impl ShapeData {
    /// Whether the TCP at `tcp` (world, mm) with axes `joints` and external axes `eax`
    /// (`None` without any) is in the zone.
    pub fn contains(&self, tcp: &Vector3<f64>, joints: &[f64; 6], eax: Option<&[f64; 6]>) -> bool {
        let within = |v: f64, lo: f64, hi: f64| v >= lo.min(hi) && v <= hi.max(lo);
        let inside = match self.shape {
            Shape::Box { low, high } => (0..3).all(|i| within(tcp[i], low[i], high[i])),
            Shape::Cylinder { centre, radius, height } => {
                let (dx, dy) = (tcp.x - centre[0], tcp.y - centre[1]);
                dx.hypot(dy) <= radius && within(tcp.z, centre[2], centre[2] + height)
            }
            Shape::Sphere { centre, radius } => (tcp - Vector3::from(centre)).norm() <= radius,
            Shape::Joints { low, high } => {
                let robot = (0..6).all(|i| within(joints[i], low[i], high[i]));
                // An external axis the system lacks (or a deactivated unit's, read as
                // 9E9) is not limited by its bounds.
                let limits = |j: usize| e_unused(eax, j) || eax.is_some_and(|e| within(e[j], low[6 + j], high[6 + j]));
                let external = eax.is_none() || (0..6).all(limits);
                robot && external
            }
        };
        inside != self.outside
    }
}

/// What an active zone does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ZoneKind {
    /// WZDOSet: the output is `value` inside the zone, the other value outside; with
    /// `before` (`\Before`) it follows where the robot would stand if it braked now.
    DoSet { signal: u32, value: f64, before: bool },
    /// WZLimSup: entering the zone stops the robot.
    LimSup,
}

/// An active world zone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zone {
    pub shape: ShapeData,
    pub kind: ZoneKind,
    pub enabled: bool,
    /// Temporary (WZFree, WZDisable and WZEnable apply) or stationary.
    pub temporary: bool,
}

fn pos(ctx: &Ctx<'_>, arg: &Value) -> Result<[f64; 3], RapidError> {
    let v = frame::vector(ctx, &ctx.value(arg)?)?;
    Ok([v.x, v.y, v.z])
}

rapid_vm::ext::layout! {
    /// `[\Inside] | [\Outside] Shape`, first in every WZ…Def.
    static DEF: DefArgs = "WZBoxDef" | "WZCylDef" | "WZSphDef" | "WZHomeJointDef" | "WZLimJointDef" {
        outside: "Outside", shape: "Shape",
    }
    static BOX: BoxArgs = "WZBoxDef" { low: "LowPoint", high: "HighPoint" }
    static CYL: CylArgs = "WZCylDef" { centre: "CentrePoint", radius: "Radius", height: "Height" }
    static SPH: SphArgs = "WZSphDef" { centre: "CentrePoint", radius: "Radius" }
    static HOME: HomeArgs = "WZHomeJointDef" { middle: "MiddleJointVal", delta: "DeltaJointVal" }
    static LIM: LimArgs = "WZLimJointDef" { low: "LowJointVal", high: "HighJointVal" }
    /// `[\Temp] | [\Stat] WorldZone`, first in WZDOSet and WZLimSup.
    static ACTIVATE: ActivateArgs = "WZDOSet" | "WZLimSup" { stat: "Stat", zone: "WorldZone" }
    static DO_SET: DoSetArgs = "WZDOSet" { before: "Before", shape: "Shape", signal: "Signal", value: "SetValue" }
    static LIM_SUP: LimSupArgs = "WZLimSup" { shape: "Shape" }
}

fn define(ctx: &mut Ctx<'_>, args: &[Value], shape: Shape) -> Res {
    let at = *DEF;
    let data = ShapeData { shape, outside: present(args.get(at.outside)) };
    let (opaque, handle) = ctx.handle_arg(&args[at.shape], "a shapedata")?;
    let shapes = &mut ctx.resources.robot_mut().shapes;
    let index = match handle.map(|h| h as usize).filter(|&h| h < shapes.len()) {
        Some(h) => {
            shapes[h] = data;
            h
        }
        None => {
            shapes.push(data);
            shapes.len() - 1
        }
    };
    let stored = Opaque { ty: opaque.ty, state: OpaqueState::Handle(index as u32) };
    ctx.store(&args[at.shape], Value::Opaque(Box::new(stored)))?;
    Ok(None)
}

/// `WZBoxDef [\Inside] | [\Outside] Shape, LowPoint, HighPoint`.
pub(crate) fn wz_box_def(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (low, high) = (pos(ctx, &args[BOX.low])?, pos(ctx, &args[BOX.high])?);
    if (0..3).any(|i| low[i] == high[i]) {
        return Err(ctx.error(Err::ArgValue, "a box zone needs a size along every axis"));
    }
    define(ctx, args, Shape::Box { low, high })
}

/// `WZCylDef [\Inside] | [\Outside] Shape, CentrePoint, Radius, Height` (a cylinder
/// along the world z axis from its centre point's height).
pub(crate) fn wz_cyl_def(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let centre = pos(ctx, &args[CYL.centre])?;
    let (radius, height) = (ctx.num(&args[CYL.radius])?, ctx.num(&args[CYL.height])?);
    if radius <= 0.0 {
        return Err(ctx.error(Err::ArgValue, "a cylinder zone needs a radius above 0"));
    }
    // uncertain: a negative height extends the cylinder downwards.
    define(ctx, args, Shape::Cylinder { centre, radius, height })
}

/// `WZSphDef [\Inside] | [\Outside] Shape, CentrePoint, Radius`.
pub(crate) fn wz_sph_def(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let centre = pos(ctx, &args[SPH.centre])?;
    let radius = ctx.num(&args[SPH.radius])?;
    if radius <= 0.0 {
        return Err(ctx.error(Err::ArgValue, "a sphere zone needs a radius above 0"));
    }
    define(ctx, args, Shape::Sphere { centre, radius })
}

/// `WZHomeJointDef [\Inside] | [\Outside] Shape, MiddleJointVal, DeltaJointVal`: the
/// axes within Delta of Middle.
// uncertain: an external axis whose middle value is 9E9 is not checked.
pub(crate) fn wz_home_joint_def(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let middle = all_axes(ctx, &args[HOME.middle])?;
    let delta = all_axes(ctx, &args[HOME.delta])?;
    let unused = |i: usize| i >= 6 && rapid_motion::external::is_unused(middle[i]);
    let low = std::array::from_fn(|i| if unused(i) { f64::NEG_INFINITY } else { middle[i] - delta[i].abs() });
    let high = std::array::from_fn(|i| if unused(i) { f64::INFINITY } else { middle[i] + delta[i].abs() });
    define(ctx, args, Shape::Joints { low, high })
}

/// A jointtarget's twelve values: `robax`, then `extax`.
fn all_axes(ctx: &Ctx<'_>, arg: &Value) -> Result<[f64; 12], RapidError> {
    let target = ctx.value(arg)?;
    let robot = data::jointtarget(ctx, &target)?;
    let external = data::target_extax(ctx, &target)?;
    Ok(std::array::from_fn(|i| if i < 6 { robot[i] } else { external[i - 6] }))
}

/// `WZLimJointDef [\Inside] | [\Outside] Shape, LowJointVal, HighJointVal`.
// uncertain: an axis whose low and high are both 9E9 is not limited.
pub(crate) fn wz_lim_joint_def(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let mut low = all_axes(ctx, &args[LIM.low])?;
    let mut high = all_axes(ctx, &args[LIM.high])?;
    for i in 0..12 {
        if rapid_motion::external::is_unused(low[i]) {
            low[i] = f64::NEG_INFINITY;
        }
        if rapid_motion::external::is_unused(high[i]) {
            high[i] = f64::INFINITY;
        }
    }
    define(ctx, args, Shape::Joints { low, high })
}

fn shape_of(ctx: &Ctx<'_>, arg: &Value) -> Result<ShapeData, RapidError> {
    let (_, handle) = ctx.handle_arg(arg, "a shapedata")?;
    handle
        .and_then(|h| ctx.resources.robot().shapes.get(h as usize).copied())
        .ok_or_else(|| ctx.error(Err::ArgValue, "the shapedata was never defined (WZBoxDef …)"))
}

/// Activates a zone and gives its number to the WorldZone record.
fn activate(ctx: &mut Ctx<'_>, args: &[Value], shape: ShapeData, kind: ZoneKind) -> Res {
    let at = *ACTIVATE;
    let temporary = !present(args.get(at.stat));
    let zones = &mut ctx.resources.robot_mut().zones;
    if zones.iter().flatten().count() >= MAX_ZONES {
        return Err(ctx.error(Err::ArgValue, format!("at most {MAX_ZONES} world zones can be active")));
    }
    let zone = Zone { shape, kind, enabled: true, temporary };
    let number = match zones.iter().position(Option::is_none) {
        Some(free) => {
            zones[free] = Some(zone);
            free + 1
        }
        None => {
            zones.push(Some(zone));
            zones.len()
        }
    };
    let Value::Record(record) = ctx.value(&args[at.zone])? else {
        return Err(ctx.error(Err::ArgValue, "WorldZone must be a wztemporary or wzstationary"));
    };
    let record = Record { ty: record.ty, fields: vec![Value::Num(number as f32)] };
    ctx.store(&args[at.zone], Value::Record(std::rc::Rc::new(record)))?;
    let now = ctx.time;
    ctx.resources.robot_mut().start_zone(number - 1, now);
    super::moves::apply_due_events(ctx)?;
    Ok(None)
}

/// `WZDOSet [\Temp] | [\Stat] WorldZone [\Inside] | [\Before] Shape, Signal, SetValue`:
/// `\Inside` sets the output while the TCP (or the axes) is in the zone, `\Before`
/// before it gets there (spec §2.9: so the robot can be stopped just inside): while
/// the place where it would stand if it braked now is in the zone.
// uncertain: the braking is taken along the path at the TCP deceleration the moves are
// planned with (AccSet, PathAccLim), v²/2a ahead of the TCP, within the move; the
// output goes back when that place has left the zone (the manual speaks of entering).
pub(crate) fn wz_do_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *DO_SET;
    let before = present(args.get(at.before));
    let shape = shape_of(ctx, &args[at.shape])?;
    let signal = rapid_signals::signal(ctx, &args[at.signal])?;
    let value = ctx.num(&args[at.value])?;
    activate(ctx, args, shape, ZoneKind::DoSet { signal, value, before })
}

/// For each sample of a move (at the path resolution), the index of the sample where
/// the robot would stand if it braked from there at `decel` (mm/s²) along its path:
/// v²/2a further along, at most the move's last sample.
pub fn braking_places(samples: &[rapid_motion::plan::Sample], decel: f64) -> Vec<usize> {
    let mut along = Vec::with_capacity(samples.len());
    let mut total = 0.0;
    for (i, sample) in samples.iter().enumerate() {
        if i > 0 {
            total += (sample.tcp.translation.vector - samples[i - 1].tcp.translation.vector).norm();
        }
        along.push(total);
    }
    let decel = if decel.is_finite() && decel > 0.0 { decel } else { f64::INFINITY };
    let mut places = Vec::with_capacity(samples.len());
    let mut j = 0;
    for (i, sample) in samples.iter().enumerate() {
        let stop_at = along[i] + sample.tcp_speed * sample.tcp_speed / (2.0 * decel);
        j = j.max(i);
        while j + 1 < samples.len() && along[j] < stop_at - 1e-9 {
            j += 1;
        }
        places.push(j);
    }
    places
}

/// `WZLimSup [\Temp] | [\Stat] WorldZone, Shape`.
pub(crate) fn wz_lim_sup(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let shape = shape_of(ctx, &args[LIM_SUP.shape])?;
    activate(ctx, args, shape, ZoneKind::LimSup)
}

/// The active temporary zone a wztemporary names.
fn temporary(ctx: &Ctx<'_>, arg: &Value) -> Result<usize, RapidError> {
    let number = match ctx.value(arg)? {
        Value::Record(r) => r.fields.first().and_then(Value::as_f64).unwrap_or(0.0),
        _ => 0.0,
    };
    let index = (number as usize).checked_sub(1);
    match index.and_then(|i| ctx.resources.robot().zones.get(i).copied().flatten().map(|z| (i, z))) {
        Some((i, zone)) if zone.temporary => Ok(i),
        // uncertain: the controller's error for a zone that is not active.
        _ => Err(ctx.error(Err::ArgValue, "the world zone is not an active temporary zone")),
    }
}

/// `WZEnable WorldZone`.
pub(crate) fn wz_enable(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let i = temporary(ctx, &args[0])?;
    if let Some(zone) = ctx.resources.robot_mut().zones[i].as_mut() {
        zone.enabled = true;
    }
    let now = ctx.time;
    ctx.resources.robot_mut().start_zone(i, now);
    super::moves::apply_due_events(ctx)?;
    Ok(None)
}

/// `WZDisable WorldZone`.
pub(crate) fn wz_disable(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let i = temporary(ctx, &args[0])?;
    if let Some(zone) = ctx.resources.robot_mut().zones[i].as_mut() {
        zone.enabled = false;
    }
    Ok(None)
}

/// `WZFree WorldZone`: the zone is gone (its number 0 again).
pub(crate) fn wz_free(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let i = temporary(ctx, &args[0])?;
    ctx.resources.robot_mut().zones[i] = None;
    if let Value::Record(record) = ctx.value(&args[0])? {
        let record = Record { ty: record.ty, fields: vec![Value::Num(0.0)] };
        ctx.store(&args[0], Value::Record(std::rc::Rc::new(record)))?;
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::braking_places;
    use rapid_motion::plan::Sample;
    use rapid_motion::Pose;

    /// Samples 10 mm apart along x, all at `speed` mm/s.
    fn straight(n: usize, speed: f64) -> Vec<Sample> {
        (0..n)
            .map(|i| {
                let tcp = Pose::translation(10.0 * i as f64, 0.0, 0.0);
                Sample { time: i as f64 * 0.1, joints: [0.0; 6], tcp, flange: tcp, tcp_speed: speed }
            })
            .collect()
    }

    #[test]
    fn braking_reaches_as_far_as_v_squared_over_twice_the_deceleration() {
        // 100 mm/s braking at 1000 mm/s²: 100² / 2000 = 5 mm, so from each sample the
        // robot stands within the next one (10 mm on); the last stays where it is.
        assert_eq!(braking_places(&straight(5, 100.0), 1000.0), [1, 2, 3, 4, 4]);
        // 200 mm/s: 200² / 2000 = 20 mm, exactly two samples on.
        assert_eq!(braking_places(&straight(5, 200.0), 1000.0), [2, 3, 4, 4, 4]);
        // Standing still: it stops where it is.
        assert_eq!(braking_places(&straight(3, 0.0), 1000.0), [0, 1, 2]);
    }

    #[test]
    fn no_deceleration_given_brakes_at_once() {
        // A deceleration that is no positive number is taken as an instant stop.
        assert_eq!(braking_places(&straight(3, 500.0), 0.0), [0, 1, 2]);
    }
}
