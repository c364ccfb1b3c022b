use tree_sitter::Node;

use crate::check::Cx;
use crate::syntax::kind;

crate::declare_rule! {
    /// A conditional argument `\A?x` where `x` is not an optional parameter of the calling routine.
    ///
    /// ### What it checks
    /// `\A?x` passes the caller's optional parameter `x` on, only if the caller was
    /// given it. `x` must therefore be an optional parameter of the routine that
    /// makes the call.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// PROC go(robtarget p)
    ///     MoveL p, v100, fine, tool0 \WObj?wobj;   ! go has no optional parameter wobj
    /// ENDPROC
    /// ```
    pub static RULE = ("E309", "conditional-argument", Error);
}

/// `?name`: it must name an optional parameter of the routine being
/// checked.
pub(crate) fn check<'t>(cx: &mut Cx<'t>, c: Node<'t>) {
    let name = cx.node_text(c);
    if crate::syntax_util::kind(c) != kind::IDENTIFIER || cx.optional_param(name).is_none() {
        cx.report(
            &RULE,
            c.byte_range(),
            format!(
                "`?{name}` passes on an optional parameter of this routine, and `{name}` is not one"
            ),
        );
    }
    if crate::syntax_util::kind(c) == kind::IDENTIFIER {
        let _ = cx.resolve_data(name);
    }
}
