use std::ops::Range;

use crate::check::Cx;
use crate::diagnostic::Diagnostic;
use crate::task::ItemRef;

crate::declare_rule! {
    /// A name used outside the module that declares it `LOCAL`.
    ///
    /// ### What it checks
    /// A declaration prefixed with `LOCAL` is visible only in its own module. The
    /// name is declared, but not for the module that uses it.
    ///
    /// ### Why
    /// The controller fails to link the module that uses the name.
    ///
    /// ### Example
    /// ```rapid
    /// ! in Tools.mod
    /// LOCAL PROC helper() ... ENDPROC
    /// ! in MainModule.mod
    /// helper;     ! helper is LOCAL to Tools
    /// ```
    pub static RULE = ("E108", "local-not-visible", Error);
}

/// `name` at `range`, which resolves to nothing here but is the `LOCAL`
/// item `r` of another module.
pub(crate) fn report(cx: &mut Cx<'_>, name: &str, range: Range<usize>, r: ItemRef) {
    let module = cx
        .task
        .module(r)
        .map(|m| m.name.clone())
        .unwrap_or_default();
    let mut d = Diagnostic::new(
        &RULE,
        range,
        format!("`{name}` is declared LOCAL in module {module} and cannot be used here"),
    );
    if let Some(rel) = cx.related_item(r, "declared LOCAL here") {
        d = d.with_related(rel);
    }
    cx.report_with(d);
}
