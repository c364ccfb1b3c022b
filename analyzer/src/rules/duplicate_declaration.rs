crate::declare_rule! {
    /// Two declarations of the same name in one scope.
    ///
    /// ### What it checks
    /// Within one module (data, routines, records and aliases share one name space)
    /// and within one routine (parameters and routine data), every name must be
    /// declared once. Names are compared without regard to case.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num count;
    /// VAR num Count;    ! same name as count
    /// ```
    pub static RULE = ("E106", "duplicate-declaration", Error);
}
