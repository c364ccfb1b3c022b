use std::ops::Range;

use crate::check::Cx;
use crate::diagnostic::{Diagnostic, Related};
use crate::sema::signature::Param;

crate::declare_rule! {
    /// The same parameter given twice.
    ///
    /// ### What it checks
    /// Each parameter takes at most one argument.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine, tool0 \WObj:=wobj1 \WObj:=wobj2;
    /// ```
    pub static RULE = ("E306", "duplicate-argument", Error);
}

/// Parameter `p` given at `range` after its first argument at `first`.
pub(crate) fn report(cx: &mut Cx<'_>, p: &Param, range: Range<usize>, first: Range<usize>) {
    let d = Diagnostic::new(&RULE, range, format!("`{}` is given twice", p.name)).with_related(
        Related {
            file: None,
            range: first,
            message: "first given here".into(),
        },
    );
    cx.report_with(d);
}
