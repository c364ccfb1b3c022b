crate::declare_rule! {
    /// A `GOTO` to a label that the routine does not have.
    ///
    /// ### What it checks
    /// The label named by `GOTO` must be declared (`name:`) in the same routine.
    ///
    /// ### Why
    /// The controller rejects the routine.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     GOTO retry_point;   ! no label retry_point in main
    /// ENDPROC
    /// ```
    pub static RULE = ("E104", "unknown-label", Error);
}
