use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// A constant expression that always fails with a run-time error.
    ///
    /// ### What it checks
    /// Expressions made only of literals, constants (`CONST` data of the task and
    /// predefined constants) and pure built-in functions are computed while the
    /// program is checked, the way the controller would compute them. When the
    /// result is one of the controller's run-time errors (division by zero, a
    /// string position outside the string, a string longer than 80 characters,
    /// an argument outside a function's domain, an index outside an array...),
    /// the expression is reported with the error code the controller would set
    /// in `ERRNO`. A constant whose own value fails is reported where it is
    /// declared, not where it is used.
    ///
    /// ### Why
    /// The module loads, but the program stops with an error (or enters its
    /// error handler) every time the statement runs. Since nothing in the
    /// expression can change, the failure is certain and is better found at the
    /// desk than on the shop floor.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num nParts := 0;
    /// ...
    /// ratio := 1 / nParts;               ! ERR_DIVZERO
    /// side := Sqrt(-1);                  ! ERR_ARGVALERR
    /// part := StrPart("abc", 5, 2);      ! ERR_OUTOFBND
    /// ```
    pub static RULE = ("E413", "constant-error", Error);
}

/// A constant expression at `range` whose evaluation fails with `e` (the
/// check, which evaluates the maximal constant parts of each statement, is
/// `crate::consteval::check_constant_errors`).
pub(crate) fn report(cx: &mut Cx<'_>, range: Range<usize>, e: &rapid_evaluator::EvalError) {
    cx.report(
        &RULE,
        range,
        format!(
            "this expression always fails when it runs: {} ({})",
            e.code.name(),
            e.message
        ),
    );
}
