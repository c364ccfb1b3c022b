//! A task's interrupts: interrupt numbers connected to trap routines
//! (`CONNECT`), timers (`ITimer`), signal watches (`ISignalDI`...),
//! persistent watches (`IPers`), and the interrupts that occurred and wait
//! for their trap routine.

use std::collections::{HashMap, HashSet, VecDeque};

use rapid_analyzer::names::fold;

#[derive(Default)]
pub(crate) struct Interrupts {
    next: i32,
    traps: HashMap<i32, u32>,
    timers: Vec<Timer>,
    watches: Vec<Watch>,
    pending: VecDeque<i32>,
    pub disabled: bool,
    sleeping: HashSet<i32>,
    /// `IPers`: the persistent watched and its value when last seen.
    pub pers: Vec<PersWatch>,
}

pub(crate) struct PersWatch {
    pub id: i32,
    pub place: crate::machine::Place,
    pub last: rapid_evaluator::Value,
    pub single: bool,
}

struct Timer {
    id: i32,
    period: f64,
    due: f64,
    single: bool,
}

struct Watch {
    id: i32,
    /// The signal, folded.
    signal: String,
    /// The value that triggers it; `None`: any change.
    value: Option<f64>,
    single: bool,
}

impl Interrupts {
    /// Connects a new interrupt number to a trap routine.
    pub(crate) fn connect(&mut self, trap: u32) -> i32 {
        self.next += 1;
        self.traps.insert(self.next, trap);
        self.next
    }

    pub(crate) fn is_connected(&self, id: i32) -> bool {
        self.traps.contains_key(&id)
    }

    pub(crate) fn add_timer(&mut self, id: i32, now: f64, period: f64, single: bool) {
        self.timers.retain(|t| t.id != id);
        self.timers.push(Timer {
            id,
            period,
            due: now + period,
            single,
        });
    }

    pub(crate) fn add_watch(&mut self, id: i32, signal: &str, value: Option<f64>, single: bool) {
        self.watches.retain(|w| w.id != id);
        self.watches.push(Watch {
            id,
            signal: fold(signal),
            value,
            single,
        });
    }

    /// `IDelete`: the interrupt is cancelled and disconnected.
    pub(crate) fn delete(&mut self, id: i32) {
        self.traps.remove(&id);
        self.timers.retain(|t| t.id != id);
        self.watches.retain(|w| w.id != id);
        self.pers.retain(|w| w.id != id);
        self.pending.retain(|p| *p != id);
    }

    pub(crate) fn sleep(&mut self, id: i32, on: bool) {
        if on {
            self.sleeping.insert(id);
        } else {
            self.sleeping.remove(&id);
        }
    }

    /// `IPers`: an interrupt each time the persistent at `place` changes
    /// from `now` (its value as the watch starts).
    pub(crate) fn add_pers(
        &mut self,
        id: i32,
        place: crate::machine::Place,
        now: rapid_evaluator::Value,
        single: bool,
    ) {
        self.pers.retain(|w| w.id != id);
        self.pers.push(PersWatch {
            id,
            place,
            last: now,
            single,
        });
    }

    /// The persistents watched changed: each changed value (`changed`, by
    /// watch) raises its interrupt.
    pub(crate) fn pers_changed(&mut self, changed: &[(usize, rapid_evaluator::Value)]) {
        let mut done = Vec::new();
        for (i, v) in changed {
            if let Some(w) = self.pers.get_mut(*i) {
                w.last = v.clone();
                done.push((w.id, w.single));
            }
        }
        for (id, single) in done {
            self.raise(id);
            if single {
                self.pers.retain(|w| w.id != id);
            }
        }
    }

    fn raise(&mut self, id: i32) {
        if !self.sleeping.contains(&id) && self.traps.contains_key(&id) {
            self.pending.push_back(id);
        }
    }

    /// A signal changed to `value`: the watches it triggers.
    pub(crate) fn signal_changed(&mut self, name: &str, value: f64) {
        let key = fold(name);
        let mut fired = Vec::new();
        for w in &self.watches {
            if w.signal == key && w.value.is_none_or(|v| v == value) {
                fired.push((w.id, w.single));
            }
        }
        for (id, single) in fired {
            self.raise(id);
            if single {
                self.watches.retain(|w| w.id != id);
            }
        }
    }

    /// The time the next timer expires.
    pub(crate) fn next_due(&self) -> Option<f64> {
        self.timers.iter().map(|t| t.due).reduce(f64::min)
    }

    /// The timers due by `t` expire.
    pub(crate) fn expire(&mut self, t: f64) {
        let mut due = Vec::new();
        for timer in &mut self.timers {
            if timer.due <= t {
                due.push((timer.id, timer.single));
                timer.due += timer.period.max(0.001);
            }
        }
        for (id, single) in due {
            self.raise(id);
            if single {
                self.timers.retain(|tm| tm.id != id);
            }
        }
    }

    pub(crate) fn has_pending(&self) -> bool {
        !self.pending.is_empty()
    }

    /// The next interrupt that occurred, with its trap routine.
    pub(crate) fn next_pending(&mut self) -> Option<(i32, u32)> {
        while let Some(id) = self.pending.pop_front() {
            if let Some(&trap) = self.traps.get(&id) {
                return Some((id, trap));
            }
        }
        None
    }
}
