//! The `reach` tool: the joint solutions of a target for the task's robot.
//!
//! The task and its robot are `rapid check`'s ([`crate::check::load_in`]:
//! the same `rapid.toml`, `MOC.cfg`, extra paths and grouping), the target,
//! tool and work object are evaluated in the task as `rapid eval --file`
//! evaluates ([`crate::eval::Expression`]), and the geometry is the robot
//! crate's: every solution within the working ranges, and the one a move
//! gets ([`rapid_robot::Robot::move_to`], what `rapid check` reports on).

use std::path::PathBuf;

use rapid_analyzer::consteval::EnvOptions;
use rapid_analyzer::robot::RobotSource;
use rapid_analyzer::task::Task;
use rapid_evaluator::{Type, Value};
use rapid_robot::frames::{self, Tool, WObj};
use rapid_robot::{Conf, ReachError, Robot, Solution};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::roots::{Confined, resolve};
use super::{Answer, shown};
use crate::check::{CheckArgs, load_in};
use crate::eval::{Expression, Failure, place};

/// The arguments of `reach`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ReachParams {
    /// A module (names resolve as inside it, with the rest of its task) or
    /// a task's folder (its global data).
    pub path: String,
    /// The robtarget: a name the task declares (`pPick`), a literal
    /// (`[[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]`), or
    /// any constant expression (`Offs(pPick, 0, 0, 100)`).
    pub target: String,
    /// The tool: a tooldata of the task, or a literal; default `tool0`.
    pub tool: Option<String>,
    /// The work object: a wobjdata of the task, or a literal; default
    /// `wobj0`.
    pub wobj: Option<String>,
    /// The robot (`IRB 120-3/0.58`, or MOC.cfg's `ROB1_120_0.58_3`) for a
    /// task whose MOC.cfg and rapid.toml name none.
    pub robot: Option<String>,
    /// Configuration monitoring (`ConfL\On`, `ConfJ\On`: the controller's
    /// default): the target's confdata selects the solution. With `false`,
    /// the solution nearest all axes at zero.
    pub conf_monitoring: Option<bool>,
}

/// A confdata.
#[derive(Debug, Serialize, JsonSchema)]
pub struct ConfInfo {
    pub cf1: i32,
    pub cf4: i32,
    pub cf6: i32,
    pub cfx: i32,
}

impl From<Conf> for ConfInfo {
    fn from(c: Conf) -> ConfInfo {
        ConfInfo {
            cf1: c.cf1,
            cf4: c.cf4,
            cf6: c.cf6,
            cfx: c.cfx,
        }
    }
}

/// The robot a task's moves are made by.
#[derive(Debug, Serialize, JsonSchema)]
pub struct RobotInfo {
    /// ABB's name of the model (`IRB 120-3/0.58`).
    pub name: String,
    /// Where it is named: `MOC.cfg`, `rapid.toml` or `argument`.
    pub source: String,
    /// In words (`MOC.cfg ROB_1 (ROB1_120_0.58_3)`).
    pub origin: String,
    /// Each axis's working range, degrees (MOC.cfg's or rapid.toml's bounds,
    /// else the data sheet's).
    pub limits: Vec<[f64; 2]>,
    /// The base frame in the world: position (mm) and orientation
    /// (q1..q4), MOC.cfg's; identity otherwise.
    pub base_position: [f64; 3],
    pub base_orientation: [f64; 4],
}

/// The target, as the controller reads it.
#[derive(Debug, Serialize, JsonSchema)]
pub struct TargetInfo {
    /// The expression given.
    pub expression: String,
    /// The TCP in the work object, mm.
    pub position: [f64; 3],
    /// q1..q4.
    pub orientation: [f64; 4],
    pub conf: ConfInfo,
}

/// One joint position that puts the TCP on the target.
#[derive(Debug, Serialize, JsonSchema)]
pub struct SolutionInfo {
    /// Axes 1 to 6, degrees.
    pub joints: [f64; 6],
    /// Its confdata.
    pub conf: ConfInfo,
}

/// Why a move to the target fails, as the controller says it.
#[derive(Debug, Serialize, JsonSchema)]
pub struct ReachFailure {
    /// `out_of_reach`, `joint_limit` or `configuration`.
    pub kind: String,
    /// The rule of `rapid check` that reports it (E601, E602, W601).
    pub rule: String,
    /// The controller's event number and title (50050 Position outside
    /// reach, 50080 Position not compatible).
    pub event: u32,
    pub title: String,
    /// The error `CalcJointT` raises (ERR_OUTSIDE_REACH, ERR_ROBLIMIT).
    pub rapid_error: String,
    pub message: String,
    /// Out of reach: by how much the wrist is, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub by_mm: Option<f64>,
    /// Beyond a working range: the axis (1 to 6), its angle, the bound it
    /// passes and by how much, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axis: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bound: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub by_degrees: Option<f64>,
    /// Another configuration: the nearest one that reaches the target.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reachable_conf: Option<ConfInfo>,
}

/// The answer of `reach`.
#[derive(Debug, Serialize, JsonSchema)]
pub struct ReachReport {
    /// The task's folder.
    pub task: String,
    pub robot: RobotInfo,
    pub target: TargetInfo,
    /// The tool and work object, as given (`tool0`, `wobj0` by default).
    pub tool: String,
    pub wobj: String,
    pub conf_monitoring: bool,
    /// Every joint solution within the working ranges, by configuration.
    pub solutions: Vec<SolutionInfo>,
    /// The index in `solutions` of the one a move to the target uses (with
    /// configuration monitoring, the one the target's confdata selects);
    /// absent when the move fails.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub selected: Option<usize>,
    /// Why the move fails.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<ReachFailure>,
    /// Data whose initial value was used (VAR and PERS data).
    pub initial_values: Vec<String>,
}

pub fn reach(roots: &[PathBuf], params: ReachParams) -> Result<Answer<ReachReport>, String> {
    let path = resolve(roots, &params.path)?;
    let env = Confined::new(roots.to_vec());
    let args = CheckArgs {
        paths: vec![path.clone()],
        ..CheckArgs::default()
    };
    let mut notes = Vec::new();
    let (mut loaded, files) = load_in(&env, &args, &mut notes)?;
    let (task, at) = place(&env, &path, &mut loaded.workspace, &files, &loaded.read)
        .map_err(|m| format!("{}: {m}", params.path))?;
    let (robot, info) = robot_of(&task, params.robot.as_deref())?;

    let mut initial = Vec::new();
    let mut value = |what: &str, text: &str, ty: &str| -> Result<Value, String> {
        let expr = Expression::parse(text).map_err(|f| failure(what, f))?;
        let v = expr
            .value_in(
                &task,
                at,
                Some(&Type::named(ty)),
                EnvOptions::initial_values(),
            )
            .map_err(|f| failure(what, f))?;
        initial.extend(v.initial_values_used);
        Ok(v.value)
    };
    let target = frames::robtarget(&value("target", &params.target, "robtarget")?)
        .map_err(|e| format!("target: {e}"))?;
    let tool = match &params.tool {
        Some(t) => {
            frames::tool(&value("tool", t, "tooldata")?).map_err(|e| format!("tool: {e}"))?
        }
        None => Tool::default(),
    };
    let wobj = match &params.wobj {
        Some(w) => {
            frames::wobj(&value("wobj", w, "wobjdata")?).map_err(|e| format!("wobj: {e}"))?
        }
        None => WObj::default(),
    };
    initial.sort();
    initial.dedup();

    let monitoring = params.conf_monitoring.unwrap_or(true);
    let flange = frames::flange_in_base(&target.pose, &tool, &wobj, &robot.base);
    let mut solutions = robot.solutions(&flange);
    let moved = robot.move_to(&flange, monitoring.then_some(&target.conf));
    let selected = moved.as_ref().ok().map(|s| index_of(&mut solutions, s));
    let t = target.pose.translation.vector;
    let q = target.pose.rotation;
    let report = ReachReport {
        task: shown(roots, std::path::Path::new(&task.key)),
        robot: info,
        target: TargetInfo {
            expression: params.target.trim().to_owned(),
            position: [t.x, t.y, t.z].map(round),
            orientation: [q.w, q.i, q.j, q.k].map(round),
            conf: target.conf.into(),
        },
        tool: params.tool.as_deref().map_or("tool0", str::trim).to_owned(),
        wobj: params.wobj.as_deref().map_or("wobj0", str::trim).to_owned(),
        conf_monitoring: monitoring,
        solutions: solutions
            .iter()
            .map(|s| SolutionInfo {
                joints: s.joints.map(round),
                conf: s.conf.into(),
            })
            .collect(),
        selected,
        error: moved.err().map(|e| failure_of(&e)),
        initial_values: initial,
    };
    Ok(Answer::new(summary(&report), report))
}

/// The robot of `task` (MOC.cfg's, else rapid.toml's), else the one named
/// by the argument; an argument that names another robot than the task's
/// is refused, so the answer is always what `rapid check` computes with.
fn robot_of(task: &Task, asked: Option<&str>) -> Result<(Robot, RobotInfo), String> {
    let asked = match asked {
        Some(name) => Some(rapid_robot::find_model(name).map_err(|why| format!("robot: {why}"))?),
        None => None,
    };
    let (robot, source, origin) = match (&task.robot, &task.robot_note, asked) {
        (Some(r), _, Some(m)) if m.name != r.robot.model.name => {
            return Err(format!(
                "the task's robot is the {} ({}); `robot` ({}) is only for a task without one",
                r.robot.model.name, r.origin, m.name
            ));
        }
        (Some(r), _, _) => {
            let source = match r.source {
                RobotSource::MocCfg => "MOC.cfg",
                RobotSource::Project => "rapid.toml",
            };
            (r.robot.clone(), source, r.origin.clone())
        }
        (None, Some(note), _) => {
            return Err(format!(
                "the task's controller names a robot that is not modelled: {note}"
            ));
        }
        (None, None, Some(m)) => (Robot::new(m), "argument", "the `robot` argument".to_owned()),
        (None, None, None) => {
            return Err(format!(
                "the task {} has no robot: its MOC.cfg and rapid.toml ([controller] robot) name none; give `robot` (e.g. \"IRB 120-3/0.58\")",
                task.key
            ));
        }
    };
    let b = robot.base.translation.vector;
    let q = robot.base.rotation;
    let info = RobotInfo {
        name: robot.model.name.clone(),
        source: source.to_owned(),
        origin,
        limits: robot.limits.0.to_vec(),
        base_position: [b.x, b.y, b.z].map(round),
        base_orientation: [q.w, q.i, q.j, q.k].map(round),
    };
    Ok((robot, info))
}

/// Why an argument has no value, for the answer.
fn failure(what: &str, f: Failure) -> String {
    format!("{what}: {f}")
}

/// The place of `s` in `list`, added when the solver's list lacks it (a
/// split of axes 4 and 6 at the wrist singularity).
fn index_of(list: &mut Vec<Solution>, s: &Solution) -> usize {
    let same = |a: &Solution| {
        a.joints
            .iter()
            .zip(&s.joints)
            .all(|(x, y)| (x - y).abs() < 1e-6)
    };
    match list.iter().position(same) {
        Some(i) => i,
        None => {
            list.push(*s);
            list.len() - 1
        }
    }
}

fn failure_of(e: &ReachError) -> ReachFailure {
    use rapid_analyzer::rules;
    let event = e.event();
    let mut f = ReachFailure {
        kind: String::new(),
        rule: String::new(),
        event: event.number,
        title: event.title.to_owned(),
        rapid_error: e.rapid_error().to_owned(),
        message: e.to_string(),
        by_mm: None,
        axis: None,
        angle: None,
        bound: None,
        by_degrees: None,
        reachable_conf: None,
    };
    let (kind, rule) = match e {
        ReachError::OutOfReach { by } => {
            f.by_mm = Some(round(*by));
            ("out_of_reach", &rules::target_out_of_reach::RULE)
        }
        ReachError::JointLimit {
            axis,
            angle,
            bound,
            by,
            ..
        } => {
            f.axis = Some(*axis);
            f.angle = Some(round(*angle));
            f.bound = Some(round(*bound));
            f.by_degrees = Some(round(*by));
            ("joint_limit", &rules::joint_out_of_range::RULE)
        }
        ReachError::Configuration { found, .. } => {
            f.reachable_conf = Some(found.conf.into());
            ("configuration", &rules::configuration_mismatch::RULE)
        }
    };
    f.kind = kind.to_owned();
    f.rule = rule.code.to_owned();
    f
}

/// Six decimals: what a robtarget holds, without the last bits' noise.
fn round(x: f64) -> f64 {
    let r = (x * 1e6).round() / 1e6;
    if r == 0.0 { 0.0 } else { r }
}

fn summary(r: &ReachReport) -> String {
    let c = |c: &ConfInfo| format!("[{},{},{},{}]", c.cf1, c.cf4, c.cf6, c.cfx);
    let p = &r.target.position;
    let mut out = format!(
        "{} ({}), task {}\ntarget {} at [{}, {}, {}] conf {}, tool {}, wobj {}{}\n",
        r.robot.name,
        r.robot.origin,
        r.task,
        r.target.expression,
        p[0],
        p[1],
        p[2],
        c(&r.target.conf),
        r.tool,
        r.wobj,
        if r.conf_monitoring {
            ""
        } else {
            " (configuration monitoring off)"
        }
    );
    if let Some(e) = &r.error {
        out.push_str(&format!(
            "a move there fails: {} (event {} {}; {}; rapid check {})\n",
            e.message, e.event, e.title, e.rapid_error, e.rule
        ));
    }
    match r.solutions.len() {
        0 => out.push_str("no joint solution within the working ranges\n"),
        n => out.push_str(&format!(
            "{n} joint solution{} within the working ranges (axes 1-6, degrees):\n",
            super::check::plural(n)
        )),
    }
    for (i, s) in r.solutions.iter().enumerate() {
        let j: Vec<String> = s.joints.iter().map(|a| format!("{a:.2}")).collect();
        let mark = if r.selected == Some(i) {
            if r.conf_monitoring {
                "  <- the target's confdata selects this one"
            } else {
                "  <- a move uses this one"
            }
        } else {
            ""
        };
        out.push_str(&format!("  [{}] conf {}{mark}\n", j.join(", "), c(&s.conf)));
    }
    out
}
