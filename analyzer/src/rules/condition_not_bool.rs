crate::declare_rule! {
    /// An `IF`, `ELSEIF` or `WHILE` condition that is not a `bool`.
    ///
    /// ### What it checks
    /// Conditions must be `bool` expressions; RAPID does not treat numbers as truth
    /// values.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// WHILE nCount DO      ! write  WHILE nCount > 0 DO
    /// ```
    pub static RULE = ("E205", "condition-not-bool", Error);
}
