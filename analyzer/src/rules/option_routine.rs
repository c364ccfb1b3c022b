crate::declare_rule! {
    /// A routine from a RobotWare option or vendor package that the catalogue lists but does not check.
    ///
    /// ### What it checks
    /// A call of a routine that belongs to an option or a vendor package (see
    /// `analyzer/catalogue/option_routines.toml`). Its signature is not known, so
    /// its arguments are not checked.
    ///
    /// ### Why
    /// Says why a call is not checked, without calling the name unknown.
    ///
    /// ### Example
    /// ```rapid
    /// PROC weld()
    ///     ArcLStart p10, v100, seam1, weld1, fine, tWeldGun;  ! Arc option
    /// ENDPROC
    /// ```
    pub static RULE = ("I102", "option-routine", Info);
}
