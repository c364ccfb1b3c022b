use std::ops::Range;

use crate::check::Cx;
use crate::diagnostic::{Diagnostic, Related};
use crate::names::same;
use crate::sema::sync::SyncPoint;

crate::declare_rule! {
    /// A task of the task list that does not meet at the same synchronisation point.
    ///
    /// ### What it checks
    /// `SyncMoveOn` and `WaitSyncTask` name a `syncident` and a task list: every
    /// task of the list meets the others at a point of the same instruction and
    /// the same `syncident` name, with a task list of the same tasks. For each
    /// such point, every other task of its list that this controller's backup
    /// holds is looked at: one whose points of that name all list other tasks
    /// is reported, and so is one with no point of that name when every module
    /// of that task is here (a complete backup's task; otherwise the point may
    /// be in a module the checked files lack). The task lists' values are
    /// their declarations' initial values.
    ///
    /// ### Why
    /// The tasks wait for each other at the point: a task that never comes, or
    /// waits for another set of tasks, leaves the others waiting for ever (or
    /// until `\TimeOut`).
    ///
    /// ### Example
    /// ```rapid
    /// ! T_ROB1
    /// PERS tasks tlAll{2} := [["T_ROB1"], ["T_ROB2"]];
    /// SyncMoveOn sync1, tlAll;
    /// ! T_ROB2: the same task list, but no SyncMoveOn sync1
    /// ```
    pub static RULE = ("W503", "sync-task-mismatch", Warning);
}

/// Checks the synchronisation points of this unit within `within` (a
/// routine) against the other tasks of their task lists.
pub(crate) fn check(cx: &mut Cx<'_>, within: Range<usize>) {
    let syncs = cx.task.syncs.clone();
    let Some((_, own_names, own)) = syncs.of_key(&cx.task.key) else {
        return;
    };
    let here = |p: &SyncPoint| p.path == cx.unit.path && within.contains(&p.range.start);
    let mut found = Vec::new();
    for p in own.points.iter().filter(|p| here(p)) {
        let Some(list) = own.list(&p.list) else {
            continue;
        };
        for (task, other) in syncs.partners(own_names, list) {
            let theirs: Vec<&SyncPoint> = other
                .points
                .iter()
                .filter(|q| q.kind == p.kind && q.ident == p.ident)
                .collect();
            let Some(first) = theirs.first() else {
                if !other.complete {
                    // The point may be in a module of the task that is
                    // not here.
                    continue;
                }
                found.push((
                    p.range.clone(),
                    format!(
                        "task {task} of the task list never meets at `{}` with {}: this task would wait for it",
                        p.ident, p.kind
                    ),
                    None,
                ));
                continue;
            };
            let other_list = |q: &&SyncPoint| other.list(&q.list);
            let differs = |l: &[String]| {
                l.len() != list.len() || !l.iter().all(|a| list.iter().any(|b| same(a, b)))
            };
            if theirs.iter().all(|q| other_list(q).is_some_and(differs)) {
                let names = other_list(first).unwrap_or_default().join(", ");
                found.push((
                    p.range.clone(),
                    format!(
                        "task {task} meets at `{}` with the tasks {names}, not with this task list's",
                        p.ident
                    ),
                    Some((first.path.clone(), first.range.clone())),
                ));
            }
        }
    }
    for (range, message, related) in found {
        let mut d = Diagnostic::new(&RULE, range, message);
        if let Some((file, range)) = related {
            d = d.with_related(Related {
                file: Some(file),
                range,
                message: "its point".to_owned(),
            });
        }
        cx.report_with(d);
    }
}
