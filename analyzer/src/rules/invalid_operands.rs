crate::declare_rule! {
    /// An operator applied to operands of types it does not take.
    ///
    /// ### What it checks
    /// RAPID's operators take fixed types: arithmetic on `num` and `dnum`, `+` on
    /// strings, `+ - *` on `pos`, `*` on `orient`, `AND OR XOR NOT` on `bool`,
    /// ordering comparisons on numbers, `=` and `<>` on two values of one type.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// IF bReady + 1 > 0 THEN    ! a bool cannot be added to
    /// ```
    pub static RULE = ("E204", "invalid-operands", Error);
}
