use std::ops::Range;

use rapid_robot::Conf;

use crate::check::Cx;

crate::declare_rule! {
    /// A target that the task's robot reaches, but not in the configuration its `confdata` names.
    ///
    /// ### What it checks
    /// For a task whose robot is known, each move whose target, tool and work
    /// object are constants or persistents, while the task never turns
    /// configuration monitoring off (`ConfL\Off` for linear and circular moves,
    /// `ConfJ\Off` for joint moves): among the joint solutions within the
    /// working ranges, one must have the target's `cf1`, `cf4` and `cf6` (the
    /// quadrants of axes 1, 4 and 6) and, on robots that use it, `cfx` (the arm
    /// configuration: wrist centre in front of or behind axis 1 and the lower
    /// arm, axis 5 positive or negative). Quadrant edges count for both sides
    /// within a degree. The message names the configuration the robot can
    /// reach the target in.
    ///
    /// ### Why
    /// With configuration monitoring on (the default), the controller stops
    /// the program at this move with event 50080 "Position not compatible".
    /// A target whose `confdata` was typed by hand, or copied from another
    /// target, is the usual cause.
    ///
    /// ### Example
    /// ```rapid
    /// ! Axis 6 at 10 degrees is quadrant 0, not 2:
    /// CONST robtarget p10 := [[400,0,400],[0,0,1,0],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    /// ```
    pub static RULE = ("W601", "configuration-mismatch", Warning);
}

/// Reports the target `what` at `range`: programmed in `wanted`, reachable
/// in `found`.
pub(crate) fn report(
    cx: &mut Cx<'_>,
    range: Range<usize>,
    what: &str,
    (wanted, found): (Conf, Conf),
    robot: &str,
) {
    cx.report(
        &RULE,
        range,
        format!(
            "`{what}` has confdata {wanted}, but the {robot} reaches it only in {found}: with ConfL/ConfJ on, the controller stops with event 50080, Position not compatible"
        ),
    );
}
