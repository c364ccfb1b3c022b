//! `sema`'s answers for readers outside the analyzer that walk a routine's
//! lowered body ([`crate::body`]) and need to know what its names denote:
//! the interpreter, which runs the body, asks here instead of resolving
//! names itself.
//!
//! A [`Resolver`] stands at a place (a module, or the start of a routine)
//! and answers with the one resolver the checker and the editor features
//! use ([`Scope::resolve_data`], [`Scope::resolve_routine`]); the reader
//! tells it where the `FOR` loops of the body begin and end, as it walks
//! them. The answers are owned values ([`DataRef`], [`Callee`]) that
//! outlive the resolver; calls are bound by the one binder
//! ([`crate::catalogue::binding::bind_args`]) with the signature the
//! checker checks them against (the task's catalogue view for built-ins).
//!
//! ```
//! use rapid_analyzer::resolve::{DataRef, Resolver};
//! use rapid_analyzer::task::{Task, Unit};
//! use std::sync::Arc;
//! let text = "MODULE m\n  VAR num n;\n  PROC main(num p)\n    FOR i FROM 1 TO 2 DO\n      n := p + i;\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
//! let task = Task::new(String::new(), vec![Arc::new(Unit::new("m.mod".into(), text.into(), None))], None);
//! let main = &task.units[0].items.modules[0].routines[0];
//! let mut r = Resolver::in_routine(&task, 0, main).unwrap();
//! assert!(matches!(r.data("P").unwrap().what, DataRef::Param(0)));
//! assert!(matches!(r.data("n").unwrap().what, DataRef::Item(_)));
//! r.enter_for("i", 0..0);
//! assert!(matches!(r.data("i").unwrap().what, DataRef::ForVar { .. }));
//! r.leave_for();
//! assert!(r.data("i").is_none());
//! ```

use std::ops::Range;

use super::def::Def;
use super::scope::Scope;
use super::signature::{Signature, bind_args};
use crate::catalogue::binding::{Arg, Binding};
use crate::catalogue::{Datum, Routine};
use crate::items::RoutineDecl;
use crate::names::fold;
use crate::task::{ItemRef, Task};
use crate::ty::{Ty, Types};

/// What a data name denotes.
#[derive(Clone, Debug, PartialEq)]
pub enum DataRef {
    /// Parameter `index` of the routine.
    Param(usize),
    /// Routine data, known by the range of its name.
    Local { name_range: Range<usize> },
    /// The variable of a `FOR` loop, known by the range of its name in the
    /// loop.
    ForVar { range: Range<usize> },
    /// Module data of the task.
    Item(ItemRef),
    /// Predefined data of the catalogue (`v100`, `ERRNO`, `ERR_DIVZERO`).
    Builtin(&'static Datum),
    /// An I/O signal the configuration declares, with its type
    /// (`signaldi`...).
    Signal { name: String, ty: &'static str },
    /// A mechanical unit the configuration declares (`mecunit` data).
    MecUnit(String),
    /// The `taskid` data of a task of the controller (`T_ROB1Id`).
    TaskId(String),
}

/// A data name's meaning and its declared type ([`Ty::Unknown`] when the
/// type is not known).
#[derive(Clone, Debug)]
pub struct DataName {
    pub what: DataRef,
    pub ty: Ty,
}

/// The routine a call names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Callee {
    /// A routine of the task.
    Routine(ItemRef),
    /// A built-in instruction or function, with the task's signature.
    Builtin(&'static Routine),
}

/// Names resolved at one place of a task, as the controller resolves them.
pub struct Resolver<'t> {
    scope: Scope<'t>,
}

impl<'t> Resolver<'t> {
    /// The names as the body of routine `routine` of unit `unit` sees them
    /// (its parameters, its data, its module's, the task's, the
    /// catalogue's and the configuration's), before any `FOR` loop.
    pub fn in_routine(task: &'t Task, unit: usize, routine: &RoutineDecl) -> Option<Resolver<'t>> {
        let scope = Scope::at(task, unit, routine.range.start)?;
        let here = scope.routine.as_ref()?;
        (here.decl.range == routine.range).then_some(Resolver { scope })
    }

    /// The names as module `module` of unit `unit` sees them (outside its
    /// routines: its data's initial values and array sizes).
    pub fn in_module(task: &'t Task, unit: usize, module: usize) -> Option<Resolver<'t>> {
        let u = task.units.get(unit)?;
        let m = u.items.modules.get(module)?;
        let mut scope = Scope::of_unit(task, unit, u);
        scope.module = Some((module, m));
        Some(Resolver { scope })
    }

    /// Enters a `FOR` loop whose variable is `name` (declared at `range`):
    /// until [`Resolver::leave_for`], the name denotes it.
    pub fn enter_for(&mut self, name: &str, range: Range<usize>) {
        if let Some(r) = &mut self.scope.routine {
            r.for_vars.push((fold(name), range));
        }
    }

    /// Leaves the innermost `FOR` loop entered.
    pub fn leave_for(&mut self) {
        if let Some(r) = &mut self.scope.routine {
            r.for_vars.pop();
        }
    }

    /// What the data name `name` denotes here.
    pub fn data(&self, name: &str) -> Option<DataName> {
        let def = self.scope.resolve_data(name)?;
        let what = match &def {
            Def::Param { decl, routine, .. } => {
                DataRef::Param(routine.params.iter().position(|p| std::ptr::eq(p, *decl))?)
            }
            Def::Local { decl, .. } => DataRef::Local {
                name_range: decl.name_range.clone(),
            },
            Def::ForVar { range, .. } => DataRef::ForVar {
                range: range.clone(),
            },
            Def::Item(r) => DataRef::Item(*r),
            Def::BuiltinDatum(d) => DataRef::Builtin(d),
            Def::Signal(name, "mecunit") => DataRef::MecUnit(name.clone()),
            Def::Signal(name, "taskid") => DataRef::TaskId(name.clone()),
            Def::Signal(name, ty) => DataRef::Signal {
                name: name.clone(),
                ty,
            },
            _ => return None,
        };
        Some(DataName {
            ty: def.ty(self.scope.task, &self.scope.types),
            what,
        })
    }

    /// The routine `name` denotes here: one of the task's, else a built-in
    /// (a function first where a function is wanted).
    pub fn routine(&self, name: &str, want_function: bool) -> Option<Callee> {
        match self.scope.resolve_routine(name, want_function)? {
            Def::Item(r) => Some(Callee::Routine(r)),
            Def::BuiltinRoutine(r) => Some(Callee::Builtin(r)),
            _ => None,
        }
    }

    /// The arguments of a call of `callee` bound to its parameters, as the
    /// checker binds them; `None` for a built-in whose parameters are not
    /// known at all (its calls are not checked either). A built-in whose
    /// parameters come from loaded code binds by them, though the checker
    /// does not check its calls.
    pub fn bind(&self, callee: &Callee, args: &[Arg<'_>]) -> Option<Binding> {
        let def = match callee {
            Callee::Routine(r) => Def::Item(*r),
            Callee::Builtin(r) => Def::BuiltinRoutine(r),
        };
        let sig = Signature::of(&def, self.scope.task)?;
        sig.binds().then(|| bind_args(&sig, args))
    }

    /// The task's types, as the checker knows them.
    pub fn types(&self) -> &Types<'t> {
        &self.scope.types
    }

    pub fn task(&self) -> &'t Task {
        self.scope.task
    }
}

/// A call and the parameter each of its arguments binds to.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct CallBinding {
    /// The start of the routine the call is in (`None`: outside routines,
    /// in a data declaration's value).
    pub routine: Option<usize>,
    /// The routine called, named as declared.
    pub callee: String,
    /// The parameter of each argument, in the order written.
    pub params: Vec<String>,
}

/// The bindings of the calls of unit `unit` as the checker sees them: from
/// the syntax tree, each call's routine resolved in the scope around it
/// and its arguments bound with the checker's signature. Calls whose
/// binding is not complete (an argument that binds to nothing or twice, a
/// missing one), whose kind does not fit the routine's (a function called
/// as an instruction), late-bound calls, `Present` and calls in code with
/// syntax errors are left out. The oracle of any other reader's
/// bindings (the interpreter's, [`Resolver::bind`] over the lowered body).
pub fn call_bindings(task: &Task, unit: usize) -> Vec<CallBinding> {
    use crate::syntax::{field, kind};
    let Some(u) = task.units.get(unit) else {
        return Vec::new();
    };
    let routines: Vec<std::ops::Range<usize>> = u
        .items
        .modules
        .iter()
        .flat_map(|m| m.routines.iter().map(|r| r.range.clone()))
        .collect();
    let tree = u.tree();
    let mut calls = Vec::new();
    crate::syntax_util::walk_pruned(tree.root_node(), &mut |n| {
        if n.is_error() || n.is_missing() {
            return false;
        }
        if matches!(n.kind(), kind::PROCEDURE_CALL | kind::FUNCTION_CALL) && !n.has_error() {
            calls.push(n);
        }
        true
    });
    let mut out = Vec::new();
    for call in calls {
        let Some(name) = call.child_by_field_name(field::NAME) else {
            continue;
        };
        if name.kind() != kind::IDENTIFIER {
            continue;
        }
        let name_text = u.text.get(name.byte_range()).unwrap_or_default();
        let function = call.kind() == kind::FUNCTION_CALL;
        if function && name_text.eq_ignore_ascii_case("present") {
            continue;
        }
        let routine = routines
            .iter()
            .find(|r| r.start <= call.start_byte() && call.end_byte() <= r.end)
            .map(|r| r.start);
        let Some(scope) = Scope::at(task, unit, routine.unwrap_or(call.start_byte())) else {
            continue;
        };
        let Some(def) = scope.resolve_routine(name_text, function) else {
            continue;
        };
        let Some(sig) = Signature::of(&def, task) else {
            continue;
        };
        if !sig.binds() || sig.is_function() != function {
            continue;
        }
        let mut cursor = call.walk();
        let args: Vec<_> = call
            .child_by_field_name(field::ARGUMENTS)
            .map(|a| {
                a.children_by_field_name(field::ARGUMENT, &mut cursor)
                    .collect()
            })
            .unwrap_or_default();
        let given: Vec<Arg<'_>> = args
            .iter()
            .map(|a| {
                let optional = {
                    let mut c = a.walk();
                    a.children(&mut c).any(|c| c.kind() == "\\")
                };
                match a
                    .child_by_field_name(field::NAME)
                    .and_then(|n| u.text.get(n.byte_range()))
                {
                    Some(n) => Arg::Named(n),
                    None if optional => Arg::Named(""),
                    None => Arg::Positional,
                }
            })
            .collect();
        let b = bind_args(&sig, &given);
        if !b.is_complete() {
            continue;
        }
        let params = (0..given.len())
            .filter_map(|k| sig.params.get(b.param_of(k)?).map(|p| p.name.clone()))
            .collect();
        out.push(CallBinding {
            routine,
            callee: sig.name.clone(),
            params,
        });
    }
    out
}
