//! The simulated controller: a clock that only moves when the program
//! waits, I/O signals (zero at the start, changed by the program or by a
//! script of timed changes), interrupts, the robot's position and open
//! files.

use std::collections::{HashMap, VecDeque};

use rapid_analyzer::names::{NameMap, fold};
use rapid_evaluator::Value;

use crate::machine::{FaultKind, Machine, R, Slot, fault, invalid, named_error};
use crate::program::{Program, SignalKind};
use crate::{Config, Move};

/// A change of a signal at a simulated time (`--set di1=1@2.5`).
#[derive(Clone, Debug, PartialEq)]
pub struct SignalChange {
    pub name: String,
    pub value: f64,
    /// Seconds after the start of the run.
    pub at: f64,
}

pub(crate) struct Signal {
    pub name: String,
    pub kind: SignalKind,
    pub value: f64,
}

pub(crate) struct Controller {
    pub clock: f64,
    pub signals: NameMap<Signal>,
    /// Scripted changes still to come, earliest first.
    pub script: Vec<SignalChange>,
    pub interrupts: Interrupts,
    pub robot: Robot,
    pub moves: Vec<Move>,
    pub files: crate::builtins::files::Files,
}

/// The robot's state after its last move.
pub(crate) struct Robot {
    /// The TCP in world coordinates with the tool of the last move:
    /// `[x, y, z]` and `[q1, q2, q3, q4]`.
    pub tcp: ([f64; 3], [f64; 4]),
    /// The tool and work object of the last move.
    pub tool: Option<Value>,
    pub robconf: Option<Value>,
    pub extax: Option<Value>,
    /// The last joint target (`MoveAbsJ`).
    pub joints: Option<Value>,
}

#[derive(Default)]
pub(crate) struct Interrupts {
    next: i32,
    traps: HashMap<i32, u32>,
    timers: Vec<Timer>,
    watches: Vec<Watch>,
    pending: VecDeque<i32>,
    pub disabled: bool,
    sleeping: std::collections::HashSet<i32>,
}

struct Timer {
    id: i32,
    period: f64,
    due: f64,
    single: bool,
}

struct Watch {
    id: i32,
    signal: String,
    /// The value that triggers it; `None`: any change (`ISignalAI` and
    /// group signals are not watched by value).
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
        self.pending.retain(|p| *p != id);
    }

    pub(crate) fn sleep(&mut self, id: i32, on: bool) {
        if on {
            self.sleeping.insert(id);
        } else {
            self.sleeping.remove(&id);
        }
    }

    fn raise(&mut self, id: i32) {
        if !self.sleeping.contains(&id) && self.traps.contains_key(&id) {
            self.pending.push_back(id);
        }
    }

    fn next_due(&self) -> Option<f64> {
        self.timers.iter().map(|t| t.due).reduce(f64::min)
    }

    /// Are there timers or signal watches that may still raise an interrupt?
    pub(crate) fn armed(&self) -> bool {
        !self.timers.is_empty() || !self.watches.is_empty()
    }
}

impl Controller {
    pub(crate) fn new(prog: &Program, config: &Config) -> Controller {
        let signals = prog
            .signals()
            .into_iter()
            .map(|(name, kind)| {
                (
                    fold(&name),
                    Signal {
                        name,
                        kind,
                        value: 0.0,
                    },
                )
            })
            .collect();
        let mut script: Vec<SignalChange> = config.signals.clone();
        // Earliest first; changes at the same time keep their order.
        script.sort_by(|a, b| a.at.total_cmp(&b.at));
        let mut c = Controller {
            clock: 0.0,
            signals,
            script,
            interrupts: Interrupts::default(),
            robot: Robot {
                tcp: ([0.0; 3], [1.0, 0.0, 0.0, 0.0]),
                tool: None,
                robconf: None,
                extax: None,
                joints: None,
            },
            moves: Vec::new(),
            files: crate::builtins::files::Files::new(config.sandbox.clone()),
        };
        c.apply_script(0.0);
        c
    }

    pub(crate) fn has_pending_interrupt(&self) -> bool {
        !self.interrupts.pending.is_empty() && !self.interrupts.disabled
    }

    /// Applies the scripted changes due by `t`.
    fn apply_script(&mut self, t: f64) {
        while self.script.first().is_some_and(|c| c.at <= t) {
            let c = self.script.remove(0);
            self.set_signal_value(&c.name, c.value);
        }
    }

    /// Sets a signal's value and raises the interrupts watching it.
    pub(crate) fn set_signal_value(&mut self, name: &str, value: f64) {
        let key = fold(name);
        let Some(s) = self.signals.get_mut(&key) else {
            return;
        };
        let old = s.value;
        s.value = value;
        if old == value {
            return;
        }
        let mut fired = Vec::new();
        for w in &self.interrupts.watches {
            if w.signal == key && w.value.is_none_or(|v| v == value) {
                fired.push((w.id, w.single));
            }
        }
        for (id, single) in fired {
            self.interrupts.raise(id);
            if single {
                self.interrupts.watches.retain(|w| w.id != id);
            }
        }
    }

    /// The time of the next event (a timer or a scripted change).
    pub(crate) fn next_event(&self) -> Option<f64> {
        let script = self.script.first().map(|c| c.at);
        match (script, self.interrupts.next_due()) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// Moves the clock to `t`, firing the events on the way.
    fn advance_to(&mut self, t: f64) {
        while let Some(next) = self.next_event().filter(|&n| n <= t) {
            self.clock = self.clock.max(next);
            self.apply_script(next);
            let mut due = Vec::new();
            for timer in &mut self.interrupts.timers {
                if timer.due <= next {
                    due.push(timer.id);
                    timer.due += timer.period.max(0.001);
                }
            }
            for id in due {
                self.interrupts.raise(id);
                let single = self
                    .interrupts
                    .timers
                    .iter()
                    .any(|tm| tm.id == id && tm.single);
                if single {
                    self.interrupts.timers.retain(|tm| tm.id != id);
                }
            }
        }
        self.clock = self.clock.max(t);
    }
}

impl Machine {
    /// Lets `seconds` of simulated time pass, running the trap routines of
    /// the interrupts that occur meanwhile.
    pub(crate) fn wait(&mut self, seconds: f64) -> R<()> {
        let end = self.ctl.clock + seconds.max(0.0);
        loop {
            let step = self.ctl.next_event().map_or(end, |n| n.min(end));
            self.advance(step)?;
            if self.ctl.has_pending_interrupt() && !self.in_trap {
                self.run_traps()?;
            }
            if self.ctl.clock >= end {
                return Ok(());
            }
        }
    }

    /// Moves the clock to `t` within the time budget.
    pub(crate) fn advance(&mut self, t: f64) -> R<()> {
        let max = self.config.limits.max_time;
        if t > max {
            self.ctl.advance_to(max);
            return fault(FaultKind::Budget(format!(
                "the simulated time budget ({max} s) ran out"
            )));
        }
        self.ctl.advance_to(t);
        Ok(())
    }

    /// Waits until `ready` holds, checking it at every event and every
    /// `poll` seconds; `ERR_WAIT_MAXTIME` after `max_time` seconds when
    /// given. When nothing can change any more (no event to come and
    /// `events_only`), the wait can never end.
    pub(crate) fn wait_until(
        &mut self,
        what: &str,
        max_time: Option<f64>,
        poll: f64,
        events_only: bool,
        ready: &mut dyn FnMut(&mut Machine) -> R<bool>,
    ) -> R<bool> {
        let start = self.ctl.clock;
        loop {
            if ready(self)? {
                return Ok(true);
            }
            let deadline = max_time.map(|m| start + m);
            if deadline.is_some_and(|d| self.ctl.clock >= d) {
                return Ok(false);
            }
            let next = self.ctl.next_event();
            if events_only && next.is_none() && !self.ctl.interrupts.armed() {
                if let Some(d) = deadline {
                    self.advance(d)?;
                    continue;
                }
                return fault(FaultKind::Deadlock(format!(
                    "{what} waits forever: nothing the simulation runs can change it (script a signal change with --set NAME=VALUE@SECONDS)"
                )));
            }
            let mut t = self.ctl.clock + poll;
            if events_only && let Some(n) = next {
                t = n.max(self.ctl.clock);
            }
            if let Some(d) = deadline {
                t = t.min(d);
            }
            self.advance(t)?;
            if self.ctl.has_pending_interrupt() && !self.in_trap {
                self.run_traps()?;
            }
        }
    }

    /// Runs the trap routines of the interrupts that occurred.
    pub(crate) fn run_traps(&mut self) -> R<()> {
        while !self.ctl.interrupts.disabled {
            let Some(id) = self.ctl.interrupts.pending.pop_front() else {
                break;
            };
            let Some(&trap) = self.ctl.interrupts.traps.get(&id) else {
                continue;
            };
            if let Some(g) = self.prog.intno
                && let Some(v) = self.globals.get_mut(g as usize)
            {
                *v = Value::Num(id as f32);
            }
            self.in_trap = true;
            let r = self.call_routine(trap, Vec::new());
            self.in_trap = false;
            r?;
        }
        Ok(())
    }

    /// Is `v` a signal (of the configuration, or a signal variable)?
    pub(crate) fn is_signal(&self, v: &Value) -> bool {
        matches!(v, Value::Record { ty, .. } if ty.len() == 8 && ty.to_ascii_lowercase().starts_with("signal"))
    }

    /// The configured signal a signal value stands for.
    pub(crate) fn signal_of(&self, v: &Value) -> R<&Signal> {
        let name = match v.field("name") {
            Some(Value::Str(n)) => n,
            _ => return invalid("not a signal"),
        };
        if name.is_empty() {
            return fault(named_error(
                &self.prog,
                "ERR_NO_ALIASIO_DEF",
                "the signal variable is not connected to a signal (AliasIO)".to_owned(),
            ));
        }
        match self.ctl.signals.get(&fold(name)) {
            Some(s) => Ok(s),
            None => fault(named_error(
                &self.prog,
                "ERR_NAME_INVALID",
                format!("there is no signal {name}"),
            )),
        }
    }

    /// The current value of a signal.
    pub(crate) fn signal_value(&self, v: &Value) -> R<f32> {
        self.signal_of(v).map(|s| s.value as f32)
    }

    /// A local slot as a debugger shows it.
    pub(crate) fn slot_value(&self, base: usize, slot: usize) -> Option<Value> {
        match self.stack.get(base + slot)? {
            Slot::Val(v) => Some(v.clone()),
            Slot::Ref(p) => self.get(p).cloned(),
            Slot::Absent => None,
        }
    }
}
