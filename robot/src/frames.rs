//! Targets read as the controller reads them: a robtarget is the TCP's pose
//! in the work object's object frame (`oframe`, inside `uframe`), the TCP is
//! the tool's `tframe` on the mounting flange (tool0), and the work object's
//! user frame is in the world frame, where the robot's base frame sits.
//!
//! A stationary tool (`robhold` FALSE) is a TCP fixed in the world, and the
//! work object is held by the robot: the flange carries the work object.
//! A user frame moved by a mechanical unit (`ufmec` naming a unit with
//! `ufprog` FALSE: a conveyor, a positioner) is not supported.

use nalgebra::Isometry3;
use rapid_evaluator::{Value, iso_of};

use crate::conf::Conf;

/// Why a value cannot be read as a target, tool or work object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FrameError {
    /// Not a value of the expected record type (or a component missing).
    NotA(&'static str),
    /// An orientation that is not normalised (the controller's
    /// ERR_ILLQUAT / event 50076).
    Orientation(String),
    /// A user frame on a mechanical unit (`ufmec`).
    MovingUserFrame(String),
}

impl std::fmt::Display for FrameError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FrameError::NotA(what) => write!(f, "not a {what}"),
            FrameError::Orientation(m) => f.write_str(m),
            FrameError::MovingUserFrame(unit) => write!(
                f,
                "the work object's user frame moves with mechanical unit {unit}, which is not modelled"
            ),
        }
    }
}

/// A robtarget.
#[derive(Clone, Debug, PartialEq)]
pub struct RobTarget {
    /// The TCP in the work object's object frame, mm.
    pub pose: Isometry3<f64>,
    pub conf: Conf,
    /// External axes, carried through (9E9 for an axis not used).
    pub extax: [f64; 6],
}

/// A tooldata.
#[derive(Clone, Debug, PartialEq)]
pub struct Tool {
    /// The robot holds the tool (TRUE for most tools).
    pub robhold: bool,
    /// The TCP on the flange (robhold), or in the world (stationary tool).
    pub tframe: Isometry3<f64>,
}

/// A wobjdata.
#[derive(Clone, Debug, PartialEq)]
pub struct WObj {
    /// The robot holds the work object (with a stationary tool).
    pub robhold: bool,
    pub uframe: Isometry3<f64>,
    pub oframe: Isometry3<f64>,
}

impl Default for Tool {
    /// tool0.
    fn default() -> Tool {
        Tool {
            robhold: true,
            tframe: Isometry3::identity(),
        }
    }
}

impl Default for WObj {
    /// wobj0.
    fn default() -> WObj {
        WObj {
            robhold: false,
            uframe: Isometry3::identity(),
            oframe: Isometry3::identity(),
        }
    }
}

fn field<'v>(v: &'v Value, name: &str, what: &'static str) -> Result<&'v Value, FrameError> {
    v.field(name).ok_or(FrameError::NotA(what))
}

fn frame(v: &Value, what: &'static str) -> Result<Isometry3<f64>, FrameError> {
    iso_of(v).map_err(|e| match e.code {
        rapid_evaluator::ErrorCode::IllQuat => FrameError::Orientation(e.message),
        _ => FrameError::NotA(what),
    })
}

fn num(v: &Value, name: &str, what: &'static str) -> Result<f64, FrameError> {
    field(v, name, what)?.as_f64().ok_or(FrameError::NotA(what))
}

fn boolean(v: &Value, name: &str, what: &'static str) -> Result<bool, FrameError> {
    match field(v, name, what)? {
        Value::Bool(b) => Ok(*b),
        _ => Err(FrameError::NotA(what)),
    }
}

/// Reads a robtarget value.
pub fn robtarget(v: &Value) -> Result<RobTarget, FrameError> {
    const W: &str = "robtarget";
    let pose = frame(v, W)?;
    let c = field(v, "robconf", W)?;
    let q = |n: &str| num(c, n, W).map(|x| x.round() as i32);
    let conf = Conf {
        cf1: q("cf1")?,
        cf4: q("cf4")?,
        cf6: q("cf6")?,
        cfx: q("cfx")?,
    };
    Ok(RobTarget {
        pose,
        conf,
        extax: extax(field(v, "extax", W)?, W)?,
    })
}

fn extax(v: &Value, what: &'static str) -> Result<[f64; 6], FrameError> {
    let mut out = [0.0; 6];
    for (o, n) in out
        .iter_mut()
        .zip(["eax_a", "eax_b", "eax_c", "eax_d", "eax_e", "eax_f"])
    {
        *o = num(v, n, what)?;
    }
    Ok(out)
}

/// Reads a jointtarget: the robot's six axes (degrees) and the external
/// axes.
pub fn jointtarget(v: &Value) -> Result<([f64; 6], [f64; 6]), FrameError> {
    const W: &str = "jointtarget";
    let r = field(v, "robax", W)?;
    let mut robax = [0.0; 6];
    for (o, n) in robax
        .iter_mut()
        .zip(["rax_1", "rax_2", "rax_3", "rax_4", "rax_5", "rax_6"])
    {
        *o = num(r, n, W)?;
    }
    Ok((robax, extax(field(v, "extax", W)?, W)?))
}

/// Reads a tooldata value.
pub fn tool(v: &Value) -> Result<Tool, FrameError> {
    const W: &str = "tooldata";
    Ok(Tool {
        robhold: boolean(v, "robhold", W)?,
        tframe: frame(field(v, "tframe", W)?, W)?,
    })
}

/// Reads a wobjdata value.
pub fn wobj(v: &Value) -> Result<WObj, FrameError> {
    const W: &str = "wobjdata";
    let ufprog = boolean(v, "ufprog", W)?;
    let ufmec = field(v, "ufmec", W)?.as_str().unwrap_or_default().trim();
    if !ufprog && !ufmec.is_empty() {
        return Err(FrameError::MovingUserFrame(ufmec.to_owned()));
    }
    Ok(WObj {
        robhold: boolean(v, "robhold", W)?,
        uframe: frame(field(v, "uframe", W)?, W)?,
        oframe: frame(field(v, "oframe", W)?, W)?,
    })
}

/// tool0's pose in the robot's base frame for the TCP at `target` (in the
/// work object), with `tool`, `wobj` and the base frame `base` (in the
/// world). With a stationary tool the flange carries the work object.
pub fn flange_in_base(
    target: &Isometry3<f64>,
    tool: &Tool,
    wobj: &WObj,
    base: &Isometry3<f64>,
) -> Isometry3<f64> {
    let object = wobj.uframe * wobj.oframe;
    if tool.robhold {
        base.inverse() * object * target * tool.tframe.inverse()
    } else {
        // The TCP (fixed, in the world) meets the target on the held work
        // object: flange * object * target = tframe.
        base.inverse() * tool.tframe * (object * target).inverse()
    }
}

/// The TCP's pose in the work object for tool0 at `flange` (base frame):
/// the inverse of [`flange_in_base`] (CRobT, CalcRobT).
pub fn target_of_flange(
    flange: &Isometry3<f64>,
    tool: &Tool,
    wobj: &WObj,
    base: &Isometry3<f64>,
) -> Isometry3<f64> {
    let object = wobj.uframe * wobj.oframe;
    if tool.robhold {
        object.inverse() * base * flange * tool.tframe
    } else {
        object.inverse() * (base * flange).inverse() * tool.tframe
    }
}
