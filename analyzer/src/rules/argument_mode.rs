crate::declare_rule! {
    /// An argument that cannot be passed to a VAR, PERS or INOUT parameter.
    ///
    /// ### What it checks
    /// A `VAR` parameter needs a variable, a `PERS` parameter a persistent, and an
    /// `INOUT` parameter a variable or a persistent: something the routine can
    /// write to. A literal, an expression, a constant or a `FOR` loop variable
    /// cannot be passed.
    ///
    /// ### Why
    /// The controller rejects the module; the routine would have nowhere to store
    /// its result.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num limit := 10;
    /// Incr limit;      ! Incr changes its argument: limit is a constant
    /// ```
    pub static RULE = ("E307", "argument-mode", Error);
}
