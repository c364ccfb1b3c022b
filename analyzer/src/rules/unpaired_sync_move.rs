use crate::check::Cx;
use crate::diagnostic::{Diagnostic, Related};
use crate::sema::sync::SyncFlow;

crate::declare_rule! {
    /// `SyncMoveOn` and `SyncMoveOff` that do not pair up on a path of a routine.
    ///
    /// ### What it checks
    /// Between `SyncMoveOn` and `SyncMoveOff` a task moves in synchronised mode
    /// with the other tasks of its task list (MultiMove). Each path through a
    /// routine is followed: a `SyncMoveOn` reached while the task is already
    /// synchronised, a `SyncMoveOff` reached after an earlier `SyncMoveOff`
    /// ended it, and, in a routine that ends synchronised mode itself, a path
    /// from a `SyncMoveOn` to the routine's end (or a `RETURN`) without
    /// `SyncMoveOff`. A routine that only starts synchronised mode (another
    /// ends it) is not reported; calls of the task's routines that turn the
    /// mode on or off, and routines with `GOTO`, are not followed.
    ///
    /// ### Why
    /// The controller stops the program with an error when `SyncMoveOn` is
    /// executed in synchronised mode, or `SyncMoveOff` outside it; a branch
    /// that forgets `SyncMoveOff` leaves the other tasks waiting at theirs.
    ///
    /// ### Example
    /// ```rapid
    /// SyncMoveOn sync1, all_tasks;
    /// IF bDone THEN
    ///     SyncMoveOff sync2;
    /// ENDIF                       ! when bDone is FALSE ...
    /// SyncMoveOn sync3, all_tasks; ! ... the task is still synchronised here
    /// ```
    pub static RULE = ("W501", "unpaired-sync-move", Warning);
}

/// Reports what the walk of a routine found unpaired.
pub(crate) fn check(cx: &mut Cx<'_>, flow: &SyncFlow) {
    for (again, earlier) in &flow.on_again {
        let d = Diagnostic::new(
            &RULE,
            again.clone(),
            "SyncMoveOn on a path that is synchronised already: SyncMoveOff must end synchronised mode before it starts again",
        )
        .with_related(Related {
            file: None,
            range: earlier.clone(),
            message: "synchronised mode starts here".to_owned(),
        });
        cx.report_with(d);
    }
    for off in &flow.off_again {
        cx.report(
            &RULE,
            off.clone(),
            "SyncMoveOff on a path where an earlier SyncMoveOff already ended synchronised mode",
        );
    }
    if flow.turns_off {
        for on in &flow.left_on {
            cx.report(
                &RULE,
                on.clone(),
                "a path from this SyncMoveOn leaves the routine in synchronised mode: the routine ends it with SyncMoveOff on its other paths",
            );
        }
    }
}
