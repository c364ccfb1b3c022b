//! Faults and error recovery. A RAPID error is offered to the `ERROR`
//! handler of the routine it reaches, at the statement that was running
//! there (so `RETRY` runs that statement again and `TRYNEXT` goes on
//! after it, inside the loops around it); a routine whose handler does
//! not take it is left (its `UNDO` handler runs first) and the error goes
//! on to the caller's call statement. An error inside a handler, or one
//! that leaves a trap routine, is taken by nobody.

use rapid_analyzer::items::RoutineKind;
use rapid_evaluator::{ErrorCode, EvalError, Value};

use super::{Frame, FrameKind, Machine, Outcome, StackFrame, Status, Stop, Yield};
use crate::code::{CodeKind, Simple};
use crate::controller::Shared;
use crate::program::{Location, Program};

/// Why execution unwinds: a RAPID error, or the end of the run.
#[derive(Debug, Clone)]
pub(crate) struct Fault {
    pub kind: FaultKind,
    /// Raised by `RAISE` in the handler of the frame of this depth: that
    /// handler must not take it, the caller's may.
    pub skip_depth: Option<usize>,
    /// No handler may take it.
    pub fatal: bool,
    /// Where it was first seen, with the stack (innermost first).
    pub trace: Option<(Location, Vec<StackFrame>)>,
    /// A debugger was shown it.
    pub reported: bool,
}

#[derive(Debug, Clone)]
pub(crate) enum FaultKind {
    /// A RAPID error: `ERRNO`, its name and a message.
    Rapid {
        errno: f32,
        name: String,
        message: String,
    },
    Unsupported(String),
    Invalid(String),
    Budget(String),
    Deadlock(String),
    /// Waiting for the operator, who does not answer (or answers what
    /// does not fit).
    Operator(String),
    /// The controller stopped the program with a motion event (no handler
    /// takes it).
    Motion(String),
    /// `EXIT` or `Stop`: ends the run without an error.
    Halt(Status),
    /// A stop that says why (`SystemStopAction`).
    Stopped(String),
}

pub(crate) type R<T> = Result<T, Box<Fault>>;

pub(crate) fn fault<T>(kind: FaultKind) -> R<T> {
    Err(Box::new(Fault {
        kind,
        skip_depth: None,
        fatal: false,
        trace: None,
        reported: false,
    }))
}

pub(crate) fn invalid<T>(message: impl Into<String>) -> R<T> {
    fault(FaultKind::Invalid(message.into()))
}

/// The fault of a controller error (`ERR_...`).
pub(crate) fn rapid_error(prog: &Program, code: ErrorCode, message: String) -> FaultKind {
    named_error(prog, code.name(), message)
}

/// The fault of the predefined error `name` (`ERR_WAIT_MAXTIME`).
pub(crate) fn named_error(prog: &Program, name: &str, message: String) -> FaultKind {
    let errno = prog.errnum(name);
    FaultKind::Rapid {
        errno,
        name: name.to_owned(),
        message,
    }
}

impl Machine {
    /// A fault for an evaluator error: the controller's error for run-time
    /// errors, an invalid program for the rest.
    pub(crate) fn eval_error<T>(&self, e: EvalError) -> R<T> {
        if e.code.is_runtime() {
            fault(rapid_error(&self.prog, e.code, e.message))
        } else {
            invalid(e.message)
        }
    }

    pub(crate) fn outcome_of(&self, f: &Fault) -> Outcome {
        let (at, stack) = match &f.trace {
            Some((at, stack)) => (Some(at.clone()), stack.clone()),
            None => (self.location(), self.stack_frames()),
        };
        let (status, message, errno) = match &f.kind {
            FaultKind::Rapid {
                errno,
                name,
                message,
            } => (Status::Error, message.clone(), Some((*errno, name.clone()))),
            FaultKind::Unsupported(name) => (
                Status::Unsupported,
                format!("not supported in simulation: {name}"),
                None,
            ),
            FaultKind::Invalid(m) => (Status::Invalid, m.clone(), None),
            FaultKind::Budget(m) => (Status::Budget, m.clone(), None),
            FaultKind::Deadlock(m) => (Status::Deadlock, m.clone(), None),
            FaultKind::Operator(m) => (Status::Operator, m.clone(), None),
            FaultKind::Motion(m) => (Status::Error, m.clone(), None),
            FaultKind::Halt(s) => (*s, String::new(), None),
            FaultKind::Stopped(m) => (Status::Stopped, m.clone(), None),
        };
        Outcome {
            status,
            message,
            errno,
            at,
            stack,
        }
    }

    /// Handles a fault: into an error handler (the machine goes on), into
    /// an `UNDO` handler, to a debugger first, or to the end of the task.
    /// `None`: go on running.
    pub(crate) fn handle(&mut self, sh: &mut Shared, mut f: Box<Fault>) -> Option<Yield> {
        if f.trace.is_none() {
            f.trace = self.location().map(|at| (at, self.stack_frames()));
        }
        loop {
            let depth = self.frames.len();
            let Some(top) = self.frames.last() else {
                let outcome = self.outcome_of(&f);
                self.finish(outcome);
                return Some(Yield::Done);
            };
            match top.kind {
                FrameKind::Eval => {
                    let outcome = self.outcome_of(&f);
                    let text = match outcome.errno {
                        Some((_, name)) => format!("{name}: {}", outcome.message),
                        None => outcome.message,
                    };
                    self.evaluated = Some(Err(text));
                    self.pop_frame();
                    return Some(Yield::Evaluated);
                }
                FrameKind::Init => {
                    let why = self.outcome_of(&f).message;
                    self.init_failed(sh, why);
                    self.pop_frame();
                    // The data's reader is told when it reads it again.
                    return None;
                }
                _ => {}
            }
            if matches!(f.kind, FaultKind::Halt(_) | FaultKind::Stopped(_)) {
                let outcome = self.outcome_of(&f);
                self.finish(outcome);
                return Some(Yield::Done);
            }
            let errno = match &f.kind {
                FaultKind::Rapid { errno, .. } => Some(*errno),
                _ => None,
            };
            if !f.reported && sh.debug.active && errno.is_none_or(|e| !self.will_recover(sh, &f, e))
            {
                f.reported = true;
                let outcome = self.outcome_of(&f);
                self.pending = Some(f);
                return Some(Yield::Stopped(Stop::Error(outcome)));
            }
            let in_handler = self.frames.last()?.in_handler;
            if let Some(errno) = errno
                && !f.fatal
                && f.skip_depth != Some(depth)
            {
                if in_handler {
                    // Errors inside an error handler are not recovered.
                    f.fatal = true;
                } else if self.handler_takes(sh, errno) {
                    self.enter_handler(errno);
                    return None;
                }
            }
            // The routine is left.
            let top = self.frames.last()?;
            if top.code.undo.is_some() && top.undoing.is_none() {
                let undo = top.code.undo;
                if let (Some(pc), Some(top)) = (undo, self.frames.last_mut()) {
                    top.undoing = Some(f);
                    top.pc = pc;
                    top.in_handler = false;
                    self.truncate_stacks();
                    return None;
                }
            }
            let left = self.pop_frame();
            if left.is_some_and(|fr| fr.code.kind == CodeKind::Routine(RoutineKind::Trap)) {
                // An error that leaves a trap routine stops the program.
                f.fatal = true;
            }
        }
    }

    /// Does the innermost frame's `ERROR` handler take `errno`?
    fn handler_takes(&mut self, sh: &mut Shared, errno: f32) -> bool {
        let Some(top) = self.frames.last() else {
            return false;
        };
        let Some(h) = &top.code.error else {
            return false;
        };
        let base = top.base as usize;
        h.errors.is_empty()
            || h.errors
                .iter()
                .any(|e| self.simple(sh, e, base) == Some(errno))
    }

    /// The value of an error number of an `ERROR (...)` list.
    fn simple(&self, sh: &Shared, e: &Simple, base: usize) -> Option<f32> {
        let v = match e {
            Simple::Const(v) => v.clone(),
            Simple::Local(s) => self.slot_value(sh, base, *s as usize)?,
            Simple::Global(g) => self.globals.get(*g as usize)?.clone(),
            Simple::Pers(k) => {
                let i = *self.pers_map.get(*k as usize)?;
                sh.pers.get(i as usize)?.clone()
            }
            Simple::Neg(x) => return self.simple(sh, x, base).map(|x| -x),
            Simple::Other => return None,
        };
        v.as_f64().map(|x| x as f32)
    }

    fn enter_handler(&mut self, errno: f32) {
        self.set_errno(errno);
        self.truncate_stacks();
        if let Some(top) = self.frames.last_mut()
            && let Some(h) = &top.code.error
        {
            top.fault_stmt = top.stmt;
            top.in_handler = true;
            top.pc = h.pc;
            top.boundary = super::Boundary::None;
        }
    }

    /// Would some frame's handler take this fault? (For debuggers, which
    /// stop on errors that end the run.)
    fn will_recover(&mut self, sh: &mut Shared, f: &Fault, errno: f32) -> bool {
        if f.fatal {
            return false;
        }
        for d in (1..=self.frames.len()).rev() {
            let Some(frame) = self.frames.get(d - 1) else {
                return false;
            };
            if matches!(frame.kind, FrameKind::Eval | FrameKind::Init) {
                return false;
            }
            if f.skip_depth == Some(d) {
                continue;
            }
            if frame.in_handler {
                return false;
            }
            let code = frame.code.clone();
            let base = frame.base as usize;
            if let Some(h) = &code.error
                && (h.errors.is_empty()
                    || h.errors
                        .iter()
                        .any(|e| self.simple(sh, e, base) == Some(errno)))
            {
                return true;
            }
            if frame.kind == FrameKind::Trap {
                return false;
            }
        }
        false
    }

    pub(crate) fn set_errno(&mut self, errno: f32) {
        if let Some(g) = self.prog.errno
            && let Some(v) = self.globals.get_mut(g as usize)
        {
            *v = Value::Num(errno);
        }
    }

    /// The operand stacks as the innermost frame found them.
    pub(crate) fn truncate_stacks(&mut self) {
        if let Some(top) = self.frames.last() {
            self.vals.truncate(top.vals as usize);
            self.places.truncate(top.places as usize);
            self.args.truncate(top.args as usize);
        }
    }

    /// `RAISE [errno]`.
    pub(crate) fn raise(&mut self, value: Option<Value>) -> R<()> {
        let in_handler = self.frames.last().is_some_and(|f| f.in_handler);
        let errno = match value {
            Some(v) => match v.as_f64() {
                Some(x) => x as f32,
                None => return invalid("RAISE needs an error number"),
            },
            None if in_handler => self
                .prog
                .errno
                .and_then(|g| self.globals.get(g as usize))
                .and_then(Value::as_f64)
                .unwrap_or(0.0) as f32,
            None => return invalid("RAISE without an error number belongs in an error handler"),
        };
        let user = (1.0..=90.0).contains(&errno) && errno.fract() == 0.0;
        let booked = self.booked.iter().any(|(b, _)| *b == errno);
        let system = self.prog.errnum_name(errno).is_some();
        let kind = if user || booked || system {
            FaultKind::Rapid {
                errno,
                name: self.errno_name(errno),
                message: "raised by RAISE".to_owned(),
            }
        } else {
            named_error(
                &self.prog,
                "ERR_ILLRAISE",
                format!("RAISE {errno}: the error number is outside 1 to 90 and not booked"),
            )
        };
        let depth = self.frames.len();
        Err(Box::new(Fault {
            kind,
            // Raised from an error handler: the caller's handler takes it.
            skip_depth: in_handler.then_some(depth),
            fatal: false,
            trace: None,
            reported: false,
        }))
    }

    /// `RETRY`: the statement the handler runs for, again.
    pub(crate) fn retry(&mut self, max: u32) -> R<()> {
        let Some(top) = self.frames.last_mut() else {
            return invalid("RETRY outside a routine");
        };
        if !top.in_handler {
            return invalid("RETRY outside an error handler");
        }
        top.retries += 1;
        let stmt = top.fault_stmt;
        if top.retries > max {
            top.stmt = stmt;
            let mut g = Box::new(Fault {
                kind: named_error(
                    &self.prog,
                    "ERR_EXCRTYMAX",
                    format!("RETRY was used more than {max} times in a row"),
                ),
                skip_depth: None,
                fatal: true,
                trace: None,
                reported: false,
            });
            g.trace = self.location().map(|at| (at, self.stack_frames()));
            return Err(g);
        }
        let start = top.code.stmts.get(stmt as usize).map_or(0, |s| s.start);
        top.in_handler = false;
        top.pc = start;
        top.boundary = super::Boundary::None;
        Ok(())
    }

    /// `TRYNEXT`: on after the statement the handler runs for.
    pub(crate) fn try_next(&mut self) -> R<()> {
        let Some(top) = self.frames.last_mut() else {
            return invalid("TRYNEXT outside a routine");
        };
        if !top.in_handler {
            return invalid("TRYNEXT outside an error handler");
        }
        let end = top
            .code
            .stmts
            .get(top.fault_stmt as usize)
            .map_or(0, |s| s.end);
        top.in_handler = false;
        top.retries = 0;
        top.pc = end;
        top.boundary = super::Boundary::None;
        Ok(())
    }

    /// A statement reached that is not inside the statement `RETRY`
    /// repeats: the count of `RETRY`s in a row starts again.
    pub(crate) fn statement_reached(frame: &mut Frame, pc: u32) {
        if frame.retries > 0 && !frame.in_handler {
            let inside = frame
                .code
                .stmts
                .get(frame.fault_stmt as usize)
                .is_some_and(|s| (s.start..s.end).contains(&pc));
            if !inside {
                frame.retries = 0;
            }
        }
    }
}
