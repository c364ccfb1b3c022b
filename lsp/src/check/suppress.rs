//! Inline suppression comments.
//!
//! - `! rapid: ignore[E201, unused-data]` after code on a line silences
//!   those rules on that line;
//! - the same comment on a line of its own silences them on the next line
//!   that holds code (blank and comment-only lines in between are skipped,
//!   so several such comments can stack above one statement);
//! - `! rapid: ignore-module[W101]` anywhere silences them in the whole file;
//! - without a list (`! rapid: ignore`, `! rapid: ignore-module`) every rule
//!   is silenced.
//!
//! Rules are named by code, code prefix or name, as in `rapid.toml`. The
//! line of a diagnostic is the line where its range starts.

use std::collections::HashMap;

use rapid_analyzer::diagnostic::Rule;
use rapid_analyzer::text::LineIndex;

use crate::config::selects;

/// Which rules a suppression names.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Which {
    All,
    Rules(Vec<String>),
}

impl Which {
    fn covers(&self, rule: &Rule) -> bool {
        match self {
            Which::All => true,
            Which::Rules(list) => list.iter().any(|s| selects(s, rule)),
        }
    }
}

/// The suppressions of one file.
#[derive(Debug, Default)]
pub struct Suppressions {
    /// By 0-based line.
    lines: HashMap<usize, Vec<Which>>,
    module: Vec<Which>,
}

impl Suppressions {
    pub fn parse(text: &str, lines: &LineIndex) -> Suppressions {
        let mut out = Suppressions::default();
        // Suppressions on their own line wait for the next line of code.
        let mut pending: Vec<Which> = Vec::new();
        // Cheap exit for the common file without any.
        if !text.contains("rapid:") {
            return out;
        }
        for line in 0..lines.line_count() {
            let range = lines.line_range(line, text);
            let Some(content) = text.get(range) else {
                continue;
            };
            let content = content.trim_end_matches(['\r', '\n']);
            let (code, comment) = split_comment(content);
            let has_code = !code.trim().is_empty();
            if has_code && !pending.is_empty() {
                out.lines.entry(line).or_default().append(&mut pending);
            }
            let Some((module, which)) = comment.and_then(directive) else {
                continue;
            };
            if module {
                out.module.push(which);
            } else if has_code {
                out.lines.entry(line).or_default().push(which);
            } else {
                pending.push(which);
            }
        }
        out
    }

    /// Is `rule` silenced on this 0-based line?
    pub fn suppresses(&self, line: usize, rule: &Rule) -> bool {
        self.module.iter().any(|w| w.covers(rule))
            || self
                .lines
                .get(&line)
                .is_some_and(|ws| ws.iter().any(|w| w.covers(rule)))
    }
}

/// A line's code and its comment (after `!`), if any. A `!` inside a string
/// literal (`"..."`, with `""` for a quote) does not start a comment.
fn split_comment(line: &str) -> (&str, Option<&str>) {
    let mut in_string = false;
    for (i, b) in line.bytes().enumerate() {
        match b {
            b'"' => in_string = !in_string,
            b'!' if !in_string => return (&line[..i], Some(&line[i + 1..])),
            _ => {}
        }
    }
    (line, None)
}

/// Reads `rapid: ignore[...]` or `rapid: ignore-module[...]` from a comment:
/// whether it is for the module, and the rules.
fn directive(comment: &str) -> Option<(bool, Which)> {
    let rest = comment.trim_start().strip_prefix("rapid:")?.trim_start();
    let (module, rest) = if let Some(r) = rest.strip_prefix("ignore-module") {
        (true, r)
    } else if let Some(r) = rest.strip_prefix("ignore") {
        (false, r)
    } else {
        return None;
    };
    let rest = rest.trim_start();
    let Some(list) = rest.strip_prefix('[') else {
        // `ignore` alone, or followed by an explanation.
        return (rest.is_empty() || !rest.starts_with(|c: char| c.is_alphanumeric() || c == '-'))
            .then_some((module, Which::All));
    };
    let list = list.split_once(']').map_or(list, |(inside, _)| inside);
    let rules: Vec<String> = list
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(str::to_owned)
        .collect();
    Some((module, Which::Rules(rules)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_analyzer::rules::find;

    /// The (1-based) lines on which each rule is silenced, for a rule list.
    fn silenced(text: &str, rule: &str) -> Vec<usize> {
        let lines = LineIndex::new(text);
        let s = Suppressions::parse(text, &lines);
        let rule = find(rule).expect("a rule");
        (0..lines.line_count())
            .filter(|&l| s.suppresses(l, rule))
            .map(|l| l + 1)
            .collect()
    }

    #[test]
    fn same_line_next_line_and_module() {
        let text = "MODULE M\n\
                    VAR num a; ! rapid: ignore[W201, unknown-label]\n\
                    VAR num b;\n\
                    ! rapid: ignore[unused-data]\n\
                    \n\
                    ! another comment\n\
                    VAR num c;\n\
                    VAR num d;\n\
                    ENDMODULE\n";
        assert_eq!(silenced(text, "W201"), [2, 7]);
        assert_eq!(silenced(text, "unknown-label"), [2]);
        assert_eq!(silenced(text, "E001"), Vec::<usize>::new());
    }

    #[test]
    fn module_wide_and_blanket_forms() {
        let text = "MODULE M\r\n! rapid: ignore-module[W1]\r\nVAR num a;\r\nVAR num b; !rapid:ignore\r\nENDMODULE";
        assert_eq!(silenced(text, "W101"), [1, 2, 3, 4, 5]);
        assert_eq!(silenced(text, "W201"), [4]);
    }

    #[test]
    fn comments_inside_strings_and_other_comments_do_not_count() {
        let text = "MODULE M\n\
                    VAR string s := \"! rapid: ignore[W201]\";\n\
                    VAR string t := \"a\"\"!\"; ! rapid: ignore[W201]\n\
                    VAR num x; ! rapid: ignored[W201]\n\
                    VAR num y; ! rapid: ignore W201\n\
                    ENDMODULE\n";
        // A list without brackets is not read as a blanket suppression.
        assert_eq!(silenced(text, "W201"), [3]);
        assert_eq!(silenced(text, "E001"), Vec::<usize>::new());
    }
}
