use std::ops::Range;

use crate::catalogue::Availability;
use crate::check::Cx;

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

/// The built-in `name`, used at `range`, that the controller's RobotWare
/// version lacks (added later, or removed).
pub(crate) fn report(
    cx: &mut Cx<'_>,
    name: &str,
    availability: &Availability<'_>,
    range: Range<usize>,
) {
    let message = match availability {
        Availability::Newer { since, selected } => {
            format!("`{name}` is not in RobotWare {selected}; added in {since}")
        }
        Availability::Removed { until, selected } => {
            format!("`{name}` is not in RobotWare {selected}; removed in {until}")
        }
        _ => return,
    };
    cx.report(&RULE, range, message);
}
