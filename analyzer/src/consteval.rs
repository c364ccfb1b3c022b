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
use tree_sitter::{Node, Tree, TreeCursor};

use crate::catalogue::{Catalogue, Datum, DatumKind, Mode};
use crate::check::Cx;
use crate::items::{DataDecl, Storage};
use crate::lower::{is_expression, lower_with};
use crate::names::fold;
use crate::sema::def::Def;
use crate::sema::scope::Scope;
use crate::sema::signature::{Arg, Signature, Target, bind_args};
use crate::syntax::{field, kind};
use crate::syntax_util::{field, fields, text_of};
use crate::task::{Item, ItemRef, Task, Unit};
use crate::ty::{Ty, Types, UserType};

mod constant_error;
mod env;

pub(crate) use constant_error::check_constant_errors;
pub use env::TypeEnv;
use env::*;

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
        .and_then(|(unit, offset)| Scope::at(task, unit, offset))
        .and_then(|scope| scope.routine);
    with_routine(task, at, options, routine, None, f)
}

/// The lowered initial values of a task's module data, kept by a checker
/// context for its whole check so that each is lowered from the syntax tree
/// once, not at every use (lowering depends only on the declaration and its
/// module); and the trees of other units parsed again to read them (their
/// own were released), kept for the check. Each unit's slots are made when
/// one of its data is first asked for: a check costs what it reads, not
/// the size of its task.
pub(crate) struct InitCache {
    /// Per unit, the slots of its modules' data in order.
    units: Vec<OnceCell<Slots>>,
    /// Trees parsed again, by the unit's address.
    trees: std::cell::RefCell<std::collections::HashMap<usize, tree_sitter::Tree>>,
}

/// The lowered initial values of one unit's module data, in order.
type Slots = Box<[OnceCell<Option<Expr>>]>;

impl InitCache {
    pub(crate) fn new(task: &Task) -> InitCache {
        InitCache {
            units: std::iter::repeat_with(OnceCell::new)
                .take(task.units.len())
                .collect(),
            trees: Default::default(),
        }
    }

    /// The slot of module data `r` of `task`.
    fn slot(&self, task: &Task, r: ItemRef) -> Option<&OnceCell<Option<Expr>>> {
        let Item::Data(i) = r.item else {
            return None;
        };
        let modules = &task.unit(r.unit)?.items.modules;
        if i >= modules.get(r.module)?.data.len() {
            return None;
        }
        let slots = self.units.get(r.unit)?.get_or_init(|| {
            let n = modules.iter().map(|m| m.data.len()).sum();
            std::iter::repeat_with(OnceCell::new).take(n).collect()
        });
        let first: usize = modules.iter().take(r.module).map(|m| m.data.len()).sum();
        slots.get(first + i)
    }

    /// The tree of `unit` (whose own was released), parsed again once per
    /// check.
    fn tree_of(&self, unit: &Unit) -> tree_sitter::Tree {
        let key = std::ptr::from_ref(unit) as usize;
        self.trees
            .borrow_mut()
            .entry(key)
            .or_insert_with(|| unit.parse_again())
            .clone()
    }
}

/// Is `offset` of unit `unit` inside a routine?
fn in_routine(task: &Task, unit: usize, offset: usize) -> bool {
    task.unit(unit).is_some_and(|u| {
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
    routine: Option<crate::sema::scope::RoutineScope<'t>>,
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
    let Some(u) = task.unit(unit) else {
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

/// The values of the module data of unit `unit` of `task`, per module
/// and datum in the order of [`crate::items::Module::data`]: a `CONST`'s
/// value, or the value a `PERS` or `VAR` declaration gives (the value a
/// backup saved), typed by its declaration; `None` where it is not known
/// (no initial value, an unknown name, a run-time error). Names resolve as
/// at the module's top level.
pub fn module_data_values(task: &Task, unit: usize) -> Vec<Vec<Option<Value>>> {
    let Some(u) = task.units.get(unit) else {
        return Vec::new();
    };
    let inits = InitCache::new(task);
    let options = EnvOptions::initial_values();
    u.items
        .modules
        .iter()
        .map(|m| {
            let at = Some((unit, m.name_range.start));
            with_routine(task, at, options, None, Some(&inits), |env| {
                m.data
                    .iter()
                    .map(|d| {
                        let name = Expr::Name(d.name.clone());
                        rapid_evaluator::eval_with(&name, None, env, &options.evaluator_options())
                            .ok()
                            .map(|e| e.value)
                    })
                    .collect()
            })
        })
        .collect()
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
    let u = task.unit(unit)?;
    let root = u.tree().root_node();
    let mut start = root.named_descendant_for_byte_range(offset, offset)?;
    // A cursor just after a name or a closing bracket means that expression
    // (as editors place it after the last character typed).
    let on_token = matches!(
        crate::syntax_util::kind(start),
        kind::IDENTIFIER | kind::NUMBER | kind::STRING | kind::BOOLEAN
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
        let typing = Scope::at(task, unit, offset);
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
                    && let Some(v) = value_of_node(task, unit, &path, env, typing.as_ref(), options)
                {
                    return Some(v);
                }
            } else if !matches!(
                crate::syntax_util::kind(n),
                kind::ARGUMENT | kind::ARGUMENT_LIST
            ) {
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
    let u = task.unit(unit)?;
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
        let typing = Scope::at(task, unit, start);
        let mut v = evaluate_node(task, unit, &path, env, typing.as_ref(), options)?;
        v.range = node.byte_range();
        Some(v)
    })
}

fn value_of_node<'t>(
    task: &'t Task,
    unit: usize,
    path: &[Step<'t>],
    env: &dyn Env,
    typing: Option<&Scope<'t>>,
    options: EnvOptions,
) -> Option<ConstValue> {
    let (node, _) = *path.last()?;
    let v = evaluate_node(task, unit, path, env, typing, options)?;
    let text = task.unit(unit).map_or("", |u| text_of(node, &u.text));
    if matches!(
        crate::syntax_util::kind(node),
        kind::NUMBER | kind::STRING | kind::BOOLEAN
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
    typing: Option<&Scope<'t>>,
    options: EnvOptions,
) -> Option<ConstValue> {
    let u = task.unit(unit)?;
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
    let m = task.unit(unit)?.items.module_at(offset)?;
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
fn expected_type<'t>(cx: &Scope<'t>, path: &[Step<'t>], env: &dyn Env) -> Option<Type> {
    expected_type_at(cx, path, env, 0)
}

fn expected_type_at<'t>(
    cx: &Scope<'t>,
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
        (kind::PARENTHESIZED_EXPRESSION, _) | (kind::UNARY_EXPRESSION, _) => {
            expected_type_at(cx, outer, env, depth + 1)
        }
        (kind::DATA_DECLARATION, field::VALUE) => {
            let name = field_of(parent, field::NAME)?;
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
        (kind::AGGREGATE, field::ELEMENT) => {
            let outer_ty = expected_type_at(cx, outer, env, depth + 1)?;
            if !outer_ty.dims.is_empty() {
                return Some(outer_ty.element());
            }
            let i = fields(parent, field::ELEMENT)
                .iter()
                .position(|e| e.id() == node.id())?;
            component_types(&outer_ty, env)?.into_iter().nth(i)
        }
        (kind::ASSIGNMENT, field::RIGHT) => {
            let left = field_of(parent, field::LEFT)?;
            type_of(&crate::sema::typing::type_of(cx, left, None))
        }
        (kind::RETURN_STATEMENT, field::VALUE) => {
            let decl = cx.routine.as_ref()?.decl;
            Some(Type::named(&decl.returns.as_ref()?.name))
        }
        (kind::ARGUMENT, field::VALUE) => {
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

/// The components of a record type, following aliases, as the evaluator
/// resolves them.
fn component_types(ty: &Type, env: &dyn Env) -> Option<Vec<Type>> {
    let layout = rapid_evaluator::record_components(&ty.name, env)?;
    Some(layout.into_iter().map(|(_, t)| t).collect())
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
    cx: &Scope<'t>,
    call: Node<'t>,
    list: Node<'t>,
    arg: Node<'t>,
) -> Option<Type> {
    let name =
        field(call, field::NAME).filter(|n| crate::syntax_util::kind(*n) == kind::IDENTIFIER)?;
    let want_function = crate::syntax_util::kind(call) == kind::FUNCTION_CALL;
    let sym = cx.resolve_routine(text_of(name, cx.text), want_function)?;
    let sig = Signature::of(&sym, cx.task)?;
    let args = fields(list, field::ARGUMENT);
    let described: Vec<Arg<'_>> = args
        .iter()
        .map(|a| match field(*a, field::NAME) {
            Some(n) => Arg::Named(text_of(n, cx.text)),
            None => Arg::Positional,
        })
        .collect();
    let k = args.iter().position(|a| a.id() == arg.id())?;
    let Target::Param(i) = bind_args(&sig, &described).args.get(k)?.target else {
        return None;
    };
    let param = sig.params.get(i)?;
    if param.switch
        || param
            .type_name
            .eq_ignore_ascii_case(crate::catalogue::ANYTYPE)
    {
        return None;
    }
    let name = if param.type_name.is_empty() {
        "?".to_owned()
    } else {
        param.type_name.clone()
    };
    Some(Type::array(name, vec![0; usize::from(param.ty.dims())]))
}
