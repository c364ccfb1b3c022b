//! The workspace's cache of file checks: each file's last diagnostics,
//! with the inputs they were computed from, and the statement results of
//! its last check (so the next check after an edit re-checks only the
//! statements it changed).
//!
//! A check can run outside the workspace (a language server runs it off
//! its lock): [`Workspace::check`] hands out a [`Check`] holding the file,
//! its task and the statement results, [`Check::run`] computes, and
//! [`Workspace::finish`] takes the result back.

use std::sync::{Arc, Weak};

use super::Workspace;
use crate::check::StmtCache;
use crate::diagnostic::Diagnostic;
use crate::layout::Grouping;
use crate::rules::Selection;
use crate::task::{Task, Unit};

/// What a file's check reads of its task besides the file's own text: the
/// key of a cached result, which is valid while these are equal.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct CheckInputs {
    /// What the task's modules, configuration, catalogue view, task ids
    /// and shared persistents declare ([`Task::interface`]).
    pub interface: u64,
    /// The task's constant values and array sizes ([`Task::constants`]).
    pub constants: u64,
    pub grouping: Grouping,
    pub complete: bool,
    pub loaded_elsewhere: bool,
    /// In a view of the task, the unit it is made for (what it leaves out
    /// follows from the group's interface and the owner).
    pub owner: Option<usize>,
}

impl CheckInputs {
    pub fn of(task: &Task) -> CheckInputs {
        CheckInputs {
            interface: task.interface,
            constants: task.constants,
            grouping: task.grouping,
            complete: task.complete,
            loaded_elsewhere: task.loaded_elsewhere,
            owner: task.owner,
        }
    }
}

/// A file's last check.
pub(super) struct Checked {
    unit: Arc<Unit>,
    inputs: CheckInputs,
    /// The workspace's configuration revision when the check was handed
    /// out ([`Workspace::revision`]).
    revision: u64,
    /// The rules checked.
    selection: Selection,
    diagnostics: Arc<Vec<Diagnostic>>,
    /// The other files its diagnostics point into (related locations), as
    /// they were: an edit there moves what they point at even when the
    /// task's interface (which ignores positions) stays the same.
    related: Vec<(String, Weak<Unit>)>,
    /// Statement results, for the next check of this file.
    pub(super) statements: StmtCache,
}

/// A check of one file handed out by [`Workspace::check`], to run anywhere.
pub struct Check {
    pub path: String,
    pub unit: Arc<Unit>,
    pub task: Arc<Task>,
    revision: u64,
    selection: Selection,
    statements: StmtCache,
}

/// The result of a [`Check`], for [`Workspace::finish`].
pub struct CheckResult {
    pub path: String,
    pub diagnostics: Arc<Vec<Diagnostic>>,
    checked: Checked,
}

impl Check {
    /// Checks the file: syntax, then the selected rules' checks, in source
    /// order.
    pub fn run(self) -> CheckResult {
        let (diagnostics, statements) =
            diagnostics_selected(&self.task, &self.unit, self.statements, &self.selection);
        let related = related_units(&self.task, &self.unit, &diagnostics);
        let diagnostics = Arc::new(diagnostics);
        CheckResult {
            path: self.path,
            diagnostics: diagnostics.clone(),
            checked: Checked {
                inputs: CheckInputs::of(&self.task),
                unit: self.unit,
                revision: self.revision,
                selection: self.selection,
                diagnostics,
                related,
                statements,
            },
        }
    }
}

/// The other units of `task` that `diagnostics` (of `unit`) point into.
fn related_units(
    task: &Task,
    unit: &Unit,
    diagnostics: &[Diagnostic],
) -> Vec<(String, Weak<Unit>)> {
    let paths: std::collections::BTreeSet<&str> = diagnostics
        .iter()
        .flat_map(|d| &d.related)
        .filter_map(|r| r.file.as_deref())
        .filter(|p| *p != unit.path)
        .collect();
    if paths.is_empty() {
        return Vec::new();
    }
    task.live_units()
        .filter(|(_, u)| paths.contains(u.path.as_str()))
        .map(|(_, u)| (u.path.clone(), Arc::downgrade(u)))
        .collect()
}

impl Workspace {
    /// The revision of everything but the files' texts (configuration,
    /// programs, the controller, extra paths, unreadable files): bumped
    /// whenever one of them changes.
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The last diagnostics of `path`, when they were computed for `unit`
    /// in a task with `task`'s inputs, for the rules of `selection`.
    pub fn cached(
        &self,
        path: &str,
        unit: &Arc<Unit>,
        task: &Task,
        selection: &Selection,
    ) -> Option<Arc<Vec<Diagnostic>>> {
        let c = self.checked.get(path)?;
        let same_related = c.related.iter().all(|(p, was)| {
            self.units
                .get(p)
                .or_else(|| self.extras.iter().find(|u| u.path == *p))
                .is_some_and(|now| std::ptr::eq(Arc::as_ptr(now), was.as_ptr()))
        });
        (Arc::ptr_eq(&c.unit, unit)
            && c.inputs == CheckInputs::of(task)
            && c.selection == *selection
            && same_related)
            .then(|| c.diagnostics.clone())
    }

    /// The last diagnostics of `path` when they are of another text than
    /// `unit`'s under the current configuration, with that text's unit:
    /// what [`crate::carry::carry_over`] moves past the edit.
    pub fn previous(
        &self,
        path: &str,
        unit: &Arc<Unit>,
    ) -> Option<(Arc<Unit>, Arc<Vec<Diagnostic>>)> {
        let c = self.checked.get(path)?;
        (!Arc::ptr_eq(&c.unit, unit) && c.revision == self.revision)
            .then(|| (c.unit.clone(), c.diagnostics.clone()))
    }

    /// A check of `unit` as the file `path` in `task` for the rules of
    /// `selection`, taking the statement results of the file's last check
    /// (a check still running for an older text finds none when it
    /// finishes, and the next starts afresh).
    pub fn check(
        &mut self,
        path: &str,
        unit: Arc<Unit>,
        task: Arc<Task>,
        selection: Selection,
    ) -> Check {
        let statements = self
            .checked
            .get_mut(path)
            .map(|c| std::mem::take(&mut c.statements))
            .unwrap_or_default();
        Check {
            path: path.to_owned(),
            unit,
            task,
            revision: self.revision,
            selection,
            statements,
        }
    }

    /// Keeps the result of a check as the file's last one; its statement
    /// results too when `keep_statements` (a file that is edited).
    pub fn finish(&mut self, result: CheckResult, keep_statements: bool) {
        let mut checked = result.checked;
        if !keep_statements {
            checked.statements = StmtCache::default();
        }
        self.checked.insert(result.path, checked);
    }

    /// Forgets the last check of `path`.
    pub fn forget_check(&mut self, path: &str) {
        self.checked.remove(path);
    }

    /// The diagnostics of a file: syntax first, then the checks, in source
    /// order. Reuses the last result while neither the file nor what its
    /// check reads of its task ([`CheckInputs`]) changed.
    pub fn diagnostics(&mut self, path: &str) -> Arc<Vec<Diagnostic>> {
        let Some(unit) = self.units.get(path).cloned() else {
            return Arc::default();
        };
        let task = self.task_of(path);
        let all = Selection::all();
        if let Some(d) = self.cached(path, &unit, &task, &all) {
            return d;
        }
        let result = self.check(path, unit, task, all).run();
        let diagnostics = result.diagnostics.clone();
        self.finish(result, true);
        diagnostics
    }
}

/// The diagnostics of one unit of a task, computed afresh: syntax, then
/// semantic, sorted by position.
pub fn diagnostics_of(task: &Task, unit: &Arc<Unit>) -> Vec<Diagnostic> {
    diagnostics_selected(task, unit, StmtCache::default(), &Selection::all()).0
}

/// [`diagnostics_of`], reusing the statement results of an earlier check of
/// the same file; returns them for the next check.
pub fn diagnostics_cached(
    task: &Task,
    unit: &Arc<Unit>,
    cache: StmtCache,
) -> (Vec<Diagnostic>, StmtCache) {
    diagnostics_selected(task, unit, cache, &Selection::all())
}

/// [`diagnostics_cached`] with only the rules `selection` has on checked
/// (syntax diagnostics are always given).
pub fn diagnostics_selected(
    task: &Task,
    unit: &Arc<Unit>,
    cache: StmtCache,
    selection: &Selection,
) -> (Vec<Diagnostic>, StmtCache) {
    let mut out = unit.syntax.clone();
    let mut next = StmtCache::default();
    if let Some(idx) = task.index_of(unit) {
        let (found, cache) = crate::check::check_unit_cached(task, idx, cache, selection);
        out.extend(found);
        next = cache;
    }
    out.sort_by_key(|d| (d.range.start, d.range.end));
    (out, next)
}
