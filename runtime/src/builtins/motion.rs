//! Motion: the move instructions hand the task's robot
//! ([`crate::world::Robot`]) what a real arm needs, in the robot's own
//! data ([`crate::world::RobTarget`]...); the task waits for a move that
//! takes time (unless `\Conc`). `CRobT`, `CPos`, `CJointT`, `CalcJointT`
//! and `CalcRobT` ask the robot. With tracing on, each move is recorded in
//! world coordinates (through the work object).

use rapid_evaluator::Value;
use rapid_evaluator::geometry::{iso_of, orient_value, pos_value};

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, R, Wait, fault, invalid, named_error};
use crate::world::{
    JointTarget, MoveKind, MoveRequest, MoveTarget, Pose, RobTarget, Robot, RobotError, Speed,
    Tool, WObj, Zone,
};

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
    /// The robot axes at the move's end, in degrees: the robot's solution
    /// (a robot with a kinematic model), else `MoveAbsJ`'s target.
    pub joints: Option<Vec<f64>>,
    /// When the move starts and ends, simulated seconds.
    pub start: f64,
    pub end: f64,
    /// The TCP speed (`v_tcp`, mm/s) and its data's name.
    pub speed: Option<f64>,
    pub speed_name: Option<String>,
    /// The zone's name (`fine`, `z10`), or its size in mm.
    pub zone: Option<String>,
    pub tool: Option<String>,
    pub wobj: Option<String>,
    /// The task that moved (when several run).
    pub task: Option<String>,
}

fn num(v: Option<&Value>, name: &str) -> f64 {
    v.and_then(|v| v.field(name))
        .and_then(Value::as_f64)
        .unwrap_or(0.0)
}

pub(crate) fn nums<const N: usize>(v: Option<&Value>, names: [&str; N]) -> [f64; N] {
    let mut out = [0.0; N];
    for (slot, n) in out.iter_mut().zip(names) {
        *slot = num(v, n);
    }
    out
}

const EXTAX: [&str; 6] = ["eax_a", "eax_b", "eax_c", "eax_d", "eax_e", "eax_f"];

impl Cx<'_> {
    /// A pose from a record with `trans` and `rot` (pose, robtarget), its
    /// orientation checked as the controller checks it (`ERR_ILLQUAT`).
    pub(super) fn pose(&self, v: &Value) -> R<Pose> {
        let iso = iso_of(v).or_else(|e| self.m.eval_error(e))?;
        Ok(Pose::from_isometry(&iso))
    }

    pub(super) fn robtarget(&self, v: &Value) -> R<RobTarget> {
        Ok(RobTarget {
            pose: self.pose(v)?,
            robconf: nums(v.field("robconf"), ["cf1", "cf4", "cf6", "cfx"]),
            extax: nums(v.field("extax"), EXTAX),
        })
    }

    pub(super) fn tool(&mut self, a: &Args, param: &str) -> R<Tool> {
        match self.opt(a, param)? {
            Some(v) => self.tool_of(&v),
            None => Ok(Tool::default()),
        }
    }

    /// A `tooldata` value as motion needs it.
    pub(super) fn tool_of(&self, v: &Value) -> R<Tool> {
        Ok(Tool {
            robhold: !matches!(v.field("robhold"), Some(Value::Bool(false))),
            tframe: match v.field("tframe") {
                Some(f) => self.pose(f)?,
                None => Pose::IDENTITY,
            },
            mass: num(v.field("tload"), "mass"),
            cog: nums(
                v.field("tload").and_then(|l| l.field("cog")),
                ["x", "y", "z"],
            ),
        })
    }

    /// The work object of `\WObj` (`wobj0` when absent) with the task's
    /// program displacement: positions are in the displaced frame.
    pub(super) fn wobj(&mut self, a: &Args) -> R<WObj> {
        let v = self.opt(a, "WObj")?;
        self.displaced(v.as_ref())
    }

    /// A work object value (`wobj0` for `None`) with the task's program
    /// displacement.
    fn displaced(&mut self, v: Option<&Value>) -> R<WObj> {
        let mut w = self.wobj_of(v)?;
        if let Some(disp) = super::displacement::active(self)? {
            w.oframe = w.oframe.then(&disp);
        }
        Ok(w)
    }

    /// The work object of `\WObj`, without the program displacement.
    pub(super) fn object_frame(&mut self, a: &Args) -> R<WObj> {
        let v = self.opt(a, "WObj")?;
        self.wobj_of(v.as_ref())
    }

    /// A `wobjdata` value as motion needs it (`wobj0` for `None`).
    fn wobj_of(&self, v: Option<&Value>) -> R<WObj> {
        let Some(v) = v else {
            return Ok(WObj::default());
        };
        let frame = |cx: &Self, name: &str| match v.field(name) {
            Some(f) => cx.pose(f),
            None => Ok(Pose::IDENTITY),
        };
        Ok(WObj {
            robhold: matches!(v.field("robhold"), Some(Value::Bool(true))),
            ufprog: !matches!(v.field("ufprog"), Some(Value::Bool(false))),
            ufmec: match v.field("ufmec") {
                Some(Value::Str(s)) => s.clone(),
                _ => String::new(),
            },
            uframe: frame(self, "uframe")?,
            oframe: frame(self, "oframe")?,
        })
    }

    /// The index of the task `\TaskRef`/`\TaskName` names (`None` when
    /// neither is given), `ERR_TASKNAME` when the controller has none.
    pub(super) fn named_task(&mut self, a: &Args) -> R<Option<usize>> {
        let other = match self.opt(a, "TaskName")? {
            Some(Value::Str(n)) => Some(n),
            _ => match self.opt(a, "TaskRef")? {
                Some(v) => match v.field("name") {
                    Some(Value::Str(n)) => n.strip_suffix("id").map(str::to_owned),
                    _ => None,
                },
                None => None,
            },
        };
        match other {
            Some(name) => match self.sh.task_named(&name) {
                Some(i) => Ok(Some(i)),
                None => fault(named_error(
                    &self.m.prog,
                    "ERR_TASKNAME",
                    format!("{}: {}", a.name, self.sh.no_such_task(&name)),
                )),
            },
            None => Ok(None),
        }
    }

    /// The robot of the task, or of the one `\TaskRef`/`\TaskName` names.
    pub(super) fn robot_index(&mut self, a: &Args) -> R<usize> {
        let index = match self.named_task(a)? {
            Some(i) => i,
            None => self.m.number.saturating_sub(1),
        };
        match self.sh.robots.get(index) {
            Some(Some(_)) => Ok(index),
            _ => invalid(format!(
                "{}: the task {} moves no robot",
                a.name,
                self.sh.names.get(index).map_or("", String::as_str)
            )),
        }
    }

    /// Asks the robot `index` (from [`Self::robot_index`]) `ask`: a robot's
    /// error is raised as the controller raises it.
    pub(super) fn ask_robot<T>(
        &self,
        a: &Args,
        index: usize,
        ask: impl FnOnce(&dyn Robot) -> Result<T, RobotError>,
    ) -> R<T> {
        let r = match self.sh.robots.get(index).and_then(Option::as_ref) {
            Some(robot) => ask(robot.as_ref()),
            None => return invalid("the task moves no robot"),
        };
        r.or_else(|e| self.robot_error(a, e))
    }

    fn robot_error<T>(&self, a: &Args, e: RobotError) -> R<T> {
        match e {
            RobotError::Unsupported(m) => fault(FaultKind::Unsupported(m)),
            RobotError::OutOfReach(m) => fault(named_error(
                &self.m.prog,
                "ERR_OUTSIDE_REACH",
                format!("{}: {m}", a.name),
            )),
            RobotError::JointLimit { message, .. } => fault(named_error(
                &self.m.prog,
                "ERR_ROBLIMIT",
                format!("{}: {message}", a.name),
            )),
            e @ RobotError::Stop { .. } => fault(FaultKind::Motion(e.to_string())),
            RobotError::Other(m) => invalid(format!("{}: {m}", a.name)),
        }
    }
}

pub(super) fn robtarget_value(t: &RobTarget) -> R<Value> {
    let (trans, rot) = (t.pose.trans, t.pose.rot);
    let pos = pos_value(&rapid_evaluator::nalgebra::Vector3::new(
        trans[0], trans[1], trans[2],
    ));
    let q = rapid_evaluator::geometry::isometry([0.0; 3], rot).rotation;
    let (Ok(pos), Ok(rot)) = (pos, orient_value(&q, false)) else {
        return invalid("the robot's position is outside the range of num");
    };
    let record = |ty: &str, names: &[&str], values: &[f64]| Value::Record {
        ty: ty.to_owned(),
        fields: names
            .iter()
            .zip(values)
            .map(|(n, v)| ((*n).to_owned(), Value::Num(*v as f32)))
            .collect(),
    };
    Ok(Value::Record {
        ty: "robtarget".to_owned(),
        fields: vec![
            ("trans".to_owned(), pos),
            ("rot".to_owned(), rot),
            (
                "robconf".to_owned(),
                record("confdata", &["cf1", "cf4", "cf6", "cfx"], &t.robconf),
            ),
            ("extax".to_owned(), record("extjoint", &EXTAX, &t.extax)),
        ],
    })
}

fn jointtarget_value(j: &JointTarget) -> Value {
    let record = |ty: &str, names: &[&str], values: &[f64]| Value::Record {
        ty: ty.to_owned(),
        fields: names
            .iter()
            .zip(values)
            .map(|(n, v)| ((*n).to_owned(), Value::Num(*v as f32)))
            .collect(),
    };
    Value::Record {
        ty: "jointtarget".to_owned(),
        fields: vec![
            (
                "robax".to_owned(),
                record(
                    "robjoint",
                    &["rax_1", "rax_2", "rax_3", "rax_4", "rax_5", "rax_6"],
                    &j.robax,
                ),
            ),
            ("extax".to_owned(), record("extjoint", &EXTAX, &j.extax)),
        ],
    }
}

pub(crate) fn jointtarget(v: &Value) -> R<JointTarget> {
    if v.field("robax").is_none() {
        return invalid("not a jointtarget");
    }
    Ok(JointTarget {
        robax: nums(
            v.field("robax"),
            ["rax_1", "rax_2", "rax_3", "rax_4", "rax_5", "rax_6"],
        ),
        extax: nums(v.field("extax"), EXTAX),
    })
}

fn kind_of(instruction: &str) -> MoveKind {
    let lower = instruction.to_ascii_lowercase();
    if lower.ends_with("absj") {
        MoveKind::AbsoluteJoint
    } else if lower.starts_with("arcc")
        || lower.contains('c') && (lower.ends_with('c') || lower.ends_with("cdo"))
    {
        MoveKind::Circular
    } else if lower.ends_with('j') || lower.ends_with("jdo") {
        MoveKind::Joint
    } else {
        MoveKind::Linear
    }
}

/// When the task's robot ends its last move.
pub(crate) fn motion_end(cx: &Cx<'_>) -> f64 {
    cx.sh
        .motion_until
        .get(cx.m.number.saturating_sub(1))
        .copied()
        .unwrap_or(0.0)
}

/// Makes a move: the robot is asked, the move recorded, and the task waits
/// for a move that takes time (unless `\Conc`).
pub(super) fn do_move(cx: &mut Cx<'_>, a: &Args, target_param: &str) -> R<Done> {
    do_move_at(cx, a, target_param, None)
}

/// A move, its TCP speed `v_tcp` (mm/s) instead of its speeddata's when
/// given (a weld's speed).
pub(crate) fn do_move_at(
    cx: &mut Cx<'_>,
    a: &Args,
    target_param: &str,
    v_tcp: Option<f64>,
) -> R<Done> {
    if a.is_star(target_param) {
        return fault(FaultKind::Unsupported(format!(
            "{} * (a target stored in the instruction, not in the program)",
            a.name
        )));
    }
    let kind = kind_of(a.name);
    let to_value = cx.req(a, target_param)?;
    let external_only = a.name.eq_ignore_ascii_case("MoveExtJ");
    let to = if kind == MoveKind::AbsoluteJoint || external_only {
        match jointtarget(&to_value) {
            Ok(j) if external_only => MoveTarget::ExternalAxes(j.extax),
            Ok(j) => MoveTarget::Joints(j),
            Err(_) => {
                return invalid(format!("{}: {target_param} is not a jointtarget", a.name));
            }
        }
    } else {
        if to_value.field("trans").is_none() {
            return invalid(format!("{}: {target_param} is not a robtarget", a.name));
        }
        MoveTarget::Cartesian(cx.robtarget(&to_value)?)
    };
    let via = match cx.opt(a, "CirPoint")? {
        Some(c) => Some(cx.robtarget(&c)?),
        None => None,
    };
    let speed_value = cx.opt(a, "Speed")?;
    let zone_value = cx.opt(a, "Zone")?;
    let speed = Speed {
        v_tcp: v_tcp.unwrap_or_else(|| num(speed_value.as_ref(), "v_tcp")),
        v_ori: num(speed_value.as_ref(), "v_ori"),
        v_leax: num(speed_value.as_ref(), "v_leax"),
        v_reax: num(speed_value.as_ref(), "v_reax"),
    };
    let zone = Zone {
        finep: zone_value
            .as_ref()
            .is_none_or(|z| matches!(z.field("finep"), Some(Value::Bool(true)))),
        pzone_tcp: num(zone_value.as_ref(), "pzone_tcp"),
        pzone_ori: num(zone_value.as_ref(), "pzone_ori"),
        pzone_eax: num(zone_value.as_ref(), "pzone_eax"),
        zone_ori: num(zone_value.as_ref(), "zone_ori"),
        zone_leax: num(zone_value.as_ref(), "zone_leax"),
        zone_reax: num(zone_value.as_ref(), "zone_reax"),
    };
    // Read once: the move's tool and work object become the active ones.
    let tool_value = cx.opt(a, "Tool")?;
    let wobj_value = cx.opt(a, "WObj")?;
    let tool = match &tool_value {
        Some(v) => cx.tool_of(v)?,
        None => Tool::default(),
    };
    let wobj = cx.displaced(wobj_value.as_ref())?;
    let settings = cx.m.settings;
    if settings.halts() {
        // The robot would stand until another task refreshes the override;
        // the simulation plans each move when it is asked for.
        return fault(FaultKind::Unsupported(format!(
            "{} while the speed override (VelSet, SpeedRefresh) holds the robot at 0",
            a.name
        )));
    }
    let speed = settings.apply(speed);
    let time = cx.opt_num(a, "T")?.map(|t| settings.stretch(t));
    let velocity = cx.opt_num(a, "V")?.map(|v| settings.tcp(v));
    let conc = a.given("Conc");
    let index = cx.robot_index(a)?;
    let start = cx.now().max(motion_end(cx));
    let request = MoveRequest {
        instruction: a.name,
        kind,
        to,
        via,
        speed,
        time,
        velocity,
        accel: settings.acc / 100.0,
        zone,
        tool,
        wobj: wobj.clone(),
        conc,
        at: start,
    };
    let result = match cx.sh.robots.get_mut(index).and_then(Option::as_mut) {
        Some(robot) => robot.move_to(&request),
        None => return invalid(format!("{}: the task moves no robot", a.name)),
    };
    let motion = match result {
        Ok(m) => m,
        Err(e) => return cx.robot_error(a, e),
    };
    let end = start + motion.duration.max(0.0);
    cx.sh.move_count += 1;
    if !external_only {
        cx.m.active_names = [
            tool_value.as_ref().and_then(|_| cx.arg_name(a, "Tool")),
            wobj_value.as_ref().and_then(|_| cx.arg_name(a, "WObj")),
        ];
        cx.m.active = [tool_value, wobj_value];
    }
    let delay = end - cx.now();
    super::zones::supervise(cx, index, &request.tool, delay, None)?;
    if let Some(slot) = cx.sh.motion_until.get_mut(index) {
        *slot = end;
    }
    if cx.sh.trace {
        let mut m = record(
            cx,
            a,
            target_param,
            &request,
            speed_value.as_ref(),
            zone_value.as_ref(),
        );
        if let Some(j) = motion.joints {
            m.joints = Some(j.robax.to_vec());
        }
        m.start = start;
        m.end = end;
        cx.sh.moves.push(m);
    }
    if end > cx.now() && !conc {
        let level = cx.sh.paths.get(index).map_or(0, |p| p.level);
        return Ok(Done::Wait(Box::new(Wait::motion(
            index,
            level,
            format!("{} (the robot moves)", a.name),
        ))));
    }
    Ok(Done::Next)
}

/// A move as the trace records it, in world coordinates (its times are
/// the caller's).
fn record(
    cx: &mut Cx<'_>,
    a: &Args,
    target_param: &str,
    request: &MoveRequest<'_>,
    speed: Option<&Value>,
    zone: Option<&Value>,
) -> Move {
    let frame = request.wobj.frame();
    let (pos, orient, joints) = match &request.to {
        MoveTarget::Cartesian(t) => {
            let world = frame.then(&t.pose);
            (Some(world.trans), Some(world.rot), None)
        }
        MoveTarget::Joints(j) => (None, None, Some(j.robax.to_vec())),
        MoveTarget::ExternalAxes(_) => (None, None, None),
    };
    let zone_name = cx.arg_name(a, "Zone").or_else(|| {
        let z = zone?;
        if matches!(z.field("finep"), Some(Value::Bool(true))) {
            return Some("fine".to_owned());
        }
        z.field("pzone_tcp")
            .and_then(Value::as_f64)
            .map(|z| format!("{z} mm"))
    });
    Move {
        instruction: a.name.to_owned(),
        target: cx.arg_name(a, target_param),
        at: cx.m.location().unwrap_or_else(|| cx.m.prog.location(0, 0)),
        pos,
        orient,
        via: request.via.map(|v| frame.then(&v.pose).trans),
        joints,
        speed: speed.and_then(|s| s.field("v_tcp")).and_then(Value::as_f64),
        speed_name: cx.arg_name(a, "Speed"),
        zone: zone_name,
        tool: cx.arg_name(a, "Tool"),
        wobj: cx.arg_name(a, "WObj"),
        task: (cx.sh.names.len() > 1).then(|| cx.m.name.clone()),
        start: 0.0,
        end: 0.0,
    }
}

/// `MoveL`, `MoveJ`, `MoveC` and the `Trigg` moves.
pub(crate) fn move_to_point(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    do_move(cx, a, "ToPoint")
}

/// `MoveLDO`, `MoveJDO`, `MoveCDO` (and the `AO`, `GO` ones): the move,
/// and the signal set when the robot reaches `ToPoint` (the middle of its
/// zone, which the simulation takes as the move's end).
pub(crate) fn move_do(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = cx.req(a, "Signal")?;
    let (name, _) = cx.m.signal_of(cx.sh, &s)?;
    let v = cx.num(a, "Value")?;
    let done = do_move(cx, a, "ToPoint")?;
    let delay = motion_end(cx) - cx.now();
    let robot = cx.m.number.saturating_sub(1);
    cx.sh.set_signal_on_path(robot, &name, v, delay);
    Ok(done)
}

/// `MoveLSync`, `MoveJSync`, `MoveCSync`: the move, and the procedure
/// `ProcName` names called when the robot reaches `ToPoint` (the middle
/// of its zone, taken as the move's end): the task waits for the move,
/// then runs the procedure, then goes on.
pub(crate) fn move_sync(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    // The statement and call depth, so that a call left pending by an
    // error during the move is not made by another instruction.
    let here = (cx.m.frames.len(), cx.m.location());
    if let Some((id, at)) = cx.m.sync_call.take()
        && at == here
    {
        return Ok(Done::Call(id));
    }
    let name = cx.string(a, "ProcName")?;
    let id = super::data::procedure_named(cx, &name)?;
    match do_move(cx, a, "ToPoint")? {
        Done::Wait(w) => {
            // When the move ends the instruction runs again, to call.
            cx.m.sync_call = Some((id, here));
            cx.m.again();
            Ok(Done::Wait(w))
        }
        _ => Ok(Done::Call(id)),
    }
}

/// `MoveAbsJ ToJointPos, ...`, and `MoveExtJ ToJointPos, ...` (its
/// external axes only).
pub(crate) fn move_abs_j(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    do_move(cx, a, "ToJointPos")
}

/// `WaitRob [\InPos] | [\ZeroSpeed]`: until the robot stands still.
pub(crate) fn wait_rob(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    let index = cx.m.number.saturating_sub(1);
    let path = cx.sh.paths.get(index).copied().unwrap_or_default();
    if motion_end(cx) <= cx.now() && !path.holds(path.level) {
        return Ok(Done::Next);
    }
    Ok(Done::Wait(Box::new(Wait::motion(
        index,
        path.level,
        "WaitRob (the robot moves)".to_owned(),
    ))))
}

/// Motion settings that do not change where the robot goes.
pub(crate) fn setting(_: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    Ok(Done::Next)
}

/// `ConfL` and `ConfJ` `\On` | `\Off`: the robot keeps the targets'
/// confdata or not.
pub(crate) fn conf(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let linear = a.name.eq_ignore_ascii_case("ConfL");
    let on = !a.given("Off");
    let index = cx.m.number.saturating_sub(1);
    if let Some(Some(robot)) = cx.sh.robots.get_mut(index) {
        robot.set_conf(linear, on);
    }
    Ok(Done::Next)
}

/// `CRobT([\TaskRef] | [\TaskName] [\Tool] [\WObj])`: where the TCP is
/// now, during a move too.
pub(crate) fn c_rob_t(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let index = cx.robot_index(a)?;
    let tool = cx.tool(a, "Tool")?;
    let wobj = cx.wobj(a)?;
    let now = cx.now();
    let t = cx.ask_robot(a, index, |robot| robot.robtarget_at(&tool, &wobj, now))?;
    robtarget_value(&t)
}

/// `CPos([\Tool] [\WObj])`.
pub(crate) fn c_pos(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let t = c_rob_t(cx, a)?;
    Ok(t.field("trans")
        .cloned()
        .unwrap_or(Value::pos(0.0, 0.0, 0.0)))
}

/// `CTool()`: the tool of the last move (`tool0` before any).
pub(crate) fn c_tool(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    active(cx, 0, "tool0")
}

/// `CWObj()`: the work object of the last move (`wobj0` before any, or
/// when the move named none).
pub(crate) fn c_wobj(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    active(cx, 1, "wobj0")
}

fn active(cx: &mut Cx<'_>, which: usize, default: &str) -> R<Value> {
    if let Some(v) = cx.m.active.get(which).cloned().flatten() {
        return Ok(v);
    }
    let place = cx.system_place(default)?;
    cx.m.load(cx.sh, &place)
}

/// `SetSysData SourceObject [\ObjectName]`: the tool or work object
/// becomes the active one (`CTool`, `CWObj`, an output zone's TCP), as if
/// a move had used it; `\ObjectName` names the data object instead (of
/// `SourceObject`'s type). A payload (`loaddata`) changes nothing the
/// simulation models.
pub(crate) fn set_sys_data(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let source = cx.req(a, "SourceObject")?;
    let (value, name) = match cx.opt_string(a, "ObjectName")? {
        Some(name) => {
            let place = super::data::data_named(cx, &name)?;
            (cx.m.load(cx.sh, &place)?, Some(name))
        }
        None => (source.clone(), cx.arg_name(a, "SourceObject")),
    };
    match source.type_name().map(str::to_ascii_lowercase).as_deref() {
        Some("tooldata") => {
            cx.m.active[0] = Some(value);
            cx.m.active_names[0] = name;
        }
        Some("wobjdata") => {
            cx.m.active[1] = Some(value);
            cx.m.active_names[1] = name;
        }
        Some("loaddata") => cx.m.active_load = Some((value, name)),
        _ => {
            return invalid(format!(
                "SetSysData: SourceObject must be a tooldata, wobjdata or loaddata, not {}",
                crate::machine::describe(&source)
            ));
        }
    }
    Ok(Done::Next)
}

/// `GetSysData DestObject [\ObjectName]`: the active tool, work object or
/// payload (by `DestObject`'s type: the last move's, or what `SetSysData`
/// set; `tool0`, `wobj0`, `load0` before any) into `DestObject`, and its
/// name into `\ObjectName` (empty when the simulation does not know it).
pub(crate) fn get_sys_data(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let dest = cx.place_arg(a, "DestObject")?;
    let current = cx.m.load(cx.sh, &dest)?;
    let kind = current.type_name().map(str::to_ascii_lowercase);
    let (value, name) = match kind.as_deref() {
        Some("tooldata") => (active(cx, 0, "tool0")?, active_name(cx, 0, "tool0")),
        Some("wobjdata") => (active(cx, 1, "wobj0")?, active_name(cx, 1, "wobj0")),
        Some("loaddata") => match cx.m.active_load.clone() {
            Some((v, n)) => (v, n.unwrap_or_default()),
            None => {
                let place = cx.system_place("load0")?;
                (cx.m.load(cx.sh, &place)?, "load0".to_owned())
            }
        },
        _ => {
            return invalid(format!(
                "GetSysData: DestObject must be a tooldata, wobjdata or loaddata, not {}",
                crate::machine::describe(&current)
            ));
        }
    };
    cx.store(&dest, value)?;
    if let Some(p) = a.place_of("ObjectName").cloned() {
        cx.store(&p, Value::Str(name))?;
    }
    Ok(Done::Next)
}

/// The name of the active tool (0) or work object (1).
fn active_name(cx: &Cx<'_>, which: usize, default: &str) -> String {
    match cx.m.active.get(which) {
        Some(Some(_)) => {
            cx.m.active_names
                .get(which)
                .cloned()
                .flatten()
                .unwrap_or_default()
        }
        _ => default.to_owned(),
    }
}

/// `CJointT([\TaskRef] | [\TaskName])`.
pub(crate) fn c_joint_t(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let index = cx.robot_index(a)?;
    let now = cx.now();
    let j = cx.ask_robot(a, index, |robot| robot.joints_at(now))?;
    Ok(jointtarget_value(&j))
}

/// `CalcJointT(Rob_target, Tool [\WObj])`.
pub(crate) fn calc_joint_t(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let index = cx.robot_index(a)?;
    let target = cx.req(a, "Rob_target")?;
    let target = cx.robtarget(&target)?;
    let tool = cx.tool(a, "Tool")?;
    let wobj = cx.wobj(a)?;
    let j = cx.ask_robot(a, index, |robot| robot.calc_joints(&target, &tool, &wobj))?;
    Ok(jointtarget_value(&j))
}

/// `CalcRobT(Joint_target, Tool [\WObj])`.
pub(crate) fn calc_rob_t(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let index = cx.robot_index(a)?;
    let joints = cx.req(a, "Joint_target")?;
    let joints = jointtarget(&joints)?;
    let tool = cx.tool(a, "Tool")?;
    let wobj = cx.wobj(a)?;
    let t = cx.ask_robot(a, index, |robot| {
        robot.calc_robtarget(&joints, &tool, &wobj)
    })?;
    robtarget_value(&t)
}
