//! Program displacement: `PDispSet`, `PDispOn`, `PDispOff` and `ORobT`.
//!
//! The displacement is the task's `C_PROGDISP.pdisp`, a frame in the work
//! object's object frame. While it is not the identity, every position
//! the task programs or reads (moves, `CRobT`, `CPos`, `CalcJointT`,
//! `CalcRobT`) is in the displaced frame: the object frame, then
//! `pdisp` ([`Cx::wobj`]). External axis offsets (`EOffs*`) are not
//! modelled: the simulated robot has no external axes.

use rapid_evaluator::Value;
use rapid_evaluator::geometry::{iso_of, pose_value, with_frame};
use rapid_evaluator::nalgebra::{Isometry3, Translation3, UnitQuaternion};

use super::{Args, Cx, Done};
use crate::machine::R;
use crate::world::Pose;

/// Where the task keeps its displacement.
const PROGDISP: &str = "C_PROGDISP";

/// The active displacement frame, `None` when there is none (the
/// identity).
pub(crate) fn active(cx: &mut Cx<'_>) -> R<Option<Pose>> {
    let p = cx.system_place(PROGDISP)?;
    let v = cx.m.load(cx.sh, &p)?;
    let Some(disp) = v.field("pdisp") else {
        return Ok(None);
    };
    let iso = match iso_of(disp) {
        Ok(iso) => iso,
        // A zero quaternion: C_PROGDISP before anything set it.
        Err(_) => return Ok(None),
    };
    if iso.translation.vector.norm() == 0.0 && iso.rotation.angle() == 0.0 {
        return Ok(None);
    }
    Ok(Some(Pose::from_isometry(&iso)))
}

/// Makes `iso` the displacement (`C_PROGDISP.pdisp`).
fn set(cx: &mut Cx<'_>, iso: &Isometry3<f64>) -> R<()> {
    let p = cx.system_place(PROGDISP)?;
    let pose = pose_value(iso, false).or_else(|e| cx.m.eval_error(e))?;
    let mut v = cx.m.load(cx.sh, &p)?;
    if let Value::Record { fields, .. } = &mut v {
        match fields
            .iter_mut()
            .find(|(n, _)| n.eq_ignore_ascii_case("pdisp"))
        {
            Some((_, slot)) => *slot = pose,
            None => fields.push(("pdisp".to_owned(), pose)),
        }
    }
    cx.store(&p, v)
}

/// `PDispSet DispFrame`: the displacement is `DispFrame`.
pub(crate) fn p_disp_set(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let frame = cx.req(a, "DispFrame")?;
    let iso = iso_of(&frame).or_else(|e| cx.m.eval_error(e))?;
    set(cx, &iso)?;
    Ok(Done::Next)
}

/// `PDispOff`: no displacement.
pub(crate) fn p_disp_off(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    set(cx, &Isometry3::identity())?;
    Ok(Done::Next)
}

/// `PDispOn [\Rot] [\ExeP] ProgPoint Tool [\WObj]`: the displacement that
/// takes `ProgPoint` to where the robot is (or to `\ExeP`), both in the
/// work object's object frame: a translation, and with `\Rot` the
/// rotation too. It replaces the displacement that was active.
pub(crate) fn p_disp_on(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let prog = cx.req(a, "ProgPoint")?;
    let prog = iso_of(&prog).or_else(|e| cx.m.eval_error(e))?;
    let now = match cx.opt(a, "ExeP")? {
        Some(v) => iso_of(&v).or_else(|e| cx.m.eval_error(e))?,
        None => {
            let index = cx.robot_index(a)?;
            let tool = cx.tool(a, "Tool")?;
            let wobj = cx.object_frame(a)?;
            let t = cx.ask_robot(a, index, |robot| robot.robtarget(&tool, &wobj))?;
            t.pose.isometry()
        }
    };
    let disp = if a.given("Rot") {
        now * prog.inverse()
    } else {
        Isometry3::from_parts(
            Translation3::from(now.translation.vector - prog.translation.vector),
            UnitQuaternion::identity(),
        )
    };
    set(cx, &disp)?;
    Ok(Done::Next)
}

/// `ORobT(OrgPoint [\InPDisp] | [\InEOffs])`: a position in the displaced
/// frame as a position in the object frame (the displacement removed);
/// `\InPDisp` keeps it in the displaced frame. External axes keep their
/// values (no offsets are modelled).
pub(crate) fn o_rob_t(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let point = cx.req(a, "OrgPoint")?;
    let disp = match active(cx)? {
        Some(d) if !a.given("InPDisp") => d.isometry(),
        _ => return Ok(point),
    };
    let iso = disp * iso_of(&point).or_else(|e| cx.m.eval_error(e))?;
    let rot = rapid_evaluator::geometry::orient_value(&iso.rotation, false)
        .or_else(|e| cx.m.eval_error(e))?;
    with_frame(&point, &iso.translation.vector, Some(rot)).or_else(|e| cx.m.eval_error(e))
}
