//! Modules of a backup's `HOME/` folder that a task loads at run time
//! (`Load`, `StartLoad` of a file named in the program): they belong to
//! that task, whose names they use and which uses theirs.

use std::collections::{BTreeMap, HashMap};

use super::Workspace;
use crate::layout::{Grouping, backup_root, in_home, locate, named_module_files};

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
        let mut loaded: HashMap<&str, BTreeMap<&str, String>> = HashMap::new();
        let mut by_path: Vec<(&String, &Vec<String>)> = self.loads.iter().collect();
        by_path.sort();
        for (path, names) in by_path {
            let (key, _) = locate(path);
            let Some(root) = backup_root(path) else {
                continue;
            };
            let files = loaded.entry(root).or_default();
            for name in names {
                files.entry(name.as_str()).or_insert_with(|| key.clone());
            }
        }
        let mut adopted = HashMap::new();
        for path in self.units.keys().filter(|p| in_home(p)) {
            let Some(root) = backup_root(path) else {
                continue;
            };
            let file = path
                .rsplit(['/', '\\'])
                .next()
                .unwrap_or_default()
                .to_ascii_lowercase();
            if let Some(key) = loaded.get(root).and_then(|f| f.get(file.as_str())) {
                adopted.insert(path.clone(), key.clone());
            }
        }
        if adopted != self.adopted {
            self.adopted = adopted;
            self.forget_all_tasks();
        }
    }
}
