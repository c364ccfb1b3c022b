//! The analyzer on the corpus of real programs: every error-level finding
//! must be a true defect of the program (triaged below), and the figures go
//! to `docs/corpus-triage.md`.
//!
//! `RAPID_BLESS=1 cargo test -p rapid-tests --test corpus_check` rewrites the
//! page; without it the test fails when the page is stale or when an error
//! appears that is not triaged as a true defect.

use std::collections::BTreeMap;
use std::path::Path;

use rapid_analyzer::diagnostic::Severity;
use rapid_analyzer::rules::RULES;
use rapid_analyzer::text::LineIndex;
use rapid_analyzer::workspace::Workspace;

/// Error-level findings reviewed by hand and found to be real defects of
/// the program: (path suffix, rule name, line, why).
const TRUE_DEFECTS: &[(&str, &str, usize, &str)] = &[
    (
        "parser/Comments.mod",
        "duplicate-declaration",
        14,
        "a parser test file: the record, the data and the procedure all take the name `name2`",
    ),
    (
        "parser/Comments.mod",
        "duplicate-declaration",
        17,
        "the same file: the procedure `name2` repeats the name again",
    ),
    (
        "Robot-Piano/PointModule.mod",
        "aggregate-arity",
        20,
        "an array declared with 14 rows initialised with 10",
    ),
    (
        "Keen1949__ABB_ROBOT_Socket/RAPID/TASK1/PROGMOD/Socket_Commands.mod",
        "argument-count",
        34,
        "`Assemble` is declared with six string parameters and called with five",
    ),
    (
        "Keen1949__ABB_ROBOT_Socket/RAPID/TASK1/PROGMOD/Socket_Commands.mod",
        "argument-count",
        39,
        "`GoSnap(string, string)` called with no arguments",
    ),
    (
        "Keen1949__ABB_ROBOT_Socket/RAPID/TASK1/PROGMOD/Socket_Commands.mod",
        "argument-count",
        47,
        "`CaliCam` takes three strings and is called with one",
    ),
    (
        "Keen1949__ABB_ROBOT_Socket/RAPID/TASK1/PROGMOD/Socket_Commands.mod",
        "argument-count",
        49,
        "`TranCam(string, string)` called with no arguments",
    ),
    (
        "liamjosephnolan__DiceRobot/MainModule.mod",
        "call-kind-mismatch",
        26,
        "the function `reset_dice` called as a procedure (its other uses assign its result)",
    ),
    (
        "ravenorb__abb-robot-welder/RAPID/PROGMOD/MainModule.mod",
        "argument-count",
        12,
        "`TPWrite` given three strings separated by commas; it takes one string",
    ),
];

/// Files whose text is not a valid RAPID module (truncated, merged or
/// otherwise damaged): their syntax errors are real, and the checks that
/// follow from them are not triaged one by one.
fn is_damaged(syntax_errors: usize) -> bool {
    syntax_errors > 0
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn corpus_errors_are_true_defects() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        eprintln!("corpus_check skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    let loaded = rapid_tests::workspace_inputs(&dir);
    let mut ws = Workspace::new();
    for (p, t) in &loaded.configs {
        ws.set_config(p, t);
    }
    for (p, t) in &loaded.programs {
        ws.set_program(p, t);
    }
    for (p, t) in &loaded.modules {
        ws.set_file(p, t.clone());
    }
    let lines: usize = loaded.modules.iter().map(|(_, t)| t.lines().count()).sum();
    let mut per_code: BTreeMap<(&str, Severity), (usize, usize)> = BTreeMap::new();
    let mut in_damaged = Vec::new();
    let mut damaged = Vec::new();
    let mut true_defects = Vec::new();
    let mut untriaged = Vec::new();
    for (path, text) in &loaded.modules {
        let diags = ws.diagnostics(path);
        let syntax = diags
            .iter()
            .filter(|d| matches!(d.rule.code, "E001" | "E002" | "E003"))
            .count();
        let broken = is_damaged(syntax);
        if broken {
            damaged.push(format!("`{path}` ({syntax} syntax errors)"));
        }
        let index = LineIndex::new(text);
        for d in diags.iter() {
            let entry = per_code.entry((d.rule.code, d.severity)).or_default();
            entry.0 += 1;
            if d.severity != Severity::Error {
                continue;
            }
            let (line, _) = index.human(d.range.start, text);
            if broken {
                if !matches!(d.rule.code, "E001" | "E002" | "E003") {
                    in_damaged.push(format!(
                        "`{path}:{line}` {} {}: {}",
                        d.rule.code, d.rule.name, d.message
                    ));
                }
                continue;
            }
            let found = TRUE_DEFECTS
                .iter()
                .find(|(p, r, l, _)| path.ends_with(p) && *r == d.rule.name && *l == line);
            let row = format!(
                "`{path}:{line}` {} {}: {}",
                d.rule.code, d.rule.name, d.message
            );
            match found {
                Some((_, _, _, why)) => {
                    entry.1 += 1;
                    true_defects.push(format!("{row} — **true defect**: {why}"));
                }
                None => untriaged.push(row),
            }
        }
    }
    let per_kloc = |n: usize| n as f64 * 1000.0 / lines.max(1) as f64;
    let mut page = String::from(
        "# Corpus triage\n\n\
         <!-- Generated by `RAPID_BLESS=1 cargo test -p rapid-tests --test corpus_check`. Do not edit. -->\n\n\
         The analyzer run over `../shared/corpus` (real RAPID programs from public repositories, \
         test input only), grouped into tasks as `rapid check` groups them (`RAPID/TASKn` \
         folders, `.pgf` programs, else one task per folder), with the corpus's `EIO.cfg` and \
         `MOC.cfg` files. Every error-level diagnostic outside damaged files is triaged by hand: \
         it is either listed below as a true defect of the program, or it is a bug of the \
         analyzer and the test fails.\n\n",
    );
    page.push_str(&format!(
        "- files: {}\n- lines: {lines}\n- damaged files (syntax errors; their other findings are not triaged): {}\n- error-level findings outside damaged files: {} (true defects: {}, untriaged: {})\n\n",
        loaded.modules.len(),
        damaged.len(),
        true_defects.len() + untriaged.len(),
        true_defects.len(),
        untriaged.len(),
    ));
    page.push_str("Counts are per code and the severity reported (ambiguous globals are errors in a backup's task and warnings in a plain folder, whose grouping is a guess).\n\n| code | name | severity | count | per 1,000 lines | true defects (errors outside damaged files) |\n| --- | --- | --- | ---: | ---: | ---: |\n");
    for rule in RULES {
        for sev in [
            Severity::Error,
            Severity::Warning,
            Severity::Info,
            Severity::Hint,
        ] {
            let Some((n, t)) = per_code.get(&(rule.code, sev)) else {
                continue;
            };
            page.push_str(&format!(
                "| {} | `{}` | {} | {n} | {:.2} | {} |\n",
                rule.code,
                rule.name,
                sev.as_str(),
                per_kloc(*n),
                if sev == Severity::Error {
                    t.to_string()
                } else {
                    "-".to_owned()
                }
            ));
        }
    }
    page.push_str("\n## True defects\n\n");
    if true_defects.is_empty() {
        page.push_str("None.\n");
    }
    for d in &true_defects {
        page.push_str(&format!("- {d}\n"));
    }
    page.push_str("\n## Untriaged errors (analyzer bugs until shown otherwise)\n\n");
    if untriaged.is_empty() {
        page.push_str("None.\n");
    }
    for d in &untriaged {
        page.push_str(&format!("- {d}\n"));
    }
    page.push_str("\n## Damaged files\n\nTheir syntax errors are real (the controller would reject them); the checks still run on what parsed.\n\n");
    for d in &damaged {
        page.push_str(&format!("- {d}\n"));
    }
    page.push_str("\n### Other errors in damaged files\n\n");
    if in_damaged.is_empty() {
        page.push_str("None.\n");
    }
    for d in &in_damaged {
        page.push_str(&format!("- {d}\n"));
    }
    let doc = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/corpus-triage.md");
    if std::env::var_os("RAPID_BLESS").is_some() {
        std::fs::write(&doc, &page).expect("write docs/corpus-triage.md");
    } else {
        let current = std::fs::read_to_string(&doc).unwrap_or_default();
        assert!(
            current == page,
            "docs/corpus-triage.md is stale: run `RAPID_BLESS=1 cargo test -p rapid-tests --test corpus_check`"
        );
    }
    assert!(
        untriaged.is_empty(),
        "error-level findings not triaged as true defects:\n{}",
        untriaged.join("\n")
    );
    let stale: Vec<String> = TRUE_DEFECTS
        .iter()
        .filter(|(p, r, l, _)| {
            !true_defects
                .iter()
                .any(|row| row.contains(&format!("{p}:{l}`")) && row.contains(&format!(" {r}: ")))
        })
        .map(|(p, r, l, _)| format!("{p}:{l} {r}"))
        .collect();
    assert!(
        stale.is_empty(),
        "triaged true defects that are no longer reported (remove them):\n{}",
        stale.join("\n")
    );
}
