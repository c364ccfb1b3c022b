//! From the analyzer's body IR to the compiled form ([`crate::code`]):
//! names resolved as the controller resolves them (`FOR` variables, the
//! routine's parameters and data, its module's data, the task's global
//! data, predefined data and signals), calls bound to routines and
//! built-ins, literals decoded, and the type each value is stored as.

use rapid_analyzer::body::{self, ArgValue as IrArg, Body, Callee, StmtKind as S};
use rapid_analyzer::catalogue::{self, Mode};
use rapid_analyzer::items::{RoutineKind, Storage};
use rapid_analyzer::names::{NameMap, fold};
use rapid_evaluator::{BinOp, Expr as E, Type, UnOp, Value};

use crate::builtins;
use crate::code::*;
use crate::program::Program;
use crate::types::Shape;

pub(crate) struct Compiler<'p> {
    prog: &'p Program,
    module: usize,
    slots: Vec<SlotInfo>,
    /// Visible local names (folded) with their slots; searched from the
    /// end, so that a `FOR` variable hides what is declared outside.
    scope: Vec<(String, u32)>,
    labels: NameMap<u32>,
}

impl<'p> Compiler<'p> {
    /// A compiler for expressions of module `module` (its data's initial
    /// values), outside any routine.
    pub(crate) fn for_module(prog: &'p Program, module: usize) -> Compiler<'p> {
        Compiler {
            prog,
            module,
            slots: Vec::new(),
            scope: Vec::new(),
            labels: NameMap::default(),
        }
    }

    /// Compiles routine `id` of the program.
    pub(crate) fn routine(prog: &'p Program, id: u32) -> Routine {
        let info = &prog.routines[id as usize];
        let module = info.module;
        let unit_idx = prog.modules.get(module).map_or(0, |m| m.unit);
        let mut c = Compiler::for_module(prog, module);
        let decl = &info.decl;
        let mut params = Vec::new();
        for p in &decl.params {
            let ty = Type::array(
                p.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                vec![0; usize::from(p.dims)],
            );
            c.add_slot(&p.name, ty.clone(), SlotKind::Param);
            params.push(Param {
                conv: c.conv(&ty),
                name: p.name.clone(),
                mode: p.mode,
                optional: p.optional,
                switch: p.switch,
            });
        }
        let returns = decl.returns.as_ref().map(|t| Type::named(t.name.clone()));
        let body = prog
            .task
            .units
            .get(unit_idx)
            .and_then(|u| body::lower_routine(u, decl))
            .unwrap_or_else(|| Body {
                kind: decl.kind,
                name: decl.name.clone(),
                range: decl.range.clone(),
                data: Vec::new(),
                stmts: Vec::new(),
                backward: None,
                error: None,
                undo: None,
            });
        let mut data = Vec::new();
        let mut pending = Vec::new();
        for d in &body.data {
            let ty = Type::array(d.ty.clone(), vec![0; d.dims.len()]);
            let kind = match d.storage {
                Storage::Var => SlotKind::Var,
                Storage::Pers => SlotKind::Pers,
                Storage::Const => SlotKind::Const,
            };
            let slot = c.add_slot(&d.name, ty, kind);
            pending.push((slot, d));
        }
        for (slot, d) in pending {
            let ty = c.slots[slot as usize].ty.clone();
            data.push(LocalInit {
                slot,
                ty_name: d.ty.clone(),
                dims: d
                    .dims
                    .iter()
                    .map(|e| c.expr(e, Some(&Type::named("num"))))
                    .collect(),
                init: d.init.as_ref().map(|e| c.expr(e, Some(&ty))),
                conv: c.conv(&ty),
                range: d.range.clone(),
            });
        }
        body.walk(&mut |s| {
            if let S::Label(name) = &s.kind {
                let n = c.labels.len() as u32;
                c.labels.entry(fold(name)).or_insert(n);
            }
        });
        let stmts = c.list(&body.stmts, returns.as_ref());
        let error = body.error.as_ref().map(|h| ErrorHandler {
            errors: h
                .errors
                .iter()
                .map(|e| c.expr(e, Some(&Type::named("num"))))
                .collect(),
            body: c.list(&h.stmts, returns.as_ref()),
        });
        let undo = body
            .undo
            .as_ref()
            .map(|h| c.list(&h.stmts, returns.as_ref()));
        let returns_conv = returns.as_ref().map_or(Conv::None, |t| c.conv(t));
        Routine {
            id,
            name: decl.name.clone(),
            kind: decl.kind,
            unit: unit_idx,
            range: decl.range.clone(),
            params,
            slots: c.slots,
            data,
            body: stmts,
            error,
            undo,
            returns_conv,
        }
    }

    /// Sees the slots of a compiled routine (for a debugger's expressions).
    pub(crate) fn adopt_slots(&mut self, r: &Routine) {
        for s in &r.slots {
            self.add_slot(&s.name, s.ty.clone(), s.kind);
        }
    }

    fn add_slot(&mut self, name: &str, ty: Type, kind: SlotKind) -> u32 {
        let slot = self.slots.len() as u32;
        self.slots.push(SlotInfo {
            name: name.to_owned(),
            ty,
            kind,
        });
        self.scope.push((fold(name), slot));
        slot
    }

    fn list(&mut self, list: &[body::Stmt], returns: Option<&Type>) -> Vec<Stmt> {
        list.iter().map(|s| self.stmt(s, returns)).collect()
    }

    fn stmt(&mut self, s: &body::Stmt, returns: Option<&Type>) -> Stmt {
        let kind = match &s.kind {
            S::Assign { target, value } => {
                let target = self.expr(target, None);
                if !target.is_place() {
                    StmtKind::Fail(target.failure().unwrap_or_else(|| {
                        Failure::Invalid("the left side of := is not a data reference".to_owned())
                    }))
                } else {
                    let ty = self.type_of(&target);
                    StmtKind::Assign {
                        value: self.expr(value, ty.as_ref()),
                        conv: ty.as_ref().map_or(Conv::None, |t| self.conv(t)),
                        target,
                    }
                }
            }
            S::Call(call) => self.call(call),
            S::If {
                branches,
                otherwise,
                ..
            } => StmtKind::If {
                branches: branches
                    .iter()
                    .map(|b| (self.cond(&b.cond), self.list(&b.body, returns)))
                    .collect(),
                otherwise: otherwise
                    .as_ref()
                    .map(|o| self.list(o, returns))
                    .unwrap_or_default(),
            },
            S::For {
                var,
                from,
                to,
                step,
                body,
                ..
            } => {
                let num = Type::named("num");
                let (from, to) = (self.expr(from, Some(&num)), self.expr(to, Some(&num)));
                let step = step.as_ref().map(|e| self.expr(e, Some(&num)));
                let depth = self.scope.len();
                let slot = self.add_slot(var, num, SlotKind::For);
                let body = self.list(body, returns);
                self.scope.truncate(depth);
                StmtKind::For {
                    slot,
                    from,
                    to,
                    step,
                    body,
                }
            }
            S::While { cond, body } => StmtKind::While {
                cond: self.cond(cond),
                body: self.list(body, returns),
            },
            S::Test {
                value,
                cases,
                default,
            } => StmtKind::Test {
                value: self.expr(value, None),
                cases: cases
                    .iter()
                    .map(|c| {
                        (
                            c.values.iter().map(|v| self.expr(v, None)).collect(),
                            self.list(&c.body, returns),
                        )
                    })
                    .collect(),
                default: default
                    .as_ref()
                    .map(|d| self.list(d, returns))
                    .unwrap_or_default(),
            },
            S::Label(name) => match self.labels.get(&fold(name)) {
                Some(&l) => StmtKind::Label(l),
                None => StmtKind::Fail(Failure::Invalid(format!("label {name}"))),
            },
            S::Goto(name) => match self.labels.get(&fold(name)) {
                Some(&l) => StmtKind::Goto(l),
                None => StmtKind::Fail(Failure::Invalid(format!(
                    "GOTO {name}: the routine has no label {name}"
                ))),
            },
            S::Return(v) => StmtKind::Return(v.as_ref().map(|e| self.expr(e, returns))),
            S::Raise(v) => {
                StmtKind::Raise(v.as_ref().map(|e| self.expr(e, Some(&Type::named("num")))))
            }
            S::Exit => StmtKind::Exit,
            S::Retry => StmtKind::Retry,
            S::TryNext => StmtKind::TryNext,
            S::Connect {
                interrupt, trap, ..
            } => match self.routine_named(trap) {
                Some(id) => StmtKind::Connect {
                    target: self.expr(interrupt, None),
                    trap: id,
                },
                None => StmtKind::Fail(Failure::Unknown(trap.clone())),
            },
            S::Invalid => StmtKind::Fail(Failure::Invalid(
                "a placeholder or a statement with a syntax error".to_owned(),
            )),
        };
        Stmt {
            range: s.range.clone(),
            kind,
        }
    }

    fn cond(&self, e: &E) -> Expr {
        self.expr(e, Some(&Type::named("bool")))
    }

    /// A routine of the program visible from this module.
    fn routine_named(&self, name: &str) -> Option<u32> {
        self.prog.routine_from(self.module, name)
    }

    fn call(&mut self, call: &body::Call) -> StmtKind {
        let name = match &call.callee {
            Callee::Late(e) => {
                return StmtKind::Late {
                    name: self.expr(e, Some(&Type::named("string"))),
                    args: self.user_args(&ir_args(&call.args), None),
                };
            }
            Callee::Name(n) => n,
        };
        if let Some(id) = self.routine_named(name) {
            let routine = self.prog.routines.get(id as usize);
            if routine.is_some_and(|r| r.decl.kind != RoutineKind::Proc) {
                return StmtKind::Fail(Failure::Invalid(format!("{name} is not a procedure")));
            }
            return StmtKind::Call {
                routine: id,
                args: self.user_args(&ir_args(&call.args), Some(id)),
            };
        }
        let key = fold(name);
        let sig = self.prog.task.catalogue.instruction(&key);
        match builtins::instruction(&key) {
            Some((canonical, f)) => match self.bind_builtin(sig, &ir_args(&call.args)) {
                Ok(args) => StmtKind::Builtin {
                    name: canonical,
                    f,
                    args,
                },
                Err(why) => StmtKind::Fail(Failure::Invalid(format!("{canonical}: {why}"))),
            },
            None if sig.is_some() || self.prog.task.catalogue.function(&key).is_some() => {
                StmtKind::Fail(Failure::Unsupported(
                    sig.map_or(name.clone(), |s| s.name.clone()),
                ))
            }
            None => StmtKind::Fail(Failure::Unknown(name.clone())),
        }
    }

    /// Arguments of a call of a program routine; typed by the routine's
    /// parameters when it is known now.
    fn user_args(&self, args: &[ArgIr<'_>], routine: Option<u32>) -> Vec<Arg> {
        let params = routine
            .and_then(|id| self.prog.routines.get(id as usize))
            .map(|r| &r.decl.params);
        let mut next = 0usize;
        args.iter()
            .map(|a| {
                let expected = params.and_then(|ps| {
                    let named = ps.iter().map(|p| (p.name.as_str(), p.optional));
                    let p = ps.get(bind_index(named, a.name, &mut next)?)?;
                    Some(Type::array(
                        p.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                        vec![0; usize::from(p.dims)],
                    ))
                });
                Arg {
                    name: a.name.map(Box::from),
                    value: self.arg_value(&a.value, expected.as_ref()),
                }
            })
            .collect()
    }

    /// Arguments typed by the catalogue's parameters, kept in source order
    /// (the evaluator binds them itself).
    fn typed_args(&self, sig: Option<&catalogue::Routine>, args: &[ArgIr<'_>]) -> Vec<Arg> {
        let mut next = 0usize;
        args.iter()
            .map(|a| {
                let expected = sig.and_then(|s| {
                    let named = s.params.iter().map(|p| (p.name.as_str(), p.optional));
                    catalogue_type(s.params.get(bind_index(named, a.name, &mut next)?)?)
                });
                Arg {
                    name: a.name.map(Box::from),
                    value: self.arg_value(&a.value, expected.as_ref()),
                }
            })
            .collect()
    }

    fn arg_value(&self, v: &IrArg, expected: Option<&Type>) -> ArgValue {
        match v {
            IrArg::Expr(e) => ArgValue::Expr(self.expr(e, expected)),
            IrArg::Switch => ArgValue::Switch,
            IrArg::Conditional(n) => match self.local(n) {
                Some(slot) => ArgValue::Conditional(slot),
                None => ArgValue::Expr(Expr::Fail(Failure::Invalid(format!(
                    "?{n}: not a parameter of the routine"
                )))),
            },
            IrArg::Star => ArgValue::Star,
            IrArg::Invalid => ArgValue::Expr(Expr::Fail(Failure::Invalid(
                "a placeholder or broken argument".to_owned(),
            ))),
        }
    }

    /// Binds arguments to the parameters of a built-in: positional ones to
    /// the required parameters in order, named ones by name.
    fn bind_builtin(
        &self,
        sig: Option<&'static catalogue::Routine>,
        args: &[ArgIr<'_>],
    ) -> Result<Vec<Option<ArgValue>>, String> {
        let Some(sig) = sig else {
            return Ok(args
                .iter()
                .map(|a| Some(self.arg_value(&a.value, None)))
                .collect());
        };
        let mut out: Vec<Option<ArgValue>> = sig.params.iter().map(|_| None).collect();
        let mut next = 0usize;
        for a in args {
            let named = sig.params.iter().map(|p| (p.name.as_str(), p.optional));
            let i = bind_index(named, a.name, &mut next).ok_or_else(|| match a.name {
                Some(n) => format!("there is no parameter {n}"),
                None => "too many arguments".to_owned(),
            })?;
            let expected = sig.params.get(i).and_then(catalogue_type);
            if let Some(slot) = out.get_mut(i) {
                *slot = Some(self.arg_value(&a.value, expected.as_ref()));
            }
        }
        Ok(out)
    }

    fn local(&self, name: &str) -> Option<u32> {
        let key = fold(name);
        self.scope
            .iter()
            .rev()
            .find(|(n, _)| *n == key)
            .map(|(_, s)| *s)
    }

    fn data(&self, name: &str) -> Option<Expr> {
        if let Some(slot) = self.local(name) {
            return Some(Expr::Local(slot));
        }
        let key = fold(name);
        self.prog
            .modules
            .get(self.module)
            .and_then(|m| m.data.get(&key))
            .or_else(|| self.prog.global_data.get(&key))
            .map(|&g| Expr::Global(g))
    }

    /// Compiles an expression; `expected` is the type its value is stored
    /// as, which types aggregates and makes literals `dnum`.
    pub(crate) fn expr(&self, e: &E, expected: Option<&Type>) -> Expr {
        self.expr_depth(e, expected, 0)
    }

    fn expr_depth(&self, e: &E, expected: Option<&Type>, depth: u32) -> Expr {
        if depth > 200 {
            return Expr::Fail(Failure::Invalid(
                "the expression is nested too deeply".into(),
            ));
        }
        let d = depth + 1;
        match e {
            E::Num(text) => match rapid_evaluator::parse_num_literal(text) {
                Ok(x) => {
                    let dnum = expected.is_some_and(|t| matches!(self.shape(t), Shape::Dnum));
                    if dnum || x > f64::from(f32::MAX) {
                        Expr::Const(Value::Dnum(x))
                    } else {
                        Expr::Const(Value::Num(x as f32))
                    }
                }
                Err(err) => Expr::Fail(Failure::Invalid(err.message)),
            },
            E::Str(text) => match rapid_evaluator::parse_string_literal(text) {
                Ok(s) => Expr::Const(Value::Str(s)),
                Err(err) => Expr::Fail(Failure::Invalid(err.message)),
            },
            E::Bool(b) => Expr::Const(Value::Bool(*b)),
            E::Value(v) => Expr::Const(v.clone()),
            E::Name(n) => self
                .data(n)
                .unwrap_or_else(|| Expr::Fail(Failure::Unknown(n.clone()))),
            E::Aggregate(items) => self.aggregate(items, expected, d),
            E::Unary(op, x) => {
                let inner = self.expr_depth(x, expected, d);
                match (op, &inner) {
                    (UnOp::Neg, Expr::Const(Value::Num(v))) => Expr::Const(Value::Num(-v)),
                    (UnOp::Neg, Expr::Const(Value::Dnum(v))) => Expr::Const(Value::Dnum(-v)),
                    _ => Expr::Unary(*op, Box::new(inner)),
                }
            }
            E::Binary(op, l, r) => {
                let hint = match op {
                    BinOp::Add | BinOp::Sub => expected.filter(|t| {
                        t.dims.is_empty()
                            && !matches!(self.shape(t), Shape::Bool | Shape::Opaque(_))
                    }),
                    BinOp::Mul | BinOp::Div | BinOp::IntDiv | BinOp::Mod => {
                        expected.filter(|t| matches!(self.shape(t), Shape::Dnum))
                    }
                    _ => None,
                };
                Expr::Binary(
                    *op,
                    Box::new(self.expr_depth(l, hint, d)),
                    Box::new(self.expr_depth(r, hint, d)),
                )
            }
            E::Call { name, args } => self.function(name, args),
            E::Component(b, f) => {
                Expr::Field(Box::new(self.expr_depth(b, None, d)), f.as_str().into())
            }
            E::Index(b, ix) => Expr::Index(
                Box::new(self.expr_depth(b, None, d)),
                ix.iter()
                    .map(|i| self.expr_depth(i, Some(&Type::named("num")), d))
                    .collect(),
            ),
            E::Conditional(n) => Expr::Fail(Failure::Invalid(format!(
                "?{n} stands outside an argument list"
            ))),
            E::Unknown => Expr::Fail(Failure::Invalid(
                "a placeholder or a broken expression".to_owned(),
            )),
        }
    }

    fn aggregate(&self, items: &[E], expected: Option<&Type>, depth: u32) -> Expr {
        let Some(ty) = expected else {
            return Expr::Aggregate(
                None,
                items
                    .iter()
                    .map(|i| self.expr_depth(i, None, depth))
                    .collect(),
            );
        };
        if !ty.dims.is_empty() {
            let elem = ty.element();
            return Expr::Aggregate(
                Some(ty.clone()),
                items
                    .iter()
                    .map(|i| self.expr_depth(i, Some(&elem), depth))
                    .collect(),
            );
        }
        match self.shape(ty) {
            Shape::Record(r) if r.1.len() == items.len() => Expr::Aggregate(
                Some(ty.clone()),
                items
                    .iter()
                    .zip(r.1.iter())
                    .map(|(i, (_, t))| self.expr_depth(i, Some(&Type::named(t.clone())), depth))
                    .collect(),
            ),
            _ => Expr::Aggregate(
                Some(ty.clone()),
                items
                    .iter()
                    .map(|i| self.expr_depth(i, None, depth))
                    .collect(),
            ),
        }
    }

    fn function(&self, name: &str, args: &[rapid_evaluator::Arg]) -> Expr {
        let ir: Vec<ArgIr<'_>> = args
            .iter()
            .map(|a| ArgIr {
                name: a.name.as_deref(),
                value: match &a.value {
                    None => IrArg::Switch,
                    Some(E::Conditional(n)) => IrArg::Conditional(n.clone()),
                    Some(e) => IrArg::Expr(e.clone()),
                },
            })
            .collect();
        if name.eq_ignore_ascii_case("present")
            && let [a] = args
            && let Some(E::Name(p)) = &a.value
        {
            return match self.local(p) {
                Some(slot)
                    if self
                        .slots
                        .get(slot as usize)
                        .is_some_and(|s| s.kind == SlotKind::Param) =>
                {
                    Expr::Present(slot)
                }
                _ => Expr::Fail(Failure::Invalid(format!(
                    "Present({p}): {p} is not a parameter of the routine"
                ))),
            };
        }
        if let Some(id) = self.routine_named(name) {
            return Expr::Call {
                routine: id,
                args: self.user_args(&ir, Some(id)),
            };
        }
        let key = fold(name);
        let sig = self.prog.task.catalogue.function(&key);
        if let Some((canonical, f)) = builtins::function(&key) {
            return match self.bind_builtin(sig, &ir) {
                Ok(args) => Expr::Func {
                    name: canonical,
                    f,
                    args,
                },
                Err(why) => Expr::Fail(Failure::Invalid(format!("{canonical}: {why}"))),
            };
        }
        if rapid_evaluator::is_function(name) {
            return Expr::Pure {
                name: name.into(),
                args: self.typed_args(sig, &ir),
            };
        }
        match sig {
            Some(s) => Expr::Fail(Failure::Unsupported(s.name.clone())),
            None if self.prog.task.catalogue.instruction(&key).is_some() => Expr::Fail(
                Failure::Invalid(format!("{name} is an instruction, not a function")),
            ),
            None => Expr::Fail(Failure::Unknown(name.to_owned())),
        }
    }

    fn shape(&self, t: &Type) -> Shape {
        self.prog.types.shape(&t.name)
    }

    /// How a value is stored as type `ty`.
    pub(crate) fn conv(&self, ty: &Type) -> Conv {
        if !ty.dims.is_empty() {
            return Conv::Full(ty.clone());
        }
        match self.shape(ty) {
            Shape::Num => Conv::Num,
            Shape::Dnum => Conv::Dnum,
            Shape::Bool | Shape::Str | Shape::Opaque(_) => Conv::None,
            Shape::Record(_) => Conv::Full(ty.clone()),
        }
    }

    /// The declared type of a data reference (array sizes not known).
    pub(crate) fn type_of(&self, e: &Expr) -> Option<Type> {
        match e {
            Expr::Local(s) => self.slots.get(*s as usize).map(|s| s.ty.clone()),
            Expr::Global(g) => self.prog.globals.get(*g as usize).map(|g| g.ty.clone()),
            Expr::Field(b, f) => {
                let t = self.type_of(b)?;
                if !t.dims.is_empty() {
                    return None;
                }
                self.prog.types.field_type(&t.name, f).map(Type::named)
            }
            Expr::Index(b, ix) => {
                let t = self.type_of(b)?;
                (t.dims.len() >= ix.len()).then(|| {
                    Type::array(
                        t.name.clone(),
                        t.dims.iter().skip(ix.len()).copied().collect(),
                    )
                })
            }
            _ => None,
        }
    }
}

/// An argument in the form both call kinds share.
struct ArgIr<'a> {
    name: Option<&'a str>,
    value: IrArg,
}

fn ir_args(args: &[body::CallArg]) -> Vec<ArgIr<'_>> {
    args.iter()
        .map(|a| ArgIr {
            name: a.name.as_deref(),
            value: a.value.clone(),
        })
        .collect()
}

/// The parameter an argument binds to: a named one by its name, a
/// positional one to the first required parameter after the last one
/// bound by position (`next`, moved on). `params` gives each parameter's
/// name and whether it is optional.
pub(crate) fn bind_index<'a>(
    mut params: impl Iterator<Item = (&'a str, bool)>,
    name: Option<&str>,
    next: &mut usize,
) -> Option<usize> {
    match name {
        Some(n) => params.position(|(p, _)| p.eq_ignore_ascii_case(n)),
        None => {
            let (i, _) = params
                .enumerate()
                .skip(*next)
                .find(|(_, (_, optional))| !optional)?;
            *next = i + 1;
            Some(i)
        }
    }
}

/// The type an argument of a built-in's parameter is computed as (none
/// for switches and `anytype`).
fn catalogue_type(p: &catalogue::Param) -> Option<Type> {
    (!p.switch && !p.ty.eq_ignore_ascii_case("anytype"))
        .then(|| Type::array(p.ty.clone(), vec![0; usize::from(p.array)]))
}

/// Is a parameter of this mode passed by reference?
pub(crate) fn by_reference(mode: Mode) -> bool {
    matches!(mode, Mode::Var | Mode::Pers | Mode::InOut | Mode::Ref)
}
