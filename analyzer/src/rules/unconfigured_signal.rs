use tree_sitter::Node;

use crate::ty::Ty;

crate::declare_rule! {
    /// A name used as an I/O signal or a mechanical unit, with no controller configuration to check it against.
    ///
    /// ### What it checks
    /// Signals and mechanical units are configured on the controller (`EIO.cfg`
    /// and `MOC.cfg` in a backup's `SYSPAR` folder), not declared in RAPID. When
    /// no such configuration file was found for the task, an unknown name passed
    /// where a signal (or a `mecunit`) is expected, compared with a number
    /// (`IF diReady = 1`), or tested with number `CASE` values (`TEST giRecipe`:
    /// a group input when a value is past 0 and 1) is reported once, at this low
    /// severity, instead of as an unknown name. The finding names the type the
    /// strongest use gives: a name compared first and set later is an output;
    /// the name's other uses in the task (a read, `TPWrite "" \Num:=doLamp`)
    /// are listed with it, not reported as unknown names. Give the configuration (put
    /// `EIO.cfg` / `MOC.cfg` next to the modules or in a `SYSPAR` folder
    /// beside them, or name its folder in `rapid.toml`) to have these names
    /// checked; with it, an unknown name is
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
        let ty = self.types.base(expected).to_string().to_ascii_lowercase();
        if configured {
            let message = if mecunit {
                format!(
                    "no mechanical unit named `{name}` in the configuration ({file}), and no data of that name"
                )
            } else {
                format!(
                    "no signal named `{name}` (`{ty}`) in the configuration ({file}), and no data of that name"
                )
            };
            self.report_unresolved(node.byte_range(), message);
        } else {
            // Reported at every use; `check_unit` keeps the first per name.
            let kind = format!(" (`{ty}`)");
            self.report(
                &RULE,
                node.byte_range(),
                format!("`{name}` is taken to be {what}{kind}; without the controller's {file} it cannot be checked"),
            );
        }
    }
}

/// The signal or mechanical unit a diagnostic of this rule (or an
/// `unresolved-name` of a signal the configuration lacks) says a name is
/// taken for: its name and type (`signaldo`, `mecunit`), for a simulation
/// that declares it from its use.
pub fn taken_signal(d: &crate::diagnostic::Diagnostic) -> Option<(&str, &str)> {
    let m = d.message.as_str();
    let (name, rest) = if d.rule.code == RULE.code {
        let rest = m.strip_prefix('`')?;
        let (name, rest) = rest
            .split_once("` is taken to be an I/O signal (`")
            .or_else(|| rest.split_once("` is taken to be a mechanical unit (`"))?;
        (name, rest)
    } else {
        let rest = m.strip_prefix("no signal named `")?;
        rest.split_once("` (`")?
    };
    let (ty, _) = rest.split_once("`)")?;
    (ty.starts_with("signal") || ty == "mecunit").then_some((name, ty))
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use crate::task::{Task, Unit};

    /// The signals the checker takes from their use, as a simulation reads
    /// them back from its diagnostics.
    fn taken(text: &str) -> Vec<(String, String)> {
        let unit = Arc::new(Unit::new("m.mod".into(), text.into(), None));
        let task = Task::new(String::new(), vec![unit.clone()], None);
        crate::workspace::diagnostics_of(&task, &unit)
            .iter()
            .filter_map(|d| super::taken_signal(d).map(|(n, t)| (n.to_owned(), t.to_owned())))
            .collect()
    }

    #[test]
    fn the_signal_a_name_is_taken_for_is_read_back_with_its_type() {
        let text = "MODULE m\n  PROC main()\n    SetDO doGrip, 1;\n    WaitDI part, 1;\n    SetAO aoSpeed, 2;\n    IF sensor = 1 Stop;\n    ActUnit STN1;\n  ENDPROC\nENDMODULE\n";
        let pairs = |v: &[(&str, &str)]| -> Vec<(String, String)> {
            v.iter().map(|(a, b)| ((*a).into(), (*b).into())).collect()
        };
        assert_eq!(
            taken(text),
            pairs(&[
                ("doGrip", "signaldo"),
                ("part", "signaldi"),
                ("aoSpeed", "signalao"),
                ("sensor", "signaldi"),
                ("STN1", "mecunit"),
            ])
        );
    }

    /// A comparison or a `TEST` takes an input; a later use that sets the
    /// name makes it the output, the one finding of the name says so.
    #[test]
    fn a_name_read_first_and_set_later_is_taken_for_the_output() {
        let text = "MODULE m\n  PROC main()\n    IF doLamp = 0 SetDO doLamp, 1;\n    TEST goCode\n    CASE 3:\n      SetGO goCode, 4;\n    ENDTEST\n    IF diPart = 1 Stop;\n    WaitDI diPart, 1;\n  ENDPROC\nENDMODULE\n";
        let got = taken(text);
        let want: Vec<(String, String)> = [
            ("doLamp", "signaldo"),
            ("goCode", "signalgo"),
            ("diPart", "signaldi"),
        ]
        .iter()
        .map(|(a, b)| ((*a).into(), (*b).into()))
        .collect();
        assert_eq!(got, want);
    }
}
