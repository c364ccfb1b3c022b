//! The robot arm of a motion task, behind [`Robot`]: the move instructions
//! hand it what a real arm needs (the kind of move, the target, speed,
//! zone, tool, work object, `\Conc`) and it answers how long the move
//! takes and where the arm ends, or a controller error (out of reach, a
//! joint limit); `CRobT`, `CJointT`, `CPos`, `CalcJointT` and `CalcRobT`
//! ask it where the arm is and what a target means in joints.
//!
//! ABB's conventions: positions in mm, angles in degrees, orientations as
//! quaternions `[q1, q2, q3, q4]` = `[w, x, y, z]` (normalised before they
//! reach a robot), a robtarget is the TCP in the work object (`uframe`,
//! then `oframe`) through the tool's `tframe`.
//!
//! [`InstantRobot`], the default, has no kinematic model: a move arrives
//! at once and leaves the TCP at its target; the joints are those of the
//! last `MoveAbsJ` (zero before any); `CalcJointT`/`CalcRobT` are not
//! supported.

/// Why a built-in that needs the arm's geometry stops without a robot
/// model; front ends tell the user how to name one.
pub const NO_KINEMATICS: &str = "the simulated robot has no kinematic model";

use rapid_evaluator::geometry::{isometry, isometry_parts};
use rapid_evaluator::nalgebra::Isometry3;

/// A position and an orientation: `trans` in mm, `rot` the quaternion
/// `[q1, q2, q3, q4]` (`[w, x, y, z]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub trans: [f64; 3],
    pub rot: [f64; 4],
}

impl Pose {
    pub const IDENTITY: Pose = Pose {
        trans: [0.0; 3],
        rot: [1.0, 0.0, 0.0, 0.0],
    };

    /// As a rigid transformation (the quaternion normalised; a zero one is
    /// no rotation).
    pub fn isometry(&self) -> Isometry3<f64> {
        isometry(self.trans, self.rot)
    }

    pub fn from_isometry(iso: &Isometry3<f64>) -> Pose {
        let (trans, rot) = isometry_parts(iso);
        Pose { trans, rot }
    }

    /// `self` then `other` (`other` expressed in `self`'s frame).
    pub fn then(&self, other: &Pose) -> Pose {
        Pose::from_isometry(&(self.isometry() * other.isometry()))
    }

    pub fn inverse(&self) -> Pose {
        Pose::from_isometry(&self.isometry().inverse())
    }
}

/// A Cartesian target (`robtarget`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RobTarget {
    /// The TCP in the work object.
    pub pose: Pose,
    /// `cf1`, `cf4`, `cf6`, `cfx`.
    pub robconf: [f64; 4],
    /// External axes `eax_a` to `eax_f` (9E9: not used).
    pub extax: [f64; 6],
}

/// A joint target (`jointtarget`): axes in degrees (mm for linear ones).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointTarget {
    pub robax: [f64; 6],
    pub extax: [f64; 6],
}

impl JointTarget {
    pub const ZERO: JointTarget = JointTarget {
        robax: [0.0; 6],
        extax: [9e9; 6],
    };
}

/// `speeddata`: mm/s and degrees/s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Speed {
    pub v_tcp: f64,
    pub v_ori: f64,
    pub v_leax: f64,
    pub v_reax: f64,
}

/// `zonedata`: a fine point, or the zone's sizes (mm and degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Zone {
    pub finep: bool,
    pub pzone_tcp: f64,
    pub pzone_ori: f64,
    pub pzone_eax: f64,
    pub zone_ori: f64,
    pub zone_leax: f64,
    pub zone_reax: f64,
}

/// `tooldata`, as motion needs it.
#[derive(Clone, Debug, PartialEq)]
pub struct Tool {
    /// The robot holds the tool (else it is stationary).
    pub robhold: bool,
    /// The TCP in the flange's frame.
    pub tframe: Pose,
    /// The load's mass in kg and centre of gravity in mm.
    pub mass: f64,
    pub cog: [f64; 3],
}

impl Default for Tool {
    /// `tool0`: the flange itself.
    fn default() -> Tool {
        Tool {
            robhold: true,
            tframe: Pose::IDENTITY,
            mass: 0.0,
            cog: [0.0; 3],
        }
    }
}

/// `wobjdata`.
#[derive(Clone, Debug, PartialEq)]
pub struct WObj {
    pub robhold: bool,
    /// The user frame is fixed (else a mechanical unit moves it).
    pub ufprog: bool,
    /// The mechanical unit that moves the user frame.
    pub ufmec: String,
    pub uframe: Pose,
    pub oframe: Pose,
}

impl Default for WObj {
    /// `wobj0`: the world frame.
    fn default() -> WObj {
        WObj {
            robhold: false,
            ufprog: true,
            ufmec: String::new(),
            uframe: Pose::IDENTITY,
            oframe: Pose::IDENTITY,
        }
    }
}

impl WObj {
    /// The object frame in world coordinates (user frame, then object
    /// frame).
    pub fn frame(&self) -> Pose {
        self.uframe.then(&self.oframe)
    }
}

/// The kind of a move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MoveKind {
    /// Joint interpolation to a Cartesian target (`MoveJ`, `SearchJ`,
    /// `TriggJ`, `MoveJDO`).
    Joint,
    /// Linear (`MoveL`...).
    Linear,
    /// Circular, through `via` (`MoveC`...).
    Circular,
    /// To joint values (`MoveAbsJ`).
    AbsoluteJoint,
    /// External axes only (`MoveExtJ`).
    External,
}

/// Where a move goes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MoveTarget {
    Cartesian(RobTarget),
    Joints(JointTarget),
    /// The external axes only (`MoveExtJ`): the arm stays where it is.
    ExternalAxes([f64; 6]),
}

/// A move, as its instruction gives it.
#[derive(Clone, Debug)]
pub struct MoveRequest<'a> {
    /// The instruction (`MoveL`, `SearchL`, `TriggJ`...).
    pub instruction: &'a str,
    pub kind: MoveKind,
    pub to: MoveTarget,
    /// The circle point of a circular move.
    pub via: Option<RobTarget>,
    pub speed: Speed,
    /// `\T`: the move's total time in seconds, instead of the speed.
    pub time: Option<f64>,
    /// `\V`: the TCP speed in mm/s, instead of the speed's.
    pub velocity: Option<f64>,
    /// `AccSet`'s `Acc`: the share of the normal accelerations (1: 100 %).
    pub accel: f64,
    pub zone: Zone,
    pub tool: Tool,
    pub wobj: WObj,
    /// `\Conc`: the program goes on while the arm moves.
    pub conc: bool,
    /// The simulated time the move is asked for, in seconds.
    pub at: f64,
}

/// What a move did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// How long it takes, in seconds.
    pub duration: f64,
    /// The arm's joints at the end, when the robot knows them.
    pub joints: Option<JointTarget>,
}

/// Why a robot cannot do what it is asked: the controller stops the
/// program with its message, or the instruction is not supported.
#[derive(Clone, Debug, PartialEq)]
pub enum RobotError {
    /// The robot model cannot answer this (no kinematics): "not supported
    /// in simulation".
    Unsupported(String),
    /// The target is outside the robot's reach.
    OutOfReach(String),
    /// A joint would pass its limit (axis 1 to 6).
    JointLimit { axis: usize, message: String },
    /// The controller stops the program with a motion event (a move to a
    /// target out of reach, beyond a working range, or in another
    /// configuration): no `ERROR` handler takes it.
    Stop {
        /// The event log's number and title (`50050`, "Position outside
        /// reach").
        event: u32,
        title: String,
        message: String,
    },
    /// Anything else the controller reports.
    Other(String),
}

impl std::fmt::Display for RobotError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RobotError::Unsupported(m) | RobotError::OutOfReach(m) | RobotError::Other(m) => {
                f.write_str(m)
            }
            RobotError::JointLimit { axis, message } => write!(f, "axis {axis}: {message}"),
            RobotError::Stop {
                event,
                title,
                message,
            } => write!(f, "{event} {title}: {message}"),
        }
    }
}

/// The robot arm of a motion task.
pub trait Robot: Send {
    /// Executes a move.
    fn move_to(&mut self, request: &MoveRequest<'_>) -> Result<Motion, RobotError>;

    /// Where the TCP of `tool` is now, in `wobj` (`CRobT`, `CPos`).
    fn robtarget(&self, tool: &Tool, wobj: &WObj) -> Result<RobTarget, RobotError>;

    /// The joints now (`CJointT`).
    fn joints(&self) -> Result<JointTarget, RobotError>;

    /// The joints that put the TCP of `tool` at `target` in `wobj`
    /// (`CalcJointT`).
    fn calc_joints(
        &self,
        target: &RobTarget,
        tool: &Tool,
        wobj: &WObj,
    ) -> Result<JointTarget, RobotError> {
        let _ = (target, tool, wobj);
        Err(RobotError::Unsupported(format!(
            "CalcJointT ({NO_KINEMATICS})"
        )))
    }

    /// Where the TCP of `tool` is, in `wobj`, at `joints` (`CalcRobT`).
    fn calc_robtarget(
        &self,
        joints: &JointTarget,
        tool: &Tool,
        wobj: &WObj,
    ) -> Result<RobTarget, RobotError> {
        let _ = (joints, tool, wobj);
        Err(RobotError::Unsupported(format!(
            "CalcRobT ({NO_KINEMATICS})"
        )))
    }

    /// `ConfL` (`linear`) or `ConfJ` `\On` or `\Off`: whether moves keep
    /// the target's confdata.
    fn set_conf(&mut self, linear: bool, on: bool) {
        let _ = (linear, on);
    }

    /// Whether its moves take time (a modelled arm's do; the default
    /// robot's arrive at once).
    fn moves_take_time(&self) -> bool {
        true
    }

    /// The arm stops at `joints` at time `at`, short of the move under way
    /// (a search that stops at its hit).
    fn stop_at(&mut self, joints: &JointTarget, at: f64) {
        let _ = (joints, at);
    }

    /// The joints at time `at`, during a move too (`CJointT` while the
    /// robot moves); by default where the last move ends.
    fn joints_at(&self, at: f64) -> Result<JointTarget, RobotError> {
        let _ = at;
        self.joints()
    }

    /// Where the TCP of `tool` is at time `at`, in `wobj` (`CRobT`, `CPos`
    /// while the robot moves); by default where the last move ends.
    fn robtarget_at(&self, tool: &Tool, wobj: &WObj, at: f64) -> Result<RobTarget, RobotError> {
        let _ = at;
        self.robtarget(tool, wobj)
    }

    /// `StopMove` at time `at`: the arm stands where it is then and keeps
    /// the rest of its move; the seconds of it left (`None`: no move was
    /// under way, or moves take no time).
    fn pause(&mut self, at: f64) -> Option<f64> {
        let _ = at;
        None
    }

    /// `StartMove` at time `at`: the kept rest of the move goes on from
    /// where the arm is, for `seconds`; `ClearPath` (`keep` false) drops
    /// it, and the arm stays where it stands.
    fn resume(&mut self, at: f64, seconds: f64, keep: bool) {
        let _ = (at, seconds, keep);
    }

    /// The working range of each axis, degrees (`[lower, upper]`), when
    /// the arm is modelled.
    fn joint_limits(&self) -> Option<[[f64; 2]; 6]> {
        None
    }

    /// Whether [`Robot::robtarget`] and [`Robot::joints`] say where the
    /// arm really is (world zones check only what is known).
    fn known(&self) -> Known {
        Known {
            tcp: true,
            joints: true,
        }
    }
}

/// What a robot knows of where its arm is ([`Robot::known`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Known {
    pub tcp: bool,
    pub joints: bool,
}

/// The default robot: every move arrives at once at its target (no
/// kinematics, no time). `CJointT` gives the last `MoveAbsJ` target.
#[derive(Clone, Debug)]
pub struct InstantRobot {
    /// The flange in world coordinates.
    flange: Pose,
    robconf: [f64; 4],
    extax: [f64; 6],
    joints: JointTarget,
    /// Which kind of move came last: a Cartesian move leaves the joints
    /// unknown, `MoveAbsJ` the TCP.
    known: Known,
}

impl Default for InstantRobot {
    fn default() -> InstantRobot {
        InstantRobot {
            flange: Pose::IDENTITY,
            robconf: [0.0; 4],
            extax: [9e9; 6],
            joints: JointTarget::ZERO,
            known: Known {
                tcp: false,
                joints: false,
            },
        }
    }
}

impl InstantRobot {
    pub fn new() -> InstantRobot {
        InstantRobot::default()
    }
}

impl Robot for InstantRobot {
    fn moves_take_time(&self) -> bool {
        false
    }

    fn move_to(&mut self, request: &MoveRequest<'_>) -> Result<Motion, RobotError> {
        match &request.to {
            MoveTarget::Cartesian(t) => {
                let tcp = request.wobj.frame().then(&t.pose);
                self.flange = tcp.then(&request.tool.tframe.inverse());
                self.robconf = t.robconf;
                self.extax = t.extax;
                self.known = Known {
                    tcp: true,
                    joints: false,
                };
            }
            MoveTarget::Joints(j) => {
                self.joints = *j;
                self.extax = j.extax;
                self.known = Known {
                    tcp: false,
                    joints: true,
                };
            }
            MoveTarget::ExternalAxes(e) => {
                self.extax = *e;
                self.joints.extax = *e;
            }
        }
        Ok(Motion {
            duration: 0.0,
            joints: None,
        })
    }

    fn robtarget(&self, tool: &Tool, wobj: &WObj) -> Result<RobTarget, RobotError> {
        let tcp = self.flange.then(&tool.tframe);
        Ok(RobTarget {
            pose: wobj.frame().inverse().then(&tcp),
            robconf: self.robconf,
            extax: self.extax,
        })
    }

    fn joints(&self) -> Result<JointTarget, RobotError> {
        Ok(self.joints)
    }

    fn known(&self) -> Known {
        self.known
    }
}
