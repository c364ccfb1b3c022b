use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// A call of a name that is data or a type, not a routine.
    ///
    /// ### What it checks
    /// The name called resolves to a data object or a data type, not to a
    /// procedure, function or trap.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num speed;
    /// speed;      ! speed is data
    /// ```
    pub static RULE = ("E208", "not-a-routine", Error);
}

/// A called name that no routine has: data or a type is reported here,
/// anything else as unresolved.
pub(crate) fn check(cx: &mut Cx<'_>, name: &str, range: Range<usize>) {
    if cx.resolve_data(name).is_some() {
        cx.report(&RULE, range, format!("`{name}` is data, not a routine"));
    } else if cx.type_exists(name) {
        cx.report(
            &RULE,
            range,
            format!("`{name}` is a data type, not a routine"),
        );
    } else {
        cx.unresolved(name, range, "routine");
    }
}
