//! Parses RAPID files once, either with raw tree-sitter or with our
//! wrapper (decode, parse, syntax diagnostics): the floor that `rapid
//! check` is measured against.
//!
//! ```sh
//! parse_cost raw [PATHS...]    # read, decode, raw tree-sitter parse, one thread
//! parse_cost ours [PATHS...]   # read, decode, our parse with syntax diagnostics
//! parse_cost read [PATHS...]   # read and decode only
//! ```
//!
//! The files are the RAPID modules below PATHS (every file with a module's
//! extension, as `rapid check` finds them), else the corpus. Each mode
//! reads the files itself, so its whole-process time compares with `rapid
//! check` on the same paths (`tests/bench/check_bench.py` does this), and
//! instruction counts do not depend on machine noise:
//!
//! ```sh
//! valgrind --tool=callgrind --callgrind-out-file=raw.out target/release/examples/parse_cost raw
//! ```
//!
//! `read` only reads and decodes the files: subtract it from the other two.
use std::path::PathBuf;
use std::process::ExitCode;

use rapid_analyzer::text::{Decoded, decode};

fn main() -> ExitCode {
    rapid_tests::alloc::init();
    let mut args = std::env::args().skip(1);
    let mode = args.next().unwrap_or_default();
    let paths: Vec<PathBuf> = args.map(PathBuf::from).collect();
    let files: Vec<PathBuf> = if paths.is_empty() {
        let Some(dir) = rapid_tests::corpus_dir() else {
            eprintln!("no corpus (set RAPID_CORPUS)");
            return ExitCode::from(2);
        };
        rapid_tests::rapid_paths(&dir, false)
    } else {
        paths
            .iter()
            .flat_map(|p| {
                if p.is_dir() {
                    rapid_tests::rapid_paths(p, false)
                } else {
                    vec![p.clone()]
                }
            })
            .collect()
    };
    let mut parser = rapid_analyzer::syntax::parser();
    let (mut bytes, mut count) = (0usize, 0usize);
    for path in &files {
        let Ok(raw) = std::fs::read(path) else {
            continue;
        };
        bytes += raw.len();
        let Decoded::Text { text, .. } = decode(&raw) else {
            continue;
        };
        count += match mode.as_str() {
            "read" => usize::from(text.is_empty()),
            "raw" => parser
                .parse(&text, None)
                .map_or(0, |tree| usize::from(tree.root_node().has_error())),
            _ => rapid_analyzer::syntax::parse(&mut parser, &text, None).map_or(0, |tree| {
                rapid_analyzer::syntax::syntax_diagnostics(&tree, &text).len()
            }),
        };
    }
    eprintln!("{} files, {bytes} bytes ({count})", files.len());
    ExitCode::SUCCESS
}
