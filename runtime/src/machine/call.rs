//! Frames: calls (arguments bound to the callee's parameter slots),
//! returns, trap routines, late binding.

use std::sync::Arc;

use rapid_analyzer::items::RoutineKind;
use rapid_evaluator::Value;

use super::{
    ArgVal, Boundary, Frame, FrameKind, Machine, Place, R, Root, Slot, TaskState, Yield, fault,
    invalid, named_error,
};
use crate::code::{Code, CodeKind};
use crate::controller::Shared;

impl Machine {
    /// Pushes a frame for `code` with its parameter slots.
    pub(crate) fn push_frame(&mut self, code: Arc<Code>, kind: FrameKind, params: Vec<Slot>) {
        let base = self.slots.len();
        self.slots.extend(params);
        self.push_frame_at(code, kind, base);
    }

    /// Pushes a frame for `code` whose slots start at `base` (its
    /// parameters are there already).
    fn push_frame_at(&mut self, code: Arc<Code>, kind: FrameKind, base: usize) {
        self.slots
            .resize(base + code.slots.len(), Slot::Val(Value::Num(0.0)));
        self.frames.push(Frame {
            code,
            pc: 0,
            base: base as u32,
            top: base as u32,
            vals: self.vals.len() as u32,
            places: self.places.len() as u32,
            args: self.args.len() as u32,
            stmt: 0,
            boundary: Boundary::None,
            kind,
            in_handler: false,
            fault_stmt: 0,
            retries: 0,
            undoing: None,
            wait: None,
            entered: 0.0,
        });
    }

    /// Pushes the frame of an expression a debugger evaluates in the frame
    /// whose slots start at `base`.
    pub(crate) fn push_eval(&mut self, code: Arc<Code>, base: u32) {
        self.push_frame(code, FrameKind::Eval, Vec::new());
        if let Some(f) = self.frames.last_mut() {
            f.base = base;
        }
    }

    /// Pops the innermost frame, with its slots and what it left on the
    /// operand stacks.
    pub(crate) fn pop_frame(&mut self) -> Option<Frame> {
        let f = self.frames.pop()?;
        self.slots.truncate(f.top as usize);
        while self.origins.last().is_some_and(|(s, _)| *s >= f.top) {
            self.origins.pop();
        }
        self.vals.truncate(f.vals as usize);
        self.places.truncate(f.places as usize);
        self.args.truncate(f.args as usize);
        Some(f)
    }

    /// Calls routine `id` with the arguments on top of the argument stack,
    /// argument `k` for parameter `bound[k]`.
    pub(crate) fn call(&mut self, sh: &mut Shared, id: u32, bound: &[u32]) -> R<()> {
        let Some(code) = self.prog.code(id).cloned() else {
            return invalid("a call of a routine that does not exist");
        };
        self.check_depth(sh, &code)?;
        let at = self.args.len().saturating_sub(bound.len());
        let base = self.slots.len();
        self.slots.resize(base + code.params.len(), Slot::Absent);
        // Which parameters an argument is given for (a parameter past the
        // 64th counts as given).
        let mut given: u64 = 0;
        let origins = self.origins.len();
        for (k, &i) in bound.iter().enumerate() {
            let a = std::mem::replace(&mut self.args[at + k], ArgVal::Absent);
            if let ArgVal::Place(p) = &a
                && code
                    .params
                    .get(i as usize)
                    .is_some_and(|p| !p.by_reference())
            {
                self.origins.push(((base + i as usize) as u32, p.root));
            }
            let slot = match self.param_slot(sh, &code, i, a) {
                Ok(s) => s,
                Err(f) => {
                    self.slots.truncate(base);
                    self.args.truncate(at);
                    self.origins.truncate(origins);
                    return Err(f);
                }
            };
            self.slots[base + i as usize] = slot;
            given |= 1u64.checked_shl(i).unwrap_or(0);
        }
        self.args.truncate(at);
        for (i, p) in code.params.iter().enumerate() {
            let bit = 1u64.checked_shl(i as u32).unwrap_or(u64::MAX);
            if !p.optional && given & bit == 0 {
                self.slots.truncate(base);
                self.origins.truncate(origins);
                return invalid(format!(
                    "the argument {} of {} is missing",
                    p.name, code.name
                ));
            }
        }
        self.push_frame_at(code, FrameKind::Call, base);
        if let Some(f) = self.frames.last_mut() {
            f.entered = sh.clock;
        }
        // In slot order (named arguments come in any order).
        self.origins[origins..].sort_unstable_by_key(|(s, _)| *s);
        Ok(())
    }

    /// The name of the data object at a place's root, following value
    /// parameters back to the data object their argument was (`ArgName`).
    /// `None` for a value parameter given a value, not a data object.
    pub(crate) fn origin_name(&self, root: Root) -> Option<String> {
        if let Root::Stack(s) = root {
            // The argument's place, in a caller's frame: below `s`.
            if let Some(&(_, from)) = self.origins.iter().rev().find(|(o, _)| *o == s) {
                return match from {
                    Root::Stack(f) if f >= s => None,
                    _ => self.origin_name(from),
                };
            }
            let frame = self.frames.iter().rev().find(|f| f.base <= s)?;
            if ((s - frame.base) as usize) < frame.code.params.len() {
                return None;
            }
        }
        self.data_name(root)
    }

    /// Pushes a routine's frame within the call-depth budget.
    pub(crate) fn enter(
        &mut self,
        sh: &Shared,
        code: Arc<Code>,
        kind: FrameKind,
        params: Vec<Slot>,
    ) -> R<()> {
        self.check_depth(sh, &code)?;
        self.push_frame(code, kind, params);
        Ok(())
    }

    fn check_depth(&self, sh: &Shared, code: &Code) -> R<()> {
        let max = sh.limits.max_depth as usize;
        if self.frames.len() >= max {
            return fault(super::FaultKind::Budget(format!(
                "the call depth limit ({max}) was reached in {} (unbounded recursion?)",
                code.name
            )));
        }
        Ok(())
    }

    /// The slot of parameter `i` of `code` for argument `a`.
    fn param_slot(&self, sh: &Shared, code: &Code, i: u32, a: ArgVal) -> R<Slot> {
        let Some(p) = code.params.get(i as usize) else {
            return invalid(format!("too many arguments for {}", code.name));
        };
        let conv = p.conv.and_then(|c| code.convs.get(c as usize));
        Ok(match a {
            ArgVal::Switch | ArgVal::Value(_) if p.switch => Slot::Val(Value::Bool(true)),
            ArgVal::Switch => {
                return invalid(format!("\\{} is not a switch of {}", p.name, code.name));
            }
            ArgVal::Star => return invalid(format!("* is no argument for {}", code.name)),
            ArgVal::Absent => Slot::Absent,
            ArgVal::Place(place) if p.by_reference() => Slot::Ref(place),
            ArgVal::Place(place) => {
                let v = self.load(sh, &place)?;
                Slot::Val(match conv {
                    Some(c) => self.convert(sh, v, c)?,
                    None => v,
                })
            }
            ArgVal::Value(v) => Slot::Val(match conv {
                Some(c) => self.convert(sh, v, c)?,
                None => v,
            }),
        })
    }

    /// The argument `\Name?p` passes on: the caller's parameter slot `p`.
    pub(crate) fn conditional_arg(
        &self,
        sh: &Shared,
        base: usize,
        slot: u32,
        by_ref: bool,
    ) -> R<ArgVal> {
        let s = base + slot as usize;
        Ok(match self.slots.get(s) {
            None | Some(Slot::Absent) => ArgVal::Absent,
            Some(Slot::Ref(p)) if by_ref => ArgVal::Place(p.clone()),
            Some(Slot::Ref(p)) => ArgVal::Value(self.load(sh, p)?),
            Some(Slot::Val(_)) if by_ref => ArgVal::Place(Place::root(Root::Stack(s as u32))),
            Some(Slot::Val(v)) => ArgVal::Value(v.clone()),
        })
    }

    /// Returns from the innermost frame (with a function's value).
    pub(crate) fn return_from(
        &mut self,
        sh: &mut Shared,
        value: Option<Value>,
    ) -> R<Option<Yield>> {
        let Some(f) = self.pop_frame() else {
            return Ok(Some(Yield::Done));
        };
        if sh.trace && matches!(f.kind, FrameKind::Call | FrameKind::Entry) {
            sh.routine_times.push(crate::RoutineTime {
                task: self.name.clone(),
                routine: f.code.name.clone(),
                start: f.entered,
                end: sh.clock,
            });
        }
        match f.kind {
            FrameKind::Call => {
                if f.code.kind == CodeKind::Routine(RoutineKind::Func) {
                    let Some(v) = value else {
                        return invalid("the function returned no value");
                    };
                    let v = match f.code.returns.and_then(|c| f.code.convs.get(c as usize)) {
                        Some(c) => self.convert(sh, v, c)?,
                        None => v,
                    };
                    self.vals.push(v);
                }
                Ok(None)
            }
            FrameKind::Entry => {
                self.finish(super::Outcome::finished());
                Ok(Some(Yield::Done))
            }
            FrameKind::Trap => Ok(None),
            FrameKind::Eval => {
                self.evaluated = Some(value.ok_or_else(|| "no value".to_owned()));
                Ok(Some(Yield::Evaluated))
            }
            FrameKind::Init => Ok(None),
        }
    }

    /// The end of a routine's body: a procedure returns, a function fails.
    pub(crate) fn end_of_body(&mut self, sh: &mut Shared) -> R<Option<Yield>> {
        let (is_func, name) = match self.frames.last() {
            Some(f) => (
                f.code.kind == CodeKind::Routine(RoutineKind::Func),
                f.code.name.clone(),
            ),
            None => return Ok(Some(Yield::Done)),
        };
        if is_func {
            return fault(named_error(
                &self.prog,
                "ERR_FNCNORET",
                format!("the function {name} ended without RETURN"),
            ));
        }
        self.return_from(sh, None)
    }

    /// Is a trap routine running?
    pub(crate) fn in_trap(&self) -> bool {
        self.frames.iter().any(|f| f.kind == FrameKind::Trap)
    }

    /// Starts the trap routine of the next interrupt that occurred, if any
    /// may run now.
    pub(crate) fn start_trap(&mut self, sh: &mut Shared) -> R<bool> {
        if self.interrupts.disabled || self.in_trap() {
            return Ok(false);
        }
        while let Some((id, trap)) = self.interrupts.next_pending() {
            let Some(code) = self.prog.code(trap).cloned() else {
                continue;
            };
            if let Some(g) = self.prog.intno
                && let Some(v) = self.globals.get_mut(g as usize)
            {
                *v = Value::Num(id as f32);
            }
            self.enter(sh, code, FrameKind::Trap, Vec::new())?;
            return Ok(true);
        }
        Ok(false)
    }

    /// Is an interrupt waiting for its trap routine, and may it run now?
    pub(crate) fn interrupt_due(&mut self, sh: &mut Shared) -> bool {
        if self.events_seen < sh.events.len() {
            let new: Vec<(String, f64)> = sh.events[self.events_seen..].to_vec();
            self.events_seen = sh.events.len();
            for (name, value) in new {
                self.interrupts.signal_changed(&name, value);
            }
        }
        while self.log_seen < sh.event_log.len() {
            if let Some(e) = sh.event_log.get(self.log_seen) {
                self.interrupts.logged(self.log_seen, e);
            }
            self.log_seen += 1;
        }
        if !self.interrupts.pers.is_empty() {
            let changed: Vec<(usize, Value)> = self
                .interrupts
                .pers
                .iter()
                .enumerate()
                .filter_map(|(i, w)| {
                    let now = self.get(sh, &w.place)?;
                    (*now != w.last).then(|| (i, now.clone()))
                })
                .collect();
            self.interrupts.pers_changed(&changed);
        }
        if !self.interrupts.rmq.is_empty() {
            self.receive_messages(sh);
        }
        self.interrupts.has_pending() && !self.interrupts.disabled && !self.in_trap()
    }

    /// `IRMQMessage`: each message of a subscribed type leaves the task's
    /// queue and raises its interrupt (in order), for `RMQGetMessage`.
    fn receive_messages(&mut self, sh: &mut Shared) {
        let own = self.number.saturating_sub(1);
        loop {
            let subs = &self.interrupts.rmq;
            let id_of =
                |m: &crate::rmq::Message| subs.iter().find(|(t, _)| *t == m.key).map(|(_, id)| *id);
            let Some(handle) = sh.rmq.take(own, |m| id_of(m).is_some()) else {
                break;
            };
            let id = sh.rmq.get(handle).and_then(id_of);
            self.rmq_received.push_back(handle);
            if let Some(id) = id {
                self.interrupts.raise(id);
            }
        }
    }

    /// `%name% args;` and `CallByVar`: the procedure `name` names, called
    /// from the innermost frame's module with the arguments on the
    /// argument stack (written with `names`).
    pub(crate) fn call_by_name(
        &mut self,
        sh: &mut Shared,
        name: &str,
        names: &[Option<Box<str>>],
    ) -> R<()> {
        let module = self.frames.last().map_or(usize::MAX, |f| f.code.module);
        let Some(id) = self.prog.routine_named(module, name) else {
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
        let bound = match self.prog.bind_late(id, names) {
            Ok(b) => b,
            Err(why) => return invalid(why),
        };
        self.call(sh, id, &bound)
    }

    /// Is the task running (not ended, not idle)?
    pub(crate) fn is_running(&self) -> bool {
        matches!(self.state, TaskState::Running)
    }
}
