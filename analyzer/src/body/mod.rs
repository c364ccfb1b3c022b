//! The lowered body of a routine: its data, statements and handlers as
//! plain data, built from the syntax tree once.
//!
//! This is the form in which tools that follow control flow read a routine
//! (an interpreter runs it; a checker can walk it for a missing `RETURN` or
//! unreachable code) without the syntax tree. It is side-effect free and
//! knows nothing of how a program runs: names stay names (resolving them is
//! the reader's business), expressions are the evaluator's [`Expr`] as
//! [`crate::lower`] gives them, and every statement keeps its byte range in
//! the file so that a reader can report a line.
//!
//! Lowering never fails and never panics: a placeholder (`<SMT>`), a
//! statement with a syntax error or one nested deeper than [`MAX_NESTING`]
//! becomes [`StmtKind::Invalid`] with its range, and a broken expression is
//! [`Expr::Unknown`].
//!
//! ```
//! use rapid_analyzer::body::{StmtKind, routine_bodies};
//! use rapid_analyzer::task::Unit;
//! let text = "MODULE m\n  PROC main()\n    x := 1;\n  ENDPROC\nENDMODULE\n";
//! let unit = Unit::new("m.mod".into(), text.into(), None);
//! let bodies = routine_bodies(&unit);
//! assert_eq!(bodies[0].name, "main");
//! assert!(matches!(bodies[0].stmts[0].kind, StmtKind::Assign { .. }));
//! ```

mod build;
#[cfg(test)]
mod tests;

use std::ops::Range;

use rapid_evaluator::Expr;

use crate::items::{RoutineKind, Storage};

pub use build::{expression_at, expression_of, lower_routine, routine_bodies};

/// Deepest nesting of compound statements that is lowered; a statement
/// deeper than this becomes [`StmtKind::Invalid`].
pub const MAX_NESTING: u32 = 200;

/// The body of one routine (`PROC`, `FUNC` or `TRAP`).
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub kind: RoutineKind,
    /// The routine's name as written.
    pub name: String,
    /// The whole declaration, `PROC` to `ENDPROC`.
    pub range: Range<usize>,
    /// The routine's data declarations, in source order (they may stand
    /// between statements; they are initialised when the routine starts).
    pub data: Vec<LocalData>,
    /// The statements of the routine, in source order.
    pub stmts: Vec<Stmt>,
    /// `BACKWARD` handler.
    pub backward: Option<Handler>,
    /// `ERROR` handler.
    pub error: Option<ErrorHandler>,
    /// `UNDO` handler.
    pub undo: Option<Handler>,
}

/// A data declaration inside a routine.
#[derive(Clone, Debug, PartialEq)]
pub struct LocalData {
    pub name: String,
    pub name_range: Range<usize>,
    pub range: Range<usize>,
    pub storage: Storage,
    /// The type name as written (`num`, `robtarget`, a user type).
    pub ty: String,
    /// The dimension expressions of an array (`{3, n}`), outermost first.
    pub dims: Vec<Expr>,
    /// The initial value, if any.
    pub init: Option<Expr>,
}

/// A `BACKWARD` or `UNDO` handler.
#[derive(Clone, Debug, PartialEq)]
pub struct Handler {
    pub range: Range<usize>,
    pub stmts: Vec<Stmt>,
}

/// An `ERROR` handler: the error numbers it is limited to
/// (`ERROR (ERR_DIVZERO, 56)`; empty: every error) and its statements.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorHandler {
    pub range: Range<usize>,
    pub errors: Vec<Expr>,
    pub stmts: Vec<Stmt>,
}

/// A statement with its byte range.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    pub range: Range<usize>,
    pub kind: StmtKind,
}

/// What a statement does.
#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    /// `target := value;`. The target is a data reference: a name, a
    /// component (`p.trans.x`) or an element (`a{i}`).
    Assign { target: Expr, value: Expr },
    /// A procedure call (instructions such as `TPWrite` or `Stop` too).
    Call(Call),
    /// `IF ... THEN ... ELSEIF ... ELSE ... ENDIF` and the compact
    /// `IF cond stmt;` (one branch, one statement, `compact` set).
    If {
        branches: Vec<Branch>,
        otherwise: Option<Vec<Stmt>>,
        compact: bool,
    },
    /// `FOR var FROM from TO to [STEP step] DO ... ENDFOR`.
    For {
        var: String,
        var_range: Range<usize>,
        from: Expr,
        to: Expr,
        step: Option<Expr>,
        body: Vec<Stmt>,
    },
    /// `WHILE cond DO ... ENDWHILE`.
    While { cond: Expr, body: Vec<Stmt> },
    /// `TEST value CASE a, b: ... DEFAULT: ... ENDTEST`.
    Test {
        value: Expr,
        cases: Vec<Case>,
        default: Option<Vec<Stmt>>,
    },
    /// `name:`, a target of `GOTO`.
    Label(String),
    /// `GOTO name;`.
    Goto(String),
    /// `RETURN [value];`.
    Return(Option<Expr>),
    /// `RAISE [errno];`.
    Raise(Option<Expr>),
    /// `EXIT;`: ends the program.
    Exit,
    /// `RETRY;` (error handlers).
    Retry,
    /// `TRYNEXT;` (error handlers).
    TryNext,
    /// `CONNECT interrupt WITH trap;`.
    Connect {
        interrupt: Expr,
        trap: String,
        trap_range: Range<usize>,
    },
    /// A placeholder (`<SMT>`), a statement with a syntax error, or one
    /// nested too deeply to lower.
    Invalid,
}

/// One `IF` or `ELSEIF` branch.
#[derive(Clone, Debug, PartialEq)]
pub struct Branch {
    pub cond: Expr,
    pub body: Vec<Stmt>,
}

/// One `CASE` of a `TEST`.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    pub range: Range<usize>,
    pub values: Vec<Expr>,
    pub body: Vec<Stmt>,
}

/// A procedure call.
#[derive(Clone, Debug, PartialEq)]
pub struct Call {
    pub callee: Callee,
    /// The range of the name (or of the `%...%` late binding).
    pub callee_range: Range<usize>,
    pub args: Vec<CallArg>,
}

/// Which procedure a call names.
#[derive(Clone, Debug, PartialEq)]
pub enum Callee {
    /// `Name args;`
    Name(String),
    /// `%expr% args;`: the name is a string computed when the call runs.
    Late(Expr),
}

/// One argument of a procedure call.
///
/// | source          | `name`        | `optional` | `value`                 |
/// |-----------------|---------------|------------|-------------------------|
/// | `x`             | `None`        | no         | `Expr(x)`               |
/// | `ToPoint:=x`    | `Some("ToPoint")` | no     | `Expr(x)`               |
/// | `\WObj:=x`      | `Some("WObj")`| yes        | `Expr(x)`               |
/// | `\Conc`         | `Some("Conc")`| yes        | `Switch`                |
/// | `\Opt?x`        | `Some("Opt")` | yes        | `Conditional("x")`      |
/// | `*`             | `None`        | no         | `Star`                  |
#[derive(Clone, Debug, PartialEq)]
pub struct CallArg {
    pub range: Range<usize>,
    pub name: Option<String>,
    /// Written in the optional form, with a backslash.
    pub optional: bool,
    pub value: ArgValue,
}

/// The value part of a [`CallArg`].
#[derive(Clone, Debug, PartialEq)]
pub enum ArgValue {
    /// An expression (a data reference for `VAR`, `PERS` and `INOUT`
    /// parameters).
    Expr(Expr),
    /// A switch, `\Name` without a value.
    Switch,
    /// `\Opt?x`: the optional parameter `x` of the calling routine,
    /// passed on when it is present.
    Conditional(String),
    /// `*`: the target stored in a motion instruction.
    Star,
    /// An argument that could not be read (a placeholder, a syntax error).
    Invalid,
}

impl Body {
    /// Every statement of the body, the handlers' too, with the ones nested
    /// in compound statements, in source order (a statement before the ones
    /// it holds).
    pub fn walk(&self, f: &mut impl FnMut(&Stmt)) {
        walk_list(&self.stmts, f);
        for h in [&self.backward, &self.undo].into_iter().flatten() {
            walk_list(&h.stmts, f);
        }
        if let Some(h) = &self.error {
            walk_list(&h.stmts, f);
        }
    }
}

/// Calls `f` on each statement of `list` and on the statements they hold,
/// in source order.
pub fn walk_list(list: &[Stmt], f: &mut impl FnMut(&Stmt)) {
    for s in list {
        f(s);
        for inner in s.kind.lists() {
            walk_list(inner, f);
        }
    }
}

impl StmtKind {
    /// The statement lists this statement holds (the branches of an `IF`,
    /// the body of a loop, the cases of a `TEST`), in source order.
    pub fn lists(&self) -> Vec<&[Stmt]> {
        match self {
            StmtKind::If {
                branches,
                otherwise,
                ..
            } => branches
                .iter()
                .map(|b| b.body.as_slice())
                .chain(otherwise.as_deref())
                .collect(),
            StmtKind::For { body, .. } | StmtKind::While { body, .. } => vec![body.as_slice()],
            StmtKind::Test { cases, default, .. } => cases
                .iter()
                .map(|c| c.body.as_slice())
                .chain(default.as_deref())
                .collect(),
            _ => Vec::new(),
        }
    }
}
