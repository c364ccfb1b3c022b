//! The machine: a program's data, the call stack and the simulated
//! controller, and the outcome of a run.

use std::sync::Arc;

use rapid_analyzer::items::Storage;
use rapid_evaluator::{ErrorCode, EvalError, Value};

use crate::code::{Conv, Routine, SlotKind};
use crate::controller::Controller;
use crate::program::{Location, Program, Start};
use crate::types::TypesEnv;
use crate::{Config, Debugger, Output};

/// How a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// The entry routine returned.
    Finished,
    /// `EXIT` (or `ExitCycle`) ended the program.
    Exited,
    /// `Stop` (or `Break`) stopped it.
    Stopped,
    /// A RAPID error no handler took (its `ERRNO` name in the outcome).
    Error,
    /// An instruction or function the simulation does not support.
    Unsupported,
    /// The program cannot run as written: an unknown name, a placeholder,
    /// arguments that do not fit, a type mismatch.
    Invalid,
    /// The step, time or call-depth budget ran out.
    Budget,
    /// The program waits for something that can never happen.
    Deadlock,
}

/// The outcome of a run.
#[derive(Clone, Debug)]
pub struct Outcome {
    pub status: Status,
    /// What happened, in a sentence (empty for a normal end).
    pub message: String,
    /// For [`Status::Error`]: the error's number and name (`ERR_DIVZERO`, a
    /// name booked with `BookErrNo`, or `user error 5`).
    pub errno: Option<(f32, String)>,
    /// Where it happened.
    pub at: Option<Location>,
    /// The routines active when it happened, innermost first.
    pub stack: Vec<StackFrame>,
}

impl Outcome {
    /// Did the run end normally (`Finished`, `Exited` or `Stopped`)?
    pub fn is_success(&self) -> bool {
        matches!(
            self.status,
            Status::Finished | Status::Exited | Status::Stopped
        )
    }
}

/// One active routine, for stack traces and debuggers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StackFrame {
    pub routine: String,
    pub at: Location,
}

/// Why execution unwinds: a RAPID error, or the end of the run.
#[derive(Debug)]
pub(crate) struct Fault {
    pub kind: FaultKind,
    /// The frame depth whose error handler must not take it (an error
    /// raised again from that frame's handler goes to its caller).
    pub skip_depth: Option<usize>,
    /// No handler may take it (an error inside an error handler, or
    /// propagated out of a trap routine).
    pub fatal: bool,
    /// Where it was first seen, with the stack (innermost first).
    pub trace: Option<(Location, Vec<StackFrame>)>,
    /// The debugger has been told.
    pub reported: bool,
}

#[derive(Debug)]
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
    /// `EXIT` or `Stop`: ends the run without an error.
    Halt(Status),
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

/// Where a reference points: a global, or a slot of the stack, then
/// components and elements.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Place {
    pub root: Root,
    pub path: Vec<Step>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Root {
    Global(u32),
    Stack(u32),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Step {
    Field(u16),
    Index(u32),
}

/// A local slot: a value, a reference (`VAR`, `INOUT`, `PERS`
/// parameters), or an optional parameter left out.
#[derive(Clone, Debug)]
pub(crate) enum Slot {
    Val(Value),
    Ref(Place),
    Absent,
}

/// The state of a global's starting value.
#[derive(Debug)]
pub(crate) enum Init {
    Ready,
    Pending,
    Busy,
    Failed(String),
}

pub(crate) struct Frame {
    pub routine: Arc<Routine>,
    pub base: u32,
    /// The byte offset of the statement running.
    pub at: usize,
    pub in_handler: bool,
}

/// A running program.
pub struct Machine {
    pub(crate) prog: Arc<Program>,
    pub(crate) globals: Vec<Value>,
    pub(crate) init: Vec<Init>,
    pub(crate) stack: Vec<Slot>,
    pub(crate) frames: Vec<Frame>,
    /// The stack index of the innermost frame's first slot.
    pub(crate) base: usize,
    pub(crate) ctl: Controller,
    pub(crate) config: Config,
    pub(crate) steps: u64,
    pub(crate) out: Box<dyn Output>,
    pub(crate) debugger: Option<Box<dyn Debugger>>,
    /// Error numbers booked with `BookErrNo`, with the names they were
    /// booked in.
    pub(crate) booked: Vec<(f32, String)>,
    /// A trap routine is running (interrupts wait until it ends).
    pub(crate) in_trap: bool,
}

impl Machine {
    /// A machine for `program`, its data as the controller sets them when
    /// the program is loaded.
    pub fn new(prog: Arc<Program>, config: Config, out: Box<dyn Output>) -> Machine {
        let n = prog.globals.len();
        let mut m = Machine {
            globals: vec![Value::Num(0.0); n],
            init: (0..n).map(|_| Init::Pending).collect(),
            stack: Vec::new(),
            frames: Vec::new(),
            base: 0,
            ctl: Controller::new(&prog, &config),
            config,
            steps: 0,
            out,
            debugger: None,
            booked: Vec::new(),
            in_trap: false,
            prog,
        };
        for g in 0..n as u32 {
            let _ = m.ensure_global(g);
        }
        m
    }

    /// Attaches a debugger, asked before every statement.
    pub fn set_debugger(&mut self, debugger: Box<dyn Debugger>) {
        self.debugger = Some(debugger);
    }

    /// The program.
    pub fn program(&self) -> &Arc<Program> {
        &self.prog
    }

    /// Runs routine `entry` (a procedure without parameters) to its end.
    pub fn run(&mut self, entry: u32) -> Outcome {
        let r = self.call_routine(entry, Vec::new());
        let outcome = match r {
            Ok(_) => Outcome {
                status: Status::Finished,
                message: String::new(),
                errno: None,
                at: None,
                stack: Vec::new(),
            },
            Err(f) => self.outcome_of(*f),
        };
        self.frames.clear();
        self.stack.clear();
        outcome
    }

    pub(crate) fn outcome_of(&self, f: Fault) -> Outcome {
        let (at, stack) = match f.trace {
            Some((at, stack)) => (Some(at), stack),
            None => (None, Vec::new()),
        };
        let (status, message, errno) = match f.kind {
            FaultKind::Rapid {
                errno,
                name,
                message,
            } => (Status::Error, message, Some((errno, name))),
            FaultKind::Unsupported(name) => (
                Status::Unsupported,
                format!("not supported in simulation: {name}"),
                None,
            ),
            FaultKind::Invalid(m) => (Status::Invalid, m, None),
            FaultKind::Budget(m) => (Status::Budget, m, None),
            FaultKind::Deadlock(m) => (Status::Deadlock, m, None),
            FaultKind::Halt(s) => (s, String::new(), None),
        };
        Outcome {
            status,
            message,
            errno,
            at,
            stack,
        }
    }

    /// The simulated time, in seconds since the run started.
    pub fn clock(&self) -> f64 {
        self.ctl.clock
    }

    /// The number of statements run so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The moves made so far (with [`Config::trace`]).
    pub fn moves(&self) -> &[crate::Move] {
        &self.ctl.moves
    }

    /// The active routines, innermost first.
    pub fn stack_frames(&self) -> Vec<StackFrame> {
        self.frames
            .iter()
            .rev()
            .map(|f| StackFrame {
                routine: f.routine.name.clone(),
                at: self.prog.location(f.routine.unit, f.at),
            })
            .collect()
    }

    /// The location of the statement running in the innermost frame.
    pub(crate) fn here(&self) -> Option<Location> {
        self.frames
            .last()
            .map(|f| self.prog.location(f.routine.unit, f.at))
    }

    /// Makes sure global `g` has its starting value.
    pub(crate) fn ensure_global(&mut self, g: u32) -> R<()> {
        let gi = g as usize;
        match self.init.get(gi) {
            Some(Init::Ready) => return Ok(()),
            Some(Init::Failed(why)) => return invalid(why.clone()),
            Some(Init::Busy) => {
                let name = self.prog.globals.get(gi).map_or("", |d| d.name.as_str());
                return invalid(format!("the initial value of {name} refers to itself"));
            }
            Some(Init::Pending) => {}
            None => return invalid("a reference to data that does not exist"),
        }
        self.init[gi] = Init::Busy;
        let prog = self.prog.clone();
        let decl = &prog.globals[gi];
        let r = match &decl.start {
            Start::Value(v) => Ok(v.clone()),
            Start::Eval { dims, init, conv } => {
                self.start_value(&decl.ty.name, dims, init.as_ref(), conv)
            }
        };
        match r {
            Ok(v) => {
                self.globals[gi] = v;
                self.init[gi] = Init::Ready;
                Ok(())
            }
            Err(f) => {
                let why = match &decl.origin {
                    crate::program::Origin::Module { module, range } => {
                        let unit = prog.modules.get(*module).map_or(0, |m| m.unit);
                        let at = prog.location(unit, range.start);
                        format!(
                            "{at}: the data {} cannot be initialised: {}",
                            decl.name,
                            self.outcome_of(*f).message
                        )
                    }
                    _ => format!("{} cannot be initialised", decl.name),
                };
                self.init[gi] = Init::Failed(why.clone());
                invalid(why)
            }
        }
    }

    /// The starting value of data of type `ty_name` with the given
    /// dimensions and initial value.
    pub(crate) fn start_value(
        &mut self,
        ty_name: &str,
        dims: &[crate::code::Expr],
        init: Option<&crate::code::Expr>,
        conv: &Conv,
    ) -> R<Value> {
        let mut sizes = Vec::with_capacity(dims.len());
        for d in dims {
            let v = self.eval(d)?;
            let n = v.as_f64().unwrap_or(-1.0);
            if n.fract() != 0.0 || !(1.0..=crate::types::MAX_ELEMENTS as f64).contains(&n) {
                return invalid(format!(
                    "an array dimension of {v} is not a positive integer"
                ));
            }
            sizes.push(n as usize);
        }
        let total = sizes.iter().try_fold(1usize, |t, &n| t.checked_mul(n));
        if total.is_none_or(|t| t > crate::types::MAX_ELEMENTS) {
            return invalid(format!(
                "an array of {} elements is larger than the simulation holds ({})",
                sizes
                    .iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(" x "),
                crate::types::MAX_ELEMENTS
            ));
        }
        let ty = rapid_evaluator::Type::array(ty_name, sizes);
        match init {
            Some(e) => {
                let v = self.eval(e)?;
                let conv = match conv {
                    Conv::Full(_) => Conv::Full(ty),
                    other => other.clone(),
                };
                self.convert(v, &conv)
            }
            None => Ok(self.prog.types.zero(&ty)),
        }
    }

    /// The value at a place.
    pub(crate) fn get(&self, p: &Place) -> Option<&Value> {
        let mut v = match p.root {
            Root::Global(g) => self.globals.get(g as usize)?,
            Root::Stack(s) => match self.stack.get(s as usize)? {
                Slot::Val(v) => v,
                _ => return None,
            },
        };
        for step in &p.path {
            v = match (step, v) {
                (Step::Field(i), Value::Record { fields, .. }) => &fields.get(usize::from(*i))?.1,
                (Step::Index(i), Value::Array(items)) => items.get(*i as usize)?,
                _ => return None,
            };
        }
        Some(v)
    }

    pub(crate) fn get_mut(&mut self, p: &Place) -> Option<&mut Value> {
        let mut v = match p.root {
            Root::Global(g) => self.globals.get_mut(g as usize)?,
            Root::Stack(s) => match self.stack.get_mut(s as usize)? {
                Slot::Val(v) => v,
                _ => return None,
            },
        };
        for step in &p.path {
            v = match (step, v) {
                (Step::Field(i), Value::Record { fields, .. }) => {
                    &mut fields.get_mut(usize::from(*i))?.1
                }
                (Step::Index(i), Value::Array(items)) => items.get_mut(*i as usize)?,
                _ => return None,
            };
        }
        Some(v)
    }

    /// Stores `v` at a place (not a constant's), keeping array sizes.
    pub(crate) fn store(&mut self, p: &Place, v: Value) -> R<()> {
        if self.is_constant(p) {
            return invalid("a constant cannot be changed");
        }
        if let (Some(Value::Array(old)), Value::Array(new)) = (self.get(p), &v)
            && old.len() != new.len()
        {
            return fault(rapid_error(
                &self.prog,
                ErrorCode::OutOfBnd,
                format!(
                    "an array of {} cannot hold {} elements",
                    old.len(),
                    new.len()
                ),
            ));
        }
        match self.get_mut(p) {
            Some(slot) => {
                *slot = v;
                Ok(())
            }
            None => invalid("the data referred to no longer exists"),
        }
    }

    fn is_constant(&self, p: &Place) -> bool {
        match p.root {
            Root::Global(g) => self
                .prog
                .globals
                .get(g as usize)
                .is_some_and(|d| d.storage == Storage::Const),
            Root::Stack(s) => {
                let Some(f) = self
                    .frames
                    .iter()
                    .rev()
                    .find(|f| (f.base as usize) <= s as usize)
                else {
                    return false;
                };
                f.routine
                    .slots
                    .get(s as usize - f.base as usize)
                    .is_some_and(|info| info.kind == SlotKind::Const)
            }
        }
    }

    /// Makes a value fit its destination.
    #[inline]
    pub(crate) fn convert(&mut self, v: Value, conv: &Conv) -> R<Value> {
        match (conv, &v) {
            (Conv::None, _) | (Conv::Num, Value::Num(_)) | (Conv::Dnum, Value::Dnum(_)) => Ok(v),
            _ => self.convert_slow(v, conv),
        }
    }

    fn convert_slow(&mut self, v: Value, conv: &Conv) -> R<Value> {
        match conv {
            Conv::None => Ok(v),
            Conv::Num => match v {
                Value::Num(_) => Ok(v),
                Value::Dnum(x) => {
                    if x.abs() > f64::from(f32::MAX) {
                        fault(rapid_error(
                            &self.prog,
                            ErrorCode::NumLimit,
                            "the value is outside the range of num".into(),
                        ))
                    } else {
                        Ok(Value::Num(x as f32))
                    }
                }
                Value::Record { .. } if self.is_signal(&v) => self.signal_value(&v).map(Value::Num),
                other => invalid(format!("expected a num, found {}", describe(&other))),
            },
            Conv::Dnum => match v {
                Value::Dnum(_) => Ok(v),
                Value::Num(x) => Ok(Value::Dnum(f64::from(x))),
                Value::Record { .. } if self.is_signal(&v) => {
                    self.signal_value(&v).map(|x| Value::Dnum(f64::from(x)))
                }
                other => invalid(format!("expected a dnum, found {}", describe(&other))),
            },
            Conv::Full(ty) => {
                if let Value::Record { ty: t, .. } = &v
                    && ty.dims.is_empty()
                    && t.eq_ignore_ascii_case(&ty.name)
                {
                    return Ok(v);
                }
                rapid_evaluator::coerce(v, ty, &TypesEnv(&self.prog.types))
                    .or_else(|e| self.eval_error(e))
            }
        }
    }

    /// A fault for an evaluator error: the controller's error for run-time
    /// errors, an invalid program for the rest.
    pub(crate) fn eval_error<T>(&self, e: EvalError) -> R<T> {
        if e.code.is_runtime() {
            fault(rapid_error(&self.prog, e.code, e.message))
        } else {
            invalid(e.message)
        }
    }

    /// The `ERRNO` name of number `n`.
    pub(crate) fn errno_name(&self, n: f32) -> String {
        if let Some((_, name)) = self.booked.iter().find(|(b, _)| *b == n) {
            return name.clone();
        }
        self.prog
            .errnum_name(n)
            .unwrap_or_else(|| format!("user error {n}"))
    }
}

/// The fault of a controller error (`ERR_...`).
pub(crate) fn rapid_error(prog: &Program, code: ErrorCode, message: String) -> FaultKind {
    named_error(prog, code.name(), message)
}

/// The fault of the predefined error `name` (`ERR_WAIT_MAXTIME`).
pub(crate) fn named_error(prog: &Program, name: &str, message: String) -> FaultKind {
    let errno = prog
        .errnums
        .get(&name.to_ascii_lowercase())
        .copied()
        .unwrap_or(0.0);
    FaultKind::Rapid {
        errno,
        name: name.to_owned(),
        message,
    }
}

pub(crate) fn describe(v: &Value) -> String {
    match v.type_name() {
        Some(t) => t.to_owned(),
        None => "an aggregate".to_owned(),
    }
}
