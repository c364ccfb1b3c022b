use std::ops::Range;

use crate::check::Cx;
use crate::diagnostic::{Diagnostic, Related};

crate::declare_rule! {
    /// Tasks that make different numbers of `\ID` moves between the same sync points.
    ///
    /// ### What it checks
    /// In synchronised mode the tasks make their moves together, paired by
    /// their `\ID`: between a `SyncMoveOn` and its `SyncMoveOff` each task of
    /// the task list makes as many moves with `\ID`. Where a task goes straight
    /// from `SyncMoveOn` to `SyncMoveOff` (no branch, loop or call of its own
    /// routines between), its moves are counted and compared with the other
    /// tasks' straight runs between the same `syncident`s.
    ///
    /// ### Why
    /// A task with fewer moves reaches `SyncMoveOff` while the others still
    /// wait for its part of a synchronised move: the program stops with an
    /// error.
    ///
    /// ### Example
    /// ```rapid
    /// ! T_ROB1                              ! T_ROB2
    /// SyncMoveOn sync1, tlAll;              SyncMoveOn sync1, tlAll;
    /// MoveL p10 \ID:=10, v100, fine, t1;    MoveL q10 \ID:=10, v100, fine, t2;
    /// MoveL p20 \ID:=20, v100, fine, t1;    SyncMoveOff sync2;
    /// SyncMoveOff sync2;
    /// ```
    pub static RULE = ("W504", "sync-move-count", Warning);
}

/// "1 move", "2 moves".
fn moves(n: usize) -> String {
    match n {
        1 => "1 move".to_owned(),
        n => format!("{n} moves"),
    }
}

/// Compares the straight synchronised runs of this unit within `within` (a
/// routine) with the other tasks'.
pub(crate) fn check(cx: &mut Cx<'_>, within: Range<usize>) {
    let syncs = cx.task.syncs.clone();
    let Some((_, own_names, own)) = syncs.of_key(&cx.task.key) else {
        return;
    };
    let mut found = Vec::new();
    for s in own
        .sections
        .iter()
        .filter(|s| s.path == cx.unit.path && within.contains(&s.range.start))
    {
        let Some(list) = own
            .points
            .iter()
            .find(|p| p.path == s.path && p.range == s.range)
            .and_then(|p| own.list(&p.list))
        else {
            continue;
        };
        for (task, other) in syncs.partners(own_names, list) {
            let theirs: Vec<_> = other
                .sections
                .iter()
                .filter(|x| x.on == s.on && x.off == s.off)
                .collect();
            let Some(first) = theirs.first() else {
                continue;
            };
            if theirs.iter().all(|x| x.moves != s.moves) {
                found.push((
                    s.range.clone(),
                    task.clone(),
                    first.moves,
                    s.moves,
                    s.on.clone(),
                    s.off.clone(),
                    first.path.clone(),
                    first.range.clone(),
                ));
            }
        }
    }
    for (range, task, theirs, mine, on, off, path, at) in found {
        let d = Diagnostic::new(
            &RULE,
            range,
            format!(
                "this task makes {} with \\ID between `{on}` and `{off}`; task {task} makes {theirs}",
                moves(mine)
            ),
        )
        .with_related(Related {
            file: Some(path),
            range: at,
            message: format!("task {task}'s SyncMoveOn"),
        });
        cx.report_with(d);
    }
}
