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
use rapid_analyzer::workspace::program_modules;

use super::discover::{Discovery, Excluder, discover_in};
use super::{Disk, Environment, Kind};

/// The folders that hold the task of a file (named by `path`, as the
/// analyzer names it).
#[derive(Debug, Default, PartialEq, Eq)]
pub struct TaskFolders {
    /// The task's folder when it is a backup's `RAPID/TASKn`: its modules
    /// are in it and its subfolders (`SYSMOD`, `PROGMOD`).
    pub deep: Option<PathBuf>,
    /// Folders whose own files belong to the task: the file's folder
    /// outside a backup; the backup's `SYSPAR` (configuration) inside one.
    pub shallow: Vec<PathBuf>,
}

/// Where the rest of the task of the file `path` lives, on the disk.
pub fn task_folders(path: &str) -> TaskFolders {
    task_folders_in(&Disk, path)
}

/// Where the rest of the task of the file `path` lives in `env`.
pub fn task_folders_in(env: &dyn Environment, path: &str) -> TaskFolders {
    let key = task_key(path);
    if key.is_empty() {
        return TaskFolders::default();
    }
    match controller_of(&key) {
        Some(controller) => TaskFolders {
            deep: Some(PathBuf::from(&key)),
            shallow: Path::new(controller)
                .parent()
                .map(|root| root.join("SYSPAR"))
                .filter(|s| env.kind(s).is_ok_and(|k| k == Kind::Folder))
                .into_iter()
                .collect(),
        },
        None => TaskFolders {
            deep: None,
            shallow: vec![PathBuf::from(key)],
        },
    }
}

/// The files of the tasks of `files` that walking `given` (the paths named
/// on the command line) did not reach: modules, programs and configuration,
/// and the modules that the programs found (`programs` and those of the
/// tasks' folders) list in other folders.
pub fn task_context(
    env: &dyn Environment,
    files: &[PathBuf],
    programs: &[PathBuf],
    given: &[PathBuf],
    excluded: Excluder,
) -> Discovery {
    let walked: Vec<PathBuf> = given
        .iter()
        .filter(|p| env.kind(p).is_ok_and(|k| k == Kind::Folder))
        .map(|p| PathBuf::from(env.name(p)))
        .collect();
    let covered = |dir: &Path| walked.iter().any(|w| dir.starts_with(w));
    let mut deep = BTreeSet::new();
    let mut shallow = BTreeSet::new();
    for file in files {
        let folders = task_folders_in(env, &env.name(file));
        deep.extend(folders.deep.filter(|d| !covered(d)));
        shallow.extend(folders.shallow.into_iter().filter(|d| !covered(d)));
    }
    let list = |set: BTreeSet<PathBuf>| set.into_iter().collect::<Vec<_>>();
    let mut out = discover_folders_in(env, &list(deep), &list(shallow), excluded.clone());
    // What cannot be walked here is not the run's problem: it was not named.
    out.errors.clear();
    out.warnings.clear();
    // The modules the programs list, wherever they are.
    let listed = program_members(env, programs.iter().chain(&out.programs));
    out.files.extend(
        listed
            .into_iter()
            .filter(|m| !excluded(m, false) && !files.contains(m)),
    );
    out.files.sort();
    out.files.dedup();
    out
}

/// The files of the `deep` folders and their subfolders, and of the
/// `shallow` folders themselves, on the disk.
pub fn discover_folders(deep: &[PathBuf], shallow: &[PathBuf], excluded: Excluder) -> Discovery {
    discover_folders_in(&Disk, deep, shallow, excluded)
}

/// [`discover_folders`] in `env`.
pub fn discover_folders_in(
    env: &dyn Environment,
    deep: &[PathBuf],
    shallow: &[PathBuf],
    excluded: Excluder,
) -> Discovery {
    let mut out = discover_in(env, deep, excluded.clone(), None);
    out.extend(discover_in(env, shallow, excluded, Some(1)));
    out
}

/// The module files that the program files `programs` (`.pgf`) list and
/// that exist.
pub fn program_members<'a>(
    env: &dyn Environment,
    programs: impl Iterator<Item = &'a PathBuf>,
) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for pgf in programs {
        let Ok(bytes) = env.read(pgf) else {
            continue;
        };
        let xml = String::from_utf8_lossy(&bytes);
        for module in program_modules(&pgf.to_string_lossy(), &xml) {
            let path = PathBuf::from(module);
            if matches!(env.kind(&path), Ok(Kind::File(_))) {
                out.push(path);
            }
        }
    }
    out.sort();
    out.dedup();
    out
}
