use std::ops::Range;

use crate::check::Cx;

crate::declare_rule! {
    /// A move to a target the task's robot cannot reach with the tool and work object given.
    ///
    /// ### What it checks
    /// For a task whose robot is known (the backup's `MOC.cfg`, or `robot` in
    /// `[controller]` of `rapid.toml`), each move instruction (`MoveL`, `MoveJ`,
    /// `MoveC`, their `DO`/`Sync` forms, `TriggL`, `SearchL`...) whose target, tool
    /// and work object are constants or persistents: the target is taken through
    /// the work object's user and object frames and the tool's TCP to the robot's
    /// mounting flange, and the arm's kinematics say whether any joint position
    /// puts the flange there. The message says by how many millimetres the wrist
    /// is out of the arm's reach. Values assigned at run time are not known and
    /// not checked. See [docs/robot.md](robot.md) for the models and what is
    /// modelled.
    ///
    /// ### Why
    /// The controller stops the program at this move with event 50050 "Position
    /// outside reach"; finding it on the real robot costs a trip to the cell.
    ///
    /// ### Example
    /// ```rapid
    /// ! On an IRB 120 (reach 580 mm):
    /// CONST robtarget pFar := [[900,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    /// MoveL pFar, v100, fine, tool0;   ! about 340 mm out of reach
    /// ```
    pub static RULE = ("E601", "target-out-of-reach", Error);
}

/// Reports the target `what` at `range`, `by` mm out of `robot`'s reach.
pub(crate) fn report(cx: &mut Cx<'_>, range: Range<usize>, what: &str, by: f64, robot: &str) {
    cx.report(
        &RULE,
        range,
        format!(
            "`{what}` is {by:.1} mm out of the reach of the {robot} with this tool and work object (the controller stops with event 50050, Position outside reach)"
        ),
    );
}
