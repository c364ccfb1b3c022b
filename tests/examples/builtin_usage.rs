//! Writes the rank table that completion orders built-ins by
//! (`analyzer/src/ide/usage.txt`): the built-in instructions and functions
//! the corpus calls most, most first. Each module adds ln(1 + its calls of
//! a name): a name called in many modules ranks above one a few modules
//! call very often (a generated path of 9,000 `MoveL` counts as some nine
//! calls in one module), and a name called often in each module (`MoveL`)
//! above one called once or twice in as many (`WaitTime`).
//!
//! ```sh
//! cargo run --release -p rapid-tests --example builtin_usage > analyzer/src/ide/usage.txt
//! ```
//!
//! Only the names and their order are kept: no text of the corpus.
#![allow(clippy::print_stdout, reason = "the table is the output")]

use std::collections::HashMap;
use std::process::ExitCode;

use rapid_analyzer::catalogue::base as catalogue;
use rapid_analyzer::names::fold;
use rapid_analyzer::text::{Decoded, decode};

/// How many names of each kind the table keeps.
const INSTRUCTIONS: usize = 60;
const FUNCTIONS: usize = 40;
/// A name called by fewer modules than this is not ranked.
const AT_LEAST: usize = 3;

/// A name's score so far: ln(1 + calls) summed over modules, and the
/// number of modules.
#[derive(Default)]
struct Score {
    weight: f64,
    modules: usize,
}

fn main() -> ExitCode {
    rapid_tests::alloc::init();
    let Some(files) = rapid_tests::corpus_files() else {
        eprintln!("no corpus (set RAPID_CORPUS)");
        return ExitCode::from(2);
    };
    let cat = catalogue();
    let mut parser = rapid_analyzer::syntax::parser();
    let mut scores: [HashMap<String, Score>; 2] = Default::default();
    for (_, bytes) in &files {
        let Decoded::Text { text, .. } = decode(bytes) else {
            continue;
        };
        let Some(tree) = rapid_analyzer::syntax::parse(&mut parser, &text, None) else {
            continue;
        };
        let mut calls: [HashMap<String, usize>; 2] = Default::default();
        let mut cursor = tree.walk();
        'walk: loop {
            let node = cursor.node();
            let kind = match node.kind() {
                "procedure_call" => Some(0),
                "function_call" => Some(1),
                _ => None,
            };
            if let Some(k) = kind
                && let Some(name) = node.child_by_field_name("name")
                && let Some(name) = text.get(name.byte_range())
            {
                let known = if k == 0 {
                    cat.instruction(name).map(|r| r.name.clone())
                } else {
                    cat.function(name).map(|r| r.name.clone())
                };
                if let Some(name) = known {
                    *calls[k].entry(name).or_default() += 1;
                }
            }
            if cursor.goto_first_child() {
                continue;
            }
            loop {
                if cursor.goto_next_sibling() {
                    continue 'walk;
                }
                if !cursor.goto_parent() {
                    break 'walk;
                }
            }
        }
        for (k, names) in calls.into_iter().enumerate() {
            for (name, n) in names {
                let score = scores[k].entry(name).or_default();
                score.weight += (1.0 + n as f64).ln();
                score.modules += 1;
            }
        }
    }
    println!(
        "# Built-in instructions and functions ranked by how much the modules of the\n\
         # test corpus call them (each module adds ln(1 + its calls)), most first:\n\
         # the order completion offers them in. Names only. Written by\n\
         # `cargo run --release -p rapid-tests --example builtin_usage`."
    );
    for (k, (title, keep)) in [("instructions", INSTRUCTIONS), ("functions", FUNCTIONS)]
        .into_iter()
        .enumerate()
    {
        let mut ranked: Vec<(&String, &Score)> = scores[k]
            .iter()
            .filter(|(_, s)| s.modules >= AT_LEAST)
            .collect();
        ranked.sort_by(|a, b| {
            b.1.weight
                .total_cmp(&a.1.weight)
                .then(fold(a.0).cmp(&fold(b.0)))
        });
        println!("[{title}]");
        for (name, _) in ranked.into_iter().take(keep) {
            println!("{name}");
        }
    }
    ExitCode::SUCCESS
}
