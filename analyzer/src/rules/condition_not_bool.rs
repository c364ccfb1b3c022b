use tree_sitter::Node;

use crate::check::Cx;
use crate::ty::Ty;

crate::declare_rule! {
    /// An `IF`, `ELSEIF` or `WHILE` condition that is not a `bool`.
    ///
    /// ### What it checks
    /// Conditions must be `bool` expressions; RAPID does not treat numbers as truth
    /// values.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// WHILE nCount DO      ! write  WHILE nCount > 0 DO
    /// ```
    pub static RULE = ("E205", "condition-not-bool", Error);
}

/// A condition of IF, ELSEIF, WHILE or a compact IF.
pub(crate) fn check<'t>(cx: &mut Cx<'t>, node: Node<'t>) {
    let ty = crate::check::exprs::expr(cx, node, Some(&Ty::bool()));
    if !cx.types.is_bool(&ty) {
        cx.report(
            &RULE,
            node.byte_range(),
            format!(
                "a condition must be a bool, found {}",
                crate::check::exprs::a_type(&ty)
            ),
        );
    }
}
