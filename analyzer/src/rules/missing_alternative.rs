crate::declare_rule! {
    /// None of a group of alternatives given where one is required.
    ///
    /// ### What it checks
    /// Some routines require exactly one argument from a group of alternatives.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// angle := EulerZYX(rot);     ! one of \X, \Y or \Z is required
    /// ```
    pub static RULE = ("E305", "missing-alternative", Error);
}
