use std::ops::Range;

use crate::check::Cx;
use crate::check::exprs::a_type;
use crate::sema::signature::Param;
use crate::ty::Ty;

crate::declare_rule! {
    /// An array given where a single value is expected, or the reverse.
    ///
    /// ### What it checks
    /// Array parameters (`{*}`) need an array of the same number of dimensions;
    /// other parameters need a single value.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num values{10};
    /// TPWrite "" \Num:=values;    ! one value is expected: values{1}
    /// ```
    pub static RULE = ("E308", "array-argument", Error);
}

/// A value of type `actual` passed at `range` to parameter `p`: whether
/// the type check goes on (`false` for an `anytype` or any-rank parameter,
/// which takes any type, and when an array is reported).
pub(crate) fn check(cx: &mut Cx<'_>, p: &Param, actual: &Ty, range: Range<usize>) -> bool {
    // `anytype` parameters take any type; an array of any rank (Dim's
    // ArrPar) or an `anytype` array needs some array.
    if p.any_rank || matches!(p.ty.element(), Ty::Any) {
        if (p.any_rank || p.ty.dims() > 0) && actual.dims() == 0 {
            cx.report(
                &RULE,
                range.clone(),
                format!("{} needs an array, found {}", p.name, a_type(actual)),
            );
        }
        return false;
    }
    if p.ty.dims() != actual.dims() {
        cx.report(
            &RULE,
            range.clone(),
            format!(
                "{} needs {}, found {}",
                p.name,
                a_type(&p.ty),
                a_type(actual)
            ),
        );
        return false;
    }
    true
}
