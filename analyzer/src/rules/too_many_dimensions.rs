use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// An array with more than three dimensions.
    ///
    /// ### What it checks
    /// RAPID arrays have one, two or three dimensions.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num cube{2,2,2,2};
    /// ```
    pub static RULE = ("E409", "too-many-dimensions", Error);
}

/// The most dimensions a RAPID array has.
pub(crate) const MAX_DIMS: usize = 3;

/// Data or a parameter `name` (at `range`) declared with `dims` dimensions.
pub(crate) fn check(cx: &mut Cx<'_>, name: &str, range: Range<usize>, dims: usize) {
    if dims > MAX_DIMS {
        cx.report(
            &RULE,
            range,
            format!("`{name}` has {dims} dimensions; RAPID arrays have at most {MAX_DIMS}"),
        );
    }
}
