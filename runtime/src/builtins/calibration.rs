//! Tool calibration from robot positions: `MToolTCPCalib`. It needs the
//! robot's kinematics (where the flange is at each joint position), so it
//! runs with a modelled arm; without one it stops as the other kinematic
//! functions do.

use rapid_evaluator::Value;
use rapid_evaluator::nalgebra::{DMatrix, DVector, Vector3};

use super::{Args, Cx, Done};
use crate::machine::{R, invalid};
use crate::world::{RobotError, Tool, WObj};

/// `MToolTCPCalib Pos1, Pos2, Pos3, Pos4, Tool, MaxErr, MeanErr`: the four
/// joint positions point the tool's tip at one fixed point; the TCP is the
/// point of the flange's frame that moves least between them (least
/// squares: each flange pose `R_i, p_i` should put `R_i t + p_i` at one
/// point `c`). `Tool`'s `tframe.trans` becomes `t` (its orientation is
/// kept); `MaxErr` and `MeanErr` get the largest and the mean distance of
/// the four tips from `c`, in mm.
pub(crate) fn m_tool_tcp_calib(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let index = cx.robot_index(a)?;
    let mut flanges = Vec::with_capacity(4);
    for p in ["Pos1", "Pos2", "Pos3", "Pos4"] {
        let v = cx.req(a, p)?;
        let joints = super::motion::jointtarget(&v)?;
        let t = cx.ask_robot(a, index, |robot| {
            robot
                .calc_robtarget(&joints, &Tool::default(), &WObj::default())
                .map_err(|e| match e {
                    RobotError::Unsupported(_) => RobotError::Unsupported(format!(
                        "MToolTCPCalib ({})",
                        crate::world::NO_KINEMATICS
                    )),
                    e => e,
                })
        })?;
        flanges.push(t.pose.isometry());
    }
    // Unknowns: t (3) then c (3); three equations per position.
    let mut m = DMatrix::<f64>::zeros(12, 6);
    let mut b = DVector::<f64>::zeros(12);
    for (i, f) in flanges.iter().enumerate() {
        let r = f.rotation.to_rotation_matrix();
        for row in 0..3 {
            for col in 0..3 {
                m[(3 * i + row, col)] = r[(row, col)];
            }
            m[(3 * i + row, 3 + row)] = -1.0;
            b[3 * i + row] = -f.translation.vector[row];
        }
    }
    let svd = m.svd(true, true);
    let (low, high) = svd
        .singular_values
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(l, h), &v| (l.min(v), h.max(v)));
    if high <= 0.0 || low / high < 1e-6 {
        return invalid(
            "MToolTCPCalib: the four positions do not determine a TCP (their tool orientations are too alike)",
        );
    }
    let x = match svd.solve(&b, 1e-9) {
        Ok(x) => x,
        Err(e) => return invalid(format!("MToolTCPCalib: {e}")),
    };
    let tcp = Vector3::new(x[0], x[1], x[2]);
    let point = Vector3::new(x[3], x[4], x[5]);
    let errors: Vec<f64> = flanges
        .iter()
        .map(|f| (f.rotation * tcp + f.translation.vector - point).norm())
        .collect();
    let max = errors.iter().copied().fold(0.0, f64::max);
    let mean = errors.iter().sum::<f64>() / errors.len() as f64;
    let place = cx.place_arg(a, "Tool")?;
    let mut tool = cx.m.load(cx.sh, &place)?;
    let trans = Value::pos(tcp.x as f32, tcp.y as f32, tcp.z as f32);
    if let Value::Record { fields, .. } = &mut tool
        && let Some((_, Value::Record { fields: frame, .. })) = fields
            .iter_mut()
            .find(|(n, _)| n.eq_ignore_ascii_case("tframe"))
        && let Some((_, slot)) = frame
            .iter_mut()
            .find(|(n, _)| n.eq_ignore_ascii_case("trans"))
    {
        *slot = trans;
    } else {
        return invalid("MToolTCPCalib: Tool is not a tooldata");
    }
    cx.store(&place, tool)?;
    let max_place = cx.place_arg(a, "MaxErr")?;
    cx.store(&max_place, Value::Num(max as f32))?;
    let mean_place = cx.place_arg(a, "MeanErr")?;
    cx.store(&mean_place, Value::Num(mean as f32))?;
    Ok(Done::Next)
}
