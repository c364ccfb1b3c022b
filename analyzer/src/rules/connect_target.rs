crate::declare_rule! {
    /// `CONNECT` with something other than an `intnum` variable and a trap routine.
    ///
    /// ### What it checks
    /// `CONNECT intno WITH trap` needs a variable of type `intnum` and the name of
    /// a `TRAP` routine.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num irq;
    /// CONNECT irq WITH main;     ! irq must be an intnum, main a TRAP
    /// ```
    pub static RULE = ("E407", "connect-target", Error);
}
