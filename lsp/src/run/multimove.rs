//! A folder of per-task programs: the programs of a MultiMove system kept
//! side by side, one module per task named `<program>_<task>`
//! (`Grey_T_ROB1.mod`, `Grey_T_ROB2.mod`), each with its own `main`, that
//! name one another's tasks in quotes (`[["T_ROB1"], ["T_ROB2"]]`, the
//! `tasks` list of a `SyncMoveOn` or a `WaitSyncTask`). `rapid check` sees
//! alternative programs in such a folder (two `main`s cannot be loaded
//! into one task); `rapid run` loads each program into the task its name
//! gives and runs them together, as the controller they were written for
//! does.

use std::sync::Arc;

use rapid_analyzer::task::{Task, Unit};

use super::load::{self, TaskToRun};

/// The tasks of a folder whose alternative programs are one program per
/// task, each named as its module says; `None` for any other folder.
pub fn per_task(task: &Arc<Task>, entry: &str) -> Option<Vec<TaskToRun>> {
    let programs = programs(task, entry)?;
    Some(
        programs
            .into_iter()
            .map(|(view, name)| {
                let mut t = load::to_run(&view, None, false, entry);
                t.name = name;
                t
            })
            .collect(),
    )
}

/// The programs of a folder of per-task programs (each the view of the
/// folder's task with its module), with the task each is for.
pub fn programs(task: &Arc<Task>, entry: &str) -> Option<Vec<(Arc<Task>, String)>> {
    let programs = load::alternatives(task, entry);
    if programs.len() < 2 {
        return None;
    }
    let units: Vec<&Arc<Unit>> = programs
        .iter()
        .map(|v| v.unit(v.owner?))
        .collect::<Option<_>>()?;
    let names = task_names(&units)?;
    Some(programs.iter().cloned().zip(names).collect())
}

/// The task each program is for: the end of its module's name, after
/// `<program>_`, that one of the programs names in quotes (the longest
/// such end: `T_ROB1` in `Grey_T_ROB1`). `None` unless every program has
/// one, all with one program name before it, and no two the same task.
fn task_names(units: &[&Arc<Unit>]) -> Option<Vec<String>> {
    let texts: Vec<String> = units.iter().map(|u| u.text.to_ascii_lowercase()).collect();
    let quoted = |s: &str| {
        let q = format!("\"{}\"", s.to_ascii_lowercase());
        texts.iter().any(|t| t.contains(&q))
    };
    let mut program: Option<String> = None;
    let mut names: Vec<String> = Vec::new();
    for unit in units {
        let module = unit.items.modules.first()?.name.as_str();
        let (prefix, name) = module
            .match_indices('_')
            .map(|(i, _)| (&module[..i], &module[i + 1..]))
            .find(|(p, n)| !p.is_empty() && !n.is_empty() && quoted(n))?;
        let prefix = prefix.to_ascii_lowercase();
        match &program {
            None => program = Some(prefix),
            Some(p) if *p == prefix => {}
            Some(_) => return None,
        }
        if names.iter().any(|n| n.eq_ignore_ascii_case(name)) {
            return None;
        }
        names.push(name.to_owned());
    }
    Some(names)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn program(module: &str) -> Arc<Unit> {
        let text = format!(
            "MODULE {module}\n  TASK PERS tasks all{{2}} := [[\"T_ROB1\"], [\"t_rob2\"]];\n  VAR syncident s1;\n  PROC main()\n    WaitSyncTask s1, all;\n  ENDPROC\nENDMODULE\n"
        );
        Arc::new(Unit::new(format!("{module}.mod"), text, None))
    }

    fn names(modules: &[&str]) -> Option<Vec<String>> {
        let units: Vec<Arc<Unit>> = modules.iter().map(|m| program(m)).collect();
        task_names(&units.iter().collect::<Vec<_>>())
    }

    #[test]
    fn programs_named_for_the_tasks_they_sync_are_one_program_per_task() {
        assert_eq!(
            names(&["Grey_T_ROB1", "GREY_T_ROB2"]),
            Some(vec!["T_ROB1".to_owned(), "T_ROB2".to_owned()])
        );
    }

    #[test]
    fn other_alternative_programs_are_not() {
        // Two versions of one program: no task named in quotes.
        assert_eq!(names(&["Cell_v1", "Cell_v2"]), None);
        // Programs for tasks, but not of one program name.
        assert_eq!(names(&["Grey_T_ROB1", "Blue_T_ROB2"]), None);
        // Two programs for one task.
        assert_eq!(names(&["Grey_T_ROB1", "Grey_t_rob1"]), None);
        // A task name alone is no program's.
        assert_eq!(names(&["T_ROB1", "T_ROB2"]), None);
    }
}
