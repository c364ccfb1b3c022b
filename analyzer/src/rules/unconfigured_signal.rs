crate::declare_rule! {
    /// A name used as an I/O signal or a mechanical unit, with no controller configuration to check it against.
    ///
    /// ### What it checks
    /// Signals and mechanical units are configured on the controller (`EIO.cfg`
    /// and `MOC.cfg` in a backup's `SYSPAR` folder), not declared in RAPID. When
    /// no such configuration file was found for the task, an unknown name passed
    /// where a signal (or a `mecunit`) is expected is reported once, at this low
    /// severity, instead of as an unknown name. Give the configuration (put
    /// `EIO.cfg` / `MOC.cfg` next to the modules, or name its folder in
    /// `rapid.toml`) to have these names checked; with it, an unknown name is
    /// reported as `unresolved-name`.
    ///
    /// ### Why
    /// Without the configuration, every signal and unit would otherwise look like
    /// an undeclared name.
    ///
    /// ### Example
    /// ```rapid
    /// PROC grip()
    ///     SetDO doGripper, 1;   ! doGripper is configured in EIO.cfg
    ///     ActUnit STN_1;        ! STN_1 is configured in MOC.cfg
    /// ENDPROC
    /// ```
    pub static RULE = ("I103", "unconfigured-signal", Info);
}
