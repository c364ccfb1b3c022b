crate::declare_rule! {
    /// An assignment to a constant, a `FOR` loop variable or read-only data.
    ///
    /// ### What it checks
    /// Only variables, persistents and parameters can be assigned. `CONST` data,
    /// the loop variable of a `FOR`, and read-only system data such as `ERRNO`
    /// cannot.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num max := 10;
    /// max := 20;
    /// ```
    pub static RULE = ("E401", "assign-to-constant", Error);
}
