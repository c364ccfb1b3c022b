//! The I/O signals, behind [`Io`]: what a signal reads, the program's
//! writes, and the changes that come from outside (a sensor, a PLC) at
//! simulated times. [`ScriptedIo`] (the default) has every signal at zero
//! at the start and a script of timed changes (`--set di1=1@2.5`).

use rapid_analyzer::names::{NameMap, fold};

use crate::{SignalChange, SignalKind};

/// The controller's I/O signals.
pub trait Io: Send {
    /// A signal the program knows (configured, or named by a script).
    fn declare(&mut self, name: &str, kind: SignalKind);
    /// The signal's kind and name as declared, if it is declared.
    fn signal(&self, name: &str) -> Option<(String, SignalKind)>;
    /// The signal's value now.
    fn read(&self, name: &str) -> Option<f64>;
    /// The program (or the controller, for a pulse) sets the signal.
    fn write(&mut self, name: &str, value: f64);
    /// When the next change from outside comes (simulated seconds).
    fn next_change(&self) -> Option<f64>;
    /// Applies the changes from outside due by `t`; the signals whose
    /// value changed, with their new values, in order.
    fn advance(&mut self, t: f64) -> Vec<(String, f64)>;
}

struct Signal {
    name: String,
    kind: SignalKind,
    value: f64,
}

/// Signals at zero at the start, changed by the program and by a script.
pub struct ScriptedIo {
    signals: NameMap<Signal>,
    /// Scripted changes still to come, earliest first (changes at the same
    /// time keep their order).
    script: Vec<SignalChange>,
}

impl ScriptedIo {
    pub fn new(mut script: Vec<SignalChange>) -> ScriptedIo {
        script.sort_by(|a, b| a.at.total_cmp(&b.at));
        ScriptedIo {
            signals: NameMap::default(),
            script,
        }
    }
}

impl Io for ScriptedIo {
    fn declare(&mut self, name: &str, kind: SignalKind) {
        self.signals.entry(fold(name)).or_insert(Signal {
            name: name.to_owned(),
            kind,
            value: 0.0,
        });
    }

    fn signal(&self, name: &str) -> Option<(String, SignalKind)> {
        self.signals
            .get(&fold(name))
            .map(|s| (s.name.clone(), s.kind))
    }

    fn read(&self, name: &str) -> Option<f64> {
        self.signals.get(&fold(name)).map(|s| s.value)
    }

    fn write(&mut self, name: &str, value: f64) {
        if let Some(s) = self.signals.get_mut(&fold(name)) {
            s.value = value;
        }
    }

    fn next_change(&self) -> Option<f64> {
        self.script.first().map(|c| c.at)
    }

    fn advance(&mut self, t: f64) -> Vec<(String, f64)> {
        let due = self.script.partition_point(|c| c.at <= t);
        let mut changed = Vec::new();
        for c in self.script.drain(..due) {
            if let Some(s) = self.signals.get_mut(&fold(&c.name))
                && s.value != c.value
            {
                s.value = c.value;
                changed.push((s.name.clone(), c.value));
            }
        }
        changed
    }
}
