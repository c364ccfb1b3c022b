//! The rest of each checked file's task: what `rapid check` loads besides
//! the files it was given, so that a file's findings depend on its place on
//! disk and not on the paths named or the folder the command runs from.
//!
//! A file's task is where it lives ([`task_key`] of its real path). In a
//! controller backup (a file of a task folder under `RAPID/`, or of the
//! backup's `HOME/`) it is the whole backup but the backups kept inside
//! it: its task's modules, the `HOME/` modules its tasks load, the other
//! tasks (which share their persistents), `SYSPAR` and `BACKINFO`.
//! Elsewhere it is the modules, programs (`.pgf`) and configuration of the
//! file's own folder. Checking `PROGMOD/Main.mod` from inside
//! `RAPID/TASK1` thus sees what a check of the whole backup, or of the
//! repository holding it, sees. The task's other files are analysed with
//! it but not reported.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use rapid_analyzer::layout::{Grouping, backup_root, home_root, locate, owner_backup};
use rapid_analyzer::task::task_key;
use rapid_analyzer::workspace::program_modules;

use super::discover::{Discovery, Excluder, discover_in};
use super::{Disk, Environment, Kind, Walked};

/// The folders that hold the task of a file (named by `path`, as the
/// analyzer names it).
#[derive(Debug, Default, PartialEq, Eq)]
pub struct TaskFolders {
    /// The backup's folder for a file of a backup: its files are the
    /// context, but those of backups kept inside it.
    pub deep: Option<PathBuf>,
    /// Folders whose own files belong to the task: the file's folder
    /// outside a backup.
    pub shallow: Vec<PathBuf>,
}

/// Where the rest of the task of the file `path` lives, on the disk.
pub fn task_folders(path: &str) -> TaskFolders {
    task_folders_in(&Disk, path)
}

/// Where the rest of the task of the file `path` lives in `env`.
pub fn task_folders_in(env: &dyn Environment, path: &str) -> TaskFolders {
    if let Some(root) = backup_of_file(path) {
        let root = if root.is_empty() { "." } else { root };
        return TaskFolders {
            deep: Some(PathBuf::from(root)).filter(|r| env.kind(r).is_ok()),
            shallow: Vec::new(),
        };
    }
    let key = task_key(path);
    if key.is_empty() {
        return TaskFolders::default();
    }
    TaskFolders {
        deep: None,
        shallow: vec![PathBuf::from(key)],
    }
}

/// The backup folder of a file of a backup's task folder or `HOME/`.
pub fn backup_of_file(path: &str) -> Option<&str> {
    if let Some(root) = home_root(path) {
        return Some(root);
    }
    match locate(path).1 {
        Grouping::Backup => backup_root(path),
        _ => None,
    }
}

/// Is the file `path` of the backup `root` itself, not of a backup kept
/// inside it?
fn of_backup(path: &Path, root: &Path, env: &dyn Environment) -> bool {
    let name = env.name(path);
    let root = env.name(root);
    let root = root.trim_end_matches(['/', '\\']);
    owner_backup(&name).is_some_and(|owner| owner.len() <= root.len())
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
    let mut out = discover_folders_in(env, &[], &list(shallow), excluded.clone());
    // A backup's files, not those of the backups kept inside it.
    for root in deep {
        let mut found = discover_in(env, std::slice::from_ref(&root), excluded.clone(), None);
        for list in [&mut found.files, &mut found.configs, &mut found.programs] {
            list.retain(|p| of_backup(p, &root, env));
        }
        out.extend(found);
    }
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
/// `shallow` folders themselves (with the configuration of their
/// `SYSPAR/` or `BACKINFO/` folder, which is theirs), on the disk.
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
    out.extend(discover_in(env, shallow, excluded.clone(), Some(1)));
    let config_folders: Vec<PathBuf> = shallow
        .iter()
        .flat_map(|dir| env.walk(dir, Some(1), &excluded))
        .filter_map(|walked| match walked {
            Walked::Entry(path, Kind::Folder) => Some(path),
            _ => None,
        })
        .filter(|path| {
            let name = path.file_name().unwrap_or_default().to_string_lossy();
            name.eq_ignore_ascii_case("syspar") || name.eq_ignore_ascii_case("backinfo")
        })
        .collect();
    let mut configs = discover_in(env, &config_folders, excluded, Some(1));
    configs.files.clear();
    configs.programs.clear();
    out.extend(configs);
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
