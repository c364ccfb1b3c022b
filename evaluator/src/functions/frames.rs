//! Positions, orientations, poses and frames: vectors, pose algebra,
//! offsets, mirroring and frame definition (the mathematics is in
//! `crate::geometry`).

use nalgebra::{Isometry3, Vector3};

use super::Args;
use crate::error::{ErrorCode, EvalError, err};
use crate::eval::num_result;
use crate::geometry as g;
use crate::operators::orient_of;
use crate::value::Value;

type R = Result<Value, EvalError>;

pub(super) fn distance(a: &Args<'_>) -> R {
    let d = g::vec_of(a.val("Point1")?)? - g::vec_of(a.val("Point2")?)?;
    num_result(d.norm())
}

pub(super) fn dot_prod(a: &Args<'_>) -> R {
    num_result(g::vec_of(a.val("Vector1")?)?.dot(&g::vec_of(a.val("Vector2")?)?))
}

pub(super) fn vect_magn(a: &Args<'_>) -> R {
    num_result(g::vec_of(a.val("Vector")?)?.norm())
}

pub(super) fn pose_inv(a: &Args<'_>) -> R {
    g::pose_value(&g::iso_of(a.val("Pose")?)?.inverse(), false)
}

pub(super) fn pose_mult(a: &Args<'_>) -> R {
    let p = g::iso_of(a.val("Pose1")?)? * g::iso_of(a.val("Pose2")?)?;
    g::pose_value(&p, false)
}

pub(super) fn pose_vect(a: &Args<'_>) -> R {
    let p = g::iso_of(a.val("Pose")?)?;
    let v = g::vec_of(a.val("Pos")?)?;
    g::pos_value(&p.transform_point(&v.into()).coords)
}

pub(super) fn orient_zyx(a: &Args<'_>) -> R {
    let q = g::orient_zyx(a.num("ZAngle")?, a.num("YAngle")?, a.num("XAngle")?);
    g::orient_value(&q, true)
}

pub(super) fn euler_zyx(a: &Args<'_>) -> R {
    let q = g::unit_quat(orient_of(a.val("Rotation")?)?)?;
    let e = g::euler_zyx_deg([q.w, q.i, q.j, q.k]);
    let v = if a.sw("Z") {
        e[0]
    } else if a.sw("Y") {
        e[1]
    } else if a.sw("X") {
        e[2]
    } else {
        return err(
            ErrorCode::ArgValErr,
            "EulerZYX: one of \\X, \\Y or \\Z must be given",
        );
    };
    num_result(v)
}

pub(super) fn norient(a: &Args<'_>) -> R {
    let q = orient_of(a.val("Rotation")?)?;
    let qd = q.map(f64::from);
    let norm = qd.iter().map(|x| x * x).sum::<f64>().sqrt();
    let normerr = (norm - 1.0).abs();
    if !normerr.is_finite() || normerr > 0.1 {
        return err(
            ErrorCode::IllQuat,
            format!("NOrient: the orientation is too far from normalised (norm {norm:.6})"),
        );
    }
    if normerr <= 0.00001 {
        return Ok(Value::orient(q));
    }
    let mut out = [0f32; 4];
    for (o, x) in out.iter_mut().zip(qd) {
        *o = (x / norm) as f32;
    }
    Ok(Value::orient(out))
}

pub(super) fn offs(a: &Args<'_>) -> R {
    let p = a.val("Point")?;
    let t = g::vec_of(p.field("trans").unwrap_or(&Value::Bool(false)))?;
    let d = Vector3::new(a.num("XOffset")?, a.num("YOffset")?, a.num("ZOffset")?);
    g::with_frame(p, &(t + d), None)
}

pub(super) fn rel_tool(a: &Args<'_>) -> R {
    let p = a.val("Point")?;
    let frame = g::iso_of(p)?;
    let d = Vector3::new(a.num("Dx")?, a.num("Dy")?, a.num("Dz")?);
    let t = frame.translation.vector + frame.rotation * d;
    let (rx, ry, rz) = (a.opt_num("Rx")?, a.opt_num("Ry")?, a.opt_num("Rz")?);
    let rot = if rx.is_some() || ry.is_some() || rz.is_some() {
        let q = frame.rotation
            * g::axis_quat(0, rx.unwrap_or(0.0))
            * g::axis_quat(1, ry.unwrap_or(0.0))
            * g::axis_quat(2, rz.unwrap_or(0.0));
        Some(g::orient_value(&q, false)?)
    } else {
        None
    };
    g::with_frame(p, &t, rot)
}

pub(super) fn mir_pos(a: &Args<'_>) -> R {
    let p = a.val("Point")?;
    let mirror = wobj_frame(a.val("MirPlane")?)?;
    let wobj = match a.get("WObj") {
        Some(w) => wobj_frame(w)?,
        None => Isometry3::identity(),
    };
    let r = g::mir_pos(&g::iso_of(p)?, &mirror, &wobj, a.sw("MirY"))?;
    g::with_frame(
        p,
        &r.translation.vector,
        Some(g::orient_value(&r.rotation, true)?),
    )
}

pub(super) fn def_frame(a: &Args<'_>) -> R {
    let p = |n: &str| -> Result<Vector3<f64>, EvalError> { trans_of(a.val(n)?) };
    let origin = a.opt_num("Origin")?.unwrap_or(1.0);
    let origin = if origin.fract() == 0.0 {
        origin as i64
    } else {
        1
    };
    let f = g::def_frame(&p("NewP1")?, &p("NewP2")?, &p("NewP3")?, origin)?;
    g::pose_value(&f, true)
}

pub(super) fn def_dframe(a: &Args<'_>) -> R {
    let p = |n: &str| -> Result<Vector3<f64>, EvalError> { trans_of(a.val(n)?) };
    let f = g::def_dframe(
        [p("OldP1")?, p("OldP2")?, p("OldP3")?],
        [p("NewP1")?, p("NewP2")?, p("NewP3")?],
    )?;
    g::pose_value(&f, true)
}

pub(super) fn def_acc_frame(a: &Args<'_>) -> R {
    let n = a.num("TargetsInList")?;
    if n.fract() != 0.0 || !(3.0..=10.0).contains(&n) {
        return err(
            ErrorCode::ArgValErr,
            "DefAccFrame: the number of targets must be 3 to 10",
        );
    }
    let n = n as usize;
    let list = |name: &str| -> Result<Vec<Vector3<f64>>, EvalError> {
        match a.val(name)? {
            Value::Array(items) if items.len() >= n => items.iter().take(n).map(trans_of).collect(),
            Value::Array(_) => err(
                ErrorCode::OutOfBnd,
                format!("DefAccFrame: {name} holds fewer than {n} targets"),
            ),
            _ => err(
                ErrorCode::TypeMismatch,
                format!("DefAccFrame: {name} must be an array of robtarget"),
            ),
        }
    };
    let f = g::def_acc_frame(&list("TargetListOne")?, &list("TargetListTwo")?)?;
    g::pose_value(&f, true)
}

fn trans_of(v: &Value) -> Result<Vector3<f64>, EvalError> {
    match v.field("trans") {
        Some(t) => g::vec_of(t),
        None => err(ErrorCode::TypeMismatch, "expected a robtarget"),
    }
}

fn wobj_frame(w: &Value) -> Result<Isometry3<f64>, EvalError> {
    match (w.field("uframe"), w.field("oframe")) {
        (Some(u), Some(o)) => Ok(g::iso_of(u)? * g::iso_of(o)?),
        _ => err(ErrorCode::TypeMismatch, "expected a wobjdata"),
    }
}
