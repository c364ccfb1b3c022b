//! Motion: moves complete at once and leave the robot at their target,
//! which `CRobT`, `CPos` and `CJointT` then read; with tracing on, each
//! move is recorded in world coordinates (through the work object).

use rapid_evaluator::Value;

use super::Args;
use crate::machine::{Machine, R, fault, invalid, named_error};

/// A move as a trace records it.
#[derive(Clone, Debug, PartialEq)]
pub struct Move {
    /// `MoveL`, `MoveJ`, `MoveC`, `MoveAbsJ`, `SearchL`...
    pub instruction: String,
    /// The target's name when the argument names data (`p10`).
    pub target: Option<String>,
    pub at: crate::Location,
    /// The TCP's position and orientation in world coordinates (not known
    /// for `MoveAbsJ`, which gives joint angles).
    pub pos: Option<[f64; 3]>,
    pub orient: Option<[f64; 4]>,
    /// The circle point of `MoveC`, in world coordinates.
    pub via: Option<[f64; 3]>,
    /// The robot axes of `MoveAbsJ`, in degrees.
    pub joints: Option<Vec<f64>>,
    /// The TCP speed (`v_tcp`, mm/s) and its data's name.
    pub speed: Option<f64>,
    pub speed_name: Option<String>,
    /// The zone's name (`fine`, `z10`), or its size in mm.
    pub zone: Option<String>,
    pub tool: Option<String>,
    pub wobj: Option<String>,
}

type Pose = ([f64; 3], [f64; 4]);

const IDENTITY: Pose = ([0.0; 3], [1.0, 0.0, 0.0, 0.0]);

fn nums<const N: usize>(v: Option<&Value>, names: [&str; N]) -> Option<[f64; N]> {
    let v = v?;
    let mut out = [0.0; N];
    for (slot, n) in out.iter_mut().zip(names) {
        *slot = v.field(n)?.as_f64()?;
    }
    Some(out)
}

fn pos_of(v: Option<&Value>) -> Option<[f64; 3]> {
    nums(v, ["x", "y", "z"])
}

fn quat_of(v: Option<&Value>) -> Option<[f64; 4]> {
    let q = nums(v, ["q1", "q2", "q3", "q4"])?;
    let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    if n < 1e-9 {
        return Some([1.0, 0.0, 0.0, 0.0]);
    }
    Some(q.map(|x| x / n))
}

/// A pose from a record with `trans` and `rot` (pose, robtarget).
fn pose_of(v: &Value) -> Option<Pose> {
    Some((pos_of(v.field("trans"))?, quat_of(v.field("rot"))?))
}

fn qmul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let p = qmul(
        qmul(q, [0.0, v[0], v[1], v[2]]),
        [q[0], -q[1], -q[2], -q[3]],
    );
    [p[1], p[2], p[3]]
}

/// `a` then `b` (b expressed in a's frame).
fn compose(a: Pose, b: Pose) -> Pose {
    let t = rotate(a.1, b.0);
    (
        [a.0[0] + t[0], a.0[1] + t[1], a.0[2] + t[2]],
        qmul(a.1, b.1),
    )
}

fn inverse(a: Pose) -> Pose {
    let qi = [a.1[0], -a.1[1], -a.1[2], -a.1[3]];
    let t = rotate(qi, a.0);
    ([-t[0], -t[1], -t[2]], qi)
}

/// The frame of a work object in world coordinates (user frame, then
/// object frame).
fn wobj_frame(w: Option<&Value>) -> Pose {
    let Some(w) = w else {
        return IDENTITY;
    };
    let u = w.field("uframe").and_then(pose_of).unwrap_or(IDENTITY);
    let o = w.field("oframe").and_then(pose_of).unwrap_or(IDENTITY);
    compose(u, o)
}

fn tool_frame(t: Option<&Value>) -> Pose {
    t.and_then(|t| t.field("tframe"))
        .and_then(pose_of)
        .unwrap_or(IDENTITY)
}

fn speed_of(v: Option<&Value>) -> Option<f64> {
    v?.field("v_tcp")?.as_f64()
}

fn zone_of(m: &Machine, a: &Args<'_>, v: Option<&Value>) -> Option<String> {
    if let Some(name) = m.arg_name(a, "Zone") {
        return Some(name);
    }
    let v = v?;
    if matches!(v.field("finep"), Some(Value::Bool(true))) {
        return Some("fine".to_owned());
    }
    v.field("pzone_tcp")
        .and_then(Value::as_f64)
        .map(|z| format!("{z} mm"))
}

/// Moves to a robtarget (`ToPoint`, or `CirPoint` too for a circle).
fn move_to(m: &mut Machine, a: &Args<'_>, target: &str) -> R<()> {
    if a.is_star(target) {
        return fault(crate::machine::FaultKind::Unsupported(format!(
            "{} * (a target stored in the instruction, not in the program)",
            a.name
        )));
    }
    let to = m.req(a, target)?;
    let Some(local) = pose_of(&to) else {
        return invalid(format!("{}: {target} is not a robtarget", a.name));
    };
    let wobj = m.opt(a, "WObj")?;
    let tool = m.opt(a, "Tool")?;
    let frame = wobj_frame(wobj.as_ref());
    let world = compose(frame, local);
    let via = match m.opt(a, "CirPoint")? {
        Some(c) => pose_of(&c).map(|p| compose(frame, p).0),
        None => None,
    };
    m.ctl.robot.tcp = world;
    m.ctl.robot.tool = tool;
    m.ctl.robot.robconf = to.field("robconf").cloned();
    m.ctl.robot.extax = to.field("extax").cloned();
    record(m, a, target, Some(world), via, None)
}

/// Records a move for the trace (with [`crate::Config::trace`]); the
/// speed and zone arguments are evaluated in any case.
fn record(
    m: &mut Machine,
    a: &Args<'_>,
    target: &str,
    world: Option<Pose>,
    via: Option<[f64; 3]>,
    joints: Option<Vec<f64>>,
) -> R<()> {
    // Evaluated with or without a trace, so that a run fails the same way.
    let speed = m.opt(a, "Speed")?;
    let zone = m.opt(a, "Zone")?;
    if !m.config.trace {
        return Ok(());
    }
    let record = crate::Move {
        instruction: a.name.to_owned(),
        target: m.arg_name(a, target),
        at: m.here().unwrap_or_else(|| m.prog.location(0, 0)),
        pos: world.map(|w| w.0),
        orient: world.map(|w| w.1),
        via,
        joints,
        speed: speed_of(speed.as_ref()),
        speed_name: m.arg_name(a, "Speed"),
        zone: zone_of(m, a, zone.as_ref()),
        tool: m.arg_name(a, "Tool"),
        wobj: m.arg_name(a, "WObj"),
    };
    m.ctl.moves.push(record);
    Ok(())
}

/// `MoveL`, `MoveJ`, `MoveC` and the `Trigg` moves.
pub(crate) fn move_to_point(m: &mut Machine, a: &Args<'_>) -> R<()> {
    move_to(m, a, "ToPoint")
}

/// `MoveLDO`, `MoveJDO`, `MoveCDO`: the move, then the signal set.
pub(crate) fn move_do(m: &mut Machine, a: &Args<'_>) -> R<()> {
    move_to(m, a, "ToPoint")?;
    let s = m.req(a, "Signal")?;
    let name = m.signal_of(&s)?.name.clone();
    let v = m.num(a, "Value")?;
    m.ctl.set_signal_value(&name, v);
    Ok(())
}

/// `MoveAbsJ ToJointPos, ...`: the joints are recorded; the TCP is not
/// computed (no kinematic model), so `CRobT` keeps the last Cartesian
/// position.
pub(crate) fn move_abs_j(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let to = m.req(a, "ToJointPos")?;
    let joints = nums(
        to.field("robax"),
        ["rax_1", "rax_2", "rax_3", "rax_4", "rax_5", "rax_6"],
    );
    if joints.is_none() {
        return invalid("MoveAbsJ: ToJointPos is not a jointtarget");
    }
    m.ctl.robot.joints = Some(to);
    record(m, a, "ToJointPos", None, None, joints.map(|j| j.to_vec()))
}

/// `SearchL`, `SearchJ`, `SearchC`: the search hits when its signal is 1
/// as the robot reaches `ToPoint` (script the signal with `--set`); the
/// hit position is then `ToPoint`. Without a hit, `ERR_WHLSEARCH`.
pub(crate) fn search(m: &mut Machine, a: &Args<'_>) -> R<()> {
    move_to(m, a, "ToPoint")?;
    let s = m.req(a, "Signal")?;
    let hit = m.signal_value(&s)? == 1.0;
    if !hit {
        return fault(named_error(
            &m.prog,
            "ERR_WHLSEARCH",
            format!("{}: the search signal never became 1", a.name),
        ));
    }
    let to = m.req(a, "ToPoint")?;
    let p = m.place_arg(a, "SearchPoint")?;
    m.store(&p, to)
}

/// Motion settings that do not change where the robot goes.
pub(crate) fn setting(_: &mut Machine, _: &Args<'_>) -> R<()> {
    Ok(())
}

/// The current TCP as a robtarget in the given tool and work object.
fn current(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let tool = m.opt(a, "Tool")?;
    let wobj = m.opt(a, "WObj")?;
    let flange = compose(
        m.ctl.robot.tcp,
        inverse(tool_frame(m.ctl.robot.tool.as_ref())),
    );
    let tcp = compose(flange, tool_frame(tool.as_ref()));
    let (p, q) = compose(inverse(wobj_frame(wobj.as_ref())), tcp);
    let zero = m
        .prog
        .types
        .zero(&rapid_evaluator::Type::named("robtarget"));
    let robconf = m
        .ctl
        .robot
        .robconf
        .clone()
        .or_else(|| zero.field("robconf").cloned())
        .unwrap_or(Value::Num(0.0));
    let extax = m.ctl.robot.extax.clone().unwrap_or_else(|| Value::Record {
        ty: "extjoint".to_owned(),
        fields: ["eax_a", "eax_b", "eax_c", "eax_d", "eax_e", "eax_f"]
            .iter()
            .map(|n| ((*n).to_owned(), Value::Num(9e9)))
            .collect(),
    });
    Ok(Value::Record {
        ty: "robtarget".to_owned(),
        fields: vec![
            (
                "trans".to_owned(),
                Value::pos(p[0] as f32, p[1] as f32, p[2] as f32),
            ),
            (
                "rot".to_owned(),
                Value::orient([q[0] as f32, q[1] as f32, q[2] as f32, q[3] as f32]),
            ),
            ("robconf".to_owned(), robconf),
            ("extax".to_owned(), extax),
        ],
    })
}

/// `CRobT([\Tool] [\WObj])`.
pub(crate) fn c_rob_t(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    current(m, a)
}

/// `CPos([\Tool] [\WObj])`.
pub(crate) fn c_pos(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let t = current(m, a)?;
    Ok(t.field("trans")
        .cloned()
        .unwrap_or(Value::pos(0.0, 0.0, 0.0)))
}

/// `CJointT()`: the joints of the last `MoveAbsJ` (zero before any).
pub(crate) fn c_joint_t(m: &mut Machine, _: &Args<'_>) -> R<Value> {
    Ok(m.ctl.robot.joints.clone().unwrap_or_else(|| {
        m.prog
            .types
            .zero(&rapid_evaluator::Type::named("jointtarget"))
    }))
}
