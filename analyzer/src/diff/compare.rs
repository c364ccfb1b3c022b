//! Matching two snapshots by name and listing what changed.

use std::collections::HashMap;

use rapid_evaluator::Value;
use similar::{Algorithm, DiffOp, capture_diff_slices, group_diff_ops};

use super::values::compare_values;
use super::{
    DataDiff, DataSide, DataSnapshot, Hunk, HunkLine, Line, ModuleDiff, ModuleSnapshot, Options,
    Report, RoutineDiff, Snapshot, Status, Tag, TaskDiff, TaskSnapshot,
};
use crate::names::fold;

/// Unchanged lines shown around each change of a routine.
const CONTEXT: usize = 2;

/// Everything that changed from `old` to `new`.
pub fn compare(old: &Snapshot, new: &Snapshot, options: &Options) -> Report {
    let mut report = Report::default();
    // One task on each side: they are the same task, whatever their names.
    let tasks = if old.tasks.len() == 1 && new.tasks.len() == 1 {
        vec![(old.tasks.first(), new.tasks.first())]
    } else {
        pairs(&old.tasks, &new.tasks, |t| fold(&t.name))
    };
    for pair in tasks {
        let (name, old_name) = match pair {
            (Some(o), Some(n)) if !o.name.eq_ignore_ascii_case(&n.name) => {
                (n.name.clone(), Some(o.name.clone()))
            }
            (_, Some(t)) | (Some(t), None) => (t.name.clone(), None),
            (None, None) => continue,
        };
        let (modules, status) = task_modules(pair, options, &mut report.ignored_moves);
        if !modules.is_empty() {
            report.tasks.push(TaskDiff {
                name,
                old_name,
                status,
                modules,
            });
        }
    }
    report.config = super::config::compare_configs(&old.configs, &new.configs);
    report.builtins = super::builtins::changed_builtins(old, new);
    report
}

/// Pairs items by key: every old item with the new one of the same key
/// (in order, when a key repeats), then the new ones left.
fn pairs<'a, T>(
    old: &'a [T],
    new: &'a [T],
    key: impl Fn(&T) -> String,
) -> Vec<(Option<&'a T>, Option<&'a T>)> {
    let mut by_key: HashMap<String, Vec<&'a T>> = HashMap::new();
    for n in new.iter().rev() {
        by_key.entry(key(n)).or_default().push(n);
    }
    let mut out = Vec::new();
    for o in old {
        let n = by_key.get_mut(&key(o)).and_then(Vec::pop);
        out.push((Some(o), n));
    }
    for n in new {
        let k = key(n);
        if let Some(left) = by_key.get_mut(&k)
            && left.last().is_some_and(|l| std::ptr::eq(*l, n))
        {
            left.pop();
            out.push((None, Some(n)));
        }
    }
    out
}

/// The module changes of a pair of tasks, and the task's status.
fn task_modules(
    pair: (Option<&TaskSnapshot>, Option<&TaskSnapshot>),
    options: &Options,
    ignored: &mut usize,
) -> (Vec<ModuleDiff>, Status) {
    let empty = TaskSnapshot::default();
    let status = match pair {
        (None, _) => Status::Added,
        (_, None) => Status::Removed,
        _ => Status::Changed,
    };
    let (o, n) = (pair.0.unwrap_or(&empty), pair.1.unwrap_or(&empty));
    let mut out = Vec::new();
    for (a, b) in pairs(&o.modules, &n.modules, |m| fold(&m.name)) {
        if let Some(d) = module_diff(a, b, options, ignored) {
            out.push(d);
        }
    }
    (out, status)
}

fn module_diff(
    old: Option<&ModuleSnapshot>,
    new: Option<&ModuleSnapshot>,
    options: &Options,
    ignored: &mut usize,
) -> Option<ModuleDiff> {
    let empty = ModuleSnapshot::default();
    let (o, n) = (old.unwrap_or(&empty), new.unwrap_or(&empty));
    let status = match (old, new) {
        (None, _) => Status::Added,
        (_, None) => Status::Removed,
        _ => Status::Changed,
    };
    let mut data = Vec::new();
    for (a, b) in pairs(&o.data, &n.data, |d| fold(&d.name)) {
        data_diffs(a, b, options, ignored, &mut data);
    }
    sort_data(&mut data);
    // A file the same on both sides: its routines and types are too.
    let same_text = o.same_text || n.same_text;
    let mut routines = Vec::new();
    for (a, b) in pairs(&o.routines, &n.routines, |r| fold(&r.name))
        .into_iter()
        .filter(|_| !same_text)
    {
        let (name, kind) = match (a, b) {
            (_, Some(r)) | (Some(r), None) => (r.name.clone(), r.kind),
            (None, None) => continue,
        };
        routines.extend(lines_diff(
            name,
            kind,
            a.map(|r| (r.line, &r.lines[..])),
            b.map(|r| (r.line, &r.lines[..])),
        ));
    }
    let mut types = Vec::new();
    for (a, b) in pairs(&o.types, &n.types, |t| fold(&t.name))
        .into_iter()
        .filter(|_| !same_text)
    {
        let (name, kind) = match (a, b) {
            (_, Some(t)) | (Some(t), None) => (t.name.clone(), type_kind(&t.lines)),
            (None, None) => continue,
        };
        types.extend(lines_diff(
            name,
            kind,
            a.map(|t| (t.line, &t.lines[..])),
            b.map(|t| (t.line, &t.lines[..])),
        ));
    }
    let attributes = (o.attributes != n.attributes && status == Status::Changed)
        .then(|| (o.attributes.clone(), n.attributes.clone()));
    let unchanged = data.is_empty() && routines.is_empty() && types.is_empty();
    if status == Status::Changed && unchanged && attributes.is_none() {
        return None;
    }
    Some(ModuleDiff {
        name: new.or(old).map(|m| m.name.clone()).unwrap_or_default(),
        status,
        old_file: old.map(|m| m.file.clone()),
        new_file: new.map(|m| m.file.clone()),
        attributes,
        data,
        routines,
        types,
    })
}

fn type_kind(lines: &[Line]) -> &'static str {
    match lines.first() {
        Some(l) if l.key.contains("ALIAS ") || l.key.starts_with("ALIAS") => "ALIAS",
        _ => "RECORD",
    }
}

/// Moves first, largest first; then the other changes, added and removed
/// data, by name.
fn sort_data(data: &mut [DataDiff]) {
    data.sort_by(|a, b| {
        let size = |d: &DataDiff| d.motion.as_ref().filter(|m| m.is_move()).map(|m| m.size());
        match (size(a), size(b)) {
            (Some(x), Some(y)) => y
                .partial_cmp(&x)
                .unwrap_or(std::cmp::Ordering::Equal)
                .then_with(|| fold(&a.name).cmp(&fold(&b.name))),
            (Some(_), None) => std::cmp::Ordering::Less,
            (None, Some(_)) => std::cmp::Ordering::Greater,
            (None, None) => rank(a.status)
                .cmp(&rank(b.status))
                .then_with(|| fold(&a.name).cmp(&fold(&b.name))),
        }
    });
}

fn rank(s: Status) -> u8 {
    match s {
        Status::Changed => 0,
        Status::Added => 1,
        Status::Removed => 2,
    }
}

fn side(d: &DataSnapshot, value: Option<&Value>) -> DataSide {
    DataSide {
        declaration: d.declaration(),
        value: value
            .map(ToString::to_string)
            .or_else(|| d.init.as_ref().map(|l| l.text.clone())),
        line: d.line,
    }
}

/// The changes of a pair of data (an array's elements one by one when only
/// they changed).
fn data_diffs(
    old: Option<&DataSnapshot>,
    new: Option<&DataSnapshot>,
    options: &Options,
    ignored: &mut usize,
    out: &mut Vec<DataDiff>,
) {
    let (o, n) = match (old, new) {
        (Some(o), Some(n)) => (o, n),
        (Some(d), None) | (None, Some(d)) => {
            let s = Some(side(d, d.value.as_ref()));
            let added = old.is_none();
            out.push(DataDiff {
                name: d.name.clone(),
                status: if added {
                    Status::Added
                } else {
                    Status::Removed
                },
                old: if added { None } else { s.clone() },
                new: if added { s } else { None },
                changed: Vec::new(),
                derived: false,
                motion: None,
                fields: Vec::new(),
            });
            return;
        }
        (None, None) => return,
    };
    let mut changed = Vec::new();
    if o.storage != n.storage {
        changed.push("storage");
    }
    if o.scope != n.scope {
        changed.push("scope");
    }
    let dims = |d: &DataSnapshot| d.dims.iter().map(|l| l.key.clone()).collect::<Vec<_>>();
    if fold(&o.ty) != fold(&n.ty) || dims(o) != dims(n) {
        changed.push("type");
    }
    let same_init = o.init.as_ref().map(|l| &l.key) == n.init.as_ref().map(|l| &l.key);
    let value_changed = match (&o.value, &n.value) {
        // Of another type (`num` and `dnum`), the same value reads the same.
        (Some(a), Some(b)) if changed.contains(&"type") => a.to_string() != b.to_string(),
        (Some(a), Some(b)) => a != b,
        _ => !same_init,
    };
    // An array whose declaration is unchanged: its elements one by one (a
    // record of a type whose components no source documents is an
    // aggregate too, but one value).
    if changed.is_empty()
        && value_changed
        && !n.dims.is_empty()
        && let (Some(Value::Array(a)), Some(Value::Array(b))) = (&o.value, &n.value)
        && a.len() == b.len()
    {
        elements(
            o,
            n,
            &mut Vec::new(),
            a,
            b,
            !same_init,
            options,
            ignored,
            out,
        );
        return;
    }
    let mut diff = DataDiff {
        name: n.name.clone(),
        status: Status::Changed,
        old: Some(side(o, o.value.as_ref())),
        new: Some(side(n, n.value.as_ref())),
        changed,
        derived: false,
        motion: None,
        fields: Vec::new(),
    };
    if value_changed {
        diff.changed.push("value");
        diff.derived = same_init;
        if let (Some(a), Some(b)) = (&o.value, &n.value) {
            let change = compare_values(a, b);
            if diff.changed == ["value"] && change.is_small(options) {
                *ignored += 1;
                return;
            }
            diff.motion = change.motion;
            diff.fields = change.fields;
        }
    }
    if !diff.changed.is_empty() {
        out.push(diff);
    }
}

/// The elements of two arrays of one shape that differ, as data of their
/// own (`path{2}`, `grid{1,3}`).
#[allow(clippy::too_many_arguments)]
fn elements(
    o: &DataSnapshot,
    n: &DataSnapshot,
    index: &mut Vec<usize>,
    a: &[Value],
    b: &[Value],
    init_changed: bool,
    options: &Options,
    ignored: &mut usize,
    out: &mut Vec<DataDiff>,
) {
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        if x == y {
            continue;
        }
        index.push(i + 1);
        match (x, y) {
            (Value::Array(xs), Value::Array(ys))
                if xs.len() == ys.len() && index.len() < n.dims.len() =>
            {
                elements(o, n, index, xs, ys, init_changed, options, ignored, out);
            }
            _ => {
                let at: Vec<String> = index.iter().map(ToString::to_string).collect();
                let name = format!("{}{{{}}}", n.name, at.join(","));
                let change = compare_values(x, y);
                if change.is_small(options) {
                    *ignored += 1;
                } else {
                    let element = |d: &DataSnapshot, v: &Value| DataSide {
                        declaration: format!("{}{{{}}}", d.declaration(), at.join(",")),
                        value: Some(v.to_string()),
                        line: d.line,
                    };
                    out.push(DataDiff {
                        name,
                        status: Status::Changed,
                        old: Some(element(o, x)),
                        new: Some(element(n, y)),
                        changed: vec!["value"],
                        derived: !init_changed,
                        motion: change.motion,
                        fields: change.fields,
                    });
                }
            }
        }
        index.pop();
    }
}

/// The hunks between two lists of lines (either may be missing: an added
/// or removed routine), or nothing when they compare equal.
fn lines_diff(
    name: String,
    kind: &'static str,
    old: Option<(usize, &[Line])>,
    new: Option<(usize, &[Line])>,
) -> Option<RoutineDiff> {
    let (status, hunks) = match (old, new) {
        (Some((_, a)), Some((_, b))) => {
            let hunks = hunks(a, b);
            if hunks.is_empty() {
                return None;
            }
            (Status::Changed, hunks)
        }
        (None, Some((_, b))) => (Status::Added, vec![whole(b, Tag::Added)]),
        (Some((_, a)), None) => (Status::Removed, vec![whole(a, Tag::Removed)]),
        (None, None) => return None,
    };
    Some(RoutineDiff {
        name,
        kind,
        status,
        old_line: old.map(|o| o.0),
        new_line: new.map(|n| n.0),
        hunks,
    })
}

fn whole(lines: &[Line], tag: Tag) -> Hunk {
    Hunk {
        lines: lines.iter().map(|l| hunk_line(l, tag)).collect(),
    }
}

fn hunk_line(l: &Line, tag: Tag) -> HunkLine {
    HunkLine {
        tag,
        depth: l.depth,
        text: l.text.clone(),
        old_line: (tag != Tag::Added).then_some(l.line),
        new_line: (tag != Tag::Removed).then_some(l.line),
    }
}

/// Hunks of changed lines with [`CONTEXT`] unchanged lines around them.
fn hunks(old: &[Line], new: &[Line]) -> Vec<Hunk> {
    let a: Vec<&str> = old.iter().map(|l| l.key.as_str()).collect();
    let b: Vec<&str> = new.iter().map(|l| l.key.as_str()).collect();
    if a == b {
        return Vec::new();
    }
    let ops = capture_diff_slices(Algorithm::Myers, &a, &b);
    let mut out = Vec::new();
    for group in group_diff_ops(ops, CONTEXT) {
        let mut lines = Vec::new();
        for op in group {
            match op {
                DiffOp::Equal {
                    old_index,
                    new_index,
                    len,
                } => {
                    for k in 0..len {
                        let (o, n) = (&old[old_index + k], &new[new_index + k]);
                        lines.push(HunkLine {
                            tag: Tag::Context,
                            depth: n.depth,
                            text: n.text.clone(),
                            old_line: Some(o.line),
                            new_line: Some(n.line),
                        });
                    }
                }
                DiffOp::Delete {
                    old_index, old_len, ..
                } => lines.extend(
                    old[old_index..old_index + old_len]
                        .iter()
                        .map(|l| hunk_line(l, Tag::Removed)),
                ),
                DiffOp::Insert {
                    new_index, new_len, ..
                } => lines.extend(
                    new[new_index..new_index + new_len]
                        .iter()
                        .map(|l| hunk_line(l, Tag::Added)),
                ),
                DiffOp::Replace {
                    old_index,
                    old_len,
                    new_index,
                    new_len,
                } => {
                    lines.extend(
                        old[old_index..old_index + old_len]
                            .iter()
                            .map(|l| hunk_line(l, Tag::Removed)),
                    );
                    lines.extend(
                        new[new_index..new_index + new_len]
                            .iter()
                            .map(|l| hunk_line(l, Tag::Added)),
                    );
                }
            }
        }
        out.push(Hunk { lines });
    }
    out
}
