//! A module file reduced to what [`super::compare`] compares.

use std::collections::{BTreeSet, HashMap};

use tree_sitter::Node;

use super::lines::Liner;
use super::{DataSnapshot, ModuleSnapshot, RoutineSnapshot, TypeSnapshot};
use crate::names::fold;
use crate::syntax::{field, kind};
use crate::syntax_util::{field, fields, kind as kind_of};
use crate::task::{Task, Unit};
use crate::text::LineIndex;

/// What to reduce a file to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Depth {
    /// Everything: statement lines, initialisers, names used.
    Full,
    /// The file's text is the same on the other side: its routines and
    /// initialisers need no comparing (only its data's values, which may
    /// come from other files), and the names it uses are not collected.
    SameText,
}

/// A digest of a file's text, to tell the files whose text is the same on
/// both sides ([`Depth::SameText`]).
pub fn text_digest(text: &str) -> u64 {
    crate::items::hash_of(&text)
}

/// The modules of unit `unit` of `task` (the task its names resolve in:
/// its group, or its view when it clashes with others), their file named
/// `file`. Data values come from the constant evaluator.
pub fn modules_of(task: &Task, unit: usize, file: &str, depth: Depth) -> Vec<ModuleSnapshot> {
    let full = depth == Depth::Full;
    let Some(u) = task.units.get(unit) else {
        return Vec::new();
    };
    let mut values = crate::consteval::module_data_values(task, unit);
    let index = LineIndex::new(&u.text);
    let text = u.text.as_str();
    let root = u.tree().root_node();
    let mut nodes: HashMap<usize, Node<'_>> = HashMap::new();
    let mut cursor = root.walk();
    for n in root.named_children(&mut cursor) {
        if kind_of(n) == kind::MODULE {
            nodes.insert(n.start_byte(), n);
        }
    }
    let line_of = |offset: usize| index.line_col(offset).line + 1;
    let mut out = Vec::new();
    for (m, module) in u.items.modules.iter().enumerate() {
        let Some(node) = nodes.get(&module.range.start).copied() else {
            continue;
        };
        let mut liner = Liner::new(text, &index);
        let mut snap = ModuleSnapshot {
            name: module.name.clone(),
            file: file.to_owned(),
            line: line_of(module.range.start),
            attributes: field(node, field::ATTRIBUTES)
                .map(|a| {
                    fields(a, field::ATTRIBUTE)
                        .iter()
                        .map(|n| text[n.byte_range()].trim().to_ascii_uppercase())
                        .collect()
                })
                .unwrap_or_default(),
            same_text: !full,
            ..ModuleSnapshot::default()
        };
        let data_at: HashMap<usize, usize> = module
            .data
            .iter()
            .enumerate()
            .map(|(i, d)| (d.range.start, i))
            .collect();
        for item in fields(node, field::BODY) {
            let k = kind_of(item);
            match k {
                kind::PROCEDURE_DECLARATION
                | kind::FUNCTION_DECLARATION
                | kind::TRAP_DECLARATION => {
                    let Some(name) = field(item, field::NAME) else {
                        continue;
                    };
                    snap.routines.push(RoutineSnapshot {
                        name: text[name.byte_range()].to_owned(),
                        kind: match k {
                            kind::PROCEDURE_DECLARATION => "PROC",
                            kind::FUNCTION_DECLARATION => "FUNC",
                            _ => "TRAP",
                        },
                        line: line_of(item.start_byte()),
                        lines: if full {
                            liner.routine(item)
                        } else {
                            Vec::new()
                        },
                    });
                }
                kind::RECORD_DECLARATION | kind::ALIAS_DECLARATION => {
                    let Some(name) = field(item, field::NAME) else {
                        continue;
                    };
                    snap.types.push(TypeSnapshot {
                        name: text[name.byte_range()].to_owned(),
                        line: line_of(item.start_byte()),
                        lines: if full {
                            liner.one_line(item, 0).into_iter().collect()
                        } else {
                            Vec::new()
                        },
                    });
                }
                kind::DATA_DECLARATION => {
                    let Some(&i) = data_at.get(&item.start_byte()) else {
                        continue;
                    };
                    let Some(d) = module.data.get(i) else {
                        continue;
                    };
                    // Its type is a name it uses (its value's are in `init`).
                    if let Some(t) = &d.ty {
                        liner.names.insert(fold(&t.name));
                    }
                    let dims = field(item, field::DIMENSIONS)
                        .map(|l| {
                            fields(l, field::DIMENSION)
                                .into_iter()
                                .filter_map(|n| liner.one_line(n, 0))
                                .collect()
                        })
                        .unwrap_or_default();
                    snap.data.push(DataSnapshot {
                        name: d.name.clone(),
                        line: line_of(d.range.start),
                        storage: d.storage,
                        scope: d.scope,
                        ty: d.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                        dims,
                        init: field(item, field::VALUE)
                            .filter(|_| full)
                            .and_then(|v| liner.one_line(v, 0)),
                        value: values
                            .get_mut(m)
                            .and_then(|v| v.get_mut(i))
                            .and_then(Option::take),
                    });
                }
                _ => {}
            }
        }
        snap.declared = declared(module);
        snap.names = std::mem::take(&mut liner.names);
        out.push(snap);
    }
    out
}

fn declared(module: &crate::items::Module) -> BTreeSet<String> {
    crate::task::module_items(module)
        .map(|(name, _, _)| fold(name))
        .collect()
}

/// The modules of `unit` in `task` ([`modules_of`] by the unit's path),
/// its file named `file`: what [`tasks_of`] does for each file, which a
/// caller may do in parallel.
pub fn unit_modules(task: &Task, unit: &Unit, file: &str, depth: Depth) -> Vec<ModuleSnapshot> {
    match task.units.iter().position(|u| u.path == unit.path) {
        Some(idx) => modules_of(task, idx, file, depth),
        None => Vec::new(),
    }
}

/// Groups each file's modules by task name: tasks in the order of their
/// names, modules in the order given.
pub fn group(per_file: Vec<(String, Vec<ModuleSnapshot>)>) -> Vec<super::TaskSnapshot> {
    let mut tasks: std::collections::BTreeMap<String, super::TaskSnapshot> = Default::default();
    for (name, modules) in per_file {
        let entry = tasks
            .entry(name.clone())
            .or_insert_with(|| super::TaskSnapshot {
                name,
                modules: Vec::new(),
            });
        entry.modules.extend(modules);
    }
    tasks.into_values().collect()
}

/// The tasks of a workspace as snapshots: each file's modules (in the task
/// that resolves its names, [`crate::workspace::Workspace::checks`]),
/// grouped by task, each task named by `task_name` of its key and each
/// file by `file_name` of its path.
pub fn tasks_of(
    workspace: &mut crate::workspace::Workspace,
    task_name: &dyn Fn(&str) -> String,
    file_name: &dyn Fn(&str) -> String,
) -> Vec<super::TaskSnapshot> {
    let per_file = workspace
        .checks()
        .iter()
        .map(|(task, unit)| {
            let modules = unit_modules(task, unit, &file_name(&unit.path), Depth::Full);
            (task_name(&task.key), modules)
        })
        .collect();
    group(per_file)
}
