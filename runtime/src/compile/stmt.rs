//! Statements: control flow becomes jumps; loops keep their state in
//! hidden slots, so that every statement starts with empty operand
//! stacks (an error handler, `RETRY` and `TRYNEXT` go back to a statement
//! boundary).

use rapid_analyzer::body::{self, Callee as IrCallee, StmtKind as S};
use rapid_analyzer::names::fold;
use rapid_analyzer::resolve::{Callee, DataRef};
use rapid_analyzer::ty::Ty;

use super::Compiler;
use crate::code::*;

/// The labels of a section (the body, or a handler) and the `GOTO`s to
/// patch when it ends.
#[derive(Default)]
pub(super) struct Labels {
    /// The labels declared directly in each statement list around the
    /// place compiled, innermost last (folded).
    scopes: Vec<Vec<String>>,
    /// Every label of the section: its folded name and where it leads.
    targets: Vec<(String, Pc)>,
    /// Jumps to patch: the operation and the label.
    gotos: Vec<(usize, String)>,
    /// Every label of the section, to tell a missing label from one
    /// outside the lists around a `GOTO`.
    all: Vec<String>,
}

impl Compiler<'_> {
    /// A section of the routine (its body, or a handler): its statements,
    /// with `GOTO`s patched to labels of the section.
    pub(super) fn section(&mut self, list: &[body::Stmt]) {
        let mut all = Vec::new();
        body::walk_list(list, &mut |s| {
            if let S::Label(name) = &s.kind {
                all.push(fold(name));
            }
        });
        let saved = std::mem::replace(
            &mut self.labels,
            Labels {
                all,
                ..Labels::default()
            },
        );
        self.list(list);
        let labels = std::mem::replace(&mut self.labels, saved);
        for (at, name) in labels.gotos {
            let target = labels
                .targets
                .iter()
                .find(|(n, _)| *n == name)
                .map(|(_, pc)| *pc);
            if let (Some(pc), Some(op)) = (target, self.code.ops.get_mut(at)) {
                *op = Op::Jump(pc);
            }
        }
    }

    fn list(&mut self, list: &[body::Stmt]) {
        let here = list
            .iter()
            .filter_map(|s| match &s.kind {
                S::Label(name) => Some(fold(name)),
                _ => None,
            })
            .collect();
        self.labels.scopes.push(here);
        for s in list {
            self.stmt(s);
        }
        self.labels.scopes.pop();
    }

    fn stmt(&mut self, s: &body::Stmt) {
        let i = self.new_stmt(s.range.clone());
        self.emit(Op::Stmt(i));
        match &s.kind {
            S::Assign { target, value } => self.assign(target, value),
            S::Call(call) => self.call_stmt(call),
            S::If {
                branches,
                otherwise,
                ..
            } => {
                let mut ends = Vec::new();
                for b in branches {
                    self.condition(&b.cond);
                    let skip = self.emit(Op::JumpIfFalse(0));
                    self.list(&b.body);
                    ends.push(self.emit(Op::Jump(0)));
                    self.patch(skip);
                }
                if let Some(o) = otherwise {
                    self.list(o);
                }
                for e in ends {
                    self.patch(e);
                }
            }
            S::For {
                var,
                var_range,
                from,
                to,
                step,
                body,
            } => {
                let num = Ty::num();
                self.expr(from, Some(&num));
                self.expr(to, Some(&num));
                if let Some(st) = step {
                    self.expr(st, Some(&num));
                }
                let state = self.hidden();
                self.hidden();
                self.hidden();
                self.emit(Op::ForStart {
                    state,
                    step: step.is_some(),
                });
                let var_slot = self.add_slot(var, &num, SlotKind::For);
                let check = self.pc();
                let exit = self.emit(Op::ForCheck {
                    var: var_slot,
                    state,
                    exit: 0,
                });
                self.names.enter_for(var, var_range.clone());
                self.for_slots.push((var_range.clone(), var_slot));
                self.list(body);
                self.for_slots.pop();
                self.names.leave_for();
                self.emit(Op::ForNext { state, check });
                let end = self.pc();
                self.code.for_loops.push(ForLoop {
                    name: var.clone(),
                    var_range: var_range.clone(),
                    slot: var_slot,
                    start: check,
                    end,
                });
                if let Some(Op::ForCheck { exit, .. }) = self.code.ops.get_mut(exit) {
                    *exit = end;
                }
            }
            S::While { cond, body } => {
                let head = self.pc();
                self.condition(cond);
                let out = self.emit(Op::JumpIfFalse(0));
                self.list(body);
                self.emit(Op::Tick);
                self.emit(Op::Mark(i));
                self.emit(Op::Jump(head));
                self.patch(out);
            }
            S::Test {
                value,
                cases,
                default,
            } => {
                let h = self.hidden();
                self.expr(value, None);
                self.emit(Op::SetHidden(h));
                let mut bodies = Vec::new();
                for c in cases {
                    let mut hits = Vec::new();
                    for v in &c.values {
                        self.emit(Op::Local(h));
                        self.expr(v, None);
                        self.emit(Op::Binary(rapid_evaluator::BinOp::Eq));
                        hits.push(self.emit(Op::JumpIfTrue(0)));
                    }
                    bodies.push((hits, &c.body));
                }
                let to_default = self.emit(Op::Jump(0));
                let mut ends = Vec::new();
                for (hits, body) in bodies {
                    for h in hits {
                        self.patch(h);
                    }
                    self.list(body);
                    ends.push(self.emit(Op::Jump(0)));
                }
                self.patch(to_default);
                if let Some(d) = default {
                    self.list(d);
                }
                for e in ends {
                    self.patch(e);
                }
            }
            S::Label(name) => {
                let pc = self.pc();
                self.labels.targets.push((fold(name), pc));
            }
            S::Goto(name) => {
                let key = fold(name);
                if self.labels.scopes.iter().any(|s| s.contains(&key)) {
                    let at = self.emit(Op::Jump(0));
                    self.labels.gotos.push((at, key));
                } else if self.labels.all.contains(&key) {
                    self.fail(Failure::Invalid(
                        "GOTO to a label outside the statement lists around it".to_owned(),
                    ));
                } else {
                    self.fail(Failure::Invalid(format!(
                        "GOTO {name}: the routine has no label {name}"
                    )));
                }
            }
            S::Return(v) => {
                if let Some(e) = v {
                    let returns = self.returns.clone();
                    self.expr(e, returns.as_ref());
                }
                self.emit(Op::Return { value: v.is_some() });
            }
            S::Raise(v) => {
                if let Some(e) = v {
                    self.expr(e, Some(&Ty::num()));
                }
                self.emit(Op::Raise { value: v.is_some() });
            }
            S::Exit => {
                self.emit(Op::Exit);
            }
            S::Retry => {
                self.emit(Op::Retry);
            }
            S::TryNext => {
                self.emit(Op::TryNext);
            }
            S::Connect {
                interrupt, trap, ..
            } => match self.names.routine(trap, false) {
                Some(Callee::Routine(item)) => match self.prog.routine_ids.get(&item) {
                    Some(&id) => {
                        if self.place(interrupt).is_some() {
                            self.emit(Op::Connect(id));
                        }
                    }
                    None => self.fail(Failure::Unknown(trap.clone())),
                },
                _ => self.fail(Failure::Unknown(trap.clone())),
            },
            S::Invalid => self.fail(Failure::Invalid(
                "a placeholder or a statement with a syntax error".to_owned(),
            )),
        }
        let end = self.pc();
        if let Some(info) = self.code.stmts.get_mut(i as usize) {
            info.end = end;
        }
    }

    /// Points the jump at `at` to here.
    fn patch(&mut self, at: usize) {
        let here = self.pc();
        if let Some(Op::Jump(t) | Op::JumpIfFalse(t) | Op::JumpIfTrue(t)) =
            self.code.ops.get_mut(at)
        {
            *t = here;
        }
    }

    fn condition(&mut self, e: &rapid_evaluator::Expr) {
        self.expr(e, Some(&Ty::bool()));
    }

    fn assign(&mut self, target: &rapid_evaluator::Expr, value: &rapid_evaluator::Expr) {
        let Some(ty) = self.place_type(target) else {
            let why = self
                .unknown_in(target)
                .map(Failure::UnknownData)
                .unwrap_or_else(|| {
                    Failure::Invalid("the left side of := is not a data reference".to_owned())
                });
            self.fail(why);
            // Never run: the calls in it bound all the same.
            self.expr(value, None);
            return;
        };
        self.expr(value, ty.as_ref());
        if let Some(c) = ty.as_ref().and_then(|t| self.conv(t)) {
            self.emit(Op::Convert(c));
        }
        match self.store_op(target) {
            Some(op) => {
                self.emit(op);
            }
            None => {
                self.place(target);
                self.emit(Op::Store);
            }
        }
    }

    /// The first name of a data reference that nothing declares.
    fn unknown_in(&self, e: &rapid_evaluator::Expr) -> Option<String> {
        use rapid_evaluator::Expr as E;
        match e {
            E::Name(n) => self.names.data(n).is_none().then(|| n.clone()),
            E::Component(b, _) | E::Index(b, _) => self.unknown_in(b),
            _ => None,
        }
    }

    fn call_stmt(&mut self, call: &body::Call) {
        let name = match &call.callee {
            IrCallee::Late(e) => {
                self.expr(e, Some(&Ty::string()));
                self.late_args(&call.args, false);
                return;
            }
            IrCallee::Name(n) => n,
        };
        match self.names.routine(name, false) {
            // A procedure no module declares yet: a module the program
            // loads (`Load`) may bring it before the call is reached.
            None => {
                self.push_const(rapid_evaluator::Value::Str(name.clone()));
                self.late_args(&call.args, true);
            }
            Some(callee) => self.procedure_call(name, callee, &call.args),
        }
    }

    /// The parameter slot a conditional argument `?name` passes on.
    pub(super) fn param_slot(&self, name: &str) -> Option<u32> {
        match self.names.data(name)?.what {
            DataRef::Param(i) => Some(i as u32),
            _ => None,
        }
    }
}
