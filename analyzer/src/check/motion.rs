//! Moves checked against the task's robot: for each move instruction whose
//! target, tool and work object are constants or persistents (their
//! declared values), the joint solution the controller would use, and the
//! rules `target-out-of-reach`, `joint-out-of-range` and
//! `configuration-mismatch` where there is none.
//!
//! Not cached with the statement: the answer depends on the task's robot
//! and on `ConfL\Off`/`ConfJ\Off` anywhere in the task, which a
//! statement's key does not hold. It runs only in tasks with a robot.

use rapid_evaluator::{Options, Type, Value};
use rapid_robot::frames::{self, RobTarget, Tool, WObj};
use rapid_robot::{ReachError, Robot, Solution, violation};
use tree_sitter::Node;

use super::Cx;
use crate::consteval::{EnvOptions, is_builtin_call, with_env};
use crate::rules::{self, Selection};
use crate::sema::def::Def;
use crate::sema::signature::{Signature, Target};
use crate::syntax::{field, kind};
use crate::syntax_util::field;
use crate::task::{Task, Unit};

/// Does the task turn configuration monitoring off for linear (`ConfL`)
/// and joint (`ConfJ`) moves anywhere?
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct ConfOff {
    linear: bool,
    joint: bool,
}

fn conf_off_in(text: &str) -> ConfOff {
    let lower = text.to_ascii_lowercase();
    let mut out = ConfOff::default();
    for (at, _) in lower.match_indices("conf") {
        let rest = &lower[at + 4..];
        let (joint, after) = match rest.as_bytes().first() {
            Some(b'l') => (false, &rest[1..]),
            Some(b'j') => (true, &rest[1..]),
            _ => continue,
        };
        if after.trim_start().starts_with("\\off") {
            if joint {
                out.joint = true;
            } else {
                out.linear = true;
            }
        }
    }
    out
}

fn conf_off(cx: &mut Cx<'_>) -> ConfOff {
    if let Some(c) = cx.conf_off {
        return c;
    }
    let mut c = ConfOff::default();
    for (_, u) in cx.task.live_units() {
        let o = conf_off_in(&u.text);
        c.linear |= o.linear;
        c.joint |= o.joint;
    }
    cx.conf_off = Some(c);
    c
}

/// Where a move's target puts the robot: its flange through the work
/// object's frames, the tool's TCP and the robot's base; a joint solution
/// in any configuration within the working ranges, then (`use_conf`: the
/// configuration is monitored) in the target's `confdata`.
pub fn reach_target(
    robot: &Robot,
    target: &RobTarget,
    tool: &Tool,
    wobj: &WObj,
    use_conf: bool,
) -> Result<Solution, ReachError> {
    let flange = frames::flange_in_base(&target.pose, tool, wobj, &robot.base);
    robot.move_to(&flange, use_conf.then_some(&target.conf))
}

/// One target of a move as the check judged it ([`move_reaches`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MoveReach {
    /// The target as written (`pPick`, `Offs(pPick, 0, 0, 50)`).
    pub target: String,
    /// The instruction (`MoveL`).
    pub instruction: String,
    /// The unit and byte offset of the target.
    pub unit: usize,
    pub offset: usize,
    /// The joint solution the controller would use, or why there is none.
    pub result: Result<Solution, ReachError>,
}

/// Every move target in the units of `task` that `wanted` lets through,
/// whose target, tool and work object have known values, with what the
/// task's robot makes of it: the check of `target-out-of-reach`,
/// `joint-out-of-range` and `configuration-mismatch` run with a log (none
/// without a robot).
pub fn move_reaches(task: &Task, wanted: &dyn Fn(&Unit) -> bool) -> Vec<MoveReach> {
    if task.robot.is_none() {
        return Vec::new();
    }
    let mine = [
        &rules::target_out_of_reach::RULE,
        &rules::joint_out_of_range::RULE,
        &rules::configuration_mismatch::RULE,
    ];
    let selection = Selection::of(|r| mine.iter().any(|m| m.code == r.code));
    let mut out = Vec::new();
    for (i, unit) in task.units.iter().enumerate() {
        if !wanted(unit) {
            continue;
        }
        let mut cx = Cx::new(task, i, unit);
        cx.selection = selection.clone();
        cx.reaches = Some(Vec::new());
        cx.check();
        out.extend(cx.reaches.take().unwrap_or_default());
    }
    out
}

/// Is this a joint move (configuration monitored by `ConfJ`)?
fn is_joint_move(name: &str) -> bool {
    let n = name.to_ascii_lowercase();
    ["movej", "triggj", "searchj", "spotj", "arcj", "moveabsj"]
        .iter()
        .any(|p| n.starts_with(p))
}

/// Checks a procedure call statement that is a move.
pub(crate) fn check<'t>(cx: &mut Cx<'t>, node: Node<'t>) {
    let Some(robot) = cx.task.robot.clone() else {
        return;
    };
    if ![
        &rules::target_out_of_reach::RULE,
        &rules::joint_out_of_range::RULE,
        &rules::configuration_mismatch::RULE,
    ]
    .iter()
    .any(|r| cx.selection.is_on(r))
        || node.has_error()
    {
        return;
    }
    let Some(name_node) = field(node, field::NAME) else {
        return;
    };
    if crate::syntax_util::kind(name_node) != kind::IDENTIFIER {
        return;
    }
    let name = cx.node_text(name_node);
    let Some(Def::BuiltinRoutine(routine)) = cx.scope.resolve_routine(name, false) else {
        return;
    };
    let sig = Signature::builtin(routine);
    let wanted = ["ToPoint", "CirPoint", "ToJointPos", "Tool", "WObj"].map(|p| sig.param(p));
    if wanted[0].is_none() && wanted[2].is_none() {
        return;
    }
    let (_, parts, binding) = super::calls::bind_call(cx, &sig, field(node, field::ARGUMENTS));
    let mut values: [Option<Node<'t>>; 5] = [None; 5];
    for (p, bound) in parts.iter().zip(&binding.args) {
        if let Target::Param(i) = bound.target
            && let Some(k) = wanted.iter().position(|w| *w == Some(i))
        {
            values[k] = p
                .value
                .filter(|v| crate::syntax_util::kind(*v) != kind::STAR);
        }
    }
    let [to_point, cir_point, joint_target, tool, wobj] = values;
    let at = (cx.unit_idx, node.start_byte());
    let task = cx.task;
    let text = &cx.unit.text;
    let module = task
        .units
        .get(cx.unit_idx)
        .and_then(|u| u.items.module_at(node.start_byte()));
    let evaluate = |n: Node<'_>, ty: &str| -> Option<Value> {
        let expr = crate::lower::lower_with(n, text, &|f| {
            is_builtin_call(task, module.map(|m| (at.0, m)), f)
        });
        let options = EnvOptions {
            pers_initial: true,
            var_initial: false,
        };
        with_env(task, Some(at), options, |env| {
            rapid_evaluator::eval_with(
                &expr,
                Some(&Type::named(ty)),
                env,
                &Options {
                    allow_initial_values: true,
                    ..Options::default()
                },
            )
            .ok()
            .map(|e| e.value)
        })
    };
    let robot_name = robot.robot.model.name.clone();
    if let Some(n) = joint_target {
        let Some(v) = evaluate(n, "jointtarget") else {
            return;
        };
        let Ok((axes, _)) = frames::jointtarget(&v) else {
            return;
        };
        if let Some((axis, bound, by)) = violation(&robot.robot.limits, &axes) {
            let what = cx.node_text(n).to_owned();
            rules::joint_out_of_range::report(
                cx,
                n.byte_range(),
                &what,
                (axis, axes[axis - 1], bound, by),
                &robot_name,
            );
        }
        return;
    }
    let tool = match tool {
        Some(n) => match evaluate(n, "tooldata").map(|v| frames::tool(&v)) {
            Some(Ok(t)) => t,
            _ => return,
        },
        None => Tool::default(),
    };
    let wobj = match wobj {
        Some(n) => match evaluate(n, "wobjdata").map(|v| frames::wobj(&v)) {
            Some(Ok(w)) => w,
            _ => return,
        },
        None => WObj::default(),
    };
    let off = conf_off(cx);
    let use_conf = if is_joint_move(name) {
        !off.joint
    } else {
        !off.linear
    };
    for n in [cir_point, to_point].into_iter().flatten() {
        let Some(Ok(target)) = evaluate(n, "robtarget").map(|v| frames::robtarget(&v)) else {
            continue;
        };
        let result = reach_target(&robot.robot, &target, &tool, &wobj, use_conf);
        let what = cx.node_text(n).to_owned();
        let unit = cx.unit_idx;
        if let Some(log) = cx.reaches.as_mut() {
            log.push(MoveReach {
                target: what.clone(),
                instruction: name.to_owned(),
                unit,
                offset: n.start_byte(),
                result: result.clone(),
            });
        }
        let Err(e) = result else {
            continue;
        };
        match e {
            ReachError::OutOfReach { by } => {
                rules::target_out_of_reach::report(cx, n.byte_range(), &what, by, &robot_name);
            }
            ReachError::JointLimit {
                axis,
                angle,
                bound,
                by,
                ..
            } => rules::joint_out_of_range::report(
                cx,
                n.byte_range(),
                &what,
                (axis, angle, bound, by),
                &robot_name,
            ),
            ReachError::Configuration { wanted, found } => {
                rules::configuration_mismatch::report(
                    cx,
                    n.byte_range(),
                    &what,
                    (wanted, found.conf),
                    &robot_name,
                );
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conf_off_is_found_in_any_spelling() {
        assert_eq!(
            conf_off_in("  ConfL\\Off;\n confj \\on;"),
            ConfOff {
                linear: true,
                joint: false
            }
        );
        assert!(conf_off_in("CONFJ \\OFF;").joint);
        assert_eq!(conf_off_in("! conf\n"), ConfOff::default());
        assert!(is_joint_move("MoveJDO") && is_joint_move("MoveAbsJ") && !is_joint_move("MoveL"));
    }
}
