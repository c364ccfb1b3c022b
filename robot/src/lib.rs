//! The robot behind a RAPID program: ABB's six-axis arms as data, their
//! kinematics in the controller's conventions, joint limits, reach with the
//! controller's errors, and the time a move takes.
//!
//! - [`model`]: the models (`data/models.toml`, each parameter with its
//!   public source), looked up by ABB's name or MOC.cfg's robot type
//!   ([`model_by_name`], [`lookup`]); arms outside the family are named as
//!   unsupported.
//! - [`kinematics`]: forward and inverse kinematics on `rs-opw-kinematics`,
//!   in degrees and mm, with ABB's joint zero, directions and axis 2-3
//!   coupling.
//! - [`conf`]: confdata (cf1, cf4, cf6, cfx) of a solution and the choice
//!   of a solution by confdata.
//! - [`frames`]: robtarget, tooldata and wobjdata values (from the
//!   evaluator) and the pose of tool0 they ask for.
//! - [`reach()`]: a pose to a joint solution, or the controller's error
//!   ([`ReachError`], with its event number and RAPID error).
//! - [`motion`]: the time of a move from its speeddata and the axes' speeds.
//!
//! [`Robot`] holds a model with the controller's joint limits and base
//! frame: what a task's moves are computed with.
//!
//! ```
//! use rapid_robot::{Conf, Robot, model_by_name};
//! let robot = Robot::new(model_by_name("IRB 120-3/0.58").unwrap());
//! let home = robot.forward(&[0.0; 6]).unwrap();
//! assert!((home.translation.vector.x - 374.0).abs() < 1e-6);
//! let back = robot.reach(&home, Some(&Conf::default())).unwrap();
//! assert!(back.joints.iter().all(|a| a.abs() < 1e-6));
//! ```

pub mod conf;
pub mod frames;
pub mod kinematics;
pub mod model;
pub mod motion;
mod reach;

use nalgebra::Isometry3;

pub use conf::Conf;
pub use kinematics::{Arm, ArmPoints, Joints};
pub use model::{Lookup, Model, find_model, lookup, model_by_name, models};
pub use reach::{
    CLOSE_TO_SINGULARITY, Event, LIMIT_TOLERANCE_DEG, POSITION_NOT_COMPATIBLE,
    POSITION_OUTSIDE_REACH, ReachError, Solution, out_of_reach_by, violation,
};

/// The working range of each axis, degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointLimits(pub [[f64; 2]; 6]);

impl JointLimits {
    /// The model's data-sheet ranges.
    pub fn of(model: &Model) -> JointLimits {
        JointLimits(model.limits)
    }

    /// These limits with MOC.cfg's ARM bounds (radians, `-lower_joint_bound`
    /// and `-upper_joint_bound` of each axis) where given.
    pub fn with_moc_bounds(mut self, bounds: &[(Option<f64>, Option<f64>); 6]) -> JointLimits {
        for (l, (lo, hi)) in self.0.iter_mut().zip(bounds) {
            if let Some(lo) = lo.filter(|v| v.is_finite()) {
                l[0] = lo.to_degrees();
            }
            if let Some(hi) = hi.filter(|v| v.is_finite()) {
                l[1] = hi.to_degrees();
            }
        }
        self
    }
}

/// A robot as a controller has it: a model, its joint limits and where its
/// base frame is in the world.
#[derive(Clone, Debug)]
pub struct Robot {
    pub model: &'static Model,
    pub limits: JointLimits,
    /// The base frame in the world frame (MOC.cfg's base frame; identity
    /// by default).
    pub base: Isometry3<f64>,
    arm: Arm,
}

impl PartialEq for Robot {
    fn eq(&self, other: &Robot) -> bool {
        self.model == other.model && self.limits == other.limits && self.base == other.base
    }
}

impl Robot {
    /// The model with its data-sheet limits, based at the world's origin.
    pub fn new(model: &'static Model) -> Robot {
        Robot {
            model,
            limits: JointLimits::of(model),
            base: Isometry3::identity(),
            arm: Arm::new(model),
        }
    }

    pub fn with_limits(mut self, limits: JointLimits) -> Robot {
        self.limits = limits;
        self
    }

    pub fn with_base(mut self, base: Isometry3<f64>) -> Robot {
        self.base = base;
        self
    }

    /// The kinematics.
    pub fn arm(&self) -> &Arm {
        &self.arm
    }

    /// tool0's pose in the base frame at joints `j` (degrees).
    pub fn forward(&self, j: &Joints) -> Option<Isometry3<f64>> {
        self.arm.forward(j)
    }

    /// confdata of joints `j`.
    pub fn conf_of(&self, j: &Joints) -> Conf {
        conf::conf_of(&self.arm, self.model, j)
    }

    /// The solution for tool0 at `pose` (base frame), in configuration
    /// `conf` when given (ConfJ/ConfL on), else any within the limits.
    pub fn reach(
        &self,
        pose: &Isometry3<f64>,
        conf: Option<&Conf>,
    ) -> Result<Solution, ReachError> {
        reach::reach(self, pose, conf, None)
    }

    /// The solution a move instruction gets for tool0 at `pose` (base
    /// frame), or the controller's error for it: out of reach, or beyond a
    /// working range in every configuration, whatever the confdata; else,
    /// with `conf` (ConfL/ConfJ on), the solution in that configuration or
    /// the configuration error. What `rapid check` reports for a move.
    pub fn move_to(
        &self,
        pose: &Isometry3<f64>,
        conf: Option<&Conf>,
    ) -> Result<Solution, ReachError> {
        reach::move_to(self, pose, conf)
    }

    /// Every joint solution for tool0 at `pose` (base frame) within the
    /// working ranges: each configuration, with every turn of an axis that
    /// its range holds (axes 4 and 6 often have two), ordered by
    /// configuration. At a wrist singularity (axis 5 at zero) any split of
    /// the rotation between axes 4 and 6 is a solution; the list holds the
    /// solver's. Empty when the pose is out of reach or beyond the ranges.
    pub fn solutions(&self, pose: &Isometry3<f64>) -> Vec<Solution> {
        reach::solutions(self, pose)
    }

    /// As [`Robot::reach`], preferring the solution nearest joints `near`
    /// (the robot's position before the move).
    pub fn reach_near(
        &self,
        pose: &Isometry3<f64>,
        conf: Option<&Conf>,
        near: &Joints,
    ) -> Result<Solution, ReachError> {
        reach::reach(self, pose, conf, Some(near))
    }

    /// The joint solution for a robtarget with a tool and work object
    /// (CalcJointT; ConfJ/ConfL on when `use_conf`).
    pub fn calc_joint_t(
        &self,
        target: &frames::RobTarget,
        tool: &frames::Tool,
        wobj: &frames::WObj,
        use_conf: bool,
    ) -> Result<Solution, ReachError> {
        let flange = frames::flange_in_base(&target.pose, tool, wobj, &self.base);
        self.reach(&flange, use_conf.then_some(&target.conf))
    }

    /// The robtarget's pose and confdata for joints `j` with a tool and work
    /// object (CalcRobT); `None` for angles that are not finite.
    pub fn calc_rob_t(
        &self,
        j: &Joints,
        tool: &frames::Tool,
        wobj: &frames::WObj,
    ) -> Option<(Isometry3<f64>, Conf)> {
        let flange = self.forward(j)?;
        Some((
            frames::target_of_flange(&flange, tool, wobj, &self.base),
            self.conf_of(j),
        ))
    }
}

/// The solution for tool0 at `pose` in the robot's base frame, in
/// configuration `conf` when given: the simple entry point for tools that
/// ask "is this target still reachable?".
pub fn reach(
    model: &'static Model,
    limits: &JointLimits,
    pose: &Isometry3<f64>,
    conf: Option<&Conf>,
) -> Result<Solution, ReachError> {
    Robot::new(model).with_limits(*limits).reach(pose, conf)
}
