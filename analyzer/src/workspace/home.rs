//! What a controller backup says about its tasks beyond their folders:
//! modules of its `HOME/` folder that a task loads (by `Load` or
//! `StartLoad` of a file named in the program, or because `SYS.cfg` lists
//! them for the task) belong to that task; and a task is complete when the
//! backup has its `SYSPAR` and every module the task loads is here.

use std::collections::{BTreeMap, HashMap};

use super::Workspace;
use crate::layout::{Grouping, backup_root, in_home, locate, named_module_files};
use crate::task::{Config, TaskModule};

impl Workspace {
    /// Records the module files a unit of a backup's task names (`text`
    /// `None` when the unit is removed). Returns whether the modules that
    /// tasks load from `HOME/` may have changed.
    pub(super) fn note_loads(&mut self, path: &str, text: Option<&str>) -> bool {
        if in_home(path) {
            // A module of HOME/ came or went (or changed: cheap to redo).
            return true;
        }
        if locate(path).1 != Grouping::Backup {
            return false;
        }
        let names = text.map(named_module_files).unwrap_or_default();
        let old = match names.is_empty() {
            true => self.loads.remove(path),
            false => self.loads.insert(path.to_owned(), names.clone()),
        };
        old.unwrap_or_default() != names
    }

    /// Works out which `HOME/` modules each backup's tasks load, and drops
    /// the cached tasks when that changed.
    pub(super) fn refresh_adoption(&mut self) {
        // Per backup folder, the file names its tasks load, with the first
        // task (by key) that loads each.
        let mut loaded: HashMap<&str, BTreeMap<String, String>> = HashMap::new();
        let mut by_path: Vec<(&String, &Vec<String>)> = self.loads.iter().collect();
        by_path.sort();
        for (path, names) in by_path {
            let (key, _) = locate(path);
            let Some(root) = backup_root(path) else {
                continue;
            };
            let files = loaded.entry(root).or_default();
            for name in names {
                files.entry(name.clone()).or_insert_with(|| key.clone());
            }
        }
        // Modules SYS.cfg has the tasks load from HOME:, by their path
        // below HOME/ (lowercase).
        let mut listed: HashMap<&str, BTreeMap<String, String>> = HashMap::new();
        for (path, config) in &self.configs {
            let Some(root) = syspar_root(path) else {
                continue;
            };
            for m in &config.task_modules {
                let (Some(home), Some(key)) = (m.home_path(), self.task_key_named(root, config, m))
                else {
                    continue;
                };
                listed
                    .entry(root)
                    .or_default()
                    .entry(home.replace('\\', "/").to_ascii_lowercase())
                    .or_insert(key);
            }
        }
        let mut adopted = HashMap::new();
        for path in self.units.keys().filter(|p| in_home(p)) {
            let Some(root) = backup_root(path) else {
                continue;
            };
            let below_home = below_home(path, root);
            let file = below_home.rsplit('/').next().unwrap_or_default();
            let key = listed
                .get(root)
                .and_then(|l| l.get(&below_home))
                .or_else(|| loaded.get(root).and_then(|f| f.get(file)));
            if let Some(key) = key {
                adopted.insert(path.clone(), key.clone());
            }
        }
        if adopted != self.adopted {
            self.adopted = adopted;
            self.forget_all_tasks();
        }
    }

    /// The key of the task of backup `root` that a `SYS.cfg` entry names
    /// (the first task for `-AllTask`): a task folder of that name, or
    /// `RAPID/TASKn` for the *n*-th task of `CAB_TASKS`.
    fn task_key_named(&self, root: &str, config: &Config, m: &TaskModule) -> Option<String> {
        let keys = self.backup_task_keys(root);
        match &m.task {
            None => keys.into_iter().next(),
            Some(name) => {
                let by_name = keys.iter().find(|k| {
                    k.rsplit('/')
                        .next()
                        .is_some_and(|last| last.eq_ignore_ascii_case(name))
                });
                let by_number = config
                    .tasks
                    .iter()
                    .position(|t| t.eq_ignore_ascii_case(name))
                    .and_then(|i| {
                        let folder = format!("task{}", i + 1);
                        keys.iter().find(|k| {
                            k.rsplit('/')
                                .next()
                                .is_some_and(|last| last.eq_ignore_ascii_case(&folder))
                        })
                    });
                by_name.or(by_number).cloned()
            }
        }
    }

    /// The keys of the task folders of backup `root` that hold modules here,
    /// in order.
    pub(super) fn backup_task_keys(&self, root: &str) -> Vec<String> {
        let mut keys: Vec<String> = self
            .units
            .keys()
            // A backup's files start with its folder: the others need no
            // look (this runs for every task of every backup).
            .filter(|p| starts_with_folder(p, root) && !in_home(p))
            .map(|p| locate(p))
            .filter(|(k, g)| *g == Grouping::Backup && backup_root(k) == Some(root))
            .map(|(k, _)| k)
            .collect();
        keys.sort();
        keys.dedup();
        keys
    }

    /// Is the backup task `key` complete: its backup has its `SYSPAR`, no
    /// module file of the task could not be read, and every module that
    /// `SYS.cfg` has the controller load into it is here?
    pub(super) fn is_complete(&self, key: &str) -> bool {
        let Some(root) = backup_root(key) else {
            return false;
        };
        let syspar: Vec<&Config> = self
            .configs
            .iter()
            .filter(|(p, _)| syspar_root(p) == Some(root))
            .map(|(_, c)| c)
            .collect();
        if syspar.is_empty() {
            return false;
        }
        let folder = format!("{key}/");
        if self
            .unreadable
            .iter()
            .any(|p| p.replace('\\', "/").starts_with(&folder))
        {
            return false;
        }
        syspar.iter().all(|config| {
            config.task_modules.iter().all(|m| {
                let mine = self.task_key_named(root, config, m).as_deref() == Some(key)
                    || m.task.is_none();
                !mine || self.has_module(root, m)
            })
        })
    }

    /// Is the module a `SYS.cfg` entry names here (below the backup's
    /// `HOME/`, for a `HOME:` file)? Files elsewhere (`RELEASE:`, an
    /// add-in's folder) never are.
    fn has_module(&self, root: &str, m: &TaskModule) -> bool {
        let Some(home) = m.home_path() else {
            return false;
        };
        let want = home.replace('\\', "/").to_ascii_lowercase();
        self.units
            .keys()
            .any(|p| in_home(p) && backup_root(p) == Some(root) && below_home(p, root) == want)
    }
}

/// Does `path` start with `folder`, either written with `/` or `\`?
fn starts_with_folder(path: &str, folder: &str) -> bool {
    let sep = |b: u8| b == b'/' || b == b'\\';
    path.len() >= folder.len()
        && path
            .bytes()
            .zip(folder.bytes())
            .all(|(a, b)| a == b || (sep(a) && sep(b)))
}

/// The backup folder of a configuration file in its `SYSPAR/` folder.
pub(super) fn syspar_root(path: &str) -> Option<&str> {
    let normal = path.replace('\\', "/");
    let (dir, _) = normal.rsplit_once('/')?;
    let (parent, last) = dir.rsplit_once('/').unwrap_or(("", dir));
    if !last.eq_ignore_ascii_case("syspar") {
        return None;
    }
    path.get(..parent.len())
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn syspar_and_home_paths() {
        assert_eq!(syspar_root("b/SYSPAR/SYS.cfg"), Some("b"));
        assert_eq!(syspar_root("b/x/SYS.cfg"), None);
        assert_eq!(below_home("b/HOME/Parts/P1.mod", "b"), "parts/p1.mod");
        assert!(starts_with_folder(r"c:\b\RAPID\TASK1\M.mod", "c:/b"));
        assert!(!starts_with_folder("c:/a/RAPID/TASK1/M.mod", "c:/b"));
        assert_eq!(below_home("b/RAPID/TASK1/a.mod", "b"), "");
    }
}
