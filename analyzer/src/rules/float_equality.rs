use tree_sitter::Node;

use crate::check::Cx;
use crate::syntax::{field, kind};
use crate::syntax_util::field;
use crate::ty::Ty;

crate::declare_rule! {
    /// `=` or `<>` comparing the result of a floating-point computation.
    ///
    /// ### What it checks
    /// Comparing with `=` or `<>` where an operand is computed with `/` or a
    /// trigonometric or other real-valued function. `num` is a single-precision
    /// value, so such results are rarely exactly equal. Comparing with a literal
    /// (`x = -112.5`) is not reported: the value compared may be taught or
    /// configured, and literals are exact. Neither is comparing a computed value
    /// with `0` (`Distance(p1, p2) = 0` asks whether two points are the same) nor
    /// `Pow` (integer powers of integers are exact).
    ///
    /// ### Why
    /// The comparison can be false when the values are equal for every practical
    /// purpose, so a branch silently never runs.
    ///
    /// ### Example
    /// ```rapid
    /// IF Sqrt(2) * Sqrt(2) = 2 THEN      ! prefer  Abs(Sqrt(2) * Sqrt(2) - 2) < 0.0001
    /// ```
    pub static RULE = ("W206", "float-equality", Warning);
}

/// A comparison (`=` or `<>`, its operator node `op`) of two operands with
/// their types: reported when both are numbers and one is a computed real
/// number, unless the other is the literal 0 (comparing with zero asks "is
/// it exactly the same point, vector or value", which identical inputs
/// answer exactly).
pub(crate) fn check(
    cx: &mut Cx<'_>,
    node: Node<'_>,
    op: Node<'_>,
    (l, lt): (Node<'_>, &Ty),
    (r, rt): (Node<'_>, &Ty),
) {
    let zero = |n: Node<'_>| {
        crate::syntax_util::kind(n) == kind::NUMBER
            && cx.node_text(n).parse::<f64>().is_ok_and(|v| v == 0.0)
    };
    if cx.types.is_num_like(lt)
        && cx.types.is_num_like(rt)
        && (is_real(cx, l) || is_real(cx, r))
        && !zero(l)
        && !zero(r)
    {
        cx.report(
            &RULE,
            node.byte_range(),
            format!(
                "`{}` compares a computed real number exactly; compare the difference with a tolerance instead",
                cx.node_text(op)
            ),
        );
    }
}

/// Is this expression a computed real number (for the float-equality
/// lint): a division or a real-valued function somewhere in it? A literal
/// such as `-112.5` is not computed: comparing a value with it is how real
/// programs test a taught or configured value.
fn is_real(cx: &Cx<'_>, node: Node<'_>) -> bool {
    match crate::syntax_util::kind(node) {
        kind::BINARY_EXPRESSION => {
            field(node, field::OPERATOR).is_some_and(|o| crate::syntax_util::kind(o) == "/")
                || field(node, field::LEFT).is_some_and(|l| is_real(cx, l))
                || field(node, field::RIGHT).is_some_and(|r| is_real(cx, r))
        }
        kind::PARENTHESIZED_EXPRESSION | kind::UNARY_EXPRESSION => {
            let inner = field(node, field::EXPRESSION).or_else(|| field(node, field::OPERAND));
            inner.is_some_and(|i| is_real(cx, i))
        }
        // Functions whose results are computed real numbers (the
        // catalogue's `real_valued`).
        kind::FUNCTION_CALL => field(node, field::NAME)
            .and_then(|n| cx.cat.function(cx.node_text(n)))
            .is_some_and(|r| r.real_valued),
        _ => false,
    }
}
