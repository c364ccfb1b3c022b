//! The environment through which names are resolved.

use std::borrow::Cow;
use std::collections::HashMap;

use rapid_catalogue::{Catalogue, DatumKind};

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

    /// Does the task declare a type of this name (a `RECORD` or an
    /// `ALIAS`, which wins over a built-in type of the name)? Asked for
    /// every built-in type a value is converted to: an environment that
    /// knows its types once may answer faster.
    fn declares_type(&self, type_name: &str) -> bool {
        self.record_layout(type_name).is_some() || self.alias_of(type_name).is_some()
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

/// Values of the constants the system predefines, from their values in the
/// whole catalogue (`pi`, `EOF_NUM`, the `STR_*` character sets, the `opnum`
/// and `opcalc` constants, `v100`, ...). Case-insensitive. `VAR` and `PERS`
/// data are not constants: `None`.
pub fn predefined(name: &str) -> Option<Value> {
    predefined_in(rapid_catalogue::base(), name)
}

/// The value of the predefined constant `name` in `cat`, evaluated as its
/// type; names in it resolve to the catalogue's other constants.
pub(crate) fn predefined_in(cat: &Catalogue, name: &str) -> Option<Value> {
    let (ty, expr) = constant(cat, name)?;
    let env = CatalogueEnv(cat);
    crate::eval::run(&expr, Some(&ty), &env, &crate::Options::default())
        .ok()
        .map(|e| e.value)
}

fn constant(cat: &Catalogue, name: &str) -> Option<(Type, Expr)> {
    let d = cat.datum(name).filter(|d| d.kind == DatumKind::Const)?;
    let expr = crate::literal_value::parse_data_literal(d.value.as_deref()?)?;
    Some((Type::named(&d.ty), expr))
}

/// The catalogue's constants as an environment, for evaluating the value of
/// one that names others.
struct CatalogueEnv<'c>(&'c Catalogue);

impl Env for CatalogueEnv<'_> {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        match constant(self.0, name) {
            Some((ty, expr)) => Lookup::Constant {
                expr: Cow::Owned(expr),
                ty,
                scope: None,
            },
            None => Lookup::Unknown,
        }
    }
    fn catalogue(&self) -> &Catalogue {
        self.0
    }
}
