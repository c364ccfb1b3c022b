use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// A move that needs an axis of the task's robot beyond its working range.
    ///
    /// ### What it checks
    /// For a task whose robot is known, each move whose target, tool and work
    /// object are constants or persistents: the joint solution the controller
    /// would use (in the configuration the target's `confdata` names, unless
    /// `ConfL\Off` or `ConfJ\Off` is used in the task) and each axis against
    /// its working range (the `ARM` bounds of `MOC.cfg`, else the data
    /// sheet's). A `MoveAbsJ` target's axes are compared directly. The message
    /// names the axis, its angle and how many degrees it is past the limit.
    ///
    /// ### Why
    /// The controller stops the program at this move with event 50050
    /// "Position outside reach" (the axis is out of its working range);
    /// `CalcJointT` raises `ERR_ROBLIMIT`.
    ///
    /// ### Example
    /// ```rapid
    /// ! On an IRB 120 (axis 1 within ±165 degrees):
    /// CONST jointtarget jBack := [[170,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    /// MoveAbsJ jBack, v100, fine, tool0;   ! axis 1 is 5 degrees past 165
    /// ```
    pub static RULE = ("E602", "joint-out-of-range", Error);
}

/// Reports the target `what` at `range`: axis `axis` at `angle`, `by`
/// degrees beyond `bound`.
pub(crate) fn report(
    cx: &mut Cx<'_>,
    range: Range<usize>,
    what: &str,
    (axis, angle, bound, by): (usize, f64, f64, f64),
    robot: &str,
) {
    cx.report(
        &RULE,
        range,
        format!(
            "`{what}` needs axis {axis} of the {robot} at {angle:.1} degrees, {by:.1} beyond its working range (limit {bound:.1}): the controller stops with event 50050, Position outside reach"
        ),
    );
}
