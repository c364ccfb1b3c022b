use tree_sitter::Node;

use crate::check::Cx;

crate::declare_rule! {
    /// A `GOTO` that jumps into another statement list.
    ///
    /// ### What it checks
    /// A `GOTO` may jump to a label in its own statement list or in a list that
    /// encloses it, but not into the body of an `IF`, `FOR`, `WHILE` or `TEST` that
    /// it is not inside.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// GOTO inside;
    /// IF di1 = 1 THEN
    ///     inside:
    ///     Stop;
    /// ENDIF
    /// ```
    pub static RULE = ("E406", "goto-into-block", Error);
}

/// A `GOTO` `s` to the label `name` (its node `label`) of the statement
/// list `list`: the list must enclose the `GOTO`.
pub(crate) fn check(
    cx: &mut Cx<'_>,
    s: Node<'_>,
    label: Node<'_>,
    name: &str,
    list: crate::sema::labels::BlockKey,
) {
    let mut at = s.parent();
    while let Some(n) = at {
        if crate::sema::labels::block_key(n) == list {
            return;
        }
        at = n.parent();
    }
    cx.report(
        &RULE,
        label.byte_range(),
        format!("`{name}` is inside another statement block; GOTO cannot jump into it"),
    );
}
