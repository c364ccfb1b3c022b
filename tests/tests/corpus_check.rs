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
        "HOME/__RELBO__/FOUNDRY.mod",
        "W101",
        1017,
        true,
        "declared in the system module `HOME/__MODULI__/TEXT.sys`, which this program (its `.pgf`) does not list: the task's system modules are not here",
    ),
    (
        "6700-132308_BACKUP_2022-12-15_STARTUP/RAPID/TASK4/SYSMOD/RRC_Control_Rx.sys",
        "W101",
        58,
        true,
        "`b_RRC_Com`, `n_RRC_R1_ChaNr`: declared in RRC_DataGlobal modules that other tasks of this backup have and TASK4 lacks; `r_RRC_CheckAndRecFrmClient` is declared nowhere in the corpus",
    ),
    (
        "Camille_BACKUP_2023-01-11/RAPID/TASK6/SYSMOD/RRC_DataTask_Tx.sysx",
        "W101",
        93,
        true,
        "the record `RRC_Protocol` is declared in RRC_DataRecord, which this task lacks",
    ),
    (
        "SDEBEUL__Kraker1/RAPID/TASK1/PROGMOD/mStation.mod",
        "W101",
        156,
        true,
        "an I/O signal: the corpus has no EIO.cfg, as the message says",
    ),
    (
        "SDEBEUL__Kraker1/RAPID/TASK1/SYSMOD/mSettings_Gripper.sys",
        "W101",
        346,
        true,
        "two analog input signals: the corpus has no EIO.cfg, as the message says",
    ),
    (
        "RW6-13_BACKUP/RAPID/TASK2/PROGMOD/RFL_Control_12.mod",
        "W101",
        159,
        true,
        "declared in RFL_GlobalData of TASK1 and TASK4; TASK2 has no module declaring it",
    ),
    (
        "RW6-13_BACKUP/RAPID/TASK4/SYSMOD/RRC_DataGlobal_Ctrl.sys",
        "W101",
        130,
        true,
        "the record `RRC_Channel` is declared in TASK1's RRC_DataRecord; TASK4 has no such module",
    ),
    (
        "RW6-13_BACKUP/RAPID/TASK5/PROGMOD/A042_Control_Tx.mod",
        "W101",
        66,
        true,
        "a `syncident` declared in the A042 data modules of TASK1 and TASK4; TASK5 has none",
    ),
    (
        "RW6-13_BACKUP/RAPID/TASK5/PROGMOD/A067_Control_Sen.mod",
        "W101",
        96,
        true,
        "a `syncident` TASK5 declares in no module",
    ),
    (
        "RW6-13_BACKUP/RAPID/TASK5/PROGMOD/A082_Control_Tx.mod",
        "W101",
        129,
        true,
        "a `syncident` TASK5 declares in no module",
    ),
    (
        "RW6-13_BACKUP/RAPID/TASK5/PROGMOD/A083_Control_Tx.mod",
        "W101",
        108,
        true,
        "a `syncident` TASK5 declares in no module",
    ),
    (
        "1200-526406_BACKUP_2026-02-11-1959/RAPID/TASK8/PROGMOD/Head_MainModule.mod",
        "W101",
        226,
        true,
        "declared in Head_Camera.mod, which an earlier backup's TASK8 has and this one lacks",
    ),
    (
        "1840_B3/RAPID/TASK2/PROGMOD/Rob2_MainModule.mod",
        "W101",
        1583,
        true,
        "declared in Rob2_TeachingData.mod, which other backups' TASK2 have and this one lacks",
    ),
    (
        "beforeplanC/RAPID/TASK8/PROGMOD/Head_Command.mod",
        "W101",
        43,
        true,
        "`fnCoordToJoint` and `fnPoseToExtax` are declared in Head_Function.mod, which this backup's TASK8 lacks",
    ),
    (
        "beforeplanC/RAPID/TASK8/PROGMOD/Head_MainModule.mod",
        "W101",
        225,
        true,
        "declared in Head_Camera.mod, which this backup's TASK8 lacks",
    ),
    (
        "beforeplanC/RAPID/TASK8/PROGMOD/Head_MoveControl.mod",
        "W101",
        129,
        true,
        "declared in Head_Function.mod, which this backup's TASK8 lacks",
    ),
    (
        "beforeplanC/RAPID/TASK9/PROGMOD/Static.mod",
        "W101",
        316,
        false,
        "`\\MecUnit:=ELM_X` names a mechanical unit (MOC.cfg); `GetMotorTorque`'s parameters are not in the catalogue, so the name is not known to be one and is not the note (I103) it should be",
    ),
    (
        "T_ROB1/TCSupport/tcdevice.sys",
        "W101",
        103,
        true,
        "an I/O signal: the corpus has no EIO.cfg",
    ),
    (
        "T_ROB1/TCSupport/tcdevice.sys",
        "W101",
        136,
        true,
        "an I/O signal: the corpus has no EIO.cfg",
    ),
    (
        "RAPID/T_POS1/CalibDataModule.mod",
        "W101",
        50,
        true,
        "declared in T_ROB1's GlobalDataModule; T_POS1 has no module declaring it",
    ),
    (
        "RAPID/T_POS1/TaskModule.mod",
        "W101",
        50,
        true,
        "the record is declared in T_ROB1's modules only; T_POS1 lacks it",
    ),
    (
        "RAPID/T_ROB2/ErrorHandlingModule.mod",
        "W101",
        45,
        true,
        "declared nowhere in the corpus: declared in a module of the program that the checked files lack",
    ),
    (
        "REHM/Source/RAPID/TASK5/PROGMOD/REHMProcessControlModule.mod",
        "W101",
        33,
        true,
        "declared nowhere in this add-in: declared in a module of the program that the checked files lack",
    ),
    (
        "ZhongXun/Source/RAPID/TASK1/PROGMOD/ServiceModule.mod",
        "W101",
        183,
        true,
        "declared nowhere in the corpus: declared in a module of the program that the checked files lack",
    ),
    (
        "ZhongXun/Source/RAPID/TASK1/PROGMOD/TestAutoCal.mod",
        "W101",
        19,
        true,
        "the record `caldata` is declared nowhere in the corpus: declared in a module of the program that the checked files lack",
    ),
    (
        "zwj12__ZhongXunRapid/ApplSys/GoSafeUsr.sys",
        "W101",
        474,
        true,
        "declared nowhere in the corpus: declared in a module of the program that the checked files lack",
    ),
    (
        "RAATCfg/RAPID/TASK1/PROGMOD/TestModule.mod",
        "W101",
        143,
        true,
        "declared nowhere in the corpus: declared in a module of the program that the checked files lack",
    ),
    (
        "RAATCfg/RAPID/TASK1/PROGMOD/TestModule.mod",
        "W101",
        257,
        true,
        "declared nowhere in the corpus: declared in a module of the program that the checked files lack",
    ),
    (
        "RAATCfg/RAPID/TASK1/SYSMOD/AutoCal2b.sys",
        "W101",
        171,
        true,
        "declared nowhere in the corpus: declared in a module of the program that the checked files lack",
    ),
];

/// Is the finding at this place in the sample of warnings triaged by hand?
/// One place in forty, by a hash of the place: the sample does not move
/// when other findings come or go.
fn in_sample(path: &str, line: usize, code: &str) -> bool {
    // FNV-1a, 64 bits
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in format!("{path}:{line}:{code}").bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h.is_multiple_of(40)
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
    page.push_str("Counts are per code and the severity reported, as `rapid check` reports them (a name a task lacks once per task; ambiguous globals are errors in a backup's task and warnings in a plain folder, whose grouping is a guess; an unresolved name is a note in a `HOME/` module that no task here loads). Rules that are off by default are counted too, and marked.\n\n| code | name | on by default | severity | count | per 1,000 lines | true defects (errors outside damaged files) |\n| --- | --- | --- | --- | ---: | ---: | ---: |\n");
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
        "\n## A sample of warnings, triaged\n\nThe warnings of the rules on by default whose place (file, line, code) hashes into one fortieth of the space: a sample that stays the same when other findings come or go. {} of {} are true ({:.0}%); the target is 9 in 10.\n\n",
        true_in_sample,
        sampled.len(),
        100.0 * true_in_sample as f64 / sampled.len().max(1) as f64,
    ));
    for row in &sampled {
        page.push_str(&format!("- {row}\n"));
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
