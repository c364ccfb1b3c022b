//! Checking a unit (one file) against its task: declarations, statements,
//! expressions and calls. Each finding belongs to a rule of [`crate::rules`].
//!
//! The checker walks the tree once per routine. Names resolve through the
//! routine's scope (parameters, routine data, `FOR` variables), the module,
//! the task's globals and the built-in catalogue, in that order.

mod availability;
mod calls;
mod decls;
mod exprs;
pub mod once;
mod shared;
mod stmts;

use std::collections::{HashMap, HashSet};
use std::hash::BuildHasherDefault;
use std::ops::Range;

use tree_sitter::Node;

use crate::catalogue::{Catalogue, Datum, DatumKind, Mode, Routine};
use crate::diagnostic::{Diagnostic, Related, Rule};
use crate::items::{DataDecl, Module, ParamDecl, RoutineDecl, Storage};
use crate::names::{NameMap, fold, with_folded};
use crate::task::{Item, ItemRef, Task, Unit};
use crate::ty::{Ty, Types};

/// Checks one unit of a task and returns its diagnostics (without the
/// syntax diagnostics, which the unit holds), sorted by position.
pub fn check_unit(task: &Task, unit: usize) -> Vec<Diagnostic> {
    check_unit_cached(task, unit, StmtCache::default()).0
}

/// [`check_unit`] reusing the results of statements that are unchanged since
/// the check that produced `cache` (same text, same routine declarations,
/// same task interface and constants); returns the cache for the next check.
/// An edit inside one routine re-checks only the statements it changed.
pub fn check_unit_cached(
    task: &Task,
    unit: usize,
    cache: StmtCache,
) -> (Vec<Diagnostic>, StmtCache) {
    let Some(u) = task.units.get(unit) else {
        return (Vec::new(), StmtCache::default());
    };
    let mut cx = Cx::new(task, unit, u);
    cx.cache = cache;
    cx.cache.generation += 1;
    cx.cache.reused = 0;
    cx.cache_enabled = true;
    cx.check();
    let diags = finish(u, std::mem::take(&mut cx.diags));
    let mut cache = std::mem::take(&mut cx.cache);
    // Keep only what this check met (as if the cache were made afresh).
    let generation = cache.generation;
    cache.entries.retain(|_, e| e.generation == generation);
    (diags, cache)
}

/// Sorts a unit's findings by position, drops those about text nested too
/// deep to analyse ([`crate::nesting::keeps`]) and reports each name once
/// ([`once::within_file`]).
fn finish(u: &Unit, mut diags: Vec<Diagnostic>) -> Vec<Diagnostic> {
    diags.retain(|d| crate::nesting::keeps(&u.text, u.cuts(), d));
    diags.sort_by_key(|d| (d.range.start, d.range.end));
    once::within_file(&mut diags, &u.text);
    diags
}

/// Results of single statements, by a key of the statement's text and its
/// context, with diagnostic ranges relative to the statement's start.
#[derive(Debug, Default)]
pub struct StmtCache {
    entries: HashMap<u64, CachedStmt, BuildHasherDefault<KeyHasher>>,
    /// How many statements the check that made this cache took from the
    /// previous one.
    reused: usize,
    /// Checks made with this cache: each entry is stamped with the last one
    /// that met its statement, and the others are dropped after a check.
    generation: u64,
    /// Routines entered by checks made with this cache (never reset), so
    /// that an entry can tell whether its uses were already recorded in the
    /// routine being checked.
    routines: u64,
}

impl StmtCache {
    /// How many statement results it holds.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// How many statements the check that made this cache did not redo.
    pub fn reused(&self) -> usize {
        self.reused
    }
}

/// The cache's keys are hashes already: use them as they are.
#[derive(Default)]
pub(crate) struct KeyHasher(u64);

impl std::hash::Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.0 = self.0.rotate_left(8) ^ u64::from(*b);
        }
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = n;
    }
}

#[derive(Clone, Debug)]
pub(crate) struct CachedStmt {
    diags: Vec<Diagnostic>,
    used: Vec<Used>,
    /// The last check that met this statement.
    generation: u64,
    /// The last routine (a [`StmtCache::routines`] count) whose `used` set
    /// holds this statement's uses.
    routine: u64,
}

/// What a data name denotes.
#[derive(Clone, Debug)]
pub(crate) enum DataSym<'t> {
    Param(&'t ParamDecl),
    Local(DataDecl),
    Module(
        &'t DataDecl,
        #[allow(dead_code, reason = "where the data is declared, for navigation")] ItemRef,
    ),
    ForVar,
    Builtin(&'static Datum),
    Signal(&'static str),
}

impl DataSym<'_> {
    /// The symbol's type; a type name the task does not know is unknown
    /// (reported once where it is declared), so nothing else is reported
    /// against it.
    pub(crate) fn ty(&self, types: &Types<'_>) -> Ty {
        let ty = match self {
            DataSym::Param(p) => {
                p.ty.as_ref()
                    .map_or(Ty::Unknown, |t| Ty::named(&t.name))
                    .array(p.dims)
            }
            DataSym::Local(d) => decl_ty(d),
            DataSym::Module(d, _) => decl_ty(d),
            DataSym::ForVar => Ty::num(),
            DataSym::Builtin(d) => Ty::named(&d.ty),
            DataSym::Signal(ty) => Ty::named(ty),
        };
        if types.is_known(&ty) { ty } else { Ty::Unknown }
    }
}

pub(crate) fn decl_ty(d: &DataDecl) -> Ty {
    let dims = u8::try_from(d.dims.len()).unwrap_or(u8::MAX);
    d.ty.as_ref()
        .map_or(Ty::Unknown, |t| Ty::named(&t.name))
        .array(dims)
}

/// What a routine name denotes.
#[derive(Clone, Copy, Debug)]
pub(crate) enum RoutineSym<'t> {
    User(
        &'t RoutineDecl,
        #[allow(dead_code, reason = "where the routine is declared, for navigation")] ItemRef,
    ),
    Builtin(&'static Routine, bool),
}

/// The scope of the routine being checked.
pub(crate) struct RoutineCx<'t> {
    pub decl: &'t RoutineDecl,
    pub params: NameMap<&'t ParamDecl>,
    pub locals: NameMap<DataDecl>,
    pub for_vars: Vec<String>,
    /// Labels by folded name: the label's range and the statement list that
    /// holds it ([`stmts::BlockKey`] of the list's parent).
    pub labels: NameMap<(Range<usize>, stmts::BlockKey)>,
    pub in_error_handler: bool,
}

pub(crate) struct Cx<'t> {
    pub task: &'t Task,
    pub unit: &'t Unit,
    pub unit_idx: usize,
    pub text: &'t str,
    pub types: Types<'t>,
    pub cat: &'static Catalogue,
    pub module: Option<(usize, &'t Module)>,
    pub routine: Option<RoutineCx<'t>>,
    pub diags: Vec<Diagnostic>,
    /// Folded names of routine-scope symbols and module items that were used.
    pub used: UsedSet,
    pub reported_signals: HashSet<String>,
    /// Statement results of the previous checks, and of this one.
    pub(crate) cache: StmtCache,
    pub(crate) cache_enabled: bool,
    /// Uses recorded while a statement is checked, for the cache.
    pub(crate) recording: Option<Vec<Used>>,
    /// A hash of the current routine's header and declarations.
    pub(crate) routine_fingerprint: u64,
    /// The last context [`Cx::statement_key`] hashed.
    statement_context: Option<StatementContext>,
    /// "Did you mean" answers by folded name, for the current scope (cleared
    /// by [`Cx::scope_changed`]): an unresolved name tends to recur.
    close_memo: HashMap<(Kind, String), Option<String>>,
    /// The module part of "did you mean", by module, kind and folded name.
    module_close_memo: HashMap<(usize, Kind, String), Option<(usize, String)>>,
    /// The first position of each unconfigured signal's diagnostic that a
    /// reused statement result added, by message.
    reused_signals: HashMap<String, (usize, usize)>,
    /// Lowered initial values of module data for rule E413, made on first
    /// use and kept for the whole check.
    pub(crate) inits: Option<crate::consteval::InitCache>,
    /// Signatures of the routines called so far, by the address of their
    /// declaration (and whether a built-in is called as a function).
    signatures: HashMap<(usize, bool, bool), std::rc::Rc<calls::Sig>>,
    /// Aggregates of literals found to fit their type, by (the type, the
    /// array sizes, the aggregate's shape): the same shape fits again.
    pub(crate) clean_literals: HashSet<(String, Vec<Option<usize>>, Vec<u8>)>,
}

/// What a statement's cache key holds besides its text (the task's interface
/// and constants are fixed for a check), and its hash.
struct StatementContext {
    fingerprint: u64,
    in_error_handler: bool,
    for_vars: Vec<String>,
    module: Option<usize>,
    hash: u64,
}

/// The uses met, hashed with the cheap [`NameHasher`] (looked up for every
/// name the checker resolves).
pub(crate) type UsedSet = HashSet<Used, std::hash::BuildHasherDefault<crate::names::NameHasher>>;

/// A use of a declaration, for the unused-symbol lints.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Used {
    RoutineSym(String),
    Item(ItemRef),
}

impl<'t> Cx<'t> {
    fn new(task: &'t Task, unit_idx: usize, unit: &'t Unit) -> Cx<'t> {
        Cx {
            task,
            unit,
            unit_idx,
            text: &unit.text,
            types: task.types(),
            cat: task.catalogue,
            module: None,
            routine: None,
            diags: Vec::new(),
            used: UsedSet::default(),
            reported_signals: HashSet::new(),
            cache: StmtCache::default(),
            cache_enabled: false,
            recording: None,
            routine_fingerprint: 0,
            statement_context: None,
            close_memo: HashMap::new(),
            module_close_memo: HashMap::new(),
            reused_signals: HashMap::new(),
            inits: None,
            signatures: HashMap::new(),
            clean_literals: HashSet::new(),
        }
    }

    /// Marks a declaration used (and records it for the statement cache).
    pub(crate) fn mark_used(&mut self, u: Used) {
        if let Some(r) = &mut self.recording {
            r.push(u.clone());
        }
        self.used.insert(u);
    }

    /// Checks a statement through the cache: a statement whose text and
    /// context are unchanged gets its previous findings back.
    pub(crate) fn cached_statement(&mut self, s: Node<'t>, check: impl FnOnce(&mut Cx<'t>)) {
        if !self.cache_enabled || self.recording.is_some() {
            check(self);
            return;
        }
        let Some(key) = self.statement_key(s) else {
            check(self);
            return;
        };
        let start = s.start_byte();
        let generation = self.cache.generation;
        let routine = self.cache.routines;
        if let Some(c) = self.cache.entries.get_mut(&key) {
            c.generation = generation;
            for d in &c.diags {
                // An unconfigured signal is kept once per name, at its first
                // use in source order: a copy that a reused one already
                // precedes (or ties with, being pushed earlier) would be
                // dropped at the end anyway.
                let at = (d.range.start + start, d.range.end + start);
                if std::ptr::eq(d.rule, &crate::rules::unconfigured_signal::RULE) {
                    match self.reused_signals.get_mut(&d.message) {
                        Some(first) if *first <= at => continue,
                        Some(first) => *first = at,
                        None => {
                            self.reused_signals.insert(d.message.clone(), at);
                        }
                    }
                }
                let mut d = d.clone();
                d.range = d.range.start + start..d.range.end + start;
                for r in &mut d.related {
                    if r.file.is_none() {
                        r.range = r.range.start + start..r.range.end + start;
                    }
                }
                if let Some(f) = &mut d.fix {
                    for e in &mut f.edits {
                        e.range = e.range.start + start..e.range.end + start;
                    }
                }
                self.diags.push(d);
            }
            // The same statement met again in this routine: its uses are
            // recorded already.
            if c.routine != routine {
                c.routine = routine;
                for u in &c.used {
                    if !self.used.contains(u) {
                        self.used.insert(u.clone());
                    }
                }
            }
            self.cache.reused += 1;
            return;
        }
        let before = self.diags.len();
        self.recording = Some(Vec::new());
        check(self);
        let used = self.recording.take().unwrap_or_default();
        let range = s.byte_range();
        let inside = |r: &Range<usize>| range.start <= r.start && r.end <= range.end;
        let found = self.diags.get(before..).unwrap_or_default();
        let cacheable = found.iter().all(|d| {
            inside(&d.range)
                && d.related
                    .iter()
                    .all(|r| r.file.is_some() || inside(&r.range))
                && d.fix
                    .as_ref()
                    .is_none_or(|f| f.edits.iter().all(|e| inside(&e.range)))
        });
        if cacheable {
            let rel = |r: &Range<usize>| r.start - start..r.end - start;
            let diags = found
                .iter()
                .map(|d| {
                    let mut d = d.clone();
                    d.range = rel(&d.range);
                    for r in &mut d.related {
                        if r.file.is_none() {
                            r.range = rel(&r.range);
                        }
                    }
                    if let Some(f) = &mut d.fix {
                        for e in &mut f.edits {
                            e.range = rel(&e.range);
                        }
                    }
                    d
                })
                .collect();
            self.cache.entries.insert(
                key,
                CachedStmt {
                    diags,
                    used,
                    generation,
                    routine,
                },
            );
        }
    }

    /// The cache key of a statement: its text and everything around it that
    /// its check reads (routine declarations, handler, FOR variables, module,
    /// the task's interface and constants).
    fn statement_key(&mut self, s: Node<'_>) -> Option<u64> {
        use std::hash::{Hash, Hasher};
        let r = self.routine.as_ref()?;
        let module = self.module_idx();
        // The context changes rarely: hash it once per change.
        let context = match &self.statement_context {
            Some(c)
                if c.fingerprint == self.routine_fingerprint
                    && c.in_error_handler == r.in_error_handler
                    && c.module == module
                    && c.for_vars == r.for_vars =>
            {
                c.hash
            }
            _ => {
                let mut h = std::hash::DefaultHasher::new();
                self.routine_fingerprint.hash(&mut h);
                r.in_error_handler.hash(&mut h);
                r.for_vars.hash(&mut h);
                module.hash(&mut h);
                self.task.interface.hash(&mut h);
                self.task.constants.hash(&mut h);
                let hash = h.finish();
                self.statement_context = Some(StatementContext {
                    fingerprint: self.routine_fingerprint,
                    in_error_handler: r.in_error_handler,
                    for_vars: r.for_vars.clone(),
                    module,
                    hash,
                });
                hash
            }
        };
        let mut h = std::hash::DefaultHasher::new();
        context.hash(&mut h);
        self.node_text(s).hash(&mut h);
        Some(h.finish())
    }

    fn check(&mut self) {
        decls::check_file_wide(self);
        for (mi, module, node) in self.modules() {
            self.enter_module(mi, module);
            decls::check_module(self, node, module);
        }
        self.module = None;
        self.scope_changed();
    }

    /// The unit's modules with their nodes (modules without a name were not
    /// lowered: the indexes stay aligned with the item tree's).
    fn modules(&self) -> Vec<(usize, &'t Module, Node<'t>)> {
        let root = self.unit.tree().root_node();
        let mut cursor = root.walk();
        let nodes: Vec<Node<'t>> = root
            .named_children(&mut cursor)
            .filter(|n| crate::syntax_util::kind(*n) == "module")
            .collect();
        let mut out = Vec::new();
        let mut mi = 0;
        for node in nodes {
            let Some(module) = self.unit.items.modules.get(mi) else {
                break;
            };
            if module.range != node.byte_range() {
                continue;
            }
            out.push((mi, module, node));
            mi += 1;
        }
        out
    }

    fn enter_module(&mut self, mi: usize, module: &'t Module) {
        self.module = Some((mi, module));
        self.scope_changed();
    }

    /// The names in scope changed (module, routine, routine data).
    pub(crate) fn scope_changed(&mut self) {
        self.close_memo.clear();
    }

    pub(crate) fn node_text(&self, node: Node<'_>) -> &'t str {
        self.text.get(node.byte_range()).unwrap_or_default()
    }

    pub(crate) fn report(
        &mut self,
        rule: &'static Rule,
        range: Range<usize>,
        message: impl Into<String>,
    ) {
        self.diags.push(Diagnostic::new(rule, range, message));
    }

    pub(crate) fn report_with(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }

    pub(crate) fn related_item(&self, r: ItemRef, message: impl Into<String>) -> Option<Related> {
        let (_, range) = self.task.item_name(r)?;
        let file = (r.unit != self.unit_idx)
            .then(|| self.task.units.get(r.unit).map(|u| u.path.clone()))
            .flatten();
        Some(Related {
            file,
            range,
            message: message.into(),
        })
    }

    fn module_idx(&self) -> Option<usize> {
        self.module.map(|(i, _)| i)
    }

    /// Items visible from the current module under `name`: its own items
    /// (any scope) first, then the task's globals.
    pub(crate) fn lookup_items(&self, name: &str) -> Vec<ItemRef> {
        with_folded(name, |key| self.lookup_items_folded(key))
    }

    fn lookup_items_folded(&self, key: &str) -> Vec<ItemRef> {
        let mine = self.module_idx();
        let here = |r: &&ItemRef| r.unit == self.unit_idx && Some(r.module) == mine;
        let mut own: Vec<ItemRef> = Vec::new();
        if let Some(locals) = self.task.locals.get(key) {
            own.extend(locals.iter().filter(here));
        }
        if let Some(globals) = self.task.globals.get(key) {
            own.extend(globals.iter().filter(here));
            if own.is_empty() {
                return globals.iter().filter(|r| !here(r)).copied().collect();
            }
        }
        own
    }

    /// A `LOCAL` declaration of another module under `name`, to explain why
    /// the name is not visible.
    pub(crate) fn local_elsewhere(&self, name: &str) -> Option<ItemRef> {
        let mine = self.module_idx();
        with_folded(name, |key| {
            self.task
                .locals
                .get(key)?
                .iter()
                .copied()
                .find(|r| !(r.unit == self.unit_idx && Some(r.module) == mine))
        })
    }

    /// Resolves a data name in the current scope. Marks it used.
    pub(crate) fn resolve_data(&mut self, name: &str) -> Option<DataSym<'t>> {
        with_folded(name, |key| self.resolve_data_folded(name, key))
    }

    fn resolve_data_folded(&mut self, name: &str, key: &str) -> Option<DataSym<'t>> {
        if let Some(r) = &self.routine {
            if r.for_vars.iter().any(|v| v == key) {
                return Some(DataSym::ForVar);
            }
            if let Some(d) = r.locals.get(key) {
                let d = d.clone();
                self.mark_used(Used::RoutineSym(key.to_owned()));
                return Some(DataSym::Local(d));
            }
            if let Some(p) = r.params.get(key).copied() {
                self.mark_used(Used::RoutineSym(key.to_owned()));
                return Some(DataSym::Param(p));
            }
        }
        for r in self.lookup_items_folded(key) {
            if let Some(d) = self.task.data(r) {
                self.mark_used(Used::Item(r));
                return Some(DataSym::Module(d, r));
            }
        }
        if let Some(d) = self.cat.datum(name) {
            return Some(DataSym::Builtin(d));
        }
        if let Some(ty) = self.task.signals.as_ref().and_then(|s| s.get(key)) {
            return Some(DataSym::Signal(ty));
        }
        if self.task.mecunits.contains(key) {
            return Some(DataSym::Signal("mecunit"));
        }
        if self.task.task_ids.contains(key) {
            return Some(DataSym::Signal("taskid"));
        }
        None
    }

    /// Resolves a routine name. Marks it used.
    pub(crate) fn resolve_routine(
        &mut self,
        name: &str,
        want_function: bool,
    ) -> Option<RoutineSym<'t>> {
        for r in self.lookup_items(name) {
            if let Some(d) = self.task.routine(r) {
                self.mark_used(Used::Item(r));
                return Some(RoutineSym::User(d, r));
            }
        }
        let (first, second) = if want_function {
            (self.cat.function(name), self.cat.instruction(name))
        } else {
            (self.cat.instruction(name), self.cat.function(name))
        };
        first
            .map(|r| RoutineSym::Builtin(r, r.returns.is_some()))
            .or_else(|| second.map(|r| RoutineSym::Builtin(r, r.returns.is_some())))
    }

    /// Does `name` denote a data type here?
    pub(crate) fn type_exists(&mut self, name: &str) -> bool {
        for r in self.lookup_items(name) {
            if matches!(r.item, Item::Record(_) | Item::Alias(_)) {
                self.mark_used(Used::Item(r));
                return true;
            }
        }
        self.types.exists(name)
    }

    /// Reports a name that resolves to nothing, with the most helpful code.
    pub(crate) fn unresolved(&mut self, name: &str, range: Range<usize>, what: &str) {
        if let Some(r) = self.local_elsewhere(name) {
            let module = self
                .task
                .module(r)
                .map(|m| m.name.clone())
                .unwrap_or_default();
            let mut d = Diagnostic::new(
                &crate::rules::local_not_visible::RULE,
                range,
                format!("`{name}` is declared LOCAL in module {module} and cannot be used here"),
            );
            if let Some(rel) = self.related_item(r, "declared LOCAL here") {
                d = d.with_related(rel);
            }
            self.report_with(d);
            return;
        }
        let mut message = format!("no {what} named `{name}` is declared in this task or built in");
        let kind = Kind::of(what);
        let memo_key = (kind, fold(name));
        let close = match self.close_memo.get(&memo_key) {
            Some(close) => close.clone(),
            None => {
                let close = self.close_match(name, kind);
                self.close_memo.insert(memo_key, close.clone());
                close
            }
        };
        if let Some(close) = close {
            message.push_str(&format!("; did you mean `{close}`?"));
        } else if what == "data" && self.task.signals.is_none() {
            message.push_str(" (if it is an I/O signal, give the controller's EIO.cfg)");
        }
        self.report_unresolved(range, message);
    }

    /// Reports a name nothing declares: an error in a complete backup's
    /// task (every module is here, so the controller would refuse to load
    /// it), a note in `HOME/` modules that no task here loads (the task
    /// they are loaded into is not here), a warning anywhere else (the
    /// declaration may be in a module or an option that is not part of the
    /// checked files).
    pub(crate) fn report_unresolved(&mut self, range: Range<usize>, message: String) {
        let mut d = Diagnostic::new(&crate::rules::unresolved_name::RULE, range, message);
        if self.task.complete {
            d.severity = crate::diagnostic::Severity::Error;
        } else if self.task.loaded_elsewhere {
            d.severity = crate::diagnostic::Severity::Info;
        }
        self.report_with(d);
    }

    /// A visible name of the same kind within a small edit distance of
    /// `name`: the first closest of the routine's data and parameters, then
    /// the module's, then the task's globals. A suggestion of another kind
    /// (a data type for a variable) would mislead more than help.
    fn close_match(&mut self, name: &str, kind: Kind) -> Option<String> {
        let key = fold(name);
        let limit = if key.len() <= 4 { 1 } else { 2 };
        let mut best = None;
        if kind == Kind::Data {
            best = self.routine.as_ref().and_then(|r| {
                let locals = r.locals.values().map(|d| d.name.as_str());
                closest(
                    &key,
                    limit,
                    locals.chain(r.params.values().map(|p| p.name.as_str())),
                )
            });
        }
        // The module's part does not depend on the routine: remembered per
        // module (a module may declare thousands of data).
        if let Some((mi, m)) = self.module {
            let memo_key = (mi, kind, key.clone());
            let found = match self.module_close_memo.get(&memo_key) {
                Some(found) => found.clone(),
                None => {
                    let found = match kind {
                        Kind::Data => closest(&key, limit, m.data.iter().map(|d| d.name.as_str())),
                        Kind::Routine => {
                            closest(&key, limit, m.routines.iter().map(|r| r.name.as_str()))
                        }
                        Kind::Type => closest(
                            &key,
                            limit,
                            m.records
                                .iter()
                                .map(|r| r.name.as_str())
                                .chain(m.aliases.iter().map(|a| a.name.as_str())),
                        ),
                    };
                    self.module_close_memo.insert(memo_key, found.clone());
                    found
                }
            };
            keep_nearer(&mut best, found);
        }
        keep_nearer(&mut best, close_global(self.task, &key, limit, kind));
        best.map(|(_, n)| n)
    }

    /// Is `name` used as an optional parameter of the routine being checked?
    pub(crate) fn optional_param(&self, name: &str) -> Option<&'t ParamDecl> {
        let p = self.routine.as_ref()?.params.get(&fold(name)).copied()?;
        p.optional.then_some(p)
    }
}

/// Where a value lives, for the parameter-mode check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Place {
    Var,
    Pers,
    Const,
    ForVar,
    Param(Mode),
    /// Read-only system data such as `ERRNO`.
    ReadOnly,
    /// Not a data reference at all: a literal, a call, an operation.
    Value,
    /// Unresolved: say nothing.
    Unknown,
}

impl Place {
    pub(crate) fn of(sym: &DataSym<'_>) -> Place {
        match sym {
            DataSym::Param(p) => Place::Param(p.mode),
            DataSym::Local(DataDecl { storage, .. })
            | DataSym::Module(DataDecl { storage, .. }, _) => match storage {
                Storage::Var => Place::Var,
                Storage::Pers => Place::Pers,
                Storage::Const => Place::Const,
            },
            DataSym::ForVar => Place::ForVar,
            DataSym::Builtin(d) => match d.kind {
                DatumKind::Const => Place::Const,
                DatumKind::Pers => Place::Pers,
                DatumKind::Var if is_read_only_system_datum(d) => Place::ReadOnly,
                DatumKind::Var => Place::Var,
            },
            DataSym::Signal(_) => Place::Var,
        }
    }

    pub(crate) fn describe(self) -> &'static str {
        match self {
            Place::Var => "a variable",
            Place::Pers => "a persistent",
            Place::Const => "a constant",
            Place::ForVar => "a FOR loop variable",
            Place::Param(Mode::In) => "an input parameter",
            Place::Param(_) => "a reference parameter",
            Place::ReadOnly => "read-only system data",
            Place::Value => "a value",
            Place::Unknown => "unknown",
        }
    }
}

/// System data the program reads but the controller sets.
pub(crate) fn is_read_only_system_datum(d: &Datum) -> bool {
    ["ERRNO", "INTNO", "ERRSTR"]
        .iter()
        .any(|n| d.name.eq_ignore_ascii_case(n))
}

/// The task's global name closest to `key` within `limit` edits, memoised
/// per task (the same unresolved name tends to recur in many places).
/// The first of the names nearest to `key` (folded), with its distance:
/// at least one edit and at most `limit`.
fn closest<'n>(
    key: &str,
    limit: usize,
    names: impl IntoIterator<Item = &'n str>,
) -> Option<(usize, String)> {
    let mut best: Option<(usize, &str)> = None;
    for cand in names {
        let d = edit_distance_folded(key, cand);
        if d > 0 && d <= limit && best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, cand));
        }
    }
    best.map(|(d, n)| (d, n.to_owned()))
}

/// Puts `other` in `best` if it is strictly nearer.
fn keep_nearer(best: &mut Option<(usize, String)>, other: Option<(usize, String)>) {
    if let Some((d, n)) = other
        && best.as_ref().is_none_or(|(bd, _)| d < *bd)
    {
        *best = Some((d, n));
    }
}

fn close_global(task: &Task, key: &str, limit: usize, kind: Kind) -> Option<(usize, String)> {
    let mut memo = task
        .close_names
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let memo_key = format!("{}{key}", kind.prefix());
    if let Some(found) = memo.get(&memo_key) {
        return found.clone();
    }
    let mut best: Option<(usize, String)> = None;
    for (folded, refs) in &task.globals {
        if folded.len().abs_diff(key.len()) > limit {
            continue;
        }
        let Some(r) = refs.iter().find(|r| kind.matches(r.item)) else {
            continue;
        };
        let d = edit_distance(key, folded);
        if d > 0
            && d <= limit
            && best.as_ref().is_none_or(|(bd, _)| d < *bd)
            && let Some((n, _)) = task.item_name(*r)
        {
            best = Some((d, n.to_owned()));
        }
    }
    memo.insert(memo_key, best.clone());
    best
}

/// What kind of name a "did you mean" looks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Kind {
    Data,
    Routine,
    Type,
}

impl Kind {
    /// From the word [`Cx::unresolved`] is given: "data", "routine", "data type".
    fn of(what: &str) -> Kind {
        match what {
            "routine" => Kind::Routine,
            "data type" => Kind::Type,
            _ => Kind::Data,
        }
    }

    fn matches(self, item: Item) -> bool {
        matches!(
            (self, item),
            (Kind::Data, Item::Data(_))
                | (Kind::Routine, Item::Routine(_))
                | (Kind::Type, Item::Record(_) | Item::Alias(_))
        )
    }

    /// Keeps the kinds apart in the task's memo of suggestions.
    fn prefix(self) -> &'static str {
        match self {
            Kind::Data => "d:",
            Kind::Routine => "r:",
            Kind::Type => "t:",
        }
    }
}

/// Levenshtein distance of two short ASCII strings.
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    distance(a.as_bytes(), b.as_bytes(), |x, y| x == y)
}

/// [`edit_distance`] between a folded `key` and `name` as if `name` were
/// folded too (without allocating its folded form).
fn edit_distance_folded(key: &str, name: &str) -> usize {
    distance(key.as_bytes(), name.as_bytes(), |x, y| {
        x == y.to_ascii_lowercase()
    })
}

/// Levenshtein distance of byte strings, or 3 when it is more than 2
/// (callers only care about distances up to 2).
fn distance(a: &[u8], b: &[u8], eq: impl Fn(u8, u8) -> bool) -> usize {
    const STACK: usize = 64;
    if a.len().abs_diff(b.len()) > 2 {
        return 3;
    }
    let mut stack = [[0usize; STACK]; 2];
    let mut heap;
    let (mut prev, mut cur): (&mut [usize], &mut [usize]) = if b.len() < STACK {
        let [p, c] = &mut stack;
        (&mut p[..=b.len()], &mut c[..=b.len()])
    } else {
        heap = (vec![0; b.len() + 1], vec![0; b.len() + 1]);
        (&mut heap.0, &mut heap.1)
    };
    for (j, p) in prev.iter_mut().enumerate() {
        *p = j;
    }
    for (i, &ca) in a.iter().enumerate() {
        cur[0] = i + 1;
        let mut row_min = cur[0];
        for (j, &cb) in b.iter().enumerate() {
            let cost = usize::from(!eq(ca, cb));
            cur[j + 1] = (prev[j] + cost).min(prev[j + 1] + 1).min(cur[j] + 1);
            row_min = row_min.min(cur[j + 1]);
        }
        // The distance is at least the smallest value of any row.
        if row_min > 2 {
            return 3;
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

/// Name resolution at a position, for the editor features ([`crate::ide`]):
/// the same scopes as the checker, entered around one offset.
impl<'t> Cx<'t> {
    /// A context whose module and routine scopes are those around `offset`
    /// of unit `unit` (parameters, routine data, and the variables of the
    /// `FOR` loops that enclose the offset).
    pub(crate) fn at(task: &'t Task, unit: usize, offset: usize) -> Option<Cx<'t>> {
        let u: &'t Unit = task.units.get(unit)?;
        let mut cx = Cx::new(task, unit, u);
        let within = |r: &Range<usize>| r.start <= offset && offset <= r.end;
        cx.module = u
            .items
            .modules
            .iter()
            .enumerate()
            .find(|(_, m)| within(&m.range));
        let Some((_, module)) = cx.module else {
            return Some(cx);
        };
        let Some(decl) = module.routines.iter().find(|r| within(&r.range)) else {
            return Some(cx);
        };
        let root = u.tree().root_node();
        let Some(node) = root.named_descendant_for_byte_range(decl.range.start, decl.range.end)
        else {
            return Some(cx);
        };
        let mut params = NameMap::default();
        for p in &decl.params {
            params.entry(fold(&p.name)).or_insert(p);
        }
        let mut locals = NameMap::default();
        // Routine data comes before the first statement: stop there, so that
        // entering a long routine costs its declarations, not its statements
        // (constant evaluation enters the scope once per statement).
        if let Some(body) = crate::syntax_util::field_id("body") {
            let mut cursor = node.walk();
            for item in node
                .children_by_field_id(body, &mut cursor)
                .take_while(|n| crate::syntax_util::kind(*n) == "data_declaration")
            {
                if let Some(d) = crate::items::lower_data(item, &u.text) {
                    locals.entry(fold(&d.name)).or_insert(d);
                }
            }
        }
        let mut for_vars = Vec::new();
        let mut at = root.descendant_for_byte_range(offset, offset);
        while let Some(n) = at {
            if n.id() == node.id() {
                break;
            }
            if crate::syntax_util::kind(n) == "for_statement"
                && let Some(v) = crate::syntax_util::field(n, "variable")
            {
                for_vars.push(fold(cx.node_text(v)));
            }
            at = n.parent();
        }
        cx.routine = Some(RoutineCx {
            decl,
            params,
            locals,
            for_vars,
            labels: NameMap::default(),
            in_error_handler: false,
        });
        Some(cx)
    }

    /// The type of an expression in this context (its findings dropped).
    pub(crate) fn type_of_expr(&mut self, node: Node<'t>) -> Ty {
        // Only this expression's findings are dropped: the checker calls
        // this in the middle of a unit (constant evaluation).
        let before = self.diags.len();
        let used = self.used.clone();
        let recorded = self.recording.as_ref().map(Vec::len);
        let signals = self.reported_signals.clone();
        let ty = exprs::expr(self, node, None);
        self.diags.truncate(before);
        self.used = used;
        // The statement cache records only the uses that stay.
        if let (Some(r), Some(len)) = (&mut self.recording, recorded) {
            r.truncate(len);
        }
        self.reported_signals = signals;
        ty
    }
}

#[cfg(test)]
mod distance_tests {
    #[test]
    fn edit_distances() {
        for (a, b, d) in [
            ("movel", "movel", 0),
            ("movel", "movej", 1),
            ("movel", "mvel", 1),
            ("ptarget", "ptraget", 2),
            ("abc", "abcdef", 3),
            ("", "ab", 2),
        ] {
            assert_eq!(super::edit_distance(a, b), d, "{a} {b}");
            assert_eq!(
                super::edit_distance_folded(a, &b.to_uppercase()),
                d,
                "{a} {b}"
            );
        }
        let long = "x".repeat(70);
        assert_eq!(super::edit_distance(&long, &format!("{long}y")), 1);
    }
}
