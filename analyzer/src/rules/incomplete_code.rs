use tree_sitter::Node;

use crate::check::Cx;

crate::declare_rule! {
    /// An unfilled FlexPendant placeholder such as `<SMT>` or `<EXP>`.
    ///
    /// ### What it checks
    /// The FlexPendant and RobotStudio write placeholders (`<SMT>`, `<EXP>`,
    /// `<ARG>`, `<VAR>`, `<ID>`, ...) for the parts of a statement still to be
    /// written. A module with placeholders is incomplete.
    ///
    /// ### Why
    /// The controller loads such a module but stops with an error when execution
    /// reaches the placeholder: a warning, since the module loads and runs until
    /// then.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     <SMT>
    /// ENDPROC
    /// ```
    pub static RULE = ("E412", "incomplete-code", Warning);
}

/// An unfilled placeholder (`<SMT>`, `<EXP>`...).
pub(crate) fn report(cx: &mut Cx<'_>, node: Node<'_>) {
    let p = cx.node_text(node);
    cx.report(
        &RULE,
        node.byte_range(),
        format!("unfilled placeholder {p}: this code is not finished"),
    );
}
