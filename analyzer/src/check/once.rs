//! Findings about a name rather than a place are reported once: an
//! unresolved name, an unconfigured signal, a built-in that needs an option
//! or another RobotWare. The first use carries the finding; for an
//! unresolved name, the other uses are its related locations (where to
//! fix them all). Within a file ([`within_file`],
//! part of every check) and, for a whole task's report, across its files
//! ([`per_task`]).

use std::collections::HashMap;
use std::ops::Range;

use crate::diagnostic::{Diagnostic, Related};
use crate::names::fold;
use crate::rules;

/// Is this a finding about a name, reported once?
fn is_about_a_name(d: &Diagnostic) -> bool {
    [
        &rules::unresolved_name::RULE,
        &rules::unconfigured_signal::RULE,
        &rules::option_routine::RULE,
        &rules::builtin_version::RULE,
    ]
    .iter()
    .any(|r| std::ptr::eq(d.rule, *r))
}

fn is_unresolved(d: &Diagnostic) -> bool {
    std::ptr::eq(d.rule, &rules::unresolved_name::RULE)
}

/// What makes two findings one: the rule and the name (the text of the
/// finding's range, case folded).
fn key(d: &Diagnostic, text: &str) -> (&'static str, String) {
    (
        d.rule.code,
        fold(text.get(d.range.clone()).unwrap_or_default()),
    )
}

/// The later use of a name, as a related location of its finding.
fn also_here(file: Option<String>, range: Range<usize>) -> Related {
    Related {
        file,
        range,
        message: "used here too".to_owned(),
    }
}

/// How much a use says of the signal a name is taken for: a comparison
/// (`IF doLamp = 0`) or a `TEST` takes an input, which an output can be
/// read as too; a use that sets the signal (`SetDO doLamp, 1`) says it is
/// an output. The finding of a name keeps the type its strongest use
/// gives, so that the simulation declares the signal it can set.
fn signal_rank(d: &Diagnostic) -> u8 {
    rules::unconfigured_signal::taken_signal(d)
        .and_then(|(_, ty)| crate::task::SignalKind::from_type(ty))
        .map_or(0, crate::task::SignalKind::strength)
}

/// Keeps the first finding of each name in a unit's findings (sorted by
/// position); the later uses become its related locations.
pub(crate) fn within_file(diags: &mut Vec<Diagnostic>, text: &str) {
    let mut first: HashMap<(&'static str, String), usize> = HashMap::new();
    let mut keep = vec![true; diags.len()];
    let mut uses: Vec<(usize, Range<usize>)> = Vec::new();
    let mut stronger: Vec<(usize, usize)> = Vec::new();
    for (i, d) in diags.iter().enumerate() {
        if !is_about_a_name(d) {
            continue;
        }
        match first.entry(key(d, text)) {
            std::collections::hash_map::Entry::Occupied(e) => {
                keep[i] = false;
                if is_unresolved(d) {
                    uses.push((*e.get(), d.range.clone()));
                } else if signal_rank(d) > 0 {
                    stronger.push((*e.get(), i));
                }
            }
            std::collections::hash_map::Entry::Vacant(e) => {
                e.insert(i);
            }
        }
    }
    // An unresolved name the file takes for a signal elsewhere (`SetDO
    // doLamp, 1` and `TPWrite "" \Num:=doLamp`) is that signal's use: a
    // related location of the signal's finding, not a finding of its own.
    let signals: HashMap<String, usize> = diags
        .iter()
        .enumerate()
        .filter(|(i, d)| keep[*i] && std::ptr::eq(d.rule, &rules::unconfigured_signal::RULE))
        .map(|(i, d)| (key(d, text).1, i))
        .collect();
    for (i, d) in diags.iter().enumerate() {
        if !keep[i] || !is_unresolved(d) {
            continue;
        }
        if let Some(&at) = signals.get(&key(d, text).1) {
            keep[i] = false;
            uses.push((at, d.range.clone()));
            // The later uses of the dropped finding go with it.
            let moved: Vec<(usize, Range<usize>)> = uses
                .iter()
                .filter(|(u, _)| *u == i)
                .map(|(_, r)| (at, r.clone()))
                .collect();
            uses.extend(moved);
        }
    }
    for (at, range) in uses {
        if keep[at]
            && let Some(d) = diags.get_mut(at)
        {
            d.related.push(also_here(None, range));
        }
    }
    for (at, later) in stronger {
        if signal_rank(&diags[later]) > signal_rank(&diags[at]) {
            diags[at].message = diags[later].message.clone();
        }
    }
    let mut keep = keep.into_iter();
    diags.retain(|_| keep.next().unwrap_or(true));
}

/// One checked file of a task report: its task's key, its path and text,
/// and its findings ([`within_file`] already applied).
pub struct FileFindings<'a> {
    pub task: &'a str,
    pub path: &'a str,
    pub text: &'a str,
    pub diagnostics: &'a mut Vec<Diagnostic>,
}

/// Keeps the first finding of each name per task, the files taken in path
/// order: a finding of a later file becomes related locations (its own
/// place and its related ones) of the first file's. `rapid check` reports
/// this way, so that a name a partial project lacks is one finding, not one
/// per file.
pub fn per_task(files: &mut [FileFindings<'_>]) {
    files.sort_by(|a, b| (a.task, a.path).cmp(&(b.task, b.path)));
    // (task, rule, name) -> (file index, diagnostic index)
    let mut first: HashMap<(&str, &'static str, String), (usize, usize)> = HashMap::new();
    let mut moved: Vec<((usize, usize), Vec<Related>)> = Vec::new();
    let mut stronger: Vec<((usize, usize), Diagnostic)> = Vec::new();
    for (f, file) in files.iter_mut().enumerate() {
        let path = file.path;
        let mut i = 0;
        while i < file.diagnostics.len() {
            let d = &file.diagnostics[i];
            if !is_about_a_name(d) {
                i += 1;
                continue;
            }
            let (code, name) = key(d, file.text);
            match first.entry((file.task, code, name)) {
                std::collections::hash_map::Entry::Occupied(e) => {
                    let d = file.diagnostics.remove(i);
                    if !is_unresolved(&d) {
                        if signal_rank(&d) > 0 {
                            stronger.push((*e.get(), d));
                        }
                        continue;
                    }
                    let mut related = vec![also_here(Some(path.to_owned()), d.range)];
                    related.extend(d.related.into_iter().map(|r| Related {
                        file: r.file.or_else(|| Some(path.to_owned())),
                        ..r
                    }));
                    moved.push((*e.get(), related));
                }
                std::collections::hash_map::Entry::Vacant(e) => {
                    e.insert((f, i));
                    i += 1;
                }
            }
        }
    }
    for ((f, i), related) in moved {
        if let Some(d) = files
            .get_mut(f)
            .and_then(|file| file.diagnostics.get_mut(i))
        {
            d.related.extend(related);
        }
    }
    for ((f, i), later) in stronger {
        if let Some(d) = files
            .get_mut(f)
            .and_then(|file| file.diagnostics.get_mut(i))
            && signal_rank(&later) > signal_rank(d)
        {
            d.message = later.message;
        }
    }
    signal_uses_per_task(files);
}

/// [`within_file`]'s rule for a task's files: an unresolved name that
/// another file of the task takes for a signal is a use of that signal.
fn signal_uses_per_task(files: &mut [FileFindings<'_>]) {
    let mut signals: HashMap<(&str, String), (usize, usize)> = HashMap::new();
    for (f, file) in files.iter().enumerate() {
        for (i, d) in file.diagnostics.iter().enumerate() {
            if std::ptr::eq(d.rule, &rules::unconfigured_signal::RULE) {
                signals
                    .entry((file.task, key(d, file.text).1))
                    .or_insert((f, i));
            }
        }
    }
    if signals.is_empty() {
        return;
    }
    let mut moved: Vec<((usize, usize), Vec<Related>)> = Vec::new();
    let mut removed: Vec<Vec<usize>> = vec![Vec::new(); files.len()];
    for (f, file) in files.iter().enumerate() {
        for (i, d) in file.diagnostics.iter().enumerate() {
            if !is_unresolved(d) {
                continue;
            }
            let Some(&at) = signals.get(&(file.task, key(d, file.text).1)) else {
                continue;
            };
            let path = file.path;
            let mut related = vec![also_here(Some(path.to_owned()), d.range.clone())];
            related.extend(d.related.iter().cloned().map(|r| Related {
                file: r.file.or_else(|| Some(path.to_owned())),
                ..r
            }));
            moved.push((at, related));
            removed[f].push(i);
        }
    }
    for ((f, i), related) in moved {
        let Some(file) = files.get_mut(f) else {
            continue;
        };
        let path = file.path.to_owned();
        if let Some(d) = file.diagnostics.get_mut(i) {
            // Locations in the signal's own file need no file name.
            d.related.extend(related.into_iter().map(|r| Related {
                file: r.file.filter(|p| *p != path),
                ..r
            }));
        }
    }
    for (file, removed) in files.iter_mut().zip(removed) {
        let mut at = 0;
        file.diagnostics.retain(|_| {
            at += 1;
            !removed.contains(&(at - 1))
        });
    }
}
