//! The interpreter on the corpus of real programs: every module's task
//! runs (its `main`, or else the module's first procedure without
//! parameters) to its end, or stops with a controller error at a real line
//! of the program, or at an instruction named as not supported in
//! simulation, or when a budget runs out; never a panic, never a hang. A
//! task the checker finds the controller would not load does not run (its
//! first error is at a real line too).
//!
//! `cargo test -p rapid-tests --test corpus_run -- --nocapture` prints how
//! the runs ended; with `RAPID_RUN_ALL=1` every procedure without
//! parameters of every module runs, not only the entry points.

#![allow(clippy::print_stdout)]

use std::collections::{BTreeMap, HashSet};
use std::sync::Arc;
use std::time::{Duration, Instant};

use rapid_analyzer::items::RoutineKind;
use rapid_runtime::{Config, Limits, Program, Status};

#[test]
fn every_corpus_module_runs_or_stops_with_a_reason_at_a_real_line() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        println!("no corpus (RAPID_CORPUS or ../shared/corpus): skipped");
        return;
    };
    let loaded = rapid_tests::workspace_inputs(&dir);
    let mut ws = loaded.workspace();
    let lines: BTreeMap<&str, usize> = loaded
        .modules
        .iter()
        .map(|(p, t)| (p.as_str(), t.lines().count().max(1)))
        .collect();
    let sandbox = std::env::temp_dir().join(format!("rapid-corpus-run-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&sandbox);
    std::fs::create_dir_all(&sandbox).expect("a sandbox");
    let limits = Limits {
        max_steps: 100_000,
        max_time: 300.0,
        max_depth: 200,
        ..Limits::default()
    };
    let mut done: HashSet<(String, String)> = HashSet::new();
    let mut by_status: BTreeMap<String, usize> = BTreeMap::new();
    let mut unsupported: BTreeMap<String, usize> = BTreeMap::new();
    let mut problems = Vec::new();
    let mut slowest = (Duration::ZERO, String::new());
    let mut runs = 0;
    let mut not_loaded: HashSet<String> = HashSet::new();
    for (path, _) in &loaded.modules {
        let task = ws.task_of(path);
        if not_loaded.contains(&task.key) {
            continue;
        }
        let errors = rapid_runtime::load_errors(&task);
        if let Some(first) = errors.first() {
            not_loaded.insert(task.key.clone());
            *by_status
                .entry("not loaded (checker errors)".to_owned())
                .or_default() += 1;
            let real = lines
                .get(first.at.path.as_str())
                .is_some_and(|&n| first.at.line >= 1 && first.at.line <= n);
            if !real {
                problems.push(format!("{path}: a load error at no real line: {first}"));
            }
            if std::env::var_os("RAPID_RUN_VERBOSE").is_some() {
                println!("{path}: not loaded: {first}");
            }
            continue;
        }
        let program = Arc::new(Program::new(task.clone(), &[]));
        let routines = program.routines();
        let entry = routines
            .iter()
            .find(|r| r.name.eq_ignore_ascii_case("main") && r.kind == RoutineKind::Proc)
            .or_else(|| {
                routines
                    .iter()
                    .find(|r| r.at.path == *path && r.kind == RoutineKind::Proc && r.params == 0)
            });
        // RAPID_RUN_ALL=1: every procedure without parameters of each
        // module, not only the entry point (a deeper, slower sweep).
        let entries: Vec<_> = if std::env::var_os("RAPID_RUN_ALL").is_some() {
            routines
                .iter()
                .filter(|r| r.at.path == *path && r.kind == RoutineKind::Proc && r.params == 0)
                .collect()
        } else {
            entry.into_iter().collect()
        };
        if entries.is_empty() {
            *by_status.entry("no entry routine".to_owned()).or_default() += 1;
            continue;
        }
        for entry in entries {
            if !done.insert((task.key.clone(), entry.name.to_ascii_lowercase())) {
                continue;
            }
            runs += 1;
            let config = Config {
                limits: limits.clone(),
                sandbox: Some(sandbox.clone()),
                ..Config::default()
            };
            let id = entry.id;
            let p = program.clone();
            let started = Instant::now();
            let outcome = std::panic::catch_unwind(move || {
                rapid_runtime::run_routine(p, id, config, Box::new(|_, _: &str| {})).0
            });
            let took = started.elapsed();
            let what = format!("{path} ({})", entry.name);
            if took > slowest.0 {
                slowest = (took, what.clone());
            }
            let Ok(outcome) = outcome else {
                problems.push(format!("{what}: the interpreter panicked"));
                continue;
            };
            let key = match outcome.status {
                Status::Finished | Status::Exited | Status::Stopped | Status::Halted => {
                    format!("{:?}", outcome.status)
                }
                Status::Error => format!(
                    "Error {}",
                    outcome.errno.as_ref().map_or("?", |(_, n)| n.as_str())
                ),
                other => format!("{other:?}"),
            };
            *by_status.entry(key).or_default() += 1;
            if outcome.status == Status::Unsupported {
                *unsupported.entry(outcome.message.clone()).or_default() += 1;
            }
            if std::env::var_os("RAPID_RUN_VERBOSE").is_some() && !outcome.is_success() {
                println!(
                    "{what}: {:?} {} at {:?}",
                    outcome.status,
                    outcome.message,
                    outcome.at.as_ref().map(|a| a.line)
                );
            }
            if !outcome.is_success() || outcome.status == Status::Stopped {
                match &outcome.at {
                    Some(at)
                        if lines
                            .get(at.path.as_str())
                            .is_some_and(|&n| at.line >= 1 && at.line <= n) => {}
                    other => problems.push(format!(
                        "{what}: {:?} ({}) at no real line: {other:?}",
                        outcome.status, outcome.message
                    )),
                }
            }
            if took > Duration::from_secs(20) {
                problems.push(format!("{what}: took {took:?}"));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&sandbox);
    println!("{runs} runs of {} modules", loaded.modules.len());
    for (k, n) in &by_status {
        println!("{n:5}  {k}");
    }
    println!("not supported in simulation:");
    let mut top: Vec<_> = unsupported.into_iter().collect();
    top.sort_by_key(|t| std::cmp::Reverse(t.1));
    for (k, n) in top.iter().take(25) {
        println!("{n:5}  {k}");
    }
    println!("slowest: {:?} {}", slowest.0, slowest.1);
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
