use std::ops::Range;

use crate::catalogue::Package;
use crate::check::Cx;

crate::declare_rule! {
    /// A built-in of a RobotWare option that is not enabled.
    ///
    /// ### What it checks
    /// A use of a routine, data type or datum that an option package brings
    /// (Arc welding, EGM, Force Control...; see `catalogue/data/options/`)
    /// while the option is not listed in `[controller] options` of
    /// `rapid.toml` nor installed according to the backup's `BACKINFO`.
    /// Reported once per name and file, with the other uses as related
    /// locations. The name is known, so it is never reported as unresolved,
    /// and its arguments are checked where the option's documentation gives
    /// the signature.
    ///
    /// ### Why
    /// Says which option the code needs, so a controller without it is not a
    /// surprise.
    ///
    /// ### Example
    /// ```rapid
    /// PROC weld()
    ///     ArcLStart p10, v100, seam1, weld1, fine, tWeldGun;  ! Arc option
    /// ENDPROC
    /// ```
    pub static RULE = ("I102", "option-routine", Info);
}

/// The built-in `name`, used at `range`, of the option `p`, which the
/// controller does not have.
pub(crate) fn report(cx: &mut Cx<'_>, name: &str, p: &Package, range: Range<usize>) {
    let message = format!(
        "`{name}` needs the {} option (`{}` in [controller] options), which is not enabled",
        p.name, p.id
    );
    cx.report(&RULE, range, message);
}
