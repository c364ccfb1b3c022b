//! The analyzer on the corpus of real programs: every error-level finding
//! must be a true defect of the program (triaged below), and the figures go
//! to `docs/corpus-triage.md`.
//!
//! `RAPID_BLESS=1 cargo test -p rapid-tests --test corpus_check` rewrites the
//! page; without it the test fails when the page is stale or when an error
//! appears that is not triaged as a true defect.

use std::collections::BTreeMap;
use std::path::Path;

use rapid_analyzer::check::once::{FileFindings, per_task};
use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use rapid_analyzer::rules::RULES;
use rapid_analyzer::text::LineIndex;

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

/// Warnings of the sample ([`in_sample`]) reviewed by hand: (path suffix,
/// code, line, true?, why).
const WARNING_SAMPLE: &[(&str, &str, usize, bool, &str)] = &[
    (
        "TPHugo__TimovyProjekt/Stavbar/Stena obluk/MainModule.mod",
        "E107",
        1685,
        true,
        "the file holds two copies of module MainModule (a generated program pasted twice, junk between): `Work` is declared in both",
    ),
    (
        "1200-526406_BACKUP_2025-12-23-1933/RAPID/TASK7/PROGMOD/Gantry_CheckPrecision.mod",
        "W204",
        350,
        true,
        "the MoveExtJ follows `GOTO re111; RETURN;`: a leftover of testing that never runs",
    ),
    (
        "SpGantry_1200_526406_BACKUP_2025-12-18/RAPID/TASK2/PROGMOD/Rob2_MainModule.mod",
        "W204",
        929,
        true,
        "moves after a RETURN in the middle of the routine: never run",
    ),
    (
        "SpGantry_1200_526406_BACKUP_2025-12-18/RAPID/TASK2/PROGMOD/Rob2_MainModule.mod",
        "W204",
        932,
        true,
        "a weld after a second RETURN: never run",
    ),
];

/// The seed of the sample of warnings: a new one draws a new sample (the
/// sample was drawn again with this one when unresolved names outside
/// complete backups became notes).
const SAMPLE_SEED: &str = "2026-11-29";

/// Is the finding at this place in the sample of warnings triaged by hand?
/// One place in twenty, by a hash of the seed and the place: the sample
/// does not move when other findings come or go.
fn in_sample(path: &str, line: usize, code: &str) -> bool {
    // FNV-1a, 64 bits
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in format!("{SAMPLE_SEED}:{path}:{line}:{code}").bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h.is_multiple_of(20)
}

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
    let mut ws = loaded.workspace();
    let lines: usize = loaded.modules.iter().map(|(_, t)| t.lines().count()).sum();
    // Each file's findings, then each name a task lacks once per task, as
    // `rapid check` reports them.
    let keys: Vec<String> = loaded.modules.iter().map(|(p, _)| ws.task_key(p)).collect();
    let mut all: Vec<Vec<Diagnostic>> = loaded
        .modules
        .iter()
        .map(|(p, _)| ws.diagnostics(p).as_ref().clone())
        .collect();
    let mut files: Vec<FileFindings<'_>> = loaded
        .modules
        .iter()
        .zip(&keys)
        .zip(all.iter_mut())
        .map(|(((path, text), task), diagnostics)| FileFindings {
            task,
            path,
            text,
            diagnostics,
        })
        .collect();
    per_task(&mut files);
    drop(files);
    let mut per_code: BTreeMap<(&str, Severity), (usize, usize)> = BTreeMap::new();
    let mut in_damaged = Vec::new();
    let mut damaged = Vec::new();
    let mut true_defects = Vec::new();
    let mut untriaged = Vec::new();
    let mut default_warnings = 0;
    let mut sample = Vec::new();
    for ((path, text), diags) in loaded.modules.iter().zip(&all) {
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
            let (line, _) = index.human(d.range.start, text);
            if d.severity == Severity::Warning && d.rule.default_on {
                default_warnings += 1;
                if in_sample(path, line, d.rule.code) {
                    sample.push((path.as_str(), line, d.rule.code, d.message.clone()));
                }
            }
            if d.severity != Severity::Error {
                continue;
            }
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
        "- files: {}\n- lines: {lines}\n- damaged files (syntax errors; their other findings are not triaged): {}\n- error-level findings outside damaged files: {} (true defects: {}, untriaged: {})\n- warnings of the rules on by default: {default_warnings} ({:.2} per 1,000 lines; the target is at most 5)\n\n",
        loaded.modules.len(),
        damaged.len(),
        true_defects.len() + untriaged.len(),
        true_defects.len(),
        untriaged.len(),
        per_kloc(default_warnings),
    ));
    page.push_str("Counts are per code and the severity reported, as `rapid check` reports them (a name a task lacks once per task; ambiguous globals are errors in a backup's task and warnings in a plain folder, whose grouping is a guess; an unresolved name is an error in a complete backup's task, a warning where it is one edit from a declared name of its kind, a note anywhere else). Rules that are off by default are counted too, and marked.\n\n| code | name | on by default | severity | count | per 1,000 lines | true defects (errors outside damaged files) |\n| --- | --- | --- | --- | ---: | ---: | ---: |\n");
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
                "| {} | `{}` | {} | {} | {n} | {:.2} | {} |\n",
                rule.code,
                rule.name,
                if rule.default_on { "yes" } else { "no" },
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
    // The sample of warnings, each with its verdict.
    let mut sampled = Vec::new();
    let mut unjudged = Vec::new();
    let mut true_in_sample = 0;
    for (path, line, code, message) in &sample {
        let judged = WARNING_SAMPLE
            .iter()
            .find(|(p, c, l, _, _)| path.ends_with(p) && c == code && l == line);
        let row = format!("`{path}:{line}` {code}: {message}");
        match judged {
            Some((_, _, _, verdict, why)) => {
                true_in_sample += usize::from(*verdict);
                let verdict = if *verdict { "true" } else { "**false**" };
                sampled.push(format!("{row} — {verdict}: {why}"));
            }
            None => unjudged.push(row),
        }
    }
    page.push_str(&format!(
        "\n## A sample of warnings, triaged\n\nThe warnings of the rules on by default whose place (file, line, code) hashes (with the seed `{SAMPLE_SEED}`) into one twentieth of the space: a sample that stays the same when other findings come or go. {} of {} are true ({:.0}%); the target is 9 in 10.\n\n",
        true_in_sample,
        sampled.len(),
        100.0 * true_in_sample as f64 / sampled.len().max(1) as f64,
    ));
    for row in &sampled {
        page.push_str(&format!("- {row}\n"));
    }
    // The robot rules: a controller ran these programs, so every finding of
    // E601, E602 or W601 on a task with a known robot is an exception to
    // explain here (or a bug).
    let robot_tasks: Vec<String> = ws
        .tasks()
        .iter()
        .filter(|t| t.robot.is_some())
        .map(|t| t.key.clone())
        .collect();
    let robot_findings: Vec<String> = loaded
        .modules
        .iter()
        .zip(&all)
        .flat_map(|((path, _), ds)| {
            ds.iter()
                .filter(|d| matches!(d.rule.code, "E601" | "E602" | "W601"))
                .map(move |d| format!("{path}: {} {}", d.rule.code, d.message))
        })
        .collect();
    page.push_str(&format!(
        "\n## The robot rules (E601, E602, W601)\n\nThey run on tasks whose robot is known (a `MOC.cfg` naming a modelled robot type, or `robot` in `[controller]`): {} task(s) here, with {} finding(s). The corpus holds no `MOC.cfg` and no `rapid.toml`, so no robot is known and these rules are exercised only by their fixtures and by the hidden backups. Each finding on a backup would be listed here with why the controller still ran the program.\n",
        robot_tasks.len(),
        robot_findings.len(),
    ));
    for f in &robot_findings {
        page.push_str(&format!("- {f}\n"));
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
        unjudged.is_empty(),
        "sampled warnings without a verdict in WARNING_SAMPLE:\n{}",
        unjudged.join("\n")
    );
    let stale_sample: Vec<String> = WARNING_SAMPLE
        .iter()
        .filter(|(p, c, l, _, _)| {
            !sample
                .iter()
                .any(|(path, line, code, _)| path.ends_with(p) && code == c && line == l)
        })
        .map(|(p, c, l, _, _)| format!("{p}:{l} {c}"))
        .collect();
    assert!(
        stale_sample.is_empty(),
        "WARNING_SAMPLE entries no longer in the sample (remove them):\n{}",
        stale_sample.join("\n")
    );
    assert!(
        per_kloc(default_warnings) <= 5.0,
        "{default_warnings} warnings of the default rules: {:.2} per 1,000 lines, more than 5",
        per_kloc(default_warnings)
    );
    assert!(
        10 * true_in_sample >= 9 * sampled.len(),
        "{true_in_sample} of {} sampled warnings are true: fewer than 9 in 10",
        sampled.len()
    );
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
