crate::declare_rule! {
    /// An array index that is not a number.
    ///
    /// ### What it checks
    /// Every index of `a{i}` must be a `num` (or `dnum`) expression.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num a{3};
    /// a{"1"} := 0;
    /// ```
    pub static RULE = ("E202", "non-numeric-index", Error);
}
