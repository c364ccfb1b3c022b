//! Mechanical units (`mecunit` data, the units of the controller's
//! `MOC.cfg`, which the checker holds the program's names to): `ActUnit`,
//! `DeactUnit`, `IsMechUnitActive`. Every unit is active
//! when the run starts (the simulation does not read `MOC.cfg`'s
//! activation at start-up); the state is the controller's, shared by its
//! tasks.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, invalid};

/// The unit a `mecunit` argument names (folded).
fn unit(cx: &mut Cx<'_>, a: &Args) -> R<String> {
    match cx.req(a, "MechUnit")?.field("name") {
        Some(Value::Str(n)) if !n.is_empty() => Ok(n.to_ascii_lowercase()),
        _ => invalid(format!("{}: MechUnit names no mechanical unit", a.name)),
    }
}

/// `ActUnit MechUnit`.
pub(crate) fn act_unit(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let u = unit(cx, a)?;
    cx.sh.inactive_units.retain(|n| *n != u);
    Ok(Done::Next)
}

/// `DeactUnit MechUnit`.
pub(crate) fn deact_unit(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let u = unit(cx, a)?;
    if !cx.sh.inactive_units.contains(&u) {
        cx.sh.inactive_units.push(u);
    }
    Ok(Done::Next)
}

/// `IsMechUnitActive(MechUnit)`.
pub(crate) fn is_mech_unit_active(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let u = unit(cx, a)?;
    Ok(Value::Bool(!cx.sh.inactive_units.contains(&u)))
}
