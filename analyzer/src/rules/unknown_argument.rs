crate::declare_rule! {
    /// A named argument (`\Name` or `Name:=`) that the routine does not have.
    ///
    /// ### What it checks
    /// Optional arguments and named required arguments must name a parameter of the
    /// routine.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine, tool0 \WObject:=wobj1;   ! the parameter is \WObj
    /// ```
    pub static RULE = ("E302", "unknown-argument", Error);
}
