//! How long a move takes: the stated model.
//!
//! - Each quantity that limits a move (the TCP's path length against
//!   speeddata's `v_tcp`, the tool's reorientation against `v_ori`, each
//!   axis's travel against its maximum speed from the data sheet) runs a
//!   trapezoidal profile: constant acceleration up to its speed, cruise,
//!   constant deceleration. The slowest one sets the move's time and the
//!   others are slowed to finish with it (synchronised motion).
//! - Accelerations are not published in ABB's data sheets: an axis
//!   reaches its maximum speed in [`AXIS_ACCEL_TIME`] seconds, the TCP
//!   accelerates at [`TCP_ACCEL`] mm/s² and reorients at
//!   [`ORI_ACCEL`] deg/s². These are stated assumptions, not measurements.
//! - A move ending in `fine` (or a stop point) decelerates to rest; a move
//!   ending in a zone hands its speed to the next move: neither its
//!   deceleration nor the next move's acceleration is counted. Corner
//!   paths are not shortened (the path is the programmed one).
//! - MoveJ and MoveAbsJ interpolate joints: each axis travels its
//!   difference; the TCP's straight distance against `v_tcp` bounds the time
//!   from below (the TCP's real path is longer). MoveL and MoveC follow the
//!   TCP's line or arc; the axes' travel is summed over samples of the path
//!   (each sample solved near the last), which also finds joint-limit
//!   crossings and singularities on the way.
//! - `AccSet`'s `Acc` scales every acceleration ([`Ends::accel`]); its
//!   `Ramp` (the jerk) is not modelled: the profiles change acceleration
//!   at once. The caller scales speeds (`VelSet`, speed overrides).
//! - Not modelled: dynamics and payload (the controller slows heavy or
//!   far-reaching motion), path
//!   smoothing beyond the rule above, external axes' own limits
//!   (`v_leax`/`v_reax` bound only moves of external axes that are given).

use nalgebra::{Isometry3, UnitQuaternion, Vector3};

use crate::conf::Conf;
use crate::kinematics::Joints;
use crate::{ReachError, Robot, Solution};

/// Seconds an axis takes from rest to its maximum speed (assumption).
pub const AXIS_ACCEL_TIME: f64 = 0.2;
/// The TCP's acceleration, mm/s² (assumption).
pub const TCP_ACCEL: f64 = 10_000.0;
/// Reorientation acceleration, deg/s² (assumption).
pub const ORI_ACCEL: f64 = 2_000.0;
/// Path samples per 10 mm of TCP travel or per degree of reorientation in
/// a linear or circular move (at least 8, at most 2000).
const SAMPLES_PER_10MM: f64 = 1.0;

/// speeddata.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Speed {
    /// TCP speed, mm/s.
    pub v_tcp: f64,
    /// Reorientation speed, deg/s.
    pub v_ori: f64,
    /// Linear external axes, mm/s.
    pub v_leax: f64,
    /// Rotating external axes, deg/s.
    pub v_reax: f64,
}

/// Time (s) to travel `d` at up to speed `v` with acceleration `a`,
/// starting and ending at rest or not.
pub fn profile(d: f64, v: f64, a: f64, from_rest: bool, to_rest: bool) -> f64 {
    let d = d.abs();
    if d <= 0.0 || v.is_nan() || a.is_nan() || v <= 0.0 || a <= 0.0 {
        return 0.0;
    }
    let ramps = f64::from(u8::from(from_rest) + u8::from(to_rest));
    if ramps == 0.0 {
        return d / v;
    }
    let ramp_distance = ramps * v * v / (2.0 * a);
    if d >= ramp_distance {
        (d - ramp_distance) / v + ramps * v / a
    } else {
        // Never reaches v: peak speed vp with ramps * vp² / 2a = d.
        let vp = (2.0 * a * d / ramps).sqrt();
        ramps * vp / a
    }
}

/// How a move starts and ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ends {
    /// The robot is at rest when the move starts (the previous move ended
    /// with `fine`, or this is the first).
    pub from_rest: bool,
    /// The move ends with `fine`.
    pub to_rest: bool,
    /// The share of the accelerations above that the move may use
    /// (`AccSet`'s `Acc`: 1 is 100 %).
    pub accel: f64,
}

impl Ends {
    /// A move from rest (or not) to rest (or not) at the full accelerations.
    pub const fn new(from_rest: bool, to_rest: bool) -> Ends {
        Ends {
            from_rest,
            to_rest,
            accel: 1.0,
        }
    }
}

/// What limited a move's time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    Tcp,
    Orientation,
    Axis(usize),
}

/// A move's time and what set it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveTime {
    pub seconds: f64,
    pub limit: Limit,
}

fn slowest(candidates: impl Iterator<Item = (f64, Limit)>) -> MoveTime {
    candidates.fold(
        MoveTime {
            seconds: 0.0,
            limit: Limit::Tcp,
        },
        |best, (t, l)| {
            if t > best.seconds {
                MoveTime {
                    seconds: t,
                    limit: l,
                }
            } else {
                best
            }
        },
    )
}

fn axis_times<'a>(
    robot: &'a Robot,
    travel: &'a [f64; 6],
    ends: Ends,
) -> impl Iterator<Item = (f64, Limit)> + 'a {
    travel.iter().enumerate().map(move |(i, d)| {
        let v = robot.model.speeds[i];
        (
            profile(
                *d,
                v,
                v / AXIS_ACCEL_TIME * ends.accel,
                ends.from_rest,
                ends.to_rest,
            ),
            Limit::Axis(i + 1),
        )
    })
}

/// A joint move (MoveJ, MoveAbsJ) from joints `from` to `to`.
pub fn joint_move(
    robot: &Robot,
    from: &Joints,
    to: &Joints,
    speed: &Speed,
    ends: Ends,
) -> MoveTime {
    let mut travel = [0.0; 6];
    for (t, (a, b)) in travel.iter_mut().zip(from.iter().zip(to)) {
        *t = (b - a).abs();
    }
    let tcp = match (robot.forward(from), robot.forward(to)) {
        (Some(a), Some(b)) => (
            (b.translation.vector - a.translation.vector).norm(),
            a.rotation.angle_to(&b.rotation).to_degrees(),
        ),
        _ => (0.0, 0.0),
    };
    slowest(
        [
            (
                profile(
                    tcp.0,
                    speed.v_tcp,
                    TCP_ACCEL * ends.accel,
                    ends.from_rest,
                    ends.to_rest,
                ),
                Limit::Tcp,
            ),
            (
                profile(
                    tcp.1,
                    speed.v_ori,
                    ORI_ACCEL * ends.accel,
                    ends.from_rest,
                    ends.to_rest,
                ),
                Limit::Orientation,
            ),
        ]
        .into_iter()
        .chain(axis_times(robot, &travel, ends)),
    )
}

/// A Cartesian path of tool0 in the base frame: a line, or an arc through
/// a point.
#[derive(Clone, Copy, Debug)]
pub enum Path {
    Line,
    /// The arc passes through this position (tool0's, base frame).
    Arc(Vector3<f64>),
}

/// A linear or circular move's result: its time, the joints at its end,
/// and the largest joint step between samples (a jump of axes 4 and 6
/// means a wrist singularity on the way).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CartesianMove {
    pub time: MoveTime,
    pub end: Solution,
    /// Smallest |axis 5| met on the path, degrees.
    pub min_axis5: f64,
}

/// The positions of a circle through three points, as a function of the
/// fraction travelled, and the arc's length; `None` when the points are
/// (nearly) on a line.
fn arc(
    a: &Vector3<f64>,
    via: &Vector3<f64>,
    b: &Vector3<f64>,
) -> Option<(f64, impl Fn(f64) -> Vector3<f64> + use<>)> {
    let u = via - a;
    let v = b - a;
    let w = u.cross(&v);
    let ww = w.norm_squared();
    if ww < 1e-9 * u.norm_squared().max(1.0) * v.norm_squared().max(1.0) {
        return None;
    }
    let centre = a + (v.norm_squared() * w.cross(&u) + u.norm_squared() * v.cross(&w)) / (2.0 * ww);
    let r = (a - centre).norm();
    let e1 = (a - centre) / r;
    let normal = w / ww.sqrt();
    let e2 = normal.cross(&e1);
    let angle_of = |p: &Vector3<f64>| {
        let d = p - centre;
        d.dot(&e2)
            .atan2(d.dot(&e1))
            .rem_euclid(std::f64::consts::TAU)
    };
    let total = angle_of(b);
    Some((r * total, move |s: f64| {
        let t = s * total;
        centre + r * (t.cos() * e1 + t.sin() * e2)
    }))
}

/// A linear (MoveL) or circular (MoveC) move of tool0 from joints `from` to
/// `to` (base frame), the orientation turned evenly along the path. Each
/// sample is solved near the previous one; the end must have
/// configuration `conf` when given (ConfL on).
pub fn cartesian_move(
    robot: &Robot,
    from: &Joints,
    to: &Isometry3<f64>,
    path: Path,
    conf: Option<&Conf>,
    speed: &Speed,
    ends: Ends,
) -> Result<CartesianMove, ReachError> {
    let along = Along {
        path,
        tcp: Isometry3::identity(),
    };
    cartesian_move_tcp(robot, from, to, &along, conf, speed, ends)
}

/// The path of a linear or circular move, for a TCP on the flange.
#[derive(Clone, Copy, Debug)]
pub struct Along {
    /// A line, or an arc through a point (the TCP's, base frame).
    pub path: Path,
    /// The TCP on the flange (tooldata's `tframe`; identity for tool0).
    pub tcp: Isometry3<f64>,
}

/// As [`cartesian_move`], for the TCP `along.tcp`: the TCP follows the
/// line or arc (as the controller moves it) and `to` is the TCP's pose in
/// the base frame; each sample's flange pose is solved.
pub fn cartesian_move_tcp(
    robot: &Robot,
    from: &Joints,
    to: &Isometry3<f64>,
    along: &Along,
    conf: Option<&Conf>,
    speed: &Speed,
    ends: Ends,
) -> Result<CartesianMove, ReachError> {
    let path = along.path;
    let flange_of = along.tcp.inverse();
    let start = robot
        .forward(from)
        .ok_or(ReachError::OutOfReach { by: 0.0 })?
        * along.tcp;
    let (p0, p1) = (start.translation.vector, to.translation.vector);
    let (q0, q1) = (start.rotation, to.rotation);
    let rotation = q0.angle_to(&q1).to_degrees();
    let (length, position): (f64, Box<dyn Fn(f64) -> Vector3<f64>>) = match path {
        Path::Arc(via) => match arc(&p0, &via, &p1) {
            Some((len, f)) => (len, Box::new(f)),
            None => ((p1 - p0).norm(), Box::new(move |s| p0 + (p1 - p0) * s)),
        },
        Path::Line => ((p1 - p0).norm(), Box::new(move |s| p0 + (p1 - p0) * s)),
    };
    let n = ((length / 10.0 * SAMPLES_PER_10MM).max(rotation).ceil() as usize).clamp(8, 2000);
    let mut travel = [0.0; 6];
    let mut previous = *from;
    let mut min_axis5 = from[4].abs();
    for k in 1..=n {
        let s = k as f64 / n as f64;
        let rot = q0.slerp(&q1, s);
        let pose = Isometry3::from_parts(position(s).into(), UnitQuaternion::from(rot));
        let want = if k == n { conf } else { None };
        let sol = robot.reach_near(&(pose * flange_of), want, &previous)?;
        for (t, (a, b)) in travel.iter_mut().zip(previous.iter().zip(&sol.joints)) {
            *t += (b - a).abs();
        }
        min_axis5 = min_axis5.min(sol.joints[4].abs());
        previous = sol.joints;
    }
    let time = slowest(
        [
            (
                profile(
                    length,
                    speed.v_tcp,
                    TCP_ACCEL * ends.accel,
                    ends.from_rest,
                    ends.to_rest,
                ),
                Limit::Tcp,
            ),
            (
                profile(
                    rotation,
                    speed.v_ori,
                    ORI_ACCEL * ends.accel,
                    ends.from_rest,
                    ends.to_rest,
                ),
                Limit::Orientation,
            ),
        ]
        .into_iter()
        .chain(axis_times(robot, &travel, ends)),
    );
    Ok(CartesianMove {
        time,
        end: Solution {
            joints: previous,
            conf: robot.conf_of(&previous),
        },
        min_axis5,
    })
}
