//! Declarations: modules, their data, records and aliases, duplicates and
//! ambiguous globals, names that are too long, and the unused `LOCAL` items
//! of a module. Routines are checked by [`super::routine`], the whole
//! file's text by [`super::file_wide`].

use std::ops::Range;

use tree_sitter::Node;

use super::{Cx, Used, decl_ty, exprs};
use crate::items::{DataDecl, Module, RoutineDecl};
use crate::names::fold;
use crate::rules;
use crate::syntax::field;
use crate::syntax_util::{field, fields};
use crate::task::{Item, ItemRef, module_items};
use crate::ty::Ty;

pub(super) fn check_module<'t>(cx: &mut Cx<'t>, node: Node<'t>, module: &'t Module) {
    let data_nodes = BodyNodes::of(node);
    check_module_prelude(cx, module, &data_nodes);
    for decl in &module.routines {
        check_routine_at(cx, &data_nodes, decl);
    }
    check_unused_locals_of_module(cx, module);
}

/// The declarations of a module's body, in source order, found by their
/// start offset.
#[derive(Debug)]
pub(super) struct BodyNodes<'t>(Vec<Node<'t>>);

impl<'t> BodyNodes<'t> {
    pub(super) fn of(module: Node<'t>) -> BodyNodes<'t> {
        BodyNodes(fields(module, field::BODY))
    }

    /// The declaration that starts at `start` (the last one, should an
    /// empty node start there too).
    pub(super) fn at(&self, start: usize) -> Option<Node<'t>> {
        let after = self.0.partition_point(|n| n.start_byte() <= start);
        let n = *self.0.get(after.checked_sub(1)?)?;
        (n.start_byte() == start).then_some(n)
    }
}

/// The checks of a module other than its routines' and its unused LOCAL
/// items: its name, duplicates, ambiguous globals, data, records, aliases.
pub(super) fn check_module_prelude<'t>(
    cx: &mut Cx<'t>,
    module: &'t Module,
    data_nodes: &BodyNodes<'t>,
) {
    check_module_names(cx, module);
    check_module_data(cx, module, data_nodes);
    check_records_and_aliases(cx, module);
}

/// The module's name, duplicates and ambiguous globals.
fn check_module_names(cx: &mut Cx<'_>, module: &Module) {
    rules::name_too_long::check(cx, &module.name, module.name_range.clone());
    check_duplicates_in_module(cx, module);
    rules::ambiguous_global::check(cx, module);
    rules::duplicate_module::check(cx, module);
}

/// Checks the module's data declarations.
fn check_module_data<'t>(cx: &mut Cx<'t>, module: &'t Module, data_nodes: &BodyNodes<'t>) {
    for decl in &module.data {
        if let Some(n) = data_nodes.at(decl.range.start) {
            check_data(cx, n, decl, false);
        }
    }
}

fn check_records_and_aliases(cx: &mut Cx<'_>, module: &Module) {
    for decl in &module.records {
        rules::name_too_long::check(cx, &decl.name, decl.name_range.clone());
        for (name, ty, range) in &decl.components {
            rules::name_too_long::check(cx, name, range.clone());
            if let Some(t) = ty {
                check_type_name(cx, &t.name, t.range.clone());
            }
        }
    }
    for decl in &module.aliases {
        rules::name_too_long::check(cx, &decl.name, decl.name_range.clone());
        if let Some(t) = &decl.of {
            check_type_name(cx, &t.name, t.range.clone());
        }
    }
}

/// Checks a routine of the current module, found by its declaration.
pub(super) fn check_routine_at<'t>(
    cx: &mut Cx<'t>,
    data_nodes: &BodyNodes<'t>,
    decl: &'t RoutineDecl,
) {
    if let Some(n) = data_nodes.at(decl.range.start) {
        super::routine::check_routine(cx, n, decl);
    }
}

pub(super) fn check_type_name(cx: &mut Cx<'_>, name: &str, range: Range<usize>) {
    if !cx.type_exists(name) {
        cx.unresolved(name, range, "data type");
    } else {
        cx.type_used(name, range);
    }
}

/// One name space per module: data, routines, records and aliases.
fn check_duplicates_in_module(cx: &mut Cx<'_>, module: &Module) {
    let mut all: Vec<(&str, Range<usize>)> = module_items(module)
        .filter_map(|(name, _, item)| {
            let r = ItemRef {
                unit: cx.unit_idx,
                module: 0,
                item,
            };
            let range = match r.item {
                Item::Data(i) => module.data.get(i)?.name_range.clone(),
                Item::Routine(i) => module.routines.get(i)?.name_range.clone(),
                Item::Record(i) => module.records.get(i)?.name_range.clone(),
                Item::Alias(i) => module.aliases.get(i)?.name_range.clone(),
            };
            Some((name, range))
        })
        .collect();
    all.sort_by_key(|(_, r)| r.start);
    rules::duplicate_declaration::report(cx, all, "in this module");
}

/// Checks a data declaration of a module or a routine.
pub(super) fn check_data<'t>(cx: &mut Cx<'t>, node: Node<'t>, decl: &DataDecl, in_routine: bool) {
    crate::consteval::check_constant_errors(cx, node);
    rules::name_too_long::check(cx, &decl.name, decl.name_range.clone());
    if let Some(t) = &decl.ty {
        check_type_name(cx, &t.name, t.range.clone());
    }
    rules::too_many_dimensions::check(cx, &decl.name, decl.name_range.clone(), decl.dims.len());
    if let Some(dims) = field(node, field::DIMENSIONS) {
        for d in fields(dims, field::DIMENSION) {
            let ty = exprs::expr(cx, d, Some(&Ty::num()));
            rules::type_mismatch::check_array_size(cx, d.byte_range(), &ty);
        }
    }
    match field(node, field::VALUE) {
        Some(value) => {
            let sizes = literal_sizes(cx, decl);
            exprs::check_initial_value(cx, value, &decl_ty(decl), &sizes);
        }
        // A declaration the parser could not read (e.g. a template's
        // `{{PORT}}` for the value) has its syntax error already.
        None if node.has_error() => {}
        None => rules::missing_initializer::check(cx, decl),
    }
    if !in_routine {
        rules::shared_persistent_mismatch::check(cx, decl);
    }
    if in_routine {
        rules::persistent_in_routine::check(cx, node, decl);
    }
}

/// The sizes of an array declaration that are written as plain numbers.
fn literal_sizes(cx: &Cx<'_>, decl: &DataDecl) -> Vec<Option<usize>> {
    decl.dims
        .iter()
        .map(|r| {
            cx.text
                .get(r.clone())
                .unwrap_or_default()
                .trim()
                .parse::<usize>()
                .ok()
        })
        .collect()
}

/// Is `name` used by name in a string of its module: late binding
/// (`%"name"%`, `%"path_" + n%`), `CallByVar "path_", n`, `GetDataVal
/// "name"`? A string that is the name, or a prefix of it of three
/// characters or more followed by what a computed suffix gives (digits or
/// any name characters), counts.
fn named_in_strings(name: &str, strings: &[String]) -> bool {
    let name = fold(name);
    strings.iter().any(|s| {
        *s == name || (s.len() >= 3 && name.len() > s.len() && name.starts_with(s.as_str()))
    })
}

pub(super) fn check_unused_locals_of_module(cx: &mut Cx<'_>, module: &Module) {
    let Some(mi) = cx.module.map(|(i, _)| i) else {
        return;
    };
    let mut found = Vec::new();
    let mut data_found = Vec::new();
    // The module's string literals, read when a LOCAL item seems unused.
    let mut strings: Option<Vec<String>> = None;
    for (name, local, item) in module_items(module) {
        if !local {
            continue;
        }
        let r = ItemRef {
            unit: cx.unit_idx,
            module: mi,
            item,
        };
        if cx.used.contains(&Used::Item(r)) {
            continue;
        }
        let strings = strings.get_or_insert_with(|| {
            let text = cx.text.get(module.range.clone()).unwrap_or_default();
            crate::lex::string_literals(text)
                .into_iter()
                .map(|(_, s)| fold(s.trim()))
                .filter(|s| !s.is_empty())
                .collect()
        });
        if named_in_strings(name, strings) {
            continue;
        }
        let Some((_, range)) = cx.task.item_name(r) else {
            continue;
        };
        match item {
            Item::Data(i) => {
                data_found.push(rules::unused_data::in_module(
                    cx.text,
                    name,
                    range,
                    module.data.get(i).map(|decl| decl.range.clone()),
                ));
            }
            Item::Routine(_) => found.push((name, range)),
            _ => {}
        }
    }
    for (name, range) in found {
        rules::unused_routine::report(cx, name, range);
    }
    for d in data_found {
        cx.report_with(d);
    }
}
