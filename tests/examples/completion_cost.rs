//! Completion at a statement start of a large module, timed in process
//! (no protocol, no transport): the analyzer's share of a completion
//! request.
//!
//! ```sh
//! python3 -c 'import sys; sys.path.insert(0, "tests/bench"); import lsp_bench; print(lsp_bench.synthesize(9000), end="")' > /tmp/Synth.mod
//! cargo run --release -p rapid-tests --example completion_cost /tmp/Synth.mod [lean]
//! ```
//!
//! `lean`: without the items' details, as the server builds lists for
//! clients that resolve details (VS Code).
#![allow(clippy::print_stdout, reason = "the figures are the output")]

use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

use rapid_analyzer::task::{Task, Unit};

fn main() -> ExitCode {
    rapid_tests::alloc::init();
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: completion_cost MODULE [lean]");
        return ExitCode::from(2);
    };
    let details = std::env::args().nth(2).as_deref() != Some("lean");
    let Ok(text) = std::fs::read_to_string(&path) else {
        eprintln!("cannot read {path}");
        return ExitCode::from(2);
    };
    let unit = Arc::new(Unit::new(path.clone(), text.clone(), None));
    let task = Task::new("t".into(), vec![unit], None);
    // The start of the middle line of the file that holds a statement.
    let lines: Vec<&str> = text.lines().collect();
    let Some(line) = (lines.len() / 2..lines.len()).find(|&i| lines[i].trim_end().ends_with(';'))
    else {
        eprintln!("no statement in the second half of {path}");
        return ExitCode::from(2);
    };
    let indent = lines[line].len() - lines[line].trim_start().len();
    let offset: usize = lines[..line].iter().map(|l| l.len() + 1).sum::<usize>() + indent;
    rapid_analyzer::ide::prepare_completions();
    let mut times = Vec::new();
    let mut n = 0;
    for _ in 0..1000 {
        let t = Instant::now();
        let items = rapid_analyzer::ide::completions_for(&task, 0, offset, details, None);
        n = items.len();
        std::hint::black_box(items);
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    println!(
        "{n} items at line {}: median {:.3} ms, p99 {:.3} ms",
        line + 1,
        times[500],
        times[990]
    );
    ExitCode::SUCCESS
}
