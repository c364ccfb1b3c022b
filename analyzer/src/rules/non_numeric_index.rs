use std::ops::Range;

use crate::check::Cx;
use crate::check::exprs::a_type;
use crate::ty::Ty;

crate::declare_rule! {
    /// An array index that is not a number.
    ///
    /// ### What it checks
    /// Every index of `a{i}` must be a `num` (or `dnum`) expression.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num a{3};
    /// a{"1"} := 0;
    /// ```
    pub static RULE = ("E202", "non-numeric-index", Error);
}

/// An index of type `ty` at `range`.
pub(crate) fn check(cx: &mut Cx<'_>, range: Range<usize>, ty: &Ty) {
    if !cx.types.is_num_like(ty) {
        cx.report(
            &RULE,
            range,
            format!("an index must be a num, found {}", a_type(ty)),
        );
    }
}
