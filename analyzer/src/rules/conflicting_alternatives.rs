crate::declare_rule! {
    /// Two arguments given for parameters that exclude each other (`|`).
    ///
    /// ### What it checks
    /// Parameters declared as alternatives, `\A | \B`, take at most one argument
    /// between them.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// TPWrite "Value" \Num:=1 \Bool:=TRUE;    ! \Num | \Bool | \Pos | \Orient
    /// ```
    pub static RULE = ("E304", "conflicting-alternatives", Error);
}
