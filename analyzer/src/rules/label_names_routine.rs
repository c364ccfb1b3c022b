use tree_sitter::Node;

use crate::check::Cx;
use crate::diagnostic::{Applicability, Diagnostic, Fix};
use crate::items::RoutineKind;
use crate::names::fold;
use crate::sema::def::Def;
use crate::sema::signature::Signature;
use crate::syntax::{field, kind};

crate::declare_rule! {
    /// A label that no `GOTO` uses and that names a procedure.
    ///
    /// Most likely a call typed with `:` instead of `;`.
    ///
    /// ### What it checks
    /// A label (`name:`) that no `GOTO` of its routine jumps to, whose name
    /// is a procedure the routine can call: one of the task's (other than
    /// the routine itself), or a built-in instruction that needs no
    /// argument (`Stop`, `ExitCycle`).
    ///
    /// ### Why
    /// `R_Home:` where `R_Home;` was meant loads without a complaint, and
    /// the routine silently never calls `R_Home`. The fix writes the call.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     R_Home:          ! a label, not a call of R_Home
    ///     TPWrite "at home";
    /// ENDPROC
    /// ```
    pub static RULE = ("W208", "label-names-routine", Warning);
}

/// The labels of the routine `node` being checked (`cx.labels`, found by
/// [`crate::sema::labels`]): each that names a procedure and that no
/// `GOTO` of the routine uses.
pub(crate) fn check(cx: &mut Cx<'_>, node: Node<'_>) {
    if cx.labels.is_empty() || !cx.selection.is_on(&RULE) {
        return;
    }
    let mut candidates: Vec<(String, std::ops::Range<usize>, String)> = Vec::new();
    // a label named after its own routine marks a place in it (a call
    // there would be a recursion)
    let own = cx.routine.as_ref().map(|r| fold(&r.decl.name));
    let labels: Vec<(String, std::ops::Range<usize>)> = cx
        .labels
        .iter()
        .filter(|(key, _)| Some(*key) != own.as_ref())
        .map(|(key, (range, _))| (key.clone(), range.clone()))
        .collect();
    for (key, range) in labels {
        let name = cx.text.get(range.clone()).unwrap_or_default();
        let Some(def) = cx.resolve_routine(name, false) else {
            continue;
        };
        let callable = match &def {
            Def::BuiltinRoutine(r) => {
                !r.is_function()
                    && Signature::builtin(r).known
                    && Signature::builtin(r).params.iter().all(|p| p.optional)
            }
            def => def
                .routine_decl(cx.task)
                .is_some_and(|d| d.kind == RoutineKind::Proc),
        };
        if callable {
            candidates.push((key, range, def.name(cx.task)));
        }
    }
    if candidates.is_empty() {
        return;
    }
    let used = goto_targets(cx.text, node);
    candidates.sort_by_key(|(_, r, _)| r.start);
    for (key, range, routine) in candidates {
        if used.contains(&key) {
            continue;
        }
        let name = cx.text.get(range.clone()).unwrap_or_default().to_owned();
        // the label's `:` (its node ends with it)
        let colon = cx.text.get(range.end..).and_then(|rest| {
            let at = rest.find(|c: char| !c.is_whitespace())?;
            (rest.as_bytes().get(at) == Some(&b':')).then(|| range.end + at)
        });
        let mut d = Diagnostic::new(
            &RULE,
            range.clone(),
            format!(
                "`{name}:` is a label that no GOTO uses, and `{routine}` is a procedure: to call it, write `{name};`"
            ),
        );
        if let Some(at) = colon {
            d = d.with_fix(Fix::edit(
                format!("Call `{routine}` (`{name};`)"),
                at..at + 1,
                ";",
                Applicability::Unsafe,
                true,
            ));
        }
        cx.report_with(d);
    }
}

/// The folded names that the `GOTO`s of the routine jump to.
fn goto_targets(text: &str, routine: Node<'_>) -> std::collections::HashSet<String> {
    let mut out = std::collections::HashSet::new();
    let mut cursor = routine.walk();
    let mut stack = vec![routine];
    while let Some(n) = stack.pop() {
        if n.kind() == kind::GOTO_STATEMENT {
            if let Some(label) = n.child_by_field_name(field::LABEL)
                && let Some(name) = text.get(label.byte_range())
            {
                out.insert(fold(name));
            }
            continue;
        }
        if n.kind().ends_with("expression") {
            continue;
        }
        stack.extend(n.named_children(&mut cursor));
    }
    out
}
