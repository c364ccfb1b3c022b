//! The robot behind a run, and `--report`: each motion task's arm is the
//! one `rapid check` knows for it (MOC.cfg, else rapid.toml), or the model
//! `--robot` names; a task without one moves as before (moves arrive at
//! once) and a note says so. The report gives the cycle time of each
//! task's entry routine, the time of each routine it called, and the axis
//! that came closest to its limit.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use rapid_runtime::world::{ArmRobot, InstantRobot, Robot};
use rapid_runtime::{Move, RoutineTime};

use super::load::TaskToRun;

/// The arm a motion task moves: `--robot`'s model when given, else the
/// task's (MOC.cfg, rapid.toml). `Err`: why there is none (a note).
pub fn arm_of(task: &TaskToRun, named: Option<&str>) -> Result<rapid_robot::Robot, String> {
    if let Some(name) = named {
        let model = rapid_robot::find_model(name).map_err(|e| format!("--robot: {e}"))?;
        return Ok(rapid_robot::Robot::new(model));
    }
    if let Some(r) = &task.task.robot {
        return Ok(r.robot.clone());
    }
    Err(match &task.task.robot_note {
        Some(why) => format!("the robot is not modelled ({why})"),
        None => "no robot is named (MOC.cfg, rapid.toml [controller] robot or --robot)".to_owned(),
    })
}

/// The robot of a motion task for the controller: the modelled arm, else
/// one whose moves arrive at once.
pub fn robot_of(task: &TaskToRun, named: Option<&str>) -> Box<dyn Robot> {
    match arm_of(task, named) {
        Ok(r) => Box::new(ArmRobot::new(r)),
        Err(_) => Box::new(InstantRobot::new()),
    }
}

/// The arm drawn and listed with the moves (`--plot`, `--trace`, the
/// debugger's path): the one motion task's (none with several).
pub fn drawn_arm(tasks: &[TaskToRun], named: Option<&str>) -> Option<rapid_robot::Robot> {
    let mut arms = tasks
        .iter()
        .filter(|t| t.motion)
        .filter_map(|t| arm_of(t, named).ok());
    let one = arms.next()?;
    arms.next().is_none().then_some(one)
}

/// The notes of a run's motion tasks without an arm, one line each, for a
/// run that moves (`--robot` naming no model is an error, not a note).
pub fn notes(tasks: &[TaskToRun], named: Option<&str>) -> Result<Vec<String>, String> {
    if let Some(name) = named {
        rapid_robot::find_model(name).map_err(|e| format!("--robot: {e}"))?;
        return Ok(Vec::new());
    }
    let several = tasks.iter().filter(|t| t.motion).count() > 1;
    Ok(tasks
        .iter()
        .filter(|t| t.motion)
        .filter_map(|t| arm_of(t, None).err().map(|why| (t, why)))
        .map(|(t, why)| {
            let who = if several {
                format!("{}: ", t.name)
            } else {
                String::new()
            };
            format!("note: {who}{why}: moves take no time and reach every target")
        })
        .collect())
}

/// How close a move's end came to an axis's limit.
#[derive(Clone, Debug, PartialEq)]
pub struct NearLimit {
    /// The move (its index in the trace).
    pub index: usize,
    /// Axis 1 to 6.
    pub axis: usize,
    pub angle: f64,
    pub bound: f64,
    /// Degrees left to the bound.
    pub margin: f64,
}

/// The axis that comes closest to its limit at the end of a move of the
/// task `task` (`None`: every task's moves).
pub fn nearest_limit(
    moves: &[Move],
    limits: &[[f64; 2]; 6],
    task: Option<&str>,
) -> Option<NearLimit> {
    let mut best: Option<NearLimit> = None;
    for (index, m) in moves.iter().enumerate() {
        if task.is_some() && m.task.as_deref() != task {
            continue;
        }
        let Some(joints) = &m.joints else { continue };
        for (i, (a, [lo, hi])) in joints.iter().zip(limits).enumerate() {
            let (bound, margin) = if a - lo < hi - a {
                (*lo, a - lo)
            } else {
                (*hi, hi - a)
            };
            if best.as_ref().is_none_or(|b| margin < b.margin) {
                best = Some(NearLimit {
                    index,
                    axis: i + 1,
                    angle: *a,
                    bound,
                    margin,
                });
            }
        }
    }
    best
}

/// One routine's share of a run: its calls and their total time.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RoutineShare {
    pub calls: usize,
    pub seconds: f64,
}

/// The time of each routine of task `task`, by name in the order first
/// called; a recursive call's time is counted once, in its outermost call.
pub fn routine_shares(times: &[RoutineTime], task: &str) -> Vec<(String, RoutineShare)> {
    let mut order: Vec<String> = Vec::new();
    let mut shares: BTreeMap<String, RoutineShare> = BTreeMap::new();
    let mine: Vec<&RoutineTime> = times.iter().filter(|t| t.task == task).collect();
    let mut by_start = mine.clone();
    by_start.sort_by(|a, b| a.start.total_cmp(&b.start));
    for t in &by_start {
        let key = t.routine.to_ascii_lowercase();
        if !shares.contains_key(&key) {
            order.push(t.routine.clone());
        }
        let inside_own = mine.iter().any(|o| {
            !std::ptr::eq(*o, *t)
                && o.routine.eq_ignore_ascii_case(&t.routine)
                && o.start <= t.start
                && t.end <= o.end
                && (o.start < t.start || t.end < o.end)
        });
        let s = shares.entry(key).or_default();
        s.calls += 1;
        if !inside_own {
            s.seconds += t.end - t.start;
        }
    }
    order
        .into_iter()
        .filter_map(|name| {
            let s = shares.remove(&name.to_ascii_lowercase())?;
            Some((name, s))
        })
        .collect()
}

/// A task `--report` speaks of.
pub struct Reported {
    pub name: String,
    /// Its arm's working ranges (a task with a modelled arm).
    pub limits: Option<[[f64; 2]; 6]>,
    /// Its entry routine.
    pub entry: String,
}

/// The `--report` text: per task, the cycle time of its entry routine, the
/// routines it called and the axis closest to its limit.
pub fn report(tasks: &[Reported], times: &[RoutineTime], moves: &[Move], clock: f64) -> String {
    let mut out = String::new();
    let several = tasks.len() > 1;
    for Reported {
        name,
        limits,
        entry,
    } in tasks
    {
        let shares = routine_shares(times, name);
        let head = if several {
            format!("{name}: ")
        } else {
            String::new()
        };
        let entry_time = shares
            .iter()
            .find(|(r, _)| r.eq_ignore_ascii_case(entry))
            .map(|(_, s)| s.seconds);
        match entry_time {
            Some(t) => {
                let _ = writeln!(out, "{head}cycle time of {entry}: {t:.3} s");
            }
            None => {
                let _ = writeln!(
                    out,
                    "{head}cycle time of {entry}: it did not return (the run ended at {clock:.3} s)"
                );
            }
        }
        let called: Vec<&(String, RoutineShare)> = shares
            .iter()
            .filter(|(r, _)| !r.eq_ignore_ascii_case(entry))
            .collect();
        if !called.is_empty() {
            let width = called
                .iter()
                .map(|(r, _)| r.len())
                .max()
                .unwrap_or(7)
                .max(7);
            let _ = writeln!(out, "  {:<width$}  calls  seconds", "routine");
            for (r, s) in called {
                let _ = writeln!(out, "  {r:<width$}  {:>5}  {:>7.3}", s.calls, s.seconds);
            }
        }
        let task = several.then_some(name.as_str());
        match limits.and_then(|l| nearest_limit(moves, &l, task)) {
            Some(n) => {
                let m = &moves[n.index];
                let what = match &m.target {
                    Some(t) => format!("{} {t}", m.instruction),
                    None => m.instruction.clone(),
                };
                let _ = writeln!(
                    out,
                    "{head}closest to a limit: axis {} at {:.2} degrees, {:.2} from its limit {:.2} ({what}, {}:{})",
                    n.axis, n.angle, n.margin, n.bound, m.at.path, m.at.line
                );
            }
            None if limits.is_some() => {
                let _ = writeln!(out, "{head}closest to a limit: no move");
            }
            None => {}
        }
    }
    out
}
