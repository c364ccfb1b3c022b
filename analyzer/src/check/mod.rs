//! Checking a unit (one file) against its task: declarations, statements,
//! expressions and calls. Each finding belongs to a rule of [`crate::rules`].
//!
//! The checker walks the tree once per routine. Names resolve through the
//! routine's scope (parameters, routine data, `FOR` variables), the module,
//! the task's globals and the built-in catalogue, in that order.

#[cfg(test)]
mod at;
mod availability;
mod cache;
mod calls;
mod decls;
pub(crate) mod exprs;
mod file_wide;
pub(crate) mod motion;
pub(crate) mod multimove;
pub mod once;
mod place;
mod routine;
mod stmts;
pub(crate) mod suggest;

#[cfg(test)]
pub(crate) use at::checker_type_of;
pub use cache::StmtCache;
pub use motion::{MoveReach, move_reaches, reach_target};
pub(crate) use place::Place;
pub(crate) use suggest::Kind;

use std::collections::{HashMap, HashSet};
use std::ops::Range;

use tree_sitter::Node;

use crate::diagnostic::{Diagnostic, Related, Rule};
use crate::items::{Module, ParamDecl};
use crate::names::{NameMap, fold, with_folded};
use crate::rules::Selection;
use crate::syntax::kind;
use crate::task::{ItemRef, Task, Unit};

/// Checks one unit of a task and returns its diagnostics (without the
/// syntax diagnostics, which the unit holds), sorted by position.
pub fn check_unit(task: &Task, unit: usize) -> Vec<Diagnostic> {
    check_unit_cached(task, unit, StmtCache::default(), &Selection::all()).0
}

/// [`check_unit`] reusing the results of statements that are unchanged since
/// the check that produced `cache` (same text, same routine declarations,
/// same task interface and constants); returns the cache for the next check.
/// An edit inside one routine re-checks only the statements it changed.
/// Only the rules `selection` has on are checked and reported.
pub fn check_unit_cached(
    task: &Task,
    unit: usize,
    cache: StmtCache,
    selection: &Selection,
) -> (Vec<Diagnostic>, StmtCache) {
    let Some(u) = task.unit(unit) else {
        return (Vec::new(), StmtCache::default());
    };
    if u.is_robotware() {
        // RobotWare's code: not the user's to fix.
        return (Vec::new(), cache);
    }
    let mut cx = Cx::new(task, unit, u);
    cx.selection = selection.clone();
    cx.cache = cache;
    cx.cache.start_check();
    cx.cache_enabled = true;
    cx.check();
    let mut diags = finish(task, unit, u, std::mem::take(&mut cx.diags));
    diags.retain(|d| selection.is_on(d.rule));
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

use crate::sema::def::Def;
pub(crate) use crate::sema::def::decl_ty;
use crate::sema::scope::{Scope, Use};

/// Labels by folded name: the label's range and the statement list that
/// holds it ([`crate::sema::labels::BlockKey`] of the list's parent).
pub(crate) type Labels = NameMap<(Range<usize>, crate::sema::labels::BlockKey)>;

/// The checker's context: the scopes it is in ([`Scope`], which it derefs
/// to), what it found and what it caches.
pub(crate) struct Cx<'t> {
    pub scope: Scope<'t>,
    /// The labels of the routine being checked.
    pub labels: Labels,
    /// Whether the statements being checked are in an ERROR handler.
    pub in_error_handler: bool,
    /// The rules this check runs.
    pub(crate) selection: Selection,
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
    pub(crate) close_memo: HashMap<(Kind, String), Option<(usize, String)>>,
    /// The module part of "did you mean", by module, kind and folded name.
    module_close_memo: HashMap<(usize, Kind, String), Option<(usize, String)>>,
    /// The first position of each unconfigured signal's diagnostic that a
    /// reused statement result added, by message.
    reused_signals: HashMap<String, (usize, usize)>,
    /// Lowered initial values of module data for rule E413, made on first
    /// use and kept for the whole check.
    pub(crate) inits: Option<crate::consteval::InitCache>,
    /// Whether the task turns configuration monitoring off anywhere
    /// (`ConfL\Off`, `ConfJ\Off`), found on the first move checked.
    pub(crate) conf_off: Option<motion::ConfOff>,
    /// The moves' targets as [`motion::check`] judged them, when asked for
    /// ([`move_reaches`]).
    pub(crate) reaches: Option<Vec<MoveReach>>,
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

impl<'t> std::ops::Deref for Cx<'t> {
    type Target = Scope<'t>;
    fn deref(&self) -> &Scope<'t> {
        &self.scope
    }
}

impl<'t> std::ops::DerefMut for Cx<'t> {
    fn deref_mut(&mut self) -> &mut Scope<'t> {
        &mut self.scope
    }
}

impl<'t> Cx<'t> {
    fn new(task: &'t Task, unit_idx: usize, unit: &'t Unit) -> Cx<'t> {
        Cx {
            scope: Scope::of_unit(task, unit_idx, unit),
            labels: Labels::default(),
            in_error_handler: false,
            selection: Selection::all(),
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
            conf_off: None,
            reaches: None,
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

    pub(crate) fn report(
        &mut self,
        rule: &'static Rule,
        range: Range<usize>,
        message: impl Into<String>,
    ) {
        // A name taken for a signal is found whatever the selection: its
        // other uses are not unresolved names ([`once::within_file`]); the
        // finding itself is dropped at the end when its rule is off.
        if self.selection.is_on(rule)
            || std::ptr::eq(rule, &crate::rules::unconfigured_signal::RULE)
        {
            self.diags.push(Diagnostic::new(rule, range, message));
        }
    }

    pub(crate) fn report_with(&mut self, d: Diagnostic) {
        if self.selection.is_on(d.rule) {
            self.diags.push(d);
        }
    }

    pub(crate) fn related_item(&self, r: ItemRef, message: impl Into<String>) -> Option<Related> {
        let (_, range) = self.task.item_name(r)?;
        let file = (r.unit != self.unit_idx)
            .then(|| self.task.unit(r.unit).map(|u| u.path.clone()))
            .flatten();
        Some(Related {
            file,
            range,
            message: message.into(),
        })
    }

    /// Resolves a data name in the current scope ([`Scope::resolve_data`]).
    /// Marks it used.
    pub(crate) fn resolve_data(&mut self, name: &str) -> Option<Def<'t>> {
        let (sym, used) = with_folded(name, |key| {
            let (sym, used) = self.scope.resolve_data_folded(name, key)?;
            let used = used.map(|u| match u {
                Use::RoutineScope => Used::RoutineSym(key.to_owned()),
                Use::Item(r) => Used::Item(r),
            });
            Some((sym, used))
        })?;
        if let Some(u) = used {
            self.mark_used(u);
        }
        Some(sym)
    }

    /// Resolves a routine name ([`Scope::resolve_routine`]). Marks it used.
    pub(crate) fn resolve_routine(&mut self, name: &str, want_function: bool) -> Option<Def<'t>> {
        let sym = self.scope.resolve_routine(name, want_function)?;
        if let Def::Item(r) = sym {
            self.mark_used(Used::Item(r));
        }
        Some(sym)
    }

    /// Does `name` denote a data type here?
    pub(crate) fn type_exists(&mut self, name: &str) -> bool {
        if let Some(r) = self.scope.type_item(name) {
            self.mark_used(Used::Item(r));
            return true;
        }
        self.types.exists(name)
    }

    /// Is `name` used as an optional parameter of the routine being checked?
    pub(crate) fn optional_param(&self, name: &str) -> Option<&'t ParamDecl> {
        let p = self
            .scope
            .routine
            .as_ref()?
            .params
            .get(&fold(name))
            .copied()?;
        p.optional.then_some(p)
    }
}
