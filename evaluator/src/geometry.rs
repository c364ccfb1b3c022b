//! Pose and orientation math on nalgebra, with RAPID's conventions:
//! orient `[q1, q2, q3, q4]` is the quaternion `q1 + q2 i + q3 j + q4 k`,
//! angles are degrees, results are stored as `num` (f32).

use nalgebra::{Isometry3, Matrix3, Quaternion, Rotation3, Translation3, UnitQuaternion, Vector3};

use crate::error::{ErrorCode, EvalError, err};
use crate::eval::num_result;
use crate::operators::{orient_of, pos_of};
use crate::value::Value;

/// Normalisation error above which an orientation is unusable.
const MAX_NORM_ERR: f64 = 0.1;

/// Sine of an angle in degrees, exact at multiples of 30 and 90 degrees
/// where the value is 0, ±0.5 or ±1.
pub fn sin_deg(a: f64) -> f64 {
    let r = a.rem_euclid(360.0);
    if r == 0.0 || r == 180.0 {
        0.0
    } else if r == 90.0 {
        1.0
    } else if r == 270.0 {
        -1.0
    } else if r == 30.0 || r == 150.0 {
        0.5
    } else if r == 210.0 || r == 330.0 {
        -0.5
    } else {
        r.to_radians().sin()
    }
}

/// Cosine of an angle in degrees, exact where the value is 0, ±0.5 or ±1.
pub fn cos_deg(a: f64) -> f64 {
    sin_deg(a + 90.0)
}

/// Checks and normalises a RAPID orientation, as the controller does before
/// using it: an orientation whose norm is off by more than 0.1 is unusable
/// (`ERR_ILLQUAT`).
pub fn unit_quat(q: [f32; 4]) -> Result<UnitQuaternion<f64>, EvalError> {
    let q = q.map(f64::from);
    let norm = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    if !norm.is_finite() || (norm - 1.0).abs() > MAX_NORM_ERR {
        return err(
            ErrorCode::IllQuat,
            format!("the orientation is not normalised (norm {norm:.6}); it cannot be used"),
        );
    }
    Ok(UnitQuaternion::from_quaternion(Quaternion::new(
        q[0], q[1], q[2], q[3],
    )))
}

/// An orient value; with `canonical`, the sign is chosen so that q1 >= 0
/// (as a quaternion computed from a rotation matrix has).
pub fn orient_value(q: &UnitQuaternion<f64>, canonical: bool) -> Result<Value, EvalError> {
    let mut c = [q.w, q.i, q.j, q.k];
    if canonical {
        let first = c.iter().copied().find(|x| *x != 0.0).unwrap_or(1.0);
        if c[0] < 0.0 || (c[0] == 0.0 && first < 0.0) {
            c = c.map(|x| -x);
        }
    }
    let mut out = [0f32; 4];
    for (o, x) in out.iter_mut().zip(c) {
        *o = f32_of(x)?;
    }
    Ok(Value::orient(out))
}

fn f32_of(x: f64) -> Result<f32, EvalError> {
    match num_result(x)? {
        Value::Num(v) => Ok(v),
        _ => Ok(0.0),
    }
}

/// A quaternion for a rotation of `deg` degrees about a principal axis
/// (0 = x, 1 = y, 2 = z), exact at multiples of 90 degrees.
pub fn axis_quat(axis: usize, deg: f64) -> UnitQuaternion<f64> {
    let (s, c) = (sin_deg(deg / 2.0), cos_deg(deg / 2.0));
    let q = match axis {
        0 => Quaternion::new(c, s, 0.0, 0.0),
        1 => Quaternion::new(c, 0.0, s, 0.0),
        _ => Quaternion::new(c, 0.0, 0.0, s),
    };
    UnitQuaternion::new_unchecked(q)
}

/// `OrientZYX`: rotation about z, then the new y, then the new x.
pub fn orient_zyx(z: f64, y: f64, x: f64) -> UnitQuaternion<f64> {
    axis_quat(2, z) * axis_quat(1, y) * axis_quat(0, x)
}

/// The Euler ZYX angles `[z, y, x]` in degrees (each in [-180, 180]) of an
/// orientation `[q1, q2, q3, q4]` — what `EulerZYX(\Z|\Y|\X, q)` returns
/// and what a hover shows for an orient or a pose. The quaternion is
/// normalised first; a zero quaternion gives `[0, 0, 0]`.
pub fn euler_zyx_deg(q: [f64; 4]) -> [f64; 3] {
    let quat = Quaternion::new(q[0], q[1], q[2], q[3]);
    if quat.norm().is_nan() || quat.norm() <= 0.0 {
        return [0.0; 3];
    }
    let u = UnitQuaternion::from_quaternion(quat);
    let (roll, pitch, yaw) = u.euler_angles();
    [yaw.to_degrees(), pitch.to_degrees(), roll.to_degrees()]
}

/// The pos value as a vector.
pub fn vec_of(v: &Value) -> Result<Vector3<f64>, EvalError> {
    let p = pos_of(v)?;
    Ok(Vector3::new(
        f64::from(p[0]),
        f64::from(p[1]),
        f64::from(p[2]),
    ))
}

/// A pos value from a vector.
pub fn pos_value(v: &Vector3<f64>) -> Result<Value, EvalError> {
    Ok(Value::pos(f32_of(v.x)?, f32_of(v.y)?, f32_of(v.z)?))
}

/// The frame of a pose-like record (`pose`, `robtarget`, a wobjdata frame)
/// from its `trans` and `rot` components.
pub fn iso_of(v: &Value) -> Result<Isometry3<f64>, EvalError> {
    let (Some(t), Some(r)) = (v.field("trans"), v.field("rot")) else {
        return err(
            ErrorCode::TypeMismatch,
            "expected a value with trans and rot components",
        );
    };
    let t = vec_of(t)?;
    let q = unit_quat(orient_of(r)?)?;
    Ok(Isometry3::from_parts(Translation3::from(t), q))
}

/// A pose value.
pub fn pose_value(iso: &Isometry3<f64>, canonical: bool) -> Result<Value, EvalError> {
    Ok(Value::Record {
        ty: "pose".into(),
        fields: vec![
            ("trans".into(), pos_value(&iso.translation.vector)?),
            ("rot".into(), orient_value(&iso.rotation, canonical)?),
        ],
    })
}

/// Replaces the `trans` (and, if given, `rot`) of a robtarget-like record.
pub fn with_frame(
    target: &Value,
    trans: &Vector3<f64>,
    rot: Option<Value>,
) -> Result<Value, EvalError> {
    let Value::Record { ty, fields } = target else {
        return err(ErrorCode::TypeMismatch, "expected a robtarget");
    };
    let mut fields = fields.clone();
    for (name, v) in fields.iter_mut() {
        if name.eq_ignore_ascii_case("trans") {
            *v = pos_value(trans)?;
        } else if name.eq_ignore_ascii_case("rot")
            && let Some(r) = &rot
        {
            *v = r.clone();
        }
    }
    Ok(Value::Record {
        ty: ty.clone(),
        fields,
    })
}

fn from_matrix(m: Matrix3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m))
}

/// The frame of three points: origin `p1`, x axis towards `p2`, `p3` in
/// the xy plane on the positive y side. `ERR_FRAME` if the points are
/// closer than 0.1 mm or (nearly) on one line.
pub fn frame_of_points(
    p1: &Vector3<f64>,
    p2: &Vector3<f64>,
    p3: &Vector3<f64>,
) -> Result<(Matrix3<f64>, Vector3<f64>), EvalError> {
    let a = p2 - p1;
    let b = p3 - p1;
    if a.norm() < 0.1 || b.norm() < 0.1 {
        return err(
            ErrorCode::Frame,
            "the positions are too close together to define a frame",
        );
    }
    let cos = a.dot(&b) / (a.norm() * b.norm());
    if cos.abs() >= 1.0 - 1e-4 {
        return err(
            ErrorCode::Frame,
            "the positions are (nearly) on one line and define no frame",
        );
    }
    let x = a.normalize();
    let z = x.cross(&b).normalize();
    let y = z.cross(&x);
    Ok((Matrix3::from_columns(&[x, y, z]), x))
}

/// `DefFrame`.
pub fn def_frame(
    p1: &Vector3<f64>,
    p2: &Vector3<f64>,
    p3: &Vector3<f64>,
    origin: i64,
) -> Result<Isometry3<f64>, EvalError> {
    let (m, x) = frame_of_points(p1, p2, p3)?;
    let o = match origin {
        2 => *p2,
        3 => p1 + x * (p3 - p1).dot(&x),
        _ => *p1,
    };
    Ok(Isometry3::from_parts(Translation3::from(o), from_matrix(m)))
}

/// `DefDFrame`: the displacement that moves the old frame onto the new one.
pub fn def_dframe(
    old: [Vector3<f64>; 3],
    new: [Vector3<f64>; 3],
) -> Result<Isometry3<f64>, EvalError> {
    let fo = def_frame(&old[0], &old[1], &old[2], 1)?;
    let fnew = def_frame(&new[0], &new[1], &new[2], 1)?;
    Ok(fnew * fo.inverse())
}

/// `DefAccFrame`: the rigid transform that best maps `one[i]` onto `two[i]`
/// (least squares).
pub fn def_acc_frame(
    one: &[Vector3<f64>],
    two: &[Vector3<f64>],
) -> Result<Isometry3<f64>, EvalError> {
    let n = one.len().min(two.len());
    if n < 3 {
        return err(ErrorCode::Frame, "at least three positions are needed");
    }
    let k = n as f64;
    let ca = one.iter().take(n).sum::<Vector3<f64>>() / k;
    let cb = two.iter().take(n).sum::<Vector3<f64>>() / k;
    let mut h = Matrix3::zeros();
    for (a, b) in one.iter().zip(two).take(n) {
        h += (a - ca) * (b - cb).transpose();
    }
    let svd = h.svd(true, true);
    let (Some(u), Some(vt)) = (svd.u, svd.v_t) else {
        return err(ErrorCode::Frame, "the frame cannot be calculated");
    };
    let mut sv: Vec<f64> = svd.singular_values.iter().copied().collect();
    sv.sort_by(|a, b| b.partial_cmp(a).unwrap_or(std::cmp::Ordering::Equal));
    if sv.get(1).copied().unwrap_or(0.0) < 1e-6 * sv.first().copied().unwrap_or(0.0).max(1e-12) {
        return err(
            ErrorCode::Frame,
            "the positions are (nearly) on one line and define no frame",
        );
    }
    let v = vt.transpose();
    let d = (v * u.transpose()).determinant().signum();
    let r = v * Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, d)) * u.transpose();
    let q = from_matrix(r);
    let t = cb - q * ca;
    Ok(Isometry3::from_parts(Translation3::from(t), q))
}

/// `MirPos`: mirrors `point` (a frame given in `wobj`) in the xy plane of
/// `mirror`; the tool's x and z axes are mirrored, or y and z with `mir_y`.
pub fn mir_pos(
    point: &Isometry3<f64>,
    mirror: &Isometry3<f64>,
    wobj: &Isometry3<f64>,
    mir_y: bool,
) -> Result<Isometry3<f64>, EvalError> {
    let world = wobj * point;
    let local = mirror.inverse() * world;
    let m = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
    let d = if mir_y {
        Matrix3::from_diagonal(&Vector3::new(-1.0, 1.0, 1.0))
    } else {
        Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, 1.0))
    };
    let r = m * local.rotation.to_rotation_matrix().into_inner() * d;
    let t = m * local.translation.vector;
    let mirrored = Isometry3::from_parts(Translation3::from(t), from_matrix(r));
    Ok(wobj.inverse() * (mirror * mirrored))
}

/// The rigid transformation of a translation (mm) and a quaternion
/// `[q1, q2, q3, q4]` (normalised here; a zero quaternion is no rotation),
/// for poses computed outside values (a robot's frames).
pub fn isometry(trans: [f64; 3], rot: [f64; 4]) -> Isometry3<f64> {
    let q = Quaternion::new(rot[0], rot[1], rot[2], rot[3]);
    let rot = if q.norm() > 1e-12 {
        UnitQuaternion::from_quaternion(q)
    } else {
        UnitQuaternion::identity()
    };
    Isometry3::from_parts(Translation3::new(trans[0], trans[1], trans[2]), rot)
}

/// The translation and the quaternion `[q1, q2, q3, q4]` of a
/// transformation ([`isometry`]'s inverse).
pub fn isometry_parts(iso: &Isometry3<f64>) -> ([f64; 3], [f64; 4]) {
    let t = iso.translation.vector;
    let q = iso.rotation;
    ([t.x, t.y, t.z], [q.w, q.i, q.j, q.k])
}

/// The distance in mm between two `pos` values (or the origins of two
/// pose-like values: `pose`, `robtarget`); `None` when either is neither.
pub fn distance_mm(old: &Value, new: &Value) -> Option<f64> {
    let at = |v: &Value| vec_of(v.field("trans").unwrap_or(v)).ok();
    Some((at(new)? - at(old)?).norm())
}

/// The angle in degrees (0 to 180) of the rotation that turns one
/// orientation into another: of two `orient` values, or of the `rot`
/// components of two pose-like values. Computed from the relative
/// quaternion's vector part and scalar (`2 atan2(|v|, |w|)`), which stays
/// accurate for tiny angles where `acos` does not; `q` and `-q` are one
/// orientation. `None` when either is not an orientation or is not
/// normalised ([`unit_quat`]).
pub fn rotation_deg(old: &Value, new: &Value) -> Option<f64> {
    let orient = |v: &Value| orient_of(v.field("rot").unwrap_or(v)).ok();
    let (a, b) = (unit_quat(orient(old)?).ok()?, unit_quat(orient(new)?).ok()?);
    // One orientation written twice: no turn, not the rounding of one.
    if orient(old) == orient(new) {
        return Some(0.0);
    }
    let r = a.inverse() * b;
    let v = r.imag().norm();
    Some((2.0 * v.atan2(r.w.abs())).to_degrees())
}

/// The frame a work object (`wobjdata`) puts its targets in: its user
/// frame `uframe` times its object frame `oframe`, as a `pose`.
pub fn wobj_frame(wobj: &Value) -> Option<Value> {
    let user = iso_of(wobj.field("uframe")?).ok()?;
    let object = iso_of(wobj.field("oframe")?).ok()?;
    pose_value(&(user * object), false).ok()
}

#[cfg(test)]
mod change_tests {
    use super::*;

    fn pose(t: [f32; 3], q: [f32; 4]) -> Value {
        Value::pose(t, q)
    }

    #[test]
    fn distances_and_angles_between_frames() {
        let a = pose([0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]);
        let b = pose([3.0, 4.0, 0.0], [0.6, 0.0, 0.0, 0.8]);
        assert_eq!(distance_mm(&a, &b), Some(5.0));
        // About z by twice atan(0.8 / 0.6).
        let angle = rotation_deg(&a, &b).expect("an angle");
        assert!((angle - 106.260_205).abs() < 1e-4, "{angle}");
        // -q is the same orientation.
        let c = pose([0.0; 3], [-1.0, 0.0, 0.0, 0.0]);
        assert_eq!(rotation_deg(&a, &c), Some(0.0));
        // A tiny turn is measured, not lost to rounding: 0.01 degrees.
        let half = (0.005f64).to_radians();
        let d = pose([0.0; 3], [half.cos() as f32, half.sin() as f32, 0.0, 0.0]);
        let tiny = rotation_deg(&a, &d).expect("an angle");
        assert!((tiny - 0.01).abs() < 1e-4, "{tiny}");
        // Unusable orientations and non-frames give nothing.
        let bad = pose([0.0; 3], [0.0; 4]);
        assert_eq!(rotation_deg(&a, &bad), None);
        assert_eq!(distance_mm(&a, &Value::Num(1.0)), None);
        assert_eq!(
            distance_mm(&Value::pos(1.0, 1.0, 1.0), &Value::pos(1.0, 1.0, 2.0)),
            Some(1.0)
        );
    }

    #[test]
    fn a_work_object_frame_is_user_times_object() {
        let wobj = Value::Record {
            ty: "wobjdata".into(),
            fields: vec![
                (
                    "uframe".into(),
                    pose([100.0, 0.0, 0.0], [0.6, 0.0, 0.0, 0.8]),
                ),
                (
                    "oframe".into(),
                    pose([10.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
                ),
            ],
        };
        let f = wobj_frame(&wobj).expect("a frame");
        // cos and sin of that turn are -0.28 and 0.96.
        let origin = Value::pos(97.2, 9.6, 0.0);
        assert!(distance_mm(&f, &origin).expect("a distance") < 1e-4);
    }
}
