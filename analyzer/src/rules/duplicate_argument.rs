crate::declare_rule! {
    /// The same parameter given twice.
    ///
    /// ### What it checks
    /// Each parameter takes at most one argument.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine, tool0 \WObj:=wobj1 \WObj:=wobj2;
    /// ```
    pub static RULE = ("E306", "duplicate-argument", Error);
}
