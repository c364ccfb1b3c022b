//! Declarations: modules, data, routines and their scopes; the checks that
//! look at the whole file (placeholders, long strings, long names).

use std::collections::HashMap;
use std::ops::Range;

use tree_sitter::Node;

use super::{Cx, RoutineCx, Used, decl_ty, exprs, stmts};
use crate::diagnostic::Diagnostic;
use crate::items::{self, DataDecl, Module, RoutineDecl, RoutineKind, Storage};
use crate::names::{NameMap, fold, same};
use crate::rules;
use crate::syntax_util::{field, fields};
use crate::task::{Item, ItemRef, module_items};
use crate::ty::Ty;

const MAX_NAME: usize = 32;
const MAX_STRING: usize = 80;
const MAX_DIMS: usize = 3;

/// Placeholders and string lengths, anywhere in the file.
pub(super) fn check_file_wide(cx: &mut Cx<'_>) {
    // The walk only enters nodes that overlap a region of the text that may
    // hold a finding, and nodes with syntax errors.
    let regions = placeholder_or_long_string_regions(cx.text);
    if regions.is_empty() {
        return;
    }
    let unit = cx.unit;
    check_file_wide_in(cx, unit.tree().root_node(), &regions);
}

/// [`check_file_wide`] in one tree, entering only nodes that overlap
/// `regions` (or hold a syntax error).
fn check_file_wide_in(cx: &mut Cx<'_>, root: Node<'_>, regions: &[Range<usize>]) {
    let overlaps = |node: Node<'_>| {
        let r = node.byte_range();
        let i = regions.partition_point(|g| g.end <= r.start);
        regions.get(i).is_some_and(|g| g.start < r.end)
    };
    let worth_entering = |node: Node<'_>| overlaps(node) || node.has_error();
    static KINDS: std::sync::OnceLock<(u16, u16)> = std::sync::OnceLock::new();
    let (placeholder, string) = *KINDS.get_or_init(|| {
        let language = crate::syntax::language();
        (
            language.id_for_node_kind("placeholder", true),
            language.id_for_node_kind("string", true),
        )
    });
    crate::syntax_util::walk_pruned(root, &mut |node| {
        let kind = node.kind_id();
        match kind {
            k if k == placeholder && overlaps(node) => {
                let p = cx.node_text(node);
                cx.report(
                    &rules::incomplete_code::RULE,
                    node.byte_range(),
                    format!("unfilled placeholder {p}: this code is not finished"),
                );
            }
            k if k == string && overlaps(node) => {
                let len = string_length(cx, node);
                if len > MAX_STRING {
                    cx.report(
                        &rules::string_too_long::RULE,
                        node.byte_range(),
                        format!("this string has {len} characters; a RAPID string holds at most {MAX_STRING}"),
                    );
                }
            }
            _ => {}
        }
        kind != string && worth_entering(node)
    });
}

/// The regions of the text (sorted, disjoint byte ranges) where a
/// placeholder or a string longer than the limit may be: the placeholder
/// token's pattern, `<[A-Z]{2,4}>` (comparisons such as `a<b` do not match),
/// and the lines with more than the limit between their first and last
/// quote (a string does not span lines).
fn placeholder_or_long_string_regions(text: &str) -> Vec<Range<usize>> {
    // Both need a quote or a `<`: most generated modules have neither, and
    // two searches of the whole text cost less than a look at every line.
    if !text.contains('"') && !text.contains('<') {
        return Vec::new();
    }
    let bytes = text.as_bytes();
    let mut regions: Vec<Range<usize>> = Vec::new();
    let mut add = |r: Range<usize>| match regions.last_mut() {
        Some(last) if last.end >= r.start => last.end = last.end.max(r.end),
        _ => regions.push(r),
    };
    let mut line_start = 0;
    for line in text.split_inclusive('\n') {
        let start = line_start;
        line_start += line.len();
        if line.len() > MAX_STRING
            && let (Some(a), Some(b)) = (line.find('"'), line.rfind('"'))
            && b - a > MAX_STRING
        {
            add(start..start + line.len());
            continue;
        }
        if !line.contains('<') {
            continue;
        }
        for (i, &b) in line.as_bytes().iter().enumerate() {
            if b != b'<' {
                continue;
            }
            let at = start + i;
            let rest = bytes.get(at + 1..).unwrap_or_default();
            let upper = rest.iter().take_while(|c| c.is_ascii_uppercase()).count();
            if (2..=4).contains(&upper) && rest.get(upper) == Some(&b'>') {
                add(at..at + upper + 2);
            }
        }
    }
    regions
}

/// The number of characters of a string literal's value (escapes count one).
fn string_length(cx: &Cx<'_>, node: Node<'_>) -> usize {
    let mut cursor = node.walk();
    node.named_children(&mut cursor)
        .map(|c| match crate::syntax_util::kind(c) {
            "escape_sequence" => 1,
            _ => cx.node_text(c).chars().count(),
        })
        .sum()
}

fn check_name_length(cx: &mut Cx<'_>, name: &str, range: Range<usize>) {
    if name.len() > MAX_NAME {
        cx.report(
            &rules::name_too_long::RULE,
            range,
            format!(
                "`{name}` has {} characters; names have at most {MAX_NAME}",
                name.len()
            ),
        );
    }
}

pub(super) fn check_module<'t>(cx: &mut Cx<'t>, node: Node<'t>, module: &'t Module) {
    let data_nodes = BodyNodes::of(cx.unit, node);
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
    pub(super) fn of(unit: &'t crate::task::Unit, module: Node<'t>) -> BodyNodes<'t> {
        let _ = unit;
        BodyNodes(fields(module, "body"))
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
    check_name_length(cx, &module.name, module.name_range.clone());
    check_duplicates_in_module(cx, module);
    check_ambiguous_globals(cx, module);
    check_duplicate_module(cx, module);
}

/// Another file of the task (left out of this view of it) declares the
/// same module: reported in the later file, once.
fn check_duplicate_module(cx: &mut Cx<'_>, module: &Module) {
    if !cx.task.is_certain() {
        return;
    }
    let first = cx.task.excluded.iter().find_map(|e| {
        let (_, range) = e.modules.iter().find(|(n, _)| same(n, &module.name))?;
        (e.path < cx.unit.path).then(|| (e.path.clone(), range.clone()))
    });
    let Some((path, range)) = first else {
        return;
    };
    let file = path
        .rsplit(['/', '\\'])
        .next()
        .unwrap_or_default()
        .to_owned();
    let d = Diagnostic::new(
        &rules::duplicate_module::RULE,
        module.name_range.clone(),
        format!(
            "module {} is also declared in {file}: a task loads only one of them",
            module.name
        ),
    )
    .with_related(crate::diagnostic::Related {
        file: Some(path),
        range,
        message: format!("module {} declared here too", module.name),
    });
    cx.report_with(d);
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
        check_name_length(cx, &decl.name, decl.name_range.clone());
        for (name, ty, range) in &decl.components {
            check_name_length(cx, name, range.clone());
            if let Some(t) = ty {
                check_type_name(cx, &t.name, t.range.clone());
            }
        }
    }
    for decl in &module.aliases {
        check_name_length(cx, &decl.name, decl.name_range.clone());
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
        check_routine(cx, n, decl);
    }
}

fn check_type_name(cx: &mut Cx<'_>, name: &str, range: Range<usize>) {
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
    report_duplicates(cx, all, "in this module");
}

fn report_duplicates(cx: &mut Cx<'_>, names: Vec<(&str, Range<usize>)>, scope: &str) {
    let mut first: HashMap<String, Range<usize>> = HashMap::new();
    for (name, range) in names {
        match first.get(&fold(name)) {
            Some(prev) => {
                let d = Diagnostic::new(
                    &rules::duplicate_declaration::RULE,
                    range,
                    format!("`{name}` is declared twice {scope}"),
                )
                .with_related(crate::diagnostic::Related {
                    file: None,
                    range: prev.clone(),
                    message: "first declared here".into(),
                });
                cx.report_with(d);
            }
            None => {
                first.insert(fold(name), range);
            }
        }
    }
}

fn check_ambiguous_globals(cx: &mut Cx<'_>, module: &Module) {
    let Some(mi) = cx.module.map(|(i, _)| i) else {
        return;
    };
    // The first declaration of another module, by folded name: only a
    // persistent needs the whole list (many declarations of one name made
    // this quadratic).
    let mut first_elsewhere: HashMap<String, Option<ItemRef>> = HashMap::new();
    for (name, local, item) in module_items(module) {
        if local {
            continue;
        }
        let me = ItemRef {
            unit: cx.unit_idx,
            module: mi,
            item,
        };
        let key = fold(name);
        let Some(all) = cx.task.globals.get(&key) else {
            continue;
        };
        let elsewhere = |r: &ItemRef| (r.unit, r.module) != (me.unit, me.module);
        let other = if cx.task.data(me).is_some_and(|d| d.storage == Storage::Pers) {
            all.iter()
                .copied()
                .find(|r| elsewhere(r) && !same_persistent(cx, me, *r))
        } else {
            // `same_persistent` is false when `me` is not a persistent.
            *first_elsewhere
                .entry(key)
                .or_insert_with(|| all.iter().copied().find(elsewhere))
        };
        if let Some(other) = other {
            let other_module = cx
                .task
                .module(other)
                .map(|m| m.name.clone())
                .unwrap_or_default();
            let Some((_, range)) = cx.task.item_name(me) else {
                continue;
            };
            let mut d = Diagnostic::new(
                &rules::ambiguous_global::RULE,
                range,
                format!("the global name `{name}` is also declared in module {other_module}"),
            );
            if let Some(rel) = cx.related_item(other, format!("also declared in {other_module}")) {
                d = d.with_related(rel);
            }
            if !cx.task.is_certain() {
                // A plain folder may hold alternative programs that are never
                // loaded together: the grouping is a guess, so only warn.
                d.severity = crate::diagnostic::Severity::Warning;
                d.message
                    .push_str(" (these modules form one task because they share a folder)");
            }
            cx.report_with(d);
        }
    }
}

/// Two `PERS` declarations of one type denote the same persistent object.
fn same_persistent(cx: &Cx<'_>, a: ItemRef, b: ItemRef) -> bool {
    match (cx.task.data(a), cx.task.data(b)) {
        (Some(x), Some(y)) => {
            x.storage == Storage::Pers && y.storage == Storage::Pers && decl_ty(x) == decl_ty(y)
        }
        _ => false,
    }
}

/// Checks a data declaration of a module or a routine.
pub(super) fn check_data<'t>(cx: &mut Cx<'t>, node: Node<'t>, decl: &DataDecl, in_routine: bool) {
    crate::consteval::check_constant_errors(cx, node);
    check_name_length(cx, &decl.name, decl.name_range.clone());
    if let Some(t) = &decl.ty {
        check_type_name(cx, &t.name, t.range.clone());
    }
    if decl.dims.len() > MAX_DIMS {
        cx.report(
            &rules::too_many_dimensions::RULE,
            decl.name_range.clone(),
            format!(
                "`{}` has {} dimensions; RAPID arrays have at most {MAX_DIMS}",
                decl.name,
                decl.dims.len()
            ),
        );
    }
    if let Some(dims) = field(node, "dimensions") {
        for d in fields(dims, "dimension") {
            let ty = exprs::expr(cx, d, Some(&Ty::num()));
            if !cx.types.is_num_like(&ty) {
                cx.report(
                    &rules::type_mismatch::RULE,
                    d.byte_range(),
                    format!("an array size must be a num, found {ty}"),
                );
            }
        }
    }
    match field(node, "value") {
        Some(value) => {
            let sizes = literal_sizes(cx, decl);
            exprs::check_initial_value(cx, value, &decl_ty(decl), &sizes);
        }
        // A declaration the parser could not read (e.g. a template's
        // `{{PORT}}` for the value) has its syntax error already.
        None if node.has_error() => {}
        None if decl.storage == Storage::Const => {
            cx.report(
                &rules::missing_initializer::RULE,
                decl.name_range.clone(),
                format!(
                    "the constant `{}` needs a value: CONST {} {} := ...;",
                    decl.name,
                    decl.ty.as_ref().map_or("<type>", |t| t.name.as_str()),
                    decl.name
                ),
            );
        }
        // Only system-global persistents may leave out the value: the
        // controller then takes it from another task's declaration of the
        // same persistent, or the type's default. TASK and LOCAL persistents
        // have no other declaration to take it from.
        None if decl.storage == Storage::Pers && decl.scope != items::Scope::Global => {
            let kind = if decl.scope == items::Scope::Task {
                "TASK"
            } else {
                "LOCAL"
            };
            cx.report(
                &rules::missing_initializer::RULE,
                decl.name_range.clone(),
                format!(
                    "the {kind} persistent `{}` needs a value: {kind} PERS {} {} := ...;",
                    decl.name,
                    decl.ty.as_ref().map_or("<type>", |t| t.name.as_str()),
                    decl.name
                ),
            );
        }
        None => {}
    }
    if !in_routine {
        super::shared::check_persistent(cx, decl);
    }
    if in_routine && decl.storage == Storage::Pers {
        let at = field(node, "storage").map_or(decl.name_range.clone(), |s| s.byte_range());
        cx.report(
            &rules::persistent_in_routine::RULE,
            at,
            format!(
                "`{}` is a persistent declared in a routine; declare it at module level, or make it VAR",
                decl.name
            ),
        );
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

/// Checks a routine: its declarations, labels, statements, handlers and
/// end, and the routine data and parameters it never uses.
fn check_routine<'t>(cx: &mut Cx<'t>, node: Node<'t>, decl: &'t RoutineDecl) {
    check_name_length(cx, &decl.name, decl.name_range.clone());
    let mut params = NameMap::default();
    let mut names: Vec<(&str, Range<usize>)> = Vec::new();
    for p in &decl.params {
        check_name_length(cx, &p.name, p.name_range.clone());
        if let Some(t) = &p.ty
            && !p.switch
        {
            check_type_name(cx, &t.name, t.range.clone());
        }
        if usize::from(p.dims) > MAX_DIMS {
            cx.report(
                &rules::too_many_dimensions::RULE,
                p.name_range.clone(),
                format!(
                    "`{}` has {} dimensions; RAPID arrays have at most {MAX_DIMS}",
                    p.name, p.dims
                ),
            );
        }
        names.push((&p.name, p.name_range.clone()));
        params.entry(fold(&p.name)).or_insert(p);
    }
    if let Some(t) = &decl.returns {
        check_type_name(cx, &t.name, t.range.clone());
    }
    cx.routine = Some(RoutineCx {
        decl,
        params,
        locals: NameMap::default(),
        for_vars: Vec::new(),
        labels: NameMap::default(),
        in_error_handler: false,
    });
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
        if crate::syntax_util::kind(item) == "data_declaration" {
            decl_nodes.push(item);
            if seen_statement {
                cx.report(
                    &rules::declaration_after_statement::RULE,
                    item.byte_range(),
                    "routine data must be declared before the routine's first statement",
                );
            }
            if let Some(d) = items::lower_data(item, cx.text) {
                check_shadowing(cx, &d.name, d.name_range.clone(), true);
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
        check_shadowing(cx, &p.name, p.name_range.clone(), false);
    }
    names.extend(local_names.iter().map(|(n, r)| (n.as_str(), r.clone())));
    report_duplicates(cx, names, "in this routine");

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
    stmts::check_block(cx, &statements);
    for (h, in_error) in handlers.into_iter().zip([false, true, false]) {
        if let Some(h) = h {
            if let Some(r) = &mut cx.routine {
                r.in_error_handler = in_error;
            }
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

/// A routine's data or parameter that hides a module or task name, or (for
/// routine data only) a built-in one. Parameters named like a built-in
/// (`speed`, `tool`...) are common and harmless: the parameter is the
/// routine's interface, and the built-in is rarely wanted inside.
fn check_shadowing(cx: &mut Cx<'_>, name: &str, range: Range<usize>, builtins: bool) {
    let visible = cx
        .lookup_items(name)
        .into_iter()
        .find(|r| cx.task.data(*r).is_some() || cx.task.routine(*r).is_some());
    let what = if let Some(r) = visible {
        let module = cx
            .task
            .module(r)
            .map(|m| m.name.clone())
            .unwrap_or_default();
        let local = cx
            .task
            .data(r)
            .is_some_and(|d| d.scope == items::Scope::Local)
            || cx.task.routine(r).is_some_and(|d| d.local);
        format!(
            "the {} `{name}` of module {module}",
            if local { "LOCAL" } else { "global" }
        )
    } else if !builtins {
        return;
    } else if cx.cat.datum(name).is_some() {
        format!("the built-in data `{name}`")
    } else if cx.cat.routine(name).is_some() {
        format!("the built-in routine `{name}`")
    } else {
        return;
    };
    cx.report(
        &rules::shadowed_name::RULE,
        range,
        format!("this declaration hides {what} within the routine"),
    );
}

fn check_unused_in_routine(cx: &mut Cx<'_>, decl: &RoutineDecl) {
    let Some(r) = &cx.routine else {
        return;
    };
    let mut found = Vec::new();
    for (key, d) in &r.locals {
        if !cx.used.contains(&Used::RoutineSym(key.clone())) {
            found.push(rules::unused_data::in_routine(
                cx.text,
                &d.name,
                d.name_range.clone(),
                d.range.clone(),
            ));
        }
    }
    for p in &decl.params {
        if !cx.used.contains(&Used::RoutineSym(fold(&p.name))) {
            found.push(Diagnostic::new(
                &rules::unused_parameter::RULE,
                p.name_range.clone(),
                format!("the parameter `{}` is never used", p.name),
            ));
        }
    }
    for d in found {
        cx.report_with(d);
    }
    // Routine symbols are per routine: forget them for the next one.
    cx.used.retain(|u| !matches!(u, Used::RoutineSym(_)));
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
            Item::Routine(_) => found.push((
                &rules::unused_routine::RULE,
                range,
                format!("the LOCAL routine `{name}` is never called in its module"),
            )),
            _ => {}
        }
    }
    for (rule, range, message) in found {
        cx.report(rule, range, message);
    }
    for d in data_found {
        cx.report_with(d);
    }
}
