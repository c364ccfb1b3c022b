//! Constant values of a task: the evaluator ([`rapid_evaluator`]) connected
//! to RAPID programs.
//!
//! - [`with_env`] gives an [`Env`] positioned at an offset of a unit: names
//!   resolve as the checker resolves them there (routine data, parameters
//!   and `FOR` variables, then the module, the task's globals, the
//!   catalogue's predefined data and configured signals). A `CONST` found in
//!   another module is evaluated in the scope of the module that declares
//!   it; `VAR` and `PERS` data are [`Lookup::Variable`]s with their initial
//!   value (used only when [`EnvOptions`] allows it).
//! - [`value_at`] and [`value_of_range`] give the value of the constant
//!   expression around an offset or at a range, for hovers.
//! - [`check_constant_errors`] reports rule E413 (constant-error) from the
//!   checker.
//!
//! Nothing here panics; evaluation is bounded by the evaluator's limits.

use std::borrow::Cow;
use std::cell::{Cell, OnceCell};
use std::ops::Range;

use rapid_evaluator::{
    Env, ErrorCode, EvalError, Evaluation, Expr, Lookup, Options, Type, Value, VarKind,
};
use tree_sitter::{Node, TreeCursor};

use crate::catalogue::{Catalogue, Datum, DatumKind, Mode, TypeKind};
use crate::check::{Cx, DataSym, RoutineSym};
use crate::items::{DataDecl, ParamDecl, Storage};
use crate::lower::{is_expression, lower_with};
use crate::names::{NameMap, fold};
use crate::syntax_util::{field, fields, text_of};
use crate::task::{Item, ItemRef, Task, Unit};
use crate::ty::{Ty, UserType};

/// The value of a constant expression, for a hover.
#[derive(Clone, Debug, PartialEq)]
pub struct ConstValue {
    /// The expression's byte range.
    pub range: Range<usize>,
    /// Its RAPID type (`num`, `robtarget`, `num{3}`, a user record name).
    pub ty: String,
    /// The value as RAPID writes it (`ValToStr`); empty when `error` is set.
    pub value: String,
    /// Euler angles `[z, y, x]` in degrees of an orientation: for an
    /// `orient`, and for records with a `rot` component (`pose`,
    /// `robtarget`).
    pub euler_zyx: Option<[f64; 3]>,
    /// The value comes from the initial value of `PERS` (or, on request,
    /// `VAR`) data: it is what the declaration says, not a constant.
    pub initial_value_only: bool,
    /// The run-time error the expression always raises: (`ERR_...` code,
    /// message).
    pub error: Option<(String, String)>,
}

/// Which initial values of non-constant data an evaluation may use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EnvOptions {
    /// Use the initial values of `PERS` data.
    pub pers_initial: bool,
    /// Use the initial values of `VAR` data.
    pub var_initial: bool,
}

impl EnvOptions {
    /// Both `VAR` and `PERS` initial values.
    pub fn initial_values() -> EnvOptions {
        EnvOptions {
            pers_initial: true,
            var_initial: true,
        }
    }

    fn evaluator_options(self) -> Options {
        Options {
            allow_initial_values: self.pers_initial || self.var_initial,
            ..Options::default()
        }
    }
}

/// Calls `f` with an [`Env`] whose names resolve as at `offset` in unit
/// `unit`: inside a routine, its data, parameters and the `FOR` variables
/// around the offset come first. With `at` `None` (or a unit index out of
/// range), only the task's global names are visible.
pub fn with_env<R>(
    task: &Task,
    at: Option<(usize, usize)>,
    options: EnvOptions,
    f: impl FnOnce(&dyn Env) -> R,
) -> R {
    let routine = at
        .filter(|&(unit, offset)| in_routine(task, unit, offset))
        .and_then(|(unit, offset)| Cx::at(task, unit, offset))
        .and_then(|cx| RoutineNames::of(&cx));
    with_routine(task, at, options, routine, None, f)
}

/// The lowered initial values of a task's module data, kept by a checker
/// context for its whole check so that each is lowered from the syntax tree
/// once, not at every use (lowering depends only on the declaration and its
/// module).
pub(crate) struct InitCache {
    /// The first slot and the number of data of each unit's modules.
    modules: Vec<Vec<(usize, usize)>>,
    slots: Vec<OnceCell<Option<Expr>>>,
}

impl InitCache {
    pub(crate) fn new(task: &Task) -> InitCache {
        let mut n = 0;
        let modules = task
            .units
            .iter()
            .map(|u| {
                u.items
                    .modules
                    .iter()
                    .map(|m| {
                        let first = n;
                        n += m.data.len();
                        (first, m.data.len())
                    })
                    .collect()
            })
            .collect();
        InitCache {
            modules,
            slots: std::iter::repeat_with(OnceCell::new).take(n).collect(),
        }
    }

    /// The slot of module data `r`.
    fn slot(&self, r: ItemRef) -> Option<&OnceCell<Option<Expr>>> {
        let Item::Data(i) = r.item else {
            return None;
        };
        let &(first, len) = self.modules.get(r.unit)?.get(r.module)?;
        (i < len).then(|| self.slots.get(first + i))?
    }
}

/// Is `offset` of unit `unit` inside a routine?
fn in_routine(task: &Task, unit: usize, offset: usize) -> bool {
    task.units.get(unit).is_some_and(|u| {
        u.items.modules.iter().any(|m| {
            m.routines
                .iter()
                .any(|r| r.range.start <= offset && offset <= r.range.end)
        })
    })
}

/// [`with_env`] with the names of the routine around `at` given.
fn with_routine<'t, R>(
    task: &'t Task,
    at: Option<(usize, usize)>,
    options: EnvOptions,
    routine: Option<RoutineNames<'t>>,
    inits: Option<&'t InitCache>,
    f: impl FnOnce(&dyn Env) -> R,
) -> R {
    let shared = Shared::new(task, options, inits);
    let mut scopes = Vec::new();
    for (u, unit) in task.units.iter().enumerate() {
        for (m, _) in unit.items.modules.iter().enumerate() {
            scopes.push(ModuleScope::new(&shared, u, Some(m)));
        }
    }
    for s in &scopes {
        let _ = s.all.set(&scopes);
    }
    let global = ModuleScope::new(&shared, usize::MAX, None);
    let _ = global.all.set(&scopes);
    let Some((unit, offset)) = at else {
        return f(&global);
    };
    let Some(u) = task.units.get(unit) else {
        return f(&global);
    };
    let Some(m) = u.items.module_at(offset) else {
        return f(&global);
    };
    let Some(scope) = shared.index(unit, m).and_then(|i| scopes.get(i)) else {
        return f(&global);
    };
    match routine {
        Some(names) => f(&RoutineScope {
            module: scope,
            unit: u,
            names,
            dims_depth: Cell::new(0),
        }),
        None => f(scope),
    }
}

/// The names a routine puts in front of its module's: its data, its
/// parameters and the `FOR` variables around a position.
struct RoutineNames<'t> {
    locals: NameMap<DataDecl>,
    params: NameMap<&'t ParamDecl>,
    for_vars: Vec<String>,
}

impl<'t> RoutineNames<'t> {
    /// The routine scope of a checker context, if it is in a routine.
    fn of(cx: &Cx<'t>) -> Option<RoutineNames<'t>> {
        let r = cx.routine.as_ref()?;
        Some(RoutineNames {
            locals: r.locals.clone(),
            params: r.params.clone(),
            for_vars: r.for_vars.clone(),
        })
    }
}

/// Evaluates `expr` with names resolved as at `at` (see [`with_env`]).
pub fn eval_in(
    task: &Task,
    at: Option<(usize, usize)>,
    expr: &Expr,
    expected: Option<&Type>,
    options: EnvOptions,
) -> Result<Evaluation, EvalError> {
    with_env(task, at, options, |env| {
        rapid_evaluator::eval_with(expr, expected, env, &options.evaluator_options())
    })
}

/// Is a call of `name` a call of the built-in function, as seen from
/// module `module` of unit `unit` (no user routine of that name hides it)?
/// With `at` `None`, only global routines hide built-ins.
pub fn is_builtin_call(task: &Task, at: Option<(usize, usize)>, name: &str) -> bool {
    let key = fold(name);
    let is_routine = |r: &crate::task::ItemRef| matches!(r.item, Item::Routine(_));
    if task
        .globals
        .get(&key)
        .is_some_and(|refs| refs.iter().any(is_routine))
    {
        return false;
    }
    match at {
        Some((unit, module)) => !task.locals.get(&key).is_some_and(|refs| {
            refs.iter()
                .any(|r| is_routine(r) && r.unit == unit && r.module == module)
        }),
        None => true,
    }
}

/// State shared by every scope of one [`with_env`] call.
struct Shared<'t> {
    task: &'t Task,
    options: EnvOptions,
    /// Index of each unit's first module in the scope list.
    offsets: Vec<usize>,
    types: OnceCell<crate::ty::Types<'t>>,
    /// Lowered initial values of module data, kept across calls.
    inits: Option<&'t InitCache>,
}

impl<'t> Shared<'t> {
    fn new(task: &'t Task, options: EnvOptions, inits: Option<&'t InitCache>) -> Shared<'t> {
        let mut offsets = Vec::with_capacity(task.units.len());
        let mut n = 0;
        for u in &task.units {
            offsets.push(n);
            n += u.items.modules.len();
        }
        Shared {
            task,
            options,
            offsets,
            types: OnceCell::new(),
            inits,
        }
    }

    fn index(&self, unit: usize, module: usize) -> Option<usize> {
        let count = self.task.units.get(unit)?.items.modules.len();
        (module < count).then(|| self.offsets.get(unit).map(|o| o + module))?
    }

    fn types(&self) -> &crate::ty::Types<'t> {
        self.types.get_or_init(|| self.task.types())
    }

    fn record_layout(&self, name: &str) -> Option<Vec<(String, Type)>> {
        match self.types().user(name) {
            Some(UserType::Record(r)) => Some(
                r.components
                    .iter()
                    .map(|(n, t, _)| {
                        let ty = t.as_ref().map_or("?", |t| t.name.as_str());
                        (n.clone(), Type::named(ty))
                    })
                    .collect(),
            ),
            Some(UserType::Alias(_)) => None,
            None => catalogue_layout(self.task.catalogue, name),
        }
    }

    fn alias_of(&self, name: &str) -> Option<Type> {
        match self.types().user(name) {
            Some(UserType::Alias(a)) => a.of.as_ref().map(|t| Type::named(&t.name)),
            Some(UserType::Record(_)) => None,
            None => catalogue_alias(self.task.catalogue, name),
        }
    }

    /// The initial value to offer for data of this storage.
    fn offers_initial(&self, storage: Storage) -> bool {
        match storage {
            Storage::Const => true,
            Storage::Pers => self.options.pers_initial,
            Storage::Var => self.options.var_initial,
        }
    }
}

fn catalogue_layout(cat: &Catalogue, name: &str) -> Option<Vec<(String, Type)>> {
    let t = cat.datatype(name)?;
    (t.kind == TypeKind::Record).then(|| {
        t.components
            .iter()
            .map(|c| (c.name.clone(), Type::named(&c.ty)))
            .collect()
    })
}

fn catalogue_alias(cat: &Catalogue, name: &str) -> Option<Type> {
    cat.datatype(name)
        .and_then(|t| t.alias_of.as_deref())
        .map(Type::named)
}

/// The names of one module (or, with `module` `None`, of the task's
/// globals only).
struct ModuleScope<'s, 't> {
    shared: &'s Shared<'t>,
    unit: usize,
    module: Option<usize>,
    /// Every module scope of the task, to evaluate a constant where it is
    /// declared.
    all: OnceCell<&'s [ModuleScope<'s, 't>]>,
    /// Guards the evaluation of array sizes against cycles.
    dims_depth: Cell<u32>,
}

impl<'s, 't> ModuleScope<'s, 't> {
    fn new(shared: &'s Shared<'t>, unit: usize, module: Option<usize>) -> Self {
        ModuleScope {
            shared,
            unit,
            module,
            all: OnceCell::new(),
            dims_depth: Cell::new(0),
        }
    }

    /// Items visible from this module under `name`
    /// ([`crate::sema::scope::visible`], the checker's lookup too).
    fn visible(&self, name: &str) -> Vec<ItemRef> {
        crate::names::with_folded(name, |key| self.visible_folded(key))
    }

    fn visible_folded(&self, key: &str) -> Vec<ItemRef> {
        crate::sema::scope::visible(self.shared.task, self.unit, self.module, key)
    }

    fn scope_of(&self, unit: usize, module: usize) -> Option<&'s ModuleScope<'s, 't>> {
        let i = self.shared.index(unit, module)?;
        self.all.get()?.get(i)
    }

    fn is_builtin(&self, name: &str) -> bool {
        is_builtin_call(self.shared.task, self.module.map(|m| (self.unit, m)), name)
    }
}

impl Env for ModuleScope<'_, '_> {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        let task = self.shared.task;
        for r in self.visible(name) {
            let Some(d) = task.data(r) else {
                continue;
            };
            let Some(unit) = task.units.get(r.unit) else {
                return Lookup::Unknown;
            };
            let Some(scope) = self.scope_of(r.unit, r.module) else {
                return Lookup::Unknown;
            };
            return data_lookup(
                self.shared,
                d,
                self.shared.inits.and_then(|c| c.slot(r)),
                unit,
                Some(scope),
                scope,
                &|n| scope.is_builtin(n),
                &scope.dims_depth,
            );
        }
        outside_the_task(task, name, self.shared.options)
    }

    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        self.shared.record_layout(type_name)
    }

    fn alias_of(&self, type_name: &str) -> Option<Type> {
        self.shared.alias_of(type_name)
    }

    /// The task's view: calls are bound with its RobotWare's signatures.
    fn catalogue(&self) -> &crate::catalogue::Catalogue {
        self.shared.task.catalogue
    }
}

/// Names the task does not declare: the catalogue's predefined data and
/// configured signals.
fn outside_the_task<'a>(task: &Task, name: &str, options: EnvOptions) -> Lookup<'a> {
    if let Some(d) = task.catalogue.datum(name) {
        return catalogue_lookup(d, options);
    }
    let key = fold(name);
    if let Some(ty) = task.signals.as_ref().and_then(|s| s.get(&key)) {
        return Lookup::Variable {
            kind: VarKind::Var,
            ty: Type::named(*ty),
            initial: None,
            scope: None,
        };
    }
    Lookup::Unknown
}

/// The predefined data of the catalogue, whose values are RAPID literals
/// (the same in every view: it reads the whole catalogue).
struct CatalogueEnv {
    options: EnvOptions,
}

static CATALOGUE_ENV: CatalogueEnv = CatalogueEnv {
    options: EnvOptions {
        pers_initial: false,
        var_initial: false,
    },
};
static CATALOGUE_ENV_INITIAL: CatalogueEnv = CatalogueEnv {
    options: EnvOptions {
        pers_initial: true,
        var_initial: true,
    },
};

impl Env for CatalogueEnv {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        match crate::catalogue::base().datum(name) {
            Some(d) => catalogue_lookup(d, self.options),
            None => Lookup::Unknown,
        }
    }
    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        catalogue_layout(crate::catalogue::base(), type_name)
    }
    fn alias_of(&self, type_name: &str) -> Option<Type> {
        catalogue_alias(crate::catalogue::base(), type_name)
    }
}

fn catalogue_lookup<'a>(d: &'static Datum, options: EnvOptions) -> Lookup<'a> {
    let value = d
        .value
        .as_deref()
        .and_then(rapid_evaluator::parse_data_literal);
    let ty = Type::named(&d.ty);
    let scope: &'static dyn Env = if options.pers_initial || options.var_initial {
        &CATALOGUE_ENV_INITIAL
    } else {
        &CATALOGUE_ENV
    };
    let kind = match d.kind {
        DatumKind::Const => {
            return match value {
                Some(e) => Lookup::Constant {
                    expr: Cow::Owned(e),
                    ty,
                    scope: Some(scope),
                },
                // Let the evaluator's own table answer (pi, STR_*, ...).
                None => Lookup::Unknown,
            };
        }
        DatumKind::Pers => VarKind::Pers,
        DatumKind::Var => VarKind::Var,
    };
    let offered = match kind {
        VarKind::Pers => options.pers_initial,
        VarKind::Var => options.var_initial,
    };
    Lookup::Variable {
        kind,
        ty,
        initial: value.filter(|_| offered).map(Cow::Owned),
        scope: Some(scope),
    }
}

/// What a data declaration gives the evaluator. `scope` is where names in
/// its initial value resolve (`None`: the asking environment); `dims_env`
/// evaluates its array sizes. `slot` keeps its lowered initial value.
#[allow(clippy::too_many_arguments)]
fn data_lookup<'a>(
    shared: &Shared<'_>,
    d: &DataDecl,
    slot: Option<&'a OnceCell<Option<Expr>>>,
    unit: &Unit,
    scope: Option<&'a dyn Env>,
    dims_env: &dyn Env,
    is_builtin: &dyn Fn(&str) -> bool,
    dims_depth: &Cell<u32>,
) -> Lookup<'a> {
    let ty = decl_type(d, unit, dims_env, dims_depth);
    let lower = || {
        d.init
            .as_ref()
            .and_then(|r| expression_at(unit, r.clone()))
            .map(|n| lower_with(n, &unit.text, is_builtin))
    };
    let init = || -> Option<Cow<'a, Expr>> {
        match slot {
            Some(slot) => slot.get_or_init(lower).as_ref().map(Cow::Borrowed),
            None => lower().map(Cow::Owned),
        }
    };
    let kind = match d.storage {
        Storage::Const => {
            return Lookup::Constant {
                expr: init().unwrap_or(Cow::Owned(Expr::Unknown)),
                ty,
                scope,
            };
        }
        Storage::Pers => VarKind::Pers,
        Storage::Var => VarKind::Var,
    };
    Lookup::Variable {
        kind,
        ty,
        initial: if shared.offers_initial(d.storage) {
            init()
        } else {
            None
        },
        scope,
    }
}

/// The declared type of data, with the array sizes that are known (a size
/// that is not a constant is 0: not checked).
fn decl_type(d: &DataDecl, unit: &Unit, env: &dyn Env, depth: &Cell<u32>) -> Type {
    let name = d.ty.as_ref().map_or("?", |t| t.name.as_str());
    let dims = d
        .dims
        .iter()
        .map(|r| array_size(unit, r.clone(), env, depth))
        .collect();
    Type::array(name, dims)
}

fn array_size(unit: &Unit, range: Range<usize>, env: &dyn Env, depth: &Cell<u32>) -> usize {
    let text = unit.text.get(range.clone()).unwrap_or_default().trim();
    if let Ok(n) = text.parse::<usize>() {
        return n;
    }
    // A size given by a constant: evaluate it, but never through a chain of
    // sizes (a constant whose size refers to itself).
    if depth.get() >= 2 {
        return 0;
    }
    let Some(node) = expression_at(unit, range) else {
        return 0;
    };
    depth.set(depth.get() + 1);
    let expr = crate::lower::lower(node, &unit.text);
    let v = rapid_evaluator::eval_as(&expr, Some(&Type::named("num")), env);
    depth.set(depth.get() - 1);
    match v.ok().and_then(|v| v.as_f64()) {
        Some(x) if x >= 1.0 && x.fract() == 0.0 && x <= 1e6 => x as usize,
        _ => 0,
    }
}

/// The outermost expression node spanning exactly `range`.
fn expression_at(unit: &Unit, range: Range<usize>) -> Option<Node<'_>> {
    path_to(unit.tree().root_node(), range.clone())
        .into_iter()
        .map(|(n, _)| n)
        .find(|n| n.byte_range() == range && is_expression(crate::syntax_util::kind(*n)))
}

/// A node with the field of its parent that holds it.
type Step<'t> = (Node<'t>, Option<&'t str>);

/// The nodes from `root` down to the smallest one that contains `range`,
/// each with its field name. (Walking down with a cursor is cheap;
/// `Node::parent` searches from the root each time.)
fn path_to(root: Node<'_>, range: Range<usize>) -> Vec<Step<'_>> {
    let mut path = vec![(root, None)];
    let mut cursor = root.walk();
    'down: while cursor.goto_first_child_for_byte(range.start).is_some() {
        loop {
            let n = cursor.node();
            if n.start_byte() > range.start {
                break 'down;
            }
            let touches_only = n.end_byte() == range.start && range.end > range.start;
            if n.end_byte() >= range.end && !touches_only {
                path.push((n, cursor.field_name()));
                continue 'down;
            }
            if !cursor.goto_next_sibling() {
                break 'down;
            }
        }
    }
    path
}

/// The names of a routine (data, parameters, `FOR` variables around the
/// offset), in front of its module's.
struct RoutineScope<'s, 't> {
    module: &'s ModuleScope<'s, 't>,
    unit: &'t Unit,
    names: RoutineNames<'t>,
    dims_depth: Cell<u32>,
}

impl Env for RoutineScope<'_, '_> {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        let key = fold(name);
        let r = &self.names;
        {
            if r.for_vars.contains(&key) {
                return Lookup::Variable {
                    kind: VarKind::Var,
                    ty: Type::named("num"),
                    initial: None,
                    scope: None,
                };
            }
            if let Some(d) = r.locals.get(&key) {
                return data_lookup(
                    self.module.shared,
                    d,
                    None,
                    self.unit,
                    None,
                    self,
                    &|n| self.module.is_builtin(n),
                    &self.dims_depth,
                );
            }
            if let Some(p) = r.params.get(&key) {
                let ty = p.ty.as_ref().map_or("?", |t| t.name.as_str());
                return Lookup::Variable {
                    kind: if p.mode == Mode::Pers {
                        VarKind::Pers
                    } else {
                        VarKind::Var
                    },
                    ty: Type::array(ty, vec![0; usize::from(p.dims)]),
                    initial: None,
                    scope: None,
                };
            }
        }
        self.module.lookup(name)
    }

    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        self.module.record_layout(type_name)
    }

    fn alias_of(&self, type_name: &str) -> Option<Type> {
        self.module.alias_of(type_name)
    }

    fn catalogue(&self) -> &crate::catalogue::Catalogue {
        self.module.catalogue()
    }
}

// ---------------------------------------------------------------------------
// Values for hovers.

/// How many enclosing expressions [`value_at`] tries, and how deep the
/// context of an aggregate is followed.
const MAX_CONTEXT_DEPTH: u32 = 64;

/// Field names whose node is a name, not a value.
const NOT_VALUES: &[&str] = &[
    "name",
    "component",
    "conditional",
    "variable",
    "trap",
    "label",
    "type",
];

/// The value of the smallest constant expression around `offset` of unit
/// `unit`: a named constant, an operation, a call of a pure function, an
/// aggregate typed by its context, a component or an element. A literal
/// whose value reads as its own text is skipped. An expression that always
/// fails with a run-time error gives that error. `PERS` data give their
/// initial value, labelled; `VAR` data are not constant.
pub fn value_at(task: &Task, unit: usize, offset: usize) -> Option<ConstValue> {
    let u = task.units.get(unit)?;
    let root = u.tree().root_node();
    let mut start = root.named_descendant_for_byte_range(offset, offset)?;
    // A cursor just after a name or a closing bracket means that expression
    // (as editors place it after the last character typed).
    let on_token = matches!(
        crate::syntax_util::kind(start),
        "identifier" | "number" | "string" | "boolean"
    ) && start.start_byte() <= offset
        && offset < start.end_byte();
    if !on_token
        && offset > 0
        && let Some(left) = root.named_descendant_for_byte_range(offset - 1, offset - 1)
        && left.end_byte() == offset
        && is_expression(crate::syntax_util::kind(left))
    {
        start = left;
    }
    let options = EnvOptions {
        pers_initial: true,
        var_initial: false,
    };
    let mut path = path_to(root, start.byte_range());
    let at = path.iter().position(|(n, _)| n.id() == start.id())?;
    path.truncate(at + 1);
    with_env(task, Some((unit, offset)), options, |env| {
        let mut typing = Cx::at(task, unit, offset);
        let mut tried = 0;
        while let Some((n, field)) = path.last().copied() {
            if is_expression(crate::syntax_util::kind(n)) {
                // Each try evaluates the whole expression: stop climbing
                // through absurdly deep nesting.
                tried += 1;
                if tried > MAX_CONTEXT_DEPTH {
                    return None;
                }
                if !field.is_some_and(|f| NOT_VALUES.contains(&f))
                    && let Some(v) = value_of_node(task, unit, &path, env, typing.as_mut(), options)
                {
                    return Some(v);
                }
            } else if !matches!(crate::syntax_util::kind(n), "argument" | "argument_list") {
                return None;
            }
            path.pop();
        }
        None
    })
}

/// The value of the expression that spans `range` of unit `unit` exactly
/// (white space around it ignored), as [`value_at`] gives it but without
/// skipping literals.
pub fn value_of_range(task: &Task, unit: usize, range: Range<usize>) -> Option<ConstValue> {
    let u = task.units.get(unit)?;
    let text = u.text.get(range.clone())?;
    let start = range.start + (text.len() - text.trim_start().len());
    let end = range.end - (text.len() - text.trim_end().len());
    let mut path = path_to(u.tree().root_node(), start..end);
    let at = path.iter().position(|(n, _)| {
        n.byte_range() == (start..end) && is_expression(crate::syntax_util::kind(*n))
    })?;
    path.truncate(at + 1);
    let (node, field) = *path.last()?;
    if field.is_some_and(|f| NOT_VALUES.contains(&f)) {
        return None;
    }
    let options = EnvOptions {
        pers_initial: true,
        var_initial: false,
    };
    with_env(task, Some((unit, start)), options, |env| {
        let mut typing = Cx::at(task, unit, start);
        let mut v = evaluate_node(task, unit, &path, env, typing.as_mut(), options)?;
        v.range = node.byte_range();
        Some(v)
    })
}

fn value_of_node<'t>(
    task: &'t Task,
    unit: usize,
    path: &[Step<'t>],
    env: &dyn Env,
    typing: Option<&mut Cx<'t>>,
    options: EnvOptions,
) -> Option<ConstValue> {
    let (node, _) = *path.last()?;
    let v = evaluate_node(task, unit, path, env, typing, options)?;
    let text = task.units.get(unit).map_or("", |u| text_of(node, &u.text));
    if matches!(
        crate::syntax_util::kind(node),
        "number" | "string" | "boolean"
    ) && v.error.is_none()
        && v.value.eq_ignore_ascii_case(text)
    {
        return None;
    }
    Some(v)
}

/// Evaluates an expression node: `Some` when it has a value or always fails
/// at run time.
fn evaluate_node<'t>(
    task: &'t Task,
    unit: usize,
    path: &[Step<'t>],
    env: &dyn Env,
    typing: Option<&mut Cx<'t>>,
    options: EnvOptions,
) -> Option<ConstValue> {
    let u = task.units.get(unit)?;
    let (node, _) = *path.last()?;
    let expected = typing.and_then(|cx| expected_type(cx, path, env));
    let at = module_at(task, unit, node.start_byte());
    let expr = lower_with(node, &u.text, &|n| is_builtin_call(task, at, n));
    let r = rapid_evaluator::eval_with(&expr, expected.as_ref(), env, &options.evaluator_options());
    to_const_value(node.byte_range(), &expr, expected.as_ref(), r, env)
}

/// Where an expression of `unit` is, for [`is_builtin_call`]: the unit and
/// the module around `offset`.
fn module_at(task: &Task, unit: usize, offset: usize) -> Option<(usize, usize)> {
    let m = task.units.get(unit)?.items.module_at(offset)?;
    Some((unit, m))
}

fn to_const_value(
    range: Range<usize>,
    expr: &Expr,
    expected: Option<&Type>,
    r: Result<Evaluation, EvalError>,
    env: &dyn Env,
) -> Option<ConstValue> {
    match r {
        Ok(e) => {
            let ty = match (&e.value, expected) {
                (Value::Array(_), _) | (_, None) => type_of_value(&e.value, expr, env),
                (_, Some(t)) => type_text(t),
            };
            Some(ConstValue {
                range,
                ty,
                // -0.0 reads badly in a hover.
                euler_zyx: e.value.euler_zyx().map(|a| a.map(|x| x + 0.0)),
                value: e.value.to_string(),
                initial_value_only: !e.initial_values_used.is_empty(),
                error: None,
            })
        }
        Err(err) if err.code.is_runtime() => Some(ConstValue {
            range,
            ty: expected.map(type_text).unwrap_or_default(),
            value: String::new(),
            euler_zyx: None,
            initial_value_only: false,
            error: Some((err.code.name().to_owned(), err.message)),
        }),
        Err(_) => None,
    }
}

/// A type as RAPID writes it, with `*` for a size that is not known.
fn type_text(t: &Type) -> String {
    if t.dims.is_empty() {
        return t.name.clone();
    }
    let dims: Vec<String> = t
        .dims
        .iter()
        .map(|d| {
            if *d == 0 {
                "*".to_owned()
            } else {
                d.to_string()
            }
        })
        .collect();
    format!("{}{{{}}}", t.name, dims.join(","))
}

/// The RAPID type of a value: arrays as `num{2,3}`; a name keeps its
/// declared type.
fn type_of_value(v: &Value, expr: &Expr, env: &dyn Env) -> String {
    if let Expr::Name(n) = expr {
        match env.lookup(n) {
            Lookup::Constant { ty, .. } | Lookup::Variable { ty, .. } => return type_text(&ty),
            _ => {}
        }
    }
    value_type(v)
}

/// The RAPID type of a value as `rapid eval` and hovers show it: arrays as
/// `num{2,3}` (an empty or untyped aggregate is `anytype`).
pub fn value_type(v: &Value) -> String {
    let mut dims = Vec::new();
    let mut cur = v;
    while let Value::Array(items) = cur {
        dims.push(items.len());
        match items.first() {
            Some(first) => cur = first,
            None => break,
        }
    }
    let base = cur.type_name().unwrap_or("anytype").to_owned();
    if dims.is_empty() {
        base
    } else {
        Type::array(base, dims).to_string()
    }
}

/// The type an expression must have where it stands: the declared type of
/// the data it initialises, the parameter it is passed to, the target it is
/// assigned to, the value a function returns, or the component or element
/// of an aggregate that has a type itself.
fn expected_type<'t>(cx: &mut Cx<'t>, path: &[Step<'t>], env: &dyn Env) -> Option<Type> {
    expected_type_at(cx, path, env, 0)
}

fn expected_type_at<'t>(
    cx: &mut Cx<'t>,
    path: &[Step<'t>],
    env: &dyn Env,
    depth: u32,
) -> Option<Type> {
    // Contexts nest no deeper than aggregates of aggregates do in practice.
    if depth > MAX_CONTEXT_DEPTH {
        return None;
    }
    let [.., (parent, _), (node, field)] = path else {
        return None;
    };
    let (parent, node) = (*parent, *node);
    let outer = &path[..path.len() - 1];
    match (crate::syntax_util::kind(parent), (*field)?) {
        ("parenthesized_expression", _) | ("unary_expression", _) => {
            expected_type_at(cx, outer, env, depth + 1)
        }
        ("data_declaration", "value") => {
            let name = field_of(parent, "name")?;
            match env.lookup(text_of(name, cx.text)) {
                Lookup::Constant { ty, .. } | Lookup::Variable { ty, .. } => Some(ty),
                _ => {
                    let d = crate::items::lower_data(parent, cx.text)?;
                    Some(Type::array(
                        d.ty.map_or("?".to_owned(), |t| t.name),
                        vec![0; d.dims.len()],
                    ))
                }
            }
        }
        ("aggregate", "element") => {
            let outer_ty = expected_type_at(cx, outer, env, depth + 1)?;
            if !outer_ty.dims.is_empty() {
                return Some(outer_ty.element());
            }
            let i = fields(parent, "element")
                .iter()
                .position(|e| e.id() == node.id())?;
            component_types(&outer_ty, env)?.into_iter().nth(i)
        }
        ("assignment", "right") => {
            let left = field_of(parent, "left")?;
            type_of(&cx.type_of_expr(left))
        }
        ("return_statement", "value") => {
            let decl = cx.routine.as_ref()?.decl;
            Some(Type::named(&decl.returns.as_ref()?.name))
        }
        ("argument", "value") => {
            let [.., (call, _), (list, _), _, _] = path else {
                return None;
            };
            argument_type(cx, *call, *list, parent)
        }
        _ => None,
    }
}

/// The child in field `name` (with the tree's lifetime).
fn field_of<'t>(node: Node<'t>, name: &str) -> Option<Node<'t>> {
    field(node, name)
}

/// The components of a record type, following aliases.
fn component_types(ty: &Type, env: &dyn Env) -> Option<Vec<Type>> {
    let mut name = ty.name.clone();
    for _ in 0..16 {
        if let Some(layout) = rapid_evaluator::builtin_record_layout(&name) {
            return Some(layout.iter().map(|c| Type::named(&c.ty)).collect());
        }
        if let Some(layout) = env.record_layout(&name) {
            return Some(layout.into_iter().map(|(_, t)| t).collect());
        }
        match env.alias_of(&name) {
            Some(t) if t.dims.is_empty() => name = t.name,
            _ => return None,
        }
    }
    None
}

fn type_of(ty: &Ty) -> Option<Type> {
    match ty {
        Ty::Named(n) => Some(Type::named(n)),
        Ty::Array(e, d) => match &**e {
            Ty::Named(n) => Some(Type::array(n, vec![0; usize::from(*d)])),
            _ => None,
        },
        Ty::Unknown | Ty::Any => None,
    }
}

/// The type of the parameter an argument is passed to.
fn argument_type<'t>(
    cx: &mut Cx<'t>,
    call: Node<'t>,
    list: Node<'t>,
    arg: Node<'t>,
) -> Option<Type> {
    let name = field(call, "name").filter(|n| crate::syntax_util::kind(*n) == "identifier")?;
    let want_function = crate::syntax_util::kind(call) == "function_call";
    let sym = cx.resolve_routine(text_of(name, cx.text), want_function)?;
    // (name, type, dims, required)
    let params: Vec<(String, String, u8, bool)> = match sym {
        RoutineSym::Builtin(r, _) => r
            .params
            .iter()
            .map(|p| {
                (
                    p.name.clone(),
                    if p.switch {
                        "switch".into()
                    } else {
                        p.ty.clone()
                    },
                    p.array,
                    !p.optional && p.alt_group.is_none(),
                )
            })
            .collect(),
        RoutineSym::User(d, _) => d
            .params
            .iter()
            .map(|p| {
                (
                    p.name.clone(),
                    p.ty.as_ref().map_or("?".into(), |t| t.name.clone()),
                    p.dims,
                    !p.optional && p.alt_group.is_none(),
                )
            })
            .collect(),
    };
    let param = match field(arg, "name") {
        Some(n) => {
            let n = text_of(n, cx.text);
            params.iter().find(|p| p.0.eq_ignore_ascii_case(n))?
        }
        None => {
            let position = fields(list, "argument")
                .into_iter()
                .take_while(|a| a.id() != arg.id())
                .filter(|a| field(*a, "name").is_none())
                .count();
            params.iter().filter(|p| p.3).nth(position)?
        }
    };
    if param.1.eq_ignore_ascii_case(crate::catalogue::ANYTYPE)
        || param.1.eq_ignore_ascii_case("switch")
    {
        return None;
    }
    Some(Type::array(param.1.clone(), vec![0; usize::from(param.2)]))
}

// ---------------------------------------------------------------------------
// Rule E413 constant-error.

/// Reports expressions in `node` (a statement or a data declaration) that
/// are made only of literals, constants and pure built-in functions and
/// always fail with a run-time error. Nested statements are left to their
/// own call. Only maximal constant expressions that hold an operation are
/// evaluated, each once.
pub(crate) fn check_constant_errors<'t>(cx: &mut Cx<'t>, node: Node<'t>) {
    // Most statements hold no operation at all (`MoveL p10, v100, z10,
    // tool0;`): their text says so without a walk of their nodes.
    if !may_hold_operation(cx.node_text(node)) {
        return;
    }
    let mut found = Vec::new();
    let mut path = vec![(node, None)];
    scan(cx, &mut path, &mut found);
    if found.is_empty() {
        return;
    }
    let task = cx.task;
    let unit = cx.unit;
    let mut reports = Vec::new();
    let at = module_at(task, cx.unit_idx, node.start_byte());
    let routine = RoutineNames::of(cx);
    // Typing the context must not disturb the checker's findings.
    let diags = std::mem::take(&mut cx.diags);
    let inits = cx.inits.take().unwrap_or_else(|| InitCache::new(task));
    with_routine(
        task,
        Some((cx.unit_idx, node.start_byte())),
        EnvOptions::default(),
        routine,
        Some(&inits),
        |env| {
            for path in found {
                let Some((n, _)) = path.last().copied() else {
                    continue;
                };
                let expected = expected_type(cx, &path, env);
                let expr = lower_with(n, &unit.text, &|name| is_builtin_call(task, at, name));
                let Err(e) =
                    rapid_evaluator::eval_with(&expr, expected.as_ref(), env, &Options::default())
                else {
                    continue;
                };
                if !e.code.is_runtime() {
                    continue;
                }
                // Without the type of its context, a literal may be meant as
                // a dnum: do not guess about limits.
                if expected.is_none()
                    && matches!(e.code, ErrorCode::MaxIntVal | ErrorCode::NumLimit)
                {
                    continue;
                }
                // A constant that fails on its own is reported where it is
                // declared, not at every use.
                if names_in(n).into_iter().any(|name| {
                    rapid_evaluator::eval(&Expr::Name(text_of(name, &unit.text).to_owned()), env)
                        .is_err()
                }) {
                    continue;
                }
                reports.push((n.byte_range(), e));
            }
        },
    );
    cx.diags = diags;
    cx.inits = Some(inits);
    for (range, e) in reports {
        cx.report(
            &crate::rules::constant_error::RULE,
            range,
            format!(
                "this expression always fails when it runs: {} ({})",
                e.code.name(),
                e.message
            ),
        );
    }
}

/// Could this text (of a statement or a declaration) hold an operation as
/// [`has_operation`] sees them: a call or a parenthesis, an index, an
/// operator other than the sign of a number literal, an operator keyword?
/// Strings and comments are skipped. `false` is certain; `true` only means
/// that the nodes must be looked at.
fn may_hold_operation(text: &str) -> bool {
    let b = text.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    // The digits and points of a number literal end just before `end`.
    let number_before = |end: usize| {
        let run = b[..end]
            .iter()
            .rev()
            .take_while(|c| c.is_ascii_digit() || **c == b'.')
            .count();
        run > 0 && (end == run || !b.get(end - run - 1).copied().is_some_and(is_word))
    };
    let mut prev = b' ';
    let mut i = 0;
    while let Some(&c) = b.get(i) {
        match c {
            b'"' => {
                i += 1;
                while b.get(i).is_some_and(|c| !matches!(c, b'"' | b'\n' | b'\r')) {
                    i += 1;
                }
                i += 1;
                prev = b'"';
                continue;
            }
            b'!' => {
                while b.get(i).is_some_and(|c| !matches!(c, b'\n' | b'\r')) {
                    i += 1;
                }
                continue;
            }
            b'(' | b'{' | b'*' | b'/' | b'<' | b'>' => return true,
            b'=' if prev != b':' => return true,
            b'+' | b'-' => {
                let digit_next = b
                    .get(i + 1)
                    .is_some_and(|d| d.is_ascii_digit() || *d == b'.');
                let sign = digit_next && matches!(prev, b'[' | b',' | b'=');
                let exponent =
                    digit_next && matches!(prev, b'e' | b'E') && i >= 1 && number_before(i - 1);
                if !(sign || exponent) {
                    return true;
                }
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let start = i;
                while b.get(i).copied().is_some_and(is_word) {
                    i += 1;
                }
                let word = &b[start..i];
                if ["div", "mod", "and", "or", "xor", "not"]
                    .iter()
                    .any(|k| word.eq_ignore_ascii_case(k.as_bytes()))
                {
                    return true;
                }
                prev = b[i - 1];
                continue;
            }
            _ => {}
        }
        if !c.is_ascii_whitespace() {
            prev = c;
        }
        i += 1;
    }
    false
}

/// Statements and declarations below a statement are checked on their own.
fn is_statement_like(kind: &str) -> bool {
    crate::syntax_util::is_simple_statement(kind)
        || crate::syntax_util::is_compound_statement(kind)
        || matches!(kind, "label" | "data_declaration")
}

/// The children of a node with their field names, read with `cursor` (one
/// cursor serves a whole statement: making one allocates).
fn children_with_fields<'t>(cursor: &mut TreeCursor<'t>, node: Node<'t>) -> Vec<Step<'t>> {
    cursor.reset(node);
    let mut out = Vec::new();
    if cursor.goto_first_child() {
        loop {
            out.push((cursor.node(), cursor.field_name()));
            if !cursor.goto_next_sibling() {
                break;
            }
        }
    }
    out
}

/// Finds the maximal expressions below the last node of `path`, in source
/// order (one cursor for the whole walk: this runs for every statement).
fn scan<'t>(cx: &mut Cx<'t>, path: &mut Vec<Step<'t>>, found: &mut Vec<Vec<Step<'t>>>) {
    let Some((node, _)) = path.last().copied() else {
        return;
    };
    let mut cursor = node.walk();
    if !cursor.goto_first_child() {
        return;
    }
    let mut aux = node.walk();
    // How far the cursor is below `node`; every node between `node` and the
    // cursor is on `path`.
    let mut depth = 1usize;
    loop {
        let child = cursor.node();
        let f = cursor.field_name();
        let mut descend = false;
        if child.is_named()
            && !is_statement_like(crate::syntax_util::kind(child))
            && !f.is_some_and(|f| NOT_VALUES.contains(&f))
        {
            path.push((child, f));
            if is_expression(crate::syntax_util::kind(child)) {
                // Aggregates of number literals (most robtargets) hold no
                // operation: their text says so without a walk.
                if !crate::syntax_util::is_literal_aggregate(child, cx.text)
                    && has_operation(&mut aux, child)
                {
                    let s = shape(cx, &mut aux, path, found, 0);
                    if s.constant && s.operation {
                        found.push(path.clone());
                    }
                }
                path.pop();
            } else {
                descend = true;
            }
        }
        if descend {
            if cursor.goto_first_child() {
                depth += 1;
                continue;
            }
            path.pop();
        }
        // The next node after `child` that is not below it.
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if depth <= 1 || !cursor.goto_parent() {
                return;
            }
            depth -= 1;
            path.pop();
        }
    }
}

/// Does the expression hold an operator, a call or an index (a cheap,
/// syntactic test before names are resolved)?
fn has_operation<'t>(cursor: &mut TreeCursor<'t>, node: Node<'t>) -> bool {
    cursor.reset(node);
    loop {
        let n = cursor.node();
        if matches!(
            crate::syntax_util::kind(n),
            "binary_expression" | "function_call" | "index_expression"
        ) || (crate::syntax_util::kind(n) == "unary_expression" && !is_signed_number(n))
        {
            return true;
        }
        if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.node().id() == node.id() {
                return false;
            }
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return false;
            }
        }
    }
}

/// `-1`, `+2.5`: a sign on a number literal.
fn is_signed_number(node: Node<'_>) -> bool {
    crate::syntax_util::kind(node) == "unary_expression"
        && field(node, "operand").is_some_and(|o| crate::syntax_util::kind(o) == "number")
        && field(node, "operator").is_some_and(|o| crate::syntax_util::kind(o) != "not")
}

/// An operand of an expression, as the steps from the expression to it.
enum Part<'t> {
    /// An expression child (an operand, a call's base).
    Operand(Step<'t>),
    /// The value of an argument: the argument list, the argument, the value.
    Argument([Step<'t>; 3]),
}

impl<'t> Part<'t> {
    fn steps(&self) -> &[Step<'t>] {
        match self {
            Part::Operand(s) => std::slice::from_ref(s),
            Part::Argument(s) => s,
        }
    }
}

#[derive(Clone, Copy)]
struct Shape {
    constant: bool,
    operation: bool,
}

/// Whether the expression at the end of `path` is made only of constants
/// and has an operation; the maximal constant parts with an operation of a
/// non-constant expression go to `found`.
fn shape<'t>(
    cx: &mut Cx<'t>,
    cursor: &mut TreeCursor<'t>,
    path: &mut Vec<Step<'t>>,
    found: &mut Vec<Vec<Step<'t>>>,
    depth: u32,
) -> Shape {
    const NOT: Shape = Shape {
        constant: false,
        operation: false,
    };
    let Some((node, _)) = path.last().copied() else {
        return NOT;
    };
    if depth > crate::lower::MAX_DEPTH || node.has_error() {
        return NOT;
    }
    let (mut constant, operation) = match crate::syntax_util::kind(node) {
        "number" | "string" | "boolean" => {
            return Shape {
                constant: true,
                operation: false,
            };
        }
        "identifier" => {
            return Shape {
                constant: is_constant_name(cx, cx.node_text(node)),
                operation: false,
            };
        }
        "parenthesized_expression" | "component_access" | "aggregate" => (true, false),
        // `-1` is a number, not a computation that could fail.
        "unary_expression" => (true, !is_signed_number(node)),
        "binary_expression" | "index_expression" => (true, true),
        "function_call" => {
            let pure = field(node, "name").is_some_and(|n| {
                let name = cx.node_text(n);
                rapid_evaluator::is_function(name)
                    && matches!(
                        cx.resolve_routine(name, true),
                        Some(RoutineSym::Builtin(..))
                    )
            });
            (pure, true)
        }
        _ => return NOT,
    };
    // The operands: expression children, and the values of arguments.
    let mut parts: Vec<Part<'t>> = Vec::new();
    for (child, f) in children_with_fields(cursor, node) {
        if !child.is_named() || f.is_some_and(|f| NOT_VALUES.contains(&f)) {
            continue;
        }
        if is_expression(crate::syntax_util::kind(child)) {
            parts.push(Part::Operand((child, f)));
        } else if crate::syntax_util::kind(child) == "argument_list" {
            for (arg, af) in children_with_fields(cursor, child) {
                if crate::syntax_util::kind(arg) != "argument" {
                    continue;
                }
                let arg_parts = crate::syntax_util::argument_parts(arg);
                if arg_parts.conditional.is_some() {
                    constant = false;
                }
                match arg_parts.value {
                    Some(v) if is_expression(crate::syntax_util::kind(v)) => {
                        parts.push(Part::Argument([(child, f), (arg, af), (v, Some("value"))]));
                    }
                    Some(_) => constant = false,
                    None if arg_parts.backslash => {}
                    None => constant = false,
                }
            }
        } else if crate::syntax_util::kind(child) != "comment" {
            constant = false;
        }
    }
    let mut shapes = Vec::with_capacity(parts.len());
    for part in &parts {
        let steps = part.steps();
        path.extend_from_slice(steps);
        shapes.push(shape(cx, cursor, path, found, depth + 1));
        path.truncate(path.len() - steps.len());
    }
    let mut op = operation;
    for s in &shapes {
        constant &= s.constant;
        op |= s.operation;
    }
    if !constant {
        for (part, s) in parts.iter().zip(&shapes) {
            if s.constant && s.operation {
                let mut p = path.clone();
                p.extend_from_slice(part.steps());
                found.push(p);
            }
        }
        return NOT;
    }
    Shape {
        constant,
        operation: op,
    }
}

/// Does this name denote constant data here (as the checker resolves it)?
fn is_constant_name(cx: &mut Cx<'_>, name: &str) -> bool {
    match cx.resolve_data(name) {
        Some(DataSym::Module(d, _)) => d.storage == Storage::Const,
        Some(DataSym::Local(d)) => d.storage == Storage::Const,
        Some(DataSym::Builtin(d)) => d.kind == DatumKind::Const,
        Some(_) => false,
        None => rapid_evaluator::predefined(name).is_some(),
    }
}

/// The data names used in an expression (not routine, component or
/// argument names).
fn names_in(node: Node<'_>) -> Vec<Node<'_>> {
    let mut cursor = node.walk();
    let mut out = Vec::new();
    let mut stack = vec![(node, None)];
    while let Some((n, f)) = stack.pop() {
        if f.is_some_and(|f| NOT_VALUES.contains(&f)) {
            continue;
        }
        if crate::syntax_util::kind(n) == "identifier" {
            out.push(n);
            continue;
        }
        stack.extend(
            children_with_fields(&mut cursor, n)
                .into_iter()
                .filter(|(c, _)| c.is_named()),
        );
    }
    out
}
