use std::collections::HashMap;

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
    /// a task is only a guess, it is a warning, and modules that cannot be meant to
    /// load together are checked apart instead: two files of one module name, two
    /// modules that both declare `main` (versions of a program), and two modules
    /// that declare largely the same globals (copies of one module, such as a left
    /// and a right arm's driver).
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
    // The first declaration of another module, by folded name: only a
    // persistent needs the whole list (many declarations of one name made
    // this quadratic).
    let mut first_elsewhere: HashMap<String, Option<ItemRef>> = HashMap::new();
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
            let other_module = cx
                .task
                .module(other)
                .map(|m| m.name.clone())
                .unwrap_or_default();
            let Some((_, range)) = cx.task.item_name(me) else {
                continue;
            };
            let mut d = Diagnostic::new(
                &RULE,
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
            x.storage == Storage::Pers
                && y.storage == Storage::Pers
                && crate::sema::def::decl_ty(x) == crate::sema::def::decl_ty(y)
        }
        _ => false,
    }
}
