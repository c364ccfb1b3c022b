//! Rendezvous of tasks: `WaitSyncTask` and `SyncMoveOn`/`SyncMoveOff`.
//! Each synchronization point is known by the name of its `syncident`
//! variable (every cooperating task declares one of that name) and holds
//! the tasks it waits for (from the task list given) and those arrived; a
//! round ends when every task of the list has arrived, and every task of
//! it goes on.

use std::collections::{BTreeMap, BTreeSet};

#[derive(Default)]
pub(crate) struct Sync {
    points: BTreeMap<String, Point>,
    /// The tasks each task moves in synchronization with (`SyncMoveOn`
    /// done), by task number.
    groups: BTreeMap<usize, Vec<String>>,
}

#[derive(Default)]
struct Point {
    /// The round in progress.
    round: u64,
    /// The tasks the round waits for (numbers), from the first task list
    /// given.
    expected: BTreeSet<usize>,
    /// The tasks arrived in the round.
    arrived: BTreeSet<usize>,
    /// The task names of the round's list, for a synchronized movement.
    names: Vec<String>,
}

impl Sync {
    /// Task `task` arrives at point `key` (of a round that waits for
    /// `expected`); the round it is in, and whether it is complete now.
    pub(crate) fn arrive(
        &mut self,
        key: &str,
        task: usize,
        expected: &[usize],
        names: &[String],
    ) -> (u64, bool) {
        let p = self.points.entry(key.to_owned()).or_default();
        if p.arrived.is_empty() {
            p.expected = expected.iter().copied().collect();
            p.names = names.to_vec();
        }
        p.expected.insert(task);
        p.arrived.insert(task);
        let round = p.round;
        let complete = p.expected.is_subset(&p.arrived);
        if complete {
            if key.starts_with("movon:") {
                for &t in &p.arrived {
                    self.groups.insert(t, p.names.clone());
                }
            } else if key.starts_with("movoff:") {
                for &t in &p.arrived {
                    self.groups.remove(&t);
                }
            }
            p.round += 1;
            p.arrived.clear();
            p.expected.clear();
        }
        (round, complete)
    }

    /// Has round `round` of point `key` ended?
    pub(crate) fn released(&self, key: &str, round: u64) -> bool {
        self.points.get(key).is_some_and(|p| p.round > round)
    }

    /// Task `task` gives up waiting at point `key` (a time-out).
    pub(crate) fn leave(&mut self, key: &str, task: usize) {
        if let Some(p) = self.points.get_mut(key) {
            p.arrived.remove(&task);
            if p.arrived.is_empty() {
                p.expected.clear();
            }
        }
    }

    /// The tasks `task` moves in synchronization with, after a
    /// `SyncMoveOn`.
    pub(crate) fn group_of(&self, task: usize) -> Option<Vec<String>> {
        self.groups.get(&task).cloned()
    }

    /// `SyncMoveUndo`: the task moves on its own again.
    pub(crate) fn undo(&mut self, task: usize) {
        self.groups.remove(&task);
    }
}
