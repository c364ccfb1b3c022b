use tree_sitter::Node;

use crate::check::Cx;
use crate::sema::signature::Signature;

crate::declare_rule! {
    /// A named argument (`\Name` or `Name:=`) that the routine does not have.
    ///
    /// ### What it checks
    /// Optional arguments and named required arguments must name a parameter of the
    /// routine.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine, tool0 \WObject:=wobj1;   ! the parameter is \WObj
    /// ```
    pub static RULE = ("E302", "unknown-argument", Error);
}

/// A named argument (its name node `n`) that no parameter of `sig` has.
pub(crate) fn report(cx: &mut Cx<'_>, sig: &Signature, n: Node<'_>) {
    let name = cx.node_text(n);
    let known: Vec<String> = sig
        .params
        .iter()
        .filter(|p| !p.positional())
        .map(|p| format!("\\{}", p.name))
        .collect();
    let hint = if known.is_empty() {
        "it has no optional parameters".to_owned()
    } else {
        format!("its optional parameters are {}", known.join(" "))
    };
    cx.report(
        &RULE,
        n.byte_range(),
        format!("`{}` has no parameter `{name}`; {hint}", sig.name),
    );
}
