//! The controller's configuration and identity: `ReadCfgData`,
//! `WriteCfgData` (the system parameters of the backup's `SYSPAR` files,
//! changed in the run's memory only), `GetSysInfo`, `IsSysId` and
//! `GetModalPayloadMode`, through the
//! controller's [`crate::world::System`].

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, fault, invalid, named_error};
use crate::world::{CfgError, CfgValue};

fn cfg_error<T>(cx: &Cx<'_>, a: &Args, e: CfgError) -> R<T> {
    fault(named_error(
        &cx.m.prog,
        e.error,
        format!("{}: {}", a.name, e.message),
    ))
}

fn ill_type<T>(cx: &Cx<'_>, a: &Args, message: String) -> R<T> {
    cfg_error(
        cx,
        a,
        CfgError {
            error: "ERR_CFG_ILLTYPE",
            message,
        },
    )
}

/// `ReadCfgData InstancePath, Attribute, CfgData [\ListNo]`: the
/// attribute's value into `CfgData` (a `num`, `dnum`, `bool` or `string`,
/// as the attribute's type); with `\ListNo`, the `ListNo`th instance of a
/// search, and `ListNo` becomes the next one's number (`END_OF_LIST`, -1,
/// after the last).
pub(crate) fn read_cfg_data(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let path = cx.string(a, "InstancePath")?;
    let attribute = cx.string(a, "Attribute")?;
    let to = cx.place_arg(a, "CfgData")?;
    let list = cx.opt_place(a, "ListNo")?;
    let list_no = match &list {
        Some(p) => match cx.m.load(cx.sh, p)? {
            Value::Num(n) => Some(n as i64),
            other => {
                return invalid(format!(
                    "ReadCfgData: \\ListNo must be a num, not {}",
                    crate::machine::describe(&other)
                ));
            }
        },
        None => None,
    };
    let (value, next) = match cx.sh.system.read(&path, &attribute, list_no) {
        Ok(r) => r,
        Err(e) => match arm_bound(cx, &path, &attribute) {
            Some(bound) => (CfgValue::Text(bound.to_string()), None),
            None => return cfg_error(cx, a, e),
        },
    };
    let old = cx.m.load(cx.sh, &to)?;
    let what = format!("{path} {attribute}");
    let v = match (&old, &value) {
        (Value::Num(_), CfgValue::Text(t)) => match t.trim().parse::<f64>() {
            Ok(x) => Value::Num(x as f32),
            Err(_) => return ill_type(cx, a, format!("{what} is {t:?}, not a number")),
        },
        (Value::Dnum(_), CfgValue::Text(t)) => match t.trim().parse::<f64>() {
            Ok(x) => Value::Dnum(x),
            Err(_) => return ill_type(cx, a, format!("{what} is {t:?}, not a number")),
        },
        (Value::Str(_), CfgValue::Text(t)) => Value::Str(t.clone()),
        (Value::Bool(_), CfgValue::Flag(b)) => Value::Bool(*b),
        (Value::Bool(_), CfgValue::Text(t)) if t.eq_ignore_ascii_case("true") => Value::Bool(true),
        (Value::Bool(_), CfgValue::Text(t)) if t.eq_ignore_ascii_case("false") => {
            Value::Bool(false)
        }
        (old, value) => {
            return ill_type(
                cx,
                a,
                format!(
                    "{what} ({}) does not go into {}",
                    match value {
                        CfgValue::Text(t) => format!("{t:?}"),
                        CfgValue::Flag(_) => "a flag".to_owned(),
                    },
                    crate::machine::describe(old)
                ),
            );
        }
    };
    cx.store(&to, v)?;
    if let (Some(p), Some(n)) = (&list, next) {
        cx.store(p, Value::Num(n as f32))?;
    }
    Ok(Done::Next)
}

/// A modelled arm's working range where the configuration has no `ARM`
/// instance for it (a program kept without its `MOC.cfg`):
/// `/MOC/ARM/rob1_3` `upper_joint_bound` (or `lower_joint_bound`) is axis
/// 3 of the first robot's range, in radians, as `MOC.cfg` gives it.
fn arm_bound(cx: &Cx<'_>, path: &str, attribute: &str) -> Option<f64> {
    let parts: Vec<&str> = path.trim_start_matches('/').split('/').collect();
    let [domain, kind, instance] = parts.as_slice() else {
        return None;
    };
    if !domain.eq_ignore_ascii_case("MOC") || !kind.eq_ignore_ascii_case("ARM") {
        return None;
    }
    let (robot, axis) = instance
        .get(..3)
        .filter(|h| h.eq_ignore_ascii_case("rob"))
        .and(instance.get(3..))?
        .split_once('_')?;
    let (robot, axis): (usize, usize) = (robot.parse().ok()?, axis.parse().ok()?);
    let side = if attribute.eq_ignore_ascii_case("upper_joint_bound") {
        1
    } else if attribute.eq_ignore_ascii_case("lower_joint_bound") {
        0
    } else {
        return None;
    };
    // ROB_n: the nth task that moves a robot.
    let arm = cx.sh.robots.iter().flatten().nth(robot.checked_sub(1)?)?;
    let range = arm.joint_limits()?.get(axis.checked_sub(1)?)?[side];
    Some(range.to_radians())
}

/// `WriteCfgData InstancePath, Attribute, CfgData [\ListNo]`: sets the
/// attribute (a `num`, `dnum`, `bool` or `string`) in the simulated
/// configuration; a later `ReadCfgData` reads it. A `bool` sets or
/// removes a flag attribute (`-Invert`), else is written `TRUE`/`FALSE`.
pub(crate) fn write_cfg_data(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let path = cx.string(a, "InstancePath")?;
    let attribute = cx.string(a, "Attribute")?;
    let list_no = cx.opt_num(a, "ListNo")?.map(|n| n as i64);
    let data = cx.req(a, "CfgData")?;
    let value = match cx.m.scalar(cx.sh, data)? {
        Value::Num(x) => CfgValue::Text(rapid_evaluator::format_num(x)),
        Value::Dnum(x) => CfgValue::Text(rapid_evaluator::format_dnum(x)),
        Value::Str(s) => CfgValue::Text(s),
        Value::Bool(b) => match cx.sh.system.read(&path, &attribute, list_no) {
            Ok((CfgValue::Text(_), _)) => {
                CfgValue::Text(if b { "TRUE" } else { "FALSE" }.to_owned())
            }
            _ => CfgValue::Flag(b),
        },
        other => {
            return ill_type(
                cx,
                a,
                format!(
                    "{path} {attribute}: {} is not a num, dnum, bool or string",
                    crate::machine::describe(&other)
                ),
            );
        }
    };
    match cx.sh.system.write(&path, &attribute, value, list_no) {
        Ok(()) => Ok(Done::Next),
        Err(e) => cfg_error(cx, a, e),
    }
}

/// `GetSysInfo(\SerialNo | \SWVersion | \SWVersionName | \RobotType |
/// \CtrlId | \LanIp | \CtrlLang | \SystemName)`: what the backup says of
/// its controller, else the simulated (virtual) controller's answer
/// ([`crate::world::System::sys_info`]).
pub(crate) fn get_sys_info(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    const SWITCHES: [&str; 8] = [
        "SerialNo",
        "SWVersion",
        "SWVersionName",
        "RobotType",
        "CtrlId",
        "LanIp",
        "CtrlLang",
        "SystemName",
    ];
    let Some(switch) = SWITCHES.iter().find(|s| a.given(s)) else {
        return invalid("GetSysInfo: no switch says what to return");
    };
    Ok(Value::Str(cx.sh.system.sys_info(switch)))
}

/// `IsSysId(SystemId)`: is this controller's system the one with that
/// serial number (`GetSysInfo(\SerialNo)`)? FALSE when neither the backup
/// nor `rapid.toml` says the serial number.
pub(crate) fn is_sys_id(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let id = cx.string(a, "SystemId")?;
    let serial = cx.sh.system.sys_info("SerialNo");
    Ok(Value::Bool(!serial.is_empty() && serial == id))
}

/// `GetModalPayloadMode()`: `SYS.cfg`'s `ModalPayLoadMode` (`SYS_MISC`),
/// 1 (payloads set with `GripLoad`) when the backup does not set it, as
/// the controller's default is.
pub(crate) fn get_modal_payload_mode(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    let mode = cx
        .sh
        .system
        .read("SYS/SYS_MISC/ModalPayLoadMode", "Value", None)
        .ok()
        .and_then(|(v, _)| match v {
            CfgValue::Text(t) => t.trim().parse::<f32>().ok(),
            CfgValue::Flag(_) => None,
        });
    Ok(Value::Num(mode.unwrap_or(1.0)))
}

/// `PPMovedInManMode()`: whether the operator moved the program pointer in
/// manual mode; nobody moves it in a simulated run.
pub(crate) fn pp_moved_in_man_mode(_: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Bool(false))
}
