crate::declare_rule! {
    /// A built-in that the configured RobotWare version does not have.
    ///
    /// ### What it checks
    /// With `[controller] robotware = "6.08"` in `rapid.toml` (or the version
    /// a backup's `BACKINFO` names), a use of a built-in routine, data type
    /// or datum that a later RobotWare added, or that an earlier one
    /// removed. Reported once per name and file, with the other uses as
    /// related locations. Without a configured version nothing is reported:
    /// every version's built-ins are accepted.
    ///
    /// ### Why
    /// The controller refuses to load a module that uses a name its
    /// RobotWare does not know.
    ///
    /// ### Example
    /// ```rapid
    /// ! rapid.toml: [controller] robotware = "5.15"
    /// PROC main()
    ///     EGMReset egmId;  ! EGM needs RobotWare 6
    /// ENDPROC
    /// ```
    pub static RULE = ("W102", "builtin-version", Warning);
}
