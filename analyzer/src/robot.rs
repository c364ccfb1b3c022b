//! The robot a task's moves are made by: from the controller's `MOC.cfg`
//! (the `ROBOT` instance's `-use_robot_type`, its base frame, and the `ARM`
//! instances' joint bounds in radians), else from the project's
//! `[controller] robot` (rapid.toml or the editor's settings). The
//! kinematics are the `rapid-robot` crate's; the rules that use them are
//! `target-out-of-reach`, `joint-out-of-range` and
//! `configuration-mismatch` (through `check::motion`).

use std::sync::Arc;

use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};
use rapid_robot::{JointLimits, Lookup, Robot};

use crate::cfg::{CfgFile, Instance};

/// A `ROBOT` instance of `MOC.cfg` with its arms' joint bounds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MocRobot {
    /// `-name`, `ROB_1`.
    pub name: String,
    /// `-use_robot_type`, `ROB1_120_0.58_3`.
    pub robot_type: String,
    /// Each axis's (`-lower_joint_bound`, `-upper_joint_bound`), radians.
    pub bounds: [(Option<f64>, Option<f64>); 6],
    /// The base frame in the world: position (mm) and orientation.
    pub base: Isometry3<f64>,
    /// `-base_frame_coordinated`: the base moves with another mechanical
    /// unit (a track), which is not modelled.
    pub coordinated: Option<String>,
    /// The `MECHANICAL_UNIT_GROUP`s whose `-robot` it is, as written: the
    /// MultiMove tasks that use one of them (`SYS.cfg`'s
    /// `-UseMechanicalUnitGroup`) move this robot.
    pub groups: Vec<String>,
}

fn number(entry: &Instance, attr: &str) -> Option<f64> {
    entry.get(attr)?.trim().parse().ok()
}

/// The robot number of an instance name: `ROB_2` and `rob2_3` give 2.
fn robot_number(name: &str) -> Option<u32> {
    let lower = name.to_ascii_lowercase();
    let rest = lower.strip_prefix("rob")?.trim_start_matches('_');
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    digits.parse().ok()
}

/// The robots of a `MOC.cfg` (none when it has no `ROBOT` section).
pub fn parse_moc_robots(cfg: &str) -> Vec<MocRobot> {
    moc_robots(&crate::cfg::parse(cfg))
}

/// The robots of a configuration file already read ([`crate::cfg`]).
pub fn moc_robots(file: &CfgFile) -> Vec<MocRobot> {
    let mut robots: Vec<MocRobot> = Vec::new();
    for e in file.instances("ROBOT") {
        let (Some(name), Some(robot_type)) = (e.get("name"), e.get("use_robot_type")) else {
            continue;
        };
        let (name, robot_type) = (name.to_owned(), robot_type.to_owned());
        let m = |o: &str| number(e, o).unwrap_or(0.0) * 1000.0;
        let q = |o: &str, d: f64| number(e, o).unwrap_or(d);
        let rotation = Quaternion::new(
            q("base_frame_orient_u0", 1.0),
            q("base_frame_orient_u1", 0.0),
            q("base_frame_orient_u2", 0.0),
            q("base_frame_orient_u3", 0.0),
        );
        let rotation = if rotation.norm() > 0.5 {
            UnitQuaternion::from_quaternion(rotation)
        } else {
            UnitQuaternion::identity()
        };
        robots.push(MocRobot {
            name,
            robot_type,
            bounds: Default::default(),
            base: Isometry3::from_parts(
                Translation3::new(
                    m("base_frame_pos_x"),
                    m("base_frame_pos_y"),
                    m("base_frame_pos_z"),
                ),
                rotation,
            ),
            coordinated: e
                .get("base_frame_coordinated")
                .filter(|s| !s.is_empty())
                .map(str::to_owned),
            groups: Vec::new(),
        });
    }
    for e in file.instances("MECHANICAL_UNIT_GROUP") {
        let (Some(group), Some(robot)) = (e.get("name"), e.get("robot")) else {
            continue;
        };
        if let Some(r) = robots
            .iter_mut()
            .find(|r| r.name.eq_ignore_ascii_case(robot))
        {
            r.groups.push(group.to_owned());
        }
    }
    for e in file.instances("ARM") {
        let Some(name) = e.get("name") else {
            continue;
        };
        // `rob1_3`: robot 1, axis 3.
        let axis: Option<usize> = name
            .rsplit('_')
            .next()
            .and_then(|d| d.parse().ok())
            .filter(|a| (1..=6).contains(a));
        let (Some(n), Some(axis)) = (robot_number(name), axis) else {
            continue;
        };
        if let Some(r) = robots.iter_mut().find(|r| robot_number(&r.name) == Some(n)) {
            r.bounds[axis - 1] = (
                number(e, "lower_joint_bound"),
                number(e, "upper_joint_bound"),
            );
        }
    }
    robots
}

/// The robot named in the project's configuration, with optional joint
/// limits in degrees.
#[derive(Clone, Debug, Default)]
pub struct RobotSetting {
    pub name: String,
    pub limits: Option<[[f64; 2]; 6]>,
}

impl PartialEq for RobotSetting {
    fn eq(&self, other: &RobotSetting) -> bool {
        self.name == other.name
            && self.limits.map(|l| l.map(|a| a.map(f64::to_bits)))
                == other.limits.map(|l| l.map(|a| a.map(f64::to_bits)))
    }
}

impl Eq for RobotSetting {}

impl std::hash::Hash for RobotSetting {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.name.hash(state);
        self.limits
            .map(|l| l.map(|a| a.map(f64::to_bits)))
            .hash(state);
    }
}

/// Where a task's robot is named.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RobotSource {
    /// The controller's `MOC.cfg` (a backup's, or one beside the modules).
    MocCfg,
    /// The project's `[controller] robot` (rapid.toml or the editor's
    /// settings).
    Project,
}

/// A task's robot, and where it comes from.
#[derive(Clone, Debug, PartialEq)]
pub struct TaskRobot {
    pub robot: Robot,
    pub source: RobotSource,
    /// `MOC.cfg ROB_1 (ROB1_120_0.58_3)`, `the project's [controller] robot`.
    pub origin: String,
}

impl TaskRobot {
    /// What identifies it for cache keys: model, limits and base.
    pub fn fingerprint(&self) -> String {
        format!(
            "{}|{:?}|{:?}",
            self.robot.model.name, self.robot.limits.0, self.robot.base
        )
    }
}

/// Which task a robot is looked for: the task's folder (`key`), its name
/// on the controller and its mechanical unit group (`SYS.cfg`).
#[derive(Clone, Copy, Debug, Default)]
pub struct RobotOf<'a> {
    pub key: &'a str,
    /// `-Name` of its `CAB_TASKS` entry (`T_ROB2` kept in `RAPID/TASK2`).
    pub name: Option<&'a str>,
    /// `-UseMechanicalUnitGroup` of its `CAB_TASKS` entry.
    pub group: Option<&'a str>,
}

/// The robot of a task from the `MOC.cfg` robots that apply to it, else
/// from the project's setting; `Err` with a note when a robot is named but
/// not modelled (or moves on a track). With several robots (MultiMove), a
/// task moves the robot of its mechanical unit group, else task `T_ROBn`
/// (its name, else its folder's) moves robot *n*.
pub fn resolve(
    task: RobotOf<'_>,
    mocs: &[&MocRobot],
    setting: Option<&RobotSetting>,
) -> Result<Option<Arc<TaskRobot>>, String> {
    let moc = match mocs {
        [] => None,
        [one] => Some(*one),
        several => {
            let by_group = task.group.and_then(|g| {
                several
                    .iter()
                    .find(|r| r.groups.iter().any(|x| x.eq_ignore_ascii_case(g)))
            });
            let number = |name: &str| {
                name.to_ascii_lowercase()
                    .strip_prefix("t_rob")
                    .and_then(|d| d.parse::<u32>().ok())
            };
            let folder = task.key.rsplit('/').next().unwrap_or(task.key);
            let n = task.name.and_then(number).or_else(|| number(folder));
            by_group
                .or_else(|| {
                    several
                        .iter()
                        .find(|r| n.is_some() && robot_number(&r.name) == n)
                })
                .copied()
        }
    };
    if let Some(moc) = moc {
        if let Some(unit) = &moc.coordinated {
            return Err(format!(
                "{} moves on {unit} (a coordinated base), which is not modelled",
                moc.name
            ));
        }
        return match rapid_robot::lookup(&moc.robot_type) {
            Lookup::Found(model) => {
                let limits = JointLimits::of(model).with_moc_bounds(&moc.bounds);
                Ok(Some(Arc::new(TaskRobot {
                    robot: Robot::new(model).with_limits(limits).with_base(moc.base),
                    source: RobotSource::MocCfg,
                    origin: format!("MOC.cfg {} ({})", moc.name, moc.robot_type),
                })))
            }
            Lookup::Unsupported(why) => Err(why),
            Lookup::Unknown => Err(format!(
                "robot type {} is not one of the modelled arms",
                moc.robot_type
            )),
        };
    }
    let Some(setting) = setting else {
        return Ok(None);
    };
    match rapid_robot::lookup(&setting.name) {
        Lookup::Found(model) => {
            let limits = setting.limits.map_or(JointLimits::of(model), JointLimits);
            Ok(Some(Arc::new(TaskRobot {
                robot: Robot::new(model).with_limits(limits),
                source: RobotSource::Project,
                origin: "the project's [controller] robot".into(),
            })))
        }
        Lookup::Unsupported(why) => Err(why),
        Lookup::Unknown => Err(format!(
            "`{}` is not one of the modelled arms",
            setting.name
        )),
    }
}

/// For a hover on robtarget data of a task with a robot: the joint angles
/// of its declared value (a constant's, or a persistent's initial value).
pub(crate) fn joints_of_def(
    task: &crate::task::Task,
    def: &crate::sema::def::Def<'_>,
) -> Option<String> {
    use crate::sema::def::Def;
    let robot = task.robot.as_ref()?;
    let (unit, decl) = match def {
        Def::Item(r) => (r.unit, task.data(*r)?),
        Def::Local { unit, decl, .. } => (*unit, decl),
        _ => return None,
    };
    if !decl.ty.as_ref()?.name.eq_ignore_ascii_case("robtarget")
        || decl.storage == crate::items::Storage::Var
    {
        return None;
    }
    let init = decl.init.clone()?;
    let u = task.units.get(unit)?;
    let node = u
        .tree()
        .root_node()
        .named_descendant_for_byte_range(init.start, init.end)?;
    let module = u.items.module_at(init.start);
    let expr = crate::lower::lower_with(node, &u.text, &|f| {
        crate::consteval::is_builtin_call(task, module.map(|m| (unit, m)), f)
    });
    let options = crate::consteval::EnvOptions {
        pers_initial: true,
        var_initial: false,
    };
    let v = crate::consteval::eval_in(
        task,
        Some((unit, init.start)),
        &expr,
        Some(&rapid_evaluator::Type::named("robtarget")),
        options,
    )
    .ok()?;
    joints_markdown(robot, &v.value)
}

/// The joint angles of a robtarget value for the task's robot, with tool0
/// and wobj0, as a line of markdown (for a hover).
pub fn joints_markdown(robot: &TaskRobot, value: &rapid_evaluator::Value) -> Option<String> {
    let target = rapid_robot::frames::robtarget(value).ok()?;
    let r = &robot.robot;
    let flange = rapid_robot::frames::flange_in_base(
        &target.pose,
        &Default::default(),
        &Default::default(),
        &r.base,
    );
    let name = &r.model.name;
    Some(match r.reach(&flange, Some(&target.conf)) {
        Ok(s) => {
            let j: Vec<String> = s.joints.iter().map(|a| format!("{a:.2}")).collect();
            format!("{name} (tool0, wobj0): axes [{}]°", j.join(", "))
        }
        Err(e) => format!("{name} (tool0, wobj0): {e}"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(key: &str) -> RobotOf<'_> {
        RobotOf {
            key,
            ..RobotOf::default()
        }
    }

    const MOC: &str = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_serv_type \"ROB_1\" -use_joint_0 \"rob1_1\"\\\n      -use_robot_type \"ROB1_120_0.58_3\" -base_frame_pos_x 0.5\\\n      -base_frame_orient_u0 0.707107 -base_frame_orient_u3 0.707107\n#\nARM:\n\n      -name \"rob1_1\" -use_arm_type \"ROB1_1\" -upper_joint_bound 1.5\\\n      -lower_joint_bound -1.5\n\n      -name \"rob1_3\" -use_arm_type \"ROB1_3\" -upper_joint_bound 1\n";

    #[test]
    fn moc_cfg_names_the_robot_its_base_and_bounds() {
        let robots = parse_moc_robots(MOC);
        assert_eq!(robots.len(), 1);
        let r = &robots[0];
        assert_eq!(
            (r.name.as_str(), r.robot_type.as_str()),
            ("ROB_1", "ROB1_120_0.58_3")
        );
        assert_eq!(r.bounds[0], (Some(-1.5), Some(1.5)));
        assert_eq!(r.bounds[2], (None, Some(1.0)));
        assert!((r.base.translation.vector.x - 500.0).abs() < 1e-9);
        let t = resolve(at("b/RAPID/TASK1"), &[r], None)
            .expect("a value in a test")
            .expect("a value in a test");
        assert_eq!(t.robot.model.name, "IRB 120-3/0.58");
        assert!((t.robot.limits.0[0][1] - 1.5f64.to_degrees()).abs() < 1e-9);
        assert!((t.robot.limits.0[2][1] - 1f64.to_degrees()).abs() < 1e-9);
        assert_eq!(t.robot.limits.0[2][0], -110.0);
        // The project's setting counts only without a MOC.cfg robot.
        let setting = RobotSetting {
            name: "IRB 2600-12/1.65".into(),
            limits: None,
        };
        let t = resolve(at("b/RAPID/TASK1"), &[r], Some(&setting))
            .expect("a value in a test")
            .expect("a value in a test");
        assert_eq!(t.robot.model.name, "IRB 120-3/0.58");
        let t = resolve(at("prog"), &[], Some(&setting))
            .expect("a value in a test")
            .expect("a value in a test");
        assert_eq!(t.robot.model.name, "IRB 2600-12/1.65");
        assert!(
            resolve(at("prog"), &[], None)
                .expect("a value in a test")
                .is_none()
        );
        let yumi = RobotSetting {
            name: "IRB 14000".into(),
            limits: None,
        };
        assert!(resolve(at("prog"), &[], Some(&yumi)).is_err());
    }

    #[test]
    fn hover_on_a_robtarget_shows_its_joint_angles() {
        let mut ws = crate::workspace::Workspace::new();
        ws.set_config(
            "cell/MOC.cfg",
            &MOC.replace(
                "-base_frame_orient_u0 0.707107 -base_frame_orient_u3 0.707107",
                "",
            ),
        );
        let text = "MODULE M\n  CONST robtarget pHome := [[874,0,630],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  CONST robtarget pFar := [[1900,0,630],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\nENDMODULE\n";
        ws.set_file("cell/M.mod", text.to_owned());
        let task = ws.task_of("cell/M.mod");
        assert!(task.robot.is_some(), "{:?}", task.robot_note);
        let unit = task
            .units
            .iter()
            .position(|u| u.path == "cell/M.mod")
            .expect("a value in a test");
        // The base is 500 mm along x: [874,0,630] is the home position.
        let at = text.find("pHome").expect("a value in a test");
        let h = crate::ide::hover(&task, unit, at).expect("a value in a test");
        assert!(
            h.markdown.contains(
                "IRB 120-3/0.58 (tool0, wobj0): axes [0.00, 0.00, 0.00, 0.00, 0.00, 0.00]"
            ),
            "{}",
            h.markdown
        );
        let at = text.find("pFar").expect("a value in a test");
        let h = crate::ide::hover(&task, unit, at).expect("a value in a test");
        assert!(
            h.markdown.contains("mm out of the arm's reach"),
            "{}",
            h.markdown
        );
    }
}
