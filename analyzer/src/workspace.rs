//! The analysis host: every file of a workspace, grouped into tasks, with
//! cached results.
//!
//! Callers hand in texts (and `EIO.cfg` texts); the workspace parses them,
//! groups them into tasks ([`task_key`]), and checks files on request. A
//! file's check result is reused until the file itself or the interface of
//! its task (the declarations other modules see) changes, so typing inside a
//! routine re-checks only that file.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::sync::Arc;

use crate::check::StmtCache;
use crate::controller::{
    ControllerInfo, ControllerOverride, is_controller_info_name, parse_controller_info,
};
use crate::diagnostic::Diagnostic;
use crate::task::{
    Config, SharedMap, Signals, Task, Unit, controller_of, parse_config, shared_persistents,
    task_key,
};

#[derive(Default)]
pub struct Workspace {
    units: BTreeMap<String, Arc<Unit>>,
    /// What each configuration file declares, by the file's path.
    configs: BTreeMap<String, Config>,
    tasks: HashMap<String, Arc<Task>>,
    /// The shared persistents of each controller (backup), by the
    /// controller's key ([`controller_of`]), with their hash.
    controllers: HashMap<String, (Arc<SharedMap>, u64)>,
    checked: HashMap<String, Checked>,
    /// Program files (`.pgf`): the pgf's path to the folded paths of the
    /// modules it lists.
    programs: BTreeMap<String, Vec<String>>,
    /// Folded module path to the program that lists it (derived from
    /// `programs`).
    listed: HashMap<String, String>,
    /// The units of a task whose cached [`Task`] was dropped because one of
    /// its files was replaced, in the task's order: rebuilding it needs no
    /// search for its members (their set did not change).
    members: HashMap<String, Vec<Arc<Unit>>>,
    /// What backups say about their controllers (`BACKINFO`), by file path.
    systems: BTreeMap<String, ControllerInfo>,
    /// The controller as the project configuration describes it.
    controller: ControllerOverride,
}

struct Checked {
    unit: Arc<Unit>,
    interface: u64,
    diagnostics: Arc<Vec<Diagnostic>>,
    /// Statement results, for the next check of this file.
    statements: StmtCache,
}

impl Workspace {
    pub fn new() -> Workspace {
        Workspace::default()
    }

    /// Adds or replaces a program file (`.pgf`, XML listing the modules of a
    /// program, `<Module>Main.mod</Module>`, relative to the pgf's folder).
    /// The listed modules, with the system modules (`.sys`) of the pgf's
    /// folder that no program lists, form one task named by the pgf's path
    /// (outside a backup's `RAPID/TASKn`, whose folders fix the tasks).
    pub fn set_program(&mut self, path: &str, xml: &str) {
        let modules = parse_program(path, xml);
        self.programs.insert(path.to_owned(), modules);
        self.programs_changed();
    }

    pub fn remove_program(&mut self, path: &str) {
        if self.programs.remove(path).is_some() {
            self.programs_changed();
        }
    }

    fn programs_changed(&mut self) {
        self.listed.clear();
        for (pgf, modules) in &self.programs {
            for m in modules {
                self.listed.entry(m.clone()).or_insert_with(|| pgf.clone());
            }
        }
        self.tasks.clear();
        self.members.clear();
    }

    /// The key of the task a file belongs to: its program's, when a `.pgf`
    /// lists it, else [`task_key`].
    pub fn task_key(&self, path: &str) -> String {
        let key = task_key(path);
        if self.programs.is_empty() || is_backup_key(&key) {
            return key;
        }
        let folded = normalize(path);
        if let Some(pgf) = self.listed.get(&folded) {
            return pgf.clone();
        }
        if folded.ends_with(".sys") || folded.ends_with(".sysx") {
            let dir = folded.rsplit_once('/').map_or("", |(d, _)| d);
            if let Some(pgf) = self
                .programs
                .keys()
                .find(|p| normalize(p).rsplit_once('/').map_or("", |(d, _)| d) == dir)
            {
                return pgf.clone();
            }
        }
        key
    }

    /// Adds or replaces a file, parsing it from scratch.
    pub fn set_file(&mut self, path: &str, text: String) {
        self.set_unit(Unit::new(path.to_owned(), text, None));
    }

    /// Adds or replaces a file parsed by the caller (e.g. incrementally).
    pub fn set_unit(&mut self, unit: Unit) {
        let key = self.task_key(&unit.path);
        let unit = Arc::new(unit);
        // The same file replaced: the task keeps its members.
        let mut members = match self.tasks.remove(&key) {
            Some(task) => Some(task.units.clone()),
            None => self.members.remove(&key),
        };
        match members
            .as_mut()
            .and_then(|m| m.iter_mut().find(|u| u.path == unit.path))
        {
            Some(slot) => *slot = unit.clone(),
            None => members = None,
        }
        if let Some(members) = members {
            self.members.insert(key.clone(), members);
        }
        let (interface, constants) = (unit.interface, unit.constants);
        let old = self.units.insert(unit.path.clone(), unit);
        // Array sizes are in `constants`, not in the interface.
        if old.is_none_or(|o| o.interface != interface || o.constants != constants) {
            self.forget_sibling_tasks(&key);
        }
    }

    pub fn remove_file(&mut self, path: &str) {
        if self.units.remove(path).is_some() {
            let key = self.task_key(path);
            self.tasks.remove(&key);
            self.members.remove(&key);
            self.forget_sibling_tasks(&key);
            self.checked.remove(path);
        }
    }

    /// Drops the other tasks of `key`'s controller, which hold its
    /// persistents in [`Task::shared`].
    fn forget_sibling_tasks(&mut self, key: &str) {
        if let Some(controller) = controller_of(key) {
            self.tasks.retain(|k, _| !k.starts_with(controller));
            self.controllers.remove(controller);
        }
    }

    /// Adds or replaces a controller configuration file: `EIO.cfg` (I/O
    /// signals) or `MOC.cfg` (mechanical units); other `.cfg` files are read
    /// for the same sections. It applies to the tasks below its folder (below
    /// the backup for `SYSPAR/*.cfg`).
    /// `BACKINFO/backinfo.txt` and `BACKINFO/system.xml` name the RobotWare
    /// version and options of the backup's controller.
    pub fn set_config(&mut self, path: &str, text: &str) {
        if is_controller_info_name(path) {
            let info = parse_controller_info(path, text, crate::catalogue::base());
            self.systems.insert(path.to_owned(), info);
        } else {
            self.configs.insert(path.to_owned(), parse_config(text));
        }
        self.tasks.clear();
        self.members.clear();
    }

    /// Sets the controller of the project configuration (`[controller]` of
    /// `rapid.toml` or the editor's settings); each key it sets wins over
    /// what a backup says.
    pub fn set_controller(&mut self, controller: ControllerOverride) {
        if self.controller != controller {
            self.controller = controller;
            self.tasks.clear();
            self.members.clear();
        }
    }

    /// What the backups and the project configuration say about the
    /// controller of the task `key`.
    pub fn controller_of_task(&self, key: &str) -> ControllerInfo {
        let mut info = ControllerInfo::default();
        for (path, system) in &self.systems {
            if key.starts_with(config_root(path)) {
                info.merge(system);
            }
        }
        let sel = info.selection(&self.controller);
        ControllerInfo {
            robotware: sel.robotware,
            options: sel.options().to_vec(),
        }
    }

    pub fn remove_config(&mut self, path: &str) {
        if self.systems.remove(path).is_some() {
            self.tasks.clear();
            self.members.clear();
        }
        if self.configs.remove(path).is_some() {
            self.tasks.clear();
            self.members.clear();
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
        let key = self.task_key(path);
        if let Some(t) = self.tasks.get(&key) {
            return t.clone();
        }
        if let Some(units) = self.members.remove(&key) {
            return self.build_task(key, units);
        }
        let units: Vec<Arc<Unit>> = self
            .units
            .values()
            .filter(|u| self.task_key(&u.path) == key)
            .cloned()
            .collect();
        self.build_task(key, units)
    }

    /// Builds and caches the task `key` of `units`.
    fn build_task(&mut self, key: String, units: Vec<Arc<Unit>>) -> Arc<Task> {
        let (signals, mecunits) = self.config_for(&key);
        // Results depend on the configuration too: the interface covers it,
        // so cached file and statement results are dropped when it changes.
        let config = config_hash(signals.as_ref(), &mecunits);
        let mut task = Task::new(key.clone(), units, signals);
        let controller = self.controller_of_task(&key);
        task.set_catalogue(&crate::catalogue::Selection::new(
            controller.robotware,
            controller.options,
        ));
        task.mecunits = mecunits;
        task.interface ^= config;
        if let Some(controller) = controller_of(&key) {
            let (shared, hash) = match self.controllers.get(controller) {
                Some(c) => c.clone(),
                None => {
                    let (map, hash) = shared_persistents(
                        self.units.values().filter(|u| under(&u.path, controller)),
                    );
                    let c = (Arc::new(map), hash);
                    self.controllers.insert(controller.to_owned(), c.clone());
                    c
                }
            };
            task.set_shared(shared, hash);
        }
        let task = Arc::new(task);
        self.tasks.insert(key, task.clone());
        task
    }

    /// Every task of the workspace.
    pub fn tasks(&mut self) -> Vec<Arc<Task>> {
        // Group the units once (asking `task_of` per task would compute
        // every unit's key again for each task).
        let mut groups: BTreeMap<String, Vec<Arc<Unit>>> = BTreeMap::new();
        for unit in self.units.values() {
            groups
                .entry(self.task_key(&unit.path))
                .or_default()
                .push(unit.clone());
        }
        groups
            .into_iter()
            .map(|(key, units)| match self.tasks.get(&key) {
                Some(task) => task.clone(),
                None => {
                    self.members.remove(&key);
                    self.build_task(key, units)
                }
            })
            .collect()
    }

    /// The configuration that applies to a task: its signals (`None` when
    /// no configuration declares signals) and its mechanical units.
    fn config_for(&self, key: &str) -> (Option<Signals>, HashSet<String>) {
        let mut signals: Option<Signals> = None;
        let mut mecunits = HashSet::new();
        for (path, config) in &self.configs {
            if key.starts_with(config_root(path)) {
                if let Some(s) = &config.signals {
                    signals
                        .get_or_insert_with(Signals::new)
                        .extend(s.iter().map(|(k, v)| (k.clone(), *v)));
                }
                mecunits.extend(config.mecunits.iter().cloned());
            }
        }
        (signals, mecunits)
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
        let cache = self
            .checked
            .remove(path)
            .map(|c| c.statements)
            .unwrap_or_default();
        let (diagnostics, statements) = diagnostics_cached(&task, &unit, cache);
        let diagnostics = Arc::new(diagnostics);
        self.checked.insert(
            path.to_owned(),
            Checked {
                unit,
                interface: task.interface,
                diagnostics: diagnostics.clone(),
                statements,
            },
        );
        diagnostics
    }
}

/// The diagnostics of one unit of a task, computed afresh: syntax, then
/// semantic, sorted by position.
pub fn diagnostics_of(task: &Task, unit: &Arc<Unit>) -> Vec<Diagnostic> {
    diagnostics_cached(task, unit, StmtCache::default()).0
}

/// [`diagnostics_of`], reusing the statement results of an earlier check of
/// the same file; returns them for the next check.
pub fn diagnostics_cached(
    task: &Task,
    unit: &Arc<Unit>,
    cache: StmtCache,
) -> (Vec<Diagnostic>, StmtCache) {
    let mut out = unit.syntax.clone();
    let mut next = StmtCache::default();
    if let Some(idx) = task.units.iter().position(|u| Arc::ptr_eq(u, unit)) {
        let (found, cache) = crate::check::check_unit_cached(task, idx, cache);
        out.extend(found);
        next = cache;
    }
    out.sort_by_key(|d| (d.range.start, d.range.end));
    (out, next)
}

/// A hash of a task's configuration (signals with their types, mechanical
/// units), independent of the maps' order.
fn config_hash(signals: Option<&Signals>, mecunits: &HashSet<String>) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::hash::DefaultHasher::new();
    if let Some(signals) = signals {
        let mut list: Vec<_> = signals.iter().collect();
        list.sort();
        list.hash(&mut h);
    }
    let mut units: Vec<_> = mecunits.iter().collect();
    units.sort();
    units.hash(&mut h);
    h.finish()
}

/// Is `path` below `folder` (a normalised prefix ending in `/`), with either
/// separator?
fn under(path: &str, folder: &str) -> bool {
    path.len() > folder.len()
        && path
            .bytes()
            .zip(folder.bytes())
            .all(|(a, b)| a == b || (a == b'\\' && b == b'/'))
}

/// Is this the key of a backup's `RAPID/TASKn` folder?
fn is_backup_key(key: &str) -> bool {
    let lower = key.to_ascii_lowercase();
    lower.contains("rapid/task")
}

/// A path with `/` separators, `.` and `..` resolved, folded.
fn normalize(path: &str) -> String {
    let mut parts: Vec<&str> = Vec::new();
    let unified = path.replace('\\', "/");
    for p in unified.split('/') {
        match p {
            "." | "" if !parts.is_empty() => {}
            ".." if parts.last().is_some_and(|l| *l != "..") => {
                parts.pop();
            }
            _ => parts.push(p),
        }
    }
    parts.join("/").to_ascii_lowercase()
}

/// The folded paths of the modules a program file lists, resolved against
/// the program file's folder. Reads `<Module>...</Module>` elements (any
/// case); anything else in the XML is ignored.
fn parse_program(path: &str, xml: &str) -> Vec<String> {
    let dir = path
        .replace('\\', "/")
        .rsplit_once('/')
        .map_or(String::new(), |(d, _)| d.to_owned());
    let lower = xml.to_ascii_lowercase();
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(open) = lower.get(at..).and_then(|s| s.find("<module>")) {
        let start = at + open + "<module>".len();
        let Some(len) = lower.get(start..).and_then(|s| s.find("</module>")) else {
            break;
        };
        let name = xml.get(start..start + len).unwrap_or_default().trim();
        if !name.is_empty() {
            let full = if dir.is_empty() {
                name.to_owned()
            } else {
                format!("{dir}/{name}")
            };
            out.push(normalize(&full));
        }
        at = start + len;
    }
    out
}

/// The folder an I/O configuration applies below: a backup's root for
/// `.../SYSPAR/EIO.cfg`, else the file's own folder.
fn config_root(path: &str) -> &str {
    let dir = path.rsplit_once(['/', '\\']).map_or("", |(d, _)| d);
    match dir.rsplit_once(['/', '\\']) {
        Some((parent, last))
            if last.eq_ignore_ascii_case("syspar") || last.eq_ignore_ascii_case("backinfo") =>
        {
            parent
        }
        None if dir.eq_ignore_ascii_case("syspar") || dir.eq_ignore_ascii_case("backinfo") => "",
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
    fn an_edit_in_one_routine_rechecks_only_its_changed_statements() {
        let mut body = String::new();
        for i in 0..200 {
            body.push_str(&format!("    n := n + {i};\n    WaitTime 0.{i};\n"));
        }
        let text = format!(
            "MODULE A\n  VAR num n;\n  PROC main()\n{body}  ENDPROC\n  PROC other()\n    n := 1;\n  ENDPROC\nENDMODULE\n"
        );
        let mut ws = Workspace::new();
        ws.set_file("p/A.mod", text.clone());
        ws.set_file(
            "p/B.mod",
            "MODULE B\n  PROC helper()\n  ENDPROC\nENDMODULE\n".into(),
        );
        assert!(ws.diagnostics("p/A.mod").is_empty());
        let b = ws.diagnostics("p/B.mod");
        // One character changed in one statement of main.
        let edited = text.replacen("n := n + 7;", "n := n + 1000;", 1);
        ws.set_file("p/A.mod", edited);
        assert!(ws.diagnostics("p/A.mod").is_empty());
        let cache = &ws.checked["p/A.mod"].statements;
        assert_eq!(cache.reused(), 400, "every other statement is reused");
        // The other module's result is not recomputed at all.
        assert!(Arc::ptr_eq(&b, &ws.diagnostics("p/B.mod")));
    }

    /// Compound statements are cached whole unless a GOTO inside depends on
    /// the routine's labels, which the cache key leaves out.
    #[test]
    fn a_goto_inside_a_compound_statement_follows_the_labels() {
        let text = |label: &str| {
            format!(
                "MODULE A\n  VAR num n;\n  PROC main()\n    {label}:\n    n := 1;\n    IF n > 0 THEN\n      n := 2;\n      GOTO again;\n    ENDIF\n  ENDPROC\nENDMODULE\n"
            )
        };
        let mut ws = Workspace::new();
        ws.set_file("p/A.mod", text("again"));
        assert!(ws.diagnostics("p/A.mod").is_empty());
        ws.set_file("p/A.mod", text("other"));
        let found = ws.diagnostics("p/A.mod");
        assert!(
            found.iter().any(|d| d.rule.name == "unknown-label"),
            "{found:?}"
        );
        let unit = ws.unit("p/A.mod").cloned().expect("the file");
        let task = ws.task_of("p/A.mod");
        assert_eq!(*found, diagnostics_of(&task, &unit));
    }

    /// An edit elsewhere leaves a compound statement's result cached, and the
    /// workspace rebuilds the task from its known members.
    #[test]
    fn compound_statements_are_reused_whole() {
        let mut body = String::new();
        for i in 0..50 {
            body.push_str(&format!(
                "    IF n > {i} THEN\n      n := {i};\n    ENDIF\n"
            ));
        }
        let text = format!("MODULE A\n  VAR num n;\n  PROC main()\n{body}  ENDPROC\nENDMODULE\n");
        let mut ws = Workspace::new();
        ws.set_file("p/A.mod", text.clone());
        ws.set_file("p/B.mod", "MODULE B\nENDMODULE\n".into());
        assert!(ws.diagnostics("p/A.mod").is_empty());
        ws.set_file("p/A.mod", text.replacen("n := 7;", "n := 8;", 1));
        assert!(ws.members.contains_key("p"), "the task's members are kept");
        assert!(ws.diagnostics("p/A.mod").is_empty());
        assert_eq!(ws.task_of("p/A.mod").units.len(), 2);
        // The 49 other IF statements, whole.
        assert_eq!(ws.checked["p/A.mod"].statements.reused(), 49);
    }

    #[test]
    fn a_persistent_changed_in_one_task_rechecks_the_other_tasks() {
        let module = |ty: &str| format!("MODULE M\n  PERS {ty} shared := 0;\nENDMODULE\n");
        let mut ws = Workspace::new();
        ws.set_file("b/RAPID/TASK1/PROGMOD/M.mod", module("num"));
        ws.set_file("b/RAPID/TASK2/PROGMOD/M.mod", module("num"));
        assert!(ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod").is_empty());
        ws.set_file("b/RAPID/TASK2/PROGMOD/M.mod", module("dnum"));
        let found = ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod");
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].rule.name, "shared-persistent-mismatch");
        let related = &found[0].related[0];
        assert_eq!(related.file.as_deref(), Some("b/RAPID/TASK2/PROGMOD/M.mod"));
        ws.remove_file("b/RAPID/TASK2/PROGMOD/M.mod");
        assert!(ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod").is_empty());
    }

    #[test]
    fn a_configuration_change_rechecks_the_files_it_applies_to() {
        let mut ws = Workspace::new();
        ws.set_file(
            "cell/M.mod",
            "MODULE M\n  PROC main()\n    SetDO doGrip, 1;\n  ENDPROC\nENDMODULE\n".into(),
        );
        ws.set_config(
            "cell/EIO.cfg",
            "EIO_SIGNAL:\n  -Name \"doOther\" -SignalType \"DO\"\n",
        );
        let first = ws.diagnostics("cell/M.mod");
        assert_eq!(first.len(), 1, "{first:?}");
        assert_eq!(first[0].rule.name, "unresolved-name");
        ws.set_config(
            "cell/EIO.cfg",
            "EIO_SIGNAL:\n  -Name \"doGrip\" -SignalType \"DO\"\n",
        );
        let again = ws.diagnostics("cell/M.mod");
        assert!(again.is_empty(), "{again:?}");
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
