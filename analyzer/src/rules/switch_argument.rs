crate::declare_rule! {
    /// A switch given a value, or an optional argument given without one.
    ///
    /// ### What it checks
    /// A `switch` parameter is given as `\Name` alone; any other optional parameter
    /// needs a value, `\Name:=value` (or `\Name?param` to pass on an optional
    /// parameter).
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine, tool0 \WObj;      ! \WObj needs a value
    /// TPWrite "x" \Num;                       ! likewise
    /// ```
    pub static RULE = ("E303", "switch-argument", Error);
}
