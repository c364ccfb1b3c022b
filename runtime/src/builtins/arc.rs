//! Arc welding (the Arc option): `ArcLStart`, `ArcL`, `ArcLEnd` and their
//! circular forms are moves. A start moves at its speeddata to where the
//! arc ignites; the others weld, at the weld speed of their welddata (its
//! first component in RobotWare 6's layout, in mm/s), else at their
//! speeddata. Not simulated: the welding equipment (arc, wire feed,
//! gas), weaving (it does not change the path's length or time here),
//! seam tracking, and the arc's errors.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::R;

/// `ArcLStart`, `ArcL`, `ArcLEnd`, `ArcCStart`, `ArcC`, `ArcCEnd`.
pub(crate) fn arc_move(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let starts = a.name.to_ascii_lowercase().ends_with("start");
    let speed = if starts { None } else { weld_speed(cx, a)? };
    super::motion::do_move_at(cx, a, "ToPoint", speed)
}

/// The weld speed of the `Weld` argument: its first component when that
/// is a positive number.
fn weld_speed(cx: &mut Cx<'_>, a: &Args) -> R<Option<f64>> {
    let Some(weld) = cx.opt(a, "Weld")? else {
        return Ok(None);
    };
    let first = match &weld {
        Value::Array(items) => items.first(),
        Value::Record { fields, .. } => fields.first().map(|(_, v)| v),
        _ => None,
    };
    Ok(first.and_then(Value::as_f64).filter(|v| *v > 0.0))
}
