//! Constant folding with the semantics of ABB RAPID.
//!
//! The evaluator computes what the robot controller would compute for an
//! expression built only from constants: literals, `CONST` data (followed
//! across modules through an [`Env`]), predefined data, operators and the
//! pure functions of the RAPID manual (`Sqrt(2) * Sin(30)`,
//! `OrientZYX(90, 0, 0)`, `Offs(pHome, 0, 0, 100)`).
//!
//! It knows nothing of syntax: the analyzer lowers tree-sitter nodes to the
//! small [`Expr`] form. Results are typed [`Value`]s, whose `Display` is what
//! RAPID's `ValToStr` prints, or an [`EvalError`] whose [`ErrorCode`] names
//! the controller's run-time error (`ERR_DIVZERO`) or says why the value is
//! not known at edit time (a `VAR`/`PERS`, an unknown name).
//!
//! RAPID semantics, not Rust's:
//! - `num` is single precision: every num result is rounded to `f32`
//!   (computed in `f64` first, as the controller's libraries do); `dnum` is
//!   `f64`. Integers up to 8388608 are exact; `DIV`/`MOD` need integers.
//! - Strings are ISO 8859-1 and at most 80 characters (`ERR_STRTOOLNG`).
//! - Angles are degrees; orientations are quaternions `[q1, q2, q3, q4]`
//!   (scalar first), checked (`ERR_ILLQUAT`) and normalised before use.
//!
//! What RAPID knows as data comes from the catalogue crate
//! (`rapid-catalogue`), through [`Env::catalogue`]: each pure function is an
//! implementation registered under its catalogue name, and its arguments are
//! bound by the catalogue's signature; which operands an operator takes is
//! the catalogue's operator table (`rapid_catalogue::operators`), which the
//! analyzer's checker types expressions with.
//!
//! Where the manual leaves a choice open, the evaluator decides as follows:
//! - `pos * pos` is the cross product and `orient * orient` composes the
//!   rotations (quaternion product); `pos / num` divides each coordinate
//!   (not in the manuals' table, but in programs real controllers load);
//!   `pose * pose` is not an operator (use `PoseMult`).
//! - `DIV` truncates towards zero and `MOD` takes the sign of the dividend;
//!   both need integer operands (`ERR_NOTINTVAL`) within the exact integer
//!   range (`ERR_MAXINTVAL`: 8388608 for num, 2^52 for dnum).
//! - A numeric literal is a `num` unless the context asks for `dnum` (an
//!   expected type of dnum reaches the literals of `+ - * / DIV MOD`) or it is
//!   beyond the range of num.
//! - Where the manual only says "a run-time error", the code is
//!   `ERR_ARGVALERR` for arguments outside a function's domain (`Sqrt(-1)`,
//!   `ACos(2)`, `Pow(-8, 0.5)`, a bad `StrToByte` string, a bad number of
//!   decimals), `ERR_OUTOFBND` for string positions outside the string, and
//!   `ERR_NUM_LIMIT` for results beyond the range of num.
//! - `Round`, `Trunc` and `NumToStr` act on the shortest decimal that reads
//!   back as the given num (0.7, not 0.699999988), rounding half away from
//!   zero.
//! - Orientations computed from angles or frames (`OrientZYX`, `MirPos`,
//!   `DefFrame`, `DefDFrame`, `DefAccFrame`) have q1 >= 0, as the manual's
//!   matrix-to-quaternion formula gives; products (`PoseMult`, `PoseInv`,
//!   `RelTool` with a rotation, `orient * orient`) keep the sign of the
//!   quaternion product. `NOrient` leaves an already normalised orientation
//!   (error at most 0.00001) unchanged.
//! - Strings print quoted (`ValToStr("ab")` is `"ab"` with the quotes);
//!   `ByteToStr(7\Char)` is the three characters `\07`.
//!
//! Evaluation never panics and always terminates: nesting depth and the
//! amount of work are bounded ([`Options`]), and cyclic constants are
//! reported ([`ErrorCode::Cycle`]).
//!
//! ```
//! use rapid_evaluator::{Arg, BinOp, EmptyEnv, Expr, eval};
//! let call = |name: &str, args: Vec<Expr>| Expr::Call {
//!     name: name.into(),
//!     args: args.into_iter().map(Arg::positional).collect(),
//! };
//! let e = Expr::Binary(
//!     BinOp::Mul,
//!     Box::new(call("Sqrt", vec![Expr::Num("2".into())])),
//!     Box::new(call("Sin", vec![Expr::Num("30".into())])),
//! );
//! assert_eq!(eval(&e, &EmptyEnv).unwrap().to_string(), "0.707107");
//! ```

mod env;
mod error;
mod eval;
mod expr;
mod functions;
pub mod geometry;
/// The linear algebra the geometry is computed with, for callers that
/// keep poses ([`geometry::isometry`]).
pub use nalgebra;
mod literal;
mod literal_value;
mod operators;
mod types;
mod value;

pub use env::{EmptyEnv, Env, Lookup, MapEnv, VarKind, predefined};
pub use error::{ErrorCode, EvalError};
pub use expr::{Arg, BinOp, Expr, Type, UnOp};
pub use functions::{FUNCTIONS, is_function};
pub use geometry::{
    distance_mm, euler_zyx_deg, iso_of, orient_value, pos_value, pose_value, rotation_deg,
    unit_quat, wobj_frame,
};
pub use literal::{MAX_STRING_LEN, parse_num_literal, parse_string_literal};
pub use literal_value::parse_data_literal;
pub use types::{builtin_record_layout, is_builtin_num_alias, is_builtin_string_alias};
pub use value::{Value, format_dnum, format_num, quote_string};

/// Limits and switches for an evaluation.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// Use the initial value of `VAR`/`PERS` data instead of failing with
    /// [`ErrorCode::NotConstant`]. The names used are reported in
    /// [`Evaluation::initial_values_used`] so the result can be labelled
    /// ("initial value").
    pub allow_initial_values: bool,
    /// Maximum nesting of expressions, counting through constant
    /// definitions ([`ErrorCode::TooDeep`] beyond). A constant whose
    /// initialiser refers to another constant through one operator uses two
    /// levels, so the default 128 allows chains of about 60 constants. Each
    /// level takes about 1 KB of stack in a release build (up to 5 KB
    /// unoptimised); raise the limit only on a thread with a large stack.
    pub max_depth: u32,
    /// Maximum units of work ([`ErrorCode::TooComplex`] beyond).
    pub max_steps: u64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            allow_initial_values: false,
            max_depth: 128,
            max_steps: 100_000,
        }
    }
}

/// A successful evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluation {
    /// The value.
    pub value: Value,
    /// Names of `VAR`/`PERS` data whose initial value went into the result
    /// (only with [`Options::allow_initial_values`]); empty when the value
    /// is truly constant.
    pub initial_values_used: Vec<String>,
}

/// Evaluates `expr` with default [`Options`]; aggregates without context
/// become arrays.
pub fn eval(expr: &Expr, env: &dyn Env) -> Result<Value, EvalError> {
    eval_as(expr, None, env)
}

/// Evaluates `expr` as a value of `expected` type (the declared type of the
/// data it initialises, the parameter type it is passed to): aggregates
/// become records or arrays of that type, num widens to dnum, and other
/// mismatches are [`ErrorCode::TypeMismatch`].
pub fn eval_as(expr: &Expr, expected: Option<&Type>, env: &dyn Env) -> Result<Value, EvalError> {
    eval_with(expr, expected, env, &Options::default()).map(|e| e.value)
}

/// Applies a binary operator to two values, with the typing rules of an
/// expression (an untyped aggregate takes the record type of the other
/// operand; `num` with `dnum` gives `dnum`). For interpreters, which
/// evaluate the operands themselves.
pub fn apply_binary(op: BinOp, a: Value, b: Value, env: &dyn Env) -> Result<Value, EvalError> {
    if matches!(a, Value::Array(_)) != matches!(b, Value::Array(_)) {
        let mut ctx = eval::Ctx::new(&Options::default());
        let (a, b) = ctx.unify(a, b, env)?;
        return operators::binary(op, a, b);
    }
    operators::binary(op, a, b)
}

/// Applies a unary operator to a value.
pub fn apply_unary(op: UnOp, v: Value) -> Result<Value, EvalError> {
    operators::unary(op, v)
}

/// Makes `v` a value of type `ty`, as an assignment or a parameter does:
/// an untyped aggregate becomes the record or array, `num` widens to
/// `dnum` (and a `dnum` in range narrows to `num`); other mismatches are
/// [`ErrorCode::TypeMismatch`]. Types the environment does not know pass
/// unchanged.
pub fn coerce(v: Value, ty: &Type, env: &dyn Env) -> Result<Value, EvalError> {
    eval::Ctx::new(&Options::default()).coerce(v, ty, env)
}

/// The value data of type `ty` starts with when it has no initial value
/// (`VAR num n;`): zero, `FALSE`, an empty string, and records and arrays
/// of those, as the environment's types say; a type the evaluator does not
/// know (a non-value type such as a signal or a clock, kept by an
/// interpreter in its own form) is `opaque`'s value for its name.
/// The components of record type `type_name` (aliases followed), as the
/// evaluator resolves types: the task's own (`env`) before a built-in type
/// of the name. `None` for a type that is not a record, or whose layout
/// no source documents.
pub fn record_components(type_name: &str, env: &dyn Env) -> Option<Vec<(String, Type)>> {
    match eval::resolve_kind(type_name, env) {
        eval::Kind::Record(r) => Some(r.1.clone()),
        _ => None,
    }
}

pub fn zero_value(ty: &Type, env: &dyn Env, opaque: &dyn Fn(&str) -> Value) -> Value {
    eval::Ctx::new(&Options::default()).zero(ty, env, opaque)
}

/// Evaluates with explicit [`Options`].
pub fn eval_with(
    expr: &Expr,
    expected: Option<&Type>,
    env: &dyn Env,
    options: &Options,
) -> Result<Evaluation, EvalError> {
    eval::run(expr, expected, env, options)
}
