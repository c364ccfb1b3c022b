//! A robot's path held and resumed: `StopMove` stops the move under way
//! where the arm is (the task that waits for it waits on), `StartMove`
//! lets it go on for the time it had left, `StorePath`/`RestoPath` open
//! and close a path level on which a trap or an error handler moves the
//! arm meanwhile, `ClearPath` drops the stopped move (the arm stays where
//! it stands), `StartMoveRetry` starts it and retries the statement that
//! raised the error, `IsStopMoveAct` tells whether a stop holds.
//! `StopMoveReset` resets the stop the system makes at an asynchronous
//! motion error, which the simulation never raises: it is accepted and
//! changes nothing.
//!
//! Simulated as time: a stop comes at once (no braking distance, `\Quick`
//! or not), and a resumed move goes from where the arm is to its end in
//! the seconds it had left. The events its path still had to set
//! (`TriggIO`, `MoveLDO`, a world zone's output, `TriggInt`'s
//! interrupts) wait with it and come as many seconds after `StartMove` as
//! they were due after the stop; `ClearPath` drops them
//! ([`crate::machine::PathMark`]). A move ordered on the stopped level
//! (without `StorePath`) is timed from when it is ordered, as if the stop
//! did not hold the arm back; its task waits for `StartMove` all the
//! same.

use super::{Args, Cx, Done};
use crate::machine::{R, Stopped};
use rapid_evaluator::Value;

/// The robots an instruction acts on: every motion task's with
/// `\AllMotionTasks`, else the task's own (none for a task without one).
fn robots(cx: &Cx<'_>, a: &Args) -> Vec<usize> {
    let all = a.given("AllMotionTasks");
    let own = cx.m.number.saturating_sub(1);
    (0..cx.sh.robots.len())
        .filter(|&i| (all || i == own) && matches!(cx.sh.robots.get(i), Some(Some(_))))
        .collect()
}

/// `StopMove [\Quick] [\AllMotionTasks]`.
pub(crate) fn stop_move(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let now = cx.now();
    for i in robots(cx, a) {
        let Some(path) = cx.sh.paths.get(i).copied() else {
            continue;
        };
        if path.stopped.is_some() {
            continue;
        }
        let moving = cx.sh.motion_until.get(i).is_some_and(|&t| t > now);
        let record = if moving {
            record_under_way(cx, i, now)
        } else {
            None
        };
        let left = if moving {
            cx.sh
                .robots
                .get_mut(i)
                .and_then(Option::as_mut)
                .and_then(|r| r.pause(now))
                .unwrap_or(0.0)
        } else {
            0.0
        };
        if moving && let Some(t) = cx.sh.motion_until.get_mut(i) {
            *t = now;
        }
        let joints = cx
            .sh
            .robots
            .get(i)
            .and_then(Option::as_ref)
            .and_then(|r| r.joints_at(now).ok())
            .map(|j| j.robax);
        if let Some(p) = cx.sh.paths.get_mut(i) {
            p.stopped = Some(Stopped {
                level: path.level,
                left,
                at: now,
                joints,
                record,
            });
        }
    }
    Ok(Done::Next)
}

/// `StartMove [\AllMotionTasks]`: the stopped move goes on.
pub(crate) fn start_move(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let now = cx.now();
    for i in robots(cx, a) {
        let Some(stopped) = cx.sh.paths.get_mut(i).and_then(|p| p.stopped.take()) else {
            continue;
        };
        if let Some(r) = cx.sh.robots.get_mut(i).and_then(Option::as_mut) {
            r.resume(now, stopped.left, true);
        }
        if let Some(t) = cx.sh.motion_until.get_mut(i) {
            *t = t.max(now + stopped.left);
        }
        if let Some(r) = stopped.record {
            split_record(cx, r, &stopped, now);
        }
        if let Some(p) = cx.sh.paths.get_mut(i) {
            p.held(stopped.level, now - stopped.at);
        }
    }
    Ok(Done::Next)
}

/// The trace's record of the move robot `i` makes at `now`.
fn record_under_way(cx: &Cx<'_>, i: usize, now: f64) -> Option<usize> {
    let name = cx.sh.names.get(i)?;
    cx.sh
        .moves
        .iter()
        .rposition(|m| m.task.as_deref().is_none_or(|t| t == name) && m.start <= now && now < m.end)
}

/// The trace's record `r` of a stopped move ends where the arm stopped
/// (its TCP taken on the line from the task's previous position, as the
/// arm is); the rest of the move, when it goes on, is a record of its own.
fn split_record(cx: &mut Cx<'_>, r: usize, stopped: &Stopped, now: f64) {
    let Some(original) = cx.sh.moves.get(r).cloned() else {
        return;
    };
    let before = cx
        .sh
        .moves
        .get(..r)
        .and_then(|earlier| earlier.iter().rev().find(|m| m.task == original.task))
        .and_then(|m| m.pos);
    let span = original.end - original.start;
    let f = if span > 0.0 {
        ((stopped.at - original.start) / span).clamp(0.0, 1.0)
    } else {
        1.0
    };
    if let Some(m) = cx.sh.moves.get_mut(r) {
        m.end = stopped.at;
        if let Some(j) = stopped.joints {
            m.joints = Some(j.to_vec());
        }
        m.pos = match (before, original.pos) {
            (Some(a), Some(b)) => Some(std::array::from_fn(|k| a[k] + f * (b[k] - a[k]))),
            _ => None,
        };
    }
    if stopped.left > 0.0 {
        let mut rest = original;
        rest.start = now;
        rest.end = now + stopped.left;
        cx.sh.moves.push(rest);
    }
}

/// `StartMoveRetry`: `StartMove` and `RETRY` in one (in an error
/// handler).
pub(crate) fn start_move_retry(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    start_move(cx, a)?;
    Ok(Done::Retry)
}

/// `StorePath [\KeepSync]`: moves are made on a new path level.
pub(crate) fn store_path(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    let own = cx.m.number.saturating_sub(1);
    if let Some(p) = cx.sh.paths.get_mut(own) {
        p.level += 1;
    }
    Ok(Done::Next)
}

/// `RestoPath`: back to the path level `StorePath` left.
pub(crate) fn resto_path(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    let own = cx.m.number.saturating_sub(1);
    if let Some(p) = cx.sh.paths.get_mut(own) {
        p.level = p.level.saturating_sub(1);
    }
    Ok(Done::Next)
}

/// `ClearPath`: the stopped move of this level is dropped; the arm stays
/// where it stands, and a `StartMove` ends the wait for it at once.
pub(crate) fn clear_path(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    let own = cx.m.number.saturating_sub(1);
    let now = cx.now();
    let Some(path) = cx.sh.paths.get_mut(own) else {
        return Ok(Done::Next);
    };
    let level = path.level;
    if let Some(stopped) = path.stopped.as_mut().filter(|s| s.level == level) {
        stopped.left = 0.0;
        path.clear(level);
        if let Some(r) = cx.sh.robots.get_mut(own).and_then(Option::as_mut) {
            r.resume(now, 0.0, false);
        }
    }
    Ok(Done::Next)
}

/// `IsStopMoveAct(\FromMoveTask | \FromNonMoveTask)`: does a `StopMove`
/// hold the task's robot (with `\FromNonMoveTask`, any robot)?
pub(crate) fn is_stop_move_act(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let own = cx.m.number.saturating_sub(1);
    let any = a.given("FromNonMoveTask");
    let held = cx
        .sh
        .paths
        .iter()
        .enumerate()
        .any(|(i, p)| (any || i == own) && p.stopped.is_some());
    Ok(Value::Bool(held))
}
