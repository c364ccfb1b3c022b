//! What a name means at a place: the scopes of a routine, a module, the
//! task, the catalogue and the controller's configuration, and the one
//! resolver over them. Nothing here reports or records: the checker marks
//! the uses it meets ([`crate::check`]), the editor features and constant
//! evaluation only ask.

use std::ops::Range;

use tree_sitter::Node;

pub(crate) use super::def::Def;
use crate::catalogue::Catalogue;
use crate::items::{DataDecl, Module, ParamDecl, RoutineDecl};
use crate::names::{NameMap, fold, with_folded};
use crate::syntax::{field, kind};
use crate::task::{Item, ItemRef, Task, Unit};
use crate::ty::Types;

/// The items visible under the folded name `key` from module `module` of
/// unit `unit`: the module's own items (any scope, `LOCAL` ones included)
/// if it declares the name, else the task's globals. `module` is `None`
/// outside any module (only globals are visible).
pub(crate) fn visible(task: &Task, unit: usize, module: Option<usize>, key: &str) -> Vec<ItemRef> {
    let here = |r: &&ItemRef| r.unit == unit && Some(r.module) == module;
    let mut own: Vec<ItemRef> = Vec::new();
    if let Some(locals) = task.locals.get(key) {
        own.extend(locals.iter().filter(here));
    }
    if let Some(globals) = task.globals.get(key) {
        own.extend(globals.iter().filter(here));
        if own.is_empty() {
            return globals.into_owned();
        }
    }
    own
}

/// The names a routine puts in front of its module's.
#[derive(Clone)]
pub(crate) struct RoutineScope<'t> {
    pub decl: &'t RoutineDecl,
    /// Parameters by folded name.
    pub params: NameMap<&'t ParamDecl>,
    /// Routine data by folded name.
    pub locals: NameMap<DataDecl>,
    /// The `FOR` variables of the loops around the place, outermost
    /// first: folded name and the range of the name in its loop.
    pub for_vars: Vec<(String, Range<usize>)>,
}

impl<'t> RoutineScope<'t> {
    /// A routine's scope with its parameters and no data yet.
    pub(crate) fn new(decl: &'t RoutineDecl) -> RoutineScope<'t> {
        let mut params = NameMap::default();
        for p in &decl.params {
            params.entry(fold(&p.name)).or_insert(p);
        }
        RoutineScope {
            decl,
            params,
            locals: NameMap::default(),
            for_vars: Vec::new(),
        }
    }
}

/// The scopes around a place of a unit: the task (with its catalogue view
/// and configuration), the module and the routine.
pub(crate) struct Scope<'t> {
    pub task: &'t Task,
    pub unit: &'t Unit,
    pub unit_idx: usize,
    pub text: &'t str,
    pub types: Types<'t>,
    pub cat: &'static Catalogue,
    pub module: Option<(usize, &'t Module)>,
    pub routine: Option<RoutineScope<'t>>,
}

impl<'t> Scope<'t> {
    /// The scope of unit `unit` outside its modules (only the task's
    /// globals and the catalogue are visible).
    pub(crate) fn of_unit(task: &'t Task, unit_idx: usize, unit: &'t Unit) -> Scope<'t> {
        Scope {
            task,
            unit,
            unit_idx,
            text: &unit.text,
            types: task.types(),
            cat: task.catalogue,
            module: None,
            routine: None,
        }
    }

    /// The scopes around `offset` of unit `unit`: its module, and in a
    /// routine the parameters, the routine data and the variables of the
    /// `FOR` loops that enclose the offset.
    pub(crate) fn at(task: &'t Task, unit: usize, offset: usize) -> Option<Scope<'t>> {
        let u: &'t Unit = task.unit(unit)?;
        let mut scope = Scope::of_unit(task, unit, u);
        let within = |r: &Range<usize>| r.start <= offset && offset <= r.end;
        scope.module = u
            .items
            .modules
            .iter()
            .enumerate()
            .find(|(_, m)| within(&m.range));
        let Some((_, module)) = scope.module else {
            return Some(scope);
        };
        let Some(decl) = module.routines.iter().find(|r| within(&r.range)) else {
            return Some(scope);
        };
        let root = u.tree().root_node();
        let Some(node) = root.named_descendant_for_byte_range(decl.range.start, decl.range.end)
        else {
            return Some(scope);
        };
        let mut routine = RoutineScope::new(decl);
        // Routine data comes before the first statement: stop there, so that
        // entering a long routine costs its declarations, not its statements
        // (constant evaluation enters the scope once per statement).
        if let Some(body) = crate::syntax_util::field_id(field::BODY) {
            let mut cursor = node.walk();
            for item in node
                .children_by_field_id(body, &mut cursor)
                .take_while(|n| crate::syntax_util::kind(*n) == kind::DATA_DECLARATION)
            {
                if let Some(d) = crate::items::lower_data(item, &u.text) {
                    routine.locals.entry(fold(&d.name)).or_insert(d);
                }
            }
        }
        let mut at = root.descendant_for_byte_range(offset, offset);
        while let Some(n) = at {
            if n.id() == node.id() {
                break;
            }
            if crate::syntax_util::kind(n) == kind::FOR_STATEMENT
                && let Some(v) = crate::syntax_util::field(n, field::VARIABLE)
            {
                routine
                    .for_vars
                    .insert(0, (fold(scope.node_text(v)), v.byte_range()));
            }
            at = n.parent();
        }
        scope.routine = Some(routine);
        Some(scope)
    }

    pub(crate) fn node_text(&self, node: Node<'_>) -> &'t str {
        self.text.get(node.byte_range()).unwrap_or_default()
    }

    pub(crate) fn module_idx(&self) -> Option<usize> {
        self.module.map(|(i, _)| i)
    }

    /// Items visible from the current module under `name`: its own items
    /// (any scope) first, then the task's globals.
    pub(crate) fn lookup_items(&self, name: &str) -> Vec<ItemRef> {
        with_folded(name, |key| self.lookup_items_folded(key))
    }

    pub(crate) fn lookup_items_folded(&self, key: &str) -> Vec<ItemRef> {
        visible(self.task, self.unit_idx, self.module_idx(), key)
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

    /// What a data name denotes here: a `FOR` variable, routine data, a
    /// parameter, module data visible from here, built-in data, then what
    /// the controller's configuration names (signals, mechanical units,
    /// tasks).
    pub(crate) fn resolve_data(&self, name: &str) -> Option<Def<'t>> {
        with_folded(name, |key| {
            self.resolve_data_folded(name, key).map(|(s, _)| s)
        })
    }

    /// [`Scope::resolve_data`] with the folded name, and the use to record
    /// for the unused-symbol lints (a routine-scope name or a module item).
    pub(crate) fn resolve_data_folded(
        &self,
        name: &str,
        key: &str,
    ) -> Option<(Def<'t>, Option<Use>)> {
        let unit = self.unit_idx;
        if let Some(r) = &self.routine {
            if let Some((_, range)) = r.for_vars.iter().rev().find(|(v, _)| v == key) {
                let range = range.clone();
                return Some((Def::ForVar { unit, range }, None));
            }
            if let Some(d) = r.locals.get(key) {
                let def = Def::Local {
                    unit,
                    decl: d.clone(),
                    routine: r.decl,
                };
                return Some((def, Some(Use::RoutineScope)));
            }
            if let Some(p) = r.params.get(key).copied() {
                let def = Def::Param {
                    unit,
                    decl: p,
                    routine: r.decl,
                };
                return Some((def, Some(Use::RoutineScope)));
            }
        }
        for r in self.lookup_items_folded(key) {
            if self.task.data(r).is_some() {
                return Some((Def::Item(r), Some(Use::Item(r))));
            }
        }
        if let Some(d) = self.cat.datum(name) {
            return Some((Def::BuiltinDatum(d), None));
        }
        let configured = if let Some(ty) = self.task.signals.as_ref().and_then(|s| s.get(key)) {
            *ty
        } else if self.task.mecunits.contains(key) {
            "mecunit"
        } else if self.task.task_ids.contains(key) {
            "taskid"
        } else {
            return None;
        };
        Some((Def::Signal(name.to_owned(), configured), None))
    }

    /// What a routine name denotes here: a routine visible from here, else
    /// a built-in one (a function first where a function is wanted).
    pub(crate) fn resolve_routine(&self, name: &str, want_function: bool) -> Option<Def<'t>> {
        for r in self.lookup_items(name) {
            if self.task.routine(r).is_some() {
                return Some(Def::Item(r));
            }
        }
        let (first, second) = if want_function {
            (self.cat.function(name), self.cat.instruction(name))
        } else {
            (self.cat.instruction(name), self.cat.function(name))
        };
        first.or(second).map(Def::BuiltinRoutine)
    }

    /// The record or alias visible here under `name`.
    pub(crate) fn type_item(&self, name: &str) -> Option<ItemRef> {
        self.lookup_items(name)
            .into_iter()
            .find(|r| matches!(r.item, Item::Record(_) | Item::Alias(_)))
    }
}

/// Which use a resolution makes, for the checker's unused-symbol lints.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Use {
    /// A parameter or routine data (recorded by folded name).
    RoutineScope,
    Item(ItemRef),
}
