//! `rapid check --fix`: applying the safe fixes of diagnostics to a text.

use rapid_analyzer::diagnostic::{Diagnostic, Edit};
use rapid_analyzer::text::LineEnding;

/// The text with every safe fix of `diagnostics` applied, and how many
/// fixes that was; `None` when there was none to apply. Fixes whose edits
/// overlap an earlier fix's, or fall outside the text, are left for the
/// next pass. New lines in replacements take the file's line ending.
pub fn apply_safe_fixes(text: &str, diagnostics: &[Diagnostic]) -> Option<(String, usize)> {
    let mut fixes: Vec<Vec<&Edit>> = diagnostics
        .iter()
        .filter_map(|d| d.fix.as_ref())
        .filter(|f| f.is_safe() && !f.edits.is_empty())
        .map(|f| {
            let mut edits: Vec<&Edit> = f.edits.iter().collect();
            edits.sort_by_key(|e| (e.range.start, e.range.end));
            edits
        })
        .collect();
    if fixes.is_empty() {
        return None;
    }
    fixes.sort_by_key(|edits| edits.first().map(|e| (e.range.start, e.range.end)));
    let mut accepted: Vec<&Edit> = Vec::new();
    let mut count = 0;
    for edits in fixes {
        let valid = edits.iter().all(|e| {
            e.range.start <= e.range.end
                && text.is_char_boundary(e.range.start)
                && text.is_char_boundary(e.range.end)
                && e.range.end <= text.len()
        });
        let internal_overlap = edits.windows(2).any(|w| w[1].range.start < w[0].range.end);
        let clashes = edits.iter().any(|e| {
            accepted.iter().any(|a| {
                (e.range.start < a.range.end && a.range.start < e.range.end)
                    || (e.range.start == a.range.start
                        && (e.range.is_empty() || a.range.is_empty()))
            })
        });
        if valid && !internal_overlap && !clashes {
            accepted.extend(edits);
            count += 1;
        }
    }
    if count == 0 {
        return None;
    }
    accepted.sort_by_key(|e| (e.range.start, e.range.end));
    let newline = LineEnding::detect(text).as_str();
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for e in accepted {
        out.push_str(&text[at..e.range.start]);
        if newline == "\n" || !e.replacement.contains('\n') || e.replacement.contains('\r') {
            out.push_str(&e.replacement);
        } else {
            out.push_str(&e.replacement.replace('\n', newline));
        }
        at = e.range.end;
    }
    out.push_str(&text[at..]);
    Some((out, count))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_analyzer::diagnostic::{Applicability, Fix};
    use rapid_analyzer::rules::find;

    fn diag(safe: bool, edits: &[(usize, usize, &str)]) -> Diagnostic {
        let rule = find("W201").expect("a rule");
        Diagnostic::new(rule, 0..0, "m").with_fix(Fix {
            title: "fix".into(),
            edits: edits
                .iter()
                .map(|&(s, e, r)| Edit {
                    range: s..e,
                    replacement: r.into(),
                })
                .collect(),
            applicability: if safe {
                Applicability::Safe
            } else {
                Applicability::Unsafe
            },
            preferred: safe,
        })
    }

    #[test]
    fn applies_safe_fixes_only() {
        let text = "abcdef";
        let ds = [
            diag(true, &[(0, 1, "A")]),
            diag(false, &[(2, 3, "C")]),
            diag(true, &[(4, 5, "E"), (5, 6, "F")]),
            Diagnostic::new(find("W201").expect("a rule"), 0..1, "no fix"),
        ];
        assert_eq!(apply_safe_fixes(text, &ds), Some(("AbcdEF".to_owned(), 2)));
        assert_eq!(apply_safe_fixes(text, &ds[1..2]), None);
    }

    #[test]
    fn overlapping_and_out_of_range_fixes_wait() {
        let text = "abcdef";
        let ds = [
            diag(true, &[(1, 3, "X")]),
            diag(true, &[(2, 4, "Y")]),
            diag(true, &[(5, 60, "Z")]),
            diag(true, &[(1, 1, "<")]),
        ];
        // In order of position: the insertion at 1, then `Y` (`X` clashes
        // with both), and `Z` is out of range.
        assert_eq!(apply_safe_fixes(text, &ds), Some(("a<bYef".to_owned(), 2)));
    }

    #[test]
    fn new_lines_follow_the_file() {
        let text = "a\r\nb\r\n";
        let ds = [diag(true, &[(3, 3, "x\ny\n")])];
        assert_eq!(
            apply_safe_fixes(text, &ds),
            Some(("a\r\nx\r\ny\r\nb\r\n".to_owned(), 1))
        );
    }
}
