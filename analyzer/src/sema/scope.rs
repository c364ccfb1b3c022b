//! What a name means from inside a module: the one lookup of a module's
//! own items and the task's globals, for the checker and constant
//! evaluation alike.

use crate::task::{ItemRef, Task};

/// The items visible under the folded name `key` from module `module` of
/// unit `unit`: the module's own items (any scope, `LOCAL` ones included)
/// if it declares the name, else the task's globals. `module` is `None`
/// outside any module (only globals are visible).
pub(crate) fn visible(task: &Task, unit: usize, module: Option<usize>, key: &str) -> Vec<ItemRef> {
    let here = |r: &&ItemRef| r.unit == unit && Some(r.module) == module;
    let mut own: Vec<ItemRef> = Vec::new();
    if let Some(locals) = task.locals.get(key) {
        own.extend(locals.iter().filter(here));
    }
    if let Some(globals) = task.globals.get(key) {
        own.extend(globals.iter().filter(here));
        if own.is_empty() {
            return globals.clone();
        }
    }
    own
}
