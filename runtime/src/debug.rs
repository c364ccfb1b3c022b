//! What a debugger sees of a paused machine: the stack, each frame's
//! variables, its module's data, expressions evaluated in a frame, and
//! assignments.

use rapid_evaluator::{Type, Value};

use crate::Control;
use crate::code::SlotKind;
use crate::compile::Compiler;
use crate::machine::{Fault, FaultKind, Machine, Outcome, R, Status, fault};
use crate::program::{Location, Origin};

/// A variable as a debugger shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    pub name: String,
    /// Its declared type (`num`, `robtarget{3}`).
    pub ty: String,
    /// `None` for an optional parameter left out.
    pub value: Option<Value>,
}

impl Machine {
    pub(crate) fn debug_statement(&mut self) -> R<()> {
        let Some(mut d) = self.debugger.take() else {
            return Ok(());
        };
        let c = d.statement(self);
        self.debugger = Some(d);
        match c {
            Control::Continue => Ok(()),
            Control::Terminate => fault(FaultKind::Halt(Status::Stopped)),
        }
    }

    pub(crate) fn debug_error(&mut self, outcome: &Outcome) {
        if let Some(mut d) = self.debugger.take() {
            d.error(self, outcome);
            self.debugger = Some(d);
        }
    }

    /// The number of active routines.
    pub fn depth(&self) -> usize {
        self.frames.len()
    }

    /// The statement about to run (or running) in the innermost routine.
    pub fn location(&self) -> Option<Location> {
        self.here()
    }

    /// Is the innermost routine running its error handler?
    pub fn in_error_handler(&self) -> bool {
        self.frames.last().is_some_and(|f| f.in_handler)
    }

    fn frame_index(&self, frame: usize) -> Option<usize> {
        self.frames.len().checked_sub(frame + 1)
    }

    /// The parameters and data of frame `frame` (0 is the innermost), in
    /// declaration order (`FOR` variables last).
    pub fn frame_variables(&self, frame: usize) -> Vec<Variable> {
        let Some(f) = self.frame_index(frame).and_then(|i| self.frames.get(i)) else {
            return Vec::new();
        };
        f.routine
            .slots
            .iter()
            .enumerate()
            .map(|(i, s)| Variable {
                name: s.name.clone(),
                ty: if s.kind == SlotKind::For {
                    "num".to_owned()
                } else {
                    s.ty.to_string().replace('0', "*")
                },
                value: self.slot_value(f.base as usize, i),
            })
            .collect()
    }

    /// The data of the module of frame `frame`.
    pub fn module_variables(&self, frame: usize) -> Vec<Variable> {
        let Some(f) = self.frame_index(frame).and_then(|i| self.frames.get(i)) else {
            return Vec::new();
        };
        let module = self
            .prog
            .routines
            .get(f.routine.id as usize)
            .map(|r| r.module);
        self.prog
            .globals
            .iter()
            .enumerate()
            .filter(
                |(_, g)| matches!(g.origin, Origin::Module { module: m, .. } if Some(m) == module),
            )
            .map(|(i, g)| Variable {
                name: g.name.clone(),
                ty: g.ty.to_string().replace('0', "*"),
                value: self.globals.get(i).cloned(),
            })
            .collect()
    }

    /// `ERRNO` and `INTNO`.
    pub fn system_variables(&self) -> Vec<Variable> {
        [("ERRNO", self.prog.errno), ("INTNO", self.prog.intno)]
            .into_iter()
            .filter_map(|(n, g)| {
                let g = g?;
                Some(Variable {
                    name: n.to_owned(),
                    ty: "num".to_owned(),
                    value: self.globals.get(g as usize).cloned(),
                })
            })
            .collect()
    }

    /// Runs `f` with names resolved in frame `frame`.
    fn in_frame<T>(
        &mut self,
        frame: usize,
        f: impl FnOnce(&mut Machine, &Compiler<'_>) -> R<T>,
    ) -> Result<T, String> {
        let Some(i) = self.frame_index(frame) else {
            return Err("no such frame".to_owned());
        };
        let prog = self.prog.clone();
        let routine = self.frames[i].routine.clone();
        let module = prog
            .routines
            .get(routine.id as usize)
            .map_or(0, |r| r.module);
        let c = Compiler::for_frame(&prog, module, &routine);
        let saved = self.base;
        self.base = self.frames[i].base as usize;
        let debugger = self.debugger.take();
        let r = f(self, &c);
        self.debugger = debugger;
        self.base = saved;
        r.map_err(|e| describe(self, *e))
    }

    /// Evaluates an expression written in RAPID in frame `frame`.
    pub fn evaluate(&mut self, frame: usize, text: &str) -> Result<Value, String> {
        let expr = rapid_analyzer::body::expression_of(text)?;
        self.in_frame(frame, |m, c| {
            let e = c.expr(&expr, None);
            m.eval(&e)
        })
    }

    /// Assigns the value of expression `value` to the data `target` (a
    /// name, a component, an element) in frame `frame`; the value stored.
    pub fn assign(&mut self, frame: usize, target: &str, value: &str) -> Result<Value, String> {
        let target = rapid_analyzer::body::expression_of(target)?;
        let value = rapid_analyzer::body::expression_of(value)?;
        self.in_frame(frame, |m, c| {
            let t = c.expr(&target, None);
            if !t.is_place() {
                return crate::machine::invalid("not a data reference");
            }
            let ty: Option<Type> = c.type_of(&t);
            let v = m.eval(&c.expr(&value, ty.as_ref()))?;
            let conv = ty.as_ref().map_or(crate::code::Conv::None, |t| c.conv(t));
            let v = m.convert(v, &conv)?;
            let p = m.place(&t)?;
            m.store(&p, v.clone())?;
            Ok(v)
        })
    }
}

fn describe(m: &Machine, f: Fault) -> String {
    let o = m.outcome_of(f);
    match o.errno {
        Some((_, name)) => format!("{name}: {}", o.message),
        None => o.message,
    }
}

impl<'p> Compiler<'p> {
    /// A compiler that sees the names of a running routine.
    pub(crate) fn for_frame(
        prog: &'p crate::program::Program,
        module: usize,
        routine: &crate::code::Routine,
    ) -> Compiler<'p> {
        let mut c = Compiler::for_module(prog, module);
        c.adopt_slots(routine);
        c
    }
}
