crate::declare_rule! {
    /// A conditional argument `\A?x` where `x` is not an optional parameter of the calling routine.
    ///
    /// ### What it checks
    /// `\A?x` passes the caller's optional parameter `x` on, only if the caller was
    /// given it. `x` must therefore be an optional parameter of the routine that
    /// makes the call.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// PROC go(robtarget p)
    ///     MoveL p, v100, fine, tool0 \WObj?wobj;   ! go has no optional parameter wobj
    /// ENDPROC
    /// ```
    pub static RULE = ("E309", "conditional-argument", Error);
}
