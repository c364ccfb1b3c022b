crate::declare_rule! {
    /// A routine parameter that the routine never uses.
    ///
    /// ### What it checks
    /// A parameter that no statement of its routine reads or writes (an optional
    /// parameter tested with `Present` counts as used).
    ///
    /// ### Why
    /// Callers pass a value that has no effect, which is sometimes a mistake, but
    /// routines often keep a parameter for a common calling convention: this is
    /// a hint, shown faded in editors.
    ///
    /// ### Example
    /// ```rapid
    /// PROC place(robtarget p, num layer)
    ///     MoveL p, v100, fine, tool0;    ! layer is unused
    /// ENDPROC
    /// ```
    pub static RULE = ("W202", "unused-parameter", Hint);
}

/// The parameters of `decl`, the routine being checked, that no statement
/// used.
pub(crate) fn check(cx: &mut crate::check::Cx<'_>, decl: &crate::items::RoutineDecl) {
    for p in &decl.params {
        if !cx
            .used
            .contains(&crate::check::Used::RoutineSym(crate::names::fold(&p.name)))
        {
            cx.report(
                &RULE,
                p.name_range.clone(),
                format!("the parameter `{}` is never used", p.name),
            );
        }
    }
}
