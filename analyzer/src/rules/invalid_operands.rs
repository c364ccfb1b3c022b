use std::ops::Range;

use tree_sitter::Node;

use crate::check::Cx;
use crate::check::exprs::a_type;
use crate::ty::Ty;

crate::declare_rule! {
    /// An operator applied to operands of types it does not take.
    ///
    /// ### What it checks
    /// RAPID's operators take fixed types: arithmetic on `num` and `dnum`, `+` on
    /// strings, `+ - *` on `pos`, `*` on `orient`, `AND OR XOR NOT` on `bool`,
    /// ordering comparisons on numbers, `=` and `<>` on two values of one type.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// IF bReady + 1 > 0 THEN    ! a bool cannot be added to
    /// ```
    pub static RULE = ("E204", "invalid-operands", Error);
}

/// The unary operator `op` applied at `range` to a value of type `ty`,
/// which it does not take.
pub(crate) fn report_unary(cx: &mut Cx<'_>, range: Range<usize>, op: Node<'_>, ty: &Ty) {
    let message = format!(
        "`{}` cannot be applied to {}",
        cx.node_text(op).to_ascii_uppercase(),
        a_type(ty)
    );
    cx.report(&RULE, range, message);
}

/// The binary operator `op` applied to values of types `lt` and `rt`,
/// which it does not take.
pub(crate) fn report_binary(cx: &mut Cx<'_>, op: Node<'_>, lt: &Ty, rt: &Ty) {
    let message = format!(
        "`{}` cannot be applied to {} and {}",
        cx.node_text(op).to_ascii_uppercase(),
        a_type(lt),
        a_type(rt)
    );
    cx.report(&RULE, op.byte_range(), message);
}
