//! A task: the modules that are loaded together on one controller task, and
//! the index of the names they declare.
//!
//! Grouping follows the controller's layout: in a backup,
//! `.../RAPID/TASKn/{SYSMOD,PROGMOD}/...` is task `TASKn`; elsewhere the
//! modules of one folder form one task. Tasks never see each other's names.

use std::collections::{HashMap, HashSet};
use std::ops::Range;
use std::sync::Arc;

use tree_sitter::Tree;

use crate::diagnostic::Diagnostic;
use crate::items::{DataDecl, FileItems, Module, RecordDecl, RoutineDecl, Scope, Storage, hash_of};
use crate::layout::Grouping;
use crate::names::{NameMap, fold};
use crate::ty::{Types, UserType};
use crate::unit_tree::UnitTree;

/// One parsed file with its item tree. Immutable once built: an edit makes
/// a new unit (reusing the old tree for an incremental parse).
#[derive(Debug)]
pub struct Unit {
    /// The file's path as the caller names it (used for task grouping and
    /// in related locations).
    pub path: String,
    pub text: String,
    /// The syntax tree ([`Unit::tree`]); it may have been released
    /// ([`Unit::release_tree`]) and is then parsed again on use.
    tree: UnitTree,
    pub items: FileItems,
    pub interface: u64,
    /// A hash of the values of the unit's module data and the sizes of its
    /// arrays (which constant evaluation reads; the interface leaves them out).
    pub constants: u64,
    pub syntax: Vec<Diagnostic>,
    /// The parts of the text nested too deep to analyse: the tree is that
    /// of a copy of the text with these replaced ([`crate::nesting`]).
    cuts: Vec<crate::nesting::Cut>,
}

impl Unit {
    /// Parses and lowers `text`; `old` is the previous tree, already edited.
    pub fn new(path: String, text: String, old: Option<&Tree>) -> Unit {
        let mut parser = crate::syntax::parser();
        // The tree of a unit with parts nested too deep is not that of its
        // text ([`crate::nesting`]): never reuse it.
        let old = old.filter(|t| !crate::nesting::is_copy(t));
        let tree = crate::syntax::parse(&mut parser, &text, old)
            .or_else(|| crate::syntax::parse(&mut parser, "", None));
        Unit::from_tree(path, text, tree)
    }

    /// Builds a unit from a tree parsed by the caller.
    pub fn from_tree(path: String, text: String, tree: Option<Tree>) -> Unit {
        if tree.as_ref().is_some_and(crate::nesting::is_copy) {
            return Unit::new(path, text, None);
        }
        let Some(tree) = tree else {
            // Only a cancelled parse returns no tree; we never cancel. Keep
            // the file, empty, rather than fail.
            let mut parser = crate::syntax::parser();
            let tree = parser.parse("", None);
            return Unit::empty(path, text, tree);
        };
        let (tree, cuts) = crate::nesting::bound(&text, tree);
        let items = FileItems::lower(&tree, &text);
        let mut syntax = crate::syntax::syntax_diagnostics(&tree, &text);
        if !cuts.is_empty() {
            syntax.extend(crate::nesting::diagnostics(&text, &cuts));
            syntax.sort_by_key(|d| d.range.start);
        }
        Unit {
            interface: items.interface_hash(),
            constants: hash_of(&items.constants(&text)),
            path,
            text,
            tree: UnitTree::new(tree),
            items,
            syntax,
            cuts,
        }
    }

    /// Releases the syntax tree to save memory (most of a unit's memory is
    /// its tree); the next use of [`Unit::tree`] parses the text again.
    /// Everything else (items, interface, syntax diagnostics) stays.
    pub fn release_tree(&mut self) {
        self.tree.release();
    }

    /// The syntax tree, parsed again from the text if it was released.
    pub fn tree(&self) -> &Tree {
        if self.cuts.is_empty() {
            self.tree.get(&self.text)
        } else {
            self.tree
                .get_or_init(|| crate::nesting::parse_copy(&self.text, &self.cuts))
        }
    }

    /// The parts of the text nested too deep to analyse (the tree has a
    /// placeholder or blanks there); empty for almost every file.
    pub fn cuts(&self) -> &[crate::nesting::Cut] {
        &self.cuts
    }

    fn empty(path: String, text: String, tree: Option<Tree>) -> Unit {
        match tree {
            Some(tree) => Unit {
                path,
                text,
                tree: UnitTree::new(tree),
                items: FileItems::default(),
                interface: 0,
                constants: 0,
                syntax: Vec::new(),
                cuts: Vec::new(),
            },
            // No tree even for empty text means the grammar could not be
            // loaded at all, which the grammar's own tests rule out.
            None => unreachable_tree(path, text),
        }
    }
}

fn unreachable_tree(path: String, _text: String) -> Unit {
    panic!("tree-sitter returned no tree for an empty text ({path})")
}

pub use crate::layout::{controller_of, task_key};

/// A system-global persistent declared in another task of the same
/// controller (see [`Task::shared`]).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct SharedPers {
    /// The name as declared.
    pub name: String,
    /// The type name as declared.
    pub ty: String,
    /// Whether that type is an `ALIAS` declared in its task (an alias and
    /// its base type are interchangeable, so no conflict is reported).
    pub alias: bool,
    /// The dimension expressions as written (`["3", "4"]`), empty for one
    /// value.
    pub dims: Vec<String>,
    /// The declaring task's key and file, and the name's byte range there.
    pub task: String,
    pub path: String,
    pub name_range: Range<usize>,
}

impl SharedPers {
    /// The type as RAPID writes it, with its dimensions: `num{3}`.
    pub fn display(&self) -> String {
        if self.dims.is_empty() {
            self.ty.clone()
        } else {
            format!("{}{{{}}}", self.ty, self.dims.join(","))
        }
    }
}

/// The system-global persistents of a controller's tasks, by folded name.
pub type SharedMap = HashMap<String, Vec<SharedPers>>;

/// The system-global persistents declared in `units` (the files of one
/// controller's `RAPID/TASKn` folders; files of other tasks are ignored), by
/// folded name, and a hash of them.
pub fn shared_persistents<'u>(units: impl Iterator<Item = &'u Arc<Unit>>) -> (SharedMap, u64) {
    let units: Vec<(String, &Arc<Unit>)> = units
        .map(|u| (task_key(&u.path), u))
        .filter(|(key, _)| controller_of(key).is_some())
        .collect();
    let mut aliases: std::collections::HashSet<(&str, String)> = Default::default();
    for (key, unit) in &units {
        for m in &unit.items.modules {
            aliases.extend(m.aliases.iter().map(|a| (key.as_str(), fold(&a.name))));
        }
    }
    let mut out = SharedMap::new();
    for (key, unit) in &units {
        for module in &unit.items.modules {
            for d in &module.data {
                if d.storage != Storage::Pers || d.scope != Scope::Global {
                    continue;
                }
                let Some(ty) = &d.ty else { continue };
                let dims = d
                    .dims
                    .iter()
                    .map(|r| {
                        unit.text
                            .get(r.clone())
                            .unwrap_or_default()
                            .trim()
                            .to_owned()
                    })
                    .collect();
                out.entry(fold(&d.name)).or_default().push(SharedPers {
                    name: d.name.clone(),
                    ty: ty.name.clone(),
                    alias: aliases.contains(&(key.as_str(), fold(&ty.name))),
                    dims,
                    task: key.clone(),
                    path: unit.path.clone(),
                    name_range: d.name_range.clone(),
                });
            }
        }
    }
    // By name (each list is in the stable order of the units).
    let hash = hash_of(&out.iter().collect::<std::collections::BTreeMap<_, _>>());
    (out, hash)
}

/// Where a declaration lives: unit (index in the task), module, and item.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ItemRef {
    pub unit: usize,
    pub module: usize,
    pub item: Item,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Item {
    Data(usize),
    Routine(usize),
    Record(usize),
    Alias(usize),
}

/// The modules of one task and the index of their names.
#[derive(Debug)]
pub struct Task {
    pub key: String,
    pub units: Vec<Arc<Unit>>,
    /// Global (non-`LOCAL`) declarations of every module, by folded name.
    pub globals: NameMap<Vec<ItemRef>>,
    /// `LOCAL` declarations, by folded name (to explain why a name is not
    /// visible from another module).
    pub locals: NameMap<Vec<ItemRef>>,
    /// Signals configured for this task (`EIO.cfg`): folded name to data
    /// type (`signaldi`...); `None` when no configuration was given.
    pub signals: Option<Signals>,
    /// Mechanical units configured for this task (`MOC.cfg`), folded; they
    /// are `mecunit` data.
    pub mecunits: std::collections::HashSet<String>,
    /// The robot the task's moves are made by (`MOC.cfg`, else the
    /// project's `[controller] robot`); set with [`Task::set_robot`].
    pub robot: Option<Arc<crate::robot::TaskRobot>>,
    /// Why a robot that is named is not used (not modelled, on a track).
    pub robot_note: Option<String>,
    /// The `taskid` data RobotWare declares for each task of the controller
    /// (the task's name and `Id`: `T_ROB1Id`), folded: from `SYS.cfg`'s
    /// tasks and the backup's task folders named after their task.
    pub task_ids: std::collections::HashSet<String>,
    /// The hash of what the task's files and controller declare
    /// ([`InterfaceInputs`]), for cache invalidation.
    pub interface: u64,
    inputs: InterfaceInputs,
    /// The hash of every unit's [`Unit::constants`], in order.
    pub constants: u64,
    /// The system-global persistents (`PERS`, neither `TASK` nor `LOCAL`)
    /// that the tasks of the same controller declare (this one included),
    /// by folded name
    /// (empty outside a backup's `RAPID/TASKn` folders): the controller
    /// shares them, so their types must agree. Set with [`Task::set_shared`].
    pub shared: Arc<SharedMap>,
    /// The catalogue as this task's controller has it (its RobotWare
    /// version and options; the union of every version when unknown). Set
    /// with [`Task::set_catalogue`].
    pub catalogue: &'static crate::catalogue::Catalogue,
    /// Memo of "did you mean" suggestions among the globals, by folded name.
    pub(crate) close_names: std::sync::Mutex<HashMap<String, Option<(usize, String)>>>,
    /// How the modules were grouped (set by the workspace).
    pub grouping: Grouping,
    /// A task of a real controller backup (one with its `SYSPAR`) whose
    /// every module is here: a name nothing declares would stop the
    /// controller from loading it, so it is an error, not a warning.
    pub complete: bool,
    /// Modules of a controller's `HOME/` folder that no task here loads: a
    /// program loads them at run time into a task that is not among the
    /// checked files, so the names they use from it cannot be checked (an
    /// unresolved name is a note, not a warning).
    pub loaded_elsewhere: bool,
    /// A view made for one unit (its index): the task as that unit sees it,
    /// without the modules that cannot be loaded with it ([`Task::excluded`]).
    /// `None` for a whole group.
    pub owner: Option<usize>,
    /// In a view, the modules of the group left out because they clash
    /// with the owner (another version of it): each with its file and its
    /// module names and their ranges.
    pub excluded: Vec<Excluded>,
    /// In a whole group, the units that clash with others, with the units
    /// each clashes with: they are checked in views of their own, not in
    /// this task.
    pub clashing: HashMap<usize, Vec<usize>>,
}

/// What [`Task::interface`] is the hash of: what each file declares for
/// the others and what the controller declares (configuration, task ids,
/// catalogue view, other tasks' shared persistents), without positions.
#[derive(Clone, Debug, Default, Hash)]
struct InterfaceInputs {
    /// Each unit's [`Unit::interface`], in the task's order.
    units: Vec<u64>,
    /// The derived hash of the configured signals with their types, sorted
    /// (`None`: no configuration declares signals). Hashed once when the
    /// task is built, not again by each setter below (a configuration may
    /// declare thousands).
    signals: Option<u64>,
    mecunits: Vec<String>,
    task_ids: Vec<String>,
    catalogue: Option<crate::catalogue::Selection>,
    /// The robot's [`crate::robot::TaskRobot::fingerprint`].
    robot: Option<String>,
    /// The hash [`shared_persistents`] gave.
    shared: u64,
}

fn sorted<T: Ord>(items: impl Iterator<Item = T>) -> Vec<T> {
    let mut out: Vec<T> = items.collect();
    out.sort();
    out
}

/// A module file that a view of a task leaves out.
#[derive(Clone, Debug)]
pub struct Excluded {
    pub path: String,
    /// The names of its modules, as declared, with their name ranges.
    pub modules: Vec<(String, Range<usize>)>,
}

impl Task {
    /// This task with `units` in place of its own: the same files in the
    /// same order (their items are what the name index points at), e.g.
    /// with their trees parsed again for one check. Everything else (the
    /// configuration, catalogue view, grouping, view, keys) is kept.
    pub fn with_units(&self, units: Vec<Arc<Unit>>) -> Task {
        Task {
            key: self.key.clone(),
            units,
            globals: self.globals.clone(),
            locals: self.locals.clone(),
            signals: self.signals.clone(),
            mecunits: self.mecunits.clone(),
            robot: self.robot.clone(),
            robot_note: self.robot_note.clone(),
            task_ids: self.task_ids.clone(),
            interface: self.interface,
            inputs: self.inputs.clone(),
            constants: self.constants,
            shared: self.shared.clone(),
            catalogue: self.catalogue,
            close_names: Default::default(),
            grouping: self.grouping,
            complete: self.complete,
            loaded_elsewhere: self.loaded_elsewhere,
            owner: self.owner,
            excluded: self.excluded.clone(),
            clashing: self.clashing.clone(),
        }
    }

    /// Sets [`Task::shared`] (with the hash [`shared_persistents`] gave):
    /// the task's interface hash then covers them, so cached results are
    /// dropped when another task's persistents change.
    pub fn set_shared(&mut self, shared: Arc<SharedMap>, hash: u64) {
        self.inputs.shared = hash;
        self.shared = shared;
        self.interface = hash_of(&self.inputs);
    }

    /// Sets [`Task::mecunits`] and [`Task::task_ids`]: names resolve
    /// through them, so the interface covers them.
    pub fn set_controller_names(&mut self, mecunits: HashSet<String>, task_ids: HashSet<String>) {
        self.inputs.mecunits = sorted(mecunits.iter().cloned());
        self.inputs.task_ids = sorted(task_ids.iter().cloned());
        self.mecunits = mecunits;
        self.task_ids = task_ids;
        self.interface = hash_of(&self.inputs);
    }

    pub fn new(key: String, units: Vec<Arc<Unit>>, signals: Option<Signals>) -> Task {
        let mut globals: NameMap<Vec<ItemRef>> = NameMap::default();
        let mut locals: NameMap<Vec<ItemRef>> = NameMap::default();
        for (u, unit) in units.iter().enumerate() {
            for (m, module) in unit.items.modules.iter().enumerate() {
                for (name, local, item) in module_items(module) {
                    let r = ItemRef {
                        unit: u,
                        module: m,
                        item,
                    };
                    let map = if local { &mut locals } else { &mut globals };
                    map.entry(fold(name)).or_default().push(r);
                }
            }
        }
        let inputs = InterfaceInputs {
            units: units.iter().map(|u| u.interface).collect(),
            signals: signals.as_ref().map(|s| hash_of(&sorted(s.iter()))),
            ..InterfaceInputs::default()
        };
        let constants: Vec<u64> = units.iter().map(|u| u.constants).collect();
        Task {
            key,
            units,
            globals,
            locals,
            signals,
            mecunits: Default::default(),
            robot: None,
            robot_note: None,
            interface: hash_of(&inputs),
            inputs,
            constants: hash_of(&constants),
            shared: Arc::default(),
            catalogue: crate::catalogue::base(),
            close_names: Default::default(),
            grouping: Grouping::Folder,
            complete: false,
            loaded_elsewhere: false,
            task_ids: Default::default(),
            owner: None,
            excluded: Vec::new(),
            clashing: Default::default(),
        }
    }

    /// Sets [`Task::catalogue`] to the view of `selection`: the interface
    /// hash covers it, so cached results are dropped when it changes.
    /// Sets the task's robot (or the note why the one named is not used).
    pub fn set_robot(&mut self, robot: Result<Option<Arc<crate::robot::TaskRobot>>, String>) {
        let (robot, note) = match robot {
            Ok(r) => (r, None),
            Err(note) => (None, Some(note)),
        };
        self.inputs.robot = robot.as_ref().map(|r| r.fingerprint());
        self.interface = hash_of(&self.inputs);
        self.robot = robot;
        self.robot_note = note;
    }

    pub fn set_catalogue(&mut self, selection: &crate::catalogue::Selection) {
        self.inputs.catalogue = Some(selection.clone());
        self.interface = hash_of(&self.inputs);
        self.catalogue = crate::catalogue::view(selection);
    }

    /// Is this task a task folder of a controller backup (so its modules
    /// were loaded together by a controller)?
    pub fn is_backup(&self) -> bool {
        self.grouping == Grouping::Backup
    }

    /// Are the modules known to be loaded together (a backup's task, or a
    /// `.pgf` program), rather than guessed from a shared folder?
    pub fn is_certain(&self) -> bool {
        self.grouping != Grouping::Folder
    }

    /// Is the unit at `idx` checked in this task (rather than in a view of
    /// its own, or in the group)?
    pub fn owns(&self, idx: usize) -> bool {
        match self.owner {
            Some(owner) => owner == idx,
            None => !self.clashing.contains_key(&idx),
        }
    }

    /// The units checked in this task ([`Task::owns`]), with their indexes.
    pub fn own_units(&self) -> impl Iterator<Item = (usize, &Arc<Unit>)> {
        self.units.iter().enumerate().filter(|(i, _)| self.owns(*i))
    }

    pub fn module(&self, r: ItemRef) -> Option<&Module> {
        self.units.get(r.unit)?.items.modules.get(r.module)
    }

    pub fn data(&self, r: ItemRef) -> Option<&DataDecl> {
        match r.item {
            Item::Data(i) => self.module(r)?.data.get(i),
            _ => None,
        }
    }

    pub fn routine(&self, r: ItemRef) -> Option<&RoutineDecl> {
        match r.item {
            Item::Routine(i) => self.module(r)?.routines.get(i),
            _ => None,
        }
    }

    pub fn record(&self, r: ItemRef) -> Option<&RecordDecl> {
        match r.item {
            Item::Record(i) => self.module(r)?.records.get(i),
            _ => None,
        }
    }

    /// The name and name range of an item.
    pub fn item_name(&self, r: ItemRef) -> Option<(&str, std::ops::Range<usize>)> {
        let m = self.module(r)?;
        Some(match r.item {
            Item::Data(i) => m
                .data
                .get(i)
                .map(|d| (d.name.as_str(), d.name_range.clone()))?,
            Item::Routine(i) => m
                .routines
                .get(i)
                .map(|d| (d.name.as_str(), d.name_range.clone()))?,
            Item::Record(i) => m
                .records
                .get(i)
                .map(|d| (d.name.as_str(), d.name_range.clone()))?,
            Item::Alias(i) => m
                .aliases
                .get(i)
                .map(|d| (d.name.as_str(), d.name_range.clone()))?,
        })
    }

    /// The types of the task: every record and alias, global or local (a
    /// local type used from another module is reported by name resolution).
    pub fn types(&self) -> Types<'_> {
        Types::new(
            self.units.iter().flat_map(|u| {
                u.items.modules.iter().flat_map(|m| {
                    m.records
                        .iter()
                        .map(UserType::Record)
                        .chain(m.aliases.iter().map(UserType::Alias))
                })
            }),
            self.catalogue,
        )
    }
}

/// Every declaration of a module: (name, is LOCAL, item).
pub fn module_items(module: &Module) -> impl Iterator<Item = (&str, bool, Item)> {
    let data = module
        .data
        .iter()
        .enumerate()
        .map(|(i, d)| (d.name.as_str(), d.scope == Scope::Local, Item::Data(i)));
    let routines = module
        .routines
        .iter()
        .enumerate()
        .map(|(i, r)| (r.name.as_str(), r.local, Item::Routine(i)));
    let records = module
        .records
        .iter()
        .enumerate()
        .map(|(i, r)| (r.name.as_str(), r.local, Item::Record(i)));
    let aliases = module
        .aliases
        .iter()
        .enumerate()
        .map(|(i, a)| (a.name.as_str(), a.local, Item::Alias(i)));
    data.chain(routines).chain(records).chain(aliases)
}

/// Configured I/O signals: folded name to RAPID data type.
pub type Signals = HashMap<String, &'static str>;

/// What a controller configuration file declares for RAPID programs.
#[derive(Clone, Debug, Default)]
pub struct Config {
    /// I/O signals (`EIO.cfg`); `None` when the file has no signal section.
    pub signals: Option<Signals>,
    /// Mechanical units (`MOC.cfg`, section `MECHANICAL_UNIT`), folded.
    pub mecunits: Vec<String>,
    /// The controller's tasks in order (`SYS.cfg`, section `CAB_TASKS`):
    /// their names as written. A backup keeps task *n* in `RAPID/TASKn`.
    pub tasks: Vec<String>,
    /// Modules the controller loads into tasks when it starts (`SYS.cfg`,
    /// section `CAB_TASK_MODULES`).
    pub task_modules: Vec<TaskModule>,
    /// The robots (`MOC.cfg`, sections `ROBOT` and `ARM`).
    pub robots: Vec<crate::robot::MocRobot>,
}

/// A module that `SYS.cfg` has the controller load into a task.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TaskModule {
    /// The file as written: `HOME:/user.sys`, `RELEASE:/options/...`.
    pub file: String,
    /// The task's name; `None` for every task (`-AllTask`).
    pub task: Option<String>,
}

impl TaskModule {
    /// The file's path below the controller's `HOME:` folder, if it is there.
    pub fn home_path(&self) -> Option<&str> {
        let head = self.file.get(..5)?;
        head.eq_ignore_ascii_case("home:").then(|| {
            self.file
                .get(5..)
                .unwrap_or_default()
                .trim_start_matches(['/', '\\'])
        })
    }

    /// The file's name, without folders, lowercase.
    pub fn file_name(&self) -> String {
        self.file
            .rsplit(['/', '\\', ':'])
            .next()
            .unwrap_or_default()
            .to_ascii_lowercase()
    }
}

/// Reads a configuration file ([`crate::cfg`]): the signals of `EIO.cfg`,
/// the mechanical units of `MOC.cfg`, the tasks and task modules of
/// `SYS.cfg` (whatever the file is called).
pub fn parse_config(cfg: &str) -> Config {
    config_of(&crate::cfg::parse(cfg))
}

/// What a task's checks need of a configuration file already read.
pub fn config_of(file: &crate::cfg::CfgFile) -> Config {
    let has_signals = file.types.iter().any(is_signal_type);
    let tasks = file
        .instances("CAB_TASKS")
        .filter_map(|e| e.get("Name").map(str::to_owned))
        .collect();
    let task_modules = file
        .instances("CAB_TASK_MODULES")
        .filter_map(|e| {
            let file = e.get("File")?.to_owned();
            let task = e
                .get("Task")
                .filter(|_| !e.has("AllTask"))
                .map(str::to_owned);
            Some(TaskModule { file, task })
        })
        .collect();
    let mecunits = file
        .instances("MECHANICAL_UNIT")
        .filter_map(|e| e.get("name").map(fold))
        .collect();
    Config {
        signals: has_signals.then(|| signals_of(file)),
        mecunits,
        tasks,
        task_modules,
        robots: crate::robot::moc_robots(file),
    }
}

/// Is this a type of I/O signals (its name holds `SIGNAL`: `EIO_SIGNAL`,
/// `EIO_USER_SIGNAL`)?
pub fn is_signal_type(t: &crate::cfg::CfgType) -> bool {
    t.name.to_ascii_uppercase().contains("SIGNAL")
}

/// The signals declared in an I/O configuration file (`EIO.cfg`): every
/// instance of a type whose name holds `SIGNAL`, with its `-Name` and
/// `-SignalType` (DI, DO, AI, AO, GI, GO).
pub fn parse_eio_signals(cfg: &str) -> Signals {
    signals_of(&crate::cfg::parse(cfg))
}

fn signals_of(file: &crate::cfg::CfgFile) -> Signals {
    let mut out = HashMap::new();
    for e in file
        .types
        .iter()
        .filter(|t| is_signal_type(t))
        .flat_map(|t| &t.instances)
    {
        let Some(name) = e.get("Name") else {
            continue;
        };
        let ty = match e.get("SignalType").map(str::to_ascii_uppercase).as_deref() {
            Some("DO") => "signaldo",
            Some("AI") => "signalai",
            Some("AO") => "signalao",
            Some("GI") => "signalgi",
            Some("GO") => "signalgo",
            _ => "signaldi",
        };
        out.insert(fold(name), ty);
    }
    out
}

#[cfg(test)]
mod tests;
