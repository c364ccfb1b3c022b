//! Every RAPID file of the corpus of real code must parse without an
//! `ERROR` or `MISSING` node, except the few reviewed files listed in
//! [`KNOWN_BROKEN`], which are not valid RAPID.
//!
//! The corpus is read from `RAPID_CORPUS` or `../shared/corpus` next to the
//! workspace; when neither exists the test prints one line and passes.

#![allow(clippy::print_stdout)]

/// Files that are not valid RAPID, with the reason (paths relative to the
/// corpus root, `/` separated). Each one must still fail: a file that
/// starts to parse clean has to leave this list.
const KNOWN_BROKEN: &[(&str, &str)] = &[
    (
        "RobotExMachina__Machina.NET/src/Machina/Resources/DriverModules/ABB/machina_abb_driver.mod",
        "a template: `{{PORT}}` is replaced by a generator before loading",
    ),
    (
        "RobotExMachina__Machina.NET/src/Machina/Resources/DriverModules/ABB/Machina_ABB_Monitor.mod",
        "a template: `{{PORT}}` is replaced by a generator before loading",
    ),
    (
        "TPHugo__TimovyProjekt/Stavbar/RTVS/Stena_coloseum.pgf",
        "generator output with stray text (`0.`) before MODULE",
    ),
    (
        "TPHugo__TimovyProjekt/Stavbar/RTVS/Stena_R.pgf",
        "generator output with stray text (`0.`) before MODULE",
    ),
    (
        "ebruun__ECL_robotic_cell/_controller_backups/4600-COMPAS_RRC_BACKUP_legacy/HOME/1/1_T_ROB1.mod",
        "module name starts with a digit (`MODULE 1_T_ROB1`), not an identifier",
    ),
    (
        "ebruun__ECL_robotic_cell/_controller_backups/4600-COMPAS_RRC_BACKUP_legacy/HOME/1/1_T_ROB2.mod",
        "module name starts with a digit (`MODULE 1_T_ROB2`), not an identifier",
    ),
    (
        "BossyMr__intellij-rapid/src/test/resources/com/bossymr/rapid/language/parser/Structures.mod",
        "another parser's error-recovery fixture: deliberately invalid",
    ),
    (
        "BossyMr__intellij-rapid/src/test/resources/com/bossymr/rapid/language/parser/Fields.mod",
        "another parser's error-recovery fixture: deliberately invalid",
    ),
    (
        "BossyMr__intellij-rapid/src/test/resources/com/bossymr/rapid/language/parser/Modules.mod",
        "another parser's error-recovery fixture: deliberately invalid",
    ),
    (
        "BossyMr__intellij-rapid/src/test/resources/com/bossymr/rapid/language/parser/Variables.mod",
        "another parser's error-recovery fixture: deliberately invalid",
    ),
    (
        "BossyMr__intellij-rapid/src/test/resources/com/bossymr/rapid/language/parser/Routines.mod",
        "another parser's error-recovery fixture: deliberately invalid",
    ),
    (
        "BossyMr__intellij-rapid/src/main/resources/codeStyle/preview/SPACING_TEMPLATE.mod",
        "formatter preview text: empty aggregate `[]` and a zero dimension",
    ),
    (
        "BossyMr__intellij-rapid/src/main/resources/codeStyle/preview/WRAPPING_AND_BRACES_TEMPLATE.mod",
        "formatter preview text: a declaration without its `;`",
    ),
    (
        "dkaynarc__tmc/src/cluster/Tmc/Robotics/bin/Debug/modFiles/PlaceTablet.mod",
        "a template: `%MagazineHover%` lines are replaced by other modules' text before loading",
    ),
    (
        "dkaynarc__tmc/src/cluster/Tmc/Robotics/bin/Debug/modFiles/SortChip.mod",
        "a template: `%XCoord%` in a target and `%MagazineHover%` lines are filled in before loading",
    ),
    (
        "dkaynarc__tmc/src/cluster/Tmc/Robotics/mod/SorterSortChip.mod",
        "a template: `%XCoord%` in a target and `%MagazineHover%` lines are filled in before loading",
    ),
];

/// `.pgf` program files are XML unless they hold RAPID text.
fn is_xml(text: &str) -> bool {
    text.trim_start_matches(['\u{feff}', ' ', '\t', '\r', '\n'])
        .starts_with('<')
}

/// The first few syntax errors of a tree, as `line:col node`.
fn syntax_errors(tree: &tree_sitter::Tree) -> Vec<String> {
    let mut out = Vec::new();
    let mut cursor = tree.walk();
    let mut descend = true;
    loop {
        let node = cursor.node();
        if descend && node.has_error() {
            if node.is_error() || node.is_missing() {
                let p = node.start_position();
                let what = if node.is_missing() {
                    format!("MISSING {}", node.kind())
                } else {
                    "ERROR".to_owned()
                };
                out.push(format!("{}:{} {what}", p.row + 1, p.column + 1));
                if out.len() >= 5 {
                    break;
                }
            } else if cursor.goto_first_child() {
                continue;
            }
        }
        if cursor.goto_next_sibling() {
            descend = true;
            continue;
        }
        if !cursor.goto_parent() {
            break;
        }
        descend = false;
    }
    out
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn every_rapid_file_of_the_corpus_parses_clean() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        println!("corpus_parse: no corpus (set RAPID_CORPUS); skipped");
        return;
    };
    let mut parser = tree_sitter::Parser::new();
    parser
        .set_language(&tree_sitter_rapid::LANGUAGE.into())
        .expect("the RAPID grammar loads");

    let (mut files, mut clean, mut excluded) = (0usize, 0usize, 0usize);
    let mut failures = Vec::new();
    let mut now_clean = Vec::new();
    for path in rapid_tests::rapid_paths(&dir, true) {
        let text = rapid_tests::decode_text(&std::fs::read(&path).expect("readable corpus file"));
        if is_xml(&text) {
            continue;
        }
        files += 1;
        let rel = path
            .strip_prefix(&dir)
            .unwrap_or(&path)
            .to_string_lossy()
            .replace('\\', "/");
        let tree = parser.parse(&text, None).expect("a tree");
        let errors = syntax_errors(&tree);
        let known = KNOWN_BROKEN.iter().any(|(p, _)| *p == rel);
        match (errors.is_empty(), known) {
            (true, false) => clean += 1,
            (true, true) => now_clean.push(rel),
            (false, true) => excluded += 1,
            (false, false) => failures.push(format!("{rel}:{}", errors.join(", "))),
        }
    }
    println!(
        "corpus_parse: {files} RAPID files, {clean} clean, {excluded} known broken, {} failing",
        failures.len()
    );
    assert!(files > 0, "no RAPID files under {}", dir.display());
    assert!(
        failures.is_empty(),
        "{} files have syntax errors:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(
        now_clean.is_empty(),
        "listed as broken but now parse clean (remove them from KNOWN_BROKEN):\n{}",
        now_clean.join("\n")
    );
}
