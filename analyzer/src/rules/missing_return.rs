crate::declare_rule! {
    /// A function that can reach its end without `RETURN`.
    ///
    /// ### What it checks
    /// Every path through a function's statements must end in `RETURN value`,
    /// `RAISE`, `EXIT` or a jump. Branches count only when every branch returns (an
    /// `IF` with an `ELSE`, a `TEST` with a `DEFAULT`).
    ///
    /// ### Why
    /// Reaching the end of a function without a value stops the program with an
    /// error at run time. The controller loads the module (real backups hold
    /// such functions, whose last branch is never reached in practice), so this
    /// is a warning, not an error.
    ///
    /// ### Example
    /// ```rapid
    /// FUNC num sign(num x)
    ///     IF x < 0 THEN
    ///         RETURN -1;
    ///     ENDIF
    /// ENDFUNC           ! nothing is returned when x >= 0
    /// ```
    pub static RULE = ("E404", "missing-return", Warning);
}
