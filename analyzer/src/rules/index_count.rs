crate::declare_rule! {
    /// Indexing with the wrong number of indexes, or indexing something that is not an array.
    ///
    /// ### What it checks
    /// `a{i}` needs `a` to be an array, and the number of indexes must equal its
    /// number of dimensions.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num grid{3,4};
    /// grid{2} := 0;     ! grid has two dimensions
    /// ```
    pub static RULE = ("E206", "index-count", Error);
}
