//! The registry of every rule. Each rule lives in its own file with its
//! documentation; this list is the one place that names them all, in code
//! order. Codes are never reused: a retired rule stays listed.

use crate::diagnostic::Rule;

pub mod missing_token;
pub mod syntax_error;

/// Every rule, in code order.
pub static RULES: &[&Rule] = &[&syntax_error::RULE, &missing_token::RULE];

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
         Codes are never reused.\n\n\
         | code | name | default severity | summary |\n| --- | --- | --- | --- |\n",
    );
    for rule in RULES {
        out.push_str(&format!(
            "| [{code}](#{anchor}) | `{name}` | {sev} | {summary} |\n",
            code = rule.code,
            anchor = anchor(rule),
            name = rule.name,
            sev = rule.severity.as_str(),
            summary = rule.summary,
        ));
    }
    for rule in RULES {
        out.push_str(&format!(
            "\n## {code} {name}\n\nDefault severity: {sev}.\n\n",
            code = rule.code,
            name = rule.name,
            sev = rule.severity.as_str(),
        ));
        for line in rule.doc.lines() {
            out.push_str(line.strip_prefix(' ').unwrap_or(line));
            out.push('\n');
        }
    }
    out
}

/// The anchor of a rule's section in the reference page.
pub fn anchor(rule: &Rule) -> String {
    format!("{}-{}", rule.code.to_ascii_lowercase(), rule.name)
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
