//! A program ready to run: the modules of one task, their data laid out in
//! storage (module data, the persistents the controller's tasks share,
//! the catalogue's predefined data and the configured signals), their
//! routines compiled on their first call. Names are resolved by `sema`
//! ([`rapid_analyzer::resolve`]) when code is compiled; what is kept here
//! is where each declaration's value lives.

use std::collections::HashMap;
use std::ops::Range;
use std::sync::{Arc, Mutex, OnceLock};

use rapid_analyzer::catalogue::DatumKind;
use rapid_analyzer::catalogue::binding::Arg;
use rapid_analyzer::consteval::TypeEnv;
use rapid_analyzer::items::{RoutineDecl, RoutineKind, Scope, Storage};
use rapid_analyzer::names::{NameMap, fold};
use rapid_analyzer::resolve::{Callee, DataRef, Resolver};
use rapid_analyzer::task::{Item, ItemRef, Task};
use rapid_analyzer::text::LineIndex;
use rapid_evaluator::{Type, Value, parse_data_literal};

use crate::code::Code;

mod load;
mod modules;
pub use load::{LoadCheck, LoadError, TakenSignal, load_check, load_errors};
pub(crate) use modules::{LoadFailure, Symbol};

/// A place in a program's source, for messages and debuggers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The module file's path as the task names it.
    pub path: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub column: usize,
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}", self.path, self.line)
    }
}

/// A routine of the program, for listing (test discovery, entry points).
#[derive(Clone, Debug)]
pub struct RoutineSummary {
    pub id: u32,
    pub name: String,
    pub module: String,
    pub kind: RoutineKind,
    pub params: usize,
    pub local: bool,
    pub at: Location,
}

pub use rapid_analyzer::task::SignalKind;

/// A module of the program.
pub(crate) struct Module {
    pub unit: usize,
    /// Its index among its unit's modules.
    pub index: usize,
    pub name: String,
}

/// Where a data object of the program is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Home {
    /// In the task ([`Program::globals`]).
    Global(u32),
    /// A persistent every task of the controller shares
    /// ([`Program::pers`]).
    Pers(u32),
}

/// Where a data object comes from.
pub(crate) enum Origin {
    /// Declared in module `module` at `range`.
    Module { module: usize, range: Range<usize> },
    /// Predefined by the system (the catalogue).
    System,
    /// A configured I/O signal.
    Signal,
}

/// A data object of the task.
pub(crate) struct Global {
    pub name: String,
    pub storage: Storage,
    pub ty: Type,
    pub origin: Origin,
    /// Its starting value: known, or computed by code when a run starts.
    pub start: Start,
}

pub(crate) enum Start {
    Value(Value),
    Code(Arc<Code>),
}

/// A shared persistent of the program: its name (how the controller knows
/// it across tasks) and its declaration.
pub(crate) struct Pers {
    pub name: String,
    pub ty: Type,
    pub module: usize,
    pub range: Range<usize>,
    pub start: Option<Arc<Code>>,
    /// The declaration gives a value (`PERS num n := 5;`).
    pub valued: bool,
}

pub(crate) struct RoutineInfo {
    pub item: ItemRef,
    pub module: usize,
    pub decl: RoutineDecl,
    pub code: OnceLock<Arc<Code>>,
}

/// A loaded program: build it once per task, run it as often as needed
/// (each [`crate::Machine`] starts from fresh data).
pub struct Program {
    pub(crate) task: Arc<Task>,
    /// The task's types, as the evaluator asks for them.
    pub(crate) types: TypeEnv,
    pub(crate) lines: Vec<LineIndex>,
    pub(crate) modules: Vec<Module>,
    pub(crate) globals: Vec<Global>,
    pub(crate) pers: Vec<Pers>,
    /// Where each module data object is.
    pub(crate) items: HashMap<ItemRef, Home>,
    /// Predefined data and configured signals, by folded name.
    pub(crate) system: NameMap<u32>,
    pub(crate) routines: Vec<RoutineInfo>,
    pub(crate) routine_ids: HashMap<ItemRef, u32>,
    /// The slot of `ERRNO` (and `INTNO`), when the catalogue has them.
    pub(crate) errno: Option<u32>,
    pub(crate) intno: Option<u32>,
    /// The number of every predefined error (`ERR_*`), by folded name.
    pub(crate) errnums: NameMap<f32>,
    /// Routines named at run time (late binding, `CallByVar`), by the
    /// calling module and the folded name.
    late: Mutex<HashMap<(usize, String), Option<u32>>>,
    /// A module calls `ArgName`: a value parameter given a data object is
    /// passed as its place, so that `ArgName` can name the object (else
    /// as its value, which is quicker).
    pub(crate) arg_name: bool,
}

/// The first number given to the predefined errors (`ERR_*`); the
/// numbers follow the catalogue's order. Programs compare `ERRNO` with the
/// constants, never with these numbers.
pub const SYSTEM_ERRNO_BASE: f32 = 1001.0;

impl Program {
    /// Loads the modules of `task`. Signals are the ones its configuration
    /// declares (see [`Task::with_signals`] for a simulation's own), with
    /// `extra` besides.
    pub fn new(task: Arc<Task>, extra: &[(String, SignalKind)]) -> Program {
        let task = if extra.is_empty() {
            task
        } else {
            let extra: Vec<(String, &'static str)> = extra
                .iter()
                .map(|(n, k)| (n.clone(), k.type_name()))
                .collect();
            Arc::new(task.with_signals(&extra))
        };
        let mut p = Program {
            types: TypeEnv::of(&task),
            lines: task.units.iter().map(|u| LineIndex::new(&u.text)).collect(),
            modules: Vec::new(),
            globals: Vec::new(),
            pers: Vec::new(),
            items: HashMap::new(),
            system: NameMap::default(),
            routines: Vec::new(),
            routine_ids: HashMap::new(),
            errno: None,
            intno: None,
            errnums: NameMap::default(),
            late: Mutex::default(),
            arg_name: task.live_units().any(|(_, u)| {
                u.text
                    .as_bytes()
                    .windows(7)
                    .any(|w| w.eq_ignore_ascii_case(b"argname"))
            }),
            task: task.clone(),
        };
        // The modules' data and routines come last: a module loaded while
        // the program runs (`Load`) adds its own after them, and nothing
        // already laid out moves.
        p.add_system_data();
        p.add_signals();
        p.lay_out_modules();
        p.compile_starts();
        p
    }

    /// Module data and routines, in the task's order; a view of a task
    /// (one of alternative programs) without the units it leaves out.
    fn lay_out_modules(&mut self) {
        let task = self.task.clone();
        for (u, unit) in task.live_units() {
            for (mi, m) in unit.items.modules.iter().enumerate() {
                let module = self.modules.len();
                self.modules.push(Module {
                    unit: u,
                    index: mi,
                    name: m.name.clone(),
                });
                for (i, d) in m.data.iter().enumerate() {
                    let item = ItemRef {
                        unit: u,
                        module: mi,
                        item: Item::Data(i),
                    };
                    let ty = Type::array(
                        d.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                        vec![0; d.dims.len()],
                    );
                    let shared = d.storage == Storage::Pers && d.scope == Scope::Global;
                    let home = if shared {
                        self.pers.push(Pers {
                            name: d.name.clone(),
                            ty,
                            module,
                            range: d.range.clone(),
                            start: None,
                            valued: d.init.is_some(),
                        });
                        Home::Pers(self.pers.len() as u32 - 1)
                    } else {
                        self.globals.push(Global {
                            name: d.name.clone(),
                            storage: d.storage,
                            ty,
                            origin: Origin::Module {
                                module,
                                range: d.range.clone(),
                            },
                            start: Start::Value(Value::Num(0.0)),
                        });
                        Home::Global(self.globals.len() as u32 - 1)
                    };
                    self.items.insert(item, home);
                }
                for (i, r) in m.routines.iter().enumerate() {
                    let item = ItemRef {
                        unit: u,
                        module: mi,
                        item: Item::Routine(i),
                    };
                    self.routine_ids.insert(item, self.routines.len() as u32);
                    self.routines.push(RoutineInfo {
                        item,
                        module,
                        decl: r.clone(),
                        code: OnceLock::new(),
                    });
                }
            }
        }
    }

    /// The catalogue's predefined data, as data of every task.
    fn add_system_data(&mut self) {
        let mut next_errno = SYSTEM_ERRNO_BASE;
        for d in &self.task.catalogue.data {
            let key = fold(&d.name);
            if self.system.contains_key(&key) {
                continue;
            }
            let ty = Type::named(d.ty.clone());
            let value = if key.starts_with("err_") && fold(&d.ty) == "errnum" {
                let v = next_errno;
                next_errno += 1.0;
                self.errnums.insert(key.clone(), v);
                Value::Num(v)
            } else {
                d.value
                    .as_deref()
                    .and_then(parse_data_literal)
                    .and_then(|e| rapid_evaluator::eval_as(&e, Some(&ty), &self.types).ok())
                    .or_else(|| rapid_evaluator::predefined(&d.name))
                    .unwrap_or_else(|| self.zero(&ty))
            };
            let storage = match d.kind {
                DatumKind::Const => Storage::Const,
                DatumKind::Var => Storage::Var,
                DatumKind::Pers => Storage::Pers,
            };
            let id = self.globals.len() as u32;
            self.globals.push(Global {
                name: d.name.clone(),
                storage,
                ty,
                origin: Origin::System,
                start: Start::Value(value),
            });
            match key.as_str() {
                "errno" => self.errno = Some(id),
                "intno" => self.intno = Some(id),
                _ => {}
            }
            self.system.insert(key, id);
        }
    }

    /// The signals the task's configuration declares, in name order.
    fn add_signals(&mut self) {
        let mut signals: Vec<(String, &'static str)> = self
            .task
            .signals
            .iter()
            .flat_map(|s| s.iter())
            .map(|(n, t)| (n.clone(), *t))
            .collect();
        signals.sort();
        for (name, ty) in signals {
            let key = fold(&name);
            if self.system.contains_key(&key) {
                continue;
            }
            let id = self.globals.len() as u32;
            self.globals.push(Global {
                name: name.clone(),
                storage: Storage::Var,
                ty: Type::named(ty),
                origin: Origin::Signal,
                start: Start::Value(signal_value(ty, &name)),
            });
            self.system.insert(key, id);
        }
    }

    /// The code that computes each module data object's starting value.
    fn compile_starts(&mut self) {
        let task = self.task.clone();
        let mut starts = Vec::new();
        for (item, home) in &self.items {
            let Some(d) = task.data(*item) else { continue };
            let Some(module) = self.module_of(item.unit, item.module) else {
                continue;
            };
            let Some(r) = Resolver::in_module(&task, item.unit, item.module) else {
                continue;
            };
            let code = crate::compile::data_start(self, r, module, d, *home);
            starts.push((*home, code));
        }
        for (home, code) in starts {
            let code = Arc::new(code);
            match home {
                Home::Global(g) => {
                    if let Some(g) = self.globals.get_mut(g as usize) {
                        g.start = Start::Code(code);
                    }
                }
                Home::Pers(k) => {
                    if let Some(p) = self.pers.get_mut(k as usize) {
                        p.start = Some(code);
                    }
                }
            }
        }
    }

    /// The program's module of module `index` of unit `unit`.
    pub(crate) fn module_of(&self, unit: usize, index: usize) -> Option<usize> {
        self.modules
            .iter()
            .position(|m| m.unit == unit && m.index == index)
    }

    /// The value data of type `ty` starts with when not initialised.
    pub(crate) fn zero(&self, ty: &Type) -> Value {
        if ty.dims.iter().product::<usize>() > MAX_ELEMENTS {
            return Value::Array(Vec::new());
        }
        rapid_evaluator::zero_value(ty, &self.types, &opaque_zero)
    }

    /// The signals of the program (configured or given), with their kinds.
    pub fn signals(&self) -> Vec<(String, SignalKind)> {
        self.globals
            .iter()
            .filter(|g| matches!(g.origin, Origin::Signal))
            .filter_map(|g| Some((g.name.clone(), SignalKind::from_type(&g.ty.name)?)))
            .collect()
    }

    /// The routine an entry point or a test names: a global routine, else
    /// a `LOCAL` one of that name (as the controller's `Task` named
    /// entry works from any module).
    pub fn find_routine(&self, name: &str) -> Option<u32> {
        let global = self
            .routines
            .iter()
            .position(|r| !r.decl.local && r.decl.name.eq_ignore_ascii_case(name));
        global
            .or_else(|| {
                self.routines
                    .iter()
                    .position(|r| r.decl.name.eq_ignore_ascii_case(name))
            })
            .map(|i| i as u32)
    }

    /// Every routine of the program, in the task's order.
    pub fn routines(&self) -> Vec<RoutineSummary> {
        self.routines
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let module = self.modules.get(r.module);
                RoutineSummary {
                    id: i as u32,
                    name: r.decl.name.clone(),
                    module: module.map(|m| m.name.clone()).unwrap_or_default(),
                    kind: r.decl.kind,
                    params: r.decl.params.len(),
                    local: r.decl.local,
                    at: self.location(module.map_or(0, |m| m.unit), r.decl.name_range.start),
                }
            })
            .collect()
    }

    /// The instructions and functions of the simulated controller that a
    /// run would stop at (not supported in the simulation), with where
    /// each is called, in the order of the routines and their statements
    /// (every routine is compiled, whether a run reaches it or not).
    pub fn unsupported(&self) -> Vec<(String, Location)> {
        let mut out = Vec::new();
        for id in 0..self.routines.len() as u32 {
            let Some(code) = self.code(id) else { continue };
            for (pc, op) in code.ops.iter().enumerate() {
                let crate::code::Op::Fail(i) = op else {
                    continue;
                };
                let Some(crate::code::Failure::Unsupported(name)) = code.failures.get(*i as usize)
                else {
                    continue;
                };
                // The innermost statement whose operations hold it.
                let offset = code
                    .stmts
                    .iter()
                    .filter(|s| (s.start as usize) <= pc && pc < s.end as usize)
                    .min_by_key(|s| s.end - s.start)
                    .map_or(code.range.start, |s| s.range.start);
                out.push((name.clone(), self.location(code.unit, offset)));
            }
        }
        out
    }

    /// The source location of byte `offset` of unit `unit`.
    pub fn location(&self, unit: usize, offset: usize) -> Location {
        match (self.task.units.get(unit), self.lines.get(unit)) {
            (Some(u), Some(lines)) => {
                let (line, column) = lines.human(offset, &u.text);
                Location {
                    path: u.path.clone(),
                    line,
                    column,
                }
            }
            _ => Location {
                path: String::new(),
                line: 0,
                column: 0,
            },
        }
    }

    /// The 1-based line of byte `offset` of unit `unit`.
    pub(crate) fn line(&self, unit: usize, offset: usize) -> u32 {
        self.location(unit, offset).line as u32
    }

    /// The task the program was loaded from.
    pub fn task(&self) -> &Arc<Task> {
        &self.task
    }

    /// The compiled form of routine `id` (compiled on first use).
    pub(crate) fn code(&self, id: u32) -> Option<&Arc<Code>> {
        let info = self.routines.get(id as usize)?;
        Some(
            info.code
                .get_or_init(|| Arc::new(crate::compile::routine(self, id))),
        )
    }

    /// The name of predefined error number `n`, if it is one.
    pub(crate) fn errnum_name(&self, n: f32) -> Option<String> {
        self.errnums
            .iter()
            .find(|(_, v)| **v == n)
            .map(|(k, _)| k.to_ascii_uppercase())
    }

    /// The procedure `name` names when called at run time from module
    /// `module` (late binding, `CallByVar`), resolved as a call written
    /// there would be: the module's own routines, then the task's. A name
    /// `Module:Routine` names a routine of that module.
    pub(crate) fn routine_named(&self, module: usize, name: &str) -> Option<u32> {
        let key = (module, fold(name));
        if let Ok(cache) = self.late.lock()
            && let Some(hit) = cache.get(&key)
        {
            return *hit;
        }
        let found = self.resolve_routine(module, name);
        if let Ok(mut cache) = self.late.lock() {
            cache.insert(key, found);
        }
        found
    }

    fn resolve_routine(&self, module: usize, name: &str) -> Option<u32> {
        let (module, name) = match name.split_once(':') {
            Some((m, r)) => (
                self.modules
                    .iter()
                    .position(|md| md.name.eq_ignore_ascii_case(m.trim()))?,
                r.trim(),
            ),
            None => (module, name),
        };
        let m = self.modules.get(module)?;
        let resolver = Resolver::in_module(&self.task, m.unit, m.index)?;
        match resolver.routine(name, false)? {
            Callee::Routine(item) => self.routine_ids.get(&item).copied(),
            Callee::Builtin(_) => None,
        }
    }

    /// The data object `name` names at run time from module `module`
    /// (`GetDataVal`, `SetDataVal`), resolved as a name written there.
    pub(crate) fn data_named(&self, module: usize, name: &str) -> Option<Home> {
        let m = self.modules.get(module)?;
        let resolver = Resolver::in_module(&self.task, m.unit, m.index)?;
        match resolver.data(name)?.what {
            DataRef::Item(item) => self.items.get(&item).copied(),
            DataRef::Builtin(d) => self.system.get(&fold(&d.name)).map(|&g| Home::Global(g)),
            DataRef::Signal { name, .. } => self.system.get(&fold(&name)).map(|&g| Home::Global(g)),
            _ => None,
        }
    }

    /// The arguments of a call of routine `id` made at run time (late
    /// binding), written with `names`, bound to its parameters: the
    /// parameter of each argument.
    pub(crate) fn bind_late(
        &self,
        id: u32,
        names: &[Option<Box<str>>],
    ) -> Result<Vec<u32>, String> {
        let info = self
            .routines
            .get(id as usize)
            .ok_or("a routine that does not exist")?;
        let m = self
            .modules
            .get(info.module)
            .ok_or("a routine that does not exist")?;
        let resolver = Resolver::in_module(&self.task, m.unit, m.index)
            .ok_or("a module that cannot be read")?;
        let shapes: Vec<Arg<'_>> = names
            .iter()
            .map(|n| match n {
                Some(n) => Arg::Named(n),
                None => Arg::Positional,
            })
            .collect();
        let b = resolver
            .bind(&Callee::Routine(info.item), &shapes)
            .ok_or("the routine's parameters are not known")?;
        if !b.is_complete() {
            return Err(format!(
                "the arguments do not fit the parameters of {}",
                info.decl.name
            ));
        }
        Ok((0..names.len())
            .filter_map(|k| b.param_of(k).map(|i| i as u32))
            .collect())
    }

    /// Every call of the program bound, as the interpreter bound it: by
    /// unit, the routine it is in (by its start; `None` for a data
    /// object's value) with the routine called and the parameter of each
    /// argument. Compiles every routine. For the oracle that compares the
    /// interpreter's bindings with the checker's
    /// ([`rapid_analyzer::resolve::call_bindings`]).
    pub fn call_bindings(&self) -> Vec<(usize, rapid_analyzer::resolve::CallBinding)> {
        let mut codes: Vec<(Option<usize>, Arc<Code>)> = Vec::new();
        for id in 0..self.routines.len() {
            if let Some(code) = self.code(id as u32) {
                codes.push((Some(code.range.start), code.clone()));
            }
        }
        for g in &self.globals {
            if let Start::Code(code) = &g.start {
                codes.push((None, code.clone()));
            }
        }
        codes.extend(
            self.pers
                .iter()
                .filter_map(|p| Some((None, p.start.clone()?))),
        );
        codes
            .into_iter()
            .flat_map(|(routine, code)| {
                code.bindings
                    .iter()
                    .map(|(callee, params)| {
                        (
                            code.unit,
                            rapid_analyzer::resolve::CallBinding {
                                routine,
                                callee: callee.clone(),
                                params: params.clone(),
                            },
                        )
                    })
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    /// The number of the predefined error `name` (`ERR_TP_MAXTIME`), 0
    /// when the catalogue has no such error.
    pub(crate) fn errnum(&self, name: &str) -> f32 {
        self.errnums
            .get(&name.to_ascii_lowercase())
            .copied()
            .unwrap_or(0.0)
    }

    /// The global of predefined data or a signal named `name`.
    pub(crate) fn system_global(&self, name: &str) -> Option<u32> {
        self.system.get(&fold(name)).copied()
    }

    /// Why the name `name`, which nothing of the task declares, cannot run
    /// (the controller would not have linked the program): a persistent
    /// of another task of the controller that this task does not declare,
    /// else a name declared nowhere the run can see (the module that
    /// declares it is not in the repository). A data name may be a signal
    /// the configuration lacks: `--set` declares one.
    pub(crate) fn undeclared(&self, name: &str, data: bool) -> String {
        let other = self
            .task
            .shared
            .get(&fold(name))
            .and_then(|p| p.iter().find(|p| p.task != self.task.key));
        match other {
            Some(p) => format!(
                "`{name}` {DECLARED_NOWHERE} in this task: it is a persistent of {} ({}), and a task that uses a persistent declares it too",
                p.task.rsplit(['/', '\\']).next().unwrap_or(&p.task),
                p.path
            ),
            None if data => format!(
                "`{name}` {DECLARED_NOWHERE} (in no module of the task, nor a built-in the catalogue knows): the module that declares it is missing (if it is an I/O signal the configuration lacks, --set {name}=VALUE declares it)"
            ),
            None => format!(
                "`{name}` {DECLARED_NOWHERE} (in no module of the task, nor a built-in the catalogue knows): the module that declares it is missing"
            ),
        }
    }
}

/// What the message of a run stopped by a name nothing declares says
/// ([`Program::undeclared`]): `` `NAME` is declared nowhere ``.
pub const DECLARED_NOWHERE: &str = "is declared nowhere";

/// The largest array the interpreter makes (elements in all).
pub(crate) const MAX_ELEMENTS: usize = 1 << 20;

/// The value of a signal data object: the signal it stands for (an empty
/// name: none, as a signal variable before `AliasIO`).
pub(crate) fn signal_value(ty: &str, name: &str) -> Value {
    Value::Record {
        ty: ty.to_owned(),
        fields: vec![("name".to_owned(), Value::Str(name.to_owned()))],
    }
}

/// The starting value of a type the simulation keeps in its own form
/// (signals, clocks, files, sockets, task and unit references).
pub(crate) fn opaque_zero(folded: &str) -> Value {
    let record = |fields: Vec<(&str, Value)>| Value::Record {
        ty: folded.to_owned(),
        fields: fields.into_iter().map(|(n, v)| (n.to_owned(), v)).collect(),
    };
    match folded {
        s if s.starts_with("signal") => signal_value(s, ""),
        "clock" => record(vec![
            ("running", Value::Bool(false)),
            ("start", Value::Dnum(0.0)),
            ("elapsed", Value::Dnum(0.0)),
        ]),
        "iodev" | "dir" | "socketdev" => record(vec![("handle", Value::Num(0.0))]),
        _ => record(Vec::new()),
    }
}
