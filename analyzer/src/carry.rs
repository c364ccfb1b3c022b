//! What carries over between two versions of a file before the new one
//! is checked: the old version's findings moved past the edit.

use std::ops::Range;

use crate::diagnostic::Diagnostic;
use crate::task::Unit;

/// The diagnostics of `unit` without checking it: its syntax diagnostics,
/// and the other diagnostics of `old_unit` (an older text of the same file)
/// moved past the edit between the two texts; those touching the edited
/// span are dropped. A fix moves with its diagnostic when none of its
/// edits touches the edited span, and is dropped otherwise (the next check
/// builds it again).
pub fn carry_over(old_unit: &Unit, old: &[Diagnostic], unit: &Unit) -> Vec<Diagnostic> {
    let (old_text, new_text) = (old_unit.text.as_bytes(), unit.text.as_bytes());
    let (prefix, suffix) = crate::text::common_affixes(old_text, new_text);
    let old_end = old_text.len() - suffix;
    let new_end = new_text.len() - suffix;
    let moved = |r: &Range<usize>| -> Option<Range<usize>> {
        if r.end <= prefix && r.end < old_end {
            Some(r.clone())
        } else if r.start >= old_end && r.start > prefix {
            Some(r.start - old_end + new_end..r.end - old_end + new_end)
        } else {
            None
        }
    };
    let mut out = unit.syntax.clone();
    for d in old.iter().filter(|d| !old_unit.syntax.contains(d)) {
        // Related locations in this file move too, or go.
        let Some(range) = moved(&d.range) else {
            continue;
        };
        let mut d = d.clone();
        d.range = range;
        d.related.retain_mut(|r| {
            if r.file.is_some() {
                return true;
            }
            match moved(&r.range) {
                Some(m) => {
                    r.range = m;
                    true
                }
                None => false,
            }
        });
        d.fix = d.fix.as_ref().and_then(|f| f.shifted(moved));
        out.push(d);
    }
    out.sort_by_key(|d| (d.range.start, d.range.end));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::task::Task;
    use crate::workspace::diagnostics_of;
    use std::sync::Arc;

    fn diagnostics(text: &str) -> (Arc<Unit>, Vec<Diagnostic>) {
        let unit = Arc::new(Unit::new("t/A.mod".into(), text.to_owned(), None));
        let task = Task::new("t".into(), vec![unit.clone()], None);
        let d = diagnostics_of(&task, &unit);
        (unit, d)
    }

    fn summary(text: &str, d: &[Diagnostic]) -> Vec<(String, String)> {
        d.iter()
            .map(|d| (d.rule.code.to_owned(), text[d.range.clone()].to_owned()))
            .collect()
    }

    #[test]
    fn diagnostics_are_carried_past_an_edit() {
        let before = "MODULE M\n  PROC p()\n    one;\n    two;\n    three;\n  ENDPROC\nENDMODULE\n";
        let (old_unit, old) = diagnostics(before);
        assert_eq!(summary(before, &old).len(), 3, "{old:?}");
        // Edit `two` (its diagnostic goes), insert a line with a syntax
        // error before `three` (which moves).
        let after = "MODULE M\n  PROC p()\n    one;\n    twice;\n    x := ;\n    three;\n  ENDPROC\nENDMODULE\n";
        let unit = Unit::new("t/A.mod".into(), after.to_owned(), None);
        let carried = carry_over(&old_unit, &old, &unit);
        let codes: Vec<(String, String)> = summary(after, &carried);
        assert_eq!(codes[0], ("W101".to_owned(), "one".to_owned()));
        assert!(codes.iter().any(|(c, _)| c.starts_with("E00")), "{codes:?}");
        assert_eq!(codes.last(), Some(&("W101".to_owned(), "three".to_owned())));
        assert!(!codes.iter().any(|(_, t)| t.contains("tw")), "{codes:?}");
        // A check finds all of them again (and what the edit brought).
        let fresh = summary(after, &diagnostics(after).1);
        assert!(
            codes.iter().all(|c| fresh.contains(c)),
            "{codes:?} {fresh:?}"
        );
        assert_eq!(fresh.len(), codes.len() + 2, "`twice` and `x`: {fresh:?}");
    }

    /// (name at the diagnostic, its fix's edits applied to `text`).
    fn fixed(text: &str, d: &[Diagnostic]) -> Vec<(String, Option<String>)> {
        d.iter()
            .map(|d| {
                let fixed = d.fix.as_ref().map(|f| {
                    let mut t = text.to_owned();
                    let mut edits = f.edits.clone();
                    edits.sort_by_key(|e| std::cmp::Reverse(e.range.start));
                    for e in edits {
                        t.replace_range(e.range, &e.replacement);
                    }
                    t
                });
                (text[d.range.clone()].to_owned(), fixed)
            })
            .collect()
    }

    #[test]
    fn fixes_move_with_carried_diagnostics_or_go() {
        let before = "MODULE M\n  PROC p()\n    VAR num spare; ! was\n    one := 1;\n  ENDPROC\n  PROC q()\n    VAR num later;\n    p;\n  ENDPROC\nENDMODULE\n";
        // The comment after `spare` edited: its diagnostic stays, but its
        // fix removed that line.
        let after = before.replace("was", "is now");
        let after = after.as_str();
        let (old_unit, old) = diagnostics(before);
        assert_eq!(old.iter().filter(|d| d.fix.is_some()).count(), 3, "{old:?}");
        let unit = Unit::new("t/A.mod".into(), after.to_owned(), None);
        let carried = fixed(after, &carry_over(&old_unit, &old, &unit));
        let fresh = fixed(after, &diagnostics(after).1);
        assert_eq!(carried.len(), 3, "{carried:?}");
        assert_eq!(fresh.len(), 3, "{fresh:?}");
        // `spare`'s fix touched the edit: gone, while a check makes it anew.
        assert_eq!(carried[0].0, "spare");
        assert_eq!(carried[0].1, None);
        assert!(fresh[0].1.is_some(), "{fresh:?}");
        // The others give what a check gives: `one`'s fix edits the top of
        // the routine (before the edit, so it stays), `later`'s moves.
        assert_eq!(carried[1..], fresh[1..]);
        assert!(
            carried[1]
                .1
                .as_deref()
                .is_some_and(|t| t.contains("  PROC p()\n    VAR num one;\n    VAR num spare;")),
            "{carried:?}"
        );
        assert!(
            carried[2]
                .1
                .as_deref()
                .is_some_and(|t| t.contains("  PROC q()\n    p;\n")),
            "{carried:?}"
        );
    }
}
