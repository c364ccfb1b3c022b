use tree_sitter::Node;

use crate::check::Cx;

crate::declare_rule! {
    /// `RETRY`, `TRYNEXT` or a `RAISE` without a value outside an `ERROR` handler.
    ///
    /// ### What it checks
    /// These statements continue or pass on the handling of an error, so they only
    /// make sense inside an `ERROR` handler.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     RETRY;      ! not in an ERROR handler
    /// ENDPROC
    /// ```
    pub static RULE = ("E405", "handler-only-statement", Error);
}

/// `RETRY`, `TRYNEXT` and the like outside an ERROR handler.
pub(crate) fn check(cx: &mut Cx<'_>, s: Node<'_>, what: &str) {
    if !(cx.routine.is_some() && cx.in_error_handler) {
        cx.report(
            &RULE,
            s.byte_range(),
            format!("{what} is only allowed in an ERROR handler"),
        );
    }
}
