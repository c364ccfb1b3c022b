//! The interpreter loop: runs the innermost frame's operations until a
//! slice of statements is used up, the task waits or ends, or a debugger
//! stops it.

use std::sync::Arc;

use rapid_evaluator::{Expr as E, Options, Value};

use super::data::describe;
use super::{
    ArgVal, Boundary, Fault, FaultKind, FrameKind, Init, Machine, Place, R, Root, Slot, Yield,
    fault, invalid, named_error,
};
use rapid_analyzer::items::Storage;

use crate::code::{BuiltinFn, Code, Conv, Failure, Op, SlotKind, Target};
use crate::controller::Shared;

impl Machine {
    /// Runs the task for at most `statements` statements.
    pub(crate) fn run_slice(&mut self, sh: &mut Shared, statements: u32) -> Yield {
        let mut budget = statements;
        if let Some(f) = self.pending.take()
            && let Some(y) = self.handle(sh, f)
        {
            return y;
        }
        loop {
            if self.frames.is_empty() {
                return Yield::Done;
            }
            let r = match self.check_wait(sh) {
                Ok(super::wait::Blocked::Ready) => self.run_ops(sh, &mut budget),
                Ok(super::wait::Blocked::Waiting) => {
                    if self.interrupt_due(sh) {
                        match self.start_trap(sh) {
                            Ok(true) => continue,
                            Ok(false) => return Yield::Blocked,
                            Err(f) => Err(f),
                        }
                    } else {
                        return Yield::Blocked;
                    }
                }
                Err(f) => Err(f),
            };
            match r {
                Ok(Some(y)) => return y,
                Ok(None) => continue,
                Err(f) => {
                    if let Some(y) = self.handle(sh, f) {
                        return y;
                    }
                }
            }
        }
    }

    /// The operations of the innermost frames, until something ends the
    /// slice.
    fn run_ops(&mut self, sh: &mut Shared, budget: &mut u32) -> R<Option<Yield>> {
        let Some(top) = self.frames.last() else {
            return Ok(Some(Yield::Done));
        };
        let mut code: Arc<Code> = top.code.clone();
        let mut pc = top.pc;
        let mut base = top.base as usize;
        // Saves the program counter and takes the innermost frame again.
        macro_rules! reload {
            () => {{
                match self.frames.last() {
                    // A frame that waits (a trap routine interrupted its
                    // wait) is looked at again first.
                    Some(top) if top.wait.is_some() => return Ok(None),
                    Some(top) => {
                        code = top.code.clone();
                        pc = top.pc;
                        base = top.base as usize;
                    }
                    None => return Ok(Some(Yield::Done)),
                }
            }};
        }
        macro_rules! save {
            () => {
                if let Some(top) = self.frames.last_mut() {
                    top.pc = pc;
                }
            };
        }
        loop {
            let Some(op) = code.ops.get(pc as usize) else {
                return invalid("the program counter left the routine");
            };
            pc += 1;
            match op {
                Op::Stmt(s) => {
                    let s = *s;
                    let phase = self.frames.last().map_or(Boundary::None, |f| f.boundary);
                    if matches!(phase, Boundary::None) {
                        if *budget == 0 {
                            pc -= 1;
                            save!();
                            return Ok(Some(Yield::Slice));
                        }
                        *budget -= 1;
                        if let Some(top) = self.frames.last_mut() {
                            top.stmt = s;
                            if top.retries > 0 {
                                Machine::statement_reached(top, pc - 1);
                            }
                        }
                        sh.steps += 1;
                        if sh.steps > sh.limits.max_steps {
                            return fault(FaultKind::Budget(format!(
                                "the step budget ({} statements) ran out",
                                sh.limits.max_steps
                            )));
                        }
                        let may_interrupt = self.events_seen < sh.events.len()
                            || self.log_seen < sh.event_log.len()
                            || self.interrupts.has_pending()
                            || !self.interrupts.pers.is_empty()
                            || !self.interrupts.rmq.is_empty();
                        if may_interrupt && self.interrupt_due(sh) {
                            pc -= 1;
                            save!();
                            if let Some(top) = self.frames.last_mut() {
                                top.boundary = Boundary::Counted;
                            }
                            if self.start_trap(sh)? {
                                reload!();
                                continue;
                            }
                            pc += 1;
                        }
                    }
                    // A statement a debugger stopped at runs on when it
                    // resumes; any other may stop.
                    if !matches!(phase, Boundary::Stopped)
                        && sh.debug.active
                        && let Some(stop) = sh.debug.stop_at(self, &code, s)
                    {
                        pc -= 1;
                        save!();
                        if let Some(top) = self.frames.last_mut() {
                            top.boundary = Boundary::Stopped;
                        }
                        return Ok(Some(Yield::Stopped(stop)));
                    }
                    if let Some(top) = self.frames.last_mut() {
                        top.boundary = Boundary::None;
                    }
                }
                Op::Mark(s) => {
                    if let Some(top) = self.frames.last_mut() {
                        top.stmt = *s;
                    }
                }
                Op::Tick => {
                    sh.steps += 1;
                    if sh.steps > sh.limits.max_steps {
                        return fault(FaultKind::Budget(format!(
                            "the step budget ({} statements) ran out",
                            sh.limits.max_steps
                        )));
                    }
                }
                Op::Const(c) => {
                    let v = code
                        .consts
                        .get(*c as usize)
                        .cloned()
                        .unwrap_or(Value::Num(0.0));
                    self.vals.push(v);
                }
                Op::Local(i) => {
                    let v = match self.slots.get(base + *i as usize) {
                        Some(Slot::Val(v)) => v.clone(),
                        _ => self.local(sh, base, *i)?,
                    };
                    self.vals.push(v);
                }
                Op::Global(g) => {
                    let g = *g as usize;
                    match self.init.get(g) {
                        Some(Init::Ready) => {
                            let v = self.globals.get(g).cloned().unwrap_or(Value::Num(0.0));
                            self.vals.push(v);
                        }
                        _ => {
                            pc -= 1;
                            save!();
                            self.await_global(sh, Target::Global(g as u32))?;
                            reload!();
                        }
                    }
                }
                Op::Pers(k) => {
                    let i = self.pers_map.get(*k as usize).copied().unwrap_or(u32::MAX) as usize;
                    match sh.pers_init.get(i) {
                        Some(Init::Ready) => {
                            let v = sh.pers.get(i).cloned().unwrap_or(Value::Num(0.0));
                            self.vals.push(v);
                        }
                        _ => {
                            pc -= 1;
                            save!();
                            self.await_global(sh, Target::Pers(*k))?;
                            reload!();
                        }
                    }
                }
                Op::Field(n) => {
                    let v = self.pop()?;
                    let name = code.names.get(*n as usize).map_or("", |n| n);
                    let v = self.field_of(v, name)?;
                    self.vals.push(v);
                }
                Op::Index(n) => {
                    let ix = self.pop_n(*n as usize)?;
                    let v = self.pop()?;
                    let v = self.element_of(sh, v, &ix)?;
                    self.vals.push(v);
                }
                Op::Aggregate { n, ty } => {
                    let items = self.pop_n(*n as usize)?;
                    let v = Value::Array(items);
                    let v = match ty.and_then(|t| code.types.get(t as usize)) {
                        Some(t) => rapid_evaluator::coerce(v, t, &self.prog.types)
                            .or_else(|e| self.eval_error(e))?,
                        None => v,
                    };
                    self.vals.push(v);
                }
                Op::Unary(op) => {
                    let v = self.pop()?;
                    let v = self.scalar(sh, v)?;
                    let v = rapid_evaluator::apply_unary(*op, v).or_else(|e| self.eval_error(e))?;
                    self.vals.push(v);
                }
                Op::Binary(op) => {
                    let b = self.pop()?;
                    let a = self.pop()?;
                    let (a, b) = match (a, b) {
                        (a @ Value::Num(_), b @ Value::Num(_)) => (a, b),
                        (a, b) => (self.scalar(sh, a)?, self.scalar(sh, b)?),
                    };
                    let v = rapid_evaluator::apply_binary(*op, a, b, &self.prog.types)
                        .or_else(|e| self.eval_error(e))?;
                    self.vals.push(v);
                }
                Op::Convert(c) => {
                    let conv = code.convs.get(*c as usize);
                    let fits = matches!(
                        (conv, self.vals.last()),
                        (Some(Conv::Num), Some(Value::Num(_)))
                            | (Some(Conv::Dnum), Some(Value::Dnum(_)))
                            | (None, _)
                    );
                    if !fits && let Some(conv) = conv {
                        let v = self.pop()?;
                        let v = self.convert(sh, v, conv)?;
                        self.vals.push(v);
                    }
                }
                Op::Present(s) => {
                    let given = !matches!(
                        self.slots.get(base + *s as usize),
                        Some(Slot::Absent) | None
                    );
                    self.vals.push(Value::Bool(given));
                }
                Op::PlaceLocal(i) => {
                    let p = self.place_local(base, *i)?;
                    self.places.push(p);
                }
                Op::PlaceGlobal(g) => match self.init.get(*g as usize) {
                    Some(Init::Ready) => self.places.push(Place::root(Root::Global(*g))),
                    _ => {
                        pc -= 1;
                        save!();
                        self.await_global(sh, Target::Global(*g))?;
                        reload!();
                    }
                },
                Op::PlacePers(k) => {
                    let i = self.pers_map.get(*k as usize).copied().unwrap_or(u32::MAX);
                    match sh.pers_init.get(i as usize) {
                        Some(Init::Ready) => self.places.push(Place::root(Root::Pers(i))),
                        _ => {
                            pc -= 1;
                            save!();
                            self.await_global(sh, Target::Pers(*k))?;
                            reload!();
                        }
                    }
                }
                Op::PlaceField(n) => {
                    let p = self.pop_place()?;
                    let name = code.names.get(*n as usize).map_or("", |n| n);
                    let p = self.field_place(sh, p, name)?;
                    self.places.push(p);
                }
                Op::PlaceIndex(n) => {
                    let ix = self.pop_n(*n as usize)?;
                    let p = self.pop_place()?;
                    let p = self.index_place(sh, p, &ix)?;
                    self.places.push(p);
                }
                Op::Load => {
                    let p = self.pop_place()?;
                    let v = self.load(sh, &p)?;
                    self.vals.push(v);
                }
                Op::Store => {
                    let p = self.pop_place()?;
                    let v = self.pop()?;
                    self.store(sh, &p, v)?;
                }
                Op::StoreLocal(i) => {
                    let v = self.pop()?;
                    let plain = code
                        .slots
                        .get(*i as usize)
                        .is_some_and(|s| s.kind != SlotKind::Const);
                    match self.slots.get_mut(base + *i as usize) {
                        Some(Slot::Val(old)) if plain && !matches!(old, Value::Array(_)) => {
                            *old = v;
                        }
                        _ => {
                            let p = self.place_local(base, *i)?;
                            self.store(sh, &p, v)?;
                        }
                    }
                }
                Op::StoreGlobal(g) => {
                    let g = *g;
                    let v = self.pop()?;
                    let ready = matches!(self.init.get(g as usize), Some(Init::Ready));
                    let plain = ready
                        && self
                            .prog
                            .globals
                            .get(g as usize)
                            .is_some_and(|d| d.storage != Storage::Const);
                    match self.globals.get_mut(g as usize) {
                        Some(old) if plain && !matches!(old, Value::Array(_)) => *old = v,
                        _ if !ready => {
                            self.vals.push(v);
                            pc -= 1;
                            save!();
                            self.await_global(sh, Target::Global(g))?;
                            reload!();
                        }
                        _ => self.store(sh, &Place::root(Root::Global(g)), v)?,
                    }
                }
                Op::ArgValue => {
                    let v = self.pop()?;
                    self.args.push(ArgVal::Value(v));
                }
                Op::ArgPlace => {
                    let p = self.pop_place()?;
                    self.args.push(ArgVal::Place(p));
                }
                Op::ArgSwitch => self.args.push(ArgVal::Switch),
                Op::ArgStar => self.args.push(ArgVal::Star),
                Op::ArgCond { slot, by_ref } => {
                    let a = self.conditional_arg(sh, base, *slot, *by_ref)?;
                    self.args.push(a);
                }
                Op::Call(site) => {
                    let Some(c) = code.calls.get(*site as usize) else {
                        return invalid("a call that does not exist");
                    };
                    save!();
                    self.call(sh, c.routine, &c.params)?;
                    reload!();
                }
                Op::Builtin(site) => {
                    let Some(b) = code.builtins.get(*site as usize) else {
                        return invalid("a call that does not exist");
                    };
                    save!();
                    let n = b.params.len();
                    let at = self.args.len().saturating_sub(n);
                    let given = self.args.split_off(at);
                    let mut args =
                        crate::builtins::Args::new(b.name, b.sig, &b.params, &b.names, given);
                    match b.f {
                        BuiltinFn::Function(f) => {
                            let v = f(&mut crate::builtins::Cx { m: self, sh }, &mut args)?;
                            if let Some(w) = self.function_wait.take() {
                                self.block(*w);
                                return Ok(Some(Yield::Blocked));
                            }
                            self.vals.push(v);
                        }
                        BuiltinFn::Instruction(f) => {
                            match f(&mut crate::builtins::Cx { m: self, sh }, &mut args)? {
                                crate::builtins::Done::Next => {}
                                crate::builtins::Done::Wait(w) => {
                                    self.block(*w);
                                    return Ok(Some(Yield::Blocked));
                                }
                                crate::builtins::Done::Call(routine) => {
                                    self.call(sh, routine, &[])?;
                                    reload!();
                                }
                                crate::builtins::Done::Retry => {
                                    self.retry(sh.limits.max_retries)?;
                                    reload!();
                                }
                            }
                        }
                    }
                }
                Op::Pure(site) => {
                    let Some(p) = code.pures.get(*site as usize) else {
                        return invalid("a call that does not exist");
                    };
                    let v = self.pure(sh, &p.name, &p.args)?;
                    self.vals.push(v);
                }
                Op::Late(site) => {
                    let Some(l) = code.lates.get(*site as usize) else {
                        return invalid("a call that does not exist");
                    };
                    let name = match self.vals.pop() {
                        Some(Value::Str(n)) => n,
                        _ => return invalid("a late-bound call needs a string"),
                    };
                    save!();
                    if l.linked && self.prog.routine_named(code.module, &name).is_none() {
                        return invalid(self.prog.undeclared(&name, false));
                    }
                    self.call_by_name(sh, &name, &l.args)?;
                    reload!();
                }
                Op::Return { value } => {
                    let v = if *value { Some(self.pop()?) } else { None };
                    save!();
                    if let Some(y) = self.return_from(sh, v)? {
                        return Ok(Some(y));
                    }
                    reload!();
                }
                Op::EndBody => {
                    save!();
                    if let Some(y) = self.end_of_body(sh)? {
                        return Ok(Some(y));
                    }
                    reload!();
                }
                Op::EndHandler => {
                    save!();
                    if let Some(y) = self.return_from(sh, None)? {
                        return Ok(Some(y));
                    }
                    reload!();
                }
                Op::EndUndo => {
                    let f = self.frames.last_mut().and_then(|f| f.undoing.take());
                    let left = self.pop_frame();
                    let mut f = f.unwrap_or_else(|| {
                        Box::new(Fault {
                            kind: FaultKind::Invalid("an UNDO handler ran without a cause".into()),
                            skip_depth: None,
                            fatal: false,
                            trace: None,
                            reported: false,
                        })
                    });
                    if left.is_some_and(|l| l.kind == FrameKind::Trap) {
                        f.fatal = true;
                    }
                    return Err(f);
                }
                Op::EndInit => {
                    self.pop_frame();
                    reload!();
                }
                Op::Jump(t) => pc = *t,
                Op::JumpIfFalse(t) => {
                    if !self.truth()? {
                        pc = *t;
                    }
                }
                Op::JumpIfTrue(t) => {
                    if self.truth()? {
                        pc = *t;
                    }
                }
                Op::ForStart { state, step } => {
                    let step = if *step {
                        Some(self.for_num(sh, "step")?)
                    } else {
                        None
                    };
                    let end = self.for_num(sh, "end")?;
                    let start = self.for_num(sh, "start")?;
                    let step = match step {
                        Some(s) => s,
                        None if start <= end => 1.0,
                        None => -1.0,
                    };
                    if step == 0.0 {
                        return invalid("the STEP of a FOR loop is zero");
                    }
                    let s = base + *state as usize;
                    for (k, v) in [start, end, step].into_iter().enumerate() {
                        if let Some(slot) = self.slots.get_mut(s + k) {
                            *slot = Slot::Val(Value::Num(v));
                        }
                    }
                }
                Op::ForCheck { var, state, exit } => {
                    let s = base + *state as usize;
                    let get = |m: &Machine, k: usize| match m.slots.get(s + k) {
                        Some(Slot::Val(Value::Num(x))) => *x,
                        _ => 0.0,
                    };
                    let (i, end, step) = (get(self, 0), get(self, 1), get(self, 2));
                    if (step > 0.0 && i <= end) || (step < 0.0 && i >= end) {
                        if let Some(slot) = self.slots.get_mut(base + *var as usize) {
                            *slot = Slot::Val(Value::Num(i));
                        }
                    } else {
                        pc = *exit;
                    }
                }
                Op::ForNext { state, check } => {
                    sh.steps += 1;
                    if sh.steps > sh.limits.max_steps {
                        return fault(FaultKind::Budget(format!(
                            "the step budget ({} statements) ran out",
                            sh.limits.max_steps
                        )));
                    }
                    let s = base + *state as usize;
                    let step = match self.slots.get(s + 2) {
                        Some(Slot::Val(Value::Num(x))) => *x,
                        _ => 1.0,
                    };
                    if let Some(Slot::Val(Value::Num(i))) = self.slots.get_mut(s) {
                        *i += step;
                    }
                    pc = *check;
                }
                Op::SetHidden(h) => {
                    let v = self.pop()?;
                    let v = self.scalar(sh, v)?;
                    if let Some(slot) = self.slots.get_mut(base + *h as usize) {
                        *slot = Slot::Val(v);
                    }
                }
                Op::Raise { value } => {
                    let v = if *value { Some(self.pop()?) } else { None };
                    let v = match v {
                        Some(v) => Some(self.scalar(sh, v)?),
                        None => None,
                    };
                    self.raise(v)?;
                }
                Op::Retry => {
                    self.retry(sh.limits.max_retries)?;
                    reload!();
                }
                Op::TryNext => {
                    self.try_next()?;
                    reload!();
                }
                Op::Exit => return fault(FaultKind::Halt(super::Status::Exited)),
                Op::Connect(trap) => {
                    let p = self.pop_place()?;
                    let current = self.get(sh, &p).and_then(Value::as_f64).unwrap_or(0.0);
                    if current != 0.0 && self.interrupts.is_connected(current as i32) {
                        return fault(named_error(
                            &self.prog,
                            "ERR_ALRDYCNT",
                            "the interrupt variable is already connected to a trap routine"
                                .to_owned(),
                        ));
                    }
                    let id = self.interrupts.connect(*trap);
                    self.store(sh, &p, Value::Num(id as f32))?;
                }
                Op::WaitUntilStart(site) => {
                    let Some(w) = code.waits.get(*site as usize) else {
                        return invalid("a wait that does not exist");
                    };
                    self.wait_until_start(sh, base, w)?;
                }
                Op::WaitUntilCheck { site, again } => {
                    let Some(w) = code.waits.get(*site as usize) else {
                        return invalid("a wait that does not exist");
                    };
                    let holds = self.truth()?;
                    pc_sync(self, pc);
                    if !self.wait_until_check(sh, base, w, holds, *again)? {
                        return Ok(Some(Yield::Blocked));
                    }
                }
                Op::InitLocal { slot, decl } => {
                    let Some(d) = code.decls.get(*decl as usize) else {
                        return invalid("a declaration that does not exist");
                    };
                    let v = self.start_value(sh, d, &code.convs)?;
                    if let Some(s) = self.slots.get_mut(base + *slot as usize) {
                        *s = Slot::Val(v);
                    }
                }
                Op::InitGlobal { decl } => {
                    let Some(d) = code.decls.get(*decl as usize) else {
                        return invalid("a declaration that does not exist");
                    };
                    let v = self.start_value(sh, d, &code.convs)?;
                    match d.target {
                        Target::Global(g) => {
                            if let Some(slot) = self.globals.get_mut(g as usize) {
                                *slot = v;
                            }
                            if let Some(i) = self.init.get_mut(g as usize) {
                                *i = Init::Ready;
                            }
                        }
                        Target::Pers(k) => {
                            if let Some(&i) = self.pers_map.get(k as usize) {
                                let valued =
                                    self.prog.pers.get(k as usize).is_some_and(|p| p.valued);
                                sh.set_persistent(i, v, valued);
                            }
                        }
                        Target::Slot => {}
                    }
                }
                Op::Fail(i) => {
                    return match code.failures.get(*i as usize) {
                        Some(Failure::Unknown(name)) => invalid(self.prog.undeclared(name, false)),
                        Some(Failure::UnknownData(name)) => {
                            invalid(self.prog.undeclared(name, true))
                        }
                        Some(Failure::Unsupported(name)) => {
                            fault(FaultKind::Unsupported(name.clone()))
                        }
                        Some(Failure::Invalid(why)) => invalid(why.clone()),
                        None => invalid("a statement that cannot run"),
                    };
                }
            }
        }
    }

    fn pop(&mut self) -> R<Value> {
        match self.vals.pop() {
            Some(v) => Ok(v),
            None => invalid("the value stack ran empty"),
        }
    }

    fn pop_n(&mut self, n: usize) -> R<Vec<Value>> {
        if self.vals.len() < n {
            return invalid("the value stack ran empty");
        }
        let at = self.vals.len() - n;
        Ok(self.vals.split_off(at))
    }

    fn pop_place(&mut self) -> R<Place> {
        match self.places.pop() {
            Some(p) => Ok(p),
            None => invalid("the place stack ran empty"),
        }
    }

    /// A condition's value.
    fn truth(&mut self) -> R<bool> {
        match self.pop()? {
            Value::Bool(b) => Ok(b),
            other => invalid(format!(
                "a condition must be a bool, not {}",
                describe(&other)
            )),
        }
    }

    /// A number of a `FOR` loop's head.
    fn for_num(&mut self, sh: &Shared, what: &str) -> R<f32> {
        let v = self.pop()?;
        match self.scalar(sh, v)? {
            Value::Num(x) => Ok(x),
            Value::Dnum(x) => Ok(x as f32),
            other => invalid(format!(
                "the {what} of a FOR loop is {}, not a num",
                describe(&other)
            )),
        }
    }

    /// Pushes the frame that computes a data object's starting value, or
    /// the fault of one that cannot start (or refers to itself).
    fn await_global(&mut self, sh: &mut Shared, target: Target) -> R<()> {
        let (state, name, code) = match target {
            Target::Global(g) => {
                let Some(decl) = self.prog.globals.get(g as usize) else {
                    return invalid("a reference to data that does not exist");
                };
                let code = match &decl.start {
                    crate::program::Start::Code(c) => Some(c.clone()),
                    crate::program::Start::Value(v) => {
                        self.globals[g as usize] = v.clone();
                        self.init[g as usize] = Init::Ready;
                        return Ok(());
                    }
                };
                (self.init.get(g as usize).cloned(), decl.name.clone(), code)
            }
            Target::Pers(k) => {
                let i = self.pers_map.get(k as usize).copied().unwrap_or(u32::MAX) as usize;
                let Some(p) = self.prog.pers.get(k as usize) else {
                    return invalid("a reference to data that does not exist");
                };
                (
                    sh.pers_init.get(i).cloned(),
                    p.name.clone(),
                    p.start.clone(),
                )
            }
            Target::Slot => return invalid("a reference to data that does not exist"),
        };
        match state {
            Some(Init::Failed(why)) => invalid(why),
            Some(Init::Busy) => invalid(format!("the initial value of {name} refers to itself")),
            Some(Init::Ready) => Ok(()),
            Some(Init::Pending) | None => match code {
                Some(code) => {
                    self.begin_init(sh, code, target);
                    Ok(())
                }
                None => invalid(format!("{name} has no starting value")),
            },
        }
    }

    /// A pure function, computed by the evaluator on the argument values
    /// (bound again there by the same binder, by the names written).
    fn pure(&mut self, sh: &Shared, name: &str, names: &[Option<Box<str>>]) -> R<Value> {
        let at = self.args.len().saturating_sub(names.len());
        let given = self.args.split_off(at);
        let mut out = Vec::with_capacity(given.len());
        for (a, n) in given.into_iter().zip(names) {
            let name = n.as_deref().map(str::to_owned);
            match a {
                ArgVal::Value(v) => out.push(rapid_evaluator::Arg {
                    name,
                    value: Some(E::Value(self.scalar(sh, v)?)),
                }),
                ArgVal::Place(p) => {
                    let v = self.load(sh, &p)?;
                    out.push(rapid_evaluator::Arg {
                        name,
                        value: Some(E::Value(self.scalar(sh, v)?)),
                    });
                }
                ArgVal::Switch => out.push(rapid_evaluator::Arg { name, value: None }),
                ArgVal::Absent => {}
                ArgVal::Star => return invalid(format!("* is no argument of {name:?}")),
            }
        }
        let call = E::Call {
            name: name.to_owned(),
            args: out,
        };
        let options = Options {
            max_steps: u64::MAX,
            ..Options::default()
        };
        match rapid_evaluator::eval_with(&call, None, &self.prog.types, &options) {
            Ok(e) => Ok(e.value),
            Err(e) => self.eval_error(e),
        }
    }
}

/// Saves `pc` in the innermost frame.
fn pc_sync(m: &mut Machine, pc: u32) {
    if let Some(top) = m.frames.last_mut() {
        top.pc = pc;
    }
}
