crate::declare_rule! {
    /// An array with more than three dimensions.
    ///
    /// ### What it checks
    /// RAPID arrays have one, two or three dimensions.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num cube{2,2,2,2};
    /// ```
    pub static RULE = ("E409", "too-many-dimensions", Error);
}
