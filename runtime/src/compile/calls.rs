//! Calls: the routine is `sema`'s answer, the arguments are bound by the
//! one binder ([`rapid_analyzer::catalogue::binding::bind_args`]) with the
//! signature the checker checks (for a built-in, the task's catalogue
//! view), and each argument is compiled for its parameter: a place for a
//! by-reference parameter, a value of the parameter's type otherwise.

use rapid_analyzer::body::{ArgValue as IrArg, CallArg};
use rapid_analyzer::catalogue::binding::{Arg, Binding, Target};
use rapid_analyzer::catalogue::{ANYTYPE, Routine as CatalogueRoutine};
use rapid_analyzer::items::RoutineKind;
use rapid_analyzer::resolve::Callee;
use rapid_analyzer::ty::Ty;
use rapid_evaluator::Expr as E;

use super::Compiler;
use crate::builtins;
use crate::code::*;

/// An argument as both kinds of call give it: its name (as written) and
/// its value.
pub(super) struct Given<'a> {
    pub name: Option<&'a str>,
    pub value: Value<'a>,
}

pub(super) enum Value<'a> {
    Expr(&'a E),
    Switch,
    Conditional(&'a str),
    Star,
    Invalid,
}

/// A parameter as an argument is compiled for it.
struct For {
    by_ref: bool,
    switch: bool,
    ty: Option<Ty>,
    /// A value parameter of the program's routine, in a program that
    /// calls `ArgName`: a data object given for it is passed as its place,
    /// loaded when the routine is entered, so the routine knows the
    /// object's name.
    named: bool,
}

pub(super) fn given_of_call(args: &[CallArg]) -> Vec<Given<'_>> {
    args.iter()
        .map(|a| Given {
            name: a.name.as_deref(),
            value: match &a.value {
                IrArg::Expr(e) => Value::Expr(e),
                IrArg::Switch => Value::Switch,
                IrArg::Conditional(n) => Value::Conditional(n),
                IrArg::Star => Value::Star,
                IrArg::Invalid => Value::Invalid,
            },
        })
        .collect()
}

fn given_of_function(args: &[rapid_evaluator::Arg]) -> Vec<Given<'_>> {
    args.iter()
        .map(|a| Given {
            name: a.name.as_deref(),
            value: match &a.value {
                None => Value::Switch,
                Some(E::Conditional(n)) => Value::Conditional(n),
                Some(e) => Value::Expr(e),
            },
        })
        .collect()
}

fn shapes<'a>(given: &'a [Given<'_>]) -> Vec<Arg<'a>> {
    given
        .iter()
        .map(|g| match g.name {
            Some(n) => Arg::Named(n),
            None => Arg::Positional,
        })
        .collect()
}

impl Compiler<'_> {
    /// `name args;` where `name` is `callee`.
    pub(super) fn procedure_call(&mut self, name: &str, callee: Callee, args: &[CallArg]) {
        let given = given_of_call(args);
        match callee {
            Callee::Routine(item) => {
                let Some(&id) = self.prog.routine_ids.get(&item) else {
                    return self.fail_call(Failure::Unknown(name.to_owned()), &given);
                };
                let kind = self.prog.routines.get(id as usize).map(|r| r.decl.kind);
                if kind != Some(RoutineKind::Proc) {
                    return self.fail_call(
                        Failure::Invalid(format!("{name} is not a procedure")),
                        &given,
                    );
                }
                self.user_call(id, callee, &given);
            }
            Callee::Builtin(r) => {
                if r.is_function() {
                    return self.fail_call(
                        Failure::Invalid(format!("{} is a function, not an instruction", r.name)),
                        &given,
                    );
                }
                if r.name.eq_ignore_ascii_case("WaitUntil") {
                    return self.wait_until(callee, r, &given);
                }
                match builtins::instruction(&r.name) {
                    Some((canonical, f)) => {
                        self.builtin_call(canonical, callee, r, &given, BuiltinFn::Instruction(f))
                    }
                    None => {
                        // Bound all the same: its binding is the checker's.
                        if self.binding(callee, &r.name, &given).is_some() {
                            self.fail_call(Failure::Unsupported(r.name.clone()), &given);
                        }
                    }
                }
            }
        }
    }

    /// A function call in an expression: its value on the stack.
    pub(super) fn function_call(&mut self, name: &str, args: &[rapid_evaluator::Arg]) {
        if name.eq_ignore_ascii_case("present")
            && let [a] = args
            && let Some(E::Name(p)) = &a.value
            && self
                .names
                .routine(name, true)
                .is_some_and(|c| matches!(c, Callee::Builtin(_)))
        {
            match self.param_slot(p) {
                Some(slot) => {
                    self.emit(Op::Present(slot));
                }
                None => self.fail(Failure::Invalid(format!(
                    "Present({p}): {p} is not a parameter of the routine"
                ))),
            }
            return;
        }
        let given = given_of_function(args);
        match self.names.routine(name, true) {
            None => self.fail_call(Failure::Unknown(name.to_owned()), &given),
            Some(Callee::Routine(item)) => {
                let Some(&id) = self.prog.routine_ids.get(&item) else {
                    return self.fail_call(Failure::Unknown(name.to_owned()), &given);
                };
                let kind = self.prog.routines.get(id as usize).map(|r| r.decl.kind);
                if kind != Some(RoutineKind::Func) {
                    return self.fail_call(
                        Failure::Invalid(format!("{name} is not a function")),
                        &given,
                    );
                }
                self.user_call(id, Callee::Routine(item), &given);
            }
            Some(callee @ Callee::Builtin(r)) => {
                if !r.is_function() {
                    return self.fail_call(
                        Failure::Invalid(format!("{} is an instruction, not a function", r.name)),
                        &given,
                    );
                }
                if let Some((canonical, f)) = builtins::function(&r.name) {
                    return self.builtin_call(canonical, callee, r, &given, BuiltinFn::Function(f));
                }
                if rapid_evaluator::is_function(&r.name) {
                    return self.pure_call(callee, r, &given);
                }
                if self.binding(callee, &r.name, &given).is_some() {
                    self.fail_call(Failure::Unsupported(r.name.clone()), &given);
                }
            }
        }
    }

    /// A call that cannot run: the failure, then its arguments compiled
    /// all the same (never run), so that the calls in them are bound as the
    /// checker binds them.
    pub(super) fn fail_call(&mut self, why: Failure, given: &[Given<'_>]) {
        self.fail(why);
        for g in given {
            if let Value::Expr(e) = g.value {
                self.expr(e, None);
            }
        }
    }

    /// The binding of a call, or the failure that says why it does not
    /// bind.
    fn binding(&mut self, callee: Callee, name: &str, given: &[Given<'_>]) -> Option<Binding> {
        let Some(b) = self.names.bind(&callee, &shapes(given)) else {
            self.fail_call(Failure::Unsupported(name.to_owned()), given);
            return None;
        };
        if let Some(why) = binding_problem(&b, given, name, |i| self.param_name(callee, i)) {
            // Parameters taken from loaded code may lack one a call uses:
            // the call is not known to be wrong, only not simulated.
            let failure = match callee {
                Callee::Builtin(r) if !r.signature_known => Failure::Unsupported(format!(
                    "{name} as called here ({why}; its parameters are those loaded code calls it with)"
                )),
                _ => Failure::Invalid(why),
            };
            self.fail_call(failure, given);
            return None;
        }
        let params = (0..given.len())
            .filter_map(|k| Some(self.param_name(callee, b.param_of(k)?)))
            .collect();
        let routine = match callee {
            Callee::Builtin(r) => r.name.clone(),
            Callee::Routine(item) => self
                .prog
                .task
                .routine(item)
                .map(|d| d.name.clone())
                .unwrap_or_default(),
        };
        self.code.bindings.push((routine, params));
        Some(b)
    }

    fn param_name(&self, callee: Callee, i: usize) -> String {
        match callee {
            Callee::Builtin(r) => r.params.get(i).map(|p| p.name.clone()),
            Callee::Routine(item) => self
                .prog
                .task
                .routine(item)
                .and_then(|d| d.params.get(i).map(|p| p.name.clone())),
        }
        .unwrap_or_default()
    }

    fn user_call(&mut self, id: u32, callee: Callee, given: &[Given<'_>]) {
        let Some(info) = self.prog.routines.get(id as usize) else {
            return self.fail(Failure::Invalid("a routine that does not exist".to_owned()));
        };
        let name = info.decl.name.clone();
        let params: Vec<For> = info
            .decl
            .params
            .iter()
            .map(|p| For {
                by_ref: by_reference(p.mode),
                named: !by_reference(p.mode) && self.prog.arg_name,
                switch: p.switch,
                ty: Some(
                    p.ty.as_ref()
                        .map_or(Ty::Unknown, |t| Ty::named(&t.name))
                        .array(p.dims),
                ),
            })
            .collect();
        let Some(b) = self.binding(callee, &name, given) else {
            return;
        };
        let Some(bound) = self.args(given, &b, &params, false, &name) else {
            return;
        };
        self.code.calls.push(CallSite {
            routine: id,
            params: bound,
        });
        let site = self.code.calls.len() as u32 - 1;
        self.emit(Op::Call(site));
    }

    fn builtin_call(
        &mut self,
        canonical: &'static str,
        callee: Callee,
        r: &'static CatalogueRoutine,
        given: &[Given<'_>],
        f: BuiltinFn,
    ) {
        let bound = if !r.signature_known && given.is_empty() {
            // No source documents its parameters, and the call gives no
            // argument: there is nothing to bind.
            Vec::new()
        } else {
            let Some(b) = self.binding(callee, &r.name, given) else {
                return;
            };
            let params = catalogue_params(r);
            let Some(bound) = self.args(given, &b, &params, true, &r.name) else {
                return;
            };
            bound
        };
        let names = given
            .iter()
            .map(|g| match g.value {
                Value::Expr(E::Name(n)) => Some(n.as_str().into()),
                _ => None,
            })
            .collect();
        self.code.builtins.push(BuiltinSite {
            name: canonical,
            sig: r,
            params: bound,
            names,
            f,
        });
        let site = self.code.builtins.len() as u32 - 1;
        self.emit(Op::Builtin(site));
    }

    fn pure_call(&mut self, callee: Callee, r: &'static CatalogueRoutine, given: &[Given<'_>]) {
        let Some(b) = self.binding(callee, &r.name, given) else {
            return;
        };
        let params = catalogue_params(r);
        if self.args(given, &b, &params, false, &r.name).is_none() {
            return;
        }
        self.code.pures.push(PureSite {
            name: r.name.as_str().into(),
            args: given.iter().map(|g| g.name.map(Into::into)).collect(),
        });
        let site = self.code.pures.len() as u32 - 1;
        self.emit(Op::Pure(site));
    }

    /// Compiles each argument for its parameter, in the order written;
    /// the parameter index of each. `star`: `*` is an argument.
    fn args(
        &mut self,
        given: &[Given<'_>],
        b: &Binding,
        params: &[For],
        star: bool,
        name: &str,
    ) -> Option<Vec<u32>> {
        let mut out = Vec::with_capacity(given.len());
        let rest = |c: &mut Self, k: usize| {
            for g in given.iter().skip(k + 1) {
                if let Value::Expr(e) = g.value {
                    c.expr(e, None);
                }
            }
        };
        for (k, g) in given.iter().enumerate() {
            let Some(i) = b.param_of(k) else {
                self.fail(Failure::Invalid(format!(
                    "{name}: an argument binds to nothing"
                )));
                return None;
            };
            let p = params.get(i)?;
            match &g.value {
                Value::Switch if p.switch => {
                    self.emit(Op::ArgSwitch);
                }
                Value::Switch => {
                    let n = g.name.unwrap_or_default();
                    self.fail(Failure::Invalid(format!("{name}: \\{n} needs a value")));
                    rest(self, k);
                    return None;
                }
                Value::Star if star => {
                    self.emit(Op::ArgStar);
                }
                Value::Star => {
                    self.fail(Failure::Invalid(format!("* is no argument for {name}")));
                    rest(self, k);
                    return None;
                }
                Value::Conditional(n) => match self.param_slot(n) {
                    Some(slot) => {
                        self.emit(Op::ArgCond {
                            slot,
                            by_ref: p.by_ref && !p.switch,
                        });
                    }
                    None => {
                        self.fail(Failure::Invalid(format!(
                            "?{n}: not a parameter of the routine"
                        )));
                        rest(self, k);
                        return None;
                    }
                },
                Value::Expr(_) if p.switch => {
                    let n = g.name.unwrap_or_default();
                    self.fail(Failure::Invalid(format!(
                        "{name}: \\{n} is a switch and takes no value"
                    )));
                    rest(self, k);
                    return None;
                }
                Value::Expr(e) if (p.by_ref || p.named) && self.is_place(e) => {
                    self.place(e);
                    self.emit(Op::ArgPlace);
                }
                Value::Expr(e) => {
                    self.expr(e, p.ty.as_ref());
                    self.emit(Op::ArgValue);
                }
                Value::Invalid => {
                    self.fail(Failure::Invalid(
                        "a placeholder or broken argument".to_owned(),
                    ));
                    rest(self, k);
                    return None;
                }
            }
            out.push(i as u32);
        }
        Some(out)
    }

    /// The arguments of a late-bound call (`%name% args;`), whose routine is
    /// known only when it runs: data references as places, the rest as
    /// values.
    pub(super) fn late_args(&mut self, args: &[CallArg], linked: bool) {
        let given = given_of_call(args);
        for g in &given {
            match &g.value {
                Value::Expr(e) if self.is_place(e) => {
                    self.place(e);
                    self.emit(Op::ArgPlace);
                }
                Value::Expr(e) => {
                    self.expr(e, None);
                    self.emit(Op::ArgValue);
                }
                Value::Switch => {
                    self.emit(Op::ArgSwitch);
                }
                Value::Conditional(n) => match self.param_slot(n) {
                    Some(slot) => {
                        self.emit(Op::ArgCond { slot, by_ref: true });
                    }
                    None => {
                        return self.fail(Failure::Invalid(format!(
                            "?{n}: not a parameter of the routine"
                        )));
                    }
                },
                Value::Star | Value::Invalid => {
                    return self.fail(Failure::Invalid(
                        "* or a broken argument in a late-bound call".to_owned(),
                    ));
                }
            }
        }
        self.code.lates.push(LateSite {
            args: given.iter().map(|g| g.name.map(Into::into)).collect(),
            linked,
        });
        let site = self.code.lates.len() as u32 - 1;
        self.emit(Op::Late(site));
    }

    /// `WaitUntil Cond [\MaxTime] [\TimeFlag] [\PollRate]`: the options
    /// evaluated once, the condition at every poll.
    fn wait_until(&mut self, callee: Callee, r: &'static CatalogueRoutine, given: &[Given<'_>]) {
        let Some(b) = self.binding(callee, &r.name, given) else {
            return;
        };
        let arg_for = |param: &str| {
            given.iter().enumerate().find_map(|(k, g)| {
                let i = b.param_of(k)?;
                r.params
                    .get(i)
                    .is_some_and(|p| p.name.eq_ignore_ascii_case(param))
                    .then_some(g)
            })
        };
        let (cond, max, flag, poll) = (
            expr_of(arg_for("Cond")),
            expr_of(arg_for("MaxTime")),
            expr_of(arg_for("TimeFlag")),
            expr_of(arg_for("PollRate")),
        );
        let Some(cond) = cond else {
            return self.fail(Failure::Invalid(
                "WaitUntil: the condition is missing".to_owned(),
            ));
        };
        let num = Ty::num();
        if let Some(e) = max {
            self.expr(e, Some(&num));
        }
        if let Some(e) = poll {
            self.expr(e, Some(&num));
        }
        if let Some(e) = flag
            && self.place(e).is_none()
        {
            return;
        }
        let state = self.hidden();
        for _ in 0..3 {
            self.hidden();
        }
        self.code.waits.push(WaitUntil {
            state,
            max_time: max.is_some(),
            poll_rate: poll.is_some(),
            time_flag: flag.is_some(),
        });
        let site = self.code.waits.len() as u32 - 1;
        self.emit(Op::WaitUntilStart(site));
        let again = self.pc();
        self.condition_value(cond);
        self.emit(Op::WaitUntilCheck { site, again });
        // The options the simulation has no use for (what the pendant
        // shows while waiting) are never run, but their calls are bound.
        let used = [Some(cond), max, flag, poll];
        let unused: Vec<&E> = given
            .iter()
            .filter_map(|g| match g.value {
                Value::Expr(e) if !used.iter().any(|u| u.is_some_and(|u| std::ptr::eq(u, e))) => {
                    Some(e)
                }
                _ => None,
            })
            .collect();
        if !unused.is_empty() {
            let over = self.emit(Op::Jump(0));
            for e in unused {
                self.expr(e, None);
            }
            let end = self.pc();
            if let Some(Op::Jump(t)) = self.code.ops.get_mut(over) {
                *t = end;
            }
        }
    }

    fn condition_value(&mut self, e: &E) {
        self.expr(e, Some(&Ty::bool()));
    }
}

/// The expression of an argument, if it is one.
fn expr_of<'a>(g: Option<&Given<'a>>) -> Option<&'a E> {
    match g.map(|g| &g.value) {
        Some(Value::Expr(e)) => Some(*e),
        _ => None,
    }
}

/// The parameters of a built-in as arguments are compiled for them.
fn catalogue_params(r: &CatalogueRoutine) -> Vec<For> {
    r.params
        .iter()
        .map(|p| For {
            by_ref: p.mode.is_some_and(by_reference),
            named: false,
            switch: p.switch,
            ty: (!p.switch && !p.ty.eq_ignore_ascii_case(ANYTYPE))
                .then(|| Ty::named(&p.ty).array(p.array)),
        })
        .collect()
}

/// Why a binding does not make a call (an argument that binds to
/// nothing or twice, a missing argument), in words.
fn binding_problem(
    b: &Binding,
    given: &[Given<'_>],
    routine: &str,
    param: impl Fn(usize) -> String,
) -> Option<String> {
    for (k, a) in b.args.iter().enumerate() {
        match a.target {
            Target::UnknownName => {
                let n = given.get(k).and_then(|g| g.name).unwrap_or_default();
                return Some(format!("{routine} has no parameter {n}"));
            }
            Target::TooMany => return Some(format!("too many arguments for {routine}")),
            Target::Param(i) if a.repeats.is_some() => {
                return Some(format!("the argument {} is given twice", param(i)));
            }
            Target::Param(i) if a.excludes.is_some() => {
                let other = a.excludes.map(&param).unwrap_or_default();
                return Some(format!(
                    "{} and {other} of {routine} exclude each other",
                    param(i)
                ));
            }
            Target::Param(_) => {}
        }
    }
    if let Some(&i) = b.missing.first() {
        return Some(format!("the argument {} of {routine} is missing", param(i)));
    }
    if !b.missing_groups.is_empty() {
        return Some(format!(
            "{routine}: one of a group of alternatives must be given"
        ));
    }
    None
}
