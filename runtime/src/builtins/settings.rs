//! A task's motion settings: `VelSet`, `AccSet` and `SpeedRefresh`, which
//! every move request carries ([`MotionSettings`]), and `C_MOTSET`, where
//! the program reads them back.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, fault, named_error};
use crate::world::Speed;

/// A task's motion settings, from the program's start at their defaults.
/// `VelSet Override, Max` scales every programmed speed (the speeddata's,
/// `\V`, and `\T` by stretching the time) and caps the TCP speed at
/// `Max` mm/s; `SpeedRefresh Override` scales again, as the program's own
/// speed override, from the next move on (a move under way keeps its
/// time: the simulation plans each move when it is asked for). `AccSet
/// Acc, Ramp` scales the accelerations by `Acc` (below 20 %, 20 %).
#[derive(Clone, Copy, Debug)]
pub(crate) struct MotionSettings {
    /// `VelSet`'s Override, percent.
    pub vel_override: f64,
    /// `VelSet`'s Max, mm/s (`None`: no cap).
    pub max_tcp: Option<f64>,
    /// `SpeedRefresh`'s Override, percent.
    pub refresh: f64,
    /// `AccSet`'s Acc, percent.
    pub acc: f64,
}

impl Default for MotionSettings {
    fn default() -> Self {
        MotionSettings {
            vel_override: 100.0,
            max_tcp: None,
            refresh: 100.0,
            acc: 100.0,
        }
    }
}

impl MotionSettings {
    fn factor(&self) -> f64 {
        self.vel_override / 100.0 * self.refresh / 100.0
    }

    /// No move can go: an override or the TCP cap is 0.
    pub(super) fn halts(&self) -> bool {
        self.factor() <= 0.0 || self.max_tcp.is_some_and(|m| m <= 0.0)
    }

    /// A TCP speed (mm/s) as the settings make it.
    pub(super) fn tcp(&self, v: f64) -> f64 {
        let v = v * self.factor();
        self.max_tcp.map_or(v, |max| v.min(max))
    }

    pub(super) fn apply(&self, s: Speed) -> Speed {
        let k = self.factor();
        Speed {
            v_tcp: self.tcp(s.v_tcp),
            v_ori: s.v_ori * k,
            v_leax: s.v_leax * k,
            v_reax: s.v_reax * k,
        }
    }

    /// A move's programmed time (`\T`) as the settings stretch it.
    pub(super) fn stretch(&self, t: f64) -> f64 {
        t / self.factor()
    }
}

/// `VelSet Override, Max`; `C_MOTSET.vel` reads them back.
pub(crate) fn vel_set(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (over, max) = (cx.num(a, "Override")?, cx.num(a, "Max")?);
    cx.m.settings.vel_override = over.max(0.0);
    cx.m.settings.max_tcp = Some(max.max(0.0));
    motset(cx, "vel", &[("oride", over), ("max", max)]);
    Ok(Done::Next)
}

/// Sets components of a component of `C_MOTSET`, the motion settings a
/// program reads.
fn motset(cx: &mut Cx<'_>, part: &str, values: &[(&str, f64)]) {
    let Some(g) = cx.m.prog.system_global("C_MOTSET") else {
        return;
    };
    let Some(part) =
        cx.m.globals
            .get_mut(g as usize)
            .and_then(|v| v.field_mut(part))
    else {
        return;
    };
    for (name, value) in values {
        if let Some(slot) = part.field_mut(name) {
            *slot = Value::Num(*value as f32);
        }
    }
}

/// `AccSet Acc, Ramp [\FinePointRamp]`: `Acc` percent of the normal
/// accelerations, at least 20 and at most 100; `Ramp` (the jerk) is not
/// modelled; `C_MOTSET.acc` reads them back.
pub(crate) fn acc_set(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (acc, ramp) = (cx.num(a, "Acc")?, cx.num(a, "Ramp")?);
    cx.m.settings.acc = acc.clamp(20.0, 100.0);
    motset(cx, "acc", &[("acc", acc), ("ramp", ramp)]);
    Ok(Done::Next)
}

/// `SpeedRefresh Override`: 0 to 100 percent, else
/// `ERR_SPEED_REFRESH_LIM`.
pub(crate) fn speed_refresh(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let over = cx.num(a, "Override")?;
    if !(0.0..=100.0).contains(&over) {
        return fault(named_error(
            &cx.m.prog,
            "ERR_SPEED_REFRESH_LIM",
            format!("SpeedRefresh: the override {over} is outside 0 to 100 percent"),
        ));
    }
    cx.m.settings.refresh = over;
    Ok(Done::Next)
}

/// `CSpeedOverride([\CTask])`: the speed override in percent. The
/// operator's (the pendant's, without `\CTask`) is always 100 in the
/// simulation; the task's (`\CTask`) is what `SpeedRefresh` last set.
pub(crate) fn c_speed_override(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let over = if a.given("CTask") {
        cx.m.settings.refresh
    } else {
        100.0
    };
    Ok(Value::Num(over as f32))
}

/// `SpeedLimAxis MechUnit, AxisNo, AxisSpeed` and `SpeedLimCheckPoint
/// RobSpeed`: the speeds the controller keeps to while it limits speed
/// (a speed-limiting input or SafeMove). The simulation never limits
/// speed that way, so the robot keeps its programmed speeds; the setting
/// is traced.
pub(crate) fn speed_limit(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (what, speed) = if a.name.eq_ignore_ascii_case("SpeedLimAxis") {
        let axis = cx.num(a, "AxisNo")?;
        (format!("axis {axis}"), cx.num(a, "AxisSpeed")?)
    } else {
        ("the check points".to_owned(), cx.num(a, "RobSpeed")?)
    };
    if speed < 0.0 {
        return fault(named_error(
            &cx.m.prog,
            "ERR_ARGVALERR",
            format!("{}: a speed limit of {speed} is negative", a.name),
        ));
    }
    cx.trace(&format!(
        "{}: {what} at most {speed} while the controller limits speed, which the simulation never does",
        a.name
    ));
    Ok(Done::Next)
}
