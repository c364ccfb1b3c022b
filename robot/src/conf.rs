//! confdata: the quadrants of axes 1, 4 and 6 and the arm configuration,
//! and the choice among inverse solutions the way the controller makes it.
//!
//! The RAPID manual (confdata): for a rotating axis the value is its
//! quadrant, 0 for 0 to 90 degrees, 1 for 90 to 180, -1 for 0 to -90 and so
//! on; `cfx` names one of eight arm configurations: bit 2 the wrist centre
//! behind axis 1, bit 1 the wrist centre behind the lower arm, bit 0 axis 5
//! negative (the manual's table: 0 in front, in front, positive ... 7 behind,
//! behind, negative). For robots whose manual entry says they use cf1, cf4
//! and cf6 only ([`Cfx::Unused`]), `cfx` is not compared.

use crate::kinematics::{Arm, Joints};
use crate::model::{Cfx, Model};

/// A robtarget's confdata.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Conf {
    pub cf1: i32,
    pub cf4: i32,
    pub cf6: i32,
    pub cfx: i32,
}

impl std::fmt::Display for Conf {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "[{},{},{},{}]", self.cf1, self.cf4, self.cf6, self.cfx)
    }
}

/// How close to a quadrant's edge (degrees) or to a configuration's
/// singular line (mm, and degrees of axis 5) a solution counts for both
/// sides: taught targets are stored in single precision, so their
/// configuration is recomputed from a pose that is a little off.
pub const EDGE_DEG: f64 = 1.0;
pub const EDGE_MM: f64 = 1.0;

/// The quadrant of an angle in degrees.
pub fn quadrant(angle: f64) -> i32 {
    (angle / 90.0).floor() as i32
}

/// Is `angle` in quadrant `q`, give or take [`EDGE_DEG`]?
pub fn in_quadrant(angle: f64, q: i32) -> bool {
    let lo = f64::from(q) * 90.0;
    angle >= lo - EDGE_DEG && angle <= lo + 90.0 + EDGE_DEG
}

/// Where the wrist centre is, for cfx: its signed distance (mm) in front of
/// axis 1 and in front of the lower arm (negative: behind).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmSides {
    pub axis1: f64,
    pub lower_arm: f64,
}

/// The sides of the wrist centre at joint angles `j`.
pub fn sides(arm: &Arm, j: &Joints) -> Option<ArmSides> {
    let p = arm.points(j)?;
    let (s, c) = j[0].to_radians().sin_cos();
    // The arm's forward direction and the normal of its plane (axis 2).
    let forward = nalgebra::Vector3::new(c, s, 0.0);
    let normal = nalgebra::Vector3::new(-s, c, 0.0);
    let axis1 = p.wrist.coords.dot(&forward);
    let lower = p.elbow - p.shoulder;
    let to_wrist = p.wrist - p.shoulder;
    let len = lower.norm();
    let lower_arm = if len > 0.0 {
        lower.cross(&to_wrist).dot(&normal) / len
    } else {
        0.0
    };
    Some(ArmSides { axis1, lower_arm })
}

/// The confdata the controller gives joint angles `j`.
pub fn conf_of(arm: &Arm, model: &Model, j: &Joints) -> Conf {
    let cfx = match model.cfx {
        Cfx::Unused => 0,
        Cfx::Arm => sides(arm, j).map_or(0, |s| {
            i32::from(s.axis1 < 0.0) * 4 + i32::from(s.lower_arm < 0.0) * 2 + i32::from(j[4] < 0.0)
        }),
    };
    Conf {
        cf1: quadrant(j[0]),
        cf4: quadrant(j[3]),
        cf6: quadrant(j[5]),
        cfx,
    }
}

/// Does a solution have configuration `want`, give or take the edges?
pub fn matches(arm: &Arm, model: &Model, j: &Joints, want: &Conf) -> bool {
    if !(in_quadrant(j[0], want.cf1) && in_quadrant(j[3], want.cf4) && in_quadrant(j[5], want.cf6))
    {
        return false;
    }
    if model.cfx == Cfx::Unused {
        return true;
    }
    let Some(s) = sides(arm, j) else {
        return false;
    };
    let bit = |value: f64, edge: f64, set: bool| value.abs() <= edge || (value < 0.0) == set;
    (0..=7).contains(&want.cfx)
        && bit(s.axis1, EDGE_MM, want.cfx & 4 != 0)
        && bit(s.lower_arm, EDGE_MM, want.cfx & 2 != 0)
        && bit(j[4], EDGE_DEG, want.cfx & 1 != 0)
}

/// The solutions with the turns of each axis that the working ranges
/// `ranges` hold (within ±2 turns: axes 4 and 6 turn up to ±400 degrees,
/// axis 3 of some arms to -230), from solutions in (-180, 180]. With
/// `want`, axes 1, 4 and 6 take the turn that puts them in its quadrants,
/// within the range or not (so that a limit error says by how much).
pub fn with_turns(ranges: &[[f64; 2]; 6], base: &[Joints], want: Option<&Conf>) -> Vec<Joints> {
    let mut out = Vec::new();
    let turns = |axis: usize, a: f64| -> Vec<f64> {
        let candidates = (-2..=2).map(|k| a + 360.0 * f64::from(k));
        let wanted = want.and_then(|c| match axis {
            0 => Some(c.cf1),
            3 => Some(c.cf4),
            5 => Some(c.cf6),
            _ => None,
        });
        if let Some(q) = wanted {
            let v: Vec<f64> = candidates.clone().filter(|x| in_quadrant(*x, q)).collect();
            if !v.is_empty() {
                return v;
            }
        }
        let [lo, hi] = ranges[axis];
        let mut v: Vec<f64> = candidates
            .filter(|x| *x >= lo - EDGE_DEG && *x <= hi + EDGE_DEG)
            .collect();
        if v.is_empty() {
            v.push(a);
        }
        v
    };
    for j in base {
        let mut partial: Vec<Joints> = vec![*j];
        for axis in 0..6 {
            let options = turns(axis, j[axis]);
            if let [only] = options.as_slice() {
                for p in &mut partial {
                    p[axis] = *only;
                }
                continue;
            }
            partial = partial
                .iter()
                .flat_map(|p| {
                    options.iter().map(move |a| {
                        let mut q = *p;
                        q[axis] = *a;
                        q
                    })
                })
                .collect();
        }
        out.extend(partial);
    }
    out
}

/// At a wrist singularity (|axis 5| below [`EDGE_DEG`]) only axis 4 plus
/// axis 6 is fixed: the solution with axis 4 moved to the middle of
/// quadrant `cf4` (and axis 6 moved back as much), when that is another
/// solution.
pub fn at_singularity(j: &Joints, cf4: i32) -> Option<Joints> {
    if j[4].abs() >= EDGE_DEG {
        return None;
    }
    let target = f64::from(cf4) * 90.0 + 45.0;
    let delta = target - j[3];
    let mut out = *j;
    out[3] += delta;
    out[5] -= delta;
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadrants_follow_the_manual() {
        assert_eq!(quadrant(0.0), 0);
        assert_eq!(quadrant(89.9), 0);
        assert_eq!(quadrant(90.0), 1);
        assert_eq!(quadrant(-0.1), -1);
        assert_eq!(quadrant(-90.1), -2);
        assert_eq!(quadrant(370.0), 4);
        assert!(in_quadrant(-0.5, 0));
        assert!(!in_quadrant(-2.0, 0));
    }
}
