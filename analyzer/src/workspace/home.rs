//! What a controller backup says about its tasks beyond their folders:
//! which modules of its `HOME/` folder a task loads, and whether a task is
//! complete.
//!
//! A module of a backup's `HOME/` joins a task of the same backup when the
//! task loads it:
//! - a `Load` or `StartLoad` of the task names its file with a literal or
//!   a constant ([`crate::loads`]; modules it brings load others in turn);
//! - `SYS.cfg` has the controller load it into the task (`-Task`, or every
//!   task with `-AllTask`);
//! - it sits in a `HOME/` folder named after the task (`HOME/T_ROB1/`,
//!   where a program saved from the task goes), or a `.pgf` program there
//!   lists it.
//!
//! A module that the task already holds a module of the same name of is
//! that module's file on `HOME:` (the original `SYS.cfg` loads, a program
//! saved from the task), not a second module: it does not join. A module
//! several tasks load joins the first (by key), and the others see its
//! declarations without checking it again. Modules that no task loads are
//! checked by their folder, as modules loaded into a task that is not
//! here.
//!
//! Only the backup's own files count: a backup kept inside another's
//! `HOME/` is a backup of its own, and the modules, configuration and
//! programs of one backup never decide another's tasks.

use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};
use std::sync::Arc;

use super::{Workspace, normalize};
use crate::layout::{Grouping, backup_root, home_root, is_within, locate};
pub(super) use crate::layout::{backinfo_root, owner_backup, syspar_root};
use crate::names::fold;
use crate::task::{Config, TaskModule, Unit};

/// Which `HOME/` modules the tasks of each backup load, worked out again
/// for a backup when its files change ([`Workspace::settle`]).
#[derive(Debug, Default)]
pub(super) struct Adoption {
    /// Backups (their folders) whose files changed since.
    dirty: BTreeSet<String>,
    /// Per backup: each `HOME/` module that a task loads, with the keys of
    /// the tasks that load it (the one it is checked in first).
    by_root: HashMap<String, BTreeMap<String, Vec<String>>>,
    /// Each adopted module's task (derived from `by_root`).
    primary: HashMap<String, String>,
    /// Per task key, the modules it loads that are checked in another task
    /// (derived from `by_root`).
    borrowed: HashMap<String, Vec<String>>,
    /// The backups whose adoption changed since the tasks were last built.
    changed: BTreeSet<String>,
}

impl Workspace {
    /// Notes that a file of the backup around `path` (a module, its
    /// configuration or a program) came, went or changed: the backup's
    /// adoption is worked out again when next asked.
    pub(super) fn mark_backup(&mut self, path: &str) {
        if let Some(root) = owner_backup(path) {
            self.adoption_mut().dirty.insert(root.to_owned());
        }
    }

    fn adoption_mut(&mut self) -> &mut Adoption {
        self.adoption
            .get_mut()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// The task that adopted the `HOME/` module `path`, if any.
    pub(super) fn adopted_key(&self, path: &str) -> Option<String> {
        let a = self.adoption();
        a.primary.get(path).cloned()
    }

    /// The `HOME/` modules checked in the task `key` ([`Workspace::adopted_key`]).
    pub(super) fn adopted_by(&self, key: &str) -> HashSet<String> {
        let a = self.adoption();
        a.primary
            .iter()
            .filter(|(_, k)| *k == key)
            .map(|(p, _)| p.clone())
            .collect()
    }

    /// [`Workspace::adopted_key`] as last worked out, without working it
    /// out again.
    pub(super) fn adopted_so_far(&mut self, path: &str) -> Option<String> {
        self.adoption_mut().primary.get(path).cloned()
    }

    /// The modules task `key` loads that are checked in another task.
    pub(super) fn borrowed_by(&self, key: &str) -> Vec<String> {
        let a = self.adoption();
        a.borrowed.get(key).cloned().unwrap_or_default()
    }

    /// The adoption, worked out for the backups whose files changed.
    fn adoption(&self) -> std::sync::MutexGuard<'_, Adoption> {
        let mut a = self
            .adoption
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if !a.dirty.is_empty() {
            self.recompute(&mut a);
        }
        a
    }

    /// Works out the adoption of the backups that changed and drops the
    /// cached tasks that were built with another adoption: those of the
    /// backups whose adoption changed (a backup's modules never join
    /// another's tasks), not every task of the workspace. While a large
    /// workspace is read, backups change all the time; the task of the
    /// file being edited is built again only when its own backup changes.
    pub(super) fn settle(&mut self) {
        let mut a = std::mem::take(self.adoption_mut());
        if !a.dirty.is_empty() {
            self.recompute(&mut a);
        }
        let changed = std::mem::take(&mut a.changed);
        *self.adoption_mut() = a;
        if !changed.is_empty() {
            self.forget_tasks_within(&changed);
        }
    }

    /// Drops the cached tasks of the backups (folders) `roots`: those whose
    /// key is within one of them, any other that holds a module of one of
    /// them, and the programs' (a `.pgf` may list a module of another
    /// folder, which joins it when no task of its backup loads it).
    /// Dropping too much is harmless (a task is built again when asked),
    /// so "within" is a plain prefix of the path.
    fn forget_tasks_within(&mut self, roots: &BTreeSet<String>) {
        let within = |path: &str| roots.iter().any(|r| starts_with_path(path, r));
        let programs = &self.programs;
        let affected = |key: &str, units: &[Arc<Unit>]| {
            within(key) || programs.contains_key(key) || units.iter().any(|u| within(&u.path))
        };
        self.revision += 1;
        self.tasks.retain(|k, t| !affected(k, &t.units));
        self.members.retain(|k, units| !affected(k, units));
        let tasks = &self.tasks;
        self.views.retain(|k, _| tasks.contains_key(k));
    }

    fn recompute(&self, a: &mut Adoption) {
        let mut changed = false;
        for root in std::mem::take(&mut a.dirty) {
            let now = self.adopt_in(&root);
            let before = match now.is_empty() {
                true => a.by_root.remove(&root),
                false => a.by_root.insert(root.clone(), now.clone()),
            };
            if before.unwrap_or_default() != now {
                changed = true;
                a.changed.insert(root);
            }
        }
        if changed {
            a.primary.clear();
            a.borrowed.clear();
            for (path, keys) in a.by_root.values().flatten() {
                let mut keys = keys.iter();
                if let Some(first) = keys.next() {
                    a.primary.insert(path.clone(), first.clone());
                }
                for key in keys {
                    a.borrowed
                        .entry(key.clone())
                        .or_default()
                        .push(path.clone());
                }
            }
        }
    }

    /// The units of the workspace below `folder` (every unit for `""`).
    pub(super) fn units_within<'a>(
        &'a self,
        folder: &'a str,
    ) -> impl Iterator<Item = &'a Arc<Unit>> + 'a {
        self.units
            .range::<str, _>((
                std::ops::Bound::Included(folder),
                std::ops::Bound::Unbounded,
            ))
            .take_while(move |(p, _)| p.starts_with(folder))
            .filter(move |(p, _)| is_within(p, folder))
            .map(|(_, u)| u)
    }

    /// The task folders of backup `root` and their modules, by key.
    fn backup_tasks<'a>(&'a self, root: &'a str) -> BTreeMap<String, Vec<&'a Arc<Unit>>> {
        let mut tasks: BTreeMap<String, Vec<&Arc<Unit>>> = BTreeMap::new();
        for unit in self.units_within(root) {
            if backup_root(&unit.path) != Some(root) || home_root(&unit.path).is_some() {
                continue;
            }
            let (key, grouping) = locate(&unit.path);
            if grouping == Grouping::Backup {
                tasks.entry(key).or_default().push(unit);
            }
        }
        tasks
    }

    /// The keys of the task folders of backup `root` that hold modules
    /// here, in order.
    pub(super) fn backup_task_keys(&self, root: &str) -> Vec<String> {
        self.backup_tasks(root).into_keys().collect()
    }

    /// The configuration files of backup `root` (its `SYSPAR/`).
    fn syspar(&self, root: &str) -> impl Iterator<Item = &Config> {
        self.configs
            .iter()
            .filter(move |(p, _)| syspar_root(p) == Some(root))
            .map(|(_, c)| c)
    }

    /// The tasks of backup `root` by their folded names: each task folder
    /// by its name (`T_ROB1`, `TASK1`), and each task `SYS.cfg` (else
    /// `BACKINFO`) names by its name (the *n*-th task is `RAPID/TASKn` when
    /// the folder has no name of its own).
    fn task_names<'k>(
        &self,
        root: &str,
        keys: impl Iterator<Item = &'k String>,
    ) -> HashMap<String, String> {
        let keys: Vec<&String> = keys.collect();
        let last = |k: &str| fold(k.rsplit(['/', '\\']).next().unwrap_or_default());
        let mut names: HashMap<String, String> =
            keys.iter().map(|k| (last(k), (*k).clone())).collect();
        for list in self.task_lists(root) {
            for (i, task) in list.iter().enumerate() {
                let Some(task) = task else { continue };
                let folder = format!("task{}", i + 1);
                let by_number = keys.iter().find(|k| last(k) == folder);
                if let Some(key) = names
                    .get(&fold(task))
                    .cloned()
                    .or(by_number.map(|k| (*k).clone()))
                {
                    names.entry(fold(task)).or_insert(key);
                }
            }
        }
        names
    }

    /// The tasks of backup `root` by their folded names ([`Workspace::task_names`]).
    pub(super) fn task_names_of(&self, root: &str) -> HashMap<String, String> {
        let keys = self.backup_task_keys(root);
        self.task_names(root, keys.iter())
    }

    /// The keys of the tasks of backup `root` that a `SYS.cfg` entry loads
    /// its module into.
    fn entry_tasks(
        names: &HashMap<String, String>,
        keys: &[String],
        m: &TaskModule,
    ) -> Vec<String> {
        match &m.task {
            None => keys.to_vec(),
            Some(name) => names.get(&fold(name)).cloned().into_iter().collect(),
        }
    }

    /// Which `HOME/` modules of backup `root` its tasks load: each module's
    /// path with the keys of the tasks that load it, in order.
    fn adopt_in(&self, root: &str) -> BTreeMap<String, Vec<String>> {
        let home: Vec<&Arc<Unit>> = self
            .units_within(root)
            .filter(|u| home_root(&u.path) == Some(root))
            .collect();
        if home.is_empty() {
            return BTreeMap::new();
        }
        let tasks = self.backup_tasks(root);
        let keys: Vec<String> = tasks.keys().cloned().collect();
        let names = self.task_names(root, keys.iter());
        // What SYS.cfg loads, by the path below HOME/.
        let mut listed: HashMap<String, Vec<String>> = HashMap::new();
        for config in self.syspar(root) {
            for m in &config.task_modules {
                if let Some(below) = m.home_path() {
                    let below = below.replace('\\', "/").to_ascii_lowercase();
                    listed
                        .entry(below)
                        .or_default()
                        .extend(Self::entry_tasks(&names, &keys, m));
                }
            }
        }
        // What the programs of HOME/<task>/ list, by folded path.
        let mut programs: HashMap<&str, String> = HashMap::new();
        for (pgf, modules) in &self.programs {
            if home_root(pgf) != Some(root) {
                continue;
            }
            let below = below_home(pgf, root);
            let Some(key) = below
                .split_once('/')
                .and_then(|(dir, _)| names.get(&fold(dir)))
            else {
                continue;
            };
            for m in modules {
                programs.insert(m.as_str(), key.clone());
            }
        }
        let mut joins: Vec<BTreeSet<String>> = home
            .iter()
            .map(|u| {
                let below = below_home(&u.path, root);
                let mut keys: BTreeSet<String> = listed
                    .get(&below)
                    .cloned()
                    .unwrap_or_default()
                    .into_iter()
                    .collect();
                if let Some(key) = below
                    .split_once('/')
                    .and_then(|(dir, _)| names.get(&fold(dir)))
                {
                    keys.insert(key.clone());
                }
                if let Some(key) = programs.get(normalize(&u.path).as_str()) {
                    keys.insert(key.clone());
                }
                keys
            })
            .collect();
        // Loads, until the modules loaded load nothing more.
        let files: Vec<String> = home.iter().map(|u| file_name(&u.path)).collect();
        loop {
            let mut more = false;
            for (key, own) in &tasks {
                let members = own.iter().copied().chain(
                    home.iter()
                        .zip(&joins)
                        .filter(|(_, j)| j.contains(key))
                        .map(|(u, _)| *u),
                );
                let loaded = crate::loads::loaded_files(members);
                for (i, file) in files.iter().enumerate() {
                    if loaded.contains(file) && joins[i].insert(key.clone()) {
                        more = true;
                    }
                }
            }
            if !more {
                break;
            }
        }
        // A module the task holds already is that module's file on HOME:.
        let held: HashMap<&String, HashSet<String>> = tasks
            .iter()
            .map(|(k, units)| {
                let modules = units
                    .iter()
                    .flat_map(|u| u.items.modules.iter().map(|m| fold(&m.name)))
                    .collect();
                (k, modules)
            })
            .collect();
        home.iter()
            .zip(joins)
            .filter_map(|(u, keys)| {
                let keys: Vec<String> = keys
                    .into_iter()
                    .filter(|k| {
                        held.get(k).is_none_or(|held| {
                            !u.items
                                .modules
                                .iter()
                                .any(|m| held.contains(&fold(&m.name)))
                        })
                    })
                    .collect();
                (!keys.is_empty()).then(|| (u.path.clone(), keys))
            })
            .collect()
    }

    /// Is the backup task `key` complete: its backup has its `SYSPAR`, no
    /// module file of the task could not be read, and every module that
    /// `SYS.cfg` has the controller load into it is here (below the
    /// backup's `HOME/`, or saved with the task)?
    pub(super) fn is_complete(&self, key: &str) -> bool {
        let Some(root) = backup_root(key) else {
            return false;
        };
        if self.syspar(root).next().is_none() {
            return false;
        }
        if self.unreadable.iter().any(|p| is_within(p, key)) {
            return false;
        }
        let tasks = self.backup_tasks(root);
        let keys: Vec<String> = tasks.keys().cloned().collect();
        let names = self.task_names(root, keys.iter());
        let own: HashSet<String> = tasks
            .get(key)
            .into_iter()
            .flatten()
            .map(|u| file_name(&u.path))
            .collect();
        self.syspar(root).all(|config| {
            config.task_modules.iter().all(|m| {
                let mine = m.task.is_none()
                    || Self::entry_tasks(&names, &keys, m).iter().any(|k| k == key);
                !mine || own.contains(&m.file_name()) || self.has_home_module(root, m)
            })
        })
    }

    /// Is the module a `SYS.cfg` entry names here, below the backup's
    /// `HOME/` (for a `HOME:` file)? Files elsewhere (`RELEASE:`, an
    /// add-in's folder) never are.
    fn has_home_module(&self, root: &str, m: &TaskModule) -> bool {
        let Some(home) = m.home_path() else {
            return false;
        };
        let want = home.replace('\\', "/").to_ascii_lowercase();
        self.units_within(root)
            .any(|u| home_root(&u.path) == Some(root) && below_home(&u.path, root) == want)
    }
}

/// The file name of a path, lowercase.
fn file_name(path: &str) -> String {
    path.rsplit(['/', '\\'])
        .next()
        .unwrap_or_default()
        .to_ascii_lowercase()
}

/// A path's part below its backup's `HOME/` folder, `/` separated and
/// lowercase.
fn below_home(path: &str, root: &str) -> String {
    let rest = path
        .get(root.len()..)
        .unwrap_or_default()
        .replace('\\', "/");
    let rest = rest.trim_start_matches('/');
    let rest = rest.get(4..).filter(|_| {
        rest.get(..4)
            .is_some_and(|h| h.eq_ignore_ascii_case("home"))
    });
    rest.unwrap_or_default()
        .trim_start_matches('/')
        .to_ascii_lowercase()
}

/// Does `path` begin with `prefix`, either slash separating folders?
pub(super) fn starts_with_path(path: &str, prefix: &str) -> bool {
    let slash = |b: u8| b == b'/' || b == b'\\';
    path.len() >= prefix.len()
        && path
            .bytes()
            .zip(prefix.bytes())
            .all(|(a, b)| a == b || (slash(a) && slash(b)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn syspar_and_home_paths() {
        assert_eq!(syspar_root("b/SYSPAR/SYS.cfg"), Some("b"));
        assert_eq!(syspar_root("b/x/SYS.cfg"), None);
        assert_eq!(below_home("b/HOME/Parts/P1.mod", "b"), "parts/p1.mod");
        assert_eq!(below_home("b/RAPID/TASK1/a.mod", "b"), "");
        assert_eq!(owner_backup("b/SYSPAR/EIO.cfg"), Some("b"));
        assert_eq!(owner_backup("b/BACKINFO/backinfo.txt"), Some("b"));
        assert_eq!(
            owner_backup("b/HOME/old/b2/SYSPAR/EIO.cfg"),
            Some("b/HOME/old/b2")
        );
        assert_eq!(
            owner_backup("b/HOME/old/b2/RAPID/TASK1/PROGMOD/m.mod"),
            Some("b/HOME/old/b2")
        );
        assert_eq!(owner_backup("b/HOME/x.mod"), Some("b"));
        assert_eq!(owner_backup("proj/src/x.mod"), None);
    }
}
