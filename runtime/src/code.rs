//! The compiled form of a routine: a flat list of operations on an operand
//! stack, with every name already resolved (by `sema`, see
//! [`crate::compile`]) to a storage slot, a routine or a built-in, and
//! every call already bound. Control flow is jumps, so a running routine
//! is a program counter in a frame: the machine can stop between any two
//! operations and go on later ([`crate::machine`]), and calls need no
//! recursion on the host's stack.

use std::ops::Range;

use rapid_analyzer::catalogue::{Mode, Routine as CatalogueRoutine};
use rapid_analyzer::items::RoutineKind;
use rapid_evaluator::{BinOp, Type, UnOp, Value};

use crate::builtins::{FuncFn, InsFn};

/// An index into [`Code::ops`].
pub(crate) type Pc = u32;

/// One operation. Values go on the value stack, places (where data is
/// stored) on the place stack, and a call's arguments on the argument
/// stack.
#[derive(Clone, Debug)]
pub(crate) enum Op {
    // Statements.
    /// A statement boundary: the statement [`Code::stmts`]`[i]` starts. A
    /// step is counted, interrupts run, a debugger may stop, and another
    /// task may run first.
    Stmt(u32),
    /// The statement running is now `i` (a loop's head, a declaration),
    /// without a boundary.
    Mark(u32),
    /// A loop iteration: counted against the step budget.
    Tick,

    // Values.
    Const(u32),
    Local(u32),
    /// Data of the task.
    Global(u32),
    /// A persistent the tasks share.
    Pers(u32),
    /// Component `names[i]` of the record on the stack.
    Field(u32),
    /// An element of the array below `n` index values.
    Index(u32),
    /// `n` values made an aggregate, of type `types[t]` when known.
    Aggregate {
        n: u32,
        ty: Option<u32>,
    },
    Unary(UnOp),
    Binary(BinOp),
    /// The value made a value of `convs[i]`.
    Convert(u32),
    /// Is parameter slot `i` given?
    Present(u32),

    // Places.
    PlaceLocal(u32),
    PlaceGlobal(u32),
    PlacePers(u32),
    PlaceField(u32),
    /// `n` index values, popped, step into the place.
    PlaceIndex(u32),
    /// The value at the place on top (which is popped).
    Load,
    /// Pops a value and a place, stores the value there.
    Store,
    /// Pops a value, stores it in local slot `i` (an assignment to a
    /// routine's data or parameter).
    StoreLocal(u32),
    /// Pops a value, stores it in the task's data object `g`.
    StoreGlobal(u32),

    // Arguments of a call, in the order written.
    ArgValue,
    ArgPlace,
    ArgSwitch,
    ArgStar,
    /// `\Name?p`: the caller's parameter slot `p`, when given.
    ArgCond {
        slot: u32,
        by_ref: bool,
    },

    // Calls.
    /// A routine of the program ([`Code::calls`]`[i]`).
    Call(u32),
    /// An instruction or function of the controller ([`Code::builtins`]).
    Builtin(u32),
    /// A pure function the evaluator computes ([`Code::pures`]).
    Pure(u32),
    /// `%name% args;`: the name on the value stack, the arguments
    /// ([`Code::lates`]`[i]`) on the argument stack.
    Late(u32),
    /// Returns from the routine (with the value on top, for a function).
    Return {
        value: bool,
    },
    /// Falls off the end of the body: a procedure returns, a function
    /// fails with `ERR_FNCNORET`.
    EndBody,
    /// The end of the `ERROR` handler: the routine returns.
    EndHandler,
    /// The end of the `UNDO` handler: the routine is left.
    EndUndo,
    /// The end of a data object's initial value (a frame of its own).
    EndInit,

    // Control flow.
    Jump(Pc),
    JumpIfFalse(Pc),
    JumpIfTrue(Pc),
    /// A `FOR` loop starts: from, to and (with `step`) the step on the
    /// stack; its state goes to three hidden slots from `state`.
    ForStart {
        state: u32,
        step: bool,
    },
    /// The loop's next value to the variable slot `var`, or out to `exit`.
    ForCheck {
        var: u32,
        state: u32,
        exit: Pc,
    },
    /// The loop variable's next value; back to the check at `check`.
    ForNext {
        state: u32,
        check: Pc,
    },
    /// The value on top to a hidden slot.
    SetHidden(u32),
    Raise {
        value: bool,
    },
    Retry,
    TryNext,
    Exit,
    /// `CONNECT` the place on top with the trap routine.
    Connect(u32),
    /// `WaitUntil` starts: `\MaxTime`, `\PollRate` on the value stack
    /// (`Const` absent markers when not given) and `\TimeFlag` as a place
    /// or not ([`WaitUntil`]).
    WaitUntilStart(u32),
    /// The condition on top: go on when it holds, else wait and go back to
    /// `again`.
    WaitUntilCheck {
        site: u32,
        again: Pc,
    },
    /// A data declaration of the routine: its dimensions and initial value
    /// (when `init`) on the stack.
    InitLocal {
        slot: u32,
        decl: u32,
    },
    /// A module data object's starting value (an initialisation frame).
    InitGlobal {
        decl: u32,
    },
    /// A statement or expression that cannot run ([`Code::failures`]).
    Fail(u32),
}

/// A compiled routine (or a data object's initial value).
#[derive(Debug)]
pub(crate) struct Code {
    pub name: String,
    pub kind: CodeKind,
    /// The routine's index in the program (none for initial values).
    pub routine: Option<u32>,
    pub unit: usize,
    /// The program's module the code belongs to.
    pub module: usize,
    pub range: Range<usize>,
    pub params: Vec<Param>,
    /// Every local slot: the parameters first, then the routine's data,
    /// the `FOR` variables and hidden state.
    pub slots: Vec<SlotInfo>,
    pub ops: Vec<Op>,
    pub stmts: Vec<StmtInfo>,
    pub consts: Vec<Value>,
    pub names: Vec<Box<str>>,
    pub types: Vec<Type>,
    pub convs: Vec<Conv>,
    pub calls: Vec<CallSite>,
    pub builtins: Vec<BuiltinSite>,
    pub pures: Vec<PureSite>,
    pub lates: Vec<LateSite>,
    pub waits: Vec<WaitUntil>,
    pub decls: Vec<DataInit>,
    pub failures: Vec<Failure>,
    /// Where the body starts (after the data's initialisation).
    pub body: Pc,
    pub error: Option<Handler>,
    /// Where the `UNDO` handler starts.
    pub undo: Option<Pc>,
    /// How a returned value is made a value of the return type.
    pub returns: Option<u32>,
    /// The statement that stands for the routine's end (`ENDFUNC`).
    pub end_stmt: u32,
    /// The `FOR` loops: where each runs and its variable.
    pub for_loops: Vec<ForLoop>,
    /// Each call bound: the routine's name and the parameter of each
    /// argument (for the oracle that compares them with the checker's).
    pub bindings: Vec<(String, Vec<String>)>,
}

/// A `FOR` loop of the code: its variable (name, the range of the name in
/// the loop, slot) and the operations it spans.
#[derive(Clone, Debug)]
pub(crate) struct ForLoop {
    pub name: String,
    pub var_range: Range<usize>,
    pub slot: u32,
    pub start: Pc,
    pub end: Pc,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum CodeKind {
    Routine(RoutineKind),
    /// A module data object's starting value.
    Init,
    /// An expression a debugger evaluates in a frame.
    Eval,
}

/// A parameter as calls bind it.
#[derive(Clone, Debug)]
pub(crate) struct Param {
    pub name: String,
    pub mode: Mode,
    pub optional: bool,
    pub switch: bool,
    pub conv: Option<u32>,
}

impl Param {
    pub fn by_reference(&self) -> bool {
        by_reference(self.mode)
    }
}

/// Is a parameter of this mode passed by reference?
pub(crate) fn by_reference(mode: Mode) -> bool {
    matches!(mode, Mode::Var | Mode::Pers | Mode::InOut | Mode::Ref)
}

/// What a local slot holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SlotKind {
    Param,
    Var,
    Pers,
    Const,
    For,
    /// State of a loop, a `TEST` or a wait, not visible to the program.
    Hidden,
}

/// A local slot's name and declared type (array sizes are 0: not known
/// before the routine runs).
#[derive(Clone, Debug)]
pub(crate) struct SlotInfo {
    pub name: String,
    pub ty: Type,
    pub kind: SlotKind,
}

/// A statement (or a declaration, or the routine's end) of the code.
#[derive(Clone, Debug)]
pub(crate) struct StmtInfo {
    pub range: Range<usize>,
    /// 1-based line of its start.
    pub line: u32,
    /// Where its operations start and end (`RETRY` goes to the start,
    /// `TRYNEXT` to the end).
    pub start: Pc,
    pub end: Pc,
}

/// The initialisation of a data object: its type, array rank, whether it
/// has an initial value, and how the value is made one of the type.
#[derive(Clone, Debug)]
pub(crate) struct DataInit {
    pub ty: Type,
    pub dims: u32,
    pub init: bool,
    pub conv: Option<u32>,
    /// The slot (routine data) or the global it initialises.
    pub target: Target,
}

#[derive(Clone, Copy, Debug)]
pub(crate) enum Target {
    Slot,
    Global(u32),
    Pers(u32),
}

/// The `ERROR` handler: where it starts and the errors it takes (none
/// listed: every error).
#[derive(Clone, Debug)]
pub(crate) struct Handler {
    pub pc: Pc,
    pub errors: Vec<Simple>,
}

/// An expression evaluated outside the operation stream (an error
/// number of an `ERROR (...)` list): constants and data references.
#[derive(Clone, Debug)]
pub(crate) enum Simple {
    Const(Value),
    Local(u32),
    Global(u32),
    Pers(u32),
    Neg(Box<Simple>),
    /// Anything else: never equal to an error number.
    Other,
}

/// How a value is made to fit where it is stored.
#[derive(Clone, Debug)]
pub(crate) enum Conv {
    /// A `num`: a `dnum` narrows, a signal is read.
    Num,
    /// A `dnum`: a `num` widens, a signal is read.
    Dnum,
    /// Anything else the evaluator types (records, arrays, aggregates).
    Full(Type),
}

/// A call of a routine of the program: the argument stack holds
/// `params.len()` arguments, argument `k` for parameter `params[k]`.
#[derive(Clone, Debug)]
pub(crate) struct CallSite {
    pub routine: u32,
    pub params: Vec<u32>,
}

/// A call of an instruction or a function of the controller: argument `k`
/// is for the catalogue parameter `params[k]` of `sig` (the task's view).
#[derive(Clone, Debug)]
pub(crate) struct BuiltinSite {
    pub name: &'static str,
    pub sig: &'static CatalogueRoutine,
    pub params: Vec<u32>,
    /// The data each argument names, when it is a name (`p10`), as
    /// written: for traces and messages.
    pub names: Vec<Option<Box<str>>>,
    pub f: BuiltinFn,
}

#[derive(Clone, Copy, Debug)]
pub(crate) enum BuiltinFn {
    Instruction(InsFn),
    Function(FuncFn),
}

/// A call of a pure function: the arguments' names (as written) and the
/// function's name.
#[derive(Clone, Debug)]
pub(crate) struct PureSite {
    pub name: Box<str>,
    pub args: Vec<Option<Box<str>>>,
}

/// A late-bound call: the arguments' names (as written), resolved when
/// it runs.
#[derive(Clone, Debug)]
pub(crate) struct LateSite {
    pub args: Vec<Option<Box<str>>>,
    /// A call written by name whose procedure no module declared when the
    /// routine was compiled: the controller links it when a `Load` brings
    /// the procedure, and a call it still cannot link stops the run as a
    /// name declared nowhere.
    pub linked: bool,
}

/// A `WaitUntil`: the hidden slots of its state and whether `\MaxTime`,
/// `\PollRate` and `\TimeFlag` are given.
#[derive(Clone, Debug)]
pub(crate) struct WaitUntil {
    pub state: u32,
    pub max_time: bool,
    pub poll_rate: bool,
    pub time_flag: bool,
}

/// Why a statement or an expression cannot run.
#[derive(Clone, Debug)]
pub(crate) enum Failure {
    /// A routine name that nothing declares.
    Unknown(String),
    /// A data name that nothing declares.
    UnknownData(String),
    /// A built-in the simulation does not implement.
    Unsupported(String),
    /// Anything else, with a message.
    Invalid(String),
}
