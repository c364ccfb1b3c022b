crate::declare_rule! {
    /// A name used outside the module that declares it `LOCAL`.
    ///
    /// ### What it checks
    /// A declaration prefixed with `LOCAL` is visible only in its own module. The
    /// name is declared, but not for the module that uses it.
    ///
    /// ### Why
    /// The controller fails to link the module that uses the name.
    ///
    /// ### Example
    /// ```rapid
    /// ! in Tools.mod
    /// LOCAL PROC helper() ... ENDPROC
    /// ! in MainModule.mod
    /// helper;     ! helper is LOCAL to Tools
    /// ```
    pub static RULE = ("E108", "local-not-visible", Error);
}
