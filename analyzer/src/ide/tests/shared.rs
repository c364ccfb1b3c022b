//! A system-global persistent shared by the tasks of a backup: references
//! and rename follow it into the tasks that declare it with the same type,
//! and rename is refused when a task declares it with another.

use std::sync::Arc;

use crate::ide::{Location, references, rename, shared_files};
use crate::task::Task;
use crate::workspace::Workspace;

const T1: &str = "B/RAPID/TASK1/PROGMOD/Main.mod";
const T2: &str = "B/RAPID/TASK2/PROGMOD/Main.mod";
const T3: &str = "B/RAPID/TASK3/PROGMOD/Main.mod";

fn workspace(third: &str) -> Workspace {
    let mut ws = Workspace::new();
    ws.set_file(
        T1,
        "MODULE Main\n  PERS bool bWaitForJob := FALSE;\n  TASK PERS num nLocal := 0;\n  PROC main()\n    bWaitForJob := TRUE;\n    nLocal := 1;\n  ENDPROC\nENDMODULE\n".to_owned(),
    );
    ws.set_file(
        T2,
        "MODULE Main\n  PERS bool bWaitForJob;\n  TASK PERS num nLocal := 0;\n  PROC main()\n    WaitUntil bWaitForJob;\n    bWaitForJob := FALSE;\n    nLocal := 2;\n  ENDPROC\nENDMODULE\n".to_owned(),
    );
    ws.set_file(T3, third.to_owned());
    ws
}

const SAME: &str = "MODULE Main\n  PERS bool bWaitForJob;\n  PROC main()\n    IF bWaitForJob Stop;\n  ENDPROC\nENDMODULE\n";
const OTHER_TYPE: &str = "MODULE Main\n  PERS num bWaitForJob;\n  PROC main()\n    bWaitForJob := 1;\n  ENDPROC\nENDMODULE\n";

/// The task of `path`, the offset of the first `name` after `after` in it,
/// and the tasks of the files [`shared_files`] names.
fn at(
    ws: &mut Workspace,
    path: &str,
    after: &str,
    name: &str,
) -> (Arc<Task>, usize, usize, Vec<Arc<Task>>) {
    let task = ws.task_of(path);
    let unit = task
        .units
        .iter()
        .position(|u| u.path == path)
        .expect("the unit");
    let text = &task.units[unit].text;
    let from = text.find(after).expect("the anchor");
    let offset = from + text[from..].find(name).expect("the name");
    let peers = shared_files(&task, unit, offset)
        .iter()
        .map(|p| ws.task_of(p))
        .collect();
    (task, unit, offset, peers)
}

fn count_by_file(found: &[Location]) -> Vec<(String, usize)> {
    let mut out: Vec<(String, usize)> = Vec::new();
    for l in found {
        match out.iter_mut().find(|(p, _)| *p == l.path) {
            Some((_, n)) => *n += 1,
            None => out.push((l.path.clone(), 1)),
        }
    }
    out.sort();
    out
}

#[test]
fn references_and_rename_follow_a_shared_persistent_into_every_task() {
    let mut ws = workspace(SAME);
    let (task, unit, offset, peers) = at(&mut ws, T2, "WaitUntil", "bWaitForJob");
    assert_eq!(peers.len(), 2);
    let found = references(&task, unit, offset, true, &peers);
    assert_eq!(
        count_by_file(&found),
        vec![(T1.into(), 2), (T2.into(), 3), (T3.into(), 2)]
    );
    // without the declarations
    assert_eq!(references(&task, unit, offset, false, &peers).len(), 4);
    let edits = rename(&task, unit, offset, "bJobReady", &peers).unwrap_or_else(|e| panic!("{e}"));
    let summary: Vec<(String, usize)> = edits.iter().map(|(p, e)| (p.clone(), e.len())).collect();
    assert_eq!(
        summary,
        vec![(T1.into(), 2), (T2.into(), 3), (T3.into(), 2)]
    );
    // a clash in another task refuses the rename
    let clash = SAME.replace("  PROC main()", "  VAR bool bJobReady;\n  PROC main()");
    let mut ws = workspace(&clash);
    let (task, unit, offset, peers) = at(&mut ws, T1, "main()", "bWaitForJob");
    let refused = rename(&task, unit, offset, "bJobReady", &peers);
    assert!(refused.is_err(), "{refused:?}");
}

/// The unused-data hint is for routine data and `LOCAL` module data: a
/// shared persistent that one task only declares (the others use it) gets
/// none.
#[test]
fn a_shared_persistent_that_one_task_only_declares_is_not_unused() {
    let only_declared =
        "MODULE Main\n  PERS bool bWaitForJob;\n  PROC main()\n  ENDPROC\nENDMODULE\n";
    let mut ws = workspace(only_declared);
    let found = ws.diagnostics(T3);
    assert!(found.is_empty(), "{found:?}");
}

#[test]
fn task_persistents_and_routine_data_stay_in_their_task() {
    let mut ws = workspace(SAME);
    let (task, unit, offset, peers) = at(&mut ws, T1, "main()", "nLocal");
    assert!(peers.is_empty());
    let found = references(&task, unit, offset, true, &peers);
    assert_eq!(count_by_file(&found), vec![(T1.into(), 2)]);
}

#[test]
fn rename_is_refused_when_a_task_declares_it_with_another_type() {
    let mut ws = workspace(OTHER_TYPE);
    let (task, unit, offset, peers) = at(&mut ws, T1, "main()", "bWaitForJob");
    let why = rename(&task, unit, offset, "bJobReady", &peers).expect_err("refused");
    assert!(
        why.contains("TASK3") && why.contains("`num`") && why.contains("`bool`"),
        "{why}"
    );
    // references keep to the tasks that share the datum
    let found = references(&task, unit, offset, true, &peers);
    assert_eq!(count_by_file(&found), vec![(T1.into(), 2), (T2.into(), 3)]);
}
