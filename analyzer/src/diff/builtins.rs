//! The built-ins a program uses whose signature or availability differs
//! between the RobotWare versions of two backups, from the catalogue's
//! views of each version (with each side's options).

use std::collections::BTreeSet;

use serde::Serialize;

use super::Snapshot;
use crate::catalogue::{Availability, Catalogue, Selection, view};

/// The built-ins that differ between two RobotWare versions.
#[derive(Clone, Debug, Serialize)]
pub struct BuiltinChanges {
    pub old_robotware: String,
    pub new_robotware: String,
    pub changed: Vec<BuiltinChange>,
}

/// One built-in the program uses, as each version has it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct BuiltinChange {
    pub name: String,
    /// `function`, `instruction`, `type` or `datum`.
    pub kind: &'static str,
    /// Its signature in the old version, or why the version lacks it.
    pub old: String,
    pub new: String,
}

/// The built-ins used on either side (a name the program does not declare
/// itself) that differ between the two sides' RobotWare versions; `None`
/// unless both versions are known and differ.
pub fn changed_builtins(old: &Snapshot, new: &Snapshot) -> Option<BuiltinChanges> {
    let (Some(vo), Some(vn)) = (old.robotware, new.robotware) else {
        return None;
    };
    if vo == vn {
        return None;
    }
    let co = view(&Selection::new(Some(vo), old.options.iter().cloned()));
    let cn = view(&Selection::new(Some(vn), new.options.iter().cloned()));
    let mut used = BTreeSet::new();
    for side in [old, new] {
        for t in &side.tasks {
            let declared: BTreeSet<&String> = t.modules.iter().flat_map(|m| &m.declared).collect();
            for m in &t.modules {
                used.extend(m.names.iter().filter(|n| !declared.contains(n)).cloned());
            }
        }
    }
    let changed = used
        .iter()
        .filter_map(|name| {
            let (kind, a) = describe(co, name)?;
            let (_, b) = describe(cn, name)?;
            (a != b).then(|| BuiltinChange {
                name: display_name(cn, name),
                kind,
                old: a,
                new: b,
            })
        })
        .collect();
    Some(BuiltinChanges {
        old_robotware: vo.to_string(),
        new_robotware: vn.to_string(),
        changed,
    })
}

/// The catalogue's spelling of a name.
fn display_name(cat: &Catalogue, name: &str) -> String {
    cat.routine(name)
        .map(|r| r.name.clone())
        .or_else(|| cat.datatype(name).map(|t| t.name.clone()))
        .or_else(|| cat.datum(name).map(|d| d.name.clone()))
        .unwrap_or_else(|| name.to_owned())
}

/// A built-in's kind and what one view says of it: its signature, or why
/// the controller lacks it.
fn describe(cat: &Catalogue, name: &str) -> Option<(&'static str, String)> {
    let (kind, signature, origin) = if let Some(r) = cat.routine(name) {
        let kind = if r.is_function() {
            "function"
        } else {
            "instruction"
        };
        (kind, r.signature(), &r.origin)
    } else if let Some(t) = cat.datatype(name) {
        ("type", t.signature(), &t.origin)
    } else if let Some(d) = cat.datum(name) {
        (
            "datum",
            format!("{} {} {}", d.kind.keyword(), d.ty, d.name),
            &d.origin,
        )
    } else {
        return None;
    };
    let text = match cat.availability(origin) {
        Availability::Yes | Availability::NeedsOption(_) => signature,
        Availability::Newer { since, .. } => format!("not yet there (added in RobotWare {since})"),
        Availability::Removed { until, .. } => format!("removed (in RobotWare {until})"),
    };
    Some((kind, text))
}
