//! Time of each position request on the adversarial inputs
//! (`rapid_tests::adversarial`), worst offset of a few: the figures behind
//! issue 16's "never hang" for references, rename and highlights.
//!
//! `cargo run --release -p rapid-tests --example adversarial_cost [N]
//! [NAME]` (N: the count of labels and chain links, 5,000 by default; deep inputs
//! are 100,000 levels; NAME: only the inputs whose name holds it;
//! `VERBOSE=1`: every time).
#![allow(clippy::print_stdout, reason = "the figures are the output")]

use std::sync::Arc;
use std::time::{Duration, Instant};

use rapid_analyzer::ide;
use rapid_analyzer::task::{Task, Unit};
use rapid_tests::adversarial::{Input, chains, deep};

fn time<R>(f: impl FnOnce() -> R) -> Duration {
    let t = Instant::now();
    let _ = f();
    t.elapsed()
}

fn measure(input: &Input) {
    let unit = Arc::new(Unit::new(
        format!("t/{}.mod", input.name),
        input.text.clone(),
        None,
    ));
    let task = Task::new("t".to_owned(), vec![unit.clone()], None);
    let len = input.text.len();
    // The offsets: the first name after `PROC main()` (or the first use),
    // the middle and the end.
    let first = input.text.find("main()").map_or(0, |i| i + 12);
    let offsets = [first, len / 2, len.saturating_sub(30)];
    let mut worst: Vec<(&str, Duration)> = Vec::new();
    let verbose = std::env::var_os("VERBOSE").is_some();
    let mut note = |name: &'static str, d: Duration| {
        if verbose {
            eprintln!("  {name} {d:?}");
        }
        match worst.iter_mut().find(|w| w.0 == name) {
            Some(w) => w.1 = w.1.max(d),
            None => worst.push((name, d)),
        }
    };
    let diags = time(|| rapid_analyzer::workspace::diagnostics_of(&task, &unit));
    note("diagnostics", diags);
    for &at in &offsets {
        note("hover", time(|| ide::hover(&task, 0, at)));
        note("definition", time(|| ide::definition(&task, 0, at)));
        note(
            "references",
            time(|| ide::references(&task, 0, at, true, &[])),
        );
        note(
            "highlights",
            time(|| ide::document_highlights(&task, 0, at)),
        );
        note("rename", time(|| ide::rename(&task, 0, at, "fresh", &[])));
        note("completion", time(|| ide::completions(&task, 0, at)));
        note("selection", time(|| ide::selection_ranges(&unit, &[at])));
    }
    note("tokens", time(|| ide::semantic_tokens(&task, 0, None)));
    note("folding", time(|| ide::folding_ranges(&unit)));
    let line: Vec<String> = worst
        .iter()
        .map(|(n, d)| format!("{n} {:.0}", d.as_secs_f64() * 1000.0))
        .collect();
    println!("{:<28} {} (ms)", input.name, line.join(", "));
}

fn main() {
    rapid_tests::alloc::init();
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5_000);
    let only = std::env::args().nth(2).unwrap_or_default();
    for input in chains(n).iter().chain(deep(100_000).iter()) {
        if !input.name.contains(&only) {
            continue;
        }
        let input = Input {
            name: input.name.clone(),
            text: input.text.clone(),
        };
        // The stack of a worker thread, as the server and rapid check run.
        std::thread::Builder::new()
            .stack_size(2 * 1024 * 1024)
            .spawn(move || measure(&input))
            .expect("a thread")
            .join()
            .expect("no panic");
    }
}
