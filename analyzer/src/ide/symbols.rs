//! Document symbols (hierarchical) and workspace symbols (fuzzy).

use std::sync::Arc;

use super::{Symbol, SymbolKind};
use crate::items::{DataDecl, Module, RoutineKind, Storage};
use crate::syntax::{field, kind};
use crate::syntax_util::fields;
use crate::task::{Task, Unit};

fn data_symbol(d: &DataDecl) -> Symbol {
    let kind = match d.storage {
        Storage::Var => SymbolKind::Variable,
        Storage::Pers => SymbolKind::Persistent,
        Storage::Const => SymbolKind::Constant,
    };
    let mut detail = d.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default();
    if !d.dims.is_empty() {
        detail.push_str(&format!("{{{}}}", vec!["*"; d.dims.len()].join(",")));
    }
    Symbol {
        name: d.name.clone(),
        kind,
        range: d.range.clone(),
        selection_range: d.name_range.clone(),
        detail: Some(format!("{} {detail}", d.storage.keyword())),
        children: Vec::new(),
    }
}

fn module_symbol(unit: &Unit, m: &Module, with_locals: bool) -> Symbol {
    let mut children: Vec<Symbol> = Vec::new();
    children.extend(m.data.iter().map(data_symbol));
    for r in &m.records {
        children.push(Symbol {
            name: r.name.clone(),
            kind: SymbolKind::Record,
            range: r.range.clone(),
            selection_range: r.name_range.clone(),
            detail: Some("RECORD".to_owned()),
            children: r
                .components
                .iter()
                .map(|(n, t, range)| Symbol {
                    name: n.clone(),
                    kind: SymbolKind::Component,
                    range: range.clone(),
                    selection_range: range.clone(),
                    detail: t.as_ref().map(|t| t.name.clone()),
                    children: Vec::new(),
                })
                .collect(),
        });
    }
    for a in &m.aliases {
        children.push(Symbol {
            name: a.name.clone(),
            kind: SymbolKind::Alias,
            range: a.range.clone(),
            selection_range: a.name_range.clone(),
            detail: a.of.as_ref().map(|t| format!("ALIAS {}", t.name)),
            children: Vec::new(),
        });
    }
    for r in &m.routines {
        let kind = match r.kind {
            RoutineKind::Proc => SymbolKind::Procedure,
            RoutineKind::Func => SymbolKind::Function,
            RoutineKind::Trap => SymbolKind::Trap,
        };
        let locals = if with_locals {
            routine_data(unit, &r.range)
        } else {
            Vec::new()
        };
        children.push(Symbol {
            name: r.name.clone(),
            kind,
            range: r.range.clone(),
            selection_range: r.name_range.clone(),
            detail: Some(super::hover::routine_header(&unit.text, r)),
            children: locals,
        });
    }
    children.sort_by_key(|s| s.range.start);
    Symbol {
        name: m.name.clone(),
        kind: SymbolKind::Module,
        range: m.range.clone(),
        selection_range: m.name_range.clone(),
        detail: None,
        children,
    }
}

/// The data declared in the routine at `range`.
fn routine_data(unit: &Unit, range: &std::ops::Range<usize>) -> Vec<Symbol> {
    let root = unit.tree().root_node();
    let Some(node) = root.named_descendant_for_byte_range(range.start, range.end) else {
        return Vec::new();
    };
    fields(node, field::BODY)
        .into_iter()
        .filter(|n| n.kind() == kind::DATA_DECLARATION)
        .filter_map(|n| crate::items::lower_data(n, &unit.text))
        .map(|d| data_symbol(&d))
        .collect()
}

/// The outline of a file: modules holding their data, records (with
/// components), aliases and routines (with their routine data), in source
/// order.
pub fn document_symbols(unit: &Unit) -> Vec<Symbol> {
    unit.items
        .modules
        .iter()
        .map(|m| module_symbol(unit, m, true))
        .collect()
}

/// Does `query` match `name`: as a substring (rank 0) or its letters in
/// order (rank 1)? Case-insensitive.
fn matches(name: &str, query: &str) -> Option<u8> {
    let n = crate::names::fold(name);
    let q = crate::names::fold(query);
    if n.contains(&q) {
        return Some(if n.starts_with(&q) { 0 } else { 1 });
    }
    let mut chars = n.chars();
    q.chars()
        .all(|c| chars.by_ref().any(|x| x == c))
        .then_some(2)
}

/// Most symbols a workspace query returns.
const MAX_WORKSPACE_SYMBOLS: usize = 500;

/// Symbols of every task whose name contains `query` or its letters in
/// order (case-insensitive), best matches first, at most 500.
pub fn workspace_symbols(tasks: &[Arc<Task>], query: &str) -> Vec<(String, Symbol)> {
    let mut found: Vec<(u8, String, Symbol)> = Vec::new();
    for task in tasks {
        for unit in task.units.iter() {
            for m in &unit.items.modules {
                let module = module_symbol(unit, m, false);
                let mut all = vec![Symbol {
                    children: Vec::new(),
                    ..module.clone()
                }];
                all.extend(module.children.into_iter().map(|mut s| {
                    s.children.clear();
                    s
                }));
                for s in all {
                    if let Some(rank) = matches(&s.name, query) {
                        found.push((rank, unit.path.clone(), s));
                    }
                }
            }
        }
    }
    found.sort_by(|a, b| {
        (a.0, a.2.name.len(), &a.2.name, &a.1).cmp(&(b.0, b.2.name.len(), &b.2.name, &b.1))
    });
    found.truncate(MAX_WORKSPACE_SYMBOLS);
    found.into_iter().map(|(_, p, s)| (p, s)).collect()
}
