use std::fmt::Display;
use std::ops::Range;

use crate::check::Cx;
use crate::check::exprs::a_type;
use crate::ty::Ty;

crate::declare_rule! {
    /// A value of one type where another is expected.
    ///
    /// ### What it checks
    /// Assignments, initial values, arguments, `RETURN` values, `TEST` cases and
    /// `FOR` bounds must have the type the target expects. Alias types count as
    /// their base type, and `num` and `dnum` convert into each other.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num n;
    /// n := "ten";      ! a string is not a num
    /// ```
    pub static RULE = ("E201", "type-mismatch", Error);
}

/// A value of type `actual` at `range` where `what` (the assigned value,
/// the argument X...) should be of type `expected`.
pub(crate) fn check_assignable(
    cx: &mut Cx<'_>,
    range: Range<usize>,
    what: impl Display,
    expected: &Ty,
    actual: &Ty,
) {
    if !cx.types.assignable(expected, actual) {
        report(cx, range, what, expected, actual);
    }
}

/// `what` at `range` is of type `actual`, not `expected`.
pub(crate) fn report(
    cx: &mut Cx<'_>,
    range: Range<usize>,
    what: impl Display,
    expected: &Ty,
    actual: &Ty,
) {
    cx.report(
        &RULE,
        range,
        format!(
            "{what} should be {}, found {}",
            a_type(expected),
            a_type(actual)
        ),
    );
}

/// An aggregate at `range` where a value of type `expected`, neither a
/// record nor an array, is expected.
pub(crate) fn report_not_aggregate(cx: &mut Cx<'_>, range: Range<usize>, expected: &Ty) {
    cx.report(
        &RULE,
        range,
        format!(
            "an aggregate [...] cannot be {}; it is not a record or an array",
            a_type(expected)
        ),
    );
}

/// An array size of type `ty` at `range`.
pub(crate) fn check_array_size(cx: &mut Cx<'_>, range: Range<usize>, ty: &Ty) {
    if !cx.types.is_num_like(ty) {
        cx.report(
            &RULE,
            range,
            format!("an array size must be a num, found {ty}"),
        );
    }
}
