//! A virtual controller for ABB RAPID programs: the tasks of a controller
//! run together on a simulated world.
//!
//! - A [`Program`] is the modules of one task (grouped as `rapid check`
//!   groups them, through the analyzer's [`rapid_analyzer::workspace`]),
//!   compiled routine by routine from the analyzer's lowered bodies with
//!   every name resolved and every call bound by `sema`
//!   ([`rapid_analyzer::resolve`]): the runtime resolves nothing itself.
//!   Values and operators are the evaluator's, so results are exactly the
//!   controller's (single-precision `num`, degrees, error codes).
//! - A [`Controller`] holds one [`Machine`] per task over one shared world
//!   (the clock, signals, the persistents the tasks share, files, robots,
//!   the operator, sockets: [`world`], each a trait a test substitutes). A
//!   deterministic scheduler interleaves the tasks statement by statement
//!   and moves the clock only when every task waits; a task's data start
//!   as the controller sets them when it loads the program (`VAR` data at
//!   their initial value or zero, `PERS` data at their declared value,
//!   constants computed).
//! - Machines keep their frames as data and run a slice at a time, so a
//!   debugger drives the controller until the next event (a breakpoint, a
//!   step's end, an error, the end) without a thread of its own, and RAPID
//!   recursion is bounded by [`Limits::max_depth`], not by the host's
//!   stack.
//!
//! A run never hangs and never panics: statements, simulated time and call
//! depth are bounded ([`Limits`]), and whatever the simulation does not
//! support ends the task with a clear [`Outcome`].
//!
//! ```
//! use std::sync::{Arc, Mutex};
//! use rapid_analyzer::task::{Task, Unit};
//! use rapid_runtime::{Config, Program, Status, Stream};
//!
//! let text = "MODULE m\n  PROC main()\n    TPWrite \"sum: \"\\Num:=1 + 2;\n  ENDPROC\nENDMODULE\n";
//! let unit = Arc::new(Unit::new("m.mod".into(), text.into(), None));
//! let task = Arc::new(Task::new(String::new(), vec![unit], None));
//! let program = Arc::new(Program::new(task, &[]));
//! let lines = Arc::new(Mutex::new(Vec::new()));
//! let sink = lines.clone();
//! let out = move |_: Stream, line: &str| sink.lock().unwrap().push(line.to_owned());
//! let entry = program.find_routine("main").unwrap();
//! let (outcome, _) = rapid_runtime::run_routine(program, entry, Config::default(), Box::new(out));
//! assert_eq!(outcome.status, Status::Finished);
//! assert_eq!(*lines.lock().unwrap(), vec!["sum: 3"]);
//! ```

mod builtins;
mod code;
mod compile;
mod controller;
mod debug;
mod interrupts;
mod machine;
mod program;
mod rmq;
pub mod world;

use std::path::PathBuf;
use std::sync::Arc;

pub use builtins::motion::Move;

/// A routine call that returned: its task, its name and when it ran
/// (simulated seconds), for a report of where a cycle's time goes.
#[derive(Clone, Debug, PartialEq)]
pub struct RoutineTime {
    pub task: String,
    pub routine: String,
    pub start: f64,
    pub end: f64,
}
pub use controller::{Controller, Event, Resume, TaskKind, TaskSpec};
pub use debug::{DataValue, Variable};
pub use machine::{Machine, Outcome, StackFrame, Status, Stop};
pub use program::{
    DECLARED_NOWHERE, LoadCheck, LoadError, Location, Program, RoutineSummary, SYSTEM_ERRNO_BASE,
    SignalKind, TakenSignal, load_check, load_errors,
};

/// Where a line of output comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stream {
    /// The FlexPendant's screen (`TPWrite`).
    Pendant,
    /// The event log (`ErrWrite`).
    EventLog,
    /// What the pendant shows changes without a line of text (`TPErase`,
    /// `TPShow`, `UIShow`, `UIMsgWriteAbort`): a trace for the person who
    /// reads the run, not a line the program writes.
    Trace,
}

/// Where a run's output goes: one call per line (named by its task,
/// `[T_ROB2] text`, when several tasks run).
pub trait Output: Send {
    fn line(&mut self, stream: Stream, text: &str);
}

impl<F: FnMut(Stream, &str) + Send> Output for F {
    fn line(&mut self, stream: Stream, text: &str) {
        self(stream, text)
    }
}

/// A change of a signal at a simulated time (`--set di1=1@2.5`).
#[derive(Clone, Debug, PartialEq)]
pub struct SignalChange {
    pub name: String,
    pub value: f64,
    /// Seconds after the start of the run.
    pub at: f64,
}

/// How far a run may go before it is stopped.
#[derive(Clone, Debug, PartialEq)]
pub struct Limits {
    /// Statements (and loop iterations), of every task together.
    pub max_steps: u64,
    /// Simulated seconds.
    pub max_time: f64,
    /// Active routines at once in a task (recursion).
    pub max_depth: u32,
    /// `RETRY`s of one statement in a row before `ERR_EXCRTYMAX` (the
    /// controller's default is 4).
    pub max_retries: u32,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_steps: 10_000_000,
            max_time: 3600.0,
            max_depth: 500,
            max_retries: 4,
        }
    }
}

/// The configuration of a run.
#[derive(Clone, Debug, Default)]
pub struct Config {
    pub limits: Limits,
    /// Scripted signal changes (at time 0: the starting values).
    pub signals: Vec<SignalChange>,
    /// The folder file instructions work in; without one they are not
    /// supported.
    pub sandbox: Option<PathBuf>,
    /// Record every move ([`Controller::moves`]).
    pub trace: bool,
    /// The operator's scripted answers, one a line
    /// ([`world::parse_answer`]'s forms), for [`world::World::simulated`].
    pub answers: Vec<String>,
    /// The controller's configuration (`SYSPAR`) and what it says of
    /// itself (`BACKINFO`): `ReadCfgData`, `WriteCfgData`, `GetSysInfo`.
    pub system: world::System,
}

/// Runs `routine` (a procedure without parameters) of `program` as the
/// one task of a simulated controller (an [`world::InstantRobot`], the
/// world of [`world::World::simulated`]) to its end: the outcome, and the
/// moves made (with [`Config::trace`]).
pub fn run_routine(
    program: Arc<Program>,
    routine: u32,
    config: Config,
    output: Box<dyn Output>,
) -> (Outcome, Vec<Move>) {
    let world = world::World::simulated(&config, output);
    let mut c = Controller::new(config, world);
    c.add_task(TaskSpec {
        name: "T_ROB1".to_owned(),
        program,
        entry: Some(routine),
        kind: TaskKind::Normal,
        robot: Some(Box::new(world::InstantRobot::new())),
    });
    c.run();
    let outcome = c
        .tasks()
        .first()
        .and_then(|t| t.outcome().cloned())
        .unwrap_or_else(Outcome::finished);
    (outcome, c.moves().to_vec())
}
