//! Statements, calls and error recovery.
//!
//! The interpreter walks the compiled statements recursively. An error
//! (a [`Fault`]) is recovered at the innermost statement list of the frame
//! it reaches: the routine's `ERROR` handler runs there, on top of the
//! loops and branches around the statement, so that `RETRY` runs the
//! statement again and `TRYNEXT` goes on with the one after it, inside the
//! same loop. A fault the frame does not take leaves the routine (running
//! its `UNDO` handler) and reaches the call statement in the caller.

use std::sync::Arc;

use rapid_analyzer::items::RoutineKind;
use rapid_evaluator::{BinOp, Value};

use crate::code::{Arg, ArgValue, Routine, Stmt, StmtKind};
use crate::compile::{bind_index, by_reference};
use crate::machine::{
    Fault, FaultKind, Frame, Machine, Place, R, Slot, Status, fault, invalid, named_error,
};

/// How a statement list goes on.
pub(crate) enum Flow {
    Next,
    Goto(u32),
    Return(Option<Value>),
    Retry,
    TryNext,
}

/// What an error handler decided.
enum Recovery {
    Retry,
    Next,
    Return(Option<Value>),
}

impl Machine {
    /// Binds `args` (in the caller's frame) and calls routine `id`.
    pub(crate) fn invoke(&mut self, id: u32, args: &[Arg]) -> R<Option<Value>> {
        let prog = self.prog.clone();
        let Some(r) = prog.routine(id) else {
            return invalid("a call of a routine that does not exist");
        };
        let slots = self.bind(r, args)?;
        self.call_routine(id, slots)
    }

    /// Binds arguments to the parameters of `r`: positional ones to the
    /// required parameters in order, the others by name.
    fn bind(&mut self, r: &Routine, args: &[Arg]) -> R<Vec<Slot>> {
        let mut slots: Vec<Option<Slot>> = r.params.iter().map(|_| None).collect();
        let mut next = 0usize;
        for a in args {
            let named = r.params.iter().map(|p| (p.name.as_str(), p.optional));
            let Some(i) = bind_index(named, a.name.as_deref(), &mut next) else {
                return invalid(match &a.name {
                    Some(n) => format!("{} has no parameter {n}", r.name),
                    None => format!("too many arguments for {}", r.name),
                });
            };
            let p = &r.params[i];
            let slot = match &a.value {
                ArgValue::Switch if p.switch => Slot::Val(Value::Bool(true)),
                ArgValue::Switch => {
                    return invalid(format!("\\{} is not a switch of {}", p.name, r.name));
                }
                ArgValue::Star => return invalid(format!("* is no argument for {}", r.name)),
                ArgValue::Conditional(s) => match self.stack.get(self.base + *s as usize) {
                    None | Some(Slot::Absent) => Slot::Absent,
                    Some(Slot::Ref(place)) if by_reference(p.mode) => Slot::Ref(place.clone()),
                    Some(Slot::Ref(place)) => {
                        let v = self.get(place).cloned().unwrap_or(Value::Bool(true));
                        Slot::Val(self.convert(v, &p.conv)?)
                    }
                    Some(Slot::Val(v)) if by_reference(p.mode) && !p.switch => {
                        let _ = v;
                        Slot::Ref(Place {
                            root: crate::machine::Root::Stack((self.base + *s as usize) as u32),
                            path: Vec::new(),
                        })
                    }
                    Some(Slot::Val(v)) => {
                        let v = v.clone();
                        Slot::Val(self.convert(v, &p.conv)?)
                    }
                },
                ArgValue::Expr(e) if by_reference(p.mode) && e.is_place() => {
                    Slot::Ref(self.place(e)?)
                }
                ArgValue::Expr(e) => {
                    let v = self.eval(e)?;
                    Slot::Val(self.convert(v, &p.conv)?)
                }
            };
            slots[i] = Some(slot);
        }
        let mut out = Vec::with_capacity(slots.len());
        for (p, s) in r.params.iter().zip(slots) {
            match s {
                Some(s) => out.push(s),
                None if p.optional => out.push(Slot::Absent),
                None => {
                    return invalid(format!("the argument {} of {} is missing", p.name, r.name));
                }
            }
        }
        Ok(out)
    }

    /// Calls routine `id` with its parameters bound.
    pub(crate) fn call_routine(&mut self, id: u32, params: Vec<Slot>) -> R<Option<Value>> {
        let prog = self.prog.clone();
        let Some(r) = prog.routine(id).cloned() else {
            return invalid("a call of a routine that does not exist");
        };
        if self.frames.len() >= self.config.limits.max_depth as usize {
            return fault(FaultKind::Budget(format!(
                "the call depth limit ({}) was reached in {} (unbounded recursion?)",
                self.config.limits.max_depth, r.name
            )));
        }
        let base = self.stack.len();
        self.stack.extend(params);
        self.stack
            .resize(base + r.slots.len(), Slot::Val(Value::Num(0.0)));
        let saved = self.base;
        self.base = base;
        self.frames.push(Frame {
            routine: r.clone(),
            base: base as u32,
            at: r.range.start,
            in_handler: false,
        });
        let result = self.run_frame(&r);
        let result = match result {
            Err(mut f) => {
                if f.trace.is_none() {
                    f.trace = self.here().map(|at| (at, self.stack_frames()));
                }
                if r.kind == RoutineKind::Trap {
                    // An error that leaves a trap routine stops the program.
                    f.fatal = true;
                }
                if !matches!(f.kind, FaultKind::Halt(_))
                    && let Some(undo) = &r.undo
                {
                    // The UNDO handler runs as the routine is left; its own
                    // errors are not recovered.
                    let _ = self.exec_list(undo);
                }
                Err(f)
            }
            ok => ok,
        };
        self.frames.pop();
        self.stack.truncate(base);
        self.base = saved;
        result
    }

    fn run_frame(&mut self, r: &Arc<Routine>) -> R<Option<Value>> {
        for d in &r.data {
            if let Some(f) = self.frames.last_mut() {
                f.at = d.range.start;
            }
            let v = self.start_value(&d.ty_name, &d.dims, d.init.as_ref(), &d.conv)?;
            if let Some(slot) = self.stack.get_mut(self.base + d.slot as usize) {
                *slot = Slot::Val(v);
            }
        }
        let value = match self.exec_list(&r.body)? {
            Flow::Next => None,
            Flow::Return(v) => v,
            Flow::Goto(_) => {
                return invalid("GOTO to a label outside the statement lists around it");
            }
            Flow::Retry | Flow::TryNext => {
                return invalid("RETRY and TRYNEXT belong in an error handler");
            }
        };
        match (r.kind, value) {
            (RoutineKind::Func, None) => {
                if let Some(f) = self.frames.last_mut() {
                    f.at = r.range.end.saturating_sub(1);
                }
                fault(named_error(
                    &self.prog,
                    "ERR_FNCNORET",
                    format!("the function {} ended without RETURN", r.name),
                ))
            }
            (RoutineKind::Func, Some(v)) => self.convert(v, &r.returns_conv).map(Some),
            _ => Ok(None),
        }
    }

    /// Runs a statement list.
    pub(crate) fn exec_list(&mut self, list: &[Stmt]) -> R<Flow> {
        let mut i = 0;
        // RETRYs of the statement at `i` in a row.
        let mut retries = 0u32;
        while let Some(s) = list.get(i) {
            self.before(s)?;
            match self.exec(s) {
                Ok(Flow::Next) => {
                    i += 1;
                    retries = 0;
                }
                Ok(Flow::Goto(label)) => {
                    match list
                        .iter()
                        .position(|s| matches!(s.kind, StmtKind::Label(l) if l == label))
                    {
                        Some(j) => i = j + 1,
                        None => return Ok(Flow::Goto(label)),
                    }
                }
                Ok(flow) => return Ok(flow),
                Err(f) => match self.recover(f)? {
                    Recovery::Retry => {
                        retries += 1;
                        let max = self.config.limits.max_retries;
                        if retries > max {
                            if let Some(f) = self.frames.last_mut() {
                                f.at = s.range.start;
                            }
                            let mut g = Box::new(Fault {
                                kind: named_error(
                                    &self.prog,
                                    "ERR_EXCRTYMAX",
                                    format!("RETRY was used more than {max} times in a row"),
                                ),
                                skip_depth: None,
                                fatal: true,
                                trace: None,
                                reported: false,
                            });
                            g.trace = self.here().map(|at| (at, self.stack_frames()));
                            return Err(g);
                        }
                    }
                    Recovery::Next => {
                        i += 1;
                        retries = 0;
                    }
                    Recovery::Return(v) => return Ok(Flow::Return(v)),
                },
            }
        }
        Ok(Flow::Next)
    }

    /// Before each statement: the budget, interrupts, the debugger.
    #[inline]
    fn before(&mut self, s: &Stmt) -> R<()> {
        self.steps += 1;
        if let Some(f) = self.frames.last_mut() {
            f.at = s.range.start;
        }
        if self.steps > self.config.limits.max_steps {
            return fault(FaultKind::Budget(format!(
                "the step budget ({} statements) ran out",
                self.config.limits.max_steps
            )));
        }
        if self.ctl.has_pending_interrupt() && !self.in_trap {
            self.run_traps()?;
        }
        if self.debugger.is_some() {
            self.debug_statement()?;
        }
        Ok(())
    }

    /// Offers a fault to the innermost frame's error handler.
    fn recover(&mut self, mut f: Box<Fault>) -> R<Recovery> {
        if f.trace.is_none() {
            f.trace = self.here().map(|at| (at, self.stack_frames()));
        }
        let depth = self.frames.len();
        let errno = match &f.kind {
            FaultKind::Rapid { errno, .. } => Some(*errno),
            FaultKind::Halt(_) => return Err(f),
            _ => None,
        };
        if !f.reported && self.debugger.is_some() && errno.is_none_or(|e| !self.will_recover(&f, e))
        {
            f.reported = true;
            let outcome = self.outcome_of(Fault {
                kind: clone_kind(&f.kind),
                skip_depth: None,
                fatal: false,
                trace: f.trace.clone(),
                reported: true,
            });
            self.debug_error(&outcome);
        }
        let Some(errno) = errno else {
            return Err(f);
        };
        if f.fatal || f.skip_depth == Some(depth) {
            return Err(f);
        }
        let Some(frame) = self.frames.last() else {
            return Err(f);
        };
        if frame.in_handler {
            // Errors inside an error handler are not recovered.
            f.fatal = true;
            return Err(f);
        }
        let r = frame.routine.clone();
        let Some(h) = &r.error else {
            return Err(f);
        };
        if !h.errors.is_empty() && !self.handler_takes(&r, errno)? {
            return Err(f);
        }
        self.set_errno(errno);
        self.set_in_handler(true);
        let flow = self.exec_list(&h.body);
        self.set_in_handler(false);
        match flow {
            Ok(Flow::Retry) => Ok(Recovery::Retry),
            Ok(Flow::TryNext) => Ok(Recovery::Next),
            Ok(Flow::Return(v)) => Ok(Recovery::Return(v)),
            Ok(Flow::Next) => Ok(Recovery::Return(None)),
            Ok(Flow::Goto(_)) => invalid("GOTO out of an error handler"),
            Err(mut g) => {
                if g.skip_depth != Some(depth) {
                    g.fatal = true;
                }
                Err(g)
            }
        }
    }

    fn set_in_handler(&mut self, on: bool) {
        if let Some(f) = self.frames.last_mut() {
            f.in_handler = on;
        }
    }

    /// Does the `ERROR (...)` list of `r` name `errno`?
    fn handler_takes(&mut self, r: &Routine, errno: f32) -> R<bool> {
        let Some(h) = &r.error else {
            return Ok(false);
        };
        for e in &h.errors {
            if self.eval(e)?.as_f64() == Some(f64::from(errno)) {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// Would some frame's handler take this fault? (For debuggers, which
    /// stop on errors that end the run.)
    fn will_recover(&mut self, f: &Fault, errno: f32) -> bool {
        if f.fatal {
            return false;
        }
        for d in (1..=self.frames.len()).rev() {
            let Some(frame) = self.frames.get(d - 1) else {
                return false;
            };
            if f.skip_depth == Some(d) {
                continue;
            }
            if frame.in_handler {
                return false;
            }
            let r = frame.routine.clone();
            if r.error.is_some() && self.handler_takes(&r, errno).unwrap_or(false)
                || r.error.as_ref().is_some_and(|h| h.errors.is_empty())
            {
                return true;
            }
            if r.kind == RoutineKind::Trap {
                return false;
            }
        }
        false
    }

    pub(crate) fn set_errno(&mut self, errno: f32) {
        if let Some(g) = self.prog.errno
            && let Some(v) = self.globals.get_mut(g as usize)
        {
            *v = Value::Num(errno);
        }
    }

    fn exec(&mut self, s: &Stmt) -> R<Flow> {
        match &s.kind {
            StmtKind::Assign {
                target,
                value,
                conv,
            } => {
                let v = self.eval(value)?;
                let v = self.convert(v, conv)?;
                let p = self.place(target)?;
                self.store(&p, v)?;
            }
            StmtKind::Call { routine, args } => {
                self.invoke(*routine, args)?;
            }
            StmtKind::Late { name, args } => {
                let v = self.eval(name)?;
                let Value::Str(n) = v else {
                    return invalid("a late-bound call needs a string");
                };
                self.call_by_name(&n, args)?;
            }
            StmtKind::Builtin { name, f, args } => {
                let a = crate::builtins::Args::new(name, args);
                f(self, &a)?;
            }
            StmtKind::If {
                branches,
                otherwise,
            } => {
                for (cond, body) in branches {
                    if self.truth(cond)? {
                        return self.exec_list(body);
                    }
                }
                return self.exec_list(otherwise);
            }
            StmtKind::For {
                slot,
                from,
                to,
                step,
                body,
            } => return self.exec_for(*slot, from, to, step.as_ref(), body),
            StmtKind::While { cond, body } => {
                while self.truth(cond)? {
                    match self.exec_list(body)? {
                        Flow::Next => {}
                        other => return Ok(other),
                    }
                    self.tick()?;
                }
            }
            StmtKind::Test {
                value,
                cases,
                default,
            } => {
                let v = self.eval(value)?;
                let v = self.scalar(v)?;
                for (values, body) in cases {
                    for c in values {
                        let c = self.eval(c)?;
                        let c = self.scalar(c)?;
                        let env = crate::types::TypesEnv(&self.prog.types);
                        let eq = rapid_evaluator::apply_binary(BinOp::Eq, v.clone(), c, &env);
                        match eq {
                            Ok(Value::Bool(true)) => return self.exec_list(body),
                            Ok(_) => {}
                            Err(e) => return self.eval_error(e),
                        }
                    }
                }
                return self.exec_list(default);
            }
            StmtKind::Label(_) => {}
            StmtKind::Goto(l) => return Ok(Flow::Goto(*l)),
            StmtKind::Return(v) => {
                let v = match v {
                    Some(e) => Some(self.eval(e)?),
                    None => None,
                };
                return Ok(Flow::Return(v));
            }
            StmtKind::Raise(v) => return self.raise(v.as_ref()),
            StmtKind::Exit => return fault(FaultKind::Halt(Status::Exited)),
            StmtKind::Retry => return self.handler_only(Flow::Retry, "RETRY"),
            StmtKind::TryNext => return self.handler_only(Flow::TryNext, "TRYNEXT"),
            StmtKind::Connect { target, trap } => self.connect(target, *trap)?,
            StmtKind::Fail(f) => return self.failure(f),
        }
        Ok(Flow::Next)
    }

    /// Counts a loop iteration that runs no statement against the budget.
    #[inline]
    fn tick(&mut self) -> R<()> {
        self.steps += 1;
        if self.steps > self.config.limits.max_steps {
            return fault(FaultKind::Budget(format!(
                "the step budget ({} statements) ran out",
                self.config.limits.max_steps
            )));
        }
        Ok(())
    }

    fn handler_only(&self, flow: Flow, what: &str) -> R<Flow> {
        if self.frames.last().is_some_and(|f| f.in_handler) {
            Ok(flow)
        } else {
            invalid(format!("{what} outside an error handler"))
        }
    }

    fn exec_for(
        &mut self,
        slot: u32,
        from: &crate::code::Expr,
        to: &crate::code::Expr,
        step: Option<&crate::code::Expr>,
        body: &[Stmt],
    ) -> R<Flow> {
        let num = |m: &mut Machine, e: &crate::code::Expr, what: &str| -> R<f32> {
            let v = m.eval(e)?;
            match m.scalar(v)? {
                Value::Num(x) => Ok(x),
                Value::Dnum(x) => Ok(x as f32),
                other => invalid(format!(
                    "the {what} of a FOR loop is {}, not a num",
                    crate::machine::describe(&other)
                )),
            }
        };
        let start = num(self, from, "start")?;
        let end = num(self, to, "end")?;
        let step = match step {
            Some(e) => num(self, e, "step")?,
            None if start <= end => 1.0,
            None => -1.0,
        };
        if step == 0.0 {
            return invalid("the STEP of a FOR loop is zero");
        }
        let mut i = start;
        let idx = self.base + slot as usize;
        while (step > 0.0 && i <= end) || (step < 0.0 && i >= end) {
            if let Some(s) = self.stack.get_mut(idx) {
                *s = Slot::Val(Value::Num(i));
            }
            match self.exec_list(body)? {
                Flow::Next => {}
                other => return Ok(other),
            }
            self.tick()?;
            i += step;
        }
        Ok(Flow::Next)
    }

    fn raise(&mut self, v: Option<&crate::code::Expr>) -> R<Flow> {
        let in_handler = self.frames.last().is_some_and(|f| f.in_handler);
        let errno = match v {
            Some(e) => {
                let v = self.eval(e)?;
                match self.scalar(v)?.as_f64() {
                    Some(x) => x as f32,
                    None => return invalid("RAISE needs an error number"),
                }
            }
            None if in_handler => self
                .prog
                .errno
                .and_then(|g| self.globals.get(g as usize))
                .and_then(Value::as_f64)
                .unwrap_or(0.0) as f32,
            None => return invalid("RAISE without an error number belongs in an error handler"),
        };
        let user = (1.0..=90.0).contains(&errno) && errno.fract() == 0.0;
        let booked = self.booked.iter().any(|(b, _)| *b == errno);
        let system = self.prog.errnum_name(errno).is_some();
        let kind = if user || booked || system {
            FaultKind::Rapid {
                errno,
                name: self.errno_name(errno),
                message: "raised by RAISE".to_owned(),
            }
        } else {
            named_error(
                &self.prog,
                "ERR_ILLRAISE",
                format!("RAISE {errno}: the error number is outside 1 to 90 and not booked"),
            )
        };
        let depth = self.frames.len();
        Err(Box::new(Fault {
            kind,
            // Raised from an error handler: the caller's handler takes it.
            skip_depth: in_handler.then_some(depth),
            fatal: false,
            trace: None,
            reported: false,
        }))
    }

    /// `CONNECT intno WITH trap`.
    fn connect(&mut self, target: &crate::code::Expr, trap: u32) -> R<()> {
        let p = self.place(target)?;
        let current = self.get(&p).and_then(Value::as_f64).unwrap_or(0.0);
        if current != 0.0 && self.ctl.interrupts.is_connected(current as i32) {
            return fault(named_error(
                &self.prog,
                "ERR_ALRDYCNT",
                "the interrupt variable is already connected to a trap routine".to_owned(),
            ));
        }
        let id = self.ctl.interrupts.connect(trap);
        self.store(&p, Value::Num(id as f32))
    }

    /// Calls a procedure by its name, as late binding and `CallByVar` do.
    pub(crate) fn call_by_name(&mut self, name: &str, args: &[Arg]) -> R<()> {
        let module = self
            .frames
            .last()
            .and_then(|f| self.prog.routines.get(f.routine.id as usize))
            .map_or(usize::MAX, |info| info.module);
        // `Module:Routine` names a routine of that module, LOCAL ones too.
        let id = match name.split_once(':') {
            Some((m, r)) => self
                .prog
                .modules
                .iter()
                .position(|md| md.name.eq_ignore_ascii_case(m.trim()))
                .and_then(|m| self.prog.modules.get(m))
                .and_then(|md| md.routines.get(&r.trim().to_ascii_lowercase()))
                .copied(),
            None => self.prog.routine_from(module, name),
        };
        let Some(id) = id else {
            return fault(named_error(
                &self.prog,
                "ERR_REFUNKPRC",
                format!("there is no procedure {name}"),
            ));
        };
        if self
            .prog
            .routines
            .get(id as usize)
            .is_some_and(|r| r.decl.kind != RoutineKind::Proc)
        {
            return fault(named_error(
                &self.prog,
                "ERR_CALLPROC",
                format!("{name} is not a procedure"),
            ));
        }
        self.invoke(id, args).map(|_| ())
    }
}

fn clone_kind(k: &FaultKind) -> FaultKind {
    match k {
        FaultKind::Rapid {
            errno,
            name,
            message,
        } => FaultKind::Rapid {
            errno: *errno,
            name: name.clone(),
            message: message.clone(),
        },
        FaultKind::Unsupported(s) => FaultKind::Unsupported(s.clone()),
        FaultKind::Invalid(s) => FaultKind::Invalid(s.clone()),
        FaultKind::Budget(s) => FaultKind::Budget(s.clone()),
        FaultKind::Deadlock(s) => FaultKind::Deadlock(s.clone()),
        FaultKind::Halt(s) => FaultKind::Halt(*s),
    }
}
