use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// Statements after a `RETURN`, `EXIT`, `RAISE`, `GOTO`, `RETRY` or `TRYNEXT` in the same list.
    ///
    /// ### What it checks
    /// A statement that follows one that always leaves the list can never run,
    /// unless it carries a label that a `GOTO` jumps to.
    ///
    /// ### Why
    /// Unreachable code is usually a leftover or a misplaced statement.
    ///
    /// ### Example
    /// ```rapid
    /// RETURN;
    /// TPWrite "done";     ! never runs
    /// ```
    pub static RULE = ("W204", "unreachable-code", Warning);
}

/// Statements at `range` that follow `by` (`RETURN`, `EXIT`, `GOTO`...)
/// in their list with no label between.
pub(crate) fn report(cx: &mut Cx<'_>, range: Range<usize>, by: &str) {
    cx.report(
        &RULE,
        range,
        format!("this code can never run: it follows {by}"),
    );
}
