//! The analysis host: every file of a workspace, grouped into tasks, with
//! cached results.
//!
//! Callers hand in texts (and `EIO.cfg` texts); the workspace parses them,
//! groups them into tasks ([`task_key`]), and checks files on request. A
//! file's check result is reused until the file itself or the interface of
//! its task (the declarations other modules see) changes, so typing inside a
//! routine re-checks only that file.

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use crate::diagnostic::Diagnostic;
use crate::task::{Signals, Task, Unit, parse_eio_signals, task_key};

#[derive(Default)]
pub struct Workspace {
    units: BTreeMap<String, Arc<Unit>>,
    /// Signal names of each I/O configuration file, by the file's path.
    configs: BTreeMap<String, Signals>,
    tasks: HashMap<String, Arc<Task>>,
    checked: HashMap<String, Checked>,
}

struct Checked {
    unit: Arc<Unit>,
    interface: u64,
    diagnostics: Arc<Vec<Diagnostic>>,
}

impl Workspace {
    pub fn new() -> Workspace {
        Workspace::default()
    }

    /// Adds or replaces a file, parsing it from scratch.
    pub fn set_file(&mut self, path: &str, text: String) {
        self.set_unit(Unit::new(path.to_owned(), text, None));
    }

    /// Adds or replaces a file parsed by the caller (e.g. incrementally).
    pub fn set_unit(&mut self, unit: Unit) {
        let key = task_key(&unit.path);
        self.tasks.remove(&key);
        self.units.insert(unit.path.clone(), Arc::new(unit));
    }

    pub fn remove_file(&mut self, path: &str) {
        if self.units.remove(path).is_some() {
            self.tasks.remove(&task_key(path));
            self.checked.remove(path);
        }
    }

    /// Adds or replaces an I/O configuration file (`EIO.cfg`). It applies
    /// to the tasks below its folder (below the backup for `SYSPAR/EIO.cfg`).
    pub fn set_config(&mut self, path: &str, text: &str) {
        self.configs
            .insert(path.to_owned(), parse_eio_signals(text));
        self.tasks.clear();
    }

    pub fn remove_config(&mut self, path: &str) {
        if self.configs.remove(path).is_some() {
            self.tasks.clear();
        }
    }

    pub fn unit(&self, path: &str) -> Option<&Arc<Unit>> {
        self.units.get(path)
    }

    pub fn paths(&self) -> impl Iterator<Item = &str> {
        self.units.keys().map(String::as_str)
    }

    /// The task a file belongs to (built on demand and cached).
    pub fn task_of(&mut self, path: &str) -> Arc<Task> {
        let key = task_key(path);
        if let Some(t) = self.tasks.get(&key) {
            return t.clone();
        }
        let units: Vec<Arc<Unit>> = self
            .units
            .values()
            .filter(|u| task_key(&u.path) == key)
            .cloned()
            .collect();
        let task = Arc::new(Task::new(key.clone(), units, self.signals_for(&key)));
        self.tasks.insert(key, task.clone());
        task
    }

    /// Every task of the workspace.
    pub fn tasks(&mut self) -> Vec<Arc<Task>> {
        let keys: BTreeMap<String, String> = self
            .units
            .keys()
            .map(|p| (task_key(p), p.clone()))
            .collect();
        keys.values().map(|p| self.task_of(p)).collect()
    }

    fn signals_for(&self, key: &str) -> Option<Signals> {
        let mut found: Option<Signals> = None;
        for (path, signals) in &self.configs {
            if key.starts_with(config_root(path)) {
                found
                    .get_or_insert_with(Signals::new)
                    .extend(signals.iter().map(|(k, v)| (k.clone(), *v)));
            }
        }
        found
    }

    /// The diagnostics of a file: syntax first, then the checks, in source
    /// order. Reuses the last result while neither the file nor its task's
    /// interface changed.
    pub fn diagnostics(&mut self, path: &str) -> Arc<Vec<Diagnostic>> {
        let Some(unit) = self.units.get(path).cloned() else {
            return Arc::default();
        };
        let task = self.task_of(path);
        if let Some(c) = self.checked.get(path)
            && Arc::ptr_eq(&c.unit, &unit)
            && c.interface == task.interface
        {
            return c.diagnostics.clone();
        }
        let diagnostics = Arc::new(diagnostics_of(&task, &unit));
        self.checked.insert(
            path.to_owned(),
            Checked {
                unit,
                interface: task.interface,
                diagnostics: diagnostics.clone(),
            },
        );
        diagnostics
    }
}

/// The diagnostics of one unit of a task, computed afresh: syntax, then
/// semantic, sorted by position.
pub fn diagnostics_of(task: &Task, unit: &Arc<Unit>) -> Vec<Diagnostic> {
    let mut out = unit.syntax.clone();
    if let Some(idx) = task.units.iter().position(|u| Arc::ptr_eq(u, unit)) {
        out.extend(crate::check::check_unit(task, idx));
    }
    out.sort_by_key(|d| (d.range.start, d.range.end));
    out
}

/// The folder an I/O configuration applies below: a backup's root for
/// `.../SYSPAR/EIO.cfg`, else the file's own folder.
fn config_root(path: &str) -> &str {
    let dir = path.rsplit_once(['/', '\\']).map_or("", |(d, _)| d);
    match dir.rsplit_once(['/', '\\']) {
        Some((parent, last)) if last.eq_ignore_ascii_case("syspar") => parent,
        None if dir.eq_ignore_ascii_case("syspar") => "",
        _ => dir,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn configuration_applies_below_its_root() {
        assert_eq!(config_root("b/SYSPAR/EIO.cfg"), "b");
        assert_eq!(config_root("proj/EIO.cfg"), "proj");
    }

    #[test]
    fn results_are_reused_until_the_task_interface_changes() {
        let mut ws = Workspace::new();
        ws.set_file(
            "p/A.mod",
            "MODULE A\n  PROC main()\n    helper;\n  ENDPROC\nENDMODULE\n".into(),
        );
        ws.set_file(
            "p/B.mod",
            "MODULE B\n  PROC helper()\n  ENDPROC\nENDMODULE\n".into(),
        );
        let first = ws.diagnostics("p/A.mod");
        assert!(first.is_empty(), "{first:?}");
        // An edit inside B's routine body keeps B's interface: A's result is reused.
        ws.set_file(
            "p/B.mod",
            "MODULE B\n  PROC helper()\n    Stop;\n  ENDPROC\nENDMODULE\n".into(),
        );
        assert!(Arc::ptr_eq(&first, &ws.diagnostics("p/A.mod")));
        // Renaming the routine changes the interface: A is checked again.
        ws.set_file(
            "p/B.mod",
            "MODULE B\n  PROC helper2()\n  ENDPROC\nENDMODULE\n".into(),
        );
        let again = ws.diagnostics("p/A.mod");
        assert_eq!(again.len(), 1, "{again:?}");
        assert_eq!(again[0].rule.name, "unresolved-name");
    }
}
