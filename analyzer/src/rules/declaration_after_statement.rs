use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// Routine data declared after the routine's first statement.
    ///
    /// ### What it checks
    /// In a routine, every data declaration comes before the first statement.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     TPErase;
    ///     VAR num n;      ! move above TPErase
    /// ENDPROC
    /// ```
    pub static RULE = ("E408", "declaration-after-statement", Error);
}

/// Routine data declared at `range`, after a statement of the routine.
pub(crate) fn report(cx: &mut Cx<'_>, range: Range<usize>) {
    cx.report(
        &RULE,
        range,
        "routine data must be declared before the routine's first statement",
    );
}
