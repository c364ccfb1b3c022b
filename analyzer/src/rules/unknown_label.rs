use tree_sitter::Node;

use crate::check::Cx;
use crate::names::fold;
use crate::syntax::field;
use crate::syntax_util::field;

crate::declare_rule! {
    /// A `GOTO` to a label that the routine does not have.
    ///
    /// ### What it checks
    /// The label named by `GOTO` must be declared (`name:`) in the same routine.
    ///
    /// ### Why
    /// The controller rejects the routine.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     GOTO retry_point;   ! no label retry_point in main
    /// ENDPROC
    /// ```
    pub static RULE = ("E104", "unknown-label", Error);
}

/// A `GOTO`: its label must be one of the routine's; where the label is,
/// rule [`super::goto_into_block`] checks.
pub(crate) fn check(cx: &mut Cx<'_>, s: Node<'_>) {
    let Some(label) = field(s, field::LABEL) else {
        return;
    };
    let name = cx.node_text(label);
    if cx.routine.is_none() {
        return;
    }
    match cx.labels.get(&fold(name)) {
        None => cx.report(
            &RULE,
            label.byte_range(),
            format!("this routine has no label `{name}`"),
        ),
        Some((_, list)) => {
            let list = *list;
            super::goto_into_block::check(cx, s, label, name, list);
        }
    }
}
