//! The MultiMove checks of a routine: one walk of its lowered body
//! ([`crate::sema::sync`]) for the rules that follow the synchronised mode
//! (`unpaired-sync-move`, `missing-sync-id`), a look before each
//! synchronisation point (`sync-without-stop-point`), and its points and
//! synchronised runs against the other tasks' of the controller
//! (`sync-task-mismatch`, `sync-move-count`, from [`crate::task::Task`]'s
//! synchronisation index). Only routines that name `SyncMove...` or
//! `WaitSyncTask` are lowered, once ([`crate::task::Unit::sync_bodies`]).

use super::Cx;
use crate::body::{Call, Callee};
use crate::items::RoutineDecl;
use crate::names::{fold, same};
use crate::rules;
use crate::sema::sync::{CallKinds, callee_name, mentions_sync};
use crate::task::{Item, Task};

pub(super) fn check(cx: &mut Cx<'_>, decl: &RoutineDecl) {
    let unit = cx.unit;
    let Some(body) = unit.sync_body(decl) else {
        return;
    };
    let kinds = TaskCalls { task: cx.task };
    if let Some(flow) = crate::sema::sync::flow(body, &kinds) {
        rules::unpaired_sync_move::check(cx, &flow);
        rules::missing_sync_id::check(cx, &flow);
    }
    rules::sync_without_stop_point::check(cx, body, &kinds);
    rules::sync_task_mismatch::check(cx, decl.range.clone());
    rules::sync_move_count::check(cx, decl.range.clone());
}

/// The calls of a routine as its task sees them.
pub(crate) struct TaskCalls<'t> {
    pub task: &'t Task,
}

impl TaskCalls<'_> {
    /// The routines of the task (global or local) named `name`, with the
    /// text of their declarations.
    fn user_routines(&self, name: &str) -> impl Iterator<Item = &str> {
        let key = fold(name);
        let refs: Vec<_> = self
            .task
            .globals
            .refs(&key)
            .chain(self.task.locals.refs(&key))
            .collect();
        refs.into_iter()
            .filter(|r| matches!(r.item, Item::Routine(_)))
            .filter_map(|r| {
                let decl = self.task.routine(r)?;
                self.task.unit(r.unit)?.text.get(decl.range.clone())
            })
    }

    /// The built-in instruction a call names, unless the task hides it.
    pub(crate) fn builtin(&self, call: &Call) -> Option<&'static crate::catalogue::Routine> {
        let name = callee_name(call);
        if name.is_empty() || self.user_routines(name).next().is_some() {
            return None;
        }
        self.task.catalogue.instruction(name)
    }
}

impl CallKinds for TaskCalls<'_> {
    fn is_builtin(&self, call: &Call, name: &str) -> bool {
        same(callee_name(call), name) && self.builtin(call).is_some()
    }

    fn is_move(&self, call: &Call) -> bool {
        // A move whose parameters come from loaded code (the Arc
        // instructions) is not checked.
        self.builtin(call).is_some_and(|r| {
            r.signature_known
                && r.params
                    .iter()
                    .any(|p| same(&p.name, "ID") && same(&p.ty, "identno"))
        })
    }

    fn may_change_mode(&self, call: &Call) -> bool {
        match &call.callee {
            Callee::Late(_) => true,
            Callee::Name(name) => self.user_routines(name).any(mentions_sync),
        }
    }
}
