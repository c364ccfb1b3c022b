//! Mechanical units (`mecunit` data, the units of the controller's
//! `MOC.cfg`, which the checker holds the program's names to): `ActUnit`,
//! `DeactUnit`, `IsMechUnitActive`, `GetMecUnitName`, `GetNextMechUnit`,
//! `GetMotorTorque`. Every unit is active
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

/// The controller's mechanical units in order: `MOC.cfg`'s, else `ROB_1`...
/// a robot for each motion task.
fn controller_units(cx: &Cx<'_>) -> Vec<crate::world::MechUnit> {
    let units = cx.sh.system.mechanical_units();
    if !units.is_empty() {
        return units;
    }
    (1..=cx.sh.robots.iter().filter(|r| r.is_some()).count().max(1))
        .map(|n| crate::world::MechUnit {
            name: format!("ROB_{n}"),
            tcp_robot: true,
            axes: 6,
        })
        .collect()
}

/// `GetNextMechUnit(ListNumber, UnitName [\MecRef] [\TCPRob] [\NoOfAxes]
/// [\MecTaskNo] [\MotPlanNo] [\Active])`: unit number `ListNumber` (from
/// 0) of the controller's list, `MOC.cfg`'s mechanical units in order
/// (without one, `ROB_1`... a robot for each motion task), its name and
/// what the optional arguments ask; `ListNumber` counts on. FALSE, and an
/// empty name, past the last. Which task and motion planner run a unit
/// the simulation does not know: `\MecTaskNo` and `\MotPlanNo` stop it.
pub(crate) fn get_next_mech_unit(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    for unknown in ["MecTaskNo", "MotPlanNo"] {
        if a.given(unknown) {
            return fault(crate::machine::FaultKind::Unsupported(format!(
                "GetNextMechUnit \\{unknown}"
            )));
        }
    }
    let units = controller_units(cx);
    let list = cx.place_arg(a, "ListNumber")?;
    let n = cx.num(a, "ListNumber")?;
    let name = cx.place_arg(a, "UnitName")?;
    let found = (n >= 0.0 && n.fract() == 0.0)
        .then(|| units.get(n as usize))
        .flatten()
        .cloned();
    cx.store(&list, Value::Num((n + 1.0) as f32))?;
    let Some(unit) = found else {
        cx.store(&name, Value::Str(String::new()))?;
        return Ok(Value::Bool(false));
    };
    cx.store(&name, Value::Str(unit.name.clone()))?;
    let active = !cx
        .sh
        .inactive_units
        .contains(&unit.name.to_ascii_lowercase());
    let outputs = [
        (
            "MecRef",
            Value::Record {
                ty: "mecunit".to_owned(),
                fields: vec![("name".to_owned(), Value::Str(unit.name.clone()))],
            },
        ),
        ("TCPRob", Value::Bool(unit.tcp_robot)),
        ("NoOfAxes", Value::Num(unit.axes as f32)),
        ("Active", Value::Bool(active)),
    ];
    for (param, value) in outputs {
        if let Some(p) = cx.opt_place(a, param)? {
            cx.store(&p, value)?;
        }
    }
    Ok(Value::Bool(true))
}

/// `RobName()`: the name of the robot the task moves (`MOC.cfg`'s TCP
/// robot of its turn among the motion tasks, else `ROB_1`...), an empty
/// string for a task that moves none.
pub(crate) fn rob_name(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    let me = cx.m.number.saturating_sub(1);
    if !matches!(cx.sh.robots.get(me), Some(Some(_))) {
        return Ok(Value::Str(String::new()));
    }
    let turn = cx.sh.robots[..me].iter().filter(|r| r.is_some()).count();
    let unit = controller_units(cx)
        .into_iter()
        .filter(|u| u.tcp_robot)
        .nth(turn);
    // A motion task past the configured robots: the default name.
    Ok(Value::Str(
        unit.map_or_else(|| format!("ROB_{}", turn + 1), |u| u.name),
    ))
}
