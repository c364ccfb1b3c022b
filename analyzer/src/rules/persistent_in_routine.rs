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
