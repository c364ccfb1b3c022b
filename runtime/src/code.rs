//! The compiled form of a routine: the body IR with its names resolved to
//! storage slots, routines and built-ins, and literals decoded, so that a
//! statement runs without looking anything up by name.

use std::ops::Range;

use rapid_analyzer::catalogue::Mode;
use rapid_analyzer::items::RoutineKind;
use rapid_evaluator::{BinOp, Type, UnOp, Value};

use crate::builtins::{FuncFn, InsFn};

/// A compiled routine.
pub(crate) struct Routine {
    /// Index in [`crate::program::Program::routines`].
    pub id: u32,
    pub name: String,
    pub kind: RoutineKind,
    pub unit: usize,
    pub range: Range<usize>,
    pub params: Vec<Param>,
    /// Every local slot: the parameters first (slot = parameter index),
    /// then the routine's data, then `FOR` variables.
    pub slots: Vec<SlotInfo>,
    /// The routine's data, initialised in order when it starts.
    pub data: Vec<LocalInit>,
    pub body: Vec<Stmt>,
    pub error: Option<ErrorHandler>,
    pub undo: Option<Vec<Stmt>>,
    /// How a returned value is made a value of the return type.
    pub returns_conv: Conv,
}

/// A parameter as calls bind it.
pub(crate) struct Param {
    pub name: String,
    pub mode: Mode,
    pub optional: bool,
    pub switch: bool,
    pub conv: Conv,
}

/// What a local slot holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SlotKind {
    Param,
    Var,
    Pers,
    Const,
    For,
}

/// A local slot's name and declared type (array dimensions are `0` when
/// not known before the routine runs).
pub(crate) struct SlotInfo {
    pub name: String,
    pub ty: Type,
    pub kind: SlotKind,
}

/// The initialisation of one routine datum.
pub(crate) struct LocalInit {
    pub slot: u32,
    pub ty_name: String,
    pub dims: Vec<Expr>,
    pub init: Option<Expr>,
    pub conv: Conv,
    pub range: Range<usize>,
}

pub(crate) struct ErrorHandler {
    /// The error numbers it handles; empty for every error.
    pub errors: Vec<Expr>,
    pub body: Vec<Stmt>,
}

/// A compiled statement with its byte range.
pub(crate) struct Stmt {
    pub range: Range<usize>,
    pub kind: StmtKind,
}

pub(crate) enum StmtKind {
    Assign {
        target: Expr,
        value: Expr,
        conv: Conv,
    },
    /// A call of a routine of the program.
    Call {
        routine: u32,
        args: Vec<Arg>,
    },
    /// `%name% args;`: resolved when it runs.
    Late {
        name: Expr,
        args: Vec<Arg>,
    },
    /// A built-in instruction the simulation implements, with its
    /// arguments bound to the catalogue's parameters.
    Builtin {
        name: &'static str,
        f: InsFn,
        args: Vec<Option<ArgValue>>,
    },
    If {
        branches: Vec<(Expr, Vec<Stmt>)>,
        otherwise: Vec<Stmt>,
    },
    For {
        slot: u32,
        from: Expr,
        to: Expr,
        step: Option<Expr>,
        body: Vec<Stmt>,
    },
    While {
        cond: Expr,
        body: Vec<Stmt>,
    },
    Test {
        value: Expr,
        cases: Vec<(Vec<Expr>, Vec<Stmt>)>,
        default: Vec<Stmt>,
    },
    Label(u32),
    Goto(u32),
    Return(Option<Expr>),
    Raise(Option<Expr>),
    Exit,
    Retry,
    TryNext,
    Connect {
        target: Expr,
        trap: u32,
    },
    /// A statement that cannot run: why (an unknown procedure, a
    /// placeholder, bad arguments), and whether it is an instruction the
    /// simulation does not support.
    Fail(Failure),
}

/// Why a statement or an expression cannot run.
#[derive(Clone, Debug)]
pub(crate) enum Failure {
    /// A name that nothing declares.
    Unknown(String),
    /// A built-in the simulation does not implement.
    Unsupported(String),
    /// Anything else, with a message (a placeholder, a broken statement,
    /// arguments that do not fit).
    Invalid(String),
}

/// How a value is made to fit its destination when stored.
#[derive(Clone, Debug)]
pub(crate) enum Conv {
    /// Stored as it is.
    None,
    /// A `num`: a `dnum` narrows, a signal is read.
    Num,
    /// A `dnum`: a `num` widens, a signal is read.
    Dnum,
    /// Anything else the evaluator types (records, arrays, aggregates).
    Full(Type),
}

/// A compiled expression.
pub(crate) enum Expr {
    Const(Value),
    Local(u32),
    Global(u32),
    Field(Box<Expr>, Box<str>),
    Index(Box<Expr>, Vec<Expr>),
    /// An aggregate, typed by the context when it has one.
    Aggregate(Option<Type>, Vec<Expr>),
    Unary(UnOp, Box<Expr>),
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// A function of the program.
    Call {
        routine: u32,
        args: Vec<Arg>,
    },
    /// A pure function the evaluator computes.
    Pure {
        name: Box<str>,
        args: Vec<Arg>,
    },
    /// A function of the simulated controller, arguments bound to the
    /// catalogue's parameters.
    Func {
        name: &'static str,
        f: FuncFn,
        args: Vec<Option<ArgValue>>,
    },
    /// `Present(p)`: the parameter slot.
    Present(u32),
    Fail(Failure),
}

/// An argument of a call of a program routine (bound when the call runs).
pub(crate) struct Arg {
    pub name: Option<Box<str>>,
    pub value: ArgValue,
}

pub(crate) enum ArgValue {
    Expr(Expr),
    Switch,
    /// `\Opt?p`: the caller's parameter slot `p`.
    Conditional(u32),
    Star,
}

impl Expr {
    /// The reason a data reference cannot run (an unknown name in it).
    pub(crate) fn failure(&self) -> Option<Failure> {
        match self {
            Expr::Fail(f) => Some(f.clone()),
            Expr::Field(b, _) => b.failure(),
            Expr::Index(b, ix) => b.failure().or_else(|| ix.iter().find_map(Expr::failure)),
            _ => None,
        }
    }

    /// Is this a reference to stored data (which `VAR`/`INOUT` parameters
    /// and assignments need)?
    pub(crate) fn is_place(&self) -> bool {
        match self {
            Expr::Local(_) | Expr::Global(_) => true,
            Expr::Field(b, _) | Expr::Index(b, _) => b.is_place(),
            _ => false,
        }
    }
}
