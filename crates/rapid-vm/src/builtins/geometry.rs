//! Frames and rotations (§1.15): orientations are unit quaternions [q1,q2,q3,q4] =
//! q1 + q2 i + q3 j + q4 k; angles are in degrees; OrientZYX/EulerZYX use the
//! rotation order Z, then Y, then X (about the rotated axes).

use super::Ctx;
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Record, Value};

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("OrientZYX", orient_zyx),
        super::native("EulerZYX", euler_zyx),
        super::native("NOrient", n_orient),
        super::native("PoseMult", pose_mult),
        super::native("PoseInv", pose_inv),
        super::native("PoseVect", pose_vect),
    ],
};

type Res = Result<Option<Value>, RapidError>;
type Quat = [f64; 4];
type Vec3 = [f64; 3];

fn numbers(ctx: &Ctx<'_>, value: &Value, n: usize) -> Result<Vec<f64>, RapidError> {
    match value {
        Value::Record(r) if r.fields.len() == n => Ok(r.fields.iter().map(|f| f.as_f64().unwrap_or(0.0)).collect()),
        _ => Err(ctx.error(Err::ArgValue, "a pos or orient was expected")),
    }
}

fn quat(ctx: &Ctx<'_>, value: &Value) -> Result<Quat, RapidError> {
    let q = numbers(ctx, value, 4)?;
    Ok([q[0], q[1], q[2], q[3]])
}

fn vec3(ctx: &Ctx<'_>, value: &Value) -> Result<Vec3, RapidError> {
    let v = numbers(ctx, value, 3)?;
    Ok([v[0], v[1], v[2]])
}

/// A pose's translation and rotation.
fn pose(ctx: &Ctx<'_>, value: &Value) -> Result<(Vec3, Quat, std::rc::Rc<Record>), RapidError> {
    match value {
        Value::Record(r) if r.fields.len() == 2 => Ok((vec3(ctx, &r.fields[0])?, quat(ctx, &r.fields[1])?, r.clone())),
        _ => Err(ctx.error(Err::ArgValue, "a pose was expected")),
    }
}

fn with_numbers(like: &Value, numbers: &[f64]) -> Value {
    match like {
        Value::Record(r) => Value::Record(std::rc::Rc::new(Record {
            ty: r.ty,
            fields: numbers.iter().map(|&x| Value::Num(x as f32)).collect(),
        })),
        other => other.clone(),
    }
}

fn normalize(q: Quat) -> Option<Quat> {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    (n > 1e-9).then(|| [q[0] / n, q[1] / n, q[2] / n, q[3] / n])
}

fn mul(a: Quat, b: Quat) -> Quat {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

fn conjugate(q: Quat) -> Quat {
    [q[0], -q[1], -q[2], -q[3]]
}

/// `v` rotated by unit quaternion `q` (q v q*).
fn rotate(q: Quat, v: Vec3) -> Vec3 {
    let r = mul(mul(q, [0.0, v[0], v[1], v[2]]), conjugate(q));
    [r[1], r[2], r[3]]
}

fn axis_angle(axis: usize, degrees: f64) -> Quat {
    let half = degrees.to_radians() / 2.0;
    let mut q = [half.cos(), 0.0, 0.0, 0.0];
    q[axis + 1] = half.sin();
    q
}

super::signature::layout! {
    static ORIENT_ZYX: OrientZyxArgs = "OrientZYX" { z: "ZAngle", y: "YAngle", x: "XAngle" }
    static EULER_ZYX: EulerZyxArgs = "EulerZYX" { x: "X", y: "Y", rotation: "Rotation" }
}

/// `OrientZYX(ZAngle, YAngle, XAngle)`.
pub(super) fn orient_zyx(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ORIENT_ZYX;
    let (z, y, x) = (ctx.num(&args[at.z])?, ctx.num(&args[at.y])?, ctx.num(&args[at.x])?);
    let q = mul(mul(axis_angle(2, z), axis_angle(1, y)), axis_angle(0, x));
    Ok(Some(Value::Record(std::rc::Rc::new(Record {
        ty: ctx.types.orient,
        fields: q.iter().map(|&c| Value::Num(c as f32)).collect(),
    }))))
}

/// `EulerZYX(\X | \Y | \Z, Rotation)`: one of the Z-Y-X angles of an orientation.
pub(super) fn euler_zyx(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *EULER_ZYX;
    let rotation = ctx.value(&args[at.rotation])?;
    let q = normalize(quat(ctx, &rotation)?).ok_or_else(|| ctx.error(Err::ArgValue, "zero orientation"))?;
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    let angle = if super::present(args.get(at.x)) {
        (2.0 * (w * x + y * z)).atan2(1.0 - 2.0 * (x * x + y * y))
    } else if super::present(args.get(at.y)) {
        (2.0 * (w * y - z * x)).clamp(-1.0, 1.0).asin()
    } else {
        (2.0 * (w * z + x * y)).atan2(1.0 - 2.0 * (y * y + z * z))
    };
    Ok(Some(Value::Num(angle.to_degrees() as f32)))
}

/// `NOrient(Rotation)`: the orientation normalised to a unit quaternion.
pub(super) fn n_orient(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let value = ctx.value(&args[0])?;
    let q = normalize(quat(ctx, &value)?)
        .ok_or_else(|| ctx.error(Err::ArgValue, "a zero quaternion has no orientation"))?;
    Ok(Some(with_numbers(&value, &q)))
}

fn make_pose(mut like: std::rc::Rc<Record>, t: Vec3, q: Quat) -> Value {
    let record = std::rc::Rc::make_mut(&mut like);
    record.fields[0] = with_numbers(&record.fields[0], &t);
    record.fields[1] = with_numbers(&record.fields[1], &q);
    Value::Record(like)
}

/// `PoseMult(Pose1, Pose2)`: Pose2 expressed in the frame of Pose1.
pub(super) fn pose_mult(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (t1, q1, like) = pose(ctx, &ctx.value(&args[0])?)?;
    let (t2, q2, _) = pose(ctx, &ctx.value(&args[1])?)?;
    let r = rotate(q1, t2);
    Ok(Some(make_pose(like, [t1[0] + r[0], t1[1] + r[1], t1[2] + r[2]], mul(q1, q2))))
}

/// `PoseInv(Pose)`: the inverse frame.
pub(super) fn pose_inv(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (t, q, like) = pose(ctx, &ctx.value(&args[0])?)?;
    let inv = conjugate(q);
    let r = rotate(inv, t);
    Ok(Some(make_pose(like, [-r[0], -r[1], -r[2]], inv)))
}

/// `PoseVect(Pose, Pos)`: the point Pos (given in the frame Pose) in the outer frame.
pub(super) fn pose_vect(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (t, q, _) = pose(ctx, &ctx.value(&args[0])?)?;
    let p = vec3(ctx, &ctx.value(&args[1])?)?;
    let r = rotate(q, p);
    Ok(Some(ctx.pos((t[0] + r[0]) as f32, (t[1] + r[1]) as f32, (t[2] + r[2]) as f32)))
}
