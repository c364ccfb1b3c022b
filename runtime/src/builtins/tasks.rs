//! Multitasking: the task's identity, semaphores (`TestAndSet`,
//! `WaitTestAndSet`), rendezvous (`WaitSyncTask`) and synchronized
//! movement (`SyncMoveOn`, `SyncMoveOff`, `SyncMoveUndo`,
//! `IsSyncMoveOn`), as the RAPID reference describes them. A
//! synchronization point is known by the name of its `syncident`
//! variable; a task list is an array of `tasks` records (`taskname`).

use rapid_analyzer::names::fold;
use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, Timeout, Wait, WaitKind, fault, invalid, named_error};

/// `GetTaskName([\TaskNo])`: the task's name; `\TaskNo` gets its number.
pub(crate) fn get_task_name(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    if let Some(p) = cx.opt_place(a, "TaskNo")? {
        let n = cx.m.number as f32;
        cx.store(&p, Value::Num(n))?;
    }
    Ok(Value::Str(cx.m.name.clone()))
}

/// `TestAndSet(Object)`: in one step, `Object` is set if it was not, and
/// `TRUE` says it was this call that set it.
pub(crate) fn test_and_set(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let p = cx.place_arg(a, "Object")?;
    match cx.m.get(cx.sh, &p) {
        Some(Value::Bool(false)) => {
            cx.store(&p, Value::Bool(true))?;
            Ok(Value::Bool(true))
        }
        Some(Value::Bool(true)) => Ok(Value::Bool(false)),
        _ => invalid("TestAndSet: Object must be a bool"),
    }
}

/// `WaitTestAndSet Object`: waits until `Object` is `FALSE`, then sets it.
pub(crate) fn wait_test_and_set(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let p = cx.place_arg(a, "Object")?;
    match cx.m.get(cx.sh, &p) {
        Some(Value::Bool(false)) => {
            cx.store(&p, Value::Bool(true))?;
            Ok(Done::Next)
        }
        Some(Value::Bool(true)) => {
            let what = format!(
                "WaitTestAndSet {}",
                cx.arg_name(a, "Object").unwrap_or_default()
            );
            Ok(Done::Wait(Box::new(Wait {
                kind: WaitKind::Semaphore(p),
                deadline: None,
                on_timeout: Timeout::Error("ERR_WAIT_MAXTIME", String::new()),
                what,
            })))
        }
        _ => invalid("WaitTestAndSet: Object must be a bool"),
    }
}

/// `TaskRunMec()`: does the task control a mechanical unit?
pub(crate) fn task_run_mec(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Bool(has_robot(cx)))
}

/// `TaskRunRob()`: does the task control a robot?
pub(crate) fn task_run_rob(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Bool(has_robot(cx)))
}

fn has_robot(cx: &Cx<'_>) -> bool {
    cx.sh
        .robots
        .get(cx.m.number.saturating_sub(1))
        .is_some_and(Option::is_some)
}

/// `IsSyncMoveOn()`.
pub(crate) fn is_sync_move_on(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Bool(cx.m.sync_move.is_some()))
}

/// The name of the `syncident` variable given.
fn sync_id(cx: &Cx<'_>, a: &Args) -> R<String> {
    match cx.arg_name(a, "SyncID") {
        Some(n) => Ok(fold(&n)),
        None => invalid(format!("{}: SyncID must be a syncident variable", a.name)),
    }
}

/// The tasks of a task list: their names as given and their numbers.
fn task_list(cx: &mut Cx<'_>, a: &Args) -> R<(Vec<String>, Vec<usize>)> {
    let list = cx.req(a, "TaskList")?;
    let items = match list {
        Value::Array(items) => items,
        record @ Value::Record { .. } => vec![record],
        _ => return invalid(format!("{}: TaskList must be a list of tasks", a.name)),
    };
    let mut names = Vec::new();
    let mut numbers = Vec::new();
    for item in items {
        let Some(Value::Str(name)) = item.field("taskname").cloned() else {
            return invalid(format!("{}: TaskList must be a list of tasks", a.name));
        };
        match cx.sh.task_named(&name) {
            Some(i) => numbers.push(i + 1),
            None => {
                return fault(named_error(
                    &cx.m.prog,
                    "ERR_TASKNAME",
                    format!("{}: {}", a.name, cx.sh.no_such_task(&name)),
                ));
            }
        }
        names.push(name);
    }
    Ok((names, numbers))
}

/// Arrives at a rendezvous: on at once when this task completes it, else
/// a wait (until `\TimeOut`: the error `timeout_error`).
fn rendezvous(
    cx: &mut Cx<'_>,
    a: &Args,
    key: String,
    names: &[String],
    numbers: &[usize],
    sync_move: Option<bool>,
    timeout_error: &'static str,
) -> R<Done> {
    let me = cx.m.number;
    let timeout = cx.opt_num(a, "TimeOut")?;
    let id = key
        .split_once(':')
        .map_or(key.as_str(), |(_, id)| id)
        .to_owned();
    let deadline = timeout.map(|t| cx.now() + t.max(0.0));
    let on_timeout = Timeout::Error(
        timeout_error,
        format!(
            "{}: the other tasks did not arrive within \\TimeOut",
            a.name
        ),
    );
    let what = format!("{} {id}", a.name);
    // `\InPos`: the task arrives when its robot stands still.
    let still = super::motion::motion_end(cx);
    if sync_move.is_none() && a.given("InPos") && still > cx.now() {
        return Ok(Done::Wait(Box::new(Wait {
            kind: WaitKind::InPos {
                at: still,
                key,
                numbers: numbers.to_vec(),
                names: names.to_vec(),
            },
            deadline,
            on_timeout,
            what,
        })));
    }
    let (round, complete) = cx.sh.sync.arrive(&key, me, numbers, names);
    if complete {
        if let Some(on) = sync_move {
            cx.m.sync_move = if on { cx.sh.sync.group_of(me) } else { None };
        }
        return Ok(Done::Next);
    }
    Ok(Done::Wait(Box::new(Wait {
        kind: WaitKind::Sync {
            key,
            round,
            sync_move,
        },
        deadline,
        on_timeout,
        what,
    })))
}

/// `WaitSyncTask [\InPos] SyncID, TaskList [\TimeOut]`: waits until every
/// task of the list has arrived at a `WaitSyncTask` of the same
/// `syncident`; with `\InPos`, a task arrives only when its robot stands
/// still (after the moves it started with `\Conc`).
pub(crate) fn wait_sync_task(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id = sync_id(cx, a)?;
    let (names, numbers) = task_list(cx, a)?;
    rendezvous(
        cx,
        a,
        format!("sync:{id}"),
        &names,
        &numbers,
        None,
        "ERR_WAITSYNCTASK",
    )
}

/// `SyncMoveOn SyncID, TaskList [\TimeOut]`: waits for the tasks of the
/// list, then their moves run synchronized.
pub(crate) fn sync_move_on(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    if cx.m.sync_move.is_some() {
        return invalid(
            "SyncMoveOn: the task is in synchronized movement already (SyncMoveOff first)",
        );
    }
    let id = sync_id(cx, a)?;
    let (names, numbers) = task_list(cx, a)?;
    rendezvous(
        cx,
        a,
        format!("movon:{id}"),
        &names,
        &numbers,
        Some(true),
        "ERR_SYNCMOVEON",
    )
}

/// `SyncMoveOff SyncID [\TimeOut]`: waits for the tasks moving in
/// synchronization with this one, then each moves on its own.
pub(crate) fn sync_move_off(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let Some(group) = cx.m.sync_move.clone() else {
        return Ok(Done::Next);
    };
    let id = sync_id(cx, a)?;
    let numbers: Vec<usize> = group
        .iter()
        .filter_map(|n| cx.sh.task_named(n).map(|i| i + 1))
        .collect();
    rendezvous(
        cx,
        a,
        format!("movoff:{id}"),
        &group,
        &numbers,
        Some(false),
        "ERR_SYNCMOVEOFF",
    )
}

/// `SyncMoveUndo`: the task moves on its own again, at once.
pub(crate) fn sync_move_undo(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    let me = cx.m.number;
    cx.sh.sync.undo(me);
    cx.m.sync_move = None;
    Ok(Done::Next)
}
