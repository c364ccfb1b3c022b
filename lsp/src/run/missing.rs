//! The modules a task lacks, taken from the repository around it.
//!
//! A task whose modules use a name that none of them declares does not
//! link on a controller. Yet a backup's task was loaded by one, and a
//! program kept in a repository was run by its author: the module that
//! declares the name existed, and the repository often still holds it
//! elsewhere (a library module kept once beside several programs, the
//! copy in another task of the controller, the same task in an earlier
//! backup; a collection of repositories that keeps each file once keeps
//! only its first copy). So, before it refuses, `rapid run` takes that
//! module from the repository: for each name the task lacks, the module
//! nearest to the task that declares it for the whole task (another task
//! of the same controller first, then the same task of another backup,
//! then the one whose path shares the most folders with the task's),
//! unless the task has a module of that name already (another version of
//! it) or declares a name the module declares too, the program loads the
//! module's file itself (`Load`: it comes then), the module declares the
//! entry routine (another program's), or it would bring load errors the
//! task did not have. A name of RobotWare's default `user` module
//! (`reg1` to `reg5`, `clock1`) that the repository declares nowhere
//! comes from that module, written out here. Each module taken is a note
//! of the run.
//!
//! Not in a complete backup, where nothing can be missing: there the
//! names are load errors (`rapid check` reports them so too).

use std::cmp::Reverse;
use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use rapid_analyzer::layout::controller_of;
use rapid_analyzer::names::fold;
use rapid_analyzer::task::{Task, Unit};

use super::load::folder_name;

/// At most this many modules are taken for one task.
const MAX_TAKEN: usize = 32;

/// At most this many modules are tried for one name (each try checks the
/// task again).
const MAX_TRIES: usize = 3;

/// Does `u` declare `name` for the whole task (not `LOCAL`)?
fn declares(u: &Unit, name: &str) -> bool {
    let name = fold(name);
    globals(u).any(|g| g == name)
}

/// The names `u` declares for the whole task, folded.
fn globals(u: &Unit) -> impl Iterator<Item = String> + '_ {
    u.items
        .modules
        .iter()
        .flat_map(|m| m.global_names().map(fold))
}

/// How many leading folders two paths share.
fn shared_folders(a: &str, b: &str) -> usize {
    fn parts(p: &str) -> impl Iterator<Item = &str> {
        p.split(['/', '\\']).filter(|s| !s.is_empty() && *s != ".")
    }
    parts(a).zip(parts(b)).take_while(|(x, y)| x == y).count()
}

/// A task with the modules it lacks taken ([`complete`]).
pub struct Completed {
    pub task: Arc<Task>,
    /// One a module taken.
    pub notes: Vec<String>,
    /// It still uses names no module of it declares.
    pub lacking: bool,
    /// What the loader finds in `task`.
    pub check: rapid_runtime::LoadCheck,
}

/// `task` with the modules it lacks taken from `pool` (the tasks of the
/// repository around it, its own among them or not), and a note for each
/// module taken. A module that declares `entry` (the routine the task
/// starts in) is another program's, never taken.
pub fn complete(task: &Arc<Task>, pool: &[Arc<Task>], entry: &str) -> Completed {
    let mut task = task.clone();
    let mut notes = Vec::new();
    let mut check = rapid_runtime::load_check(&task);
    let mut given_up: HashSet<String> = HashSet::new();
    let mut index = None;
    while notes.len() < MAX_TAKEN {
        let names: Vec<String> = check
            .missing
            .iter()
            .filter(|n| given_up.insert(fold(n)))
            .cloned()
            .collect();
        if names.is_empty() {
            break;
        }
        let index = index.get_or_insert_with(|| self::index(pool));
        let has = Has::of(&task);
        let lists: Vec<(String, Vec<Arc<Unit>>)> = names
            .into_iter()
            .map(|n| {
                let found = candidates(&task, &has, index, &n, entry);
                (n, found)
            })
            .collect();
        // Each name's nearest module, all at once (one check), as long as
        // they declare nothing twice; else one by one.
        let mut batch: Vec<(&str, &Arc<Unit>)> = Vec::new();
        let mut batch_globals: HashSet<String> = HashSet::new();
        for (name, found) in &lists {
            if batch.len() + notes.len() >= MAX_TAKEN {
                break;
            }
            let Some(unit) = found.first() else { continue };
            if batch_globals.contains(&fold(name)) {
                continue;
            }
            if globals(unit).any(|g| batch_globals.contains(&g)) {
                continue;
            }
            batch_globals.extend(globals(unit));
            batch.push((name, unit));
        }
        if batch.is_empty() {
            continue;
        }
        let with = Arc::new(task.with_extra_units(batch.iter().map(|(_, u)| (*u).clone())));
        let after = rapid_runtime::load_check(&with);
        if after.errors.len() <= check.errors.len() {
            for (name, unit) in &batch {
                notes.push(note(&task, name, unit));
            }
            task = with;
            check = after;
            continue;
        }
        for (name, found) in &lists {
            if task.units.iter().any(|u| declares(u, name)) {
                continue;
            }
            let declared = Has::of(&task).declared;
            for unit in found.iter().take(MAX_TRIES) {
                if globals(unit).any(|g| declared.contains(&g)) {
                    continue;
                }
                let with = Arc::new(task.with_extra_units([unit.clone()]));
                let after = rapid_runtime::load_check(&with);
                if after.errors.len() > check.errors.len() {
                    continue;
                }
                notes.push(note(&task, name, unit));
                task = with;
                check = after;
                break;
            }
        }
    }
    Completed {
        task,
        notes,
        lacking: !check.missing.is_empty(),
        check,
    }
}

/// The note of a module taken for `name`.
fn note(task: &Task, name: &str, unit: &Unit) -> String {
    if unit.path == DEFAULT_USER_PATH {
        return format!(
            "note: task {} lacks a module that declares `{name}`: simulated with RobotWare's default user module (reg1 to reg5, clock1), as the repository holds no module that declares it",
            folder_name(&task.key)
        );
    }
    let module = unit.items.modules.first().map_or("", |m| m.name.as_str());
    format!(
        "note: task {} lacks a module that declares `{name}`: simulated with module {module} of {}, the repository's nearest that declares it",
        folder_name(&task.key),
        unit.path
    )
}

/// The modules of the pool by the names they declare for the whole task.
type Index<'p> = HashMap<String, Vec<(&'p Arc<Task>, &'p Arc<Unit>)>>;

fn index(pool: &[Arc<Task>]) -> Index<'_> {
    let mut out: Index<'_> = HashMap::new();
    for t in pool {
        for u in t.units.iter() {
            let mut names: Vec<String> = globals(u).collect();
            names.sort_unstable();
            names.dedup();
            for n in names {
                out.entry(n).or_default().push((t, u));
            }
        }
    }
    out
}

/// What a task has, that a module it takes must not have again.
struct Has {
    /// The files its program loads itself (`Load`): they come when it
    /// loads them, not before.
    loads: HashSet<String>,
    /// Its modules' names, folded.
    modules: HashSet<String>,
    /// The names it declares for the whole task, folded.
    declared: HashSet<String>,
}

impl Has {
    fn of(task: &Task) -> Has {
        Has {
            loads: rapid_analyzer::loads::loaded_files(task.units.iter()),
            modules: task
                .units
                .iter()
                .flat_map(|u| u.items.modules.iter().map(|m| fold(&m.name)))
                .collect(),
            declared: task.units.iter().flat_map(|u| globals(u)).collect(),
        }
    }
}

/// The data RobotWare's own `user` system module declares in every task
/// of a new system (registers `reg1` to `reg5`, the stopwatch `clock1`),
/// which programs use without declaring them.
const DEFAULT_USER_NAMES: [&str; 6] = ["reg1", "reg2", "reg3", "reg4", "reg5", "clock1"];

/// Where the default `user` module is said to come from (its path).
const DEFAULT_USER_PATH: &str = "RobotWare's default user.sys";

/// RobotWare's default `user` module, written out ([`DEFAULT_USER_NAMES`]).
fn default_user() -> Arc<Unit> {
    static UNIT: std::sync::OnceLock<Arc<Unit>> = std::sync::OnceLock::new();
    UNIT.get_or_init(|| {
        let text = "MODULE user(SYSMODULE)\n  VAR num reg1 := 0;\n  VAR num reg2 := 0;\n  VAR num reg3 := 0;\n  VAR num reg4 := 0;\n  VAR num reg5 := 0;\n  VAR clock clock1;\nENDMODULE\n";
        Arc::new(Unit::new(DEFAULT_USER_PATH.to_owned(), text.to_owned(), None))
    })
    .clone()
}

/// The modules of the pool (`index`) that could be the one `task` lacks
/// for `name`, the nearest first ([`complete`]); for a name of RobotWare's
/// default `user` module that the repository declares nowhere, that
/// module, unless the task has a `user` module of its own.
fn candidates(
    task: &Task,
    has: &Has,
    index: &Index<'_>,
    name: &str,
    entry: &str,
) -> Vec<Arc<Unit>> {
    let controller = controller_of(&task.key);
    let default = || {
        let known = DEFAULT_USER_NAMES.contains(&fold(name).as_str());
        if known && !has.modules.contains("user") {
            vec![default_user()]
        } else {
            Vec::new()
        }
    };
    let Some(declaring) = index.get(&fold(name)) else {
        return default();
    };
    let mut found: Vec<(&Arc<Task>, &Arc<Unit>)> = declaring
        .iter()
        .copied()
        .filter(|(_, u)| {
            !u.items
                .modules
                .iter()
                .any(|m| has.modules.contains(&fold(&m.name)))
                && !declares(u, entry)
                && !globals(u).any(|g| has.declared.contains(&g))
                && rapid_analyzer::loads::module_file_name(&u.path)
                    .is_none_or(|f| !has.loads.contains(&f))
        })
        .collect();
    let folder = folder_name(&task.key);
    found.sort_by_cached_key(|(t, u)| {
        let other = controller_of(&t.key);
        let same = controller.is_some() && other == controller;
        // The same task of another backup (`TASK2` of an earlier one).
        let same_task = controller.is_some()
            && other.is_some()
            && folder_name(&t.key).eq_ignore_ascii_case(folder);
        (
            !same,
            !same_task,
            Reverse(shared_folders(&u.path, &task.key)),
            u.path.clone(),
        )
    });
    found.dedup_by(|a, b| a.1.path == b.1.path);
    if found.is_empty() {
        return default();
    }
    found.into_iter().map(|(_, u)| u.clone()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(path: &str, text: &str) -> Arc<Unit> {
        Arc::new(Unit::new(path.to_owned(), text.to_owned(), None))
    }

    fn task(key: &str, units: Vec<Arc<Unit>>) -> Arc<Task> {
        Arc::new(Task::new(key.to_owned(), units, None))
    }

    #[test]
    fn a_routine_the_task_lacks_comes_from_the_nearest_module_that_declares_it() {
        let main = unit(
            "repo/a/Main.mod",
            "MODULE Main\n  PROC main()\n    Greet;\n  ENDPROC\nENDMODULE\n",
        );
        let near = unit(
            "repo/b/Lib.sys",
            "MODULE Lib(SYSMODULE)\n  PROC Greet()\n    TPWrite \"near\";\n  ENDPROC\nENDMODULE\n",
        );
        let far = unit(
            "other/x/y/Lib2.sys",
            "MODULE Lib2(SYSMODULE)\n  PROC Greet()\n    TPWrite \"far\";\n  ENDPROC\nENDMODULE\n",
        );
        let local = unit(
            "repo/a/c/Hidden.sys",
            "MODULE Hidden(SYSMODULE)\n  LOCAL PROC Greet()\n  ENDPROC\nENDMODULE\n",
        );
        let t = task("repo/a", vec![main]);
        let pool = vec![
            task("other/x/y", vec![far]),
            task("repo/b", vec![near]),
            task("repo/a/c", vec![local]),
        ];
        let Completed {
            task: done, notes, ..
        } = complete(&t, &pool, "main");
        let paths: Vec<&str> = done.units.iter().map(|u| u.path.as_str()).collect();
        assert_eq!(paths, ["repo/a/Main.mod", "repo/b/Lib.sys"]);
        assert_eq!(notes.len(), 1);
        assert!(notes[0].contains("`Greet`"), "{notes:?}");
        assert!(rapid_runtime::load_check(&done).missing.is_empty());
    }

    #[test]
    fn a_module_that_would_bring_errors_repeats_a_module_or_is_a_program_is_not_taken() {
        let main = unit(
            "repo/a/Main.mod",
            "MODULE Main\n  PROC main()\n    Greet 1;\n  ENDPROC\nENDMODULE\n",
        );
        // Another version of Main: never taken.
        let version = unit(
            "repo/b/Main.mod",
            "MODULE Main\n  PROC Greet(num n)\n  ENDPROC\nENDMODULE\n",
        );
        // Takes no argument: the call would be an error.
        let wrong = unit(
            "repo/c/Lib.sys",
            "MODULE Lib\n  PROC Greet()\n  ENDPROC\nENDMODULE\n",
        );
        // Another program (it has a `main`): never taken.
        let program = unit(
            "repo/d/Other.mod",
            "MODULE Other\n  PROC main()\n  ENDPROC\n  PROC Greet(num n)\n  ENDPROC\nENDMODULE\n",
        );
        // Declares a name the task has too: not the module it lacks.
        let overlapping = unit(
            "repo/e/Both.sys",
            "MODULE Both\n  VAR num nCount;\n  PROC Greet(num n)\n  ENDPROC\nENDMODULE\n",
        );
        let data = unit(
            "repo/a/Data.mod",
            "MODULE Data\n  VAR num nCount;\nENDMODULE\n",
        );
        let t = task("repo/a", vec![main, data]);
        let pool = vec![
            task("repo/b", vec![version]),
            task("repo/c", vec![wrong]),
            task("repo/d", vec![program]),
            task("repo/e", vec![overlapping]),
        ];
        let Completed {
            task: done, notes, ..
        } = complete(&t, &pool, "main");
        assert_eq!(done.units.len(), 2);
        assert!(notes.is_empty());
        assert_eq!(rapid_runtime::load_check(&done).missing, ["Greet"]);
    }

    #[test]
    fn a_backup_s_task_takes_what_it_lacks_from_the_same_task_of_another_backup() {
        let main = unit(
            "repo/B2/RAPID/TASK2/PROGMOD/Main.mod",
            "MODULE Main\n  PROC main()\n    Greet;\n  ENDPROC\nENDMODULE\n",
        );
        let lib = |task: &str, said: &str| {
            unit(
                &format!("repo/B1/RAPID/{task}/SYSMOD/Lib.sys"),
                &format!(
                    "MODULE Lib\n  PROC Greet()\n    TPWrite \"{said}\";\n  ENDPROC\nENDMODULE\n"
                ),
            )
        };
        let t = task("repo/B2/RAPID/TASK2", vec![main]);
        let pool = vec![
            task("repo/B1/RAPID/TASK1", vec![lib("TASK1", "robot 1")]),
            task("repo/B1/RAPID/TASK2", vec![lib("TASK2", "robot 2")]),
        ];
        let done = complete(&t, &pool, "main");
        assert_eq!(
            done.task.units[1].path,
            "repo/B1/RAPID/TASK2/SYSMOD/Lib.sys"
        );
    }

    #[test]
    fn the_registers_and_clock_of_robotware_s_user_module_come_from_it() {
        let main = unit(
            "repo/a/Main.mod",
            "MODULE Main\n  PROC main()\n    ClkStart clock1;\n    reg1 := 2;\n  ENDPROC\nENDMODULE\n",
        );
        let t = task("repo/a", vec![main.clone()]);
        let done = complete(&t, &[], "main");
        assert_eq!(done.task.units[1].path, DEFAULT_USER_PATH);
        assert_eq!(done.notes.len(), 1, "{:?}", done.notes);
        assert!(done.notes[0].contains("RobotWare's default user module"));
        assert!(!done.lacking);
        // A task with a user module of its own lacks them for real.
        let own = unit("repo/a/user.sys", "MODULE user(SYSMODULE)\nENDMODULE\n");
        let t = task("repo/a", vec![main, own]);
        assert!(complete(&t, &[], "main").lacking);
    }

    #[test]
    fn a_module_taken_brings_what_it_lacks_too() {
        let main = unit(
            "repo/a/Main.mod",
            "MODULE Main\n  PROC main()\n    Outer;\n  ENDPROC\nENDMODULE\n",
        );
        let outer = unit(
            "repo/b/Outer.sys",
            "MODULE Outer\n  PROC Outer()\n    Inner;\n  ENDPROC\nENDMODULE\n",
        );
        let inner = unit(
            "repo/c/Inner.sys",
            "MODULE Inner\n  PROC Inner()\n  ENDPROC\nENDMODULE\n",
        );
        let t = task("repo/a", vec![main]);
        let pool = vec![task("repo/b", vec![outer]), task("repo/c", vec![inner])];
        let Completed {
            task: done, notes, ..
        } = complete(&t, &pool, "main");
        assert_eq!(done.units.len(), 3, "{notes:?}");
        assert!(rapid_runtime::load_check(&done).missing.is_empty());
    }
}
