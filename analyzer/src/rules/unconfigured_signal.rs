use tree_sitter::Node;

use crate::ty::Ty;

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

/// The checker reports names taken for signals here.
impl crate::check::Cx<'_> {
    /// A name where a signal (or a mechanical unit) is expected that nothing
    /// declares: without the configuration, say once that it cannot be checked.
    pub(crate) fn unknown_signal(&mut self, node: Node<'_>, name: &str, expected: &Ty) {
        let mecunit = self.types.base(expected).is("mecunit");
        let (configured, what, file) = if mecunit {
            (
                !self.task.mecunits.is_empty(),
                "a mechanical unit",
                "MOC.cfg",
            )
        } else {
            (self.task.signals.is_some(), "an I/O signal", "EIO.cfg")
        };
        if configured {
            let message = format!(
                "no {} named `{name}` in the configuration ({file}), and no data of that name",
                if mecunit { "mechanical unit" } else { "signal" }
            );
            self.report_unresolved(node.byte_range(), message);
        } else {
            // Reported at every use; `check_unit` keeps the first per name.
            self.report(
                &RULE,
                node.byte_range(),
                format!("`{name}` is taken to be {what}; without the controller's {file} it cannot be checked"),
            );
        }
    }
}
