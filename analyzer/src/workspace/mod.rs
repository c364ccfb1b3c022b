//! The analysis host: every file of a workspace, grouped into tasks, with
//! cached results.
//!
//! Callers hand in texts (and `EIO.cfg` texts); the workspace parses them,
//! groups them into tasks ([`task_key`]), and checks files on request. A
//! file's check result is reused until the file itself or the interface of
//! its task (the declarations other modules see) changes, so typing inside a
//! routine re-checks only that file.

mod alternatives;
mod checks;
mod controller;
mod home;
#[cfg(test)]
mod tests;

pub use checks::{
    Check, CheckInputs, CheckResult, diagnostics_cached, diagnostics_of, diagnostics_selected,
};
pub use controller::{config_applies, config_root, settings_by_folder};

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use crate::controller::{
    ControllerInfo, ControllerOverride, is_controller_info_name, parse_controller_info,
};
use crate::layout::{Grouping, locate};
use crate::task::{Config, Task, Unit, controller_of, parse_config};
use controller::Controller;

#[derive(Default)]
pub struct Workspace {
    units: BTreeMap<String, Arc<Unit>>,
    /// What each configuration file declares, by the file's path.
    configs: BTreeMap<String, Config>,
    /// Each configuration file as read, by its path (for a run's
    /// `ReadCfgData`).
    cfg_files: BTreeMap<String, Arc<crate::cfg::CfgFile>>,
    tasks: HashMap<String, Arc<Task>>,
    /// Views of a task for its units that clash with others, by the task's
    /// key and the unit's path (see [`alternatives`]).
    views: HashMap<String, HashMap<String, Arc<Task>>>,
    /// Modules of a backup's `HOME/` that a task of the backup loads, and
    /// so belong to it ([`home`]).
    adoption: std::sync::Mutex<home::Adoption>,
    /// Module files that exist but could not be read (see
    /// [`Workspace::set_unreadable`]).
    unreadable: std::collections::BTreeSet<String>,
    /// The shared persistents of each controller (backup), by the
    /// controller's key ([`controller_of`]), with their hash.
    controllers: HashMap<String, Controller>,
    /// Each file's last check ([`checks`]).
    checked: HashMap<String, checks::Checked>,
    /// See [`Workspace::revision`].
    revision: u64,
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
    /// Modules that join every task whatever their place says (a
    /// project's extra paths): see [`Workspace::add_extra_unit`].
    extras: Vec<Arc<Unit>>,
    /// Configuration that applies to every task whatever its place says
    /// (a project's extra paths), in the order given.
    extra_configs: Vec<Config>,
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
        self.mark_backup(path);
        self.programs_changed();
    }

    pub fn remove_program(&mut self, path: &str) {
        if self.programs.remove(path).is_some() {
            self.mark_backup(path);
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
        self.forget_all_tasks();
    }

    /// Drops every cached task (their grouping or configuration changed).
    fn forget_all_tasks(&mut self) {
        self.revision += 1;
        self.tasks.clear();
        self.views.clear();
        self.members.clear();
    }

    /// Drops the cached task `key` and its views; returns the task.
    fn forget_task(&mut self, key: &str) -> Option<Arc<Task>> {
        self.views.remove(key);
        self.tasks.remove(key)
    }

    /// The key of the task a file belongs to: its program's, when a `.pgf`
    /// lists it, the task's of a backup that loads it from `HOME/`, else
    /// its place's ([`crate::layout::task_key`]).
    pub fn task_key(&self, path: &str) -> String {
        self.locate(path).0
    }

    /// [`Workspace::task_key`], and how the task's modules are grouped.
    fn locate(&self, path: &str) -> (String, Grouping) {
        match self.adopted_key(path) {
            Some(key) => (key, Grouping::Backup),
            None => self.locate_by_place(path),
        }
    }

    /// [`Workspace::locate`] by the file's place and the programs, leaving
    /// out what tasks load from `HOME/`.
    fn locate_by_place(&self, path: &str) -> (String, Grouping) {
        let (key, grouping) = locate(path);
        if self.programs.is_empty() || grouping == Grouping::Backup {
            return (key, grouping);
        }
        let folded = normalize(path);
        if let Some(pgf) = self.listed.get(&folded) {
            return (pgf.clone(), Grouping::Program);
        }
        if folded.ends_with(".sys") || folded.ends_with(".sysx") {
            let dir = folded.rsplit_once('/').map_or("", |(d, _)| d);
            if let Some(pgf) = self
                .programs
                .keys()
                .find(|p| normalize(p).rsplit_once('/').map_or("", |(d, _)| d) == dir)
            {
                return (pgf.clone(), Grouping::Program);
            }
        }
        (key, grouping)
    }

    /// Adds or replaces a file, parsing it from scratch.
    pub fn set_file(&mut self, path: &str, text: String) {
        self.set_unit(Unit::new(path.to_owned(), text, None));
    }

    /// Adds or replaces a file parsed by the caller (e.g. incrementally).
    /// Returns whether what the other files' checks read of it changed (its
    /// interface or constants, or it is new): whether they are to be
    /// checked again.
    pub fn set_unit(&mut self, unit: Unit) -> bool {
        self.set_shared_unit(Arc::new(unit))
    }

    /// [`Workspace::set_unit`] of a unit shared with other workspaces (a
    /// module of the extra paths, parsed once for every part of a
    /// project).
    pub fn set_shared_unit(&mut self, unit: Arc<Unit>) -> bool {
        // Which HOME/ modules the backup's tasks load may change with what
        // the unit loads or which modules it holds.
        let moved = self.units.get(&unit.path).is_none_or(|old| {
            old.loads != unit.loads || !same_modules(&old.items.modules, &unit.items.modules)
        });
        if moved {
            self.mark_backup(&unit.path);
        }
        // The key as grouped so far (a new adoption drops every task).
        let key = self.key_so_far(&unit.path);
        // The same file replaced: the task keeps its members.
        let mut members = match self.forget_task(&key) {
            Some(task) => Some(task.units.to_vec()),
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
        let seen = old.is_none_or(|o| o.interface != interface || o.constants != constants);
        if seen {
            self.forget_sibling_tasks(&key);
        }
        seen
    }

    /// Adds or replaces many units ([`Workspace::set_unit`] of each; which
    /// `HOME/` modules the tasks load is worked out when first asked).
    pub fn set_units(&mut self, units: impl IntoIterator<Item = Unit>) {
        for unit in units {
            self.set_unit(unit);
        }
    }

    /// [`Workspace::task_key`] without working out the adoption of
    /// `HOME/` modules again (for invalidation while files are set: when
    /// the adoption changes, [`Workspace::settle`] drops every task).
    fn key_so_far(&mut self, path: &str) -> String {
        match self.adopted_so_far(path) {
            Some(key) => key,
            None => self.locate_by_place(path).0,
        }
    }

    /// Makes `unit` a member of every task besides the modules their
    /// places group there: a module of a project's extra paths (a library
    /// the program's tasks load from elsewhere). The unit keeps its own
    /// path, by which related locations name it, and it is not one of the
    /// files [`Workspace::checks`] and [`Workspace::diagnostics`] check.
    pub fn add_extra_unit(&mut self, unit: Arc<Unit>) {
        self.extras.push(unit);
        self.forget_all_tasks();
        self.controllers.clear();
    }

    /// Makes the configuration `text` (`EIO.cfg` signals, `MOC.cfg`
    /// mechanical units) apply to every task besides what applies by place
    /// (a project's extra paths). A task's own configuration wins where
    /// both declare a signal.
    pub fn add_extra_config(&mut self, text: &str) {
        self.add_parsed_extra_config(parse_config(text));
    }

    /// [`Workspace::add_extra_config`] of a configuration read already.
    pub fn add_parsed_extra_config(&mut self, config: Config) {
        self.extra_configs.push(config);
        self.forget_all_tasks();
    }

    /// Forgets the modules and configuration of the extra paths.
    pub fn clear_extras(&mut self) {
        if !self.extras.is_empty() || !self.extra_configs.is_empty() {
            self.extras.clear();
            self.extra_configs.clear();
            self.forget_all_tasks();
            self.controllers.clear();
        }
    }

    pub fn remove_file(&mut self, path: &str) {
        if self.units.remove(path).is_some() {
            let key = self.key_so_far(path);
            self.forget_task(&key);
            self.members.remove(&key);
            self.forget_sibling_tasks(&key);
            self.checked.remove(path);
            self.mark_backup(path);
        }
    }

    /// Drops the other tasks of `key`'s controller, which hold its
    /// persistents in [`Task::shared`].
    fn forget_sibling_tasks(&mut self, key: &str) {
        if let Some(controller) = controller_of(key) {
            self.tasks.retain(|k, _| !k.starts_with(controller));
            self.views.retain(|k, _| !k.starts_with(controller));
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
            let file = crate::cfg::parse(text);
            self.configs
                .insert(path.to_owned(), crate::task::config_of(&file));
            self.cfg_files.insert(path.to_owned(), Arc::new(file));
        }
        self.forget_all_tasks();
        self.mark_backup(path);
    }

    /// Sets the controller of the project configuration (`[controller]` of
    /// `rapid.toml` or the editor's settings); each key it sets wins over
    /// what a backup says.
    pub fn set_controller(&mut self, controller: ControllerOverride) {
        if self.controller != controller {
            self.controller = controller;
            self.forget_all_tasks();
        }
    }

    pub fn remove_config(&mut self, path: &str) {
        if self.systems.remove(path).is_some() {
            self.forget_all_tasks();
            self.mark_backup(path);
        }
        self.cfg_files.remove(path);
        if self.configs.remove(path).is_some() {
            self.forget_all_tasks();
            self.mark_backup(path);
        }
    }

    /// Records a module file that exists but could not be read (encrypted,
    /// binary, unreadable): its task is then known to be incomplete, and
    /// names nothing declares are not errors there.
    pub fn set_unreadable(&mut self, path: &str) {
        if self.unreadable.insert(path.to_owned()) {
            self.forget_all_tasks();
        }
    }

    pub fn remove_unreadable(&mut self, path: &str) {
        if self.unreadable.remove(path) {
            self.forget_all_tasks();
        }
    }

    /// Is `unit` the workspace's file of its path (not an extra unit)?
    fn is_own(&self, unit: &Arc<Unit>) -> bool {
        self.units
            .get(&unit.path)
            .is_some_and(|u| Arc::ptr_eq(u, unit))
    }

    pub fn unit(&self, path: &str) -> Option<&Arc<Unit>> {
        self.units.get(path)
    }

    pub fn paths(&self) -> impl Iterator<Item = &str> {
        self.units.keys().map(String::as_str)
    }

    /// The task a file is checked in (built on demand and cached): its
    /// group, or the view of its group made for it when it clashes with
    /// other modules of the group ([`alternatives`]).
    pub fn task_of(&mut self, path: &str) -> Arc<Task> {
        self.settle();
        let group = self.group_of(path);
        let Some(idx) = group.units.iter().position(|u| u.path == path) else {
            return group;
        };
        if group.owns(idx) {
            return group;
        }
        if let Some(view) = self.views.get(&group.key).and_then(|v| v.get(path)) {
            return view.clone();
        }
        let view = Arc::new(group.view(idx));
        self.views
            .entry(group.key.clone())
            .or_default()
            .insert(path.to_owned(), view.clone());
        view
    }

    /// The whole group of modules a file belongs to (built on demand and
    /// cached).
    fn group_of(&mut self, path: &str) -> Arc<Task> {
        self.settle();
        let key = self.task_key(path);
        if let Some(t) = self.tasks.get(&key) {
            return t.clone();
        }
        if let Some(units) = self.members.remove(&key) {
            return self.build_task(key, units);
        }
        // A file is in the task by its place (the key is then a folder of
        // its path), by a program that lists it (the key is the program's
        // path) or adopted by it: `task_key`, which costs microseconds, is
        // worked out only for the files that can be (in ten thousand files,
        // a task of twelve was built in 40 ms; issue 27).
        let program = self.programs.contains_key(&key);
        let adopted = self.adopted_by(&key);
        let mut units: Vec<Arc<Unit>> = self
            .units
            .values()
            .filter(|u| {
                program || adopted.contains(&u.path) || home::starts_with_path(&u.path, &key)
            })
            .filter(|u| self.task_key(&u.path) == key)
            .cloned()
            .collect();
        units.extend(self.borrowed_units(&key));
        units.extend(self.extras.iter().cloned());
        self.build_task(key, units)
    }

    /// The modules task `key` loads from `HOME/` that are checked in
    /// another task ([`home`]): members it does not check.
    fn borrowed_units(&self, key: &str) -> Vec<Arc<Unit>> {
        self.borrowed_by(key)
            .iter()
            .filter_map(|p| self.units.get(p).cloned())
            .collect()
    }

    /// Builds and caches the group task `key` of `units`.
    fn build_task(&mut self, key: String, units: Vec<Arc<Unit>>) -> Arc<Task> {
        let grouping = match units.first() {
            Some(u) if self.units.contains_key(&u.path) => self.locate(&u.path).1,
            // Only extra units: nothing places the task.
            _ => Grouping::Folder,
        };
        let mut task = self.make_task(key.clone(), units, grouping);
        task.clashes = Arc::new(alternatives::clashes(&task.units, grouping));
        let task = Arc::new(task);
        self.tasks.insert(key, task.clone());
        task
    }

    /// A task of `units` under `key`, with its configuration and the
    /// persistents its controller shares.
    fn make_task(&mut self, key: String, units: Vec<Arc<Unit>>, grouping: Grouping) -> Task {
        let (signals, mecunits) = self.config_for(&key);
        let complete = grouping == Grouping::Backup && self.is_complete(&key);
        let loaded_elsewhere = grouping == Grouping::Folder
            && !units.is_empty()
            && units.iter().all(|u| crate::layout::in_home(&u.path));
        let mut task = Task::new(key.clone(), units, signals);
        task.grouping = grouping;
        task.complete = complete;
        task.loaded_elsewhere = loaded_elsewhere;
        let controller = self.controller_of_task(&key);
        task.set_catalogue(&crate::catalogue::Selection::new(
            controller.robotware,
            controller.options,
        ));
        task.set_controller_names(mecunits, self.task_ids_for(&key));
        task.set_robot(self.robot_for(&key));
        if let Some(controller) = controller_of(&key).filter(|_| grouping == Grouping::Backup) {
            let c = match self.controllers.get(controller) {
                Some(c) => c.clone(),
                None => {
                    let c = self.controller_data(controller);
                    self.controllers.insert(controller.to_owned(), c.clone());
                    c
                }
            };
            task.set_shared(c.shared, c.shared_hash);
            task.set_syncs(c.syncs, c.syncs_hash);
        }
        task
    }

    /// Every unit of the workspace with the task it is checked in (its
    /// group, or its own view of the group: [`Workspace::task_of`]), in
    /// the order of the groups.
    pub fn checks(&mut self) -> Vec<(Arc<Task>, Arc<Unit>)> {
        let mut out = Vec::with_capacity(self.units.len());
        for group in self.tasks() {
            for (i, unit) in group.units.iter().enumerate() {
                if !self.is_own(unit) || self.task_key(&unit.path) != group.key {
                    // An extra unit, or one checked in another task.
                    continue;
                }
                if group.owns(i) {
                    out.push((group.clone(), unit.clone()));
                } else {
                    out.push((self.task_of(&unit.path), unit.clone()));
                }
            }
        }
        out
    }

    /// Every task of the workspace: each group of modules (a unit that
    /// clashes with others of its group is checked in a view of its own,
    /// see [`Workspace::checks`]).
    pub fn tasks(&mut self) -> Vec<Arc<Task>> {
        self.settle();
        // Group the units once (asking `task_of` per task would compute
        // every unit's key again for each task).
        let mut groups: BTreeMap<String, Vec<Arc<Unit>>> = BTreeMap::new();
        for unit in self.units.values() {
            groups
                .entry(self.task_key(&unit.path))
                .or_default()
                .push(unit.clone());
        }
        for (key, units) in groups.iter_mut() {
            units.extend(self.borrowed_units(key));
            units.extend(self.extras.iter().cloned());
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
}

/// Do two files hold modules of the same names, in order?
fn same_modules(a: &[crate::items::Module], b: &[crate::items::Module]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.name == y.name)
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

/// A path with `/` separators, `.` and `..` resolved, folded.
fn normalize(path: &str) -> String {
    resolve_dots(path).to_ascii_lowercase()
}

/// A path with `/` separators, `.` and `..` resolved.
fn resolve_dots(path: &str) -> String {
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
    parts.join("/")
}

/// The folded paths of the modules a program file lists, resolved against
/// the program file's folder.
fn parse_program(path: &str, xml: &str) -> Vec<String> {
    program_modules(path, xml)
        .iter()
        .map(|m| m.to_ascii_lowercase())
        .collect()
}

/// The paths of the modules a program file (`.pgf`) lists, resolved
/// against the program file's folder (with `/` separators, in the case the
/// program writes them), for a loader to read them. Reads
/// `<Module>...</Module>` elements (any case); anything else in the XML is
/// ignored.
pub fn program_modules(path: &str, xml: &str) -> Vec<String> {
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
            out.push(resolve_dots(&full));
        }
        at = start + len;
    }
    out
}
