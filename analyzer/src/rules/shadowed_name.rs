use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// Routine data or a parameter with the name of a global or built-in.
    ///
    /// ### What it checks
    /// A name declared in a routine hides a global of the task or a built-in of the
    /// same name within the routine.
    ///
    /// ### Why
    /// Reading the routine, one easily takes the name for the global or built-in
    /// one. Real programs do this on purpose all the time (a routine's own `i` or
    /// `pTemp`), so the rule is off unless a project selects it.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     VAR tooldata tool0;     ! hides the built-in tool0
    /// ENDPROC
    /// ```
    pub static RULE = ("W205", "shadowed-name", Warning, off);
}

/// A routine's data or parameter that hides a module or task name, or (for
/// routine data only) a built-in one. Parameters named like a built-in
/// (`speed`, `tool`...) are common and harmless: the parameter is the
/// routine's interface, and the built-in is rarely wanted inside.
pub(crate) fn check(cx: &mut Cx<'_>, name: &str, range: Range<usize>, builtins: bool) {
    let visible = cx
        .lookup_items(name)
        .into_iter()
        .find(|r| cx.task.data(*r).is_some() || cx.task.routine(*r).is_some());
    let what = if let Some(r) = visible {
        let module = cx
            .task
            .module(r)
            .map(|m| m.name.clone())
            .unwrap_or_default();
        let local = cx
            .task
            .data(r)
            .is_some_and(|d| d.scope == crate::items::Scope::Local)
            || cx.task.routine(r).is_some_and(|d| d.local);
        format!(
            "the {} `{name}` of module {module}",
            if local { "LOCAL" } else { "global" }
        )
    } else if !builtins {
        return;
    } else if cx.cat.datum(name).is_some() {
        format!("the built-in data `{name}`")
    } else if cx.cat.routine(name).is_some() {
        format!("the built-in routine `{name}`")
    } else {
        return;
    };
    cx.report(
        &RULE,
        range,
        format!("this declaration hides {what} within the routine"),
    );
}
