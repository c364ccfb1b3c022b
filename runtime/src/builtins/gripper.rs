//! The YuMi SmartGripper (the `smartgripper` option): the servo fingers
//! of the task's gripper, as one position from 0 mm (closed) to 25 mm
//! (fully open). The 25 mm is each finger's travel in ROS-Industrial's
//! description of the gripper (OrebroUniversity/yumi,
//! `yumi_description/urdf/yumi_servo_gripper.xacro`: prismatic finger
//! joints from 0 to 0.025 m).
//!
//! What is modelled: the fingers' position after each instruction
//! (`g_Init`, `g_Calibrate`, `g_GripIn`, `g_GripOut`, `g_MoveTo`,
//! `g_JogIn`, `g_JogOut`), read by `g_GetPos`, and whether the gripper is
//! calibrated (`g_IsCalibrated`). What is not: the time the fingers take
//! (they arrive at once), the holding force, an object between the
//! fingers (a grip closes to 0 mm), the suction cups (`g_BlowOn1`,
//! `g_VacuumOn1`... are accepted; their pressure is not simulated).

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::R;

/// The fingers' travel, in mm.
pub(crate) const STROKE: f64 = 25.0;

/// The gripper of a task.
#[derive(Clone, Debug, Default)]
pub(crate) struct Gripper {
    /// The fingers' position, mm from closed.
    pub pos: f64,
    pub calibrated: bool,
}

fn calibrate(cx: &mut Cx<'_>) {
    cx.m.gripper.calibrated = true;
    cx.m.gripper.pos = 0.0;
}

/// `g_Init [\maxSpd] [\holdForce] [\phyLimit] [\Calibrate]`.
pub(crate) fn g_init(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    if a.given("Calibrate") {
        calibrate(cx);
    }
    Ok(Done::Next)
}

/// `g_Calibrate`: the fingers close and their zero is set.
pub(crate) fn g_calibrate(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    calibrate(cx);
    Ok(Done::Next)
}

/// `g_GripIn` and `g_JogIn`: the fingers close (nothing stops them).
pub(crate) fn g_grip_in(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    cx.m.gripper.pos = 0.0;
    Ok(Done::Next)
}

/// `g_GripOut [\holdForce] [\targetPos] [\NoWait]` and `g_JogOut`: the
/// fingers open fully, or to `targetPos`.
pub(crate) fn g_grip_out(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let to = cx.opt_num(a, "targetPos")?.unwrap_or(STROKE);
    cx.m.gripper.pos = to.clamp(0.0, STROKE);
    Ok(Done::Next)
}

/// `g_MoveTo targetPos [\NoWait]`: the fingers go to `targetPos`, within
/// the stroke.
pub(crate) fn g_move_to(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let to = cx.num(a, "targetPos")?;
    cx.m.gripper.pos = to.clamp(0.0, STROKE);
    Ok(Done::Next)
}

/// `g_Stop`, the suction cups' `g_BlowOn1`... : accepted.
pub(crate) fn g_accept(_: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    Ok(Done::Next)
}

/// `g_GetPos()`: the fingers' position in mm.
pub(crate) fn g_get_pos(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Num(cx.m.gripper.pos as f32))
}

/// `g_IsCalibrated()`.
pub(crate) fn g_is_calibrated(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Bool(cx.m.gripper.calibrated))
}
