use std::ops::Range;

use crate::check::Cx;
use crate::sema::signature::Param;

crate::declare_rule! {
    /// A switch given a value, or an optional argument given without one.
    ///
    /// ### What it checks
    /// A `switch` parameter is given as `\Name` alone; any other optional parameter
    /// needs a value, `\Name:=value` (or `\Name?param` to pass on an optional
    /// parameter).
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine, tool0 \WObj;      ! \WObj needs a value
    /// TPWrite "x" \Num;                       ! likewise
    /// ```
    pub static RULE = ("E303", "switch-argument", Error);
}

/// A value given at `range` to the switch `p`.
pub(crate) fn given_a_value(cx: &mut Cx<'_>, p: &Param, range: Range<usize>) {
    cx.report(
        &RULE,
        range,
        format!("\\{} is a switch and takes no value", p.name),
    );
}

/// `\Name` without a value at `range` for the parameter `p`, which is not
/// a switch.
pub(crate) fn needs_a_value(cx: &mut Cx<'_>, p: &Param, range: Range<usize>) {
    cx.report(
        &RULE,
        range,
        format!("\\{} needs a value: \\{}:=...", p.name, p.name),
    );
}
