//! Mechanical units (`mecunit` data, the units of the controller's
//! `MOC.cfg`, which the checker holds the program's names to): `ActUnit`,
//! `DeactUnit`, `IsMechUnitActive`, `GetMecUnitName`, `GetMotorTorque`. Every unit is active
//! when the run starts (the simulation does not read `MOC.cfg`'s
//! activation at start-up); the state is the controller's, shared by its
//! tasks.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, fault, invalid, named_error};

/// The unit the `mecunit` argument `param` names (folded).
fn unit_of(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<String> {
    match cx.req(a, param)?.field("name") {
        Some(Value::Str(n)) if !n.is_empty() => Ok(n.to_ascii_lowercase()),
        _ => invalid(format!("{}: {param} names no mechanical unit", a.name)),
    }
}

/// The unit of the `MechUnit` argument.
fn unit(cx: &mut Cx<'_>, a: &Args) -> R<String> {
    unit_of(cx, a, "MechUnit")
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

/// `GetMecUnitName(MechUnit)`: the unit's name, as the program spells it
/// where it names the unit (the configuration's spelling is not kept).
pub(crate) fn get_mec_unit_name(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    match cx.req(a, "MechUnit")?.field("name") {
        Some(Value::Str(n)) if !n.is_empty() => Ok(Value::Str(n.clone())),
        _ => invalid(format!("{}: MechUnit names no mechanical unit", a.name)),
    }
}

/// `IsMechUnitActive(MechUnit)`.
pub(crate) fn is_mech_unit_active(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let u = unit(cx, a)?;
    Ok(Value::Bool(!cx.sh.inactive_units.contains(&u)))
}

/// `GetMotorTorque([\MecUnit,] AxisNo)`: the torque of an axis's motor.
/// The simulation has no dynamics model (no masses, no loads, no
/// friction), so every motor reads 0 Nm, as a robot at rest with its
/// weight balanced would; the axis number is checked (1 to 6).
pub(crate) fn get_motor_torque(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    if a.given("MecUnit") {
        unit_of(cx, a, "MecUnit")?;
    }
    let axis = cx.num(a, "AxisNo")?;
    if axis.fract() != 0.0 || !(1.0..=6.0).contains(&axis) {
        return fault(named_error(
            &cx.m.prog,
            "ERR_AXIS_PAR",
            format!("GetMotorTorque: there is no axis {axis}"),
        ));
    }
    Ok(Value::Num(0.0))
}
