use std::collections::{BTreeMap, HashMap};

use crate::check::Cx;
use crate::diagnostic::Diagnostic;
use crate::items::{Module, Storage};
use crate::names::fold;
use crate::task::ItemRef;

crate::declare_rule! {
    /// A global name declared in more than one module of the task.
    ///
    /// ### What it checks
    /// Global (not `LOCAL`) data, routines and types are visible in the whole task,
    /// so two modules of one task may not both declare the same global name.
    /// Persistents are the exception: several declarations of one `PERS` name with
    /// the same type denote the same object. In a plain folder, whose grouping into
    /// a task is only a guess, modules that cannot be meant to load together are
    /// checked apart instead: two files of one module name, two modules that both
    /// declare `main` (versions of a program), and two modules that declare largely
    /// the same globals (copies of one module, such as a left and a right arm's
    /// driver). Other modules of a plain folder that share names get one warning
    /// per pair of modules, in the later one, listing the shared names, each
    /// with the other module's declaration as a related location. The
    /// modules of a controller's `HOME` folder that a program loads while it
    /// runs (`Load`, by a file name it writes out or computes) are part
    /// programs loaded one at a time: they share names by design, and are
    /// not checked against each other.
    ///
    /// ### Why
    /// The controller refuses to load the second module; which declaration was
    /// meant is ambiguous.
    ///
    /// ### Example
    /// ```rapid
    /// ! in MainModule.mod
    /// PROC init() ... ENDPROC
    /// ! in Tools.mod
    /// PROC init() ... ENDPROC    ! ambiguous
    /// ```
    pub static RULE = ("E107", "ambiguous-global", Error);
}

pub(crate) fn check(cx: &mut Cx<'_>, module: &Module) {
    let Some(mi) = cx.module.map(|(i, _)| i) else {
        return;
    };
    if cx.task.loaded_elsewhere {
        return;
    }

    // The first declaration of another module, by folded name: only a
    // persistent needs the whole list (many declarations of one name made
    // this quadratic).
    let mut first_elsewhere: HashMap<String, Option<ItemRef>> = HashMap::new();
    let mut clashes: Vec<(ItemRef, ItemRef)> = Vec::new();
    for (name, local, item) in crate::task::module_items(module) {
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
            clashes.push((me, other));
        }
    }
    // Modules the program loads while it runs are there each in its turn
    // (loaded, run, unloaded): they may share names with each other.
    // Asked only when there is a clash (it reads every unit's loads).
    if !clashes.is_empty() && crate::layout::in_home(&cx.unit.path) {
        let later = cx.task.run_time_loads();
        clashes.retain(|(me, other)| !(later.contains(&me.unit) && later.contains(&other.unit)));
    }
    if cx.task.is_certain() {
        for (me, other) in clashes {
            report_name(cx, me, other);
        }
    } else {
        report_by_module(cx, module, clashes);
    }
}

/// A task the controller loads: each name declared twice is an error.
fn report_name(cx: &mut Cx<'_>, me: ItemRef, other: ItemRef) {
    let other_module = module_name(cx, other);
    let Some((name, range)) = cx.task.item_name(me) else {
        return;
    };
    let mut d = Diagnostic::new(
        &RULE,
        range,
        format!("the global name `{name}` is also declared in module {other_module}"),
    );
    if let Some(rel) = cx.related_item(other, format!("also declared in {other_module}")) {
        d = d.with_related(rel);
    }
    cx.report_with(d);
}

/// The most names a finding of a plain folder lists in its message (its
/// related locations show every one).
const NAMES_LISTED: usize = 5;

/// A plain folder, whose grouping is a guess, may hold alternative programs
/// that are never loaded together: one warning per pair of modules, in the
/// later one, with every shared name as a related location, rather than
/// one per shared name.
fn report_by_module(cx: &mut Cx<'_>, module: &Module, clashes: Vec<(ItemRef, ItemRef)>) {
    let mut by_module: BTreeMap<(usize, usize), Vec<(ItemRef, ItemRef)>> = BTreeMap::new();
    for (me, other) in clashes {
        // The earlier module's first other declaration is reported there.
        if (other.unit, other.module) < (me.unit, me.module) {
            by_module
                .entry((other.unit, other.module))
                .or_default()
                .push((me, other));
        }
    }
    for pairs in by_module.into_values() {
        let Some(&(first, other)) = pairs.first() else {
            continue;
        };
        let Some((_, range)) = cx.task.item_name(first) else {
            continue;
        };
        let other_module = module_name(cx, other);
        let names: Vec<String> = pairs
            .iter()
            .filter_map(|(me, _)| cx.task.item_name(*me))
            .map(|(n, _)| format!("`{n}`"))
            .collect();
        let listed = match names.len() {
            0 => String::new(),
            1 => format!("the global name {}", names[0]),
            n if n <= NAMES_LISTED => format!("{n} global names ({})", names.join(", ")),
            n => format!(
                "{n} global names ({} and {} more)",
                names[..NAMES_LISTED].join(", "),
                n - NAMES_LISTED
            ),
        };
        let mut d = Diagnostic::new(
            &RULE,
            range,
            format!(
                "module {} declares {listed} that module {other_module} declares too \
                 (these modules form one task because they share a folder)",
                module.name
            ),
        );
        d.severity = crate::diagnostic::Severity::Warning;
        for (me, other) in &pairs {
            let name = cx.task.item_name(*me).map(|(n, _)| n.to_owned());
            let message = format!(
                "`{}` also declared in {other_module}",
                name.unwrap_or_default()
            );
            if let Some(rel) = cx.related_item(*other, message) {
                d = d.with_related(rel);
            }
        }
        cx.report_with(d);
    }
}

fn module_name(cx: &Cx<'_>, r: ItemRef) -> String {
    cx.task
        .module(r)
        .map(|m| m.name.clone())
        .unwrap_or_default()
}

/// Two `PERS` declarations of one type denote the same persistent object.
fn same_persistent(cx: &Cx<'_>, a: ItemRef, b: ItemRef) -> bool {
    match (cx.task.data(a), cx.task.data(b)) {
        (Some(x), Some(y)) => {
            x.storage == Storage::Pers
                && y.storage == Storage::Pers
                && crate::sema::def::decl_ty(x) == crate::sema::def::decl_ty(y)
        }
        _ => false,
    }
}
