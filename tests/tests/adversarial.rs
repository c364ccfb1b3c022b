//! Deep and adversarial inputs (generated, see `rapid_tests::adversarial`)
//! through every analyzer entry point the tools use: parsing and syntax
//! diagnostics, the checker, constant values, and every editor feature at sampled offsets. Each
//! input runs on a thread with a 2 MiB stack, the size of the server's and
//! `rapid check`'s worker threads: a stack overflow aborts this test, a
//! panic fails it. Bounded: about a minute in a debug build.

use std::sync::Arc;

use rapid_analyzer::ide;
use rapid_analyzer::task::{Task, Unit};
use rapid_tests::adversarial::{Input, Rng, chains, deep, mutate};

/// Runs `f` on a thread with the stack of a worker thread.
fn on_worker<R: Send + 'static>(name: &str, f: impl FnOnce() -> R + Send + 'static) -> R {
    let handle = std::thread::Builder::new()
        .name(name.to_owned())
        .stack_size(2 * 1024 * 1024)
        .spawn(f)
        .expect("a thread");
    match handle.join() {
        Ok(r) => r,
        Err(_) => panic!("{name}: the analyzer panicked"),
    }
}

/// Everything the tools do with one file; returns the codes found.
fn exercise(input: &Input, samples: usize) -> Vec<&'static str> {
    let unit = Arc::new(Unit::new(
        format!("t/{}.mod", input.name),
        input.text.clone(),
        None,
    ));
    let task = Task::new("t".to_owned(), vec![unit.clone()], None);
    let diags = rapid_analyzer::workspace::diagnostics_of(&task, &unit);
    let len = input.text.len();
    let mut rng = Rng::new(len as u64);
    let mut offsets: Vec<usize> = (0..samples).map(|_| rng.below(len + 2)).collect();
    offsets.extend([0, len / 2, len, len + 5]);
    let tasks = vec![Arc::new(Task::new(
        "t".to_owned(),
        vec![unit.clone()],
        None,
    ))];
    for &offset in &offsets {
        let _ = ide::hover(&task, 0, offset);
        let _ = ide::completions(&task, 0, offset);
        let _ = ide::signature_help(&task, 0, offset);
        let _ = ide::definition(&task, 0, offset);
        let _ = ide::type_definition(&task, 0, offset);
        let _ = ide::prepare_rename(&task, 0, offset);
        let _ = ide::references(&task, 0, offset, true, &[]);
        let _ = ide::document_highlights(&task, 0, offset);
        let _ = ide::rename(&task, 0, offset, "fresh", &[]);
        let _ = ide::inlay_hints(
            &task,
            0,
            offset..(offset + 400).min(len),
            ide::ParameterHints::All,
        );
        let _ = rapid_analyzer::consteval::value_at(&task, 0, offset);
    }
    let _ = ide::semantic_tokens(&task, 0, None);
    let _ = ide::document_symbols(&unit);
    let _ = ide::workspace_symbols(&tasks, "c");
    let _ = ide::folding_ranges(&unit);
    let _ = ide::selection_ranges(&unit, &offsets);
    let _ = ide::code_actions(&task, 0, 0..len, &diags);
    diags.iter().map(|d| d.rule.code).collect()
}

#[test]
fn deep_inputs_give_a_diagnostic_and_every_feature_survives() {
    for input in deep(100_000) {
        let name = input.name.clone();
        let codes = on_worker(&name, move || exercise(&input, 12));
        // Every kind nests past the limit, except text the parser cannot
        // nest (unclosed or stray brackets, compact IFs inside compact IFs
        // make syntax errors, not depth).
        if !["unclosed", "stray", "compact"]
            .iter()
            .any(|k| name.contains(k))
        {
            assert!(codes.contains(&"W001"), "{name}: {codes:?}");
        }
    }
}

#[test]
fn chains_cycles_and_duplicates_survive() {
    for input in chains(3_000) {
        let name = input.name.clone();
        let codes = on_worker(&name, move || exercise(&input, 12));
        if name.starts_with("duplicates") {
            assert_eq!(
                codes.iter().filter(|c| **c == "E106").count(),
                2_999,
                "{name}"
            );
        }
    }
}

#[test]
fn damaged_inputs_survive() {
    // Each generated input around the limit, damaged a few times.
    let mut rng = Rng::new(16);
    let mut bases = deep(300);
    bases.extend(chains(300));
    for base in bases {
        for round in 0..4 {
            let input = Input {
                name: format!("{}-damaged-{round}", base.name),
                text: mutate(&base.text, &mut rng),
            };
            on_worker(&input.name.clone(), move || exercise(&input, 8));
        }
    }
}
