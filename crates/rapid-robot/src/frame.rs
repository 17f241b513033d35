//! Reading and writing RAPID's pos, orient, pose, robtarget and wobjdata values as
//! nalgebra frames, for the motion family's position functions.
//!
//! An orient is [q1, q2, q3, q4] with q1 the scalar part (motion.md §3.4); a pose is
//! [trans, rot]; a robtarget is [trans, rot, robconf, extax]; a wobjdata is
//! [robhold, ufprog, ufmec, uframe, oframe]. Arithmetic is done in f64 and stored
//! back as num (f32).

use crate::RobotResources;
use std::rc::Rc;

use nalgebra::{Isometry3, Matrix3, Quaternion, Rotation3, Translation3, UnitQuaternion, Vector3};

use rapid_vm::ext::{Ctx, Err, RapidError, Record, Value};

/// A value's fields, when it is a record of `n` fields.
fn fields<'v>(ctx: &Ctx<'_>, value: &'v Value, n: usize, what: &str) -> Result<&'v [Value], RapidError> {
    match value {
        Value::Record(r) if r.fields.len() == n => Ok(&r.fields),
        _ => Err(ctx.error(Err::ArgValue, format!("{what} was expected"))),
    }
}

fn numbers<const N: usize>(ctx: &Ctx<'_>, value: &Value, what: &str) -> Result<[f64; N], RapidError> {
    let fields = fields(ctx, value, N, what)?;
    let mut out = [0.0; N];
    for (slot, field) in out.iter_mut().zip(fields) {
        *slot = field.as_f64().ok_or_else(|| ctx.error(Err::ArgValue, format!("{what} was expected")))?;
    }
    Ok(out)
}

/// A pos value as a vector.
pub(super) fn vector(ctx: &Ctx<'_>, value: &Value) -> Result<Vector3<f64>, RapidError> {
    let [x, y, z] = numbers::<3>(ctx, value, "a pos")?;
    Ok(Vector3::new(x, y, z))
}

/// An orient value as it stands (not normalised).
pub(super) fn quaternion(ctx: &Ctx<'_>, value: &Value) -> Result<Quaternion<f64>, RapidError> {
    let [q1, q2, q3, q4] = numbers::<4>(ctx, value, "an orient")?;
    Ok(Quaternion::new(q1, q2, q3, q4))
}

/// A rotation from an orient; an orient of (near) zero length has no direction.
// uncertain: the controller stops with an "orientation not normalised" event at
// motion time; a position function here raises ERR_ARGVALERR instead.
pub(super) fn unit(ctx: &Ctx<'_>, q: Quaternion<f64>) -> Result<UnitQuaternion<f64>, RapidError> {
    if q.norm() < 1e-6 {
        return Err(ctx.error(Err::ArgValue, "an orientation of zero length has no direction"));
    }
    Ok(UnitQuaternion::new_normalize(q))
}

/// The translation and orient of a pose or a robtarget (their first two fields).
pub(super) fn trans_rot(ctx: &Ctx<'_>, value: &Value) -> Result<(Vector3<f64>, Quaternion<f64>), RapidError> {
    match value {
        Value::Record(r) if r.fields.len() >= 2 => Ok((vector(ctx, &r.fields[0])?, quaternion(ctx, &r.fields[1])?)),
        _ => Err(ctx.error(Err::ArgValue, "a pose or robtarget was expected")),
    }
}

/// A pose or robtarget as a rigid frame.
pub(super) fn frame(ctx: &Ctx<'_>, value: &Value) -> Result<Isometry3<f64>, RapidError> {
    let (t, q) = trans_rot(ctx, value)?;
    Ok(Isometry3::from_parts(Translation3::from(t), unit(ctx, q)?))
}

/// The frame of a work object: its object frame in world (uframe · oframe).
pub(super) fn wobj_frame(ctx: &Ctx<'_>, value: &Value) -> Result<Isometry3<f64>, RapidError> {
    let fields = fields(ctx, value, 5, "a wobjdata")?;
    Ok(frame(ctx, &fields[3])? * frame(ctx, &fields[4])?)
}

/// The six values of an extjoint.
pub(super) fn extjoint(ctx: &Ctx<'_>, value: &Value) -> Result<[f64; 6], RapidError> {
    numbers::<6>(ctx, value, "an extjoint")
}

/// The quaternion of a rotation matrix with q1 >= 0, as the orient page's formula
/// (q1 = ½√(x1+y2+z3+1)) gives it.
pub(super) fn from_matrix(m: &Matrix3<f64>) -> Quaternion<f64> {
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(*m)).into_inner();
    if q.w < 0.0 {
        -q
    } else {
        q
    }
}

fn num(x: f64) -> Value {
    // Exact zeros stay positive, so a result never prints as -0.
    Value::Num(if x == 0.0 { 0.0 } else { x as f32 })
}

/// `like` (a pos/orient/extjoint record) with new numbers.
fn with_numbers(like: &Value, numbers: &[f64]) -> Value {
    match like {
        Value::Record(r) => {
            Value::Record(Rc::new(Record { ty: r.ty, fields: numbers.iter().map(|&x| num(x)).collect() }))
        }
        other => other.clone(),
    }
}

/// `like` (a pose or robtarget) with a new translation and orient; its other fields
/// (robconf, extax) are kept.
pub(super) fn with_trans_rot(like: &Value, t: &Vector3<f64>, q: &Quaternion<f64>) -> Value {
    let Value::Record(record) = like else { return like.clone() };
    let mut record = record.clone();
    let fields = &mut Rc::make_mut(&mut record).fields;
    if fields.len() >= 2 {
        fields[0] = with_numbers(&fields[0], &[t.x, t.y, t.z]);
        fields[1] = with_numbers(&fields[1], &[q.w, q.i, q.j, q.k]);
    }
    Value::Record(record)
}

/// `like` (a robtarget) with a frame's translation and rotation.
pub(super) fn with_frame(like: &Value, frame: &Isometry3<f64>) -> Value {
    let q = frame.rotation.into_inner();
    with_trans_rot(like, &frame.translation.vector, &q)
}

/// `like` (a robtarget or a jointtarget, whose last field is `extax`) with new
/// external axis values.
pub(super) fn with_extax(like: &Value, extax: &[f64; 6]) -> Value {
    let Value::Record(record) = like else { return like.clone() };
    let mut record = record.clone();
    let fields = &mut Rc::make_mut(&mut record).fields;
    if matches!(fields.len(), 2 | 4) {
        let last = fields.len() - 1;
        fields[last] = with_numbers(&fields[last], extax);
    }
    Value::Record(record)
}

/// A new pose value (DefFrame, DefDFrame, DefAccFrame); the rotation is written
/// with q1 >= 0.
pub(super) fn pose_value(ctx: &Ctx<'_>, frame: &Isometry3<f64>) -> Result<Value, RapidError> {
    let Some(pose_ty) = ctx.resources.motion().links.pose else {
        return Err(ctx.error(Err::ArgValue, "the pose type is not known to this program"));
    };
    let q = from_matrix(frame.rotation.to_rotation_matrix().matrix());
    let t = frame.translation.vector;
    let pos = Value::Record(Rc::new(Record { ty: ctx.types.pos, fields: vec![num(t.x), num(t.y), num(t.z)] }));
    let orient =
        Value::Record(Rc::new(Record { ty: ctx.types.orient, fields: vec![num(q.w), num(q.i), num(q.j), num(q.k)] }));
    Ok(Value::Record(Rc::new(Record { ty: pose_ty, fields: vec![pos, orient] })))
}

#[cfg(test)]
mod tests {
    use super::from_matrix;
    use nalgebra::Matrix3;

    #[test]
    fn a_rotation_matrix_gives_the_orient_pages_quaternion() {
        // A quarter turn about x (y goes to z, z to -y) is [cos 45°, sin 45°, 0, 0]; the
        // orient page's formula agrees: q1 = ½√(1 + 0 + 0 + 1) = √½, q2 = ½√(1 - 0 - 0 + 1).
        let m = Matrix3::new(1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0);
        let q = from_matrix(&m);
        let half = std::f64::consts::FRAC_1_SQRT_2;
        assert!((q.w - half).abs() < 1e-12 && (q.i - half).abs() < 1e-12 && q.j.abs() < 1e-12 && q.k.abs() < 1e-12);
        // Of the two quaternions of a rotation, the one with q1 >= 0: the identity is
        // [1, 0, 0, 0], not [-1, 0, 0, 0].
        let one = from_matrix(&Matrix3::identity());
        assert!((one.w - 1.0).abs() < 1e-12);
    }
}
