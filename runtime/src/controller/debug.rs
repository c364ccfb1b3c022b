//! Where a debugger wants the controller to stop: line breakpoints, the
//! step it asked for (in one task), a pause, the first statement.

use std::collections::{HashMap, HashSet};

use crate::code::Code;
use crate::machine::{Machine, Stop};

/// How the controller goes on after a stop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Resume {
    /// Until a breakpoint, an error or the end.
    Continue,
    /// Task `task` runs to its next statement at the same depth or less.
    StepOver { task: usize },
    /// Task `task` runs to its next statement.
    StepIn { task: usize },
    /// Task `task` runs out of its innermost routine.
    StepOut { task: usize },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    Run,
    In(usize),
    Over(usize, usize),
    Out(usize, usize),
}

pub(crate) struct Debug {
    /// Stops are looked for (a debugger is attached).
    pub active: bool,
    /// Lines with a breakpoint, by the unit's path.
    breakpoints: HashMap<String, HashSet<u32>>,
    mode: Mode,
    /// Stop at the next statement of any task.
    pub pause: bool,
    /// Stop at the first statement.
    pub entry: bool,
}

impl Default for Debug {
    fn default() -> Debug {
        Debug {
            active: false,
            breakpoints: HashMap::new(),
            mode: Mode::Run,
            pause: false,
            entry: false,
        }
    }
}

impl Debug {
    pub(crate) fn set_breakpoints(&mut self, path: &str, lines: &[u32]) {
        if lines.is_empty() {
            self.breakpoints.remove(path);
        } else {
            self.breakpoints
                .insert(path.to_owned(), lines.iter().copied().collect());
        }
    }

    /// How to go on; `depth` is the number of active routines of the task
    /// named.
    pub(crate) fn resume(&mut self, how: Resume, depth: usize) {
        self.mode = match how {
            Resume::Continue => Mode::Run,
            Resume::StepIn { task } => Mode::In(task),
            Resume::StepOver { task } => Mode::Over(task, depth),
            Resume::StepOut { task } => Mode::Out(task, depth),
        };
    }

    /// Does the debugger stop task `m` before statement `s` of `code`?
    pub(crate) fn stop_at(&mut self, m: &Machine, code: &Code, s: u32) -> Option<Stop> {
        if std::mem::take(&mut self.entry) {
            return Some(Stop::Entry);
        }
        if std::mem::take(&mut self.pause) {
            self.mode = Mode::Run;
            return Some(Stop::Pause);
        }
        let task = m.number.saturating_sub(1);
        let stepped = match self.mode {
            Mode::Run => false,
            Mode::In(t) => t == task,
            Mode::Over(t, d) => t == task && m.depth() <= d,
            Mode::Out(t, d) => t == task && m.depth() < d,
        };
        if stepped {
            self.mode = Mode::Run;
            return Some(Stop::Step);
        }
        if self.breakpoints.is_empty() {
            return None;
        }
        let line = code.stmts.get(s as usize)?.line;
        let path = &m.prog.task().units.get(code.unit)?.path;
        if self
            .breakpoints
            .get(path)
            .is_some_and(|l| l.contains(&line))
        {
            self.mode = Mode::Run;
            return Some(Stop::Breakpoint);
        }
        None
    }
}
