crate::declare_rule! {
    /// A function called as an instruction, or an instruction called as a function.
    ///
    /// ### What it checks
    /// A function returns a value and is called inside an expression with
    /// parentheses; an instruction (procedure) is a statement of its own. Calling a
    /// function as a statement throws its result away, which RAPID does not allow;
    /// calling a procedure in an expression has no value to use.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// Abs reg1;             ! Abs is a function: reg1 := Abs(reg1);
    /// reg2 := MoveL(p10);  ! MoveL is an instruction
    /// ```
    pub static RULE = ("E207", "call-kind-mismatch", Error);
}
