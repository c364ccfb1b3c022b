crate::declare_rule! {
    /// Too few or too many arguments for a routine's required parameters.
    ///
    /// ### What it checks
    /// Every required parameter must get an argument, and there may not be more
    /// positional arguments than required parameters. Optional arguments are
    /// written with `\` and do not count here.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine;     ! the Tool argument is missing
    /// ```
    pub static RULE = ("E301", "argument-count", Error);
}
