//! One task of the controller: its data, its frames and operand stacks,
//! its interrupts. A machine runs a slice of its task at a time
//! ([`Machine::run_slice`]) and stops at a statement boundary, at a wait,
//! when the task ends or where a debugger wants it to; every frame is data
//! (a routine's code, its program counter, its slots), so nothing is kept
//! on the host's stack between slices and RAPID recursion is bounded by
//! [`crate::Limits::max_depth`] alone.

mod call;
mod data;
mod fault;
mod run;
mod wait;

use std::sync::Arc;

use rapid_evaluator::Value;

use crate::code::{Code, Pc};
use crate::controller::Shared;
use crate::interrupts::Interrupts;
use crate::program::{Location, Program};

pub(crate) use data::{Place, Root, describe, is_signal};
pub(crate) use fault::{Fault, FaultKind, R, fault, invalid, named_error, rapid_error};
pub(crate) use wait::{
    OperatorWait, PathMark, PathState, SearchWait, SignalTest, Stopped, Timeout, Wait, WaitKind,
    due_on,
};

/// How a task's run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// The entry routine returned.
    Finished,
    /// `EXIT` (or `ExitCycle`) ended the program.
    Exited,
    /// `Stop` (or `Break`) stopped it, or a debugger ended it.
    Stopped,
    /// A static or semistatic task that still ran when the normal tasks
    /// ended (the program ended: the simulation ends with it).
    Halted,
    /// A RAPID error no handler took (its `ERRNO` name in the outcome).
    Error,
    /// An instruction or function the simulation does not support.
    Unsupported,
    /// The program cannot run as written: an unknown name, a placeholder,
    /// arguments that do not fit, a type mismatch.
    Invalid,
    /// The step, time or call-depth budget ran out.
    Budget,
    /// The task waits for something that can never happen.
    Deadlock,
    /// The task waits for the operator and nobody answers (no answer
    /// scripted, no terminal), or the scripted answer does not fit the
    /// question.
    Operator,
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
            Status::Finished | Status::Exited | Status::Stopped | Status::Halted
        )
    }

    pub(crate) fn finished() -> Outcome {
        Outcome {
            status: Status::Finished,
            message: String::new(),
            errno: None,
            at: None,
            stack: Vec::new(),
        }
    }
}

/// One active routine, for stack traces and debuggers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StackFrame {
    pub routine: String,
    pub at: Location,
}

/// A local slot: a value, a reference (`VAR`, `INOUT`, `PERS`
/// parameters), or an optional parameter left out.
#[derive(Clone, Debug)]
pub(crate) enum Slot {
    Val(Value),
    Ref(Place),
    Absent,
}

/// An argument on its way to a call.
#[derive(Clone, Debug)]
pub(crate) enum ArgVal {
    Value(Value),
    Place(Place),
    Switch,
    Star,
    /// A conditional argument whose parameter is not given.
    Absent,
}

/// The state of a data object's starting value.
#[derive(Clone, Debug)]
pub(crate) enum Init {
    Ready,
    Pending,
    Busy,
    Failed(String),
}

/// What a frame is for, and what its end means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FrameKind {
    /// The task's entry routine: its end ends the run.
    Entry,
    /// A call: a function's value goes to the caller's value stack.
    Call,
    /// A trap routine, run for an interrupt.
    Trap,
    /// A data object's starting value.
    Init,
    /// An expression a debugger evaluates.
    Eval,
}

/// Where a frame is at a statement boundary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Boundary {
    /// Not at one (or not yet counted).
    None,
    /// Counted; interrupts and the debugger still to ask.
    Counted,
    /// The debugger stopped here; going on runs the statement.
    Stopped,
}

pub(crate) struct Frame {
    pub code: Arc<Code>,
    pub pc: Pc,
    /// The index of its first slot.
    pub base: u32,
    /// The number of slots below its own (where they are cut back to when
    /// it ends; an evaluation frame shares the slots of the frame it reads).
    pub top: u32,
    /// The heights of the operand stacks when it started.
    pub vals: u32,
    pub places: u32,
    pub args: u32,
    /// The statement running.
    pub stmt: u32,
    pub boundary: Boundary,
    pub kind: FrameKind,
    /// Its error handler runs (for the fault taken at `fault_stmt`).
    pub in_handler: bool,
    pub fault_stmt: u32,
    /// `RETRY`s of `fault_stmt` in a row.
    pub retries: u32,
    /// Leaving the routine with this fault, its `UNDO` handler runs.
    pub undoing: Option<Box<Fault>>,
    /// The frame waits for something ([`Wait`]).
    pub wait: Option<Box<Wait>>,
    /// The simulated time its routine was entered (calls and entries).
    pub entered: f64,
}

/// Where a task is.
#[derive(Clone, Debug)]
pub(crate) enum TaskState {
    /// Not started, or between runs.
    Idle,
    Running,
    Done(Outcome),
}

/// Why a slice ended.
#[derive(Clone, Debug)]
pub(crate) enum Yield {
    /// Its statements are used up; the task can go on.
    Slice,
    /// The task waits.
    Blocked,
    /// A debugger stops the task here.
    Stopped(Stop),
    /// The task ended.
    Done,
    /// An expression a debugger evaluates is done.
    Evaluated,
}

/// Why a debugger stops a task.
#[derive(Clone, Debug)]
pub enum Stop {
    /// Before the first statement (`stopOnEntry`).
    Entry,
    Breakpoint,
    /// A step ended.
    Step,
    Pause,
    /// An error no handler takes; the routines are still active.
    Error(Outcome),
}

/// A running task.
pub struct Machine {
    pub(crate) prog: Arc<Program>,
    /// The task's name (`T_ROB1`) and number (1 for the first).
    pub(crate) name: String,
    pub(crate) number: usize,
    /// The task's own data ([`crate::program::Home::Global`]).
    pub(crate) globals: Vec<Value>,
    pub(crate) init: Vec<Init>,
    /// The controller's persistent of each of the program's.
    pub(crate) pers_map: Vec<u32>,
    pub(crate) slots: Vec<Slot>,
    pub(crate) vals: Vec<Value>,
    pub(crate) places: Vec<Place>,
    pub(crate) args: Vec<ArgVal>,
    pub(crate) frames: Vec<Frame>,
    pub(crate) interrupts: Interrupts,
    /// Error numbers booked with `BookErrNo`, with the names they were
    /// booked in.
    pub(crate) booked: Vec<(f32, String)>,
    pub(crate) state: TaskState,
    /// The signal events seen so far ([`Shared::events`]).
    pub(crate) events_seen: usize,
    /// The event log entries this task's interrupts have seen.
    pub(crate) log_seen: usize,
    /// Messages of the task's queue an `IRMQMessage` interrupt took, for
    /// `RMQGetMessage` in its trap routine.
    pub(crate) rmq_received: std::collections::VecDeque<u32>,
    /// In synchronized movement (`SyncMoveOn`).
    pub(crate) sync_move: Option<Vec<String>>,
    /// A fault a debugger was shown before it ends the task.
    pub(crate) pending: Option<Box<Fault>>,
    /// The value of the last expression a debugger evaluated.
    pub(crate) evaluated: Option<Result<Value, String>>,
    /// A builtin read the clock while evaluating a `WaitUntil`
    /// condition.
    pub(crate) read_clock: bool,
    /// A function of the controller waits (for the operator): the task
    /// blocks, and the wait's end gives the function's result.
    pub(crate) function_wait: Option<Box<Wait>>,
    /// The part the operator chose for `ExecEngine`, run when its answer's
    /// delay is over.
    pub(crate) engine_part: Option<String>,
    /// The procedure a `MoveLSync` calls when its move ends, with the
    /// call depth and statement of the instruction.
    pub(crate) sync_call: Option<(u32, (usize, Option<crate::Location>))>,
    /// The task's YuMi SmartGripper.
    pub(crate) gripper: crate::builtins::gripper::Gripper,
    /// The tool and the work object of the last move (`CTool`, `CWObj`).
    pub(crate) active: [Option<Value>; 2],
    /// The names of the data objects `active` holds, when known
    /// (`GetSysData \ObjectName`).
    pub(crate) active_names: [Option<String>; 2],
    /// The payload `SetSysData` made active, and its name.
    pub(crate) active_load: Option<(Value, Option<String>)>,
    /// The task's motion settings: `VelSet`, `SpeedRefresh`, `AccSet`.
    pub(crate) settings: crate::builtins::settings::MotionSettings,
    /// The task's world zones and their shapes.
    pub(crate) zones: crate::builtins::zones::Zones,
    /// The symbol search `SetDataSearch` started.
    pub(crate) search: crate::builtins::symbols::Search,
    /// The module files `Load` loaded, in order.
    pub(crate) loaded: Vec<crate::builtins::modules::LoadedModule>,
    /// The loads `StartLoad` started.
    pub(crate) load_sessions: crate::builtins::modules::Sessions,
    /// The value parameters given a data object, by slot, with the root
    /// of the place the argument was (`ArgName`), in slot order.
    pub(crate) origins: Vec<(u32, Root)>,
}

impl Machine {
    /// After the instruction running now (its call, its wait), its
    /// statement runs again: the frame goes back to the statement's start.
    pub(crate) fn again(&mut self) {
        if let Some(top) = self.frames.last_mut() {
            let ran = top.code.ops.get(..top.pc as usize).unwrap_or_default();
            if let Some(start) = ran
                .iter()
                .rposition(|op| matches!(op, crate::code::Op::Stmt(_)))
            {
                top.pc = start as Pc;
            }
        }
    }

    /// A task of `prog`, its data as the controller sets them when it
    /// loads the program; shared persistents live in `shared`.
    pub(crate) fn new(
        prog: Arc<Program>,
        name: String,
        number: usize,
        shared: &mut Shared,
    ) -> Machine {
        let n = prog.globals.len();
        let pers_map = prog
            .pers
            .iter()
            .map(|p| shared.persistent(&p.name))
            .collect();
        let mut m = Machine {
            globals: vec![Value::Num(0.0); n],
            init: vec![Init::Pending; n],
            pers_map,
            slots: Vec::new(),
            vals: Vec::new(),
            places: Vec::new(),
            args: Vec::new(),
            frames: Vec::new(),
            interrupts: Interrupts::default(),
            booked: Vec::new(),
            state: TaskState::Idle,
            events_seen: shared.events.len(),
            log_seen: shared.event_log.len(),
            rmq_received: Default::default(),
            sync_move: None,
            pending: None,
            evaluated: None,
            read_clock: false,
            function_wait: None,
            engine_part: None,
            sync_call: None,
            gripper: Default::default(),
            active: [None, None],
            active_names: [None, None],
            active_load: None,
            settings: Default::default(),
            zones: Default::default(),
            search: Default::default(),
            loaded: Vec::new(),
            load_sessions: Default::default(),
            origins: Vec::new(),
            name,
            number,
            prog,
        };
        m.initialise(shared, true);
        m
    }

    /// The program.
    pub fn program(&self) -> &Arc<Program> {
        &self.prog
    }

    /// The task's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The number of active routines.
    pub fn depth(&self) -> usize {
        self.frames
            .iter()
            .filter(|f| !matches!(f.kind, FrameKind::Init | FrameKind::Eval))
            .count()
    }

    /// The active routines, innermost first.
    pub fn stack_frames(&self) -> Vec<StackFrame> {
        self.frames
            .iter()
            .rev()
            .filter(|f| !matches!(f.kind, FrameKind::Init | FrameKind::Eval))
            .map(|f| StackFrame {
                routine: f.code.name.clone(),
                at: self.frame_location(f),
            })
            .collect()
    }

    /// The location of the statement running in the innermost frame.
    pub fn location(&self) -> Option<Location> {
        self.frames.last().map(|f| self.frame_location(f))
    }

    pub(crate) fn frame_location(&self, f: &Frame) -> Location {
        let offset = f
            .code
            .stmts
            .get(f.stmt as usize)
            .map_or(f.code.range.start, |s| s.range.start);
        self.prog.location(f.code.unit, offset)
    }

    /// The task's outcome, once it ended.
    pub fn outcome(&self) -> Option<&Outcome> {
        match &self.state {
            TaskState::Done(o) => Some(o),
            _ => None,
        }
    }

    pub(crate) fn is_done(&self) -> bool {
        matches!(self.state, TaskState::Done(_) | TaskState::Idle)
    }

    /// Starts routine `entry` (a procedure without parameters) from a
    /// clean stack; the task's data stay as they are.
    pub(crate) fn start(&mut self, entry: u32) -> Result<(), String> {
        let Some(code) = self.prog.code(entry).cloned() else {
            return Err("no such routine".to_owned());
        };
        if !code.params.is_empty() {
            return Err(format!("{} takes parameters", code.name));
        }
        self.slots.clear();
        self.origins.clear();
        self.vals.clear();
        self.places.clear();
        self.args.clear();
        self.frames.clear();
        self.pending = None;
        self.push_frame(code, FrameKind::Entry, Vec::new());
        self.state = TaskState::Running;
        Ok(())
    }

    /// Ends the task's run with `outcome`.
    pub(crate) fn finish(&mut self, outcome: Outcome) {
        self.frames.clear();
        self.slots.clear();
        self.origins.clear();
        self.vals.clear();
        self.places.clear();
        self.args.clear();
        self.state = TaskState::Done(outcome);
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
