//! An interpreter for ABB RAPID programs, with a simulated controller
//! around it.
//!
//! A [`Program`] is the modules of one task (grouped as `rapid check`
//! groups them, through the analyzer's [`rapid_analyzer::workspace`]);
//! a [`Machine`] runs one of its routines with the program's data
//! initialised as the controller initialises them when it loads the
//! program (`VAR` data to their initial value or zero, `PERS` data to
//! their declared value, constants computed). Routines are the analyzer's
//! lowered bodies ([`rapid_analyzer::body`]), compiled on their first call
//! with every name resolved; expressions use the evaluator's operators
//! and pure functions, so values are exactly the controller's
//! (single-precision `num`, degrees, error codes).
//!
//! The controller is simulated ([`Machine`] docs): `TPWrite` and
//! `ErrWrite` go to an [`Output`]; moves complete at once; time passes
//! only when the program waits; signals start at zero and follow a
//! script; interrupts run their trap routines; files live in a sandbox
//! folder. A run never hangs and never panics: statements, simulated time
//! and call depth are bounded ([`Limits`]), and whatever the simulation
//! does not support ends the run with a clear [`Outcome`].
//!
//! ```
//! use std::sync::{Arc, Mutex};
//! use rapid_analyzer::task::{Task, Unit};
//! use rapid_runtime::{Config, Machine, Program, Status, Stream};
//!
//! let text = "MODULE m\n  PROC main()\n    TPWrite \"sum: \"\\Num:=1 + 2;\n  ENDPROC\nENDMODULE\n";
//! let unit = Arc::new(Unit::new("m.mod".into(), text.into(), None));
//! let task = Arc::new(Task::new(String::new(), vec![unit], None));
//! let program = Arc::new(Program::new(task, &[]));
//! let lines = Arc::new(Mutex::new(Vec::new()));
//! let sink = lines.clone();
//! let out = move |_: Stream, line: &str| sink.lock().unwrap().push(line.to_owned());
//! let mut machine = Machine::new(program.clone(), Config::default(), Box::new(out));
//! let outcome = machine.run(program.find_routine("main").unwrap());
//! assert_eq!(outcome.status, Status::Finished);
//! assert_eq!(*lines.lock().unwrap(), vec!["sum: 3"]);
//! ```

mod builtins;
mod code;
mod compile;
mod controller;
mod debug;
mod eval;
mod exec;
mod machine;
mod program;
mod types;

use std::path::PathBuf;

pub use builtins::motion::Move;
pub use controller::SignalChange;
pub use debug::Variable;
pub use machine::{Machine, Outcome, StackFrame, Status};
pub use program::{Location, Program, RoutineSummary, SYSTEM_ERRNO_BASE, SignalKind};

/// Where a line of output comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stream {
    /// The FlexPendant's screen (`TPWrite`).
    Pendant,
    /// The event log (`ErrWrite`).
    EventLog,
}

/// Where a run's output goes: one call per line.
pub trait Output: Send {
    fn line(&mut self, stream: Stream, text: &str);
}

impl<F: FnMut(Stream, &str) + Send> Output for F {
    fn line(&mut self, stream: Stream, text: &str) {
        self(stream, text)
    }
}

/// What a debugger decides before a statement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Control {
    /// Run the statement.
    Continue,
    /// End the run (it stops as `Stop` would).
    Terminate,
}

/// A debugger attached to a [`Machine`] ([`Machine::set_debugger`]).
///
/// Its methods are called on the thread that runs the program, with the
/// machine paused at a statement; they may inspect it (stack, variables,
/// evaluate, assign) as long as they like before returning.
pub trait Debugger: Send {
    /// Before each statement ([`Machine::location`] says which).
    fn statement(&mut self, machine: &mut Machine) -> Control;
    /// When an error that no handler will take is about to end the run;
    /// the routines are still active.
    fn error(&mut self, machine: &mut Machine, outcome: &Outcome);
}

/// How far a run may go before it is stopped.
#[derive(Clone, Debug, PartialEq)]
pub struct Limits {
    /// Statements (and loop iterations).
    pub max_steps: u64,
    /// Simulated seconds.
    pub max_time: f64,
    /// Active routines at once (recursion).
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
    /// Record every move ([`Machine::moves`]).
    pub trace: bool,
}

/// Runs `f` on a thread with a stack large enough for [`Limits::max_depth`]
/// nested routines (deep recursion in RAPID is deep recursion here), and
/// returns its result; a panic becomes `None`.
pub fn on_large_stack<R: Send + 'static>(f: impl FnOnce() -> R + Send + 'static) -> Option<R> {
    std::thread::Builder::new()
        .name("rapid-run".to_owned())
        .stack_size(STACK_BYTES)
        .spawn(f)
        .ok()?
        .join()
        .ok()
}

/// The stack [`on_large_stack`] gives: about 1 MB per nested routine in an
/// unoptimised build, far less in a release build.
pub const STACK_BYTES: usize = 512 << 20;
