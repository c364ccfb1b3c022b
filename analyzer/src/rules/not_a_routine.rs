crate::declare_rule! {
    /// A call of a name that is data or a type, not a routine.
    ///
    /// ### What it checks
    /// The name called resolves to a data object or a data type, not to a
    /// procedure, function or trap.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num speed;
    /// speed;      ! speed is data
    /// ```
    pub static RULE = ("E208", "not-a-routine", Error);
}
