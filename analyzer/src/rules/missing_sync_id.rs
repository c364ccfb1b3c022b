use crate::check::Cx;
use crate::diagnostic::{Diagnostic, Related};
use crate::sema::sync::SyncFlow;

crate::declare_rule! {
    /// A move in synchronised mode without `\ID`.
    ///
    /// ### What it checks
    /// Between `SyncMoveOn` and `SyncMoveOff` every move instruction (a
    /// built-in that takes `\ID`: `MoveL`, `MoveJ`, `MoveC`, `MoveAbsJ`,
    /// `SearchL`...) of a synchronised task carries an `\ID` number, the same in
    /// every task, which pairs the moves the tasks make together. A move is
    /// reported when the task is synchronised on every path that reaches it
    /// within the routine.
    ///
    /// ### Why
    /// The controller stops the program with an error at a move without `\ID`
    /// in synchronised mode. The module loads, so this is a warning.
    ///
    /// ### Example
    /// ```rapid
    /// SyncMoveOn sync1, all_tasks;
    /// MoveL p10 \ID:=10, v100, fine, tool1;
    /// MoveL p20, v100, fine, tool1;     ! no \ID
    /// SyncMoveOff sync2;
    /// ```
    pub static RULE = ("E501", "missing-sync-id", Warning);
}

/// Reports the moves of synchronised sections that have no `\ID`.
pub(crate) fn check(cx: &mut Cx<'_>, flow: &SyncFlow) {
    for m in flow.moves.iter().filter(|m| !m.has_id) {
        let d = Diagnostic::new(
            &RULE,
            m.range.clone(),
            format!(
                "`{}` moves in synchronised mode: it needs an \\ID number, the same as the move it pairs with in the other tasks",
                m.name
            ),
        )
        .with_related(Related {
            file: None,
            range: m.on.clone(),
            message: "synchronised mode starts here".to_owned(),
        });
        cx.report_with(d);
    }
}
