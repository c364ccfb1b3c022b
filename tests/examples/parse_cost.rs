//! Parses the whole corpus once, either with raw tree-sitter or with our
//! wrapper (decode, parse, syntax diagnostics), for instruction counts that
//! do not depend on machine noise:
//!
//! ```sh
//! valgrind --tool=callgrind --callgrind-out-file=raw.out target/release/examples/parse_cost raw
//! valgrind --tool=callgrind --callgrind-out-file=ours.out target/release/examples/parse_cost ours
//! valgrind --tool=callgrind --callgrind-out-file=read.out target/release/examples/parse_cost read
//! ```
//!
//! `read` only reads and decodes the files: subtract it from the other two.
use std::process::ExitCode;

use rapid_analyzer::text::{Decoded, decode};

fn main() -> ExitCode {
    rapid_tests::alloc::init();
    let Some(files) = rapid_tests::corpus_files() else {
        eprintln!("no corpus (set RAPID_CORPUS)");
        return ExitCode::from(2);
    };
    let mode = std::env::args().nth(1).unwrap_or_default();
    let raw = mode == "raw" || mode == "read";
    let texts: Vec<String> = if raw {
        files
            .iter()
            .filter_map(|(_, b)| match decode(b) {
                Decoded::Text { text, .. } => Some(text),
                _ => None,
            })
            .collect()
    } else {
        Vec::new()
    };
    let mut parser = rapid_analyzer::syntax::parser();
    let mut nodes = 0usize;
    if mode == "read" {
        nodes = texts.len();
    } else if raw {
        for text in &texts {
            if let Some(tree) = parser.parse(text, None) {
                nodes += usize::from(tree.root_node().has_error());
            }
        }
    } else {
        for (_, bytes) in &files {
            if let Decoded::Text { text, .. } = decode(bytes)
                && let Some(tree) = rapid_analyzer::syntax::parse(&mut parser, &text, None)
            {
                nodes += rapid_analyzer::syntax::syntax_diagnostics(&tree, &text).len();
            }
        }
    }
    eprintln!("{} files, {nodes}", files.len());
    ExitCode::SUCCESS
}
