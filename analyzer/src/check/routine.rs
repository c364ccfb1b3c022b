//! A routine: its parameters and data, labels, statements, handlers and
//! end, what its data hides, and the data and parameters it never uses.

use std::ops::Range;

use tree_sitter::Node;

use super::decls::{check_data, check_type_name};
use super::{Cx, Used, exprs, stmts};
use crate::items::{self, RoutineDecl, RoutineKind};
use crate::names::{NameMap, fold};
use crate::rules;
use crate::sema::scope::RoutineScope;
use crate::syntax_util::fields;
use crate::ty::Ty;

/// Checks a routine: its declarations, labels, statements, handlers and
/// end, and the routine data and parameters it never uses.
pub(super) fn check_routine<'t>(cx: &mut Cx<'t>, node: Node<'t>, decl: &'t RoutineDecl) {
    rules::name_too_long::check(cx, &decl.name, decl.name_range.clone());
    let mut params = NameMap::default();
    let mut names: Vec<(&str, Range<usize>)> = Vec::new();
    for p in &decl.params {
        rules::name_too_long::check(cx, &p.name, p.name_range.clone());
        if let Some(t) = &p.ty
            && !p.switch
        {
            check_type_name(cx, &t.name, t.range.clone());
        }
        rules::too_many_dimensions::check(cx, &p.name, p.name_range.clone(), usize::from(p.dims));
        names.push((&p.name, p.name_range.clone()));
        params.entry(fold(&p.name)).or_insert(p);
    }
    if let Some(t) = &decl.returns {
        check_type_name(cx, &t.name, t.range.clone());
    }
    cx.routine = Some(RoutineScope {
        decl,
        params,
        locals: NameMap::default(),
        for_vars: Vec::new(),
    });
    cx.labels.clear();
    cx.in_error_handler = false;
    cx.scope_changed();

    // One walk over the routine's children (long generated routines make
    // each walk costly): the items of its body, its handlers, its labels.
    let RoutineChildren {
        body,
        labels,
        handlers,
    } = all_routine_children(cx.unit, node);
    // Routine data, which must come before the first statement.
    let mut seen_statement = false;
    let mut statements = Vec::new();
    let mut local_names: Vec<(String, Range<usize>)> = Vec::new();
    let mut decl_nodes = Vec::new();
    for item in body {
        if crate::syntax_util::kind(item) == crate::syntax::kind::DATA_DECLARATION {
            decl_nodes.push(item);
            if seen_statement {
                rules::declaration_after_statement::report(cx, item.byte_range());
            }
            if let Some(d) = items::lower_data(item, cx.text) {
                rules::shadowed_name::check(cx, &d.name, d.name_range.clone(), true);
                check_data(cx, item, &d, true);
                local_names.push((d.name.clone(), d.name_range.clone()));
                if let Some(r) = &mut cx.routine {
                    r.locals.entry(fold(&d.name)).or_insert(d);
                }
                cx.scope_changed();
            }
        } else {
            seen_statement = true;
            statements.push(item);
        }
    }
    for p in &decl.params {
        rules::shadowed_name::check(cx, &p.name, p.name_range.clone(), false);
    }
    names.extend(local_names.iter().map(|(n, r)| (n.as_str(), r.clone())));
    rules::duplicate_declaration::report(cx, names, "in this routine");

    // The statement cache's view of the routine: its name and kind (the
    // parameters are in the task's interface) and the text of its data
    // declarations, so that white space around statements does not count.
    cx.cache.routines += 1;
    cx.routine_fingerprint = {
        use std::hash::{Hash, Hasher};
        let mut h = std::hash::DefaultHasher::new();
        (fold(&decl.name), decl.kind).hash(&mut h);
        for item in &decl_nodes {
            cx.node_text(*item).hash(&mut h);
        }
        h.finish()
    };
    stmts::collect_labels(cx, labels);
    rules::label_names_routine::check(cx, node);
    stmts::check_block(cx, &statements);
    for (h, in_error) in handlers.into_iter().zip([false, true, false]) {
        if let Some(h) = h {
            cx.in_error_handler = in_error;
            for e in fields(h, "error") {
                exprs::check_expected(cx, e, &Ty::named("errnum"), "an error number");
            }
            stmts::check_block(cx, &fields(h, "body"));
        }
    }
    if decl.kind == RoutineKind::Func && !stmts::block_terminates(cx, &statements) {
        let mut d = rules::missing_return::diagnostic(&decl.name, decl.name_range.clone());
        let last = statements.last().or(decl_nodes.last()).copied();
        if let Some(returns) = &decl.returns
            && let Some(fix) = rules::missing_return::fix(
                cx.text,
                &cx.types,
                node,
                last,
                &decl.name,
                &returns.name,
            )
        {
            d = d.with_fix(fix);
        }
        cx.report_with(d);
    }
    super::multimove::check(cx, decl);
    check_unused_in_routine(cx, decl);
    cx.routine = None;
    cx.scope_changed();
}

/// A routine's children, from one walk.
#[derive(Debug)]
struct RoutineChildren<'t> {
    /// In field `body`.
    body: Vec<Node<'t>>,
    /// The labels of the routine ([`crate::sema::labels::find`]).
    labels: Vec<crate::sema::labels::Label>,
    /// The first child in fields `backward`, `error` and `undo`.
    handlers: [Option<Node<'t>>; 3],
}

/// The children of a routine, with its labels.
fn all_routine_children<'t>(unit: &'t crate::task::Unit, node: Node<'t>) -> RoutineChildren<'t> {
    let (mut children, named) = routine_children(node);
    children.labels = crate::sema::labels::find(&unit.text, node, Some(named));
    children
}

/// A routine's children without its labels, and its named children.
fn routine_children(node: Node<'_>) -> (RoutineChildren<'_>, Vec<Node<'_>>) {
    use crate::syntax_util::field_id;
    let body_id = field_id("body");
    let handler_ids = [field_id("backward"), field_id("error"), field_id("undo")];
    let mut out = RoutineChildren {
        body: Vec::new(),
        labels: Vec::new(),
        handlers: [None; 3],
    };
    let mut named = Vec::new();
    let mut cursor = node.walk();
    if cursor.goto_first_child() {
        loop {
            let child = cursor.node();
            if let Some(id) = cursor.field_id() {
                if Some(id) == body_id {
                    out.body.push(child);
                }
                for (slot, h) in out.handlers.iter_mut().zip(handler_ids) {
                    if slot.is_none() && Some(id) == h {
                        *slot = Some(child);
                    }
                }
            }
            if child.is_named() {
                named.push(child);
            }
            if !cursor.goto_next_sibling() {
                break;
            }
        }
    }
    (out, named)
}

fn check_unused_in_routine(cx: &mut Cx<'_>, decl: &RoutineDecl) {
    rules::unused_data::check_routine(cx);
    rules::unused_parameter::check(cx, decl);
    // Routine symbols are per routine: forget them for the next one.
    cx.used.retain(|u| !matches!(u, Used::RoutineSym(_)));
}
