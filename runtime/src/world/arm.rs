//! [`ArmRobot`]: a robot with the kinematics of a modelled ABB arm
//! (`rapid-robot`), its joint limits and its base frame. A move solves the
//! inverse kinematics of its target through the tool and work object,
//! picks the solution the target's confdata names (with `ConfJ`/`ConfL`
//! on; else the one nearest the arm's joints), checks the working ranges
//! and takes the time `rapid_robot::motion` gives it. A target the arm
//! cannot reach stops the run with the controller's event (as a real
//! controller stops with a motion error); `CalcJointT` raises
//! `ERR_OUTSIDE_REACH` or `ERR_ROBLIMIT`, which an `ERROR` handler takes.
//!
//! The arm starts at its calibration position (every axis at zero), at
//! rest. See docs/robot.md for what is modelled and what not.

use rapid_evaluator::nalgebra::Isometry3;
use rapid_robot::frames;
use rapid_robot::motion::{self, Along, Ends, Path};
use rapid_robot::{Conf, Joints, ReachError};

use super::robot::{
    JointTarget, Motion, MoveKind, MoveRequest, MoveTarget, Pose, RobTarget, Robot, RobotError,
    Tool, WObj,
};

/// A modelled arm: where it is, and the controller's settings that choose
/// among its solutions.
#[derive(Clone, Debug)]
pub struct ArmRobot {
    robot: rapid_robot::Robot,
    joints: Joints,
    extax: [f64; 6],
    /// The last move ended at a fine point (or none was made).
    at_rest: bool,
    /// When the last move ends (simulated seconds).
    until: f64,
    /// Where and when the last move started: between then and `until`
    /// the arm is taken to go from `from` to `joints` evenly in time.
    from: Joints,
    start: f64,
    /// The last move's TCP in the flange's frame when it went straight
    /// (`MoveL`): then the TCP is taken along the line between the ends.
    straight: Option<Isometry3<f64>>,
    /// The end of a move `StopMove` interrupted, kept for `StartMove`.
    paused: Option<(Joints, [f64; 6])>,
    /// `ConfJ\On`, `ConfL\On` (the controller's defaults).
    conf_j: bool,
    conf_l: bool,
}

impl ArmRobot {
    /// The arm at its calibration position.
    pub fn new(robot: rapid_robot::Robot) -> ArmRobot {
        ArmRobot {
            robot,
            joints: [0.0; 6],
            extax: [9e9; 6],
            at_rest: true,
            until: 0.0,
            from: [0.0; 6],
            start: 0.0,
            straight: None,
            paused: None,
            conf_j: true,
            conf_l: true,
        }
    }

    /// The joints at time `at`: during a move, between where it started
    /// and where it ends in proportion to the time gone (not along the
    /// speed profile): a `MoveL`'s TCP on the line between its ends, other
    /// moves joint by joint.
    fn joints_then(&self, at: f64) -> Joints {
        let span = self.until - self.start;
        if at >= self.until || span <= 0.0 {
            return self.joints;
        }
        let f = ((at - self.start) / span).clamp(0.0, 1.0);
        let evenly: Joints =
            std::array::from_fn(|i| self.from[i] + f * (self.joints[i] - self.from[i]));
        let on_line = self.straight.and_then(|tcp| {
            let a = self.robot.forward(&self.from)? * tcp;
            let b = self.robot.forward(&self.joints)? * tcp;
            let tcp_then = a.lerp_slerp(&b, f);
            let flange = tcp_then * tcp.inverse();
            self.robot.reach_near(&flange, None, &evenly).ok()
        });
        on_line.map_or(evenly, |s| s.joints)
    }

    /// The model, limits and base frame.
    pub fn robot(&self) -> &rapid_robot::Robot {
        &self.robot
    }
}

fn iso(p: &Pose) -> Isometry3<f64> {
    p.isometry()
}

fn tool_of(t: &Tool) -> frames::Tool {
    frames::Tool {
        robhold: t.robhold,
        tframe: iso(&t.tframe),
    }
}

fn wobj_of(w: &WObj) -> frames::WObj {
    frames::WObj {
        robhold: w.robhold,
        uframe: iso(&w.uframe),
        oframe: iso(&w.oframe),
    }
}

fn conf_of(robconf: &[f64; 4]) -> Conf {
    Conf {
        cf1: robconf[0].round() as i32,
        cf4: robconf[1].round() as i32,
        cf6: robconf[2].round() as i32,
        cfx: robconf[3].round() as i32,
    }
}

/// A move's error: the controller stops with its motion event.
fn stop(instruction: &str, e: &ReachError) -> RobotError {
    let event = e.event();
    RobotError::Stop {
        event: event.number,
        title: event.title.to_owned(),
        message: format!("{instruction}: {e}"),
    }
}

/// `CalcJointT`'s error: the RAPID error an `ERROR` handler can take.
fn raised(e: &ReachError) -> RobotError {
    let event = e.event();
    let message = format!("{} {}: {e}", event.number, event.title);
    match e {
        ReachError::OutOfReach { .. } => RobotError::OutOfReach(message),
        ReachError::JointLimit { axis, .. } => RobotError::JointLimit {
            axis: *axis,
            message,
        },
        ReachError::Configuration { .. } => RobotError::JointLimit { axis: 0, message },
    }
}

impl Robot for ArmRobot {
    fn joint_limits(&self) -> Option<[[f64; 2]; 6]> {
        Some(self.robot.limits.0)
    }

    fn stop_at(&mut self, joints: &JointTarget, at: f64) {
        self.from = joints.robax;
        self.joints = joints.robax;
        self.at_rest = true;
        self.until = self.until.min(at);
    }

    fn move_to(&mut self, request: &MoveRequest<'_>) -> Result<Motion, RobotError> {
        if !request.wobj.ufprog && !request.wobj.ufmec.is_empty() {
            return Err(RobotError::Unsupported(format!(
                "{}: a user frame moved by the mechanical unit {}",
                request.instruction, request.wobj.ufmec
            )));
        }
        let mut speed = motion::Speed {
            v_tcp: request.speed.v_tcp,
            v_ori: request.speed.v_ori,
            v_leax: request.speed.v_leax,
            v_reax: request.speed.v_reax,
        };
        if let Some(v) = request.velocity {
            speed.v_tcp = v;
        }
        // A move asked for after the last one ended (the program waited in
        // between) starts from rest.
        let ends = Ends {
            from_rest: self.at_rest || request.at > self.until + 1e-9,
            to_rest: request.zone.finep,
            accel: request.accel,
        };
        let tool = tool_of(&request.tool);
        let wobj = wobj_of(&request.wobj);
        let (joints, seconds, extax) = match (&request.to, request.kind) {
            // External axes are not modelled: they arrive at once.
            (MoveTarget::ExternalAxes(e), _) => (self.joints, 0.0, *e),
            (MoveTarget::Joints(j), _) => {
                let to = j.robax;
                if let Some((axis, bound, by)) = rapid_robot::violation(&self.robot.limits, &to) {
                    let e = ReachError::JointLimit {
                        axis,
                        angle: to[axis - 1],
                        bound,
                        by,
                        joints: to,
                    };
                    return Err(stop(request.instruction, &e));
                }
                let t = motion::joint_move(&self.robot, &self.joints, &to, &speed, ends);
                (to, t.seconds, j.extax)
            }
            (MoveTarget::Cartesian(t), MoveKind::Linear | MoveKind::Circular) => {
                let conf = self.conf_l.then(|| conf_of(&t.robconf));
                let flange = frames::flange_in_base(&iso(&t.pose), &tool, &wobj, &self.robot.base);
                // The controller refuses an unreachable target before it
                // moves: the same error as for a joint move.
                self.robot
                    .move_to(&flange, conf.as_ref())
                    .map_err(|e| stop(request.instruction, &e))?;
                let object = wobj.uframe * wobj.oframe;
                let world_to_base = self.robot.base.inverse();
                // The TCP's path in the base frame (a stationary tool: the
                // flange's, approximately).
                let (to, along) = if tool.robhold {
                    let tcp = world_to_base * object * iso(&t.pose);
                    let path = match (&request.via, request.kind) {
                        (Some(v), MoveKind::Circular) => {
                            Path::Arc((world_to_base * object * iso(&v.pose)).translation.vector)
                        }
                        _ => Path::Line,
                    };
                    (
                        tcp,
                        Along {
                            path,
                            tcp: tool.tframe,
                        },
                    )
                } else {
                    let path = match (&request.via, request.kind) {
                        (Some(v), MoveKind::Circular) => Path::Arc(
                            frames::flange_in_base(&iso(&v.pose), &tool, &wobj, &self.robot.base)
                                .translation
                                .vector,
                        ),
                        _ => Path::Line,
                    };
                    (
                        flange,
                        Along {
                            path,
                            tcp: Isometry3::identity(),
                        },
                    )
                };
                let m = motion::cartesian_move_tcp(
                    &self.robot,
                    &self.joints,
                    &to,
                    &along,
                    conf.as_ref(),
                    &speed,
                    ends,
                )
                .map_err(|e| stop(request.instruction, &e))?;
                (m.end.joints, m.time.seconds, t.extax)
            }
            (MoveTarget::Cartesian(t), _) => {
                let conf = self.conf_j.then(|| conf_of(&t.robconf));
                let flange = frames::flange_in_base(&iso(&t.pose), &tool, &wobj, &self.robot.base);
                let sol = match conf {
                    Some(c) => self.robot.move_to(&flange, Some(&c)),
                    None => self.robot.reach_near(&flange, None, &self.joints),
                }
                .map_err(|e| stop(request.instruction, &e))?;
                let t2 = motion::joint_move(&self.robot, &self.joints, &sol.joints, &speed, ends);
                (sol.joints, t2.seconds, t.extax)
            }
        };
        let seconds = request.time.unwrap_or(seconds).max(0.0);
        self.straight = match (&request.to, request.kind) {
            (MoveTarget::Cartesian(_), MoveKind::Linear) if tool.robhold => Some(tool.tframe),
            (MoveTarget::Cartesian(_), MoveKind::Linear) => Some(Isometry3::identity()),
            _ => None,
        };
        self.from = self.joints;
        self.start = request.at;
        self.joints = joints;
        self.extax = extax;
        self.at_rest = request.zone.finep;
        self.until = request.at + seconds;
        Ok(Motion {
            duration: seconds,
            joints: Some(JointTarget {
                robax: joints,
                extax,
            }),
        })
    }

    fn robtarget(&self, tool: &Tool, wobj: &WObj) -> Result<RobTarget, RobotError> {
        let t = self.calc_robtarget(
            &JointTarget {
                robax: self.joints,
                extax: self.extax,
            },
            tool,
            wobj,
        )?;
        Ok(t)
    }

    fn joints(&self) -> Result<JointTarget, RobotError> {
        Ok(JointTarget {
            robax: self.joints,
            extax: self.extax,
        })
    }

    fn calc_joints(
        &self,
        target: &RobTarget,
        tool: &Tool,
        wobj: &WObj,
    ) -> Result<JointTarget, RobotError> {
        let t = frames::RobTarget {
            pose: iso(&target.pose),
            conf: conf_of(&target.robconf),
            extax: target.extax,
        };
        let sol = self
            .robot
            .calc_joint_t(&t, &tool_of(tool), &wobj_of(wobj), self.conf_l)
            .map_err(|e| raised(&e))?;
        Ok(JointTarget {
            robax: sol.joints,
            extax: target.extax,
        })
    }

    fn calc_robtarget(
        &self,
        joints: &JointTarget,
        tool: &Tool,
        wobj: &WObj,
    ) -> Result<RobTarget, RobotError> {
        let Some((pose, conf)) =
            self.robot
                .calc_rob_t(&joints.robax, &tool_of(tool), &wobj_of(wobj))
        else {
            return Err(RobotError::Other(
                "the joint angles are not numbers".to_owned(),
            ));
        };
        Ok(RobTarget {
            pose: Pose::from_isometry(&pose),
            robconf: [
                f64::from(conf.cf1),
                f64::from(conf.cf4),
                f64::from(conf.cf6),
                f64::from(conf.cfx),
            ],
            extax: joints.extax,
        })
    }

    fn joints_at(&self, at: f64) -> Result<JointTarget, RobotError> {
        Ok(JointTarget {
            robax: self.joints_then(at),
            extax: self.extax,
        })
    }

    fn robtarget_at(&self, tool: &Tool, wobj: &WObj, at: f64) -> Result<RobTarget, RobotError> {
        self.calc_robtarget(&self.joints_at(at)?, tool, wobj)
    }

    fn pause(&mut self, at: f64) -> Option<f64> {
        if at >= self.until || self.paused.is_some() {
            return None;
        }
        let left = self.until - at;
        self.paused = Some((self.joints, self.extax));
        self.joints = self.joints_then(at);
        self.from = self.joints;
        self.start = at;
        self.until = at;
        self.at_rest = true;
        Some(left)
    }

    fn resume(&mut self, at: f64, seconds: f64, keep: bool) {
        let Some((joints, extax)) = self.paused.take() else {
            return;
        };
        if !keep {
            return;
        }
        self.from = self.joints;
        self.start = at;
        self.joints = joints;
        self.extax = extax;
        self.until = at + seconds.max(0.0);
    }

    fn set_conf(&mut self, linear: bool, on: bool) {
        if linear {
            self.conf_l = on;
        } else {
            self.conf_j = on;
        }
    }
}
