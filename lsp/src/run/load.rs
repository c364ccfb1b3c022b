//! Loading the task(s) a path holds for `rapid run`, `rapid test` and
//! `rapid dap`: the files are found and grouped as `rapid check` finds and
//! groups them (a backup's `RAPID/TASKn`, the modules a `.pgf` lists, else
//! a folder), through the analyzer's `Workspace`.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use rapid_analyzer::task::{Task, Unit};
use rapid_runtime::{Program, SignalChange, SignalKind};

use crate::project::Environment;

/// The tasks found under `paths` (each named file's task whole: the other
/// modules of its folder or backup task are loaded with it). Files that
/// cannot be read are reported in `skipped`.
pub struct Found {
    pub tasks: Vec<Arc<Task>>,
    pub skipped: Vec<(PathBuf, String)>,
}

pub fn tasks(paths: &[PathBuf]) -> Result<Found, String> {
    tasks_in(&crate::project::DiskAsNamed, paths)
}

/// [`tasks`] in `env`.
pub fn tasks_in(env: &dyn Environment, paths: &[PathBuf]) -> Result<Found, String> {
    let around = crate::project::load_around(env, paths)
        .map_err(|(p, e)| format!("{}: {e}", p.display()))?;
    let mut workspace = around.loaded.workspace;
    let skipped = around
        .loaded
        .read
        .iter()
        .zip(&around.files)
        .filter_map(|(r, file)| r.as_ref().err().map(|why| (file.clone(), why.to_string())))
        .collect();
    let mut tasks = if around.named.is_empty() {
        workspace.tasks()
    } else {
        let mut t: Vec<Arc<Task>> = around
            .named
            .iter()
            .map(|n| workspace.task_of(&env.name(n)))
            .collect();
        t.dedup_by(|a, b| a.key == b.key);
        t
    };
    tasks.retain(|t| !t.units.is_empty());
    Ok(Found { tasks, skipped })
}

/// The one task `path` holds (a module: its task; a folder: its only
/// task, or the one that declares `entry`).
pub fn one_task(path: &Path, entry: &str) -> Result<Arc<Task>, String> {
    one_task_in(&crate::project::DiskAsNamed, path, entry)
}

/// [`one_task`] in `env`.
pub fn one_task_in(env: &dyn Environment, path: &Path, entry: &str) -> Result<Arc<Task>, String> {
    let found = tasks_in(env, std::slice::from_ref(&path.to_path_buf()))?;
    let mut tasks = found.tasks;
    match tasks.len() {
        0 => Err(format!("{}: no RAPID modules found", path.display())),
        1 => Ok(tasks.remove(0)),
        n => {
            let with_entry: Vec<Arc<Task>> = tasks
                .iter()
                .filter(|t| declares(t, entry))
                .cloned()
                .collect();
            match with_entry.len() {
                1 => Ok(with_entry[0].clone()),
                _ => {
                    let keys: Vec<&str> = tasks.iter().map(|t| t.key.as_str()).take(5).collect();
                    Err(format!(
                        "{}: the folder holds {n} tasks; name one of them (e.g. {})",
                        path.display(),
                        keys.join(", ")
                    ))
                }
            }
        }
    }
}

fn declares(task: &Task, routine: &str) -> bool {
    task.units.iter().any(|u| {
        u.items.modules.iter().any(|m| {
            m.routines
                .iter()
                .any(|r| r.name.eq_ignore_ascii_case(routine))
        })
    })
}

/// `task` with more modules (given as path and text), unless it declares
/// a routine of theirs already: the same controller's task (configuration,
/// catalogue view, controller names), as `rapid check` checks it, with the
/// modules added ([`Task::with_extra_units`]).
pub fn with_modules(task: &Arc<Task>, modules: &[(&str, &str)]) -> Arc<Task> {
    let mut extra = Vec::new();
    for (path, text) in modules {
        let unit = Unit::new((*path).to_owned(), (*text).to_owned(), None);
        let clash = unit
            .items
            .modules
            .iter()
            .flat_map(|m| m.routines.iter())
            .any(|r| declares(task, &r.name));
        if !clash {
            extra.push(Arc::new(unit));
        }
    }
    if extra.is_empty() {
        return task.clone();
    }
    Arc::new(task.with_extra_units(extra))
}

/// A `--set NAME=VALUE[@SECONDS]` option.
pub fn parse_set(text: &str) -> Result<SignalChange, String> {
    let (name, rest) = text
        .split_once('=')
        .ok_or_else(|| format!("--set {text}: expected NAME=VALUE or NAME=VALUE@SECONDS"))?;
    let (value, at) = rest.split_once('@').unwrap_or((rest, "0"));
    let value: f64 = value
        .trim()
        .parse()
        .map_err(|_| format!("--set {text}: {value:?} is not a number"))?;
    let at: f64 = at
        .trim()
        .parse()
        .ok()
        .filter(|t: &f64| *t >= 0.0 && t.is_finite())
        .ok_or_else(|| format!("--set {text}: {at:?} is not a time in seconds"))?;
    let name = name.trim();
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(format!("--set {text}: {name:?} is not a signal name"));
    }
    Ok(SignalChange {
        name: name.to_owned(),
        value,
        at,
    })
}

/// The program of `task`, with the signals `--set` names that its
/// configuration does not declare (their kind guessed from the name's
/// first letters: `di`, `do`, `ai`, `ao`, `gi`, `go`; a digital input
/// otherwise), configured as `EIO.cfg` would ([`Task::with_signals`]).
pub fn program(task: Arc<Task>, sets: &[SignalChange]) -> Arc<Program> {
    let configured = |n: &str| {
        task.signals
            .as_ref()
            .is_some_and(|s| s.contains_key(&n.to_ascii_lowercase()))
    };
    let mut extra: Vec<(String, &'static str)> = Vec::new();
    for s in sets {
        if !configured(&s.name) && !extra.iter().any(|(n, _)| n.eq_ignore_ascii_case(&s.name)) {
            extra.push((s.name.clone(), SignalKind::guess(&s.name).type_name()));
        }
    }
    let task = if extra.is_empty() {
        task
    } else {
        Arc::new(task.with_signals(&extra))
    };
    Arc::new(Program::new(task, &[]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_options_parse_or_say_what_is_wrong() {
        let s = parse_set("di1=1@2.5").expect("valid");
        assert_eq!((s.name.as_str(), s.value, s.at), ("di1", 1.0, 2.5));
        assert_eq!(parse_set("go_code=12").expect("valid").at, 0.0);
        assert!(
            parse_set("di1")
                .expect_err("invalid")
                .contains("NAME=VALUE")
        );
        assert!(
            parse_set("di1=x")
                .expect_err("invalid")
                .contains("not a number")
        );
        assert!(
            parse_set("di1=1@-2")
                .expect_err("invalid")
                .contains("seconds")
        );
        assert!(
            parse_set("a b=1")
                .expect_err("invalid")
                .contains("signal name")
        );
    }
}
