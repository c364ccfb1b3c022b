//! How a value changed: positions and frames measured (the evaluator's
//! pose math, [`rapid_evaluator::distance_mm`] and
//! [`rapid_evaluator::rotation_deg`]), arm configurations, joints and
//! external axes named, every other component listed by path with its old
//! and new value.
//!
//! Records are recognised by type: `pos`, `orient`, `pose` and any record
//! with a `pos` `trans` and an `orient` `rot` (`robtarget`) are frames;
//! `confdata` is the arm configuration; `robjoint` the robot's joints;
//! `extjoint` the external axes. A `wobjdata` moves by its user frame
//! times its object frame ([`rapid_evaluator::wobj_frame`]).

use rapid_evaluator::{Value, distance_mm, rotation_deg, wobj_frame};

use super::{FieldChange, FrameChange, Motion, Options};

/// What changed between two values of one datum.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ValueChange {
    /// Frames, joints, configuration and external axes; `None` when none
    /// of them changed.
    pub motion: Option<Motion>,
    /// Every other component that changed.
    pub fields: Vec<FieldChange>,
}

impl ValueChange {
    /// A move smaller than the thresholds and nothing else.
    pub fn is_small(&self, options: &Options) -> bool {
        let below = |x: Option<f64>, limit: f64| x.is_none_or(|x| x == 0.0 || x < limit);
        self.fields.is_empty()
            && self.motion.as_ref().is_some_and(|m| {
                m.conf.is_none()
                    && m.external_axes.is_empty()
                    && below(m.translation_mm, options.moves_below_mm)
                    && below(m.rotation_deg, options.rotations_below_deg)
                    && below(m.joints_deg, options.rotations_below_deg)
            })
    }
}

/// The components of a frame record (record components, not syntax).
const TRANS: &str = "trans";
const ROT: &str = "rot";

#[derive(Default)]
struct Acc {
    frames: Vec<FrameChange>,
    joints: Option<f64>,
    joint_changes: Vec<FieldChange>,
    conf: Option<(String, String)>,
    external_axes: Vec<FieldChange>,
    fields: Vec<FieldChange>,
}

/// Compares two values of a datum.
pub fn compare_values(old: &Value, new: &Value) -> ValueChange {
    let mut acc = Acc::default();
    walk("", old, new, true, &mut acc);
    let mut motion = Motion {
        joints_deg: acc.joints,
        joints: acc.joint_changes,
        conf: acc.conf,
        external_axes: acc.external_axes,
        ..Motion::default()
    };
    let max = |f: fn(&FrameChange) -> Option<f64>| {
        acc.frames
            .iter()
            .filter_map(f)
            .fold(None, |m: Option<f64>, x| Some(m.map_or(x, |m| m.max(x))))
    };
    let wobj = (type_is(old, "wobjdata") && type_is(new, "wobjdata"))
        .then(|| Some((wobj_frame(old)?, wobj_frame(new)?)))
        .flatten();
    match wobj {
        Some((a, b)) if !acc.frames.is_empty() => {
            motion.translation_mm = distance_mm(&a, &b);
            motion.rotation_deg = rotation_deg(&a, &b);
        }
        _ => {
            motion.translation_mm = max(|f| f.translation_mm);
            motion.rotation_deg = max(|f| f.rotation_deg);
        }
    }
    // Frames inside the value are listed; the value's own is the motion.
    if acc.frames.iter().any(|f| !f.path.is_empty()) {
        motion.frames = acc.frames;
    }
    let any = motion.translation_mm.is_some()
        || motion.rotation_deg.is_some()
        || motion.joints_deg.is_some()
        || motion.conf.is_some()
        || !motion.external_axes.is_empty()
        || !motion.frames.is_empty();
    ValueChange {
        motion: any.then_some(motion),
        fields: acc.fields,
    }
}

fn type_is(v: &Value, name: &str) -> bool {
    v.type_name().is_some_and(|t| t.eq_ignore_ascii_case(name))
}

fn join(path: &str, name: &str) -> String {
    if path.is_empty() {
        name.to_owned()
    } else {
        format!("{path}.{name}")
    }
}

fn is_frame(v: &Value) -> bool {
    v.field(TRANS).is_some_and(|t| type_is(t, "pos"))
        && v.field(ROT).is_some_and(|r| type_is(r, "orient"))
}

/// Compares two values below `path`; with `frames` false, positions and
/// orientations are compared as plain fields (a tool's load: its centre of
/// gravity moving is not the tool moving).
fn walk(path: &str, old: &Value, new: &Value, frames: bool, acc: &mut Acc) {
    if old == new {
        return;
    }
    match (old, new) {
        (Value::Record { ty: a, fields: fa }, Value::Record { ty: b, fields: fb })
            if !frames && a.eq_ignore_ascii_case(b) && fa.len() == fb.len() =>
        {
            let leaf = fa
                .iter()
                .all(|(_, v)| !matches!(v, Value::Record { .. } | Value::Array(_)));
            if leaf {
                acc.fields.push(FieldChange {
                    path: path.to_owned(),
                    old: old.to_string(),
                    new: new.to_string(),
                });
            } else {
                for ((name, x), (_, y)) in fa.iter().zip(fb) {
                    walk(&join(path, name), x, y, false, acc);
                }
            }
        }
        (Value::Record { ty: a, fields: fa }, Value::Record { ty: b, fields: fb })
            if a.eq_ignore_ascii_case(b) && fa.len() == fb.len() =>
        {
            let ty = a.to_ascii_lowercase();
            match ty.as_str() {
                "pos" => acc.frames.push(FrameChange {
                    path: path.to_owned(),
                    translation_mm: distance_mm(old, new),
                    rotation_deg: None,
                }),
                "orient" => acc.frames.push(FrameChange {
                    path: path.to_owned(),
                    translation_mm: None,
                    rotation_deg: rotation_deg(old, new),
                }),
                "confdata" => acc.conf = Some((old.to_string(), new.to_string())),
                "extjoint" | "robjoint" => {
                    for ((name, x), (_, y)) in fa.iter().zip(fb) {
                        if x == y {
                            continue;
                        }
                        let change = FieldChange {
                            path: join(path, name),
                            old: x.to_string(),
                            new: y.to_string(),
                        };
                        if ty == "extjoint" {
                            acc.external_axes.push(change);
                        } else {
                            let delta = match (x.as_f64(), y.as_f64()) {
                                (Some(x), Some(y)) => (y - x).abs(),
                                _ => 0.0,
                            };
                            acc.joints = Some(acc.joints.map_or(delta, |j| j.max(delta)));
                            acc.joint_changes.push(change);
                        }
                    }
                }
                _ if is_frame(old) && is_frame(new) => {
                    let (t, r) = (old.field(TRANS), old.field(ROT));
                    let moved = t != new.field(TRANS) || r != new.field(ROT);
                    if moved {
                        acc.frames.push(FrameChange {
                            path: path.to_owned(),
                            translation_mm: distance_mm(old, new),
                            rotation_deg: rotation_deg(old, new),
                        });
                    }
                    for ((name, x), (_, y)) in fa.iter().zip(fb) {
                        if !name.eq_ignore_ascii_case(TRANS) && !name.eq_ignore_ascii_case(ROT) {
                            walk(&join(path, name), x, y, true, acc);
                        }
                    }
                }
                _ => {
                    let tool = ty == "tooldata";
                    for ((name, x), (_, y)) in fa.iter().zip(fb) {
                        let frames = !(tool && name.eq_ignore_ascii_case("tload"));
                        walk(&join(path, name), x, y, frames, acc);
                    }
                }
            }
        }
        (Value::Array(a), Value::Array(b)) if a.len() == b.len() => {
            for (i, (x, y)) in a.iter().zip(b).enumerate() {
                walk(&format!("{path}{{{}}}", i + 1), x, y, frames, acc);
            }
        }
        _ => acc.fields.push(FieldChange {
            path: path.to_owned(),
            old: old.to_string(),
            new: new.to_string(),
        }),
    }
}
