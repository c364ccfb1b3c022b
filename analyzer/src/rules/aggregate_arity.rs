use std::ops::Range;

use crate::check::Cx;
use crate::ty::Ty;

crate::declare_rule! {
    /// An aggregate `[...]` with the wrong number of elements for its type.
    ///
    /// ### What it checks
    /// An aggregate takes its type from where it is used; a record type fixes the
    /// number of components, and an array declared with a literal size fixes the
    /// number of elements. Nested aggregates are checked the same way.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// CONST pos p := [100, 200];     ! pos has three components: x, y, z
    /// ```
    pub static RULE = ("E203", "aggregate-arity", Error);
}

/// An aggregate whose element count is not its array's size (when the size
/// is written as a number).
pub(crate) fn check_array(
    cx: &mut Cx<'_>,
    range: Range<usize>,
    sizes: &[Option<usize>],
    given: usize,
) {
    if let Some(Some(size)) = sizes.first()
        && *size != given
    {
        cx.report(
            &RULE,
            range,
            format!("the array has {size} elements, this aggregate gives {given}"),
        );
    }
}

/// An aggregate whose element count is not its record's component count.
pub(crate) fn check_record(
    cx: &mut Cx<'_>,
    range: Range<usize>,
    expected: &Ty,
    components: &[(String, Ty)],
    given: usize,
) {
    if components.len() != given {
        let names: Vec<&str> = components.iter().map(|(n, _)| n.as_str()).collect();
        cx.report(
            &RULE,
            range,
            format!(
                "{expected} has {} components ({}), this aggregate gives {given}",
                components.len(),
                names.join(", "),
            ),
        );
    }
}
