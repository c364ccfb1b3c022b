//! A program ready to run: the modules of one task with every name the
//! interpreter can meet resolved once (module data, routines, the
//! catalogue's predefined data, configured signals), and routines compiled
//! on their first call.

use std::ops::Range;
use std::sync::{Arc, OnceLock};

use rapid_analyzer::catalogue::DatumKind;
use rapid_analyzer::items::{RoutineDecl, RoutineKind, Scope, Storage};
use rapid_analyzer::names::{NameMap, fold};
use rapid_analyzer::task::Task;
use rapid_analyzer::text::LineIndex;
use rapid_evaluator::{Type, Value, parse_data_literal};

use crate::code::{Conv, Expr, Routine};
use crate::compile::Compiler;
use crate::types::Types;

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

/// The kind of an I/O signal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SignalKind {
    DigitalIn,
    DigitalOut,
    AnalogIn,
    AnalogOut,
    GroupIn,
    GroupOut,
}

impl SignalKind {
    /// The RAPID type of the signal (`signaldi` ...).
    pub fn type_name(self) -> &'static str {
        match self {
            SignalKind::DigitalIn => "signaldi",
            SignalKind::DigitalOut => "signaldo",
            SignalKind::AnalogIn => "signalai",
            SignalKind::AnalogOut => "signalao",
            SignalKind::GroupIn => "signalgi",
            SignalKind::GroupOut => "signalgo",
        }
    }

    /// The kind a signal's name suggests, for signals no configuration
    /// declares: `di...`, `do...`, `ai...`, `ao...`, `gi...`, `go...`; a
    /// digital input otherwise.
    pub fn guess(name: &str) -> SignalKind {
        match name.get(..2).map(str::to_ascii_lowercase).as_deref() {
            Some("do") => SignalKind::DigitalOut,
            Some("ai") => SignalKind::AnalogIn,
            Some("ao") => SignalKind::AnalogOut,
            Some("gi") => SignalKind::GroupIn,
            Some("go") => SignalKind::GroupOut,
            _ => SignalKind::DigitalIn,
        }
    }

    /// The kind of a RAPID signal type name.
    pub fn from_type(name: &str) -> Option<SignalKind> {
        Some(match fold(name).as_str() {
            "signaldi" => SignalKind::DigitalIn,
            "signaldo" => SignalKind::DigitalOut,
            "signalai" => SignalKind::AnalogIn,
            "signalao" => SignalKind::AnalogOut,
            "signalgi" => SignalKind::GroupIn,
            "signalgo" => SignalKind::GroupOut,
            _ => return None,
        })
    }
}

pub(crate) struct Module {
    pub unit: usize,
    pub name: String,
    pub data: NameMap<u32>,
    pub routines: NameMap<u32>,
}

/// Where a global data object comes from.
pub(crate) enum Origin {
    /// Declared in module `module` at `range`.
    Module { module: usize, range: Range<usize> },
    /// Predefined by the system (the catalogue).
    System,
    /// A configured I/O signal.
    Signal,
}

/// A data object of the task (module data, predefined data, signals).
pub(crate) struct Global {
    pub name: String,
    pub storage: Storage,
    pub ty: Type,
    pub origin: Origin,
    /// How to compute its starting value (compiled when the program loads).
    pub start: Start,
}

pub(crate) enum Start {
    /// Dimensions and initial value, evaluated when a run starts.
    Eval {
        dims: Vec<Expr>,
        init: Option<Expr>,
        conv: Conv,
    },
    /// A value known when the program loads.
    Value(Value),
}

pub(crate) struct RoutineInfo {
    pub module: usize,
    pub decl: RoutineDecl,
    pub compiled: OnceLock<Arc<Routine>>,
}

/// A loaded program: build it once per task, run it as often as needed
/// (each [`crate::Machine`] starts from fresh data).
pub struct Program {
    pub(crate) task: Arc<Task>,
    pub(crate) types: Types,
    pub(crate) lines: Vec<LineIndex>,
    pub(crate) modules: Vec<Module>,
    pub(crate) globals: Vec<Global>,
    pub(crate) global_data: NameMap<u32>,
    pub(crate) routines: Vec<RoutineInfo>,
    pub(crate) global_routines: NameMap<u32>,
    /// The slot of `ERRNO` (and `INTNO`), when the catalogue has them.
    pub(crate) errno: Option<u32>,
    pub(crate) intno: Option<u32>,
    /// The number of every predefined error (`ERR_*`), by folded name, and
    /// the names by number.
    pub(crate) errnums: NameMap<f32>,
}

/// The first number given to the predefined errors (`ERR_*`); the
/// numbers follow the catalogue's order. Programs compare `ERRNO` with the
/// constants, never with these numbers.
pub const SYSTEM_ERRNO_BASE: f32 = 1001.0;

impl Program {
    /// Loads the modules of `task`, with extra signals (name and kind)
    /// besides the ones its configuration declares.
    pub fn new(task: Arc<Task>, extra_signals: &[(String, SignalKind)]) -> Program {
        let lines = task.units.iter().map(|u| LineIndex::new(&u.text)).collect();
        let types = Types::new(&task);
        let mut p = Program {
            types,
            lines,
            modules: Vec::new(),
            globals: Vec::new(),
            global_data: NameMap::default(),
            routines: Vec::new(),
            global_routines: NameMap::default(),
            errno: None,
            intno: None,
            errnums: NameMap::default(),
            task: task.clone(),
        };
        let mut raw: Vec<(
            u32,
            Vec<rapid_evaluator::Expr>,
            Option<rapid_evaluator::Expr>,
        )> = Vec::new();
        for (u, unit) in task.units.iter().enumerate() {
            for m in &unit.items.modules {
                let mi = p.modules.len();
                let mut module = Module {
                    unit: u,
                    name: m.name.clone(),
                    data: NameMap::default(),
                    routines: NameMap::default(),
                };
                for d in &m.data {
                    let id = p.globals.len() as u32;
                    let ty = Type::array(
                        d.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                        vec![0; d.dims.len()],
                    );
                    p.globals.push(Global {
                        name: d.name.clone(),
                        storage: d.storage,
                        ty,
                        origin: Origin::Module {
                            module: mi,
                            range: d.range.clone(),
                        },
                        start: Start::Value(Value::Num(0.0)),
                    });
                    let dims = d
                        .dims
                        .iter()
                        .map(|r| {
                            rapid_analyzer::body::expression_at(unit, r.clone())
                                .unwrap_or(rapid_evaluator::Expr::Unknown)
                        })
                        .collect();
                    let init = d
                        .init
                        .as_ref()
                        .map(|r| rapid_analyzer::body::expression_at(unit, r.clone()))
                        .map(|e| e.unwrap_or(rapid_evaluator::Expr::Unknown));
                    raw.push((id, dims, init));
                    let key = fold(&d.name);
                    module.data.entry(key.clone()).or_insert(id);
                    if d.scope != Scope::Local {
                        p.global_data.entry(key).or_insert(id);
                    }
                }
                for r in &m.routines {
                    let id = p.routines.len() as u32;
                    p.routines.push(RoutineInfo {
                        module: mi,
                        decl: r.clone(),
                        compiled: OnceLock::new(),
                    });
                    let key = fold(&r.name);
                    module.routines.entry(key.clone()).or_insert(id);
                    if !r.local {
                        p.global_routines.entry(key).or_insert(id);
                    }
                }
                p.modules.push(module);
            }
        }
        p.add_system_data();
        let mut signals: Vec<(String, SignalKind)> = task
            .signals
            .iter()
            .flat_map(|s| s.iter())
            .filter_map(|(n, t)| Some((n.clone(), SignalKind::from_type(t)?)))
            .collect();
        signals.sort_by(|a, b| a.0.cmp(&b.0));
        signals.extend(extra_signals.iter().cloned());
        for (name, kind) in signals {
            p.add_signal(&name, kind);
        }
        // Module data: dimensions and initial values compiled in their
        // module's scope.
        for (id, dims, init) in raw {
            let Some(g) = p.globals.get(id as usize) else {
                continue;
            };
            let Origin::Module { module, .. } = g.origin else {
                continue;
            };
            let ty = g.ty.clone();
            let c = Compiler::for_module(&p, module);
            let dims = dims
                .iter()
                .map(|d| c.expr(d, Some(&Type::named("num"))))
                .collect();
            let init = init.map(|e| c.expr(&e, Some(&ty)));
            let conv = c.conv(&ty);
            if let Some(g) = p.globals.get_mut(id as usize) {
                g.start = Start::Eval { dims, init, conv };
            }
        }
        p
    }

    /// The catalogue's predefined data, as globals of every task.
    fn add_system_data(&mut self) {
        let mut next_errno = SYSTEM_ERRNO_BASE;
        for d in &self.task.catalogue.data {
            let key = fold(&d.name);
            if self.global_data.contains_key(&key) {
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
                    .and_then(|e| {
                        rapid_evaluator::eval_as(
                            &e,
                            Some(&ty),
                            &crate::types::TypesEnv(&self.types),
                        )
                        .ok()
                    })
                    .or_else(|| rapid_evaluator::predefined(&d.name))
                    .unwrap_or_else(|| self.types.zero(&ty))
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
            self.global_data.insert(key, id);
        }
    }

    fn add_signal(&mut self, name: &str, kind: SignalKind) {
        let key = fold(name);
        if self.global_data.contains_key(&key) {
            return;
        }
        let id = self.globals.len() as u32;
        let ty = kind.type_name();
        self.globals.push(Global {
            name: name.to_owned(),
            storage: Storage::Var,
            ty: Type::named(ty),
            origin: Origin::Signal,
            start: Start::Value(Value::Record {
                ty: ty.to_owned(),
                fields: vec![("name".to_owned(), Value::Str(name.to_owned()))],
            }),
        });
        self.global_data.insert(key, id);
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
    /// a `LOCAL` one of that name.
    pub fn find_routine(&self, name: &str) -> Option<u32> {
        let key = fold(name);
        self.global_routines.get(&key).copied().or_else(|| {
            self.modules
                .iter()
                .find_map(|m| m.routines.get(&key).copied())
        })
    }

    /// The routine `name` as module `module` sees it: its own (`LOCAL`
    /// ones too), else a global one.
    pub(crate) fn routine_from(&self, module: usize, name: &str) -> Option<u32> {
        let key = fold(name);
        self.modules
            .get(module)
            .and_then(|m| m.routines.get(&key))
            .or_else(|| self.global_routines.get(&key))
            .copied()
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

    /// The task the program was loaded from.
    pub fn task(&self) -> &Arc<Task> {
        &self.task
    }

    /// The compiled form of routine `id` (compiled on first use).
    pub(crate) fn routine(&self, id: u32) -> Option<&Arc<Routine>> {
        let info = self.routines.get(id as usize)?;
        Some(
            info.compiled
                .get_or_init(|| Arc::new(Compiler::routine(self, id))),
        )
    }

    /// The name of predefined error number `n`, if it is one.
    pub(crate) fn errnum_name(&self, n: f32) -> Option<String> {
        self.errnums
            .iter()
            .find(|(_, v)| **v == n)
            .map(|(k, _)| k.to_ascii_uppercase())
    }
}
