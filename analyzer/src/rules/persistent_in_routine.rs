use tree_sitter::Node;

use crate::check::Cx;
use crate::items::{DataDecl, Storage};
use crate::syntax::field;
use crate::syntax_util::field;

crate::declare_rule! {
    /// A persistent (`PERS`) declared inside a routine.
    ///
    /// ### What it checks
    /// Routine data can be `VAR` or `CONST`. A persistent keeps its value in
    /// the module's source and can be shared between tasks, so it belongs to
    /// the module: declare it at module level.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///   PERS num count := 0;     ! move it to the module, or make it VAR
    /// ENDPROC
    /// ```
    pub static RULE = ("E414", "persistent-in-routine", Error);
}

/// Routine data `decl` (its node `node`).
pub(crate) fn check(cx: &mut Cx<'_>, node: Node<'_>, decl: &DataDecl) {
    if decl.storage != Storage::Pers {
        return;
    }
    let at = field(node, field::STORAGE).map_or(decl.name_range.clone(), |s| s.byte_range());
    cx.report(
        &RULE,
        at,
        format!(
            "`{}` is a persistent declared in a routine; declare it at module level, or make it VAR",
            decl.name
        ),
    );
}
