crate::declare_rule! {
    /// A `CONST` declared without a value.
    ///
    /// ### What it checks
    /// A constant must be given its value where it is declared.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num max;     ! write  CONST num max := 10;
    /// ```
    pub static RULE = ("E402", "missing-initializer", Error);
}
