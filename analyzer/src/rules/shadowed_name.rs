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
