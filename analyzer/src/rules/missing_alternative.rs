use std::ops::Range;

use crate::check::Cx;
use crate::sema::signature::Signature;

crate::declare_rule! {
    /// None of a group of alternatives given where one is required.
    ///
    /// ### What it checks
    /// Some routines require exactly one argument from a group of alternatives.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// angle := EulerZYX(rot);     ! one of \X, \Y or \Z is required
    /// ```
    pub static RULE = ("E305", "missing-alternative", Error);
}

/// A call at `range` that gives no parameter of `|` group `group`.
pub(crate) fn report(cx: &mut Cx<'_>, sig: &Signature, group: u32, range: Range<usize>) {
    let members: Vec<String> = sig
        .members(group)
        .map(|q| format!("\\{}", q.name))
        .collect();
    cx.report(
        &RULE,
        range,
        format!("`{}` needs one of {}", sig.name, members.join(" | ")),
    );
}
