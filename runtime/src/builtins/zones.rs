//! World zones: the shapes (`WZBoxDef`, `WZCylDef`, `WZSphDef`,
//! `WZHomeJointDef`, `WZLimJointDef`), the zones that set an output
//! (`WZDOSet`) or stop the robot (`WZLimSup`), and `WZEnable`,
//! `WZDisable`, `WZFree`.
//!
//! What is modelled: each zone of a task is checked where each move of
//! the task ends (and an output zone also when it is activated): a
//! Cartesian shape against the TCP of the move's tool in the world frame,
//! a joint shape against the robot's axes 1 to 6. An output zone sets its
//! signal to `SetValue` inside the shape and to the other value outside,
//! when the move ends; a limit zone stops the program when a move ends
//! inside its shape. What is not: the path between the ends of moves
//! (a move that crosses a zone without ending in it goes unseen), `\Before`
//! (taken as `\Inside`), external axes, and the controller's minimum
//! sizes of a shape. Without a kinematic model, a joint shape knows the
//! axes only after `MoveAbsJ`, a Cartesian shape the TCP only after a
//! Cartesian move; a zone whose shape cannot be checked counts as left.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, R, fault, invalid};
use crate::world::{Tool, WObj};

/// The geometry of a `shapedata`.
#[derive(Clone, Debug)]
pub(crate) enum Shape {
    /// Two opposite corners, sorted per axis (mm, world frame).
    Box {
        low: [f64; 3],
        high: [f64; 3],
    },
    /// The centre of the base, the radius, the height (negative: down).
    Cylinder {
        centre: [f64; 3],
        radius: f64,
        height: f64,
    },
    Sphere {
        centre: [f64; 3],
        radius: f64,
    },
    /// Each axis within `[low, high]` (degrees; 9E9 leaves an axis free).
    Joints {
        low: [f64; 6],
        high: [f64; 6],
    },
}

/// A shape and which side of it counts (`\Inside`, `\Outside`).
#[derive(Clone, Debug)]
pub(crate) struct ShapeDef {
    shape: Shape,
    outside: bool,
}

/// What an active zone does.
#[derive(Clone, Debug)]
enum Action {
    /// `WZDOSet`: the signal gets `value` inside, the other value outside.
    Output { signal: String, value: f64 },
    /// `WZLimSup`: the robot may not be inside.
    Limit,
}

/// An active world zone of the task.
#[derive(Clone, Debug)]
pub(crate) struct Zone {
    id: u32,
    shape: ShapeDef,
    action: Action,
    enabled: bool,
    stationary: bool,
    /// Where it was activated, for a limit zone's stop message.
    at: String,
}

/// The world zones of a task.
#[derive(Clone, Debug, Default)]
pub(crate) struct Zones {
    shapes: Vec<ShapeDef>,
    zones: Vec<Zone>,
    next_id: u32,
}

const FREE: f64 = 8.9e9;

impl Shape {
    /// Is the point (TCP, mm) or are the axes (degrees) inside? `None`:
    /// the robot's state this shape needs is not known.
    fn contains(&self, tcp: Option<[f64; 3]>, joints: Option<[f64; 6]>) -> Option<bool> {
        match self {
            Shape::Box { low, high } => {
                let p = tcp?;
                Some((0..3).all(|i| low[i] <= p[i] && p[i] <= high[i]))
            }
            Shape::Cylinder {
                centre,
                radius,
                height,
            } => {
                let p = tcp?;
                let (dx, dy) = (p[0] - centre[0], p[1] - centre[1]);
                let (z0, z1) = if *height >= 0.0 {
                    (centre[2], centre[2] + height)
                } else {
                    (centre[2] + height, centre[2])
                };
                Some(dx * dx + dy * dy <= radius * radius && z0 <= p[2] && p[2] <= z1)
            }
            Shape::Sphere { centre, radius } => {
                let p = tcp?;
                let d2: f64 = (0..3).map(|i| (p[i] - centre[i]).powi(2)).sum();
                Some(d2 <= radius * radius)
            }
            Shape::Joints { low, high } => {
                let j = joints?;
                Some((0..6).all(|i| {
                    low[i].abs() >= FREE
                        || high[i].abs() >= FREE
                        || (low[i] <= j[i] && j[i] <= high[i])
                }))
            }
        }
    }
}

impl ShapeDef {
    fn contains(&self, tcp: Option<[f64; 3]>, joints: Option<[f64; 6]>) -> Option<bool> {
        self.shape
            .contains(tcp, joints)
            .map(|inside| inside != self.outside)
    }
}

/// Stores a shape in the `Shape` argument (as its number in the task).
fn define(cx: &mut Cx<'_>, a: &Args, shape: Shape) -> R<Done> {
    if a.given("Inside") == a.given("Outside") {
        return invalid(format!("{}: give one of \\Inside and \\Outside", a.name));
    }
    let p = cx.place_arg(a, "Shape")?;
    let zones = &mut cx.m.zones;
    zones.shapes.push(ShapeDef {
        shape,
        outside: a.given("Outside"),
    });
    let n = zones.shapes.len() as f32;
    cx.store(
        &p,
        Value::Record {
            ty: "shapedata".to_owned(),
            fields: vec![("shape".to_owned(), Value::Num(n))],
        },
    )?;
    Ok(Done::Next)
}

fn point(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<[f64; 3]> {
    Ok(super::motion::nums(
        Some(&cx.req(a, param)?),
        ["x", "y", "z"],
    ))
}

/// The robot axes of a jointtarget argument (degrees).
fn axes(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<[f64; 6]> {
    Ok(super::motion::jointtarget(&cx.req(a, param)?)?.robax)
}

/// `WZBoxDef [\Inside] | [\Outside] Shape LowPoint HighPoint`.
pub(crate) fn wz_box_def(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (p, q) = (point(cx, a, "LowPoint")?, point(cx, a, "HighPoint")?);
    let low = [p[0].min(q[0]), p[1].min(q[1]), p[2].min(q[2])];
    let high = [p[0].max(q[0]), p[1].max(q[1]), p[2].max(q[2])];
    define(cx, a, Shape::Box { low, high })
}

/// `WZCylDef [\Inside] | [\Outside] Shape CentrePoint Radius Height`.
pub(crate) fn wz_cyl_def(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let centre = point(cx, a, "CentrePoint")?;
    let radius = cx.num(a, "Radius")?;
    let height = cx.num(a, "Height")?;
    define(
        cx,
        a,
        Shape::Cylinder {
            centre,
            radius,
            height,
        },
    )
}

/// `WZSphDef [\Inside] | [\Outside] Shape CentrePoint Radius`.
pub(crate) fn wz_sph_def(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let centre = point(cx, a, "CentrePoint")?;
    let radius = cx.num(a, "Radius")?;
    define(cx, a, Shape::Sphere { centre, radius })
}

/// `WZHomeJointDef [\Inside] | [\Outside] Shape MiddleJointVal
/// DeltaJointVal`: each axis within its delta of the middle value.
pub(crate) fn wz_home_joint_def(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let middle = axes(cx, a, "MiddleJointVal")?;
    let delta = axes(cx, a, "DeltaJointVal")?;
    let mut low = [0.0; 6];
    let mut high = [0.0; 6];
    for i in 0..6 {
        if middle[i].abs() >= FREE {
            (low[i], high[i]) = (9e9, 9e9);
        } else {
            (low[i], high[i]) = (middle[i] - delta[i].abs(), middle[i] + delta[i].abs());
        }
    }
    define(cx, a, Shape::Joints { low, high })
}

/// `WZLimJointDef [\Inside] | [\Outside] Shape LowJointVal HighJointVal`.
pub(crate) fn wz_lim_joint_def(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let low = axes(cx, a, "LowJointVal")?;
    let high = axes(cx, a, "HighJointVal")?;
    define(cx, a, Shape::Joints { low, high })
}

/// The shape a `shapedata` argument holds.
fn shape_of(cx: &mut Cx<'_>, a: &Args) -> R<ShapeDef> {
    let v = cx.req(a, "Shape")?;
    let n = v.field("shape").and_then(Value::as_f64).unwrap_or(0.0) as usize;
    match n.checked_sub(1).and_then(|i| cx.m.zones.shapes.get(i)) {
        Some(s) => Ok(s.clone()),
        None => invalid(format!(
            "{}: the shape is not defined (WZBoxDef, WZCylDef, WZSphDef, WZHomeJointDef or WZLimJointDef first)",
            a.name
        )),
    }
}

/// Adds a zone and gives its identity to `WorldZone`.
fn activate(cx: &mut Cx<'_>, a: &Args, action: Action) -> R<u32> {
    if a.given("Temp") == a.given("Stat") {
        return invalid(format!("{}: give one of \\Temp and \\Stat", a.name));
    }
    let shape = shape_of(cx, a)?;
    let p = cx.place_arg(a, "WorldZone")?;
    let at =
        cx.m.location()
            .map_or_else(String::new, |l| format!("{}:{}", l.path, l.line));
    let zones = &mut cx.m.zones;
    zones.next_id += 1;
    let id = zones.next_id;
    zones.zones.push(Zone {
        id,
        shape,
        action,
        enabled: true,
        stationary: a.given("Stat"),
        at,
    });
    let ty = if a.given("Stat") {
        "wzstationary"
    } else {
        "wztemporary"
    };
    cx.store(
        &p,
        Value::Record {
            ty: ty.to_owned(),
            fields: vec![("wz".to_owned(), Value::Num(id as f32))],
        },
    )?;
    Ok(id)
}

/// `WZDOSet [\Temp] | [\Stat] WorldZone [\Inside] | [\Before] Shape
/// Signal SetValue`: the output follows the zone from now on.
pub(crate) fn wz_do_set(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = cx.req(a, "Signal")?;
    let (signal, _) = cx.m.signal_of(cx.sh, &s)?;
    let value = cx.num(a, "SetValue")?;
    if value != 0.0 && value != 1.0 {
        return invalid(format!("WZDOSet: SetValue {value} is not 0 or 1"));
    }
    let id = activate(cx, a, Action::Output { signal, value })?;
    let index = cx.robot_index(a)?;
    let tool = match cx.m.active[0].clone() {
        Some(v) => cx.tool_of(&v)?,
        None => Tool::default(),
    };
    supervise(cx, index, &tool, 0.0, Some(id))?;
    Ok(Done::Next)
}

/// `WZLimSup [\Temp] | [\Stat] WorldZone Shape`.
pub(crate) fn wz_lim_sup(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    activate(cx, a, Action::Limit)?;
    Ok(Done::Next)
}

/// The temporary zone a `WorldZone` argument names.
fn zone_index(cx: &mut Cx<'_>, a: &Args) -> R<usize> {
    let v = cx.req(a, "WorldZone")?;
    let id = v.field("wz").and_then(Value::as_f64).unwrap_or(0.0) as u32;
    match cx.m.zones.zones.iter().position(|z| z.id == id) {
        Some(i) if cx.m.zones.zones[i].stationary => invalid(format!(
            "{}: a stationary world zone cannot be changed",
            a.name
        )),
        Some(i) => Ok(i),
        None => invalid(format!("{}: the world zone is not active", a.name)),
    }
}

/// `WZEnable WorldZone`.
pub(crate) fn wz_enable(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let i = zone_index(cx, a)?;
    cx.m.zones.zones[i].enabled = true;
    Ok(Done::Next)
}

/// `WZDisable WorldZone`.
pub(crate) fn wz_disable(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let i = zone_index(cx, a)?;
    cx.m.zones.zones[i].enabled = false;
    Ok(Done::Next)
}

/// `WZFree WorldZone`.
pub(crate) fn wz_free(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let i = zone_index(cx, a)?;
    cx.m.zones.zones.remove(i);
    Ok(Done::Next)
}

/// Checks the task's enabled zones (or only zone `only`) where the robot
/// is now, the TCP being that of `tool`: outputs change `delay` seconds
/// from now (when the move ends); a limit zone the robot is inside stops
/// the program.
pub(crate) fn supervise(
    cx: &mut Cx<'_>,
    index: usize,
    tool: &Tool,
    delay: f64,
    only: Option<u32>,
) -> R<()> {
    if cx.m.zones.zones.is_empty() {
        return Ok(());
    }
    let (tcp, joints) = match cx.sh.robots.get(index).and_then(Option::as_ref) {
        Some(robot) => {
            let known = robot.known();
            let tcp = robot
                .robtarget(tool, &WObj::default())
                .ok()
                .filter(|_| known.tcp)
                .map(|t| t.pose.trans);
            let joints = robot
                .joints()
                .ok()
                .filter(|_| known.joints)
                .map(|j| j.robax);
            (tcp, joints)
        }
        None => return Ok(()),
    };
    let mut changes = Vec::new();
    for z in &cx.m.zones.zones {
        if !z.enabled || only.is_some_and(|id| id != z.id) {
            continue;
        }
        let inside = z.shape.contains(tcp, joints);
        match &z.action {
            Action::Output { signal, value } => {
                let v = if inside == Some(true) {
                    *value
                } else {
                    1.0 - value
                };
                changes.push((signal.clone(), v));
            }
            Action::Limit if inside == Some(true) => {
                return fault(FaultKind::Motion(format!(
                    "world zone violated: the robot ends a move inside the zone that WZLimSup forbids ({})",
                    z.at
                )));
            }
            Action::Limit => {}
        }
    }
    for (signal, v) in changes {
        cx.sh.set_signal_on_path(index, &signal, v, delay);
    }
    Ok(())
}
