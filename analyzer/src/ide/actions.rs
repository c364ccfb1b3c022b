//! Code actions: the fixes the diagnostics carry, as actions. Every fix is
//! built by its rule (`rules/<rule>.rs`) and attached to its diagnostic;
//! nothing here knows a rule.

use std::ops::Range;

use super::CodeAction;
use crate::diagnostic::Diagnostic;
use crate::task::Task;

/// The fixes of the diagnostics that overlap `range`, each an action for
/// its diagnostic (an index into `diagnostics`). `task` and `unit` are
/// those the diagnostics were found in; a diagnostic whose fix was dropped
/// (one carried past an edit that touched it) offers none until it is
/// checked again.
pub fn code_actions(
    task: &Task,
    unit: usize,
    range: Range<usize>,
    diagnostics: &[Diagnostic],
) -> Vec<CodeAction> {
    let Some(u) = task.unit(unit) else {
        return Vec::new();
    };
    let fits = |r: &Range<usize>| {
        r.start <= r.end && u.text.is_char_boundary(r.start) && u.text.is_char_boundary(r.end)
    };
    diagnostics
        .iter()
        .enumerate()
        .filter(|(_, d)| d.range.end >= range.start && d.range.start <= range.end)
        .filter_map(|(i, d)| {
            let fix = d.fix.as_ref()?;
            if fix.edits.is_empty() || !fix.edits.iter().all(|e| fits(&e.range)) {
                return None;
            }
            Some(CodeAction {
                title: fix.title.clone(),
                edits: fix.edits.clone(),
                diagnostic: Some(i),
                preferred: fix.preferred,
            })
        })
        .collect()
}
