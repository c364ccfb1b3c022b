crate::declare_rule! {
    /// A `GOTO` that jumps into another statement list.
    ///
    /// ### What it checks
    /// A `GOTO` may jump to a label in its own statement list or in a list that
    /// encloses it, but not into the body of an `IF`, `FOR`, `WHILE` or `TEST` that
    /// it is not inside.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// GOTO inside;
    /// IF di1 = 1 THEN
    ///     inside:
    ///     Stop;
    /// ENDIF
    /// ```
    pub static RULE = ("E406", "goto-into-block", Error);
}
