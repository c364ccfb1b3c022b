//! From the analyzer's lowered body ([`rapid_analyzer::body`]) to the
//! compiled form ([`crate::code`]). Every name is resolved by `sema`
//! ([`rapid_analyzer::resolve::Resolver`], the resolver the checker uses)
//! and every call is bound by the one binder; what is left here is
//! translation: which storage slot a declaration has, which operations a
//! statement becomes, and the type a value is stored as (from the task's
//! one type model, [`rapid_analyzer::ty::Types`]).

mod calls;
mod expr;
mod stmt;

use std::ops::Range;

use rapid_analyzer::body::{self, Body};
use rapid_analyzer::items::{DataDecl, Storage};
use rapid_analyzer::names::fold;
use rapid_analyzer::resolve::Resolver;
use rapid_analyzer::ty::Ty;
use rapid_evaluator::{Type, Value};

use crate::code::*;
use crate::program::{Home, Program};

pub(crate) struct Compiler<'p> {
    prog: &'p Program,
    names: Resolver<'p>,
    code: Code,
    /// Routine data slots, by the range of their name.
    locals: Vec<(Range<usize>, u32)>,
    /// The slots of the `FOR` variables entered, by the range of their
    /// name.
    for_slots: Vec<(Range<usize>, u32)>,
    labels: stmt::Labels,
    /// The function's return type.
    returns: Option<Ty>,
}

/// Compiles routine `id` of the program.
pub(crate) fn routine(prog: &Program, id: u32) -> Code {
    let Some(info) = prog.routines.get(id as usize) else {
        return failed(prog, "a routine that does not exist", 0, 0..0);
    };
    let unit_idx = info.item.unit;
    let decl = &info.decl;
    let Some(names) = Resolver::in_routine(&prog.task, unit_idx, decl) else {
        return failed(
            prog,
            "the routine cannot be read",
            info.module,
            decl.range.clone(),
        );
    };
    let kind = CodeKind::Routine(decl.kind);
    let mut c = Compiler::new(prog, names, kind, info.module, unit_idx, decl.range.clone());
    c.code.name = decl.name.clone();
    c.code.routine = Some(id);
    for p in &decl.params {
        let ty =
            p.ty.as_ref()
                .map_or(Ty::Unknown, |t| Ty::named(&t.name))
                .array(p.dims);
        let slot = c.add_slot(&p.name, &ty, SlotKind::Param);
        let conv = c.conv(&ty);
        c.code.params.push(Param {
            name: p.name.clone(),
            mode: p.mode,
            optional: p.optional,
            switch: p.switch,
            conv,
        });
        let _ = slot;
    }
    c.returns = decl.returns.as_ref().map(|t| Ty::named(&t.name));
    c.code.returns = c.returns.clone().and_then(|t| c.conv(&t));
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
    c.routine_body(&body);
    c.code
}

/// The code that computes module data object `d`'s starting value (in its
/// module's scope) and stores it at `home`.
pub(crate) fn data_start(
    prog: &Program,
    names: Resolver<'_>,
    module: usize,
    d: &DataDecl,
    home: Home,
) -> Code {
    let unit = prog.modules.get(module).map_or(0, |m| m.unit);
    let mut c = Compiler::new(prog, names, CodeKind::Init, module, unit, d.range.clone());
    c.code.name = d.name.clone();
    let ty =
        d.ty.as_ref()
            .map_or(Ty::Unknown, |t| Ty::named(&t.name))
            .array(u8::try_from(d.dims.len()).unwrap_or(u8::MAX));
    let s = c.new_stmt(d.range.clone());
    c.emit(Op::Mark(s));
    let unit_ref = prog.task.units.get(unit);
    let lower = |r: &Range<usize>| {
        unit_ref
            .and_then(|u| body::expression_at(u, r.clone()))
            .unwrap_or(rapid_evaluator::Expr::Unknown)
    };
    for dim in &d.dims {
        let e = lower(dim);
        c.expr(&e, Some(&Ty::num()));
    }
    if let Some(init) = &d.init {
        let e = lower(init);
        c.expr(&e, Some(&ty));
    }
    let target = match home {
        Home::Global(g) => Target::Global(g),
        Home::Pers(k) => Target::Pers(k),
    };
    let decl = c.data_init(&ty, d.dims.len(), d.init.is_some(), target);
    c.emit(Op::InitGlobal { decl });
    c.emit(Op::EndInit);
    c.code.end_stmt = s;
    c.code
}

/// Code that fails at once with `why` (a routine that cannot be compiled).
fn failed(prog: &Program, why: &str, module: usize, range: Range<usize>) -> Code {
    let unit = prog.modules.get(module).map_or(0, |m| m.unit);
    let names = Resolver::in_module(
        &prog.task,
        unit,
        prog.modules.get(module).map_or(0, |m| m.index),
    );
    let mut code = empty_code(
        CodeKind::Routine(rapid_analyzer::items::RoutineKind::Proc),
        module,
        unit,
        range.clone(),
    );
    code.stmts.push(StmtInfo {
        range: range.clone(),
        line: prog.line(unit, range.start),
        start: 0,
        end: 2,
    });
    code.failures.push(Failure::Invalid(why.to_owned()));
    code.ops = vec![Op::Mark(0), Op::Fail(0)];
    let _ = names;
    code
}

fn empty_code(kind: CodeKind, module: usize, unit: usize, range: Range<usize>) -> Code {
    Code {
        name: String::new(),
        kind,
        routine: None,
        unit,
        module,
        range,
        params: Vec::new(),
        slots: Vec::new(),
        ops: Vec::new(),
        stmts: Vec::new(),
        consts: Vec::new(),
        names: Vec::new(),
        types: Vec::new(),
        convs: Vec::new(),
        calls: Vec::new(),
        builtins: Vec::new(),
        pures: Vec::new(),
        lates: Vec::new(),
        waits: Vec::new(),
        decls: Vec::new(),
        failures: Vec::new(),
        body: 0,
        error: None,
        undo: None,
        returns: None,
        end_stmt: 0,
        for_loops: Vec::new(),
        bindings: Vec::new(),
    }
}

impl<'p> Compiler<'p> {
    fn new(
        prog: &'p Program,
        names: Resolver<'p>,
        kind: CodeKind,
        module: usize,
        unit: usize,
        range: Range<usize>,
    ) -> Compiler<'p> {
        Compiler {
            prog,
            names,
            code: empty_code(kind, module, unit, range),
            locals: Vec::new(),
            for_slots: Vec::new(),
            labels: stmt::Labels::default(),
            returns: None,
        }
    }

    /// A compiler for an expression a debugger evaluates in a frame of
    /// `code` (its slots are the frame's).
    pub(crate) fn for_frame(
        prog: &'p Program,
        code: &Code,
        for_vars: &[(String, Range<usize>, u32)],
    ) -> Option<Compiler<'p>> {
        let names = match code.routine {
            Some(id) => {
                let info = prog.routines.get(id as usize)?;
                Resolver::in_routine(&prog.task, info.item.unit, &info.decl)?
            }
            None => {
                let m = prog.modules.get(code.module)?;
                Resolver::in_module(&prog.task, m.unit, m.index)?
            }
        };
        let mut c = Compiler::new(
            prog,
            names,
            CodeKind::Eval,
            code.module,
            code.unit,
            code.range.clone(),
        );
        c.code.slots = code.slots.clone();
        c.code.params = code.params.clone();
        c.code.routine = code.routine;
        if let Some(id) = code.routine
            && let Some(info) = prog.routines.get(id as usize)
            && let Some(body) = prog
                .task
                .units
                .get(info.item.unit)
                .and_then(|u| body::lower_routine(u, &info.decl))
        {
            for (i, d) in body.data.iter().enumerate() {
                let slot = (code.params.len() + i) as u32;
                c.locals.push((d.name_range.clone(), slot));
            }
        }
        for (name, range, slot) in for_vars {
            c.names.enter_for(name, range.clone());
            c.for_slots.push((range.clone(), *slot));
        }
        Some(c)
    }

    /// Compiles `e` as the whole code: its value, then the end.
    pub(crate) fn eval_code(mut self, e: &rapid_evaluator::Expr) -> Code {
        let s = self.new_stmt(self.code.range.start..self.code.range.start);
        self.emit(Op::Mark(s));
        self.expr(e, None);
        self.emit(Op::Return { value: true });
        self.code
    }

    /// Compiles `target := value` as the whole code: the value stored,
    /// then returned.
    pub(crate) fn assign_code(
        mut self,
        target: &rapid_evaluator::Expr,
        value: &rapid_evaluator::Expr,
    ) -> Code {
        let s = self.new_stmt(self.code.range.start..self.code.range.start);
        self.emit(Op::Mark(s));
        match self.place_type(target) {
            Some(ty) => {
                self.expr(value, ty.as_ref());
                if let Some(c) = ty.as_ref().and_then(|t| self.conv(t)) {
                    self.emit(Op::Convert(c));
                }
                self.place(target);
                self.emit(Op::Store);
                self.place(target);
                self.emit(Op::Load);
                self.emit(Op::Return { value: true });
            }
            None => self.fail(Failure::Invalid("not a data reference".to_owned())),
        }
        self.code
    }

    fn routine_body(&mut self, body: &Body) {
        for d in &body.data {
            let ty = Ty::named(&d.ty).array(u8::try_from(d.dims.len()).unwrap_or(u8::MAX));
            let kind = match d.storage {
                Storage::Var => SlotKind::Var,
                Storage::Pers => SlotKind::Pers,
                Storage::Const => SlotKind::Const,
            };
            let slot = self.add_slot(&d.name, &ty, kind);
            self.locals.push((d.name_range.clone(), slot));
        }
        for (i, d) in body.data.iter().enumerate() {
            let slot = (self.code.params.len() + i) as u32;
            let ty = Ty::named(&d.ty).array(u8::try_from(d.dims.len()).unwrap_or(u8::MAX));
            let s = self.new_stmt(d.range.clone());
            self.emit(Op::Mark(s));
            for dim in &d.dims {
                self.expr(dim, Some(&Ty::num()));
            }
            if let Some(init) = &d.init {
                self.expr(init, Some(&ty));
            }
            let decl = self.data_init(&ty, d.dims.len(), d.init.is_some(), Target::Slot);
            self.emit(Op::InitLocal { slot, decl });
        }
        self.code.body = self.pc();
        self.section(&body.stmts);
        let end = body.range.end.saturating_sub(1);
        self.code.end_stmt = self.new_stmt(end..body.range.end);
        self.emit(Op::Mark(self.code.end_stmt));
        self.emit(Op::EndBody);
        if let Some(h) = &body.error {
            let pc = self.pc();
            let errors = h.errors.iter().map(|e| self.simple(e)).collect();
            self.code.error = Some(Handler { pc, errors });
            self.section(&h.stmts);
            self.emit(Op::EndHandler);
        }
        if let Some(h) = &body.undo {
            self.code.undo = Some(self.pc());
            self.section(&h.stmts);
            self.emit(Op::EndUndo);
        }
        if let Some(h) = &body.backward {
            // Runs only when the program is stepped backwards, which the
            // simulation does not do: compiled (its calls bound), never
            // entered.
            self.section(&h.stmts);
            self.emit(Op::EndHandler);
        }
    }

    // Building blocks.

    fn pc(&self) -> Pc {
        self.code.ops.len() as Pc
    }

    fn emit(&mut self, op: Op) -> usize {
        self.code.ops.push(op);
        self.code.ops.len() - 1
    }

    fn new_stmt(&mut self, range: Range<usize>) -> u32 {
        let line = self.prog.line(self.code.unit, range.start);
        let pc = self.pc();
        self.code.stmts.push(StmtInfo {
            range,
            line,
            start: pc,
            end: pc,
        });
        self.code.stmts.len() as u32 - 1
    }

    fn add_slot(&mut self, name: &str, ty: &Ty, kind: SlotKind) -> u32 {
        self.code.slots.push(SlotInfo {
            name: name.to_owned(),
            ty: type_of_ty(ty).unwrap_or_else(|| Type::named("")),
            kind,
        });
        self.code.slots.len() as u32 - 1
    }

    fn hidden(&mut self) -> u32 {
        self.add_slot("", &Ty::Unknown, SlotKind::Hidden)
    }

    fn constant(&mut self, v: Value) -> u32 {
        self.code.consts.push(v);
        self.code.consts.len() as u32 - 1
    }

    fn name_index(&mut self, name: &str) -> u32 {
        match self
            .code
            .names
            .iter()
            .position(|n| n.eq_ignore_ascii_case(name))
        {
            Some(i) => i as u32,
            None => {
                self.code.names.push(name.into());
                self.code.names.len() as u32 - 1
            }
        }
    }

    fn fail(&mut self, f: Failure) {
        self.code.failures.push(f);
        let i = self.code.failures.len() as u32 - 1;
        self.emit(Op::Fail(i));
    }

    fn data_init(&mut self, ty: &Ty, dims: usize, init: bool, target: Target) -> u32 {
        let conv = self.conv(ty);
        self.code.decls.push(DataInit {
            ty: type_of_ty(ty).unwrap_or_else(|| Type::named("")),
            dims: dims as u32,
            init,
            conv,
            target,
        });
        self.code.decls.len() as u32 - 1
    }

    /// What the task's types say a type is, as far as storing values
    /// needs it.
    fn shape(&self, ty: &Ty) -> Shape {
        if ty.dims() > 0 {
            return Shape::Array;
        }
        let types = self.names.types();
        let base = types.base(ty);
        if base.is("num") {
            Shape::Num
        } else if base.is("dnum") {
            Shape::Dnum
        } else if base.is("bool") {
            Shape::Bool
        } else if base.is("string") {
            Shape::Str
        } else if types.components(ty).is_some_and(|c| !c.is_empty()) {
            Shape::Record
        } else {
            Shape::Other
        }
    }

    /// How a value is stored as type `ty` (`None`: as it is).
    fn conv(&mut self, ty: &Ty) -> Option<u32> {
        let conv = match self.shape(ty) {
            Shape::Num => Conv::Num,
            Shape::Dnum => Conv::Dnum,
            Shape::Record | Shape::Array => Conv::Full(type_of_ty(ty)?),
            Shape::Bool | Shape::Str | Shape::Other => return None,
        };
        self.code.convs.push(conv);
        Some(self.code.convs.len() as u32 - 1)
    }

    fn type_index(&mut self, ty: Type) -> u32 {
        self.code.types.push(ty);
        self.code.types.len() as u32 - 1
    }

    /// The slot of a `FOR` variable or routine data known by its name's
    /// range.
    fn slot_at(list: &[(Range<usize>, u32)], range: &Range<usize>) -> Option<u32> {
        list.iter().rev().find(|(r, _)| r == range).map(|(_, s)| *s)
    }
}

/// What a type is, as far as storing values needs it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    Num,
    Dnum,
    Bool,
    Str,
    Record,
    Array,
    Other,
}

/// The evaluator's form of a type (array sizes 0: not known).
pub(crate) fn type_of_ty(ty: &Ty) -> Option<Type> {
    match ty {
        Ty::Named(n) => Some(Type::named(n.clone())),
        Ty::Array(e, d) => match e.as_ref() {
            Ty::Named(n) => Some(Type::array(n.clone(), vec![0; usize::from(*d)])),
            _ => None,
        },
        Ty::Unknown | Ty::Any => None,
    }
}

/// The value a `taskid` or `mecunit` name stands for.
pub(crate) fn named_object(ty: &str, name: &str) -> Value {
    Value::Record {
        ty: ty.to_owned(),
        fields: vec![("name".to_owned(), Value::Str(fold(name)))],
    }
}
