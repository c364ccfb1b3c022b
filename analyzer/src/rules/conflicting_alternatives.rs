use std::ops::Range;

use crate::check::Cx;
use crate::sema::signature::{Param, Signature};

crate::declare_rule! {
    /// Two arguments given for parameters that exclude each other (`|`).
    ///
    /// ### What it checks
    /// Parameters declared as alternatives, `\A | \B`, take at most one argument
    /// between them.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// TPWrite "Value" \Num:=1 \Bool:=TRUE;    ! \Num | \Bool | \Pos | \Orient
    /// ```
    pub static RULE = ("E304", "conflicting-alternatives", Error);
}

/// Parameter `p` of `|` group `group` given at `range` with parameter
/// `other` of the same group.
pub(crate) fn report(
    cx: &mut Cx<'_>,
    sig: &Signature,
    p: &Param,
    other: usize,
    group: u32,
    range: Range<usize>,
) {
    let members: Vec<String> = sig
        .members(group)
        .map(|q| format!("\\{}", q.name))
        .collect();
    let other_name = sig
        .params
        .get(other)
        .map(|q| q.name.as_str())
        .unwrap_or_default();
    cx.report(
        &RULE,
        range,
        format!(
            "\\{} and \\{other_name} exclude each other: give one of {}",
            p.name,
            members.join(" | ")
        ),
    );
}
