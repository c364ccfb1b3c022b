//! Reach: the joint solution for a pose, the way the controller chooses it,
//! or the controller's error.

use nalgebra::{Isometry3, Vector3};

use crate::conf::{self, Conf};
use crate::kinematics::Joints;
use crate::{JointLimits, Robot};

/// A controller event: number and title, as the event log shows them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Event {
    pub number: u32,
    pub title: &'static str,
}

/// Event 50050: a programmed position the robot cannot reach, out of the
/// arm's reach or beyond an axis's working range.
pub const POSITION_OUTSIDE_REACH: Event = Event {
    number: 50050,
    title: "Position outside reach",
};
/// Event 50080: a position the robot reaches only in another configuration
/// than the programmed confdata (with ConfL/ConfJ on).
pub const POSITION_NOT_COMPATIBLE: Event = Event {
    number: 50080,
    title: "Position not compatible",
};
/// Event 50026: a linear move through a singularity.
pub const CLOSE_TO_SINGULARITY: Event = Event {
    number: 50026,
    title: "Close to singularity",
};

/// A joint solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solution {
    /// Degrees, axes 1 to 6.
    pub joints: Joints,
    /// Its confdata.
    pub conf: Conf,
}

/// Why a pose cannot be reached.
#[derive(Clone, Debug, PartialEq)]
pub enum ReachError {
    /// The wrist centre is outside the arm's reach, by `by` mm.
    OutOfReach { by: f64 },
    /// Reachable only with axis `axis` (1 to 6) at `angle`, beyond its
    /// working range (`bound`) by `by` degrees; `joints` is that solution.
    JointLimit {
        axis: usize,
        angle: f64,
        bound: f64,
        by: f64,
        joints: Joints,
    },
    /// Reachable within the working ranges, but not in configuration
    /// `wanted`; `found` is the nearest solution that is (by the largest
    /// axis difference from the configuration's quadrants).
    Configuration { wanted: Conf, found: Solution },
}

impl ReachError {
    /// The controller's event for a move to this position.
    pub fn event(&self) -> Event {
        match self {
            ReachError::Configuration { .. } => POSITION_NOT_COMPATIBLE,
            _ => POSITION_OUTSIDE_REACH,
        }
    }

    /// The RAPID error CalcJointT raises (RobotWare 5 and later):
    /// ERR_OUTSIDE_REACH out of reach, ERR_ROBLIMIT beyond a working range
    /// or in no solution of the programmed configuration.
    pub fn rapid_error(&self) -> &'static str {
        match self {
            ReachError::OutOfReach { .. } => "ERR_OUTSIDE_REACH",
            _ => "ERR_ROBLIMIT",
        }
    }
}

impl std::fmt::Display for ReachError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReachError::OutOfReach { by } => {
                write!(f, "the position is {by:.1} mm out of the arm's reach")
            }
            ReachError::JointLimit {
                axis,
                angle,
                bound,
                by,
                ..
            } => write!(
                f,
                "axis {axis} would be at {angle:.1} degrees, {by:.1} degrees beyond its limit of {bound:.1}"
            ),
            ReachError::Configuration { wanted, found } => write!(
                f,
                "the position is reachable in configuration {} but not in the programmed {wanted}",
                found.conf
            ),
        }
    }
}

/// How far (degrees) past a bound an axis may be and still count as
/// inside: a robtarget is stored in single precision, so the angles
/// recomputed from a target taught at a bound are off by some 0.001 degree.
pub const LIMIT_TOLERANCE_DEG: f64 = 0.01;

/// The axis furthest beyond its working range, if any: (axis 1-6, bound,
/// excess in degrees).
pub fn violation(limits: &JointLimits, j: &Joints) -> Option<(usize, f64, f64)> {
    let mut worst: Option<(usize, f64, f64)> = None;
    for (i, (a, [lo, hi])) in j.iter().zip(limits.0.iter()).enumerate() {
        let v = if *a < lo - LIMIT_TOLERANCE_DEG {
            Some((i + 1, *lo, lo - a))
        } else if *a > hi + LIMIT_TOLERANCE_DEG {
            Some((i + 1, *hi, a - hi))
        } else {
            None
        };
        if let Some(v) = v
            && worst.is_none_or(|w| v.2 > w.2)
        {
            worst = Some(v);
        }
    }
    worst
}

/// How far (mm) the wrist centre of tool0 at `pose` is out of the arm's
/// reach, in front of axis 1 or behind it, whichever is nearer; 0 inside.
pub fn out_of_reach_by(robot: &Robot, pose: &Isometry3<f64>) -> f64 {
    let o = &robot.model.opw;
    let wc = pose * nalgebra::Point3::new(0.0, 0.0, -o.c4);
    let forearm = (o.a2 * o.a2 + o.c3 * o.c3).sqrt();
    let (min, max) = ((o.c2 - forearm).abs(), o.c2 + forearm);
    let planar = (wc.x * wc.x + wc.y * wc.y - o.b * o.b).max(0.0).sqrt();
    [planar - o.a1, -planar - o.a1]
        .into_iter()
        .map(|x| {
            let r = Vector3::new(x, 0.0, wc.z - o.c1).norm();
            (r - max).max(min - r).max(0.0)
        })
        .fold(f64::INFINITY, f64::min)
}

/// The solution for tool0 at `pose` (base frame). With `conf`, the
/// solution must have that configuration (ConfL/ConfJ on); without, any
/// solution within the working ranges does: the one nearest `near` (the
/// robot's current joints) when given, else nearest all axes at zero.
pub fn reach(
    robot: &Robot,
    pose: &Isometry3<f64>,
    conf: Option<&Conf>,
    near: Option<&Joints>,
) -> Result<Solution, ReachError> {
    let base = robot.arm.inverse(pose);
    if base.is_empty() {
        return Err(ReachError::OutOfReach {
            by: out_of_reach_by(robot, pose).max(0.1),
        });
    }
    let mut all = conf::with_turns(&robot.model.limits, &base, conf);
    if let Some(c) = conf {
        let singular: Vec<Joints> = base
            .iter()
            .filter_map(|j| conf::at_singularity(j, c.cf4))
            .collect();
        all.extend(conf::with_turns(&robot.model.limits, &singular, conf));
    }
    let solution = |j: &Joints| Solution {
        joints: *j,
        conf: robot.conf_of(j),
    };
    let within: Vec<&Joints> = all
        .iter()
        .filter(|j| violation(&robot.limits, j).is_none())
        .collect();
    let distance = |a: &Joints, b: &Joints| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    let Some(want) = conf else {
        // Nearest the robot's joints, else nearest all axes at zero.
        let n = near.copied().unwrap_or([0.0; 6]);
        let best = within
            .iter()
            .min_by(|a, b| distance(a, &n).total_cmp(&distance(b, &n)));
        return match best {
            Some(j) => Ok(solution(j)),
            None => Err(least_violation(robot, all.iter())),
        };
    };
    let matching: Vec<&Joints> = all
        .iter()
        .filter(|j| conf::matches(&robot.arm, robot.model, j, want))
        .collect();
    if let Some(j) = matching
        .iter()
        .filter(|j| violation(&robot.limits, j).is_none())
        .min_by(|a, b| {
            let n = near.copied().unwrap_or([0.0; 6]);
            distance(a, &n).total_cmp(&distance(b, &n))
        })
    {
        return Ok(solution(j));
    }
    if !matching.is_empty() {
        return Err(least_violation(robot, matching.into_iter()));
    }
    match within.first() {
        Some(_) => {
            // The nearest configuration that works: fewest quadrant steps.
            let steps = |j: &Joints| {
                let c = robot.conf_of(j);
                (c.cf1 - want.cf1).abs()
                    + (c.cf4 - want.cf4).abs()
                    + (c.cf6 - want.cf6).abs()
                    + i32::from(c.cfx != want.cfx)
            };
            let best = within.iter().copied().min_by_key(|j| steps(j)).copied();
            match best {
                Some(j) => Err(ReachError::Configuration {
                    wanted: *want,
                    found: solution(&j),
                }),
                None => Err(least_violation(robot, all.iter())),
            }
        }
        None => Err(least_violation(robot, all.iter())),
    }
}

/// [`Robot::move_to`].
pub fn move_to(
    robot: &Robot,
    pose: &Isometry3<f64>,
    conf: Option<&Conf>,
) -> Result<Solution, ReachError> {
    let any = reach(robot, pose, None, None);
    match (any, conf) {
        (Ok(_), Some(c)) => reach(robot, pose, Some(c), None),
        (any, _) => any,
    }
}

/// [`Robot::solutions`].
pub fn solutions(robot: &Robot, pose: &Isometry3<f64>) -> Vec<Solution> {
    let base = robot.arm.inverse(pose);
    // Turns within the data sheet's ranges or the controller's, whichever
    // are wider; the controller's decide what is within.
    let mut ranges = robot.model.limits;
    for (r, l) in ranges.iter_mut().zip(robot.limits.0) {
        r[0] = r[0].min(l[0]);
        r[1] = r[1].max(l[1]);
    }
    let mut out: Vec<Solution> = Vec::new();
    for j in conf::with_turns(&ranges, &base, None) {
        let seen = out
            .iter()
            .any(|s| s.joints.iter().zip(&j).all(|(a, b)| (a - b).abs() < 1e-6));
        if seen || violation(&robot.limits, &j).is_some() {
            continue;
        }
        out.push(Solution {
            joints: j,
            conf: robot.conf_of(&j),
        });
    }
    out.sort_by(|a, b| {
        let key = |s: &Solution| (s.conf.cfx, s.conf.cf1, s.conf.cf4, s.conf.cf6);
        key(a).cmp(&key(b)).then_with(|| {
            a.joints
                .iter()
                .zip(&b.joints)
                .map(|(x, y)| x.total_cmp(y))
                .find(|o| o.is_ne())
                .unwrap_or(std::cmp::Ordering::Equal)
        })
    });
    out
}

/// The joint-limit error of the solution that misses its limits least.
fn least_violation<'a>(robot: &Robot, solutions: impl Iterator<Item = &'a Joints>) -> ReachError {
    let mut best: Option<ReachError> = None;
    let mut best_by = f64::INFINITY;
    for j in solutions {
        if let Some((axis, bound, by)) = violation(&robot.limits, j)
            && by < best_by
        {
            best_by = by;
            best = Some(ReachError::JointLimit {
                axis,
                angle: j[axis - 1],
                bound,
                by,
                joints: *j,
            });
        }
    }
    best.unwrap_or(ReachError::OutOfReach { by: 0.1 })
}
