//! The names of a backup's tasks when the backup does not say them.
//!
//! A controller calls its tasks what `SYS.cfg` says (`T_ROB1`, `T_Gantry`);
//! a backup keeps each task's modules in a numbered folder (`RAPID/TASK7`)
//! and says the names in `SYSPAR/SYS.cfg` and `BACKINFO/backinfo.txt`. A
//! repository that keeps only the modules loses them, and a program that
//! names a task (`CJointT \TaskName:="T_Gantry"`, the `tasks` list of a
//! `WaitSyncTask`, `IF GetTaskName() = "T_ROB1"`) would name no task. The
//! program is the evidence then: each task name it uses that no task has
//! is given to a numbered folder, `T_ROBn` to `TASKn` (RobotWare calls the
//! n-th robot's task `T_ROBn`, and a MultiMove system lists its robots'
//! tasks first), any other name to the one folder whose modules are named
//! for it (`T_Gantry` to the folder of `Gantry_MainModule.mod`), and
//! every task knows its `taskid` (`T_GantryId`). Each name given is a
//! note.

use std::sync::Arc;

use rapid_analyzer::names::fold;
use rapid_analyzer::task::Task;

use super::load::TaskToRun;

/// The task names the modules of `task` use in quotes: a `\TaskName`
/// argument, the items of a `tasks` list, what `GetTaskName()` is
/// compared with.
fn used_names(task: &Task) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut add = |name: &str| {
        let name = name.trim();
        let fits = !name.is_empty()
            && name.len() <= 32
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if fits && !out.iter().any(|n| n.eq_ignore_ascii_case(name)) {
            out.push(name.to_owned());
        }
    };
    for unit in task.units.iter() {
        for statement in unit.text.split(';') {
            let code: String = statement
                .lines()
                .map(|l| l.split('!').next().unwrap_or_default())
                .collect::<Vec<_>>()
                .join("\n");
            let lower = code.to_ascii_lowercase();
            let words: Vec<&str> = lower.split_whitespace().collect();
            let is_list = words
                .windows(2)
                .any(|w| matches!(w[0], "pers" | "var" | "const") && w[1] == "tasks");
            if is_list && lower.contains(":=") {
                code.split('"').skip(1).step_by(2).for_each(&mut add);
                continue;
            }
            // A comparison with the task's own name (`IF GetTaskName() =
            // "T_ROB1"`).
            for line in code.lines() {
                if line.to_ascii_lowercase().contains("gettaskname(") {
                    line.split('"').skip(1).step_by(2).for_each(&mut add);
                }
            }
            let mut rest = lower.as_str();
            while let Some(at) = rest.find("taskname") {
                let after = rest[at + "taskname".len()..].trim_start();
                if let Some(value) = after.strip_prefix(":=")
                    && let Some(quoted) = value.trim_start().strip_prefix('"')
                    && let Some(end) = quoted.find('"')
                {
                    // The spelling as written.
                    let start = code.len() - quoted.len();
                    add(&code[start..start + end]);
                }
                rest = &rest[at + "taskname".len()..];
            }
        }
    }
    out
}

/// `TASKn`'s number ([`rapid_analyzer::layout::task_folder_number`]).
pub(crate) use rapid_analyzer::layout::task_folder_number as folder_number;

/// Names the numbered tasks of a backup whose names are not known (each
/// is called as its folder, `TASKn`) for the task names their program
/// uses; a note for each name given.
pub fn name_from_use(tasks: &mut [TaskToRun]) -> Vec<String> {
    let unknown = |t: &TaskToRun| t.task.is_backup() && folder_number(&t.name).is_some();
    if tasks.is_empty() || !tasks.iter().all(unknown) {
        return Vec::new();
    }
    give_names(tasks)
}

/// [`name_from_use`], the tasks known to be numbered folders.
fn give_names(tasks: &mut [TaskToRun]) -> Vec<String> {
    let mut used: Vec<String> = Vec::new();
    for t in tasks.iter() {
        for n in used_names(&t.task) {
            if !used.iter().any(|u| u.eq_ignore_ascii_case(&n)) {
                used.push(n);
            }
        }
    }
    used.retain(|n| !tasks.iter().any(|t| t.name.eq_ignore_ascii_case(n)));
    let mut given = vec![false; tasks.len()];
    let mut notes = Vec::new();
    let mut give = |tasks: &mut [TaskToRun], i: usize, name: &str, why: &str| {
        notes.push(format!(
            "note: the backup does not say what its tasks are called (no SYS.cfg, no BACKINFO): {} is taken to be {name}, {why}",
            tasks[i].name
        ));
        name.clone_into(&mut tasks[i].name);
    };
    // `T_ROBn` first: the folders of the other names are the rest.
    for name in &used {
        let Some(n) = name
            .get(..5)
            .filter(|p| p.eq_ignore_ascii_case("t_rob"))
            .and_then(|_| name[5..].parse::<u32>().ok())
        else {
            continue;
        };
        if let Some(i) =
            (0..tasks.len()).find(|&i| !given[i] && folder_number(&tasks[i].name) == Some(n))
        {
            given[i] = true;
            let why = format!("as RobotWare calls the task of robot {n}");
            give(tasks, i, name, &why);
        }
    }
    for name in &used {
        if tasks.iter().any(|t| t.name.eq_ignore_ascii_case(name)) {
            continue;
        }
        let stem = name
            .get(..2)
            .filter(|p| p.eq_ignore_ascii_case("t_"))
            .map_or(name.as_str(), |_| &name[2..])
            .to_ascii_lowercase();
        if stem.len() < 3 {
            continue;
        }
        let named_for = |t: &TaskToRun| {
            t.task.units.iter().any(|u| {
                let file = u.path.rsplit(['/', '\\']).next().unwrap_or(&u.path);
                file.to_ascii_lowercase().contains(&stem)
                    || u.items
                        .modules
                        .iter()
                        .any(|m| m.name.to_ascii_lowercase().contains(&stem))
            })
        };
        let fits: Vec<usize> = (0..tasks.len())
            .filter(|&i| !given[i] && named_for(&tasks[i]))
            .collect();
        if let [i] = fits[..] {
            given[i] = true;
            give(tasks, i, name, "its modules are named for it");
        }
    }
    if !notes.is_empty() {
        with_task_ids(tasks);
    }
    notes
}

/// Every task knows the `taskid` of each task by its name
/// (`T_GantryId`), as RobotWare declares one for each task.
fn with_task_ids(tasks: &mut [TaskToRun]) {
    let ids: Vec<String> = tasks
        .iter()
        .map(|t| fold(&format!("{}Id", t.name)))
        .collect();
    for t in tasks {
        let mut task = (*t.task).clone();
        let mut known = (*task.task_ids).clone();
        known.extend(ids.iter().cloned());
        task.set_controller_names((*task.mecunits).clone(), known);
        t.task = Arc::new(task);
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use rapid_analyzer::task::{TaskKind, Unit};

    use super::*;

    fn task(folder: &str, modules: &[(&str, &str)]) -> TaskToRun {
        let units = modules
            .iter()
            .map(|(file, text)| {
                Arc::new(Unit::new(
                    format!("cell/RAPID/{folder}/PROGMOD/{file}"),
                    (*text).to_owned(),
                    None,
                ))
            })
            .collect();
        TaskToRun {
            name: folder.to_owned(),
            task: Arc::new(Task::new(format!("cell/RAPID/{folder}"), units, None)),
            kind: TaskKind::Normal,
            entry: "main".to_owned(),
            motion: true,
            checked: None,
        }
    }

    const STATIC: &str = "MODULE Watch
  PERS tasks tlAll{2} := [[\"T_ROB1\"], [\"t_rob2\"]]; ! \"T_Comment\"
  PROC main()
    VAR jointtarget j;
    j := CJointT(\\TaskName:=\"T_Gantry\");
    j := CJointT(\\TaskName := \"T_Painter\");
    TPWrite \"T_NotATask\";
    IF GetTaskName() = \"T_Weld\" TPWrite GetTaskName() + \" is here\";
  ENDPROC
ENDMODULE
";

    #[test]
    fn the_names_a_program_uses_are_its_task_lists_and_task_name_arguments() {
        let t = task("TASK9", &[("Watch.mod", STATIC)]);
        assert_eq!(
            used_names(&t.task),
            ["T_ROB1", "t_rob2", "T_Gantry", "T_Painter", "T_Weld"]
        );
    }

    #[test]
    fn robots_tasks_go_to_their_numbers_and_other_names_to_the_folder_named_for_them() {
        let main = "MODULE M\n  PROC main()\n  ENDPROC\nENDMODULE\n";
        let mut tasks = vec![
            task("TASK1", &[("Rob1_Main.mod", main)]),
            task("TASK2", &[("Rob2_Main.mod", main)]),
            task("TASK7", &[("Gantry_Main.mod", main)]),
            task("TASK9", &[("Watch.mod", STATIC)]),
        ];
        let notes = give_names(&mut tasks);
        let names: Vec<&str> = tasks.iter().map(|t| t.name.as_str()).collect();
        // No folder is named for T_Painter: it stays no task's name.
        assert_eq!(names, ["T_ROB1", "t_rob2", "T_Gantry", "TASK9"]);
        assert_eq!(notes.len(), 3);
        assert!(
            notes[2].contains("TASK7 is taken to be T_Gantry"),
            "{notes:?}"
        );
    }

    #[test]
    fn a_name_two_folders_could_have_is_given_to_neither() {
        let main = "MODULE M\n  PROC main()\n  ENDPROC\nENDMODULE\n";
        let mut tasks = vec![
            task("TASK3", &[("Gantry_A.mod", main)]),
            task("TASK4", &[("Gantry_B.mod", main)]),
            task("TASK9", &[("Watch.mod", STATIC)]),
        ];
        assert!(give_names(&mut tasks).is_empty());
        assert_eq!(tasks[0].name, "TASK3");
    }
}
