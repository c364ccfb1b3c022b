//! Characters RAPID does not know outside strings and comments: blanks
//! other than the ASCII ones (a no-break space pasted as indentation, an
//! ideographic space typed with an East Asian keyboard) and symbols beyond
//! ASCII that are not letters of Latin-1. The parser makes an error of each
//! run of them; they are reported once per line, with a fix that turns
//! such blanks into spaces.

use std::collections::BTreeMap;

use tree_sitter::Node;

use crate::diagnostic::{Applicability, Diagnostic, Edit, Fix};
use crate::rules::syntax_error;

/// Is `c` a character that is neither ASCII nor a letter of a name?
fn is_stray(c: char) -> bool {
    !c.is_ascii() && !crate::names::is_name_char(c) && c != '\u{feff}'
}

/// The stray characters of an error node that holds nothing else (blanks
/// aside), as (byte range, character).
pub(super) fn stray(node: Node<'_>, text: &str) -> Option<Vec<(std::ops::Range<usize>, char)>> {
    let start = node.start_byte();
    let t = text.get(node.byte_range())?;
    let mut found = Vec::new();
    for (i, c) in t.char_indices() {
        if is_stray(c) {
            found.push((start + i..start + i + c.len_utf8(), c));
        } else if !c.is_ascii_whitespace() {
            return None;
        }
    }
    (!found.is_empty()).then_some(found)
}

/// What a stray character is, in words.
fn describe(c: char) -> String {
    let name = match c {
        '\u{a0}' => "a no-break space",
        '\u{3000}' => "an ideographic space",
        '\u{200b}' => "a zero-width space",
        c if c.is_whitespace() => "a blank that is not a space",
        _ => "",
    };
    let code = format!("U+{:04X}", c as u32);
    if name.is_empty() {
        format!("`{c}` ({code})")
    } else {
        format!("{name} ({code})")
    }
}

/// One diagnostic per line for the stray characters found (each run with
/// its range), naming the first; blanks among them are made spaces by
/// the fix.
pub(super) fn once_per_line(
    text: &str,
    runs: Vec<Vec<(std::ops::Range<usize>, char)>>,
) -> Vec<Diagnostic> {
    let mut lines: BTreeMap<usize, Vec<(std::ops::Range<usize>, char)>> = BTreeMap::new();
    for (range, c) in runs.into_iter().flatten() {
        let line = text
            .get(..range.start)
            .map_or(0, |b| b.bytes().filter(|&b| b == b'\n').count());
        lines.entry(line).or_default().push((range, c));
    }
    lines
        .into_values()
        .filter_map(|chars| {
            let (first, c) = chars.first()?.clone();
            let more = chars.len() - 1;
            let message = match more {
                0 => format!(
                    "unexpected {}: outside strings and comments RAPID knows spaces, tabs, ASCII and the letters of Latin-1",
                    describe(c)
                ),
                n => format!(
                    "unexpected {} and {n} more such character{} on this line: outside strings and comments RAPID knows spaces, tabs, ASCII and the letters of Latin-1",
                    describe(c),
                    if n == 1 { "" } else { "s" }
                ),
            };
            let edits: Vec<Edit> = chars
                .iter()
                .filter(|(_, c)| c.is_whitespace())
                .map(|(range, _)| Edit {
                    range: range.clone(),
                    replacement: " ".to_owned(),
                })
                .collect();
            let d = Diagnostic::new(&syntax_error::RULE, first, message);
            Some(if edits.is_empty() {
                d
            } else {
                d.with_fix(Fix {
                    title: "Replace the blanks with spaces".to_owned(),
                    edits,
                    applicability: Applicability::Safe,
                    preferred: true,
                })
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use crate::task::Unit;

    fn syntax(text: &str) -> Vec<(usize, String)> {
        let unit = Unit::new("m.mod".into(), text.into(), None);
        let index = crate::text::LineIndex::new(text);
        unit.syntax
            .iter()
            .map(|d| (index.human(d.range.start, text).0, d.message.clone()))
            .collect()
    }

    #[test]
    fn stray_blanks_are_one_error_per_line() {
        let nb = '\u{a0}';
        let text = format!(
            "MODULE M\n  PROC P()\n{nb}{nb}{nb}{nb}P;\n  \u{3000}P; {nb} \n    P;\n  ENDPROC\nENDMODULE\n"
        );
        let found = syntax(&text);
        assert_eq!(found.len(), 2, "{found:?}");
        assert_eq!(found[0].0, 3);
        assert!(
            found[0]
                .1
                .starts_with("unexpected a no-break space (U+00A0) and 3 more"),
            "{}",
            found[0].1
        );
        assert_eq!(found[1].0, 4);
        assert!(
            found[1].1.starts_with(
                "unexpected an ideographic space (U+3000) and 1 more such character on"
            ),
            "{}",
            found[1].1
        );
        let unit = Unit::new("m.mod".into(), text.clone(), None);
        let fix = unit.syntax[0].fix.as_ref().expect("a fix");
        assert_eq!(fix.edits.len(), 4);
    }

    #[test]
    fn symbols_are_no_letters() {
        let found = syntax("MODULE M\n  VAR num a\u{d7}b;\nENDMODULE\n");
        assert!(!found.is_empty());
        assert!(syntax("MODULE M\n  VAR num a\u{f8}b;\nENDMODULE\n").is_empty());
    }
}
