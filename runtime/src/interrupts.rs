//! A task's interrupts: interrupt numbers connected to trap routines
//! (`CONNECT`), timers (`ITimer`), signal watches (`ISignalDI`...),
//! persistent watches (`IPers`), error watches (`IError`, on the entries
//! of the controller's event log), and the interrupts that occurred and
//! wait for their trap routine.

use crate::machine::{PathMark, PathState, due_on};
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
    errors: Vec<ErrorWatch>,
    /// The event log entry each `IError` interrupt was raised for (its
    /// index in [`crate::controller::Shared::event_log`]).
    error_entries: HashMap<i32, usize>,
    /// `IRMQMessage`: the data type (folded) whose messages raise each
    /// interrupt.
    pub rmq: Vec<(String, i32)>,
}

/// An entry of the controller's event log: its domain (`USER_DEF_ERR`,
/// 8, for `ErrWrite`), number within the domain, type (`TYPE_ERR` 3,
/// `TYPE_WARN` 2, `TYPE_STATE` 1), title and text lines.
#[derive(Clone, Debug)]
pub(crate) struct LogEntry {
    pub domain: u32,
    pub number: u32,
    pub kind: u32,
    pub title: String,
    pub lines: Vec<String>,
}

/// `IError ErrorDomain [\ErrorId] ErrorType`: `COMMON_ERR` (0) is every
/// domain, `TYPE_ALL` (0) every type.
struct ErrorWatch {
    id: i32,
    domain: u32,
    number: Option<u32>,
    kind: u32,
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
    /// A position event's timer (`TriggInt`): it rides on that robot's
    /// path.
    path: Option<PathMark>,
}

impl Timer {
    /// When it expires, given the robots' paths (a position event's
    /// timer rides on its robot's path).
    fn due(&self, paths: &[PathState]) -> Option<f64> {
        due_on(self.due, self.path.as_ref(), paths)
    }
}

struct Watch {
    id: i32,
    /// The signal, folded.
    signal: String,
    trigger: Trigger,
    single: bool,
}

/// What a signal watch waits for.
enum Trigger {
    /// `ISignalDI`/`ISignalDO`: a change to the value; `ISignalGI`/`GO`
    /// (`None`): any change.
    Digital(Option<f64>),
    /// `ISignalAI`/`ISignalAO`.
    Analog(AnalogTrigger),
}

/// `ISignalAI [\Single] Signal, Condition, HighValue, LowValue, DeltaValue
/// [\DPos] | [\DNeg], Interrupt`. The reference is the signal's value when
/// the interrupt is ordered. At each new value that meets the condition and
/// differs from the reference by more than `delta`, the value becomes the
/// reference, and an interrupt occurs if the change is in the direction
/// asked (`\DPos` up, `\DNeg` down, else either).
#[derive(Clone, Copy, Debug)]
pub(crate) struct AnalogTrigger {
    /// `aiotrigg`: 1 above high, 2 below high, 3 above low, 4 below low,
    /// 5 between, 6 outside, 7 always.
    pub condition: i32,
    pub high: f64,
    pub low: f64,
    pub delta: f64,
    /// 1: `\DPos`, -1: `\DNeg`, 0: either way.
    pub direction: i8,
    pub reference: f64,
}

impl AnalogTrigger {
    fn meets(&self, v: f64) -> bool {
        match self.condition {
            1 => v > self.high,
            2 => v < self.high,
            3 => v > self.low,
            4 => v < self.low,
            5 => self.low <= v && v <= self.high,
            6 => v < self.low || v > self.high,
            _ => true,
        }
    }

    /// A new sample: does it raise the interrupt (and move the reference)?
    fn sample(&mut self, v: f64) -> bool {
        let change = v - self.reference;
        if !self.meets(v) || change.abs() <= self.delta {
            return false;
        }
        self.reference = v;
        match self.direction {
            1 => change > 0.0,
            -1 => change < 0.0,
            _ => true,
        }
    }
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
        self.push_timer(id, now, period, single, None);
    }

    /// A single timer due `delay` seconds from now as a robot passes a
    /// point of its path ([`PathMark`]).
    pub(crate) fn add_path_timer(&mut self, id: i32, now: f64, delay: f64, mark: PathMark) {
        self.push_timer(id, now, delay, true, Some(mark));
    }

    fn push_timer(&mut self, id: i32, now: f64, period: f64, single: bool, path: Option<PathMark>) {
        self.timers.retain(|t| t.id != id);
        self.timers.push(Timer {
            id,
            period,
            due: now + period,
            single,
            path,
        });
    }

    pub(crate) fn add_watch(&mut self, id: i32, signal: &str, value: Option<f64>, single: bool) {
        self.push_watch(id, signal, Trigger::Digital(value), single);
    }

    pub(crate) fn add_analog_watch(
        &mut self,
        id: i32,
        signal: &str,
        trigger: AnalogTrigger,
        single: bool,
    ) {
        self.push_watch(id, signal, Trigger::Analog(trigger), single);
    }

    fn push_watch(&mut self, id: i32, signal: &str, trigger: Trigger, single: bool) {
        self.watches.retain(|w| w.id != id);
        self.watches.push(Watch {
            id,
            signal: fold(signal),
            trigger,
            single,
        });
    }

    /// `IDelete`: the interrupt is cancelled and disconnected.
    pub(crate) fn delete(&mut self, id: i32) {
        self.traps.remove(&id);
        self.timers.retain(|t| t.id != id);
        self.watches.retain(|w| w.id != id);
        self.pers.retain(|w| w.id != id);
        self.errors.retain(|w| w.id != id);
        self.rmq.retain(|(_, i)| *i != id);
        self.pending.retain(|p| *p != id);
    }

    /// `IError`: an interrupt at each event log entry of `domain` (0: any),
    /// `number` (if given) and `kind` (0: any).
    pub(crate) fn add_error_watch(&mut self, id: i32, domain: u32, number: Option<u32>, kind: u32) {
        self.errors.retain(|w| w.id != id);
        self.errors.push(ErrorWatch {
            id,
            domain,
            number,
            kind,
        });
    }

    /// The event log got entry `index`: the error watches it triggers.
    pub(crate) fn logged(&mut self, index: usize, e: &LogEntry) {
        let fired: Vec<i32> = self
            .errors
            .iter()
            .filter(|w| {
                (w.domain == 0 || w.domain == e.domain)
                    && (w.kind == 0 || w.kind == e.kind)
                    && w.number.is_none_or(|n| n == e.number)
            })
            .map(|w| w.id)
            .collect();
        for id in fired {
            self.error_entries.insert(id, index);
            self.raise(id);
        }
    }

    /// The event log entry the `IError` interrupt `id` was last raised for.
    pub(crate) fn error_entry(&self, id: i32) -> Option<usize> {
        self.error_entries.get(&id).copied()
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

    pub(crate) fn raise(&mut self, id: i32) {
        if !self.sleeping.contains(&id) && self.traps.contains_key(&id) {
            self.pending.push_back(id);
        }
    }

    /// A signal changed to `value`: the watches it triggers.
    pub(crate) fn signal_changed(&mut self, name: &str, value: f64) {
        let key = fold(name);
        let mut fired = Vec::new();
        for w in &mut self.watches {
            if w.signal != key {
                continue;
            }
            let fires = match &mut w.trigger {
                Trigger::Digital(wanted) => wanted.is_none_or(|v| v == value),
                Trigger::Analog(t) => t.sample(value),
            };
            if fires {
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

    /// The time the next timer expires (the robots' paths hold position
    /// events).
    pub(crate) fn next_due(&self, paths: &[PathState]) -> Option<f64> {
        self.timers
            .iter()
            .filter_map(|t| t.due(paths))
            .reduce(f64::min)
    }

    /// The timers due by `t` expire; position events whose move
    /// `ClearPath` dropped are dropped.
    pub(crate) fn expire(&mut self, t: f64, paths: &[PathState]) {
        self.timers
            .retain(|timer| timer.path.is_none_or(|m| !m.dropped(paths)));
        let mut due = Vec::new();
        for timer in &mut self.timers {
            if timer.due(paths).is_some_and(|d| d <= t) {
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

#[cfg(test)]
mod tests {
    use super::AnalogTrigger;

    fn trigger(condition: i32, delta: f64, direction: i8) -> AnalogTrigger {
        AnalogTrigger {
            condition,
            high: 6.0,
            low: 2.0,
            delta,
            direction,
            reference: 4.0,
        }
    }

    /// The samples that raise the interrupt.
    fn raised(mut t: AnalogTrigger, samples: &[f64]) -> Vec<f64> {
        samples.iter().copied().filter(|&v| t.sample(v)).collect()
    }

    #[test]
    fn each_condition_admits_its_values() {
        let samples = [1.0, 3.0, 5.0, 7.0];
        let cases = [
            (1, vec![7.0]),                // above high
            (2, vec![1.0, 3.0, 5.0]),      // below high
            (3, vec![3.0, 5.0, 7.0]),      // above low
            (4, vec![1.0]),                // below low
            (5, vec![3.0, 5.0]),           // between
            (6, vec![1.0, 7.0]),           // outside
            (7, vec![1.0, 3.0, 5.0, 7.0]), // always
        ];
        for (condition, want) in cases {
            assert_eq!(
                raised(trigger(condition, 0.0, 0), &samples),
                want,
                "{condition}"
            );
        }
    }

    #[test]
    fn the_reference_moves_by_more_than_delta_and_direction_filters() {
        // From 4: 4.5 is within 1 (no new reference); 2.5 moves down by 1.5
        // (a new reference, raised only without \DPos); 4 moves up by 1.5.
        let samples = [4.5, 2.5, 4.0];
        assert_eq!(raised(trigger(7, 1.0, 0), &samples), vec![2.5, 4.0]);
        assert_eq!(raised(trigger(7, 1.0, 1), &samples), vec![4.0]);
        assert_eq!(raised(trigger(7, 1.0, -1), &samples), vec![2.5]);
    }
}
