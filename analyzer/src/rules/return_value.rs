crate::declare_rule! {
    /// `RETURN` without a value in a function, or with one in a procedure or trap.
    ///
    /// ### What it checks
    /// A function returns a value of its type with `RETURN value;`; procedures and
    /// traps end with a plain `RETURN;`.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// FUNC num twice(num x)
    ///     RETURN;        ! the value is missing
    /// ENDFUNC
    /// ```
    pub static RULE = ("E403", "return-value", Error);
}
