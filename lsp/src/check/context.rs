//! The rest of each checked file's task: what `rapid check` loads besides
//! the files it was given, so that a file's findings depend on its place on
//! disk and not on the paths named or the folder the command runs from.
//!
//! A file's task is where it lives ([`task_key`] of its real path): in a
//! controller backup, its `RAPID/TASKn` folder (with its `SYSMOD` and
//! `PROGMOD`) and the backup's `SYSPAR` configuration; elsewhere, the
//! modules, programs (`.pgf`) and configuration of its own folder. Checking
//! `PROGMOD/Main.mod` from inside `RAPID/TASK1` thus sees the system
//! modules of `SYSMOD` as a check of the whole backup does. The task's other
//! files are analysed with it but not reported.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use rapid_analyzer::task::{controller_of, task_key};

use super::discover::{Discovery, Excluder, discover_to_depth};
use super::unit_path;

/// The files of the tasks of `files` that walking `given` (the paths named
/// on the command line) did not reach: modules, programs and configuration.
pub fn task_context(files: &[PathBuf], given: &[PathBuf], excluded: Excluder) -> Discovery {
    let walked: Vec<PathBuf> = given
        .iter()
        .filter(|p| p.is_dir())
        .map(|p| PathBuf::from(unit_path(p)))
        .collect();
    let covered = |dir: &Path| walked.iter().any(|w| dir.starts_with(w));
    let mut tasks = BTreeSet::new();
    let mut folders = BTreeSet::new();
    let mut syspar = BTreeSet::new();
    for file in files {
        let key = task_key(&unit_path(file));
        if key.is_empty() {
            continue;
        }
        let dir = PathBuf::from(&key);
        match controller_of(&key) {
            Some(controller) => {
                if let Some(root) = Path::new(controller).parent() {
                    let configs = root.join("SYSPAR");
                    if !covered(&configs) && configs.is_dir() {
                        syspar.insert(configs);
                    }
                }
                if !covered(&dir) {
                    tasks.insert(dir);
                }
            }
            None if !covered(&dir) => {
                folders.insert(dir);
            }
            None => {}
        }
    }
    let list = |set: BTreeSet<PathBuf>| set.into_iter().collect::<Vec<_>>();
    let mut out = discover_to_depth(&list(tasks), excluded.clone(), None);
    let plain = discover_to_depth(&list(folders), excluded.clone(), Some(1));
    let configs = discover_to_depth(&list(syspar), excluded, Some(1));
    out.files.extend(plain.files);
    out.programs.extend(plain.programs);
    out.configs.extend(plain.configs);
    out.configs.extend(configs.configs);
    for list in [&mut out.files, &mut out.programs, &mut out.configs] {
        list.sort();
        list.dedup();
    }
    // What cannot be walked here is not the run's problem: it was not named.
    out.errors.clear();
    out.warnings.clear();
    out
}
