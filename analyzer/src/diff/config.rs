//! Configuration files compared by type, instance and attribute, never as
//! text: files by name, types by name, instances by their `-Name` (any
//! letter case), else by their first attribute (`CAB_TASK_MODULES` by
//! `-File`), attributes by name (any case), values as numbers where both
//! read as numbers (`1` is `1.0`). Instances are labelled where a change
//! means something to an integrator: an I/O signal moved to another
//! device or address is `remapped`, a changed joint bound of `MOC.cfg` is
//! a `joint limit`, an entry of `SYS.cfg`'s `CAB_TASKS` is a `task`.

use std::collections::HashMap;

use serde::Serialize;

use super::Status;
use crate::cfg::{CfgFile, Instance};

/// A configuration file added, removed or changed.
#[derive(Clone, Debug, Serialize)]
pub struct ConfigDiff {
    pub file: String,
    pub status: Status,
    /// The instances that changed (every instance of an added or removed
    /// file).
    pub instances: Vec<InstanceDiff>,
}

/// An instance added, removed or changed.
#[derive(Clone, Debug, Serialize)]
pub struct InstanceDiff {
    /// Its type (`EIO_SIGNAL`).
    #[serde(rename = "type")]
    pub type_name: String,
    /// What identifies it: its `-Name`, else its first attribute.
    pub instance: String,
    pub status: Status,
    /// `remapped`, `joint limit`, `task`, when it is one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub label: Option<&'static str>,
    /// The attributes that differ (all of them, for an instance added or
    /// removed); a flag has no value.
    pub attributes: Vec<AttrChange>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old_line: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub new_line: Option<usize>,
}

/// An attribute on each side (`None`: not there; `Some("")`: a flag).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct AttrChange {
    pub name: String,
    pub old: Option<String>,
    pub new: Option<String>,
}

/// Signal attributes that say where a signal is wired.
const MAPPING: &[&str] = &[
    "Device",
    "DeviceMap",
    "Unit",
    "UnitMap",
    "Network",
    "Assembly",
];

/// Compares the configuration files of two sides, matched by name (any
/// letter case).
pub fn compare_configs(old: &[(String, CfgFile)], new: &[(String, CfgFile)]) -> Vec<ConfigDiff> {
    let mut out = Vec::new();
    let key = |s: &String| s.to_ascii_lowercase();
    let olds: HashMap<String, &CfgFile> = old.iter().map(|(n, f)| (key(n), f)).collect();
    let news: HashMap<String, &CfgFile> = new.iter().map(|(n, f)| (key(n), f)).collect();
    let empty = CfgFile::default();
    let mut names: Vec<&String> = old.iter().chain(new).map(|(n, _)| n).collect();
    names.sort_by_key(|n| key(n));
    names.dedup_by_key(|n| key(n));
    for name in names {
        let (a, b) = (olds.get(&key(name)), news.get(&key(name)));
        let status = match (a, b) {
            (None, _) => Status::Added,
            (_, None) => Status::Removed,
            _ => Status::Changed,
        };
        let instances = compare_files(a.copied().unwrap_or(&empty), b.copied().unwrap_or(&empty));
        if !instances.is_empty() || status != Status::Changed {
            out.push(ConfigDiff {
                file: name.clone(),
                status,
                instances,
            });
        }
    }
    out
}

/// Every instance of a file, keyed by (type, identity), in file order.
fn keyed(file: &CfgFile) -> Vec<((String, String), &str, &Instance)> {
    let mut seen: HashMap<(String, String), usize> = HashMap::new();
    let mut out = Vec::new();
    for t in &file.types {
        for i in &t.instances {
            let id = identity(i);
            let k = (t.name.to_ascii_uppercase(), id.to_ascii_lowercase());
            let n = seen.entry(k.clone()).or_default();
            *n += 1;
            let k = if *n > 1 {
                (k.0, format!("{} #{n}", k.1))
            } else {
                k
            };
            out.push((k, t.name.as_str(), i));
        }
    }
    out
}

/// What names an instance: its `-Name`, else its first attribute.
fn identity(i: &Instance) -> String {
    if let Some(name) = i.get("Name") {
        return name.to_owned();
    }
    match i.attrs.first() {
        Some(a) => match &a.value {
            Some(v) => format!("{} {v}", a.name),
            None => a.name.clone(),
        },
        None => String::new(),
    }
}

fn compare_files(old: &CfgFile, new: &CfgFile) -> Vec<InstanceDiff> {
    let olds = keyed(old);
    let news = keyed(new);
    let by_key: HashMap<&(String, String), (&str, &Instance)> =
        olds.iter().map(|(k, t, i)| (k, (*t, *i))).collect();
    let new_keys: HashMap<&(String, String), ()> = news.iter().map(|(k, _, _)| (k, ())).collect();
    let mut out = Vec::new();
    for (k, ty, n) in &news {
        match by_key.get(k) {
            Some((_, o)) => {
                let attributes = attr_changes(Some(o), Some(n));
                if !attributes.is_empty() {
                    out.push(InstanceDiff {
                        type_name: (*ty).to_owned(),
                        instance: identity(n),
                        status: Status::Changed,
                        label: label(ty, &attributes),
                        attributes,
                        old_line: Some(o.line),
                        new_line: Some(n.line),
                    });
                }
            }
            None => out.push(InstanceDiff {
                type_name: (*ty).to_owned(),
                instance: identity(n),
                status: Status::Added,
                label: label(ty, &[]),
                attributes: attr_changes(None, Some(n)),
                old_line: None,
                new_line: Some(n.line),
            }),
        }
    }
    for (k, ty, o) in &olds {
        if !new_keys.contains_key(k) {
            out.push(InstanceDiff {
                type_name: (*ty).to_owned(),
                instance: identity(o),
                status: Status::Removed,
                label: label(ty, &[]),
                attributes: attr_changes(Some(o), None),
                old_line: Some(o.line),
                new_line: None,
            });
        }
    }
    out
}

fn attr_changes(old: Option<&Instance>, new: Option<&Instance>) -> Vec<AttrChange> {
    let value = |i: Option<&Instance>, name: &str| {
        i.and_then(|i| i.attr(name))
            .map(|a| a.value.clone().unwrap_or_default())
    };
    let mut names: Vec<&str> = Vec::new();
    for i in [old, new].into_iter().flatten() {
        for a in &i.attrs {
            if !names.iter().any(|n| n.eq_ignore_ascii_case(&a.name)) {
                names.push(&a.name);
            }
        }
    }
    names
        .into_iter()
        .filter_map(|name| {
            let (a, b) = (value(old, name), value(new, name));
            let same = match (&a, &b) {
                (Some(x), Some(y)) => same_value(x, y),
                (None, None) => true,
                _ => false,
            };
            (!same).then(|| AttrChange {
                name: name.to_owned(),
                old: a,
                new: b,
            })
        })
        .collect()
}

fn same_value(a: &str, b: &str) -> bool {
    match (a.trim().parse::<f64>(), b.trim().parse::<f64>()) {
        (Ok(x), Ok(y)) => x == y,
        _ => a == b,
    }
}

fn label(ty: &str, changed: &[AttrChange]) -> Option<&'static str> {
    let ty = ty.to_ascii_uppercase();
    let any = |names: &[&str]| {
        changed
            .iter()
            .any(|c| names.iter().any(|n| c.name.eq_ignore_ascii_case(n)))
    };
    if ty.contains("SIGNAL") {
        return any(MAPPING).then_some("remapped");
    }
    if ty == "ARM" && any(&["upper_joint_bound", "lower_joint_bound"]) {
        return Some("joint limit");
    }
    (ty == "CAB_TASKS").then_some("task")
}
