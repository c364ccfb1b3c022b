//! The formatter on every file of the corpus of real code that parses
//! without errors: the result parses without errors, has the same tokens
//! (keywords compared in upper case, comments without trailing blanks), keeps
//! every comment on a line with the same neighbours, and formatting it again
//! changes nothing (also with a narrow line width, where many calls are
//! wrapped). Prints how many files were formatted, how many were
//! already formatted, and the time taken.
//!
//! The corpus is read from `RAPID_CORPUS` or `../shared/corpus`; without it
//! the test prints one line and passes.

#![allow(clippy::print_stdout)]

use std::time::{Duration, Instant};

use rapid_analyzer::format::{FormatOptions, format};
use rapid_analyzer::text::{Decoded, decode};
use tree_sitter::{Node, Tree};

/// A leaf token: its kind and text (keywords upper case; comments without
/// trailing blanks).
#[derive(Debug, PartialEq, Eq)]
struct Token {
    kind: String,
    text: String,
}

fn parse(text: &str) -> Tree {
    let mut parser = rapid_analyzer::syntax::parser();
    rapid_analyzer::syntax::parse(&mut parser, text, None).expect("a tree")
}

fn tokens(tree: &Tree, text: &str) -> Vec<Token> {
    fn walk(node: Node<'_>, text: &str, out: &mut Vec<Token>) {
        if node.child_count() == 0 || node.kind() == "string" {
            let mut t = text[node.byte_range()].to_owned();
            if node.kind() == "comment" {
                t.truncate(t.trim_end().len());
            } else if !node.is_named() {
                t = t.to_ascii_uppercase();
            }
            if node.kind() == "trailing_text" {
                // kept verbatim; compare without the blanks it starts after
                t = t.trim().to_owned();
            }
            out.push(Token {
                kind: node.kind().to_owned(),
                text: t,
            });
            return;
        }
        let mut cursor = node.walk();
        for child in node.children(&mut cursor) {
            walk(child, text, out);
        }
    }
    let mut out = Vec::new();
    walk(tree.root_node(), text, &mut out);
    out
}

/// For each comment: the token before it on its line (or none) — a
/// trailing comment stays trailing after the same token, an own-line comment
/// stays on its own line.
fn comment_places(tree: &Tree, text: &str) -> Vec<(String, Option<String>)> {
    let mut out = Vec::new();
    let mut prev: Option<(usize, String)> = None; // end byte, text of the last leaf
    fn leaves<'a>(node: Node<'a>, out: &mut Vec<Node<'a>>) {
        if node.child_count() == 0 || node.kind() == "string" {
            out.push(node);
            return;
        }
        let mut cursor = node.walk();
        for child in node.children(&mut cursor) {
            leaves(child, out);
        }
    }
    let mut all = Vec::new();
    leaves(tree.root_node(), &mut all);
    for leaf in all {
        let leaf_text = text[leaf.byte_range()].trim_end().to_owned();
        if leaf.kind() == "comment" {
            let before = prev.as_ref().and_then(|(end, t)| {
                let between = &text[*end..leaf.start_byte()];
                (!between.contains(['\n', '\r'])).then(|| t.to_ascii_uppercase())
            });
            out.push((leaf_text.clone(), before));
        }
        prev = Some((leaf.end_byte(), leaf_text));
    }
    out
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn formatting_the_corpus_is_safe_and_stable() {
    let Some(files) = rapid_tests::corpus_files() else {
        println!("format corpus test skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    let options = FormatOptions::default();
    let (mut formatted, mut unchanged, mut skipped) = (0, 0, 0);
    let mut time = Duration::ZERO;
    let mut failures = Vec::new();
    for (path, bytes) in &files {
        let Decoded::Text { text, .. } = decode(bytes) else {
            skipped += 1;
            continue;
        };
        let tree = parse(&text);
        if tree.root_node().has_error() {
            skipped += 1;
            assert!(
                format(&text, &options).is_err(),
                "{}: a file with errors was formatted",
                path.display()
            );
            continue;
        }
        let start = Instant::now();
        let result = format(&text, &options);
        time += start.elapsed();
        let out = match result {
            Ok(out) => out,
            Err(e) => {
                failures.push(format!("{}: {e}", path.display()));
                continue;
            }
        };
        if out == text {
            unchanged += 1;
        } else {
            formatted += 1;
        }
        let out_tree = parse(&out);
        if out_tree.root_node().has_error() {
            failures.push(format!("{}: the output does not parse", path.display()));
            continue;
        }
        if tokens(&tree, &text) != tokens(&out_tree, &out) {
            failures.push(format!("{}: the tokens changed", path.display()));
        }
        if comment_places(&tree, &text) != comment_places(&out_tree, &out) {
            failures.push(format!("{}: a comment moved", path.display()));
        }
        // narrow settings wrap far more calls: still stable
        let narrow = FormatOptions {
            indent_width: 2,
            line_width: 60,
        };
        if let Ok(once) = format(&text, &narrow)
            && format(&once, &narrow).as_ref() != Ok(&once)
        {
            failures.push(format!("{}: not idempotent at width 60", path.display()));
        }
        match format(&out, &options) {
            Ok(again) if again == out => {}
            Ok(_) => failures.push(format!("{}: not idempotent", path.display())),
            Err(e) => failures.push(format!(
                "{}: the output does not format: {e}",
                path.display()
            )),
        }
    }
    println!(
        "format corpus: {} files: {formatted} formatted, {unchanged} already formatted, \
         {skipped} skipped (syntax errors or not text); formatting took {:.3} s",
        files.len(),
        time.as_secs_f64()
    );
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(formatted + unchanged > 0, "nothing was formatted");
}
