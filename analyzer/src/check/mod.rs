//! Checking a unit (one file) against its task: declarations, statements,
//! expressions and calls. Each finding belongs to a rule of [`crate::rules`].
//!
//! The checker walks the tree once per routine. Names resolve through the
//! routine's scope (parameters, routine data, `FOR` variables), the module,
//! the task's globals and the built-in catalogue, in that order.

mod at;
mod availability;
mod cache;
mod calls;
mod decls;
mod exprs;
mod file_wide;
pub mod once;
mod place;
mod routine;
mod shared;
mod stmts;
mod suggest;

pub use cache::StmtCache;
pub(crate) use place::Place;
pub(crate) use suggest::Kind;

use std::collections::{HashMap, HashSet};
use std::ops::Range;

use tree_sitter::Node;

use crate::catalogue::{Catalogue, Datum, Routine};
use crate::diagnostic::{Diagnostic, Related, Rule};
use crate::items::{DataDecl, Module, ParamDecl, RoutineDecl};
use crate::names::{NameMap, fold, with_folded};
use crate::syntax::kind;
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
    cx.cache.start_check();
    cx.cache_enabled = true;
    cx.check();
    let diags = finish(task, unit, u, std::mem::take(&mut cx.diags));
    let mut cache = std::mem::take(&mut cx.cache);
    cache.drop_stale();
    (diags, cache)
}

/// Sorts a unit's findings by position, drops those about text nested too
/// deep to analyse ([`crate::nesting::keeps`]), reports each name once
/// ([`once::within_file`]) and completes the fixes that need the whole unit
/// ([`crate::rules::complete_fixes`]).
fn finish(task: &Task, unit: usize, u: &Unit, mut diags: Vec<Diagnostic>) -> Vec<Diagnostic> {
    diags.retain(|d| crate::nesting::keeps(&u.text, u.cuts(), d));
    diags.sort_by_key(|d| (d.range.start, d.range.end));
    once::within_file(&mut diags, &u.text);
    crate::rules::complete_fixes(task, unit, &mut diags);
    diags
}

/// What a data name denotes.
#[derive(Clone, Debug)]
pub(crate) enum DataSym<'t> {
    Param(&'t ParamDecl),
    Local(DataDecl),
    Module(&'t DataDecl, ItemRef),
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
    User(&'t RoutineDecl, ItemRef),
    Builtin(&'static Routine),
}

/// The scope of the routine being checked.
pub(crate) struct RoutineCx<'t> {
    pub decl: &'t RoutineDecl,
    pub params: NameMap<&'t ParamDecl>,
    pub locals: NameMap<DataDecl>,
    pub for_vars: Vec<String>,
    /// Labels by folded name: the label's range and the statement list that
    /// holds it ([`crate::sema::labels::BlockKey`] of the list's parent).
    pub labels: NameMap<(Range<usize>, crate::sema::labels::BlockKey)>,
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
    /// declaration (and whether it is declared in the task).
    signatures: HashMap<(usize, bool), std::rc::Rc<crate::sema::signature::Signature>>,
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

    fn check(&mut self) {
        file_wide::check_file_wide(self);
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
            .filter(|n| crate::syntax_util::kind(*n) == kind::MODULE)
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
        crate::sema::scope::visible(self.task, self.unit_idx, self.module_idx(), key)
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
            .map(RoutineSym::Builtin)
            .or_else(|| second.map(RoutineSym::Builtin))
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
        let mut d = self.unresolved_diagnostic(range, message);
        if kind == Kind::Data {
            d = d.with_fix(crate::rules::unresolved_name::pending_declare_fix());
        }
        self.report_with(d);
    }

    /// Reports a name nothing declares: an error in a complete backup's
    /// task (every module is here, so the controller would refuse to load
    /// it), a note in `HOME/` modules that no task here loads (the task
    /// they are loaded into is not here), a warning anywhere else (the
    /// declaration may be in a module or an option that is not part of the
    /// checked files).
    pub(crate) fn report_unresolved(&mut self, range: Range<usize>, message: String) {
        let d = self.unresolved_diagnostic(range, message);
        self.report_with(d);
    }

    fn unresolved_diagnostic(&self, range: Range<usize>, message: String) -> Diagnostic {
        let mut d = Diagnostic::new(&crate::rules::unresolved_name::RULE, range, message);
        if self.task.complete {
            d.severity = crate::diagnostic::Severity::Error;
        } else if self.task.loaded_elsewhere {
            d.severity = crate::diagnostic::Severity::Info;
        }
        d
    }

    /// Is `name` used as an optional parameter of the routine being checked?
    pub(crate) fn optional_param(&self, name: &str) -> Option<&'t ParamDecl> {
        let p = self.routine.as_ref()?.params.get(&fold(name)).copied()?;
        p.optional.then_some(p)
    }
}
