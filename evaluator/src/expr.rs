//! The small expression form the evaluator works on.
//!
//! The analyzer lowers syntax nodes to [`Expr`]; the evaluator never sees the
//! syntax tree itself. Literals keep their source text so that decoding
//! (string escapes, `0xFF`, `2E3`) follows RAPID's rules in one place.

use std::fmt;

/// An expression to evaluate.
///
/// Deeply nested trees are evaluated with a depth limit, so evaluation never
/// overflows the stack; building and dropping such a tree is the caller's
/// concern.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// A numeric literal, as written in the source: `3`, `1.`, `.5`, `2E3`,
    /// `0xFF`, `0o17`, `0b101`. Decoded with [`crate::parse_num_literal`].
    Num(String),
    /// A string literal, as written in the source **including** the
    /// surrounding quotes: `"a""b\41"`. Decoded with
    /// [`crate::parse_string_literal`].
    Str(String),
    /// `TRUE` or `FALSE`.
    Bool(bool),
    /// A reference to a data object (`pHome`, `pi`, `reg1`), resolved through
    /// [`crate::Env::lookup`].
    Name(String),
    /// An aggregate `[a, b, c]`. It becomes a record or an array from the
    /// expected type (see [`crate::eval_as`]); without one it is an array.
    Aggregate(Vec<Expr>),
    /// A unary operation.
    Unary(UnOp, Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// A function call `Name(args)`.
    Call {
        /// The function name, any case.
        name: String,
        /// The arguments in source order.
        args: Vec<Arg>,
    },
    /// Component access `expr.name`.
    Component(Box<Expr>, String),
    /// Array indexing `expr{i, j}` (1-based).
    Index(Box<Expr>, Vec<Expr>),
    /// A conditional argument `\Dec?d` of a call: the optional parameter
    /// `d` of the calling routine, passed on only when it is present. Its
    /// presence is known only when a program runs: the evaluator reports it
    /// as [`crate::ErrorCode::Unsupported`]; an interpreter resolves it.
    Conditional(String),
    /// A value computed elsewhere (by an interpreter that evaluates the
    /// arguments of a function itself): evaluates to itself, made a value
    /// of the expected type as any other value is.
    Value(crate::Value),
    /// Something the analyzer could not lower (a syntax error, an unsupported
    /// construct). Evaluates to an [`crate::ErrorCode::Unsupported`] error.
    Unknown,
}

/// One argument of a function call.
///
/// | source          | `name`        | `value`      |
/// |-----------------|---------------|--------------|
/// | `x`             | `None`        | `Some(x)`    |
/// | `Val:=x`        | `Some("Val")` | `Some(x)`    |
/// | `\Dec:=x`       | `Some("Dec")` | `Some(x)`    |
/// | `\Hex` (switch) | `Some("Hex")` | `None`       |
#[derive(Debug, Clone, PartialEq)]
pub struct Arg {
    /// The parameter name for named, optional and switch arguments.
    pub name: Option<String>,
    /// The argument value; `None` for a switch.
    pub value: Option<Expr>,
}

impl Arg {
    /// A positional argument.
    pub fn positional(value: Expr) -> Self {
        Arg {
            name: None,
            value: Some(value),
        }
    }
    /// A named or optional argument (`Name:=value` or `\Name:=value`).
    pub fn named(name: impl Into<String>, value: Expr) -> Self {
        Arg {
            name: Some(name.into()),
            value: Some(value),
        }
    }
    /// A switch argument (`\Name`).
    pub fn switch(name: impl Into<String>) -> Self {
        Arg {
            name: Some(name.into()),
            value: None,
        }
    }
}

/// Unary operators.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnOp {
    /// `-x` for num, dnum and pos.
    Neg,
    /// `+x` for num, dnum and pos.
    Plus,
    /// `NOT b`.
    Not,
}

/// Binary operators: the catalogue's ([`rapid_catalogue::operators::Op`]),
/// whose table says which operand types each takes.
pub use rapid_catalogue::operators::Op as BinOp;

/// A plain description of a RAPID data type: a type name and, for arrays,
/// the size of each dimension (`num{2,3}` is `name: "num", dims: [2, 3]`).
///
/// Type names compare case-insensitively.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Type {
    /// The type name as declared (`num`, `robtarget`, a user record name).
    pub name: String,
    /// Array dimensions, outermost first; empty for a non-array.
    pub dims: Vec<usize>,
}

impl Type {
    /// A non-array type.
    pub fn named(name: impl Into<String>) -> Self {
        Type {
            name: name.into(),
            dims: Vec::new(),
        }
    }
    /// An array type.
    pub fn array(name: impl Into<String>, dims: Vec<usize>) -> Self {
        Type {
            name: name.into(),
            dims,
        }
    }
    /// Whether the type name is `name` (case-insensitive) and not an array.
    pub fn is(&self, name: &str) -> bool {
        self.dims.is_empty() && self.name.eq_ignore_ascii_case(name)
    }
    /// The element type of an array type (one dimension removed).
    pub fn element(&self) -> Type {
        Type {
            name: self.name.clone(),
            dims: self.dims.iter().skip(1).copied().collect(),
        }
    }
}

impl fmt::Display for Type {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)?;
        if !self.dims.is_empty() {
            f.write_str("{")?;
            for (i, d) in self.dims.iter().enumerate() {
                if i > 0 {
                    f.write_str(",")?;
                }
                write!(f, "{d}")?;
            }
            f.write_str("}")?;
        }
        Ok(())
    }
}
