//! A system-global persistent (`PERS`, neither `TASK` nor `LOCAL`) is one
//! datum for the whole controller: every task of a backup that declares it
//! with the same type shares its value. References and rename follow it
//! into those tasks (the caller hands them over: each task is analysed on
//! its own); rename is refused when a task declares it with another type
//! (rule `shared-persistent-mismatch` says the same of the declarations).

use std::sync::Arc;

use super::resolve::Def;
use crate::items::DataDecl;
use crate::names::fold;
use crate::rules::shared_persistent_mismatch::{elsewhere, own_display, same_datum, task_name};
use crate::task::{Item, ItemRef, SharedPers, Task};

/// The module data `def` denotes, if it is some.
fn data_decl<'t>(task: &'t Task, def: &Def<'_>) -> Option<&'t DataDecl> {
    match def {
        Def::Item(r) if matches!(r.item, Item::Data(_)) => task.data(*r),
        _ => None,
    }
}

/// The other tasks' declarations of the shared persistent `def` (of
/// `task`), each with whether it is the same datum; empty when `def` is
/// not a shared persistent.
pub(crate) fn declarations<'t>(task: &'t Task, def: &Def<'_>) -> Vec<(&'t SharedPers, bool)> {
    let Some(decl) = data_decl(task, def) else {
        return Vec::new();
    };
    let Some(unit) = def.location(task).and_then(|(u, _, _)| task.units.get(u)) else {
        return Vec::new();
    };
    elsewhere(task, decl)
        .into_iter()
        .map(|o| (o, same_datum(task, &unit.text, decl, o)))
        .collect()
}

/// The files of other tasks that declare the shared persistent `def`, so
/// that the caller can hand their tasks to [`linked`].
pub(crate) fn files(task: &Task, def: &Def<'_>) -> Vec<String> {
    let mut out: Vec<String> = declarations(task, def)
        .into_iter()
        .map(|(o, _)| o.path.clone())
        .collect();
    out.sort();
    out.dedup();
    out
}

/// Why `def` cannot be renamed in `task` alone: another task declares the
/// same persistent with another type (so it is not the same datum, and a
/// rename would leave one of them behind).
pub(crate) fn rename_refusal(task: &Task, def: &Def<'_>) -> Option<String> {
    let decl = data_decl(task, def)?;
    let (other, _) = declarations(task, def)
        .into_iter()
        .find(|(_, same)| !same)?;
    let text = def
        .location(task)
        .and_then(|(u, _, _)| task.units.get(u))
        .map(|u| u.text.as_str())
        .unwrap_or_default();
    let here = decl
        .ty
        .as_ref()
        .map(|t| own_display(text, decl, &t.name))
        .unwrap_or_default();
    Some(format!(
        "`{}` is a persistent shared by the tasks of the controller, but {} declares it as `{}` and this task as `{here}`: make the declarations agree before renaming it",
        decl.name,
        task_name(other),
        other.display()
    ))
}

/// The declaration, in each task of `peers` that shares it, of the shared
/// persistent `def` of `task`: that task and the persistent's item there.
/// Tasks that declare it with another type are left out.
pub(crate) fn linked<'p>(
    task: &Task,
    def: &Def<'_>,
    peers: &'p [Arc<Task>],
) -> Vec<(&'p Task, ItemRef)> {
    let shared: Vec<&SharedPers> = declarations(task, def)
        .into_iter()
        .filter(|(_, same)| *same)
        .map(|(o, _)| o)
        .collect();
    if shared.is_empty() {
        return Vec::new();
    }
    let name = fold(&def.name(task));
    let mut out: Vec<(&Task, ItemRef)> = Vec::new();
    for peer in peers {
        if peer.key == task.key || out.iter().any(|(t, _)| t.key == peer.key) {
            continue;
        }
        let Some(r) = peer.globals.get(&name).and_then(|refs| {
            refs.iter().copied().find(|r| {
                let path = peer.units.get(r.unit).map(|u| u.path.as_str());
                peer.data(*r).is_some()
                    && shared
                        .iter()
                        .any(|o| o.task == peer.key && Some(o.path.as_str()) == path)
            })
        }) else {
            continue;
        };
        out.push((peer.as_ref(), r));
    }
    out
}
