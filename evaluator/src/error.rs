//! Evaluation errors.

use std::fmt;

/// Why an evaluation did not produce a value.
///
/// The first group are the controller's run-time errors (the `ERRNO` the
/// robot would set); [`ErrorCode::name`] gives their RAPID constant name. The
/// second group are reasons why the evaluator cannot or will not compute a
/// value at edit time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorCode {
    /// `ERR_DIVZERO`: division by zero (`/`, `DIV`, `MOD`).
    DivZero,
    /// `ERR_OUTOFBND`: array index or string position outside its bounds.
    OutOfBnd,
    /// `ERR_STRTOOLNG`: a string longer than 80 characters.
    StrTooLong,
    /// `ERR_ILLQUAT`: an orientation too far from normalised to be used.
    IllQuat,
    /// `ERR_NOTINTVAL`: an integer operation on a non-integer value.
    NotIntVal,
    /// `ERR_MAXINTVAL`: an integer too large for an integer operation.
    MaxIntVal,
    /// `ERR_ARGVALERR`: an argument outside the function's domain
    /// (`Sqrt(-1)`, `ACos(2)`, an invalid `StrToByte` string, ...).
    ArgValErr,
    /// `ERR_NUM_LIMIT`: a result outside the range of `num`/`dnum`.
    NumLimit,
    /// `ERR_FRAME`: a frame cannot be computed from the given positions.
    Frame,
    /// `ERR_ILLDIM`: an incorrect array dimension.
    IllDim,
    /// The name refers to a `VAR` or `PERS` data object, whose value is only
    /// known at run time.
    NotConstant,
    /// The name is not known to the environment.
    UnknownName,
    /// The function is not pure or not supported by the evaluator.
    UnknownFunction,
    /// The expression is something the evaluator does not handle.
    Unsupported,
    /// Operand or argument types do not fit (a compile-time error in RAPID).
    TypeMismatch,
    /// Wrong number, names or kinds of arguments in a call.
    BadArguments,
    /// A literal that cannot be decoded.
    BadLiteral,
    /// A constant that (indirectly) refers to itself.
    Cycle,
    /// Nesting (of expressions or constant chains) deeper than the limit.
    TooDeep,
    /// The step budget ran out (huge aggregates, exponential constant
    /// chains).
    TooComplex,
}

impl ErrorCode {
    /// The RAPID error constant (`"ERR_DIVZERO"`) for run-time errors, or a
    /// short kebab-case name for the edit-time kinds (`"not-constant"`).
    pub fn name(self) -> &'static str {
        match self {
            ErrorCode::DivZero => "ERR_DIVZERO",
            ErrorCode::OutOfBnd => "ERR_OUTOFBND",
            ErrorCode::StrTooLong => "ERR_STRTOOLNG",
            ErrorCode::IllQuat => "ERR_ILLQUAT",
            ErrorCode::NotIntVal => "ERR_NOTINTVAL",
            ErrorCode::MaxIntVal => "ERR_MAXINTVAL",
            ErrorCode::ArgValErr => "ERR_ARGVALERR",
            ErrorCode::NumLimit => "ERR_NUM_LIMIT",
            ErrorCode::Frame => "ERR_FRAME",
            ErrorCode::IllDim => "ERR_ILLDIM",
            ErrorCode::NotConstant => "not-constant",
            ErrorCode::UnknownName => "unknown-name",
            ErrorCode::UnknownFunction => "unknown-function",
            ErrorCode::Unsupported => "unsupported",
            ErrorCode::TypeMismatch => "type-mismatch",
            ErrorCode::BadArguments => "bad-arguments",
            ErrorCode::BadLiteral => "bad-literal",
            ErrorCode::Cycle => "cycle",
            ErrorCode::TooDeep => "too-deep",
            ErrorCode::TooComplex => "too-complex",
        }
    }

    /// Whether the controller would raise this error at run time (and set
    /// `ERRNO` to the constant of [`ErrorCode::name`]).
    pub fn is_runtime(self) -> bool {
        matches!(
            self,
            ErrorCode::DivZero
                | ErrorCode::OutOfBnd
                | ErrorCode::StrTooLong
                | ErrorCode::IllQuat
                | ErrorCode::NotIntVal
                | ErrorCode::MaxIntVal
                | ErrorCode::ArgValErr
                | ErrorCode::NumLimit
                | ErrorCode::Frame
                | ErrorCode::IllDim
        )
    }
}

impl fmt::Display for ErrorCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An evaluation failure: a code and a human-readable message.
#[derive(Debug, Clone, PartialEq)]
pub struct EvalError {
    /// What kind of failure.
    pub code: ErrorCode,
    /// A sentence for the user, e.g. `division by zero`.
    pub message: String,
}

impl EvalError {
    /// A new error.
    pub fn new(code: ErrorCode, message: impl Into<String>) -> Self {
        EvalError {
            code,
            message: message.into(),
        }
    }
}

impl fmt::Display for EvalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.code.name(), self.message)
    }
}

impl std::error::Error for EvalError {}

pub(crate) fn err<T>(code: ErrorCode, message: impl Into<String>) -> Result<T, EvalError> {
    Err(EvalError::new(code, message))
}
