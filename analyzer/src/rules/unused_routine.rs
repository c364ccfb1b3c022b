use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// A `LOCAL` routine that nothing in its module calls.
    ///
    /// ### What it checks
    /// A routine declared `LOCAL` can only be called from its own module; if
    /// nothing there calls it (or connects it, for a trap), it is dead code.
    ///
    /// ### Why
    /// Dead code is misleading to read and still has to load. A routine named in
    /// a late-bound call (`%"name"%`, `CallByVar`) counts as called. This is a
    /// hint, shown faded in editors.
    ///
    /// ### Example
    /// ```rapid
    /// LOCAL PROC oldHelper()
    ///     TPWrite "never called";
    /// ENDPROC
    /// ```
    pub static RULE = ("W203", "unused-routine", Hint);
}

/// The `LOCAL` routine `name` (its name at `range`) that nothing in its
/// module calls.
pub(crate) fn report(cx: &mut Cx<'_>, name: &str, range: Range<usize>) {
    cx.report(
        &RULE,
        range,
        format!("the LOCAL routine `{name}` is never called in its module"),
    );
}
