//! Every `CONST` declaration of the corpus of real code is evaluated, in
//! its task (files grouped as `rapid check` groups them), through
//! `consteval`: nothing may panic, and the outcome of each is counted (a
//! value, not constant, a run-time error, something the evaluator cannot
//! compute). The counts and the slowest evaluation are printed; the test
//! fails on a panic or when almost nothing evaluates (a broken connection).
//! Evaluation is bounded by the evaluator's step and depth limits, not by a
//! clock.
//!
//! The corpus is read from `RAPID_CORPUS` or `../shared/corpus` next to the
//! workspace; when neither exists the test prints one line and passes.

#![allow(clippy::print_stdout)]

use std::collections::BTreeMap;
use std::time::{Duration, Instant};

use rapid_analyzer::consteval::{EnvOptions, eval_in};
use rapid_analyzer::text::{Decoded, decode};
use rapid_analyzer::workspace::Workspace;
use rapid_evaluator::Expr;

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn every_corpus_constant_evaluates_without_panic() {
    let Some(files) = rapid_tests::corpus_files() else {
        println!("no corpus: skipped");
        return;
    };
    let mut workspace = Workspace::new();
    for (path, bytes) in &files {
        if let Decoded::Text { text, .. } = decode(bytes) {
            workspace.set_file(&path.to_string_lossy(), text);
        }
    }
    let mut outcomes: BTreeMap<String, usize> = BTreeMap::new();
    let mut total = 0;
    let mut slowest = (Duration::ZERO, String::new());
    for task in workspace.tasks() {
        for (u, unit) in task.units.iter().enumerate() {
            for (name, offset) in constants(unit.tree(), &unit.text) {
                total += 1;
                let start = Instant::now();
                let r = eval_in(
                    &task,
                    Some((u, offset)),
                    &Expr::Name(name.clone()),
                    None,
                    EnvOptions::default(),
                );
                let took = start.elapsed();
                if took > slowest.0 {
                    slowest = (took, format!("{} {name}", unit.path));
                }
                let outcome = match r {
                    Ok(_) => "value".to_owned(),
                    Err(e) if e.code.is_runtime() => format!("run-time error {}", e.code.name()),
                    Err(e) => e.code.name().to_owned(),
                };
                *outcomes.entry(outcome).or_default() += 1;
            }
        }
    }
    println!("{total} CONST declarations evaluated");
    for (outcome, n) in &outcomes {
        println!("  {n:6}  {outcome}");
    }
    println!("slowest: {:?} ({})", slowest.0, slowest.1);
    let values = outcomes.get("value").copied().unwrap_or(0);
    assert!(
        total == 0 || values * 2 > total,
        "fewer than half the constants evaluate: {outcomes:?}"
    );
}

/// The names and positions of every `CONST` declaration of a file (module
/// and routine data).
fn constants(tree: &tree_sitter::Tree, text: &str) -> Vec<(String, usize)> {
    let mut out = Vec::new();
    let mut cursor = tree.walk();
    loop {
        let node = cursor.node();
        if node.kind() == "data_declaration" {
            let is_const = node
                .child_by_field_name("storage")
                .is_some_and(|s| s.kind() == "const");
            if is_const && let Some(name) = node.child_by_field_name("name") {
                out.push((
                    text.get(name.byte_range()).unwrap_or_default().to_owned(),
                    node.start_byte(),
                ));
            }
        }
        if node.kind() != "data_declaration" && cursor.goto_first_child() {
            continue;
        }
        while !cursor.goto_next_sibling() {
            if !cursor.goto_parent() {
                return out;
            }
        }
    }
}
