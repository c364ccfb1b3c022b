//! The environment through which names are resolved.

use std::borrow::Cow;
use std::collections::HashMap;

use crate::expr::{Expr, Type};
use crate::value::Value;

/// Whether a non-constant data object is a `VAR` or a `PERS`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VarKind {
    /// `VAR` data (or a routine parameter, a loop variable).
    Var,
    /// `PERS` data.
    Pers,
}

/// What a name refers to. Supplied by [`Env::lookup`].
#[derive(Clone)]
pub enum Lookup<'a> {
    /// A `CONST` data object with its initialiser and declared type.
    Constant {
        /// The initialiser expression.
        expr: Cow<'a, Expr>,
        /// The declared type (aggregates in `expr` are typed by it).
        ty: Type,
        /// The environment in which names inside `expr` resolve (the
        /// declaring module), if different from the one being asked.
        scope: Option<&'a dyn Env>,
    },
    /// A data object whose value is already known (predefined data from a
    /// catalogue, such as `v100` or `tool0`).
    Known {
        /// The value.
        value: Value,
    },
    /// A `VAR` or `PERS` data object: not constant. Its initial value is used
    /// only if [`crate::Options::allow_initial_values`] is set, and the
    /// result is then labelled (see [`crate::Evaluation::initial_values_used`]).
    Variable {
        /// `VAR` or `PERS`.
        kind: VarKind,
        /// The declared type.
        ty: Type,
        /// The initialiser, if the declaration has one.
        initial: Option<Cow<'a, Expr>>,
        /// Where names inside `initial` resolve, if not the asking env.
        scope: Option<&'a dyn Env>,
    },
    /// The name is not known.
    Unknown,
}

/// Resolves names and user-defined types for the evaluator.
///
/// Name comparison is case-insensitive in RAPID; implementations should fold
/// case. When a name is [`Lookup::Unknown`], the evaluator falls back to
/// [`predefined`] (pi, the `STR_*` character sets, the `opnum` constants).
pub trait Env {
    /// What `name` refers to.
    fn lookup(&self, name: &str) -> Lookup<'_>;

    /// The components of a user `RECORD` type, in declaration order.
    /// Built-in records (pos, robtarget, ...) are known to the evaluator.
    fn record_layout(&self, _type_name: &str) -> Option<Vec<(String, Type)>> {
        None
    }

    /// The type a user `ALIAS` type stands for.
    fn alias_of(&self, _type_name: &str) -> Option<Type> {
        None
    }

    /// The catalogue of built-ins the names resolve against: the signatures
    /// of the pure functions come from it. The whole catalogue
    /// ([`rapid_catalogue::base`]) unless the environment has a task's
    /// versioned view.
    fn catalogue(&self) -> &rapid_catalogue::Catalogue {
        rapid_catalogue::base()
    }
}

impl std::fmt::Debug for Lookup<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Lookup::Constant { expr, ty, scope } => f
                .debug_struct("Constant")
                .field("expr", expr)
                .field("ty", ty)
                .field("scoped", &scope.is_some())
                .finish(),
            Lookup::Known { value } => f.debug_struct("Known").field("value", value).finish(),
            Lookup::Variable {
                kind,
                ty,
                initial,
                scope,
            } => f
                .debug_struct("Variable")
                .field("kind", kind)
                .field("ty", ty)
                .field("initial", initial)
                .field("scoped", &scope.is_some())
                .finish(),
            Lookup::Unknown => f.write_str("Unknown"),
        }
    }
}

/// An environment that knows no names.
#[derive(Debug, Clone, Copy, Default)]
pub struct EmptyEnv;

impl Env for EmptyEnv {
    fn lookup(&self, _name: &str) -> Lookup<'_> {
        Lookup::Unknown
    }
}

/// A simple in-memory environment, handy for tests, tools and the `eval`
/// command: constants, variables and records by (case-folded) name.
#[derive(Debug, Clone, Default)]
pub struct MapEnv {
    entries: HashMap<String, Entry>,
    records: HashMap<String, Vec<(String, Type)>>,
    aliases: HashMap<String, Type>,
}

#[derive(Debug, Clone)]
enum Entry {
    Constant(Expr, Type),
    Known(Value),
    Variable(VarKind, Type, Option<Expr>),
}

impl MapEnv {
    /// An empty environment.
    pub fn new() -> Self {
        Self::default()
    }
    /// Declares `CONST ty name := expr`.
    pub fn constant(&mut self, name: &str, ty: Type, expr: Expr) -> &mut Self {
        self.entries
            .insert(name.to_lowercase(), Entry::Constant(expr, ty));
        self
    }
    /// Declares a name with a known value.
    pub fn known(&mut self, name: &str, value: Value) -> &mut Self {
        self.entries
            .insert(name.to_lowercase(), Entry::Known(value));
        self
    }
    /// Declares `VAR`/`PERS ty name [:= initial]`.
    pub fn variable(
        &mut self,
        name: &str,
        kind: VarKind,
        ty: Type,
        initial: Option<Expr>,
    ) -> &mut Self {
        self.entries
            .insert(name.to_lowercase(), Entry::Variable(kind, ty, initial));
        self
    }
    /// Declares `RECORD name ... ENDRECORD`.
    pub fn record(&mut self, name: &str, fields: Vec<(String, Type)>) -> &mut Self {
        self.records.insert(name.to_lowercase(), fields);
        self
    }
    /// Declares `ALIAS target name`.
    pub fn alias(&mut self, name: &str, target: Type) -> &mut Self {
        self.aliases.insert(name.to_lowercase(), target);
        self
    }
}

impl Env for MapEnv {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        match self.entries.get(&name.to_lowercase()) {
            Some(Entry::Constant(e, t)) => Lookup::Constant {
                expr: Cow::Borrowed(e),
                ty: t.clone(),
                scope: None,
            },
            Some(Entry::Known(v)) => Lookup::Known { value: v.clone() },
            Some(Entry::Variable(k, t, i)) => Lookup::Variable {
                kind: *k,
                ty: t.clone(),
                initial: i.as_ref().map(Cow::Borrowed),
                scope: None,
            },
            None => Lookup::Unknown,
        }
    }
    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        self.records.get(&type_name.to_lowercase()).cloned()
    }
    fn alias_of(&self, type_name: &str) -> Option<Type> {
        self.aliases.get(&type_name.to_lowercase()).cloned()
    }
}

/// `STR_DIGIT`: the decimal digits.
pub const STR_DIGIT: &str = "0123456789";
/// `STR_UPPER`: upper-case letters of ISO 8859-1.
pub const STR_UPPER: &str = "ABCDEFGHIJKLMNOPQRSTUVWXYZ\u{c0}\u{c1}\u{c2}\u{c3}\u{c4}\u{c5}\u{c6}\u{c7}\u{c8}\u{c9}\u{ca}\u{cb}\u{cc}\u{cd}\u{ce}\u{cf}\u{d0}\u{d1}\u{d2}\u{d3}\u{d4}\u{d5}\u{d6}\u{d8}\u{d9}\u{da}\u{db}\u{dc}\u{dd}\u{de}";
/// `STR_LOWER`: lower-case letters of ISO 8859-1, in the same order as
/// [`STR_UPPER`], followed by `ß` and `ÿ`, which have no upper-case form.
pub const STR_LOWER: &str = "abcdefghijklmnopqrstuvwxyz\u{e0}\u{e1}\u{e2}\u{e3}\u{e4}\u{e5}\u{e6}\u{e7}\u{e8}\u{e9}\u{ea}\u{eb}\u{ec}\u{ed}\u{ee}\u{ef}\u{f0}\u{f1}\u{f2}\u{f3}\u{f4}\u{f5}\u{f6}\u{f8}\u{f9}\u{fa}\u{fb}\u{fc}\u{fd}\u{fe}\u{df}\u{ff}";
/// `STR_WHITE`: the blank characters: space, tab, line feed, vertical tab,
/// form feed and carriage return.
pub const STR_WHITE: &str = " \t\n\u{b}\u{c}\r";

/// Values of data predefined by the system that the evaluator knows itself:
/// `pi`, `EOF_BIN`, `EOF_NUM`, the `STR_*` character sets, the `opnum`
/// constants (`LT` .. `GT`), the `opcalc` constants (`OpAdd` .. `OpMod`,
/// numbered 1 to 5 here) and the disk names. Case-insensitive.
pub fn predefined(name: &str) -> Option<Value> {
    let lower = name.to_ascii_lowercase();
    Some(match lower.as_str() {
        // BASE declares pi with 8 digits, which is not f32::consts::PI.
        #[allow(clippy::approx_constant)]
        "pi" => Value::Num(3.141_592_6),
        "eof_bin" => Value::Num(-1.0),
        "eof_num" => Value::Num(9.998e36),
        "str_digit" => Value::Str(STR_DIGIT.into()),
        "str_upper" => Value::Str(STR_UPPER.into()),
        "str_lower" => Value::Str(STR_LOWER.into()),
        "str_white" => Value::Str(STR_WHITE.into()),
        "lt" => Value::Num(1.0),
        "lteq" => Value::Num(2.0),
        "eq" => Value::Num(3.0),
        "noteq" => Value::Num(4.0),
        "gteq" => Value::Num(5.0),
        "gt" => Value::Num(6.0),
        "opadd" => Value::Num(1.0),
        "opsub" => Value::Num(2.0),
        "opmult" => Value::Num(3.0),
        "opdiv" => Value::Num(4.0),
        "opmod" => Value::Num(5.0),
        "diskhome" | "ram1disk" => Value::Str("HOME:".into()),
        "disktemp" => Value::Str("TEMP:".into()),
        "flp1" => Value::Str("flp1:".into()),
        "stempty" => Value::Str(String::new()),
        _ => return None,
    })
}
