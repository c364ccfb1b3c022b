crate::declare_rule! {
    /// A name used as an I/O signal, with no I/O configuration to check it against.
    ///
    /// ### What it checks
    /// Signals are configured on the controller (`EIO.cfg` in a backup's `SYSPAR`
    /// folder), not declared in RAPID. When no configuration file was found for the
    /// task, an unknown name passed where a signal is expected is reported once, at
    /// this low severity, instead of as an unknown name. Give the configuration
    /// (put `EIO.cfg` next to the modules, or name its folder in `rapid.toml`) to
    /// have signal names checked.
    ///
    /// ### Why
    /// Without the configuration, every signal would otherwise look like an
    /// undeclared name.
    ///
    /// ### Example
    /// ```rapid
    /// PROC grip()
    ///     SetDO doGripper, 1;   ! doGripper is configured in EIO.cfg
    /// ENDPROC
    /// ```
    pub static RULE = ("I103", "unconfigured-signal", Info);
}
