//! A task: the modules that are loaded together on one controller task, and
//! the index of the names they declare.
//!
//! Grouping follows the controller's layout: in a backup,
//! `.../RAPID/TASKn/{SYSMOD,PROGMOD}/...` is task `TASKn`; elsewhere the
//! modules of one folder form one task. Tasks never see each other's names.

use std::collections::{HashMap, HashSet};
use std::ops::Range;
use std::sync::Arc;

use crate::items::{DataDecl, Module, RecordDecl, RoutineDecl, Scope, Storage, hash_of};
use crate::layout::Grouping;
use crate::names::{NameMap, fold};
use crate::ty::{Types, UserType};

mod config;
mod unit;
mod view;
pub use config::{
    Config, SignalKind, Signals, TaskKind, TaskModule, TaskSettings, config_of, is_signal_type,
    parse_config, parse_eio_signals,
};
pub use unit::Unit;
use view::View;
pub use view::{Clashes, NameIndex};

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
///
/// A task is cheap to clone: its units, name index and configuration are
/// shared. A view of a group ([`Task::view`]) shares them with the group
/// and leaves out the units that clash with its owner when names are
/// looked up.
#[derive(Clone, Debug)]
pub struct Task {
    pub key: String,
    /// Every unit of the group, a view's left-out ones included (so that
    /// [`ItemRef::unit`] indexes the same units in the group and its
    /// views); [`Task::live_units`] leaves those out.
    pub units: Arc<[Arc<Unit>]>,
    /// Global (non-`LOCAL`) declarations of every module, by folded name.
    pub globals: NameIndex,
    /// `LOCAL` declarations, by folded name (to explain why a name is not
    /// visible from another module).
    pub locals: NameIndex,
    /// Signals configured for this task (`EIO.cfg`): folded name to data
    /// type (`signaldi`...); `None` when no configuration was given.
    pub signals: Option<Arc<Signals>>,
    /// Mechanical units configured for this task (`MOC.cfg`), folded; they
    /// are `mecunit` data.
    pub mecunits: Arc<HashSet<String>>,
    /// The robot the task's moves are made by (`MOC.cfg`, else the
    /// project's `[controller] robot`); set with [`Task::set_robot`].
    pub robot: Option<Arc<crate::robot::TaskRobot>>,
    /// Why a robot that is named is not used (not modelled, on a track).
    pub robot_note: Option<String>,
    /// The `taskid` data RobotWare declares for each task of the controller
    /// (the task's name and `Id`: `T_ROB1Id`), folded: from `SYS.cfg`'s
    /// tasks and the backup's task folders named after their task.
    pub task_ids: Arc<HashSet<String>>,
    /// The hash of what the task's files and controller declare
    /// ([`InterfaceInputs`]), for cache invalidation.
    pub interface: u64,
    inputs: Arc<InterfaceInputs>,
    /// The hash of every unit's [`Unit::constants`], in order.
    pub constants: u64,
    /// The system-global persistents (`PERS`, neither `TASK` nor `LOCAL`)
    /// that the tasks of the same controller declare (this one included),
    /// by folded name
    /// (empty outside a backup's `RAPID/TASKn` folders): the controller
    /// shares them, so their types must agree. Set with [`Task::set_shared`].
    pub shared: Arc<SharedMap>,
    /// How the tasks of the same controller meet (MultiMove): their
    /// names and synchronisation points (empty outside a backup). Set with
    /// [`Task::set_syncs`].
    pub(crate) syncs: Arc<crate::sema::sync::ControllerSyncs>,
    /// The catalogue as this task's controller has it (its RobotWare
    /// version and options; the union of every version when unknown). Set
    /// with [`Task::set_catalogue`].
    pub catalogue: &'static crate::catalogue::Catalogue,
    /// The global names near others, for "did you mean" (shared by a group
    /// and its views).
    pub(crate) close_names: Arc<crate::check::suggest::CloseNames>,
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
    /// without the modules that cannot be loaded with it
    /// ([`Task::left_out`]). `None` for a whole group.
    pub owner: Option<usize>,
    /// The units of the group that clash with others: each is checked in
    /// a view of its own, which leaves out the units it clashes with.
    pub clashes: Arc<Clashes>,
    /// A unit in place of the group's unit of that index ([`Task::with_unit`]).
    overlay: Option<(usize, Arc<Unit>)>,
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
    /// The hash of [`Task::syncs`].
    syncs: u64,
}

fn sorted<T: Ord>(items: impl Iterator<Item = T>) -> Vec<T> {
    let mut out: Vec<T> = items.collect();
    out.sort();
    out
}

impl Task {
    /// This task with `units` in place of its own: the same files in the
    /// same order (their items are what the name index points at), e.g.
    /// with their trees parsed again for one check. Everything else (the
    /// configuration, catalogue view, grouping, view, keys) is kept.
    pub fn with_units(&self, units: Vec<Arc<Unit>>) -> Task {
        Task {
            units: units.into(),
            overlay: None,
            ..self.clone()
        }
    }

    /// This task with `unit` in place of its unit `idx` (the same file, e.g.
    /// with its tree parsed again for one check: [`Unit::loaded`]), sharing
    /// everything else: [`Task::unit`] gives it.
    pub fn with_unit(&self, idx: usize, unit: Arc<Unit>) -> Task {
        Task {
            overlay: Some((idx, unit)),
            ..self.clone()
        }
    }

    /// The unit of index `idx` ([`ItemRef::unit`]).
    pub fn unit(&self, idx: usize) -> Option<&Arc<Unit>> {
        match &self.overlay {
            Some((i, u)) if *i == idx => Some(u),
            _ => self.units.get(idx),
        }
    }

    /// The index of `unit`, which is one of this task's units.
    pub fn index_of(&self, unit: &Arc<Unit>) -> Option<usize> {
        match &self.overlay {
            Some((i, u)) if Arc::ptr_eq(u, unit) => Some(*i),
            _ => self.units.iter().position(|u| Arc::ptr_eq(u, unit)),
        }
    }

    /// The view of this group for its unit `owner`: the same task without
    /// the units that clash with `owner` ([`Task::clashes`]), sharing the
    /// group's units and index.
    pub fn view(&self, owner: usize) -> Task {
        let view = Some(View {
            owner,
            clashes: self.clashes.clone(),
        });
        Task {
            globals: self.globals.seen_by(view.clone()),
            locals: self.locals.seen_by(view),
            owner: Some(owner),
            ..self.clone()
        }
    }

    /// Does this task (a view) leave unit `u` out?
    pub fn hides(&self, u: usize) -> bool {
        self.owner.is_some_and(|o| self.clashes.clash(o, u))
    }

    /// The units this task sees (all but those a view leaves out), with
    /// their indexes.
    pub fn live_units(&self) -> impl Iterator<Item = (usize, &Arc<Unit>)> {
        (0..self.units.len())
            .filter(|&i| !self.hides(i))
            .filter_map(|i| Some((i, self.unit(i)?)))
    }

    /// The units a view leaves out (none for a group).
    pub fn left_out(&self) -> impl Iterator<Item = &Arc<Unit>> {
        self.owner
            .map(|o| self.clashes.partners(o))
            .unwrap_or_default()
            .into_iter()
            .filter_map(|u| self.units.get(u))
    }

    /// This task with more modules after its own (a test harness's
    /// assertion module, say), its names indexed again; the controller it
    /// belongs to stays (configuration, catalogue view, controller names,
    /// shared persistents, synchronisation, grouping, view), so the task is
    /// the one `rapid check` checks, with more in it.
    pub fn with_extra_units(&self, extra: impl IntoIterator<Item = Arc<Unit>>) -> Task {
        let mut units = self.units.to_vec();
        units.extend(extra);
        self.rebuilt(units, self.signals.as_deref().cloned())
    }

    /// The units of a controller's `HOME/` that the task's program loads
    /// while it runs: a `Load` or `StartLoad` of another of its units names
    /// the file ([`crate::loads`]). The checker checks them with the task
    /// (their names against its); the controller has them only between
    /// their `Load` and `UnLoad`, each in its turn.
    pub fn run_time_loads(&self) -> Vec<usize> {
        let loaded = crate::loads::loaded_files(self.units.iter());
        (0..self.units.len())
            .filter(|&i| {
                self.unit(i).is_some_and(|u| {
                    crate::layout::in_home(&u.path)
                        && crate::loads::module_file_name(&u.path)
                            .is_some_and(|f| loaded.contains(&f))
                })
            })
            .collect()
    }

    /// This task without the units `drop` (indexes), its names indexed
    /// again and no module set apart as clashing (the clashes were between
    /// indexes that move); the controller it belongs to stays, as in
    /// [`Task::with_extra_units`]. A view (of one of alternative programs)
    /// is kept whole.
    pub fn without_units(&self, drop: &[usize]) -> Task {
        if drop.is_empty() || self.owner.is_some() {
            return self.clone();
        }
        let units = (0..self.units.len())
            .filter(|i| !drop.contains(i))
            .filter_map(|i| self.unit(i).cloned())
            .collect();
        let whole = Task {
            clashes: Arc::default(),
            ..self.clone()
        };
        whole.rebuilt(units, self.signals.as_deref().cloned())
    }

    /// This task with more configured I/O signals (name and RAPID type,
    /// `signaldi`...), as a configuration file would declare them: a
    /// simulation's scripted signals. Signals it has already keep their
    /// type.
    pub fn with_signals(&self, extra: &[(String, &'static str)]) -> Task {
        let mut signals = self.signals.as_deref().cloned().unwrap_or_default();
        for (name, ty) in extra {
            signals.entry(fold(name)).or_insert(ty);
        }
        self.rebuilt(self.units.to_vec(), Some(signals))
    }

    /// A task of `units` and `signals` that belongs to the same controller
    /// as this one (units after this task's keep their indexes, so its
    /// clashes and view stay valid).
    fn rebuilt(&self, units: Vec<Arc<Unit>>, signals: Option<Signals>) -> Task {
        let mut task = Task::new(self.key.clone(), units, signals);
        if let Some(selection) = &self.inputs.catalogue {
            task.set_catalogue(selection);
        }
        task.set_controller_names((*self.mecunits).clone(), (*self.task_ids).clone());
        task.set_robot(match &self.robot_note {
            Some(note) => Err(note.clone()),
            None => Ok(self.robot.clone()),
        });
        task.set_shared(self.shared.clone(), self.inputs.shared);
        task.set_syncs(self.syncs.clone(), self.inputs.syncs);
        task.grouping = self.grouping;
        task.complete = self.complete;
        task.loaded_elsewhere = self.loaded_elsewhere;
        task.clashes = self.clashes.clone();
        match self.owner {
            Some(owner) => task.view(owner),
            None => task,
        }
    }

    /// Sets [`Task::shared`] (with the hash [`shared_persistents`] gave):
    /// the task's interface hash then covers them, so cached results are
    /// dropped when another task's persistents change.
    pub fn set_shared(&mut self, shared: Arc<SharedMap>, hash: u64) {
        Arc::make_mut(&mut self.inputs).shared = hash;
        self.shared = shared;
        self.interface = hash_of(&self.inputs);
    }

    /// Sets [`Task::syncs`] (with its hash): the interface hash covers
    /// them, so cached results are dropped when another task's
    /// synchronisation changes.
    pub(crate) fn set_syncs(&mut self, syncs: Arc<crate::sema::sync::ControllerSyncs>, hash: u64) {
        Arc::make_mut(&mut self.inputs).syncs = hash;
        self.syncs = syncs;
        self.interface = hash_of(&self.inputs);
    }

    /// Sets [`Task::mecunits`] and [`Task::task_ids`]: names resolve
    /// through them, so the interface covers them.
    pub fn set_controller_names(&mut self, mecunits: HashSet<String>, task_ids: HashSet<String>) {
        let inputs = Arc::make_mut(&mut self.inputs);
        inputs.mecunits = sorted(mecunits.iter().cloned());
        inputs.task_ids = sorted(task_ids.iter().cloned());
        self.mecunits = Arc::new(mecunits);
        self.task_ids = Arc::new(task_ids);
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
            units: units.into(),
            globals: NameIndex::new(globals),
            locals: NameIndex::new(locals),
            signals: signals.map(Arc::new),
            mecunits: Default::default(),
            robot: None,
            robot_note: None,
            interface: hash_of(&inputs),
            inputs: Arc::new(inputs),
            constants: hash_of(&constants),
            shared: Arc::default(),
            syncs: Arc::default(),
            catalogue: crate::catalogue::base(),
            close_names: Default::default(),
            grouping: Grouping::Folder,
            complete: false,
            loaded_elsewhere: false,
            task_ids: Default::default(),
            owner: None,
            clashes: Arc::default(),
            overlay: None,
        }
    }

    /// Sets the task's robot (or the note why the one named is not used).
    pub fn set_robot(&mut self, robot: Result<Option<Arc<crate::robot::TaskRobot>>, String>) {
        let (robot, note) = match robot {
            Ok(r) => (r, None),
            Err(note) => (None, Some(note)),
        };
        Arc::make_mut(&mut self.inputs).robot = robot.as_ref().map(|r| r.fingerprint());
        self.interface = hash_of(&self.inputs);
        self.robot = robot;
        self.robot_note = note;
    }

    /// Sets [`Task::catalogue`] to the view of `selection`: the interface
    /// hash covers it, so cached results are dropped when it changes.
    pub fn set_catalogue(&mut self, selection: &crate::catalogue::Selection) {
        Arc::make_mut(&mut self.inputs).catalogue = Some(selection.clone());
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
            None => !self.clashes.any(idx),
        }
    }

    /// The units checked in this task ([`Task::owns`]), with their indexes.
    pub fn own_units(&self) -> impl Iterator<Item = (usize, &Arc<Unit>)> {
        self.units.iter().enumerate().filter(|(i, _)| self.owns(*i))
    }

    pub fn module(&self, r: ItemRef) -> Option<&Module> {
        self.unit(r.unit)?.items.modules.get(r.module)
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
        Types::of_task(self)
    }

    /// The record or alias of the folded name `key`, global or local: the
    /// first declared (by unit, module, records before aliases).
    pub fn user_type(&self, key: &str) -> Option<UserType<'_>> {
        let rank = |r: &ItemRef| match r.item {
            Item::Record(i) => Some((r.unit, r.module, 0, i)),
            Item::Alias(i) => Some((r.unit, r.module, 1, i)),
            _ => None,
        };
        let first = self
            .globals
            .refs(key)
            .chain(self.locals.refs(key))
            .filter_map(|r| Some((rank(&r)?, r)))
            .min_by_key(|(k, _)| *k)?
            .1;
        let m = self.module(first)?;
        match first.item {
            Item::Record(i) => m.records.get(i).map(UserType::Record),
            Item::Alias(i) => m.aliases.get(i).map(UserType::Alias),
            _ => None,
        }
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

#[cfg(test)]
mod tests;
