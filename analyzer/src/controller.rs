//! What a controller backup says about its controller: the RobotWare
//! version, the installed options and the system's name, from
//! `BACKINFO/backinfo.txt` (`>>SYSTEM_ID:` names the system) and
//! `BACKINFO/system.xml`, and the catalogue view that follows.
//!
//! `backinfo.txt` is sections of lines, each headed `>>NAME:`; the line after
//! `>>PRODUCTS_ID:` names the RobotWare (`RobotWare Version: 6.08.01.00` or
//! `RobotWare_6.13.0135`), and the product and option sections name the
//! installed options. `system.xml` lists options as elements and
//! attributes. Both are read tolerantly: a line or value that names a known
//! option package (by its option number or name, see
//! [`crate::catalogue::Package::matches`]) enables it.

use crate::catalogue::{Catalogue, Selection, Version};

/// A controller's RobotWare version and installed options, as far as known.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ControllerInfo {
    pub robotware: Option<Version>,
    /// Package ids ([`crate::catalogue::Package::id`]) of the installed
    /// options the catalogue knows.
    pub options: Vec<String>,
    /// The system's name (`backinfo.txt`'s `>>SYSTEM_ID:`).
    pub system_name: Option<String>,
    /// The RobotWare version as the backup writes it (`6.08.01.00`).
    pub robotware_text: Option<String>,
    /// The tasks `backinfo.txt` names (`>>TASK1: (T_ROB1,,)`): each task
    /// folder's number (`RAPID/TASKn`) and its task's name.
    pub tasks: Vec<(usize, String)>,
}

impl ControllerInfo {
    /// Adds what `other` knows and this does not.
    pub fn merge(&mut self, other: &ControllerInfo) {
        if self.robotware.is_none() {
            self.robotware = other.robotware;
        }
        if self.system_name.is_none() {
            self.system_name.clone_from(&other.system_name);
        }
        if self.robotware_text.is_none() {
            self.robotware_text.clone_from(&other.robotware_text);
        }
        for o in &other.options {
            if !self.options.contains(o) {
                self.options.push(o.clone());
            }
        }
        if self.tasks.is_empty() {
            self.tasks.clone_from(&other.tasks);
        }
    }

    /// The catalogue selection, with `overrides` (from `rapid.toml` or the
    /// editor) taking precedence key by key.
    pub fn selection(&self, overrides: &ControllerOverride) -> Selection {
        let robotware = overrides.robotware.or(self.robotware);
        let options = match &overrides.options {
            Some(o) => crate::catalogue::base().with_included(o),
            None => self.options.clone(),
        };
        Selection::new(robotware, options)
    }
}

/// The controller as the project configuration describes it; each key set
/// there replaces what a backup says.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub struct ControllerOverride {
    pub robotware: Option<Version>,
    /// Option package ids; `None` keeps the backup's.
    pub options: Option<Vec<String>>,
    /// The robot, for tasks whose `MOC.cfg` does not name one.
    pub robot: Option<crate::robot::RobotSetting>,
    /// The task names by task number (`RAPID/TASKn` is the *n*-th), for
    /// backups whose `SYS.cfg` and `BACKINFO` are missing.
    pub tasks: Option<Vec<String>>,
}

/// Is this a file that describes a controller (`backinfo.txt`, or
/// `system.xml` in a `BACKINFO` folder), in any letter case?
pub fn is_controller_info_name(path: &str) -> bool {
    let mut parts = path.rsplit(['/', '\\']);
    let base = parts.next().unwrap_or(path);
    let dir = parts.next().unwrap_or("");
    base.eq_ignore_ascii_case("backinfo.txt")
        || (base.eq_ignore_ascii_case("system.xml") && dir.eq_ignore_ascii_case("backinfo"))
}

/// Reads `backinfo.txt` or `system.xml` (by the file name in `path`).
pub fn parse_controller_info(path: &str, text: &str, cat: &Catalogue) -> ControllerInfo {
    let base = path.rsplit(['/', '\\']).next().unwrap_or(path);
    if base.to_ascii_lowercase().ends_with(".xml") {
        parse_system_xml(text, cat)
    } else {
        parse_backinfo(text, cat)
    }
}

/// Reads `BACKINFO/backinfo.txt`.
pub fn parse_backinfo(text: &str, cat: &Catalogue) -> ControllerInfo {
    let mut info = ControllerInfo::default();
    let mut section = String::new();
    for line in text.lines() {
        let line = line.trim();
        if let Some(head) = line.strip_prefix(">>") {
            section = head.trim_end_matches(':').trim().to_ascii_uppercase();
            if let Some(task) = task_in(head) {
                info.tasks.push(task);
            }
            continue;
        }
        if line.is_empty() {
            continue;
        }
        let products = section.contains("PRODUCT") || section.contains("OPTION");
        if section == "SYSTEM_ID" && info.system_name.is_none() {
            info.system_name = Some(line.to_owned());
        }
        if info.robotware.is_none() {
            info.robotware = robotware_in(line);
            if info.robotware.is_some() {
                info.robotware_text = robotware_token(line);
            }
        }
        // System names, ids and task lists can hold any word: only the
        // product and option sections name options.
        if products {
            add_options(&mut info, line, cat);
        }
    }
    info
}

/// The task a `>>TASKn: (NAME,...)` header names: `n` and `NAME`.
fn task_in(head: &str) -> Option<(usize, String)> {
    let (key, rest) = head.split_once(':')?;
    let key = key.trim().to_ascii_uppercase();
    let number = key.strip_prefix("TASK")?.parse::<usize>().ok()?;
    let inner = rest.trim().strip_prefix('(')?;
    let name = inner.split([',', ')']).next()?.trim();
    (!name.is_empty() && number > 0).then(|| (number, name.to_owned()))
}

/// Reads `BACKINFO/system.xml`: every attribute value and text between tags
/// is a candidate option or version.
pub fn parse_system_xml(text: &str, cat: &Catalogue) -> ControllerInfo {
    let mut info = ControllerInfo::default();
    // `Name="RobotWare" Version="6.13.0135"`: the version may be the next value.
    let mut after_robotware = false;
    for value in xml_values(text) {
        if info.robotware.is_none() {
            if after_robotware {
                info.robotware = Version::parse(&value).ok();
            }
            if info.robotware.is_none() {
                info.robotware = robotware_in(&value);
            }
            after_robotware = value.to_ascii_lowercase().contains("robotware");
        }
        add_options(&mut info, &value, cat);
    }
    info
}

fn add_options(info: &mut ControllerInfo, text: &str, cat: &Catalogue) {
    for id in cat.packages_named_in(text) {
        if !info.options.iter().any(|o| o == id) {
            info.options.push(id.to_owned());
        }
    }
}

/// The first RobotWare version in a line: `RobotWare Version: 6.08.01.00`,
/// `RobotWare_6.13.0135`, `RW 7.10`.
fn robotware_in(line: &str) -> Option<Version> {
    Version::parse(&robotware_token(line)?).ok()
}

/// The version of [`robotware_in`] as written (`6.08.01.00`).
fn robotware_token(line: &str) -> Option<String> {
    let lower = line.to_ascii_lowercase();
    let start = match lower.find("robotware") {
        Some(i) => i + "robotware".len(),
        None if lower.starts_with("rw") => 2,
        None => return None,
    };
    let rest = &line[start..];
    let digits = rest.find(|c: char| c.is_ascii_digit())?;
    let token: String = rest[digits..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect();
    Some(token.trim_end_matches('.').to_owned())
}

/// Attribute values and element texts of an XML document, without a parser
/// (the file is small and only words are wanted).
fn xml_values(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find(['"', '>']) {
        let quote = rest.as_bytes()[i] == b'"';
        rest = &rest[i + 1..];
        let end = if quote {
            rest.find('"')
        } else {
            rest.find('<')
        };
        let Some(end) = end else { break };
        let value = rest[..end].trim();
        if !value.is_empty() {
            out.push(value.to_owned());
        }
        if quote {
            rest = &rest[end + 1..];
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backinfo_names_the_version_and_the_options() {
        let text = ">>SYSTEM_ID:\n6700-123456\n\n>>PRODUCTS_ID:\nRobotWare Version: 6.08.01.00\nArc 6.08.0000\n\n>>OPTIONS:\n689-1 Externally Guided Motion (EGM)\n608-1 World Zones\n\n>>TASK1: (T_ROB1,,)\nSYSMOD/user.sys\n";
        let info = parse_backinfo(text, crate::catalogue::base());
        assert_eq!(info.robotware, Some(Version::new(6, 8)));
        assert_eq!(info.robotware_text.as_deref(), Some("6.08.01.00"));
        assert_eq!(info.system_name.as_deref(), Some("6700-123456"));
        assert_eq!(info.options, vec!["arc", "egm", "worldzones"]);
        assert_eq!(info.tasks, vec![(1, "T_ROB1".to_owned())]);
        let two = parse_backinfo(
            ">>TASK2: (T_ROB2,Main,)\n>>task1: ( T_ROB1 ,,)\n>>TASK: (x)\n",
            crate::catalogue::base(),
        );
        assert_eq!(
            two.tasks,
            vec![(2, "T_ROB2".to_owned()), (1, "T_ROB1".to_owned())]
        );
        let none = parse_backinfo(">>SYSTEM_ID:\nArc cell 7\n", crate::catalogue::base());
        assert_eq!(
            none,
            ControllerInfo {
                system_name: Some("Arc cell 7".to_owned()),
                ..ControllerInfo::default()
            }
        );
        // RobotWare 6's PC Interface brings Socket Messaging.
        let pc = parse_backinfo(">>OPTIONS:\n616-1 PC Interface\n", crate::catalogue::base());
        assert_eq!(pc.options, vec!["pcinterface", "socket"]);
        let sel = pc.selection(&ControllerOverride {
            robotware: None,
            options: Some(vec!["pcinterface".into()]),
            ..ControllerOverride::default()
        });
        assert!(sel.enabled("socket"));
    }

    #[test]
    fn system_xml_names_the_options() {
        let text = r#"<?xml version="1.0"?><System><Product Name="RobotWare" Version="6.13.0135"/><Option>672-1 Socket Messaging</Option><Option Name="623-1 Multitasking"/></System>"#;
        let info = parse_system_xml(text, crate::catalogue::base());
        assert_eq!(info.robotware, Some(Version::new(6, 13)));
        assert_eq!(info.options, vec!["socket", "multitasking"]);
    }

    #[test]
    fn overrides_win_key_by_key() {
        let info = ControllerInfo {
            robotware: Some(Version::new(6, 8)),
            options: vec!["arc".into()],
            ..ControllerInfo::default()
        };
        let sel = info.selection(&ControllerOverride {
            robotware: Some(Version::new(7, 1)),
            ..ControllerOverride::default()
        });
        assert_eq!(sel.robotware, Some(Version::new(7, 1)));
        assert!(sel.enabled("arc"));
        assert!(is_controller_info_name("b/BACKINFO/backinfo.txt"));
        assert!(is_controller_info_name("b/BACKINFO/system.xml"));
        assert!(!is_controller_info_name("b/system.xml"));
    }
}
