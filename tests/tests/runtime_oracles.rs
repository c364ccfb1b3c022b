//! Oracles of the interpreter over the whole corpus: it runs what the
//! analyzer says a program means.
//!
//! - Every call the interpreter compiles (from the lowered bodies, names
//!   resolved through `rapid_analyzer::resolve`) is bound as the checker
//!   binds it from the syntax tree (`resolve::call_bindings`): the same
//!   routine, each argument to the same parameter.
//! - Every constant of every module starts with the value the constant
//!   evaluator computes for its declaration (`consteval::value_of_range`,
//!   the hover's value), or fails where it fails.
//!
//! `cargo test -p rapid-tests --test runtime_oracles -- --nocapture`
//! prints how much was compared.

#![allow(clippy::print_stdout)]

use std::collections::{BTreeMap, HashSet};
use std::sync::Arc;

use rapid_analyzer::items::Storage;
use rapid_analyzer::resolve::{CallBinding, call_bindings};
use rapid_analyzer::task::Task;
use rapid_runtime::world::World;
use rapid_runtime::{Config, Controller, Program, TaskKind, TaskSpec};

/// Every distinct task of the corpus (a module's task, or its own view of
/// it).
fn corpus_tasks() -> Option<Vec<Arc<Task>>> {
    let dir = rapid_tests::corpus_dir()?;
    let loaded = rapid_tests::workspace_inputs(&dir);
    let mut ws = loaded.workspace();
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for (path, _) in &loaded.modules {
        let task = ws.task_of(path);
        if seen.insert(Arc::as_ptr(&task) as usize) {
            out.push(task);
        }
    }
    Some(out)
}

#[test]
fn every_call_is_bound_as_the_checker_binds_it() {
    let Some(tasks) = corpus_tasks() else {
        println!("no corpus (RAPID_CORPUS or ../shared/corpus): skipped");
        return;
    };
    let mut compared = 0usize;
    let mut mismatches = Vec::new();
    for task in &tasks {
        let program = Program::new(task.clone(), &[]);
        let mut runtime: BTreeMap<usize, Vec<CallBinding>> = BTreeMap::new();
        for (unit, b) in program.call_bindings() {
            runtime.entry(unit).or_default().push(b);
        }
        // A view (one of alternative programs) loads only what it sees.
        for (i, unit) in task.live_units() {
            let mut ours = runtime.remove(&i).unwrap_or_default();
            // Code with syntax errors is not lowered whole.
            if !unit.syntax.is_empty() {
                continue;
            }
            let mut checker = call_bindings(task, i);
            checker.sort();
            ours.sort();
            compared += checker.len();
            if checker != ours {
                let only = |a: &[CallBinding], b: &[CallBinding]| -> Vec<String> {
                    a.iter()
                        .filter(|x| !b.contains(x))
                        .take(3)
                        .map(|x| format!("{x:?}"))
                        .collect()
                };
                mismatches.push(format!(
                    "{}: {} calls bound by the checker, {} by the interpreter\n  checker only: {:?}\n  interpreter only: {:?}",
                    unit.path,
                    checker.len(),
                    ours.len(),
                    only(&checker, &ours),
                    only(&ours, &checker),
                ));
            }
        }
        if let Some((&unit, _)) = runtime.first_key_value() {
            mismatches.push(format!(
                "unit {unit}: bound by the interpreter, hidden from the task"
            ));
        }
    }
    println!(
        "{compared} calls of {} tasks bound alike by the checker and the interpreter",
        tasks.len()
    );
    assert!(
        mismatches.is_empty(),
        "{} units differ:\n{}",
        mismatches.len(),
        mismatches
            .iter()
            .take(20)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
    assert!(compared > 1000, "too few calls compared: {compared}");
}

#[test]
fn every_constant_starts_as_the_constant_evaluator_computes_it() {
    let Some(tasks) = corpus_tasks() else {
        println!("no corpus (RAPID_CORPUS or ../shared/corpus): skipped");
        return;
    };
    let mut compared = 0usize;
    let mut failing = 0usize;
    let mut mismatches = Vec::new();
    for task in &tasks {
        let program = Arc::new(Program::new(task.clone(), &[]));
        let config = Config::default();
        let world = World::simulated(&config, Box::new(|_: rapid_runtime::Stream, _: &str| {}));
        let mut controller = Controller::new(config, world);
        controller.add_task(TaskSpec {
            name: "T_ROB1".to_owned(),
            program,
            entry: None,
            kind: TaskKind::Normal,
            robot: None,
        });
        for data in controller.data_values(0) {
            let Some(unit) = task.units.get(data.unit) else {
                continue;
            };
            let decl = unit
                .items
                .modules
                .iter()
                .flat_map(|m| m.data.iter())
                .find(|d| d.range == data.range);
            let Some(decl) = decl.filter(|d| d.storage == Storage::Const) else {
                continue;
            };
            let Some(init) = decl.init.clone() else {
                continue;
            };
            let Some(expected) =
                rapid_analyzer::consteval::value_of_range(task, data.unit, init.clone())
            else {
                continue;
            };
            if expected.initial_value_only {
                continue;
            }
            compared += 1;
            let got = data.value.as_ref().map(ToString::to_string);
            let agree = match (&expected.error, &got) {
                (Some(_), None) => {
                    failing += 1;
                    true
                }
                (None, Some(v)) => *v == expected.value,
                _ => false,
            };
            if !agree {
                mismatches.push(format!(
                    "{} {}: the constant evaluator gives {:?} (error {:?}), the interpreter {got:?}",
                    unit.path, decl.name, expected.value, expected.error
                ));
            }
        }
    }
    println!(
        "{compared} constants of {} tasks start alike ({failing} fail in both)",
        tasks.len()
    );
    assert!(
        mismatches.is_empty(),
        "{} constants differ:\n{}",
        mismatches.len(),
        mismatches
            .iter()
            .take(30)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
    assert!(compared > 1000, "too few constants compared: {compared}");
}
