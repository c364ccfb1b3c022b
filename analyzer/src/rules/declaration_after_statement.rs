crate::declare_rule! {
    /// Routine data declared after the routine's first statement.
    ///
    /// ### What it checks
    /// In a routine, every data declaration comes before the first statement.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     TPErase;
    ///     VAR num n;      ! move above TPErase
    /// ENDPROC
    /// ```
    pub static RULE = ("E408", "declaration-after-statement", Error);
}
