//! Forward and inverse kinematics of an OPW arm in ABB's conventions, on
//! `rs-opw-kinematics`.
//!
//! Joint angles are the controller's: degrees, zero at the calibration
//! position (lower arm vertical, forearm horizontal), positive as ABB's
//! axis directions. Positions are mm in the robot's base frame; the pose is
//! tool0's (the mounting flange, z out of the flange, x down at zero).
//! For parallel-arm robots ([`Model::coupled`]) the controller's axis 3 is
//! measured from the horizontal: the serial chain's axis 3 is axis 3 minus
//! axis 2.

use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use rs_opw_kinematics::glam::{DQuat, DVec3};
use rs_opw_kinematics::kinematic_traits::{Kinematics, Pose};
use rs_opw_kinematics::kinematics_impl::OPWKinematics;
use rs_opw_kinematics::parameters::opw_kinematics::Parameters;

use crate::model::Model;

/// Six joint angles in degrees, the controller's axes 1 to 6.
pub type Joints = [f64; 6];

/// The kinematics of one model.
#[derive(Clone, Debug)]
pub struct Arm {
    opw: OPWKinematics,
    coupled: bool,
}

/// The points of the arm at a joint position, in the base frame (mm): for
/// drawing it and for telling its configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArmPoints {
    /// Axis 2 (the shoulder).
    pub shoulder: Point3<f64>,
    /// Axis 3 (the elbow).
    pub elbow: Point3<f64>,
    /// Where axes 4, 5 and 6 meet.
    pub wrist: Point3<f64>,
    /// tool0.
    pub flange: Point3<f64>,
}

impl Arm {
    pub fn new(model: &Model) -> Arm {
        let o = &model.opw;
        let parameters = Parameters {
            a1: o.a1,
            a2: o.a2,
            b: o.b,
            c1: o.c1,
            c2: o.c2,
            c3: o.c3,
            c4: o.c4,
            // The OPW zero has the forearm upright; ABB's has it horizontal.
            offsets: [0.0, 0.0, -std::f64::consts::FRAC_PI_2, 0.0, 0.0, 0.0],
            sign_corrections: [1; 6],
            dof: 6,
        };
        Arm {
            opw: OPWKinematics::new(parameters),
            coupled: model.coupled,
        }
    }

    /// The serial chain's angles (radians) of the controller's angles.
    fn to_chain(&self, j: &Joints) -> [f64; 6] {
        let mut q = j.map(f64::to_radians);
        if self.coupled {
            q[2] -= q[1];
        }
        q
    }

    /// The controller's angles (degrees) of the serial chain's.
    fn of_chain(&self, q: &[f64; 6]) -> Joints {
        let mut j = q.map(f64::to_degrees);
        if self.coupled {
            j[2] += j[1];
        }
        j
    }

    /// tool0's pose in the base frame at joint angles `j`; `None` for
    /// angles that are not finite.
    pub fn forward(&self, j: &Joints) -> Option<Isometry3<f64>> {
        if !j.iter().all(|a| a.is_finite()) {
            return None;
        }
        self.opw
            .try_forward(&self.to_chain(j))
            .ok()
            .map(|p| iso_of_pose(&p))
    }

    /// Every joint solution for tool0 at `pose` (base frame), each angle in
    /// (-180, 180]: at most eight (axis 1 forward or backward, elbow up or
    /// down, axis 5 positive or negative). Empty when the pose is out of
    /// reach. Angles beyond ±180 (axes 4 and 6 turn further) are the
    /// caller's to add ([`crate::conf`]).
    pub fn inverse(&self, pose: &Isometry3<f64>) -> Vec<Joints> {
        let Some(p) = pose_of_iso(pose) else {
            return Vec::new();
        };
        self.opw
            .inverse(&p)
            .iter()
            .map(|q| {
                let mut j = self.of_chain(q);
                for a in &mut j {
                    *a = wrap180(*a);
                }
                j
            })
            .collect()
    }

    /// The arm's points at joint angles `j`.
    pub fn points(&self, j: &Joints) -> Option<ArmPoints> {
        if !j.iter().all(|a| a.is_finite()) {
            return None;
        }
        let poses = self.opw.forward_with_joint_poses(&self.to_chain(j));
        let p = |i: usize| {
            let t = poses[i].translation;
            Point3::new(t.x, t.y, t.z)
        };
        Some(ArmPoints {
            shoulder: p(1),
            elbow: p(2),
            wrist: p(4),
            flange: p(5),
        })
    }
}

/// An angle in degrees brought into (-180, 180].
pub fn wrap180(a: f64) -> f64 {
    let r = a.rem_euclid(360.0);
    if r > 180.0 { r - 360.0 } else { r }
}

fn iso_of_pose(p: &Pose) -> Isometry3<f64> {
    let t = p.translation;
    let r = p.rotation;
    Isometry3::from_parts(
        Translation3::new(t.x, t.y, t.z),
        UnitQuaternion::new_normalize(Quaternion::new(r.w, r.x, r.y, r.z)),
    )
}

fn pose_of_iso(iso: &Isometry3<f64>) -> Option<Pose> {
    let t = iso.translation.vector;
    let q = iso.rotation;
    Pose::try_from_parts(
        DVec3::new(t.x, t.y, t.z),
        DQuat::from_xyzw(q.i, q.j, q.k, q.w),
    )
    .ok()
}

/// The angle in degrees between two orientations.
pub fn angle_between(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
    a.angle_to(b).to_degrees()
}

/// A vector's length, for distances in mm.
pub fn distance(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    (a - b).norm()
}
