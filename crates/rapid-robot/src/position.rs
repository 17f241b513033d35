//! Position functions that need no robot (manual §1.8, motion.md §3.5-3.6): Offs,
//! RelTool, ORobT, MirPos and Distance. robconf and extax of a robtarget pass through
//! unchanged unless the function is about them (ORobT's external axis offsets).

use crate::RobotResources;
use nalgebra::{Matrix3, Translation3, UnitQuaternion, Vector3};

use super::frame;
use rapid_vm::ext::{present, Ctx, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// External axis values at or above this mark an axis that is not used (9E9).
const UNUSED_AXIS: f64 = 8.9e9;

rapid_vm::ext::layout! {
    static OFFS: OffsArgs = "Offs" { x: "XOffset", y: "YOffset", z: "ZOffset" }
    static REL_TOOL: RelToolArgs = "RelTool" { dx: "Dx", dy: "Dy", dz: "Dz", rx: "Rx", ry: "Ry", rz: "Rz" }
}

/// `Offs(Point, XOffset, YOffset, ZOffset)`: Point moved by the offsets along the axes
/// of its own (object) frame; orientation, configuration and external axes kept.
pub(crate) fn offs(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let point = ctx.value(&args[0])?;
    let (t, q) = frame::trans_rot(ctx, &point)?;
    let at = *OFFS;
    let d = Vector3::new(ctx.num(&args[at.x])?, ctx.num(&args[at.y])?, ctx.num(&args[at.z])?);
    Ok(Some(frame::with_trans_rot(&point, &(t + d), &q)))
}

/// `RelTool(Point, Dx, Dy, Dz, [\Rx], [\Ry], [\Rz])`: Point displaced along the axes of
/// its tool frame, then turned (degrees) about the tool's x, the new y and the new z
/// axis: T · Trans(d) · Rx · Ry · Rz (motion.md §3.5).
pub(crate) fn rel_tool(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let point = ctx.value(&args[0])?;
    let (t, q) = frame::trans_rot(ctx, &point)?;
    let rot = frame::unit(ctx, q)?;
    let at = *REL_TOOL;
    let d = Vector3::new(ctx.num(&args[at.dx])?, ctx.num(&args[at.dy])?, ctx.num(&args[at.dz])?);
    let angles = [ctx.opt_num(args.get(at.rx))?, ctx.opt_num(args.get(at.ry))?, ctx.opt_num(args.get(at.rz))?];
    let moved = t + rot * d;
    // Without a rotation the orient is passed on exactly as given.
    if angles.iter().all(Option::is_none) {
        return Ok(Some(frame::with_trans_rot(&point, &moved, &q)));
    }
    let axes = [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()];
    let turn = axes.iter().zip(angles).fold(UnitQuaternion::identity(), |acc, (axis, deg)| {
        acc * UnitQuaternion::from_axis_angle(axis, deg.unwrap_or(0.0).to_radians())
    });
    Ok(Some(frame::with_trans_rot(&point, &moved, &(rot * turn).into_inner())))
}

/// `ORobT(OrgPoint [\InPDisp] | [\InEOffs])`: a position from the program
/// displacement frame in the object frame, and external axes without their offsets.
/// \InPDisp keeps the robot part in the displacement frame (removes only the
/// offsets); \InEOffs keeps the external axes as they are (removes only the
/// displacement).
pub(crate) fn orob_t(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let point = ctx.value(&args[0])?;
    let remove_pdisp = !present(args.get(1));
    let remove_eoffs = !present(args.get(2));
    let settings = &ctx.resources.motion_mut().settings;
    let (pdisp, eoffs) = (settings.pdisp, settings.eoffs);
    let mut result = point.clone();
    // With no displacement the position is passed on exactly (not renormalised).
    if remove_pdisp && pdisp != nalgebra::Isometry3::identity() {
        let displaced = pdisp * frame::frame(ctx, &point)?;
        result = frame::with_frame(&result, &displaced);
    }
    if remove_eoffs {
        let Value::Record(record) = &point else { return Ok(Some(result)) };
        if let Some(extax) = record.fields.get(3) {
            let mut axes = frame::extjoint(ctx, extax)?;
            for (axis, offset) in axes.iter_mut().zip(eoffs) {
                // uncertain: an unused axis (9E9) keeps its mark, and an offset of 9E9
                // counts as none.
                if *axis < UNUSED_AXIS && offset < UNUSED_AXIS {
                    *axis += offset;
                }
            }
            result = frame::with_extax(&result, &axes);
        }
    }
    Ok(Some(result))
}

/// `MirPos(Point, MirPlane [\WObj] [\MirY])`: Point mirrored in the xy plane of
/// MirPlane's object frame. Point is given in WObj's object frame (world without
/// \WObj) and the result is given in the same frame. The tool frame's x and z axes
/// are mirrored and its y axis follows (right-handed); with \MirY its y and z axes
/// are mirrored and x follows.
// uncertain: robconf and extax are passed on unchanged.
pub(crate) fn mir_pos(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let point = ctx.value(&args[0])?;
    let plane = frame::wobj_frame(ctx, &ctx.value(&args[1])?)?;
    let wobj = match args.get(2) {
        Some(arg) if present(Some(arg)) => frame::wobj_frame(ctx, &ctx.value(arg)?)?,
        _ => nalgebra::Isometry3::identity(),
    };
    let mir_y = present(args.get(3));
    // The point in the mirror plane's frame.
    let local = plane.inverse() * wobj * frame::frame(ctx, &point)?;
    let mirror = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
    let mut axes = mirror * local.rotation.to_rotation_matrix().into_inner();
    // Mirroring all three axes makes a left-handed frame; the axis that is not
    // mirrored is turned round.
    let follower = if mir_y { 0 } else { 1 };
    axes.set_column(follower, &(-axes.column(follower)));
    let mirrored = nalgebra::Isometry3::from_parts(
        Translation3::from(mirror * local.translation.vector),
        UnitQuaternion::from_quaternion(frame::from_matrix(&axes)),
    );
    let back = wobj.inverse() * plane * mirrored;
    let q = frame::from_matrix(back.rotation.to_rotation_matrix().matrix());
    Ok(Some(frame::with_trans_rot(&point, &back.translation.vector, &q)))
}

/// `Distance(Point1, Point2)`: the straight-line distance in mm.
pub(crate) fn distance(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let a = frame::vector(ctx, &ctx.value(&args[0])?)?;
    let b = frame::vector(ctx, &ctx.value(&args[1])?)?;
    Ok(Some(Value::Num((a - b).norm() as f32)))
}
