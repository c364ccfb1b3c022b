//! What a debugger reads and changes in a stopped controller: each task's
//! routines, their variables, their modules' data, expressions evaluated
//! in a routine, assignments.

use std::sync::Arc;

use rapid_evaluator::Value;

use crate::code::SlotKind;
use crate::compile::Compiler;
use crate::controller::Controller;
use crate::machine::{FrameKind, Machine, StackFrame, Yield};
use crate::program::Origin;

/// A module data object of a task and its value.
#[derive(Clone, Debug, PartialEq)]
pub struct DataValue {
    /// The unit (of the task) and the declaration's range.
    pub unit: usize,
    pub range: std::ops::Range<usize>,
    pub name: String,
    /// `None`: its starting value could not be computed.
    pub value: Option<Value>,
}

/// A variable as a debugger shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    pub name: String,
    /// Its declared type (`num`, `robtarget{*}`).
    pub ty: String,
    /// `None` for an optional parameter left out.
    pub value: Option<Value>,
}

impl Machine {
    /// The index in `frames` of routine frame `frame` (0: the innermost).
    fn frame_index(&self, frame: usize) -> Option<usize> {
        let routines: Vec<usize> = (0..self.frames.len())
            .rev()
            .filter(|&i| !matches!(self.frames[i].kind, FrameKind::Init | FrameKind::Eval))
            .collect();
        routines.get(frame).copied()
    }
}

fn shown_type(ty: &rapid_evaluator::Type) -> String {
    ty.to_string().replace('0', "*")
}

impl Controller {
    /// The active routines of task `task`, innermost first.
    pub fn stack(&self, task: usize) -> Vec<StackFrame> {
        self.tasks()
            .get(task)
            .map(Machine::stack_frames)
            .unwrap_or_default()
    }

    /// The parameters and data of routine frame `frame` of task `task` (0
    /// is the innermost), in declaration order (`FOR` variables last).
    pub fn frame_variables(&self, task: usize, frame: usize) -> Vec<Variable> {
        let Some(m) = self.tasks().get(task) else {
            return Vec::new();
        };
        let Some(f) = m.frame_index(frame).and_then(|i| m.frames.get(i)) else {
            return Vec::new();
        };
        f.code
            .slots
            .iter()
            .enumerate()
            .filter(|(_, s)| s.kind != SlotKind::Hidden)
            .map(|(i, s)| Variable {
                name: s.name.clone(),
                ty: if s.kind == SlotKind::For {
                    "num".to_owned()
                } else {
                    shown_type(&s.ty)
                },
                value: m.slot_value(self.shared(), f.base as usize, i),
            })
            .collect()
    }

    /// The data of the module of routine frame `frame` of task `task`.
    pub fn module_variables(&self, task: usize, frame: usize) -> Vec<Variable> {
        let Some(m) = self.tasks().get(task) else {
            return Vec::new();
        };
        let Some(f) = m.frame_index(frame).and_then(|i| m.frames.get(i)) else {
            return Vec::new();
        };
        let module = f.code.module;
        let mut out: Vec<(usize, Variable)> = m
            .prog
            .globals
            .iter()
            .enumerate()
            .filter_map(|(i, g)| match &g.origin {
                Origin::Module { module: md, range } if *md == module => Some((
                    range.start,
                    Variable {
                        name: g.name.clone(),
                        ty: shown_type(&g.ty),
                        value: m.globals.get(i).cloned(),
                    },
                )),
                _ => None,
            })
            .collect();
        for (k, p) in m.prog.pers.iter().enumerate() {
            if p.module != module {
                continue;
            }
            let value = m
                .pers_map
                .get(k)
                .and_then(|&i| self.shared().pers.get(i as usize))
                .cloned();
            out.push((
                p.range.start,
                Variable {
                    name: p.name.clone(),
                    ty: shown_type(&p.ty),
                    value,
                },
            ));
        }
        out.sort_by_key(|(at, _)| *at);
        out.into_iter().map(|(_, v)| v).collect()
    }

    /// The module data of task `task` with their values now, in the task's
    /// order (after [`Controller::add_task`]: their starting values).
    pub fn data_values(&self, task: usize) -> Vec<DataValue> {
        let Some(m) = self.tasks().get(task) else {
            return Vec::new();
        };
        let unit_of = |module: usize| m.prog.modules.get(module).map_or(0, |md| md.unit);
        let mut out: Vec<DataValue> = m
            .prog
            .globals
            .iter()
            .enumerate()
            .filter_map(|(i, g)| match &g.origin {
                Origin::Module { module, range } => Some(DataValue {
                    unit: unit_of(*module),
                    range: range.clone(),
                    name: g.name.clone(),
                    value: matches!(m.init.get(i), Some(crate::machine::Init::Ready))
                        .then(|| m.globals.get(i).cloned())
                        .flatten(),
                }),
                _ => None,
            })
            .collect();
        for (k, p) in m.prog.pers.iter().enumerate() {
            let i = m.pers_map.get(k).map(|&i| i as usize);
            let ready = i.is_some_and(|i| {
                matches!(
                    self.shared().pers_init.get(i),
                    Some(crate::machine::Init::Ready)
                )
            });
            out.push(DataValue {
                unit: unit_of(p.module),
                range: p.range.clone(),
                name: p.name.clone(),
                value: i
                    .filter(|_| ready)
                    .and_then(|i| self.shared().pers.get(i).cloned()),
            });
        }
        out.sort_by_key(|d| (d.unit, d.range.start));
        out
    }

    /// `ERRNO` and `INTNO` of task `task`.
    pub fn system_variables(&self, task: usize) -> Vec<Variable> {
        let Some(m) = self.tasks().get(task) else {
            return Vec::new();
        };
        [("ERRNO", m.prog.errno), ("INTNO", m.prog.intno)]
            .into_iter()
            .filter_map(|(n, g)| {
                let g = g?;
                Some(Variable {
                    name: n.to_owned(),
                    ty: "num".to_owned(),
                    value: m.globals.get(g as usize).cloned(),
                })
            })
            .collect()
    }

    /// Evaluates an expression written in RAPID in routine frame `frame`
    /// of task `task` (its names resolve as they do there).
    pub fn evaluate(&mut self, task: usize, frame: usize, text: &str) -> Result<Value, String> {
        let expr = rapid_analyzer::body::expression_of(text)?;
        self.in_frame(task, frame, |c| c.eval_code(&expr))
    }

    /// Assigns the value of expression `value` to the data `target` (a
    /// name, a component, an element) in routine frame `frame` of task
    /// `task`; the value stored.
    pub fn assign(
        &mut self,
        task: usize,
        frame: usize,
        target: &str,
        value: &str,
    ) -> Result<Value, String> {
        let target = rapid_analyzer::body::expression_of(target)?;
        let value = rapid_analyzer::body::expression_of(value)?;
        self.in_frame(task, frame, |c| c.assign_code(&target, &value))
    }

    /// Runs code compiled in a frame's scope on top of the task's stack,
    /// with no debugger and no interrupts, to its value.
    fn in_frame(
        &mut self,
        task: usize,
        frame: usize,
        compile: impl FnOnce(Compiler<'_>) -> crate::code::Code,
    ) -> Result<Value, String> {
        let Some((m, sh)) = self.parts(task) else {
            return Err("no such task".to_owned());
        };
        let Some(i) = m.frame_index(frame) else {
            return Err("no such frame".to_owned());
        };
        let target = &m.frames[i];
        let prog = m.prog.clone();
        let loops: Vec<(String, std::ops::Range<usize>, u32)> = target
            .code
            .for_loops
            .iter()
            .filter(|l| (l.start..l.end).contains(&target.pc))
            .map(|l| (l.name.clone(), l.var_range.clone(), l.slot))
            .collect();
        let Some(c) = Compiler::for_frame(&prog, &target.code, &loops) else {
            return Err("the routine cannot be read".to_owned());
        };
        let code = Arc::new(compile(c));
        let base = target.base;
        let depth = m.frames.len();
        let active = std::mem::replace(&mut sh.debug.active, false);
        let disabled = std::mem::replace(&mut m.interrupts.disabled, true);
        let pending = m.pending.take();
        m.push_eval(code, base);
        m.evaluated = None;
        let mut guard = 0;
        while m.frames.len() > depth && guard < 100_000 {
            guard += 1;
            match m.run_slice(sh, u32::MAX) {
                Yield::Evaluated | Yield::Done => break,
                Yield::Blocked | Yield::Stopped(_) => {
                    m.evaluated = Some(Err(
                        "the expression cannot be evaluated here (it waits)".to_owned()
                    ));
                    break;
                }
                Yield::Slice => {}
            }
        }
        while m.frames.len() > depth {
            m.pop_frame();
        }
        sh.debug.active = active;
        m.interrupts.disabled = disabled;
        m.pending = pending;
        m.evaluated
            .take()
            .unwrap_or_else(|| Err("the expression has no value".to_owned()))
    }
}
