use std::ops::Range;

use crate::check::{Cx, Place};

crate::declare_rule! {
    /// An assignment to a constant, a `FOR` loop variable or read-only data.
    ///
    /// ### What it checks
    /// Only variables, persistents and parameters can be assigned. `CONST` data,
    /// the loop variable of a `FOR`, and read-only system data such as `ERRNO`
    /// cannot.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num max := 10;
    /// max := 20;
    /// ```
    pub static RULE = ("E401", "assign-to-constant", Error);
}

/// An assignment to the place `place` (the target at `range`).
pub(crate) fn check(cx: &mut Cx<'_>, range: Range<usize>, place: Place) {
    if matches!(place, Place::Const | Place::ForVar | Place::ReadOnly) {
        cx.report(
            &RULE,
            range,
            format!("cannot assign to {}", place.describe()),
        );
    }
}
