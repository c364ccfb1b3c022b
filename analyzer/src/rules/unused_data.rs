use std::ops::Range;

use super::fix_text::{line_end, line_start, starts_line};
use crate::diagnostic::{Applicability, Diagnostic, Fix};

crate::declare_rule! {
    /// Routine data, or `LOCAL` module data, that is never used.
    ///
    /// ### What it checks
    /// Data declared in a routine, or declared `LOCAL` in a module, that no
    /// statement of its scope reads or writes.
    ///
    /// ### Why
    /// Unused data is often left over from an edit, or a sign that the wrong name
    /// was used elsewhere. The program works as it is, so this is a hint: editors
    /// show the declaration faded rather than listing a problem.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     VAR num unused;
    ///     TPWrite "Hello";
    /// ENDPROC
    /// ```
    pub static RULE = ("W201", "unused-data", Hint);
}

/// The finding on unused routine data `name` (at `name_range`), whose
/// declaration spans `decl` in `text`.
pub(crate) fn in_routine(
    text: &str,
    name: &str,
    name_range: Range<usize>,
    decl: Range<usize>,
) -> Diagnostic {
    Diagnostic::new(
        &RULE,
        name_range,
        format!("`{name}` is declared but never used"),
    )
    .with_fix(fix(text, decl, name))
}

/// The finding on unused `LOCAL` module data `name`, with its
/// declaration's span when known.
pub(crate) fn in_module(
    text: &str,
    name: &str,
    name_range: Range<usize>,
    decl: Option<Range<usize>>,
) -> Diagnostic {
    let d = Diagnostic::new(
        &RULE,
        name_range,
        format!("the LOCAL data `{name}` is never used in its module"),
    );
    match decl {
        Some(decl) => d.with_fix(fix(text, decl, name)),
        None => d,
    }
}

/// Removes the declaration at `decl`, with its whole line when nothing
/// but white space precedes it there and nothing but white space or a
/// comment (which describes the declaration) follows. Not safe: the
/// author may have meant to use it.
pub(crate) fn fix(text: &str, decl: Range<usize>, name: &str) -> Fix {
    let end = line_end(text, decl.end);
    let after = text.get(decl.end..end).unwrap_or_default().trim();
    let alone = starts_line(text, decl.start) && (after.is_empty() || after.starts_with('!'));
    let range = if alone {
        line_start(text, decl.start)..end
    } else {
        decl
    };
    Fix::edit(
        format!("Remove the declaration of `{name}`"),
        range,
        "",
        Applicability::Unsafe,
        false,
    )
}

/// The routine data of the routine being checked that no statement used.
pub(crate) fn check_routine(cx: &mut crate::check::Cx<'_>) {
    let Some(r) = &cx.routine else {
        return;
    };
    let found: Vec<Diagnostic> = r
        .locals
        .iter()
        .filter(|(key, _)| {
            !cx.used
                .contains(&crate::check::Used::RoutineSym((*key).clone()))
        })
        .map(|(_, d)| in_routine(cx.text, &d.name, d.name_range.clone(), d.range.clone()))
        .collect();
    for d in found {
        cx.report_with(d);
    }
}
