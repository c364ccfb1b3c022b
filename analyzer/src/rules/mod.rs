//! The registry of every rule. Each rule lives in its own file with its
//! documentation; this list is the one place that names them all, in code
//! order. Codes are never reused: a retired rule stays listed.

use crate::diagnostic::{Diagnostic, Rule};
use crate::task::Task;

pub mod aggregate_arity;
pub mod ambiguous_global;
pub mod argument_count;
pub mod argument_mode;
pub mod array_argument;
pub mod assign_to_constant;
pub mod builtin_version;
pub mod call_kind_mismatch;
pub mod condition_not_bool;
pub mod conditional_argument;
pub mod configuration_mismatch;
pub mod conflicting_alternatives;
pub mod connect_target;
pub mod constant_error;
pub mod declaration_after_statement;
pub mod duplicate_argument;
pub mod duplicate_declaration;
pub mod duplicate_module;
pub mod equals_for_assignment;
pub(crate) mod fix_text;
pub mod float_equality;
pub mod goto_into_block;
pub mod handler_only_statement;
pub mod incomplete_code;
pub mod index_count;
pub mod invalid_escape;
pub mod invalid_operands;
pub mod joint_out_of_range;
pub mod label_names_routine;
pub mod local_not_visible;
pub mod missing_alternative;
pub mod missing_initializer;
pub mod missing_return;
pub mod missing_sync_id;
pub mod missing_token;
pub mod name_too_long;
pub mod nesting_too_deep;
pub mod non_numeric_index;
pub mod not_a_routine;
pub mod option_routine;
pub mod persistent_in_routine;
pub mod return_value;
pub mod shadowed_name;
pub mod shared_persistent_mismatch;
pub mod string_too_long;
pub mod switch_argument;
pub mod sync_move_count;
pub mod sync_task_mismatch;
pub mod sync_without_stop_point;
pub mod syntax_error;
pub mod target_out_of_reach;
pub mod too_many_dimensions;
pub mod type_mismatch;
pub mod unconfigured_signal;
pub mod unknown_argument;
pub mod unknown_component;
pub mod unknown_label;
pub mod unpaired_sync_move;
pub mod unreachable_code;
pub mod unresolved_name;
pub mod unused_data;
pub mod unused_parameter;
pub mod unused_routine;

/// Every rule, in code order.
pub static RULES: &[&Rule] = &[
    &syntax_error::RULE,
    &missing_token::RULE,
    &equals_for_assignment::RULE,
    &unknown_label::RULE,
    &unknown_component::RULE,
    &duplicate_declaration::RULE,
    &ambiguous_global::RULE,
    &local_not_visible::RULE,
    &shared_persistent_mismatch::RULE,
    &type_mismatch::RULE,
    &non_numeric_index::RULE,
    &aggregate_arity::RULE,
    &invalid_operands::RULE,
    &condition_not_bool::RULE,
    &index_count::RULE,
    &call_kind_mismatch::RULE,
    &not_a_routine::RULE,
    &argument_count::RULE,
    &unknown_argument::RULE,
    &switch_argument::RULE,
    &conflicting_alternatives::RULE,
    &missing_alternative::RULE,
    &duplicate_argument::RULE,
    &argument_mode::RULE,
    &array_argument::RULE,
    &conditional_argument::RULE,
    &assign_to_constant::RULE,
    &missing_initializer::RULE,
    &return_value::RULE,
    &missing_return::RULE,
    &handler_only_statement::RULE,
    &goto_into_block::RULE,
    &connect_target::RULE,
    &declaration_after_statement::RULE,
    &too_many_dimensions::RULE,
    &name_too_long::RULE,
    &string_too_long::RULE,
    &incomplete_code::RULE,
    &constant_error::RULE,
    &persistent_in_routine::RULE,
    &invalid_escape::RULE,
    &missing_sync_id::RULE,
    &target_out_of_reach::RULE,
    &joint_out_of_range::RULE,
    &option_routine::RULE,
    &unconfigured_signal::RULE,
    &nesting_too_deep::RULE,
    &unresolved_name::RULE,
    &builtin_version::RULE,
    &unused_data::RULE,
    &unused_parameter::RULE,
    &unused_routine::RULE,
    &unreachable_code::RULE,
    &shadowed_name::RULE,
    &float_equality::RULE,
    &duplicate_module::RULE,
    &label_names_routine::RULE,
    &unpaired_sync_move::RULE,
    &sync_without_stop_point::RULE,
    &sync_task_mismatch::RULE,
    &sync_move_count::RULE,
    &configuration_mismatch::RULE,
];

/// The rules a check runs. A rule switched off is not reported, and the
/// checks that cost something (constant evaluation for E413) do not run
/// for it; the same selection applied after the check would keep the same
/// findings.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Selection {
    /// Codes of the rules switched off.
    off: std::collections::BTreeSet<&'static str>,
}

impl Selection {
    /// Every rule on (the analyzer's findings, before any configuration).
    pub fn all() -> Selection {
        Selection::default()
    }

    /// The rules for which `on` holds.
    pub fn of(on: impl Fn(&Rule) -> bool) -> Selection {
        Selection {
            off: RULES.iter().filter(|r| !on(r)).map(|r| r.code).collect(),
        }
    }

    pub fn is_on(&self, rule: &Rule) -> bool {
        self.off.is_empty() || !self.off.contains(rule.code)
    }
}

/// The rule with this code or name (any case).
pub fn find(code_or_name: &str) -> Option<&'static Rule> {
    RULES.iter().copied().find(|r| {
        r.code.eq_ignore_ascii_case(code_or_name) || r.name.eq_ignore_ascii_case(code_or_name)
    })
}

/// The reference page `docs/diagnostics.md`, generated from [`RULES`].
pub fn reference_page() -> String {
    let mut out = String::from(
        "# Diagnostics reference\n\n\
         <!-- Generated from analyzer/src/rules by `RAPID_BLESS=1 cargo test -p rapid-analyzer reference_page`. Do not edit. -->\n\n\
         Every diagnostic of `rapid check` and `rapid lsp` has a stable code and name. \
         Codes are never reused.\n\n",
    );
    out.push_str(DEFAULT_SET);
    out.push_str(
        "\n| code | name | default severity | on by default | summary |\n| --- | --- | --- | --- | --- |\n",
    );
    for rule in RULES {
        out.push_str(&format!(
            "| [{code}](#{anchor}) | `{name}` | {sev} | {on} | {summary} |\n",
            code = rule.code,
            anchor = anchor(rule),
            name = rule.name,
            sev = rule.severity.as_str(),
            on = if rule.default_on { "yes" } else { "no" },
            summary = rule.summary,
        ));
    }
    for rule in RULES {
        out.push_str(&format!(
            "\n## {code} {name}\n\nDefault severity: {sev}{on}.\n\n",
            code = rule.code,
            name = rule.name,
            sev = rule.severity.as_str(),
            on = if rule.default_on {
                ""
            } else {
                "; off unless selected (`[lint] select` or `--select`)"
            },
        ));
        for line in rule.doc.lines() {
            out.push_str(line.strip_prefix(' ').unwrap_or(line));
            out.push('\n');
        }
    }
    out
}

/// What the reference page says of the default set of rules.
const DEFAULT_SET: &str = "## The default set\n\n\
A finding is an **error** only when a controller would refuse to load the module, or \
the code cannot work at all. Code from a controller backup was loaded by a controller, so \
an error there is presumed to be our mistake until the language rules show otherwise; \
where the manuals are silent, the reading that accepts loaded code is chosen.\n\n\
A **warning** is a probable mistake that the controller accepts and that shows only at \
run time (a function that can end without `RETURN`, an unfilled `<SMT>` placeholder, \
unreachable code, a name that nothing in a partial folder declares). Warnings are meant to \
stay switched on in CI: each name that cannot be resolved is reported once per file, with \
its other uses as related locations.\n\n\
**Info** notes say what cannot be checked (an option routine, a signal without the \
controller's `EIO.cfg`), once per name per file. **Hints** (unused data, parameters and \
`LOCAL` routines) are shown faded in editors; they are not problems of the program.\n\n\
Rules that flag style choices real programs make on purpose are off unless a project \
selects them: `shadowed-name` (a routine's own `i` or `pTemp` hiding a global of the same \
name is common and harmless).\n";

/// The anchor of a rule's section in the reference page.
pub fn anchor(rule: &Rule) -> String {
    format!("{}-{}", rule.code.to_ascii_lowercase(), rule.name)
}

/// Completes the fixes attached without edits while unit `unit` was checked
/// (see [`crate::diagnostic::Fix::edits`]) through their rule's builder,
/// and drops those it cannot complete.
pub(crate) fn complete_fixes(task: &Task, unit: usize, diags: &mut [Diagnostic]) {
    for d in diags {
        if d.fix.as_ref().is_none_or(|f| !f.edits.is_empty()) {
            continue;
        }
        d.fix = if std::ptr::eq(d.rule, &unresolved_name::RULE) {
            unresolved_name::declare_fix(task, unit, d.range.clone())
        } else {
            None
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_and_names_are_unique_and_well_formed() {
        let mut seen = std::collections::HashSet::new();
        for rule in RULES {
            assert!(seen.insert(rule.code), "duplicate code {}", rule.code);
            assert!(seen.insert(rule.name), "duplicate name {}", rule.name);
            let (letter, digits) = rule.code.split_at(1);
            assert!(matches!(letter, "E" | "W" | "I"), "{}", rule.code);
            assert!(digits.len() == 3 && digits.bytes().all(|b| b.is_ascii_digit()));
            assert!(
                rule.name
                    .bytes()
                    .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-'),
                "{} is not kebab-case",
                rule.name
            );
        }
        let codes: Vec<_> = RULES.iter().map(|r| r.code).collect();
        let mut sorted = codes.clone();
        sorted.sort_unstable();
        assert_eq!(codes, sorted, "RULES is kept in code order");
    }

    #[test]
    fn every_rule_documents_what_why_and_an_example() {
        for rule in RULES {
            for part in ["### What it checks", "### Why", "### Example"] {
                assert!(rule.doc.contains(part), "{} lacks '{part}'", rule.code);
            }
            assert!(!rule.summary.is_empty() && !rule.summary.starts_with('#'));
            // The summary is the doc's first line: a whole sentence.
            assert!(
                rule.summary.ends_with('.'),
                "{}: the first doc line is the summary and must be a whole sentence",
                rule.code
            );
        }
    }

    #[test]
    fn reference_page_is_current() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/diagnostics.md");
        let page = reference_page();
        if std::env::var_os("RAPID_BLESS").is_some() {
            std::fs::write(path, &page).expect("write docs/diagnostics.md");
            return;
        }
        let current = std::fs::read_to_string(path).unwrap_or_default();
        assert!(
            current == page,
            "docs/diagnostics.md is stale: run `RAPID_BLESS=1 cargo test -p rapid-analyzer reference_page`"
        );
    }
}

#[cfg(test)]
mod units {
    /// Rules are units: outside `rules/`, a diagnostic is built only by the
    /// parser's findings (`syntax/`: E001 to E003, which the parse tree
    /// gives), the nesting bound (`nesting.rs`: W110 is where the tree is
    /// cut) and the checker's generic `Cx::report` (`check/mod.rs`); and
    /// nothing outside `rules/` reports through `Cx::report`.
    #[test]
    fn diagnostics_are_built_in_their_rules_files() {
        let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
        let allowed = ["syntax/", "nesting.rs", "check/mod.rs", "diagnostic.rs"];
        let mut found = Vec::new();
        let mut stack = vec![src.clone()];
        while let Some(dir) = stack.pop() {
            for entry in std::fs::read_dir(&dir).expect("src readable").flatten() {
                let path = entry.path();
                if path.is_dir() {
                    stack.push(path);
                    continue;
                }
                let rel = path
                    .strip_prefix(&src)
                    .map(|p| p.to_string_lossy().replace('\\', "/"))
                    .unwrap_or_default();
                if !rel.ends_with(".rs")
                    || rel.starts_with("rules/")
                    || rel.contains("tests")
                    || allowed.iter().any(|a| rel.starts_with(a))
                {
                    continue;
                }
                let text = std::fs::read_to_string(&path).expect("readable");
                let code = text.split("#[cfg(test)]").next().unwrap_or_default();
                for (i, line) in code.lines().enumerate() {
                    if line.contains("Diagnostic::new(") || line.contains(".report(") {
                        found.push(format!("{rel}:{}", i + 1));
                    }
                }
            }
        }
        assert!(
            found.is_empty(),
            "diagnostics built outside their rule's file: {found:?}"
        );
    }
}
