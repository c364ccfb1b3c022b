//! Every file of the corpus of real code that `split_parse` can plan (at
//! whatever size: `rapid check` only splits files of 128 KB or more) is
//! parsed as two parts and compared with its whole parse: the same items,
//! syntax diagnostics and diagnostics, each file alone in its task. Files
//! whose parts do not fit are parsed again whole and must then equal the
//! whole parse too. The counts are printed.
//!
//! The corpus is read from `RAPID_CORPUS` or `../shared/corpus` next to the
//! workspace; when neither exists the test prints one line and passes.

#![allow(clippy::print_stdout)]

use rapid_analyzer::split_parse::{PartKind, parse_ranges, plan};
use rapid_analyzer::task::Unit;
use rapid_analyzer::text::{Decoded, decode};
use rapid_analyzer::workspace::{Workspace, diagnostics_of};

/// The diagnostics of `unit` alone in its task, as (code, range, message).
fn alone(unit: Unit) -> Vec<(&'static str, std::ops::Range<usize>, String)> {
    let mut ws = Workspace::new();
    ws.set_unit(unit);
    let task = ws.tasks().into_iter().next().expect("a task");
    diagnostics_of(&task, &task.units[0])
        .into_iter()
        .map(|d| (d.rule.code, d.range, d.message))
        .collect()
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn corpus_files_parsed_in_two_parts_check_as_parsed_whole() {
    let Some(files) = rapid_tests::corpus_files() else {
        println!("no corpus: skipped");
        return;
    };
    let (mut declarations, mut statements, mut refused, mut unplanned) = (0, 0, 0, 0);
    let mut failures = Vec::new();
    for (path, bytes) in &files {
        let Decoded::Text { text, .. } = decode(bytes) else {
            continue;
        };
        let Some(plan) = plan(&text, 0.5) else {
            unplanned += 1;
            continue;
        };
        let name = path.to_string_lossy().into_owned();
        let (Some(main), Some(part)) = (
            parse_ranges(&text, &plan.main),
            parse_ranges(&text, &plan.part),
        ) else {
            failures.push(format!("{name}: no tree"));
            continue;
        };
        let split = Unit::from_split(
            name.clone(),
            text.clone(),
            main,
            part,
            plan.chunk,
            plan.kind,
        );
        match (split.is_split(), plan.kind) {
            (false, _) => refused += 1,
            (true, PartKind::Declarations) => declarations += 1,
            (true, PartKind::Statements) => statements += 1,
        }
        let whole = Unit::new(name.clone(), text, None);
        if split.items != whole.items {
            failures.push(format!("{name}: items differ"));
        } else if split.syntax != whole.syntax {
            failures.push(format!("{name}: syntax diagnostics differ"));
        } else if alone(split) != alone(whole) {
            failures.push(format!("{name}: diagnostics differ"));
        }
    }
    println!(
        "{} files: {declarations} split between declarations, {statements} between statements, {refused} parsed again whole, {unplanned} without a plan",
        files.len()
    );
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(
        declarations + statements > files.len() / 4,
        "few files split: the planner finds too little"
    );
}
