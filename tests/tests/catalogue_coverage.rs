//! Coverage of the built-in catalogue on real code: every routine called in the corpus
//! that the corpus does not declare itself must be in the catalogue
//! (`analyzer/catalogue/*.toml`) or in the reviewed list of option and vendor routines
//! (`analyzer/catalogue/option_routines.toml`).
//!
//! The corpus is read from `RAPID_CORPUS` or `../shared/corpus` next to the workspace;
//! when neither exists the test prints one line and passes.

#![allow(clippy::print_stdout)]

use std::collections::{BTreeMap, HashSet};
use std::path::{Path, PathBuf};

use rapid_analyzer::catalogue::{catalogue, option_routines};

/// Routines the corpus calls whose declaring module is simply not in the corpus (user or
/// project code, not option routines, so they do not belong in `option_routines.toml`),
/// and calls in files that are not programs. Reviewed: (name, reason).
const CORPUS_GAPS: &[(&str, &str)] = &[
    (
        "attemptSystemRoutine",
        "panin-anan grinding project: helper module not in the corpus",
    ),
    (
        "attemptNonBlockingSystemRoutine",
        "panin-anan grinding project: helper module not in the corpus",
    ),
    (
        "initializeSystemModule",
        "panin-anan grinding project: helper module not in the corpus",
    ),
    (
        "state_server_main",
        "ROS-Industrial abb_driver: ROS_stateServer.mod not in the corpus",
    ),
    (
        "joint_trajectory_server_main",
        "ROS-Industrial abb_driver: ROS_motionServer.mod not in the corpus",
    ),
    (
        "FitSphere",
        "FLo-ABB ToolCenterCalculations: math helper module not in the corpus",
    ),
    (
        "Max",
        "FLo-ABB ToolCenterCalculations: math helper module not in the corpus",
    ),
    (
        "Rand",
        "FLo-ABB CycleTime: random-number helper not in the corpus (not a RobotWare function)",
    ),
    (
        "condition",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "something",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "getValue",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "doSomething",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "doDefault",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "Routine",
        "intellij-rapid code-style preview text (its declaration does not parse: known broken)",
    ),
];

/// Routine names declared in a tree, and (name, is_function) of every call by name.
fn walk(
    tree: &tree_sitter::Tree,
    text: &str,
    declared: &mut HashSet<String>,
    calls: &mut Vec<(String, bool)>,
) {
    let mut cursor = tree.walk();
    loop {
        let node = cursor.node();
        let kind = node.kind();
        let name = node
            .child_by_field_name("name")
            .filter(|n| n.kind() == "identifier")
            .and_then(|n| n.utf8_text(text.as_bytes()).ok());
        match (kind, name) {
            ("procedure_declaration" | "function_declaration" | "trap_declaration", Some(n)) => {
                declared.insert(n.to_lowercase());
            }
            ("procedure_call", Some(n)) => calls.push((n.to_owned(), false)),
            ("function_call", Some(n)) => calls.push((n.to_owned(), true)),
            _ => {}
        }
        if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return;
            }
        }
    }
}

#[derive(Default)]
struct Count {
    calls: usize,
    files: HashSet<PathBuf>,
    spelling: String,
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn every_called_builtin_is_catalogued_or_a_reviewed_option_routine() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        println!("catalogue_coverage: no corpus (set RAPID_CORPUS); skipped");
        return;
    };
    let cat = catalogue();
    let options = option_routines().expect("option_routines.toml parses");
    let option_names: HashSet<String> = options.iter().map(|o| o.name.to_lowercase()).collect();

    let mut parser = tree_sitter::Parser::new();
    parser
        .set_language(&tree_sitter_rapid::LANGUAGE.into())
        .expect("the RAPID grammar loads");

    let mut declared = HashSet::new();
    let mut called: BTreeMap<String, Count> = BTreeMap::new();
    let mut files = 0usize;
    for path in rapid_tests::rapid_paths(&dir, true) {
        let text = rapid_tests::decode_text(&std::fs::read(&path).expect("readable corpus file"));
        if text
            .trim_start_matches(['\u{feff}', ' ', '\t', '\r', '\n'])
            .starts_with('<')
        {
            continue; // an XML program descriptor
        }
        files += 1;
        let tree = parser.parse(&text, None).expect("a tree");
        let mut calls = Vec::new();
        walk(&tree, &text, &mut declared, &mut calls);
        for (name, _) in calls {
            let entry = called.entry(name.to_lowercase()).or_default();
            entry.calls += 1;
            entry.files.insert(path.clone());
            if entry.spelling.is_empty() {
                entry.spelling = name;
            }
        }
    }

    let gaps: HashSet<String> = CORPUS_GAPS.iter().map(|(n, _)| n.to_lowercase()).collect();
    let (mut builtin, mut option, mut own, mut gap) = ((0, 0), (0, 0), (0, 0), (0, 0));
    let mut unknown = Vec::new();
    for (lower, count) in &called {
        if declared.contains(lower) {
            own = (own.0 + 1, own.1 + count.calls);
        } else if cat.routine(lower).is_some() {
            builtin = (builtin.0 + 1, builtin.1 + count.calls);
        } else if option_names.contains(lower) {
            option = (option.0 + 1, option.1 + count.calls);
        } else if gaps.contains(lower) {
            gap = (gap.0 + 1, gap.1 + count.calls);
        } else {
            unknown.push(format!(
                "{} ({} calls in {} files)",
                count.spelling,
                count.calls,
                count.files.len()
            ));
        }
    }
    println!(
        "catalogue_coverage: {files} files; {} distinct routine names called ({} calls): \
         {} declared in the corpus ({} calls), {} built-in ({} calls), \
         {} option/vendor ({} calls), {} missing from the corpus ({} calls), {} unknown",
        called.len(),
        called.values().map(|c| c.calls).sum::<usize>(),
        own.0,
        own.1,
        builtin.0,
        builtin.1,
        option.0,
        option.1,
        gap.0,
        gap.1,
        unknown.len()
    );
    assert!(files > 0, "no RAPID files under {}", dir.display());
    // A gap entry that no longer matches anything must leave the list.
    let stale: Vec<&str> = CORPUS_GAPS
        .iter()
        .filter(|(n, _)| {
            !called.contains_key(&n.to_lowercase()) || declared.contains(&n.to_lowercase())
        })
        .map(|(n, _)| *n)
        .collect();
    assert!(stale.is_empty(), "stale CORPUS_GAPS entries: {stale:?}");
    assert!(
        unknown.is_empty(),
        "called but neither declared, catalogued nor listed as option routines:\n{}",
        unknown.join("\n")
    );
}

/// Every argument passed by name (`\Name` or `Name :=`) to a catalogued routine names one
/// of its parameters.
#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn named_arguments_of_builtins_are_parameters() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        println!("catalogue_coverage: no corpus (set RAPID_CORPUS); skipped");
        return;
    };
    let cat = catalogue();
    let mut parser = tree_sitter::Parser::new();
    parser
        .set_language(&tree_sitter_rapid::LANGUAGE.into())
        .expect("the RAPID grammar loads");
    let mut declared = HashSet::new();
    let mut uses: Vec<(String, String, PathBuf)> = Vec::new();
    for path in rapid_tests::rapid_paths(&dir, true) {
        let text = rapid_tests::decode_text(&std::fs::read(&path).expect("readable corpus file"));
        if text
            .trim_start_matches(['\u{feff}', ' ', '\t', '\r', '\n'])
            .starts_with('<')
        {
            continue;
        }
        let tree = parser.parse(&text, None).expect("a tree");
        let mut calls = Vec::new();
        walk(&tree, &text, &mut declared, &mut calls);
        named_arguments(&tree, &text, &mut uses, &path);
    }
    let mut bad: BTreeMap<String, usize> = BTreeMap::new();
    let mut checked = 0usize;
    for (routine, arg, _) in &uses {
        if declared.contains(&routine.to_lowercase()) {
            continue;
        }
        let Some(r) = cat.routine(routine) else {
            continue;
        };
        checked += 1;
        if !r.params.iter().any(|p| p.name.eq_ignore_ascii_case(arg)) {
            *bad.entry(format!("{}\\{}", r.name, arg)).or_default() += 1;
        }
    }
    println!(
        "catalogue_coverage: {checked} named arguments of built-in routines, {} unknown names",
        bad.len()
    );
    let list: Vec<String> = bad.iter().map(|(k, n)| format!("{k} ({n})")).collect();
    assert!(
        list.is_empty(),
        "named arguments that are not parameters:\n{}",
        list.join("\n")
    );
}

fn named_arguments(
    tree: &tree_sitter::Tree,
    text: &str,
    out: &mut Vec<(String, String, PathBuf)>,
    path: &Path,
) {
    let mut cursor = tree.walk();
    loop {
        let node = cursor.node();
        if matches!(node.kind(), "procedure_call" | "function_call")
            && let Some(name) = node
                .child_by_field_name("name")
                .filter(|n| n.kind() == "identifier")
                .and_then(|n| n.utf8_text(text.as_bytes()).ok())
            && let Some(args) = node.child_by_field_name("arguments")
        {
            let mut c = args.walk();
            for arg in args.children_by_field_name("argument", &mut c) {
                if let Some(a) = arg
                    .child_by_field_name("name")
                    .and_then(|n| n.utf8_text(text.as_bytes()).ok())
                {
                    out.push((name.to_owned(), a.to_owned(), path.to_path_buf()));
                }
            }
        }
        if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return;
            }
        }
    }
}
