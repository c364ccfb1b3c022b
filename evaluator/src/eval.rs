//! The evaluator core: names, aggregates, operators, typing.

use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

use rapid_catalogue::TypeKind;

use crate::env::{Env, Lookup, VarKind};
use crate::error::{ErrorCode, EvalError, err};
use crate::expr::{BinOp, Expr, Type};
use crate::literal::{MAX_STRING_LEN, parse_num_literal, parse_string_literal};
use crate::value::Value;
use crate::{Evaluation, Options};

/// Largest integer `num` holds exactly; the limit for `DIV`/`MOD` on num.
pub(crate) const NUM_INT_MAX: f64 = 8_388_608.0;
/// Largest integer `dnum` holds exactly; the limit for `DIV`/`MOD` on dnum.
pub(crate) const DNUM_INT_MAX: f64 = 4_503_599_627_370_496.0;

/// How a type name resolves.
#[derive(Debug, Clone)]
pub(crate) enum Kind {
    Num,
    Dnum,
    Bool,
    Str,
    /// A record type: its name and its components in declaration order.
    Record(Rc<(String, Vec<(String, Type)>)>),
    Array(Type),
    /// A type the evaluator knows nothing about; values pass unchecked.
    Opaque,
}

pub(crate) struct Ctx {
    steps: u64,
    max_steps: u64,
    depth: u32,
    max_depth: u32,
    allow_initial: bool,
    pub(crate) initial_used: Vec<String>,
    in_progress: Vec<(usize, String)>,
    cache: HashMap<(usize, String), Value>,
    /// Type names resolved so far, with the scope they were resolved in:
    /// an aggregate asks for the kinds of its components at every element.
    kinds: RefCell<Vec<(usize, String, Kind)>>,
}

/// How many resolved type names a [`Ctx`] remembers.
const KIND_CACHE: usize = 64;

fn scope_id(env: &dyn Env) -> usize {
    (env as *const dyn Env).cast::<()>() as usize
}

pub(crate) fn run(
    expr: &Expr,
    expected: Option<&Type>,
    env: &dyn Env,
    opts: &Options,
) -> Result<Evaluation, EvalError> {
    let mut ctx = Ctx::new(opts);
    let value = ctx.eval(expr, expected, env)?;
    Ok(Evaluation {
        value,
        initial_values_used: ctx.initial_used,
    })
}

pub(crate) fn num_result(x: f64) -> Result<Value, EvalError> {
    if !x.is_finite() || x.abs() > f64::from(f32::MAX) {
        return err(
            ErrorCode::NumLimit,
            "the result is outside the range of num",
        );
    }
    Ok(Value::Num(x as f32))
}

pub(crate) fn dnum_result(x: f64) -> Result<Value, EvalError> {
    if !x.is_finite() {
        return err(
            ErrorCode::NumLimit,
            "the result is outside the range of dnum",
        );
    }
    Ok(Value::Dnum(x))
}

pub(crate) fn check_len(s: String) -> Result<Value, EvalError> {
    let n = s.chars().count();
    if n > MAX_STRING_LEN {
        return err(
            ErrorCode::StrTooLong,
            format!("the string would be {n} characters long; the limit is {MAX_STRING_LEN}"),
        );
    }
    Ok(Value::Str(s))
}

pub(crate) fn describe(v: &Value) -> String {
    match v.type_name() {
        Some(t) => t.to_string(),
        None => "an aggregate".to_string(),
    }
}

/// The kinds of the four basic types, whatever the environment.
fn primitive_kind(name: &str) -> Option<Kind> {
    let is = |n: &str| name.eq_ignore_ascii_case(n);
    match name.len() {
        3 if is("num") => Some(Kind::Num),
        4 if is("dnum") => Some(Kind::Dnum),
        4 if is("bool") => Some(Kind::Bool),
        6 if is("string") => Some(Kind::Str),
        _ => None,
    }
}

/// Resolves a type name through built-in (catalogue) and user aliases.
pub(crate) fn resolve_kind(name: &str, env: &dyn Env) -> Kind {
    let cat = env.catalogue();
    let mut name = name.to_owned();
    for _ in 0..16 {
        if let Some(k) = primitive_kind(&name) {
            return k;
        }
        // The task's own types first: a RECORD or ALIAS of a built-in
        // type's name (an option's `partdata` in a task without the
        // option) is the task's.
        let builtin = cat.datatype(&name);
        if builtin.is_none() || env.declares_type(&name) {
            if let Some(layout) = env.record_layout(&name) {
                return Kind::Record(Rc::new((name, layout)));
            }
            if let Some(t) = env.alias_of(&name) {
                if !t.dims.is_empty() {
                    return Kind::Array(t.element());
                }
                name = t.name;
                continue;
            }
        }
        if let Some(t) = builtin {
            match (t.kind, &t.alias_of) {
                (TypeKind::Alias, Some(of)) => {
                    name = of.clone();
                    continue;
                }
                // A record known by name only (an option's data whose
                // components no source documents): its values pass
                // unchecked, aggregates as written.
                (TypeKind::Record, _) if !t.layout_known => return Kind::Opaque,
                (TypeKind::Record, _) if !t.components.is_empty() => {
                    let layout = t
                        .components
                        .iter()
                        .map(|c| (c.name.clone(), Type::named(&c.ty)))
                        .collect();
                    return Kind::Record(Rc::new((name.to_ascii_lowercase(), layout)));
                }
                _ => {}
            }
        }
        return Kind::Opaque;
    }
    Kind::Opaque
}

impl Ctx {
    pub(crate) fn new(opts: &Options) -> Ctx {
        Ctx {
            steps: 0,
            max_steps: opts.max_steps,
            depth: 0,
            max_depth: opts.max_depth,
            allow_initial: opts.allow_initial_values,
            initial_used: Vec::new(),
            in_progress: Vec::new(),
            cache: HashMap::new(),
            kinds: RefCell::new(Vec::new()),
        }
    }

    /// See [`crate::zero_value`].
    pub(crate) fn zero(&self, ty: &Type, env: &dyn Env, opaque: &dyn Fn(&str) -> Value) -> Value {
        self.zero_depth(&ty.name, &ty.dims, env, opaque, 0)
    }

    fn zero_depth(
        &self,
        name: &str,
        dims: &[usize],
        env: &dyn Env,
        opaque: &dyn Fn(&str) -> Value,
        depth: u32,
    ) -> Value {
        if let Some((&n, rest)) = dims.split_first() {
            let item = self.zero_depth(name, rest, env, opaque, depth);
            return Value::Array(vec![item; n]);
        }
        // Records nest a few levels; a cycle of user records must end.
        if depth > 16 {
            return Value::Num(0.0);
        }
        match self.kind(&Type::named(name), env) {
            Kind::Num => Value::Num(0.0),
            Kind::Dnum => Value::Dnum(0.0),
            Kind::Bool => Value::Bool(false),
            Kind::Str => Value::Str(String::new()),
            Kind::Record(r) => Value::Record {
                ty: r.0.clone(),
                fields: r
                    .1
                    .iter()
                    .map(|(f, t)| {
                        let v = self.zero_depth(&t.name, &t.dims, env, opaque, depth + 1);
                        (f.clone(), v)
                    })
                    .collect(),
            },
            Kind::Array(_) => Value::Array(Vec::new()),
            Kind::Opaque => opaque(&name.to_ascii_lowercase()),
        }
    }

    /// Counts `n` units of work against the budget.
    pub(crate) fn step(&mut self, n: u64) -> Result<(), EvalError> {
        self.steps = self.steps.saturating_add(n);
        if self.steps > self.max_steps {
            return err(
                ErrorCode::TooComplex,
                "the expression is too large to evaluate",
            );
        }
        Ok(())
    }

    /// Resolves a type name (through aliases) to what the evaluator needs.
    pub(crate) fn kind(&self, ty: &Type, env: &dyn Env) -> Kind {
        if !ty.dims.is_empty() {
            return Kind::Array(ty.element());
        }
        if let Some(k) = primitive_kind(&ty.name) {
            return k;
        }
        let scope = scope_id(env);
        let known = self
            .kinds
            .borrow()
            .iter()
            .find(|(s, n, _)| *s == scope && n.eq_ignore_ascii_case(&ty.name))
            .map(|(_, _, k)| k.clone());
        if let Some(k) = known {
            return k;
        }
        let k = resolve_kind(&ty.name, env);
        let mut kinds = self.kinds.borrow_mut();
        if kinds.len() < KIND_CACHE {
            kinds.push((scope, ty.name.clone(), k.clone()));
        }
        k
    }

    pub(crate) fn eval(
        &mut self,
        expr: &Expr,
        expected: Option<&Type>,
        env: &dyn Env,
    ) -> Result<Value, EvalError> {
        self.step(1)?;
        if self.depth >= self.max_depth {
            return err(
                ErrorCode::TooDeep,
                "the expression or its chain of constants is nested too deeply",
            );
        }
        self.depth += 1;
        let r = self.eval_inner(expr, expected, env);
        self.depth -= 1;
        let v = r?;
        match expected {
            // An aggregate is built for the expected type already.
            Some(_) if matches!(expr, Expr::Aggregate(_)) => Ok(v),
            Some(t) => self.coerce(v, t, env),
            None => Ok(v),
        }
    }

    fn eval_inner(
        &mut self,
        expr: &Expr,
        expected: Option<&Type>,
        env: &dyn Env,
    ) -> Result<Value, EvalError> {
        match expr {
            Expr::Num(text) => {
                let x = parse_num_literal(text)?;
                let kind = expected.map(|t| self.kind(t, env));
                let want_dnum = matches!(kind, Some(Kind::Dnum));
                let want_num = matches!(kind, Some(Kind::Num));
                if want_dnum {
                    dnum_result(x)
                } else if !want_num && x > f64::from(f32::MAX) {
                    // Too large for num and no context asks for num: dnum.
                    dnum_result(x)
                } else {
                    num_result(x)
                }
            }
            Expr::Str(text) => Ok(Value::Str(parse_string_literal(text)?)),
            Expr::Bool(b) => Ok(Value::Bool(*b)),
            Expr::Name(name) => self.name(name, env),
            Expr::Aggregate(items) => self.aggregate(items, expected, env),
            Expr::Unary(op, operand) => {
                let v = self.eval(operand, expected, env)?;
                crate::operators::unary(*op, v)
            }
            Expr::Binary(op, l, r) => self.binary(*op, l, r, expected, env),
            Expr::Call { name, args } => crate::functions::call(self, name, args, env),
            Expr::Component(base, field) => self.component(base, field, env),
            Expr::Index(base, indices) => self.index(base, indices, env),
            Expr::Value(v) => Ok(v.clone()),
            Expr::Conditional(_) | Expr::Unknown => {
                err(ErrorCode::Unsupported, "the expression cannot be evaluated")
            }
        }
    }

    #[inline(never)]
    fn component(&mut self, base: &Expr, field: &str, env: &dyn Env) -> Result<Value, EvalError> {
        let v = self.eval(base, None, env)?;
        match v {
            Value::Record { ty, mut fields } => {
                match fields
                    .iter()
                    .position(|(n, _)| n.eq_ignore_ascii_case(field))
                {
                    Some(i) => Ok(fields.swap_remove(i).1),
                    None => err(
                        ErrorCode::TypeMismatch,
                        format!("{ty} has no component `{field}`"),
                    ),
                }
            }
            other => err(
                ErrorCode::TypeMismatch,
                format!("{} has no components", describe(&other)),
            ),
        }
    }

    #[inline(never)]
    fn index(&mut self, base: &Expr, indices: &[Expr], env: &dyn Env) -> Result<Value, EvalError> {
        let mut v = self.eval(base, None, env)?;
        if indices.is_empty() {
            return err(ErrorCode::BadArguments, "an index is missing");
        }
        for ix in indices {
            let i = self.eval(ix, Some(&Type::named("num")), env)?;
            let i = i.as_f64().unwrap_or(f64::NAN);
            if i.fract() != 0.0 {
                return err(ErrorCode::NotIntVal, "an array index must be an integer");
            }
            v = match v {
                Value::Array(mut items) => {
                    let n = items.len();
                    if i < 1.0 || i > n as f64 {
                        return err(
                            ErrorCode::OutOfBnd,
                            format!("index {i} is outside the array bounds 1..{n}"),
                        );
                    }
                    items.swap_remove(i as usize - 1)
                }
                other => {
                    return err(
                        ErrorCode::TypeMismatch,
                        format!("{} is not an array", describe(&other)),
                    );
                }
            };
        }
        Ok(v)
    }

    #[inline(never)]
    fn name(&mut self, name: &str, env: &dyn Env) -> Result<Value, EvalError> {
        match env.lookup(name) {
            Lookup::Constant { expr, ty, scope } => {
                let scope = scope.unwrap_or(env);
                self.with_definition(name, &expr, &ty, scope)
            }
            Lookup::Known { value } => Ok(value),
            Lookup::Variable {
                kind,
                ty,
                initial,
                scope,
            } => {
                let what = match kind {
                    VarKind::Var => "variable (VAR)",
                    VarKind::Pers => "persistent (PERS)",
                };
                match initial {
                    Some(init) if self.allow_initial => {
                        let scope = scope.unwrap_or(env);
                        let v = self.with_definition(name, &init, &ty, scope)?;
                        if !self
                            .initial_used
                            .iter()
                            .any(|n| n.eq_ignore_ascii_case(name))
                        {
                            self.initial_used.push(name.to_string());
                        }
                        Ok(v)
                    }
                    _ => err(
                        ErrorCode::NotConstant,
                        format!("`{name}` is a {what}; its value is known only at run time"),
                    ),
                }
            }
            Lookup::Unknown => match crate::env::predefined_in(env.catalogue(), name) {
                Some(v) => Ok(v),
                None => err(ErrorCode::UnknownName, format!("`{name}` is not known")),
            },
        }
    }

    #[inline(never)]
    fn with_definition(
        &mut self,
        name: &str,
        expr: &Expr,
        ty: &Type,
        scope: &dyn Env,
    ) -> Result<Value, EvalError> {
        let key = (scope_id(scope), name.to_lowercase());
        if let Some(v) = self.cache.get(&key) {
            return Ok(v.clone());
        }
        if self.in_progress.contains(&key) {
            return err(
                ErrorCode::Cycle,
                format!("the definition of `{name}` refers to itself"),
            );
        }
        self.in_progress.push(key.clone());
        let r = self.eval(expr, Some(ty), scope);
        self.in_progress.pop();
        let v = r?;
        self.cache.insert(key, v.clone());
        Ok(v)
    }

    #[inline(never)]
    fn aggregate(
        &mut self,
        items: &[Expr],
        expected: Option<&Type>,
        env: &dyn Env,
    ) -> Result<Value, EvalError> {
        let kind = expected.map(|t| self.kind(t, env));
        match kind {
            Some(Kind::Array(elem)) => {
                let want = expected.and_then(|t| t.dims.first().copied()).unwrap_or(0);
                if want != 0 && items.len() != want {
                    return err(
                        ErrorCode::TypeMismatch,
                        format!(
                            "the aggregate has {} elements; the array has {want}",
                            items.len()
                        ),
                    );
                }
                let mut out = Vec::with_capacity(items.len().min(1024));
                for it in items {
                    out.push(self.eval(it, Some(&elem), env)?);
                }
                Ok(Value::Array(out))
            }
            Some(Kind::Record(record)) => {
                let (ty, layout) = &*record;
                if items.len() != layout.len() {
                    return err(
                        ErrorCode::TypeMismatch,
                        format!(
                            "{ty} has {} components; the aggregate has {}",
                            layout.len(),
                            items.len()
                        ),
                    );
                }
                let mut fields = Vec::with_capacity(layout.len());
                for (it, (fname, fty)) in items.iter().zip(layout) {
                    let v = self.eval(it, Some(fty), env)?;
                    fields.push((fname.clone(), v));
                }
                Ok(Value::Record {
                    ty: ty.clone(),
                    fields,
                })
            }
            Some(Kind::Num | Kind::Dnum | Kind::Bool | Kind::Str) => err(
                ErrorCode::TypeMismatch,
                format!(
                    "an aggregate cannot be a {}",
                    expected.map(|t| t.name.as_str()).unwrap_or("")
                ),
            ),
            Some(Kind::Opaque) | None => {
                let mut out = Vec::with_capacity(items.len().min(1024));
                for it in items {
                    out.push(self.eval(it, None, env)?);
                }
                Ok(Value::Array(out))
            }
        }
    }

    /// Makes `v` a value of type `ty`: types untyped aggregates, widens num
    /// to dnum, and checks the rest.
    #[inline(never)]
    pub(crate) fn coerce(
        &mut self,
        v: Value,
        ty: &Type,
        env: &dyn Env,
    ) -> Result<Value, EvalError> {
        let kind = self.kind(ty, env);
        let mismatch = |v: &Value| {
            err(
                ErrorCode::TypeMismatch,
                format!("expected {ty}, found {}", describe(v)),
            )
        };
        match (kind, v) {
            (Kind::Num, Value::Num(x)) => Ok(Value::Num(x)),
            (Kind::Num, Value::Dnum(x)) => num_result(x),
            (Kind::Dnum, Value::Num(x)) => Ok(Value::Dnum(f64::from(x))),
            (Kind::Dnum, Value::Dnum(x)) => Ok(Value::Dnum(x)),
            (Kind::Bool, Value::Bool(b)) => Ok(Value::Bool(b)),
            (Kind::Str, Value::Str(s)) => Ok(Value::Str(s)),
            (Kind::Record(record), Value::Record { ty: vty, fields }) => {
                let (name, layout) = &*record;
                if vty.eq_ignore_ascii_case(name) {
                    Ok(Value::Record { ty: vty, fields })
                } else if layout.len() == fields.len()
                    && layout
                        .iter()
                        .zip(&fields)
                        .all(|((a, _), (b, _))| a.eq_ignore_ascii_case(b))
                {
                    // Same layout under another name (robtarget / o_robtarget).
                    Ok(Value::Record {
                        ty: name.clone(),
                        fields,
                    })
                } else {
                    mismatch(&Value::Record { ty: vty, fields })
                }
            }
            (Kind::Record(record), Value::Array(items)) => {
                let (name, layout) = &*record;
                if items.len() != layout.len() {
                    return mismatch(&Value::Array(items));
                }
                let mut fields = Vec::with_capacity(items.len());
                for (v, (fname, fty)) in items.into_iter().zip(layout) {
                    self.step(1)?;
                    fields.push((fname.clone(), self.coerce(v, fty, env)?));
                }
                Ok(Value::Record {
                    ty: name.clone(),
                    fields,
                })
            }
            (Kind::Array(elem), Value::Array(items)) => {
                if let Some(&n) = ty.dims.first()
                    && n != 0
                    && n != items.len()
                {
                    return err(
                        ErrorCode::TypeMismatch,
                        format!("expected {ty}, found an array of {}", items.len()),
                    );
                }
                let mut out = Vec::with_capacity(items.len());
                for v in items {
                    self.step(1)?;
                    out.push(self.coerce(v, &elem, env)?);
                }
                Ok(Value::Array(out))
            }
            (Kind::Opaque, v) => Ok(v),
            (_, v) => mismatch(&v),
        }
    }

    #[inline(never)]
    fn binary(
        &mut self,
        op: BinOp,
        l: &Expr,
        r: &Expr,
        expected: Option<&Type>,
        env: &dyn Env,
    ) -> Result<Value, EvalError> {
        // Operands of + and - have the type of the result; this lets
        // `[1,2,3] + p` and dnum literals work.
        let hint = match op {
            BinOp::Add | BinOp::Sub => {
                expected.filter(|t| !matches!(self.kind(t, env), Kind::Bool | Kind::Opaque))
            }
            // dnum context reaches the literals of a product or quotient,
            // so that `CONST dnum d := 1/3;` is computed in double.
            BinOp::Mul | BinOp::Div | BinOp::IntDiv | BinOp::Mod => {
                expected.filter(|t| matches!(self.kind(t, env), Kind::Dnum))
            }
            _ => None,
        };
        let a = self.eval(l, hint, env)?;
        let b = self.eval(r, hint, env)?;
        let (a, b) = self.unify(a, b, env)?;
        crate::operators::binary(op, a, b)
    }

    /// Gives an untyped aggregate the record type of the other operand.
    pub(crate) fn unify(
        &mut self,
        a: Value,
        b: Value,
        env: &dyn Env,
    ) -> Result<(Value, Value), EvalError> {
        match (&a, &b) {
            (Value::Record { ty, .. }, Value::Array(_)) => {
                let t = Type::named(ty.clone());
                let b = self.coerce(b, &t, env)?;
                Ok((a, b))
            }
            (Value::Array(_), Value::Record { ty, .. }) => {
                let t = Type::named(ty.clone());
                let a = self.coerce(a, &t, env)?;
                Ok((a, b))
            }
            _ => Ok((a, b)),
        }
    }
}
