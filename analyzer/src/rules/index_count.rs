use std::ops::Range;

use crate::check::Cx;
use crate::check::exprs::a_type;
use crate::sema::typing::IndexError;
use crate::ty::Ty;

crate::declare_rule! {
    /// Indexing with the wrong number of indexes, or indexing something that is not an array.
    ///
    /// ### What it checks
    /// `a{i}` needs `a` to be an array, and the number of indexes must equal its
    /// number of dimensions.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num grid{3,4};
    /// grid{2} := 0;     ! grid has two dimensions
    /// ```
    pub static RULE = ("E206", "index-count", Error);
}

/// A value of type `obj` indexed at `range` with `count` indexes, which
/// [`crate::sema::typing::index`] found wrong.
pub(crate) fn report(
    cx: &mut Cx<'_>,
    range: Range<usize>,
    obj: &Ty,
    error: &IndexError,
    count: usize,
) {
    let message = match error {
        IndexError::NotArray => format!("{} is not an array and cannot be indexed", a_type(obj)),
        IndexError::Count(dims) => format!(
            "{obj} has {dims} dimension{}, indexed with {count}",
            if *dims == 1 { "" } else { "s" },
        ),
    };
    cx.report(&RULE, range, message);
}
