//! The controller's system: its configuration (the backup's `SYSPAR/*.cfg`
//! files, read by the analyzer's one reader, [`rapid_analyzer::cfg`]) and
//! what it says of itself (`GetSysInfo`). `ReadCfgData` reads the
//! configuration and `WriteCfgData` changes it, in the run's memory only.
//!
//! An instance path is `/DOMAIN/TYPE/NAME` (the instance whose `Name`
//! attribute is `NAME`; `MOC.cfg` writes it `-name`), or
//! `/DOMAIN/TYPE/ATTRIBUTE/VALUE` with `\ListNo` (the instances whose
//! `ATTRIBUTE` is `VALUE`, counted from 0). The leading `/` may be left
//! out, as the controller accepts. Names and values compare without regard
//! to letter case.

use rapid_analyzer::cfg::{Attr, CfgFile, Instance};

/// The controller's system.
#[derive(Clone, Debug, Default)]
pub struct System {
    /// The configuration files, each with its domain (`EIO`, `MOC`, `SYS`,
    /// `PROC`...: its header's first word, else the file name's stem).
    pub domains: Vec<(String, CfgFile)>,
    pub info: SysInfo,
}

/// What the backup (or the project) says of the controller, for
/// `GetSysInfo`; `None`: not known (see [`System::sys_info`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SysInfo {
    pub serial_no: Option<String>,
    pub sw_version: Option<String>,
    pub sw_version_name: Option<String>,
    pub robot_type: Option<String>,
    pub ctrl_id: Option<String>,
    pub lan_ip: Option<String>,
    pub ctrl_lang: Option<String>,
    pub system_name: Option<String>,
}

/// `GetSysInfo`'s answers where the backup does not say: the switch, the
/// answer, and where it comes from.
pub const SYS_INFO_DEFAULTS: &[(&str, &str, &str)] = &[
    (
        "LanIp",
        "VC",
        "RAPID reference, GetSysInfo: a virtual controller answers VC; public RAPID servers test for it",
    ),
    (
        "CtrlLang",
        "en",
        "RAPID reference, GetSysInfo: the language as its two-letter code; English is the controller's language as delivered",
    ),
];

/// Why `ReadCfgData` or `WriteCfgData` fails: the error it raises
/// (`ERR_CFG_NOTFND`, `ERR_CFG_ILLTYPE`, `ERR_CFG_OUTOFBOUNDS`) and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CfgError {
    pub error: &'static str,
    pub message: String,
}

fn not_found<T>(message: String) -> Result<T, CfgError> {
    Err(CfgError {
        error: "ERR_CFG_NOTFND",
        message,
    })
}

/// A parameter's value as the configuration holds it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CfgValue {
    /// A value as written (a number, a word, a quoted text).
    Text(String),
    /// A flag: there (`-AllTask`) or not.
    Flag(bool),
}

/// Where an instance is kept: the file, the type in it, the instance.
type At = (usize, usize, usize);

/// An instance path taken apart.
struct Path<'a> {
    domain: &'a str,
    ty: &'a str,
    /// The instance's name, or the attribute and value a search matches.
    select: Select<'a>,
}

enum Select<'a> {
    Name(&'a str),
    Search(&'a str, &'a str),
}

fn parse_path(path: &str) -> Result<Path<'_>, CfgError> {
    let parts: Vec<&str> = path.trim().trim_start_matches('/').split('/').collect();
    match parts.as_slice() {
        [domain, ty, name] if !name.is_empty() => Ok(Path {
            domain,
            ty,
            select: Select::Name(name),
        }),
        [domain, ty, attr, value] if !attr.is_empty() => Ok(Path {
            domain,
            ty,
            select: Select::Search(attr, value),
        }),
        _ => not_found(format!(
            "{path:?} is not an instance path (/DOMAIN/TYPE/NAME or /DOMAIN/TYPE/ATTRIBUTE/VALUE)"
        )),
    }
}

impl System {
    /// The domain of a configuration file: its header's first word
    /// (`MOC:CFG_1.0:6:1::`), else the file name's stem (`MOC.cfg`).
    pub fn domain_of(file_name: &str, cfg: &CfgFile) -> String {
        if let Some(h) = &cfg.header
            && let Some((d, _)) = h.split_once(':')
            && !d.trim().is_empty()
        {
            return d.trim().to_ascii_uppercase();
        }
        let base = file_name.rsplit(['/', '\\']).next().unwrap_or(file_name);
        base.split('.').next().unwrap_or(base).to_ascii_uppercase()
    }

    /// The instances `path` selects, in order, each with the file and
    /// index it is kept at.
    fn select(&self, path: &str) -> Result<Vec<At>, CfgError> {
        let p = parse_path(path)?;
        let mut found = Vec::new();
        let mut domain_seen = false;
        let mut type_seen = false;
        for (f, (domain, file)) in self.domains.iter().enumerate() {
            if !domain.eq_ignore_ascii_case(p.domain) {
                continue;
            }
            domain_seen = true;
            for (t, ty) in file.types.iter().enumerate() {
                if !ty.name.eq_ignore_ascii_case(p.ty) {
                    continue;
                }
                type_seen = true;
                for (i, inst) in ty.instances.iter().enumerate() {
                    let hit = match p.select {
                        Select::Name(n) => {
                            inst.get("Name").is_some_and(|v| v.eq_ignore_ascii_case(n))
                        }
                        Select::Search(a, v) => matches_value(inst, a, v),
                    };
                    if hit {
                        found.push((f, t, i));
                    }
                }
            }
        }
        if !domain_seen {
            return not_found(format!(
                "{path:?}: the configuration has no {} domain (no {}.cfg in the backup)",
                p.domain.to_ascii_uppercase(),
                p.domain.to_ascii_uppercase()
            ));
        }
        if !type_seen {
            return not_found(format!(
                "{path:?}: the {} domain has no type {}",
                p.domain, p.ty
            ));
        }
        Ok(found)
    }

    fn instance(&self, at: At) -> Option<&Instance> {
        self.domains
            .get(at.0)?
            .1
            .types
            .get(at.1)?
            .instances
            .get(at.2)
    }

    /// `ReadCfgData InstancePath, Attribute, ... [\ListNo]`: the value of
    /// `attribute` of the instance `path` selects (with `list_no`, the
    /// `list_no`th of a search, counted from 0) and the next `\ListNo`
    /// (-1, `END_OF_LIST`, after the last match).
    pub fn read(
        &self,
        path: &str,
        attribute: &str,
        list_no: Option<i64>,
    ) -> Result<(CfgValue, Option<i64>), CfgError> {
        let found = self.select(path)?;
        let (at, next) = pick(&found, path, list_no)?;
        let Some(inst) = self.instance(at) else {
            return not_found(format!("{path:?}: no such instance"));
        };
        let value = match inst.attr(attribute) {
            Some(Attr { value: Some(v), .. }) => CfgValue::Text(v.clone()),
            Some(Attr { value: None, .. }) => CfgValue::Flag(true),
            None if is_flag_of_type(self, at, attribute) => CfgValue::Flag(false),
            None => {
                return not_found(format!(
                    "{path:?} sets no {attribute} in the backup's configuration (the controller's default is not known to the simulation)"
                ));
            }
        };
        Ok((value, next))
    }

    /// `WriteCfgData InstancePath, Attribute, CfgData [\ListNo]`: sets
    /// `attribute` of the instance `path` selects to `value` (a flag is
    /// set or removed), in memory.
    pub fn write(
        &mut self,
        path: &str,
        attribute: &str,
        value: CfgValue,
        list_no: Option<i64>,
    ) -> Result<(), CfgError> {
        let found = self.select(path)?;
        let ((f, t, i), _) = pick(&found, path, list_no)?;
        let Some(inst) = self
            .domains
            .get_mut(f)
            .and_then(|d| d.1.types.get_mut(t))
            .and_then(|ty| ty.instances.get_mut(i))
        else {
            return not_found(format!("{path:?}: no such instance"));
        };
        let pos = inst
            .attrs
            .iter()
            .position(|a| a.name.eq_ignore_ascii_case(attribute));
        match (value, pos) {
            (CfgValue::Flag(false), Some(p)) => {
                inst.attrs.remove(p);
            }
            (CfgValue::Flag(false), None) => {}
            (CfgValue::Flag(true), Some(p)) => inst.attrs[p].value = None,
            (CfgValue::Text(v), Some(p)) => inst.attrs[p].value = Some(v),
            (v, None) => inst.attrs.push(Attr {
                name: attribute.to_owned(),
                value: match v {
                    CfgValue::Text(t) => Some(t),
                    CfgValue::Flag(_) => None,
                },
            }),
        }
        Ok(())
    }

    /// The answer of `GetSysInfo` with `switch` (`SerialNo`, `SWVersion`,
    /// `SWVersionName`, `RobotType`, `CtrlId`, `LanIp`, `CtrlLang`,
    /// `SystemName`): what the backup says, else the serial number and
    /// robot type of `MOC.cfg`'s first robot, else [`SYS_INFO_DEFAULTS`],
    /// else an empty string (the controller would know; the backup does
    /// not say).
    pub fn sys_info(&self, switch: &str) -> String {
        let i = &self.info;
        let given = match switch.to_ascii_lowercase().as_str() {
            "serialno" => i.serial_no.clone().or_else(|| self.robot_serial()),
            "swversion" => i.sw_version.clone(),
            "swversionname" => i.sw_version_name.clone(),
            "robottype" => i.robot_type.clone().or_else(|| self.robot_type()),
            "ctrlid" => i.ctrl_id.clone(),
            "lanip" => i.lan_ip.clone(),
            "ctrllang" => i.ctrl_lang.clone(),
            "systemname" => i.system_name.clone(),
            _ => None,
        };
        given
            .or_else(|| {
                SYS_INFO_DEFAULTS
                    .iter()
                    .find(|(s, _, _)| s.eq_ignore_ascii_case(switch))
                    .map(|(_, v, _)| (*v).to_owned())
            })
            .unwrap_or_default()
    }

    fn moc_instances<'a>(&'a self, ty: &'a str) -> impl Iterator<Item = &'a Instance> + 'a {
        self.domains
            .iter()
            .filter(|(d, _)| d == "MOC")
            .flat_map(move |(_, f)| f.instances(ty))
    }

    /// `MOC.cfg`'s `ROBOT_SERIAL_NUMBER`: `HIGH-LOW` (`6700-132308`).
    fn robot_serial(&self) -> Option<String> {
        self.moc_instances("ROBOT_SERIAL_NUMBER").find_map(|r| {
            let high = r.get("robot_serial_number_high_part")?;
            let low = r.get("robot_serial_number_low_part")?;
            Some(format!("{high}-{low}"))
        })
    }

    /// `MOC.cfg`'s mechanical units (`MECHANICAL_UNIT`), in its order:
    /// each unit's name, whether it is a robot with a TCP (`-use_robot`)
    /// and its number of axes (the robot's `-use_joint_N`, six when they
    /// are not written; one for each of its singles).
    pub fn mechanical_units(&self) -> Vec<MechUnit> {
        self.moc_instances("MECHANICAL_UNIT")
            .filter_map(|u| {
                let name = u.get("name")?.to_owned();
                let robot = u.get("use_robot").filter(|r| !r.is_empty());
                let axes = match robot {
                    Some(r) => self
                        .moc_instances("ROBOT")
                        .find(|i| i.get("name").is_some_and(|n| n.eq_ignore_ascii_case(r)))
                        .map(|i| count_prefixed(i, "use_joint_"))
                        .filter(|&n| n > 0)
                        .unwrap_or(6),
                    None => count_prefixed(u, "use_single_"),
                };
                Some(MechUnit {
                    name,
                    tcp_robot: robot.is_some(),
                    axes,
                })
            })
            .collect()
    }

    /// `MOC.cfg`'s first robot's type (`-use_robot_type`).
    fn robot_type(&self) -> Option<String> {
        self.moc_instances("ROBOT")
            .find_map(|r| r.get("use_robot_type").map(str::to_owned))
    }
}

/// A mechanical unit of the controller (`GetNextMechUnit`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MechUnit {
    pub name: String,
    /// A robot with a TCP.
    pub tcp_robot: bool,
    pub axes: usize,
}

/// How many of an instance's attributes with a value start with `prefix`.
fn count_prefixed(inst: &Instance, prefix: &str) -> usize {
    inst.attrs
        .iter()
        .filter(|a| {
            a.name.len() > prefix.len()
                && a.name[..prefix.len()].eq_ignore_ascii_case(prefix)
                && a.value.as_deref().is_some_and(|v| !v.is_empty())
        })
        .count()
}

fn matches_value(inst: &Instance, attr: &str, value: &str) -> bool {
    match inst.attr(attr) {
        Some(Attr { value: Some(v), .. }) => v.eq_ignore_ascii_case(value),
        Some(Attr { value: None, .. }) => value.eq_ignore_ascii_case("TRUE"),
        None => false,
    }
}

/// Is `attribute` a flag in some instance of the type at `at` (so that an
/// instance without it has it off)?
fn is_flag_of_type(s: &System, at: At, attribute: &str) -> bool {
    s.domains
        .get(at.0)
        .and_then(|d| d.1.types.get(at.1))
        .is_some_and(|t| {
            t.instances
                .iter()
                .any(|i| i.attr(attribute).is_some_and(|a| a.value.is_none()))
        })
}

/// The instance `list_no` picks of `found`, and the next `\ListNo`.
fn pick(found: &[At], path: &str, list_no: Option<i64>) -> Result<(At, Option<i64>), CfgError> {
    let n = list_no.unwrap_or(0);
    if n < 0 || (list_no.is_some() && n as usize >= found.len() && !found.is_empty()) {
        return Err(CfgError {
            error: "ERR_CFG_OUTOFBOUNDS",
            message: format!(
                "{path:?}: \\ListNo {n} is beyond the {} instances found",
                found.len()
            ),
        });
    }
    match found.get(n as usize) {
        Some(&at) => {
            let next = list_no.map(|_| {
                if (n as usize) + 1 < found.len() {
                    n + 1
                } else {
                    -1
                }
            });
            Ok((at, next))
        }
        None => not_found(format!("{path:?}: no such instance in the configuration")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn system() -> System {
        let moc = rapid_analyzer::cfg::parse(
            "MOC:CFG_1.0:6:0::\n#\nSINGLE:\n\n      -name \"TRACK\" -use_single_type \"T1\" -base_frame_pos_x 1.5\n#\nROBOT_SERIAL_NUMBER:\n\n      -name \"rob1\" -robot_serial_number_high_part \"120\" -robot_serial_number_low_part 501234\n",
        );
        let eio = rapid_analyzer::cfg::parse(
            "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"do1\" -SignalType \"DO\"\n\n      -Name \"di1\" -SignalType \"DI\" -Access \"All\"\n\n      -Name \"do2\" -SignalType \"DO\" -Invert\n",
        );
        System {
            domains: vec![
                (System::domain_of("MOC.cfg", &moc), moc),
                (System::domain_of("x/EIO.cfg", &eio), eio),
            ],
            info: SysInfo::default(),
        }
    }

    #[test]
    fn instances_are_read_by_name_or_searched_with_list_numbers() {
        let mut s = system();
        let text = |v: &str| CfgValue::Text(v.to_owned());
        assert_eq!(
            s.read("/MOC/SINGLE/track", "base_frame_pos_x", None),
            Ok((text("1.5"), None))
        );
        assert_eq!(
            s.read("MOC/SINGLE/TRACK", "use_single_type", None),
            Ok((text("T1"), None))
        );
        assert_eq!(
            s.read("/EIO/EIO_SIGNAL/SignalType/DO", "Name", Some(0)),
            Ok((text("do1"), Some(1)))
        );
        assert_eq!(
            s.read("/EIO/EIO_SIGNAL/SignalType/DO", "Name", Some(1)),
            Ok((text("do2"), Some(-1)))
        );
        assert_eq!(
            s.read("/EIO/EIO_SIGNAL/SignalType/DO", "Name", Some(2))
                .map_err(|e| e.error),
            Err("ERR_CFG_OUTOFBOUNDS")
        );
        assert_eq!(
            s.read("/EIO/EIO_SIGNAL/do2", "Invert", None),
            Ok((CfgValue::Flag(true), None))
        );
        assert_eq!(
            s.read("/EIO/EIO_SIGNAL/do1", "Invert", None),
            Ok((CfgValue::Flag(false), None))
        );
        for (path, attr) in [
            ("/MOC/SINGLE/NONE", "base_frame_pos_x"),
            ("/MOC/SINGLE/TRACK", "base_frame_pos_y"),
            ("/MOC/NO_TYPE/TRACK", "x"),
            ("/PROC/ARC/x", "x"),
            ("MOC", "x"),
        ] {
            assert_eq!(
                s.read(path, attr, None).map_err(|e| e.error),
                Err("ERR_CFG_NOTFND"),
                "{path}"
            );
        }
        s.write("/MOC/SINGLE/TRACK", "base_frame_pos_y", text("0.25"), None)
            .expect("written");
        s.write("/MOC/SINGLE/TRACK", "base_frame_pos_x", text("2"), None)
            .expect("written");
        s.write("/EIO/EIO_SIGNAL/do2", "Invert", CfgValue::Flag(false), None)
            .expect("written");
        assert_eq!(
            s.read("/MOC/SINGLE/TRACK", "base_frame_pos_y", None),
            Ok((text("0.25"), None))
        );
        assert_eq!(
            s.read("/MOC/SINGLE/TRACK", "base_frame_pos_x", None),
            Ok((text("2"), None))
        );
        assert!(s.write("/MOC/SINGLE/NONE", "x", text("1"), None).is_err());
    }

    #[test]
    fn system_information_comes_from_the_backup_else_documented_defaults() {
        let mut s = system();
        assert_eq!(s.sys_info("SerialNo"), "120-501234");
        assert_eq!(s.sys_info("LanIp"), "VC");
        assert_eq!(s.sys_info("CtrlLang"), "en");
        assert_eq!(s.sys_info("SystemName"), "");
        s.info.system_name = Some("Cell 1".to_owned());
        s.info.lan_ip = Some("192.168.125.1".to_owned());
        assert_eq!(s.sys_info("systemname"), "Cell 1");
        assert_eq!(s.sys_info("LanIp"), "192.168.125.1");
    }
}
