//! The formatter on every file of the corpus of real code.
//!
//! Safety, in every style (and with a narrow line width, where many calls
//! are wrapped): a file with syntax errors is refused; the result parses
//! without errors, has the same tokens (keywords compared in upper case,
//! comments without trailing blanks), the same characters apart from
//! blanks and line breaks, keeps every comment on a line with the same
//! neighbours, can be written back in the file's encoding, uses the file's
//! line ending, and formatting it again changes nothing.
//!
//! Layout: in the default style, the modules of controller backups change
//! on at most 2% of their lines, and only in their indentation (the layout
//! is the one the controller already keeps). Prints the figures for each
//! origin of modules.
//!
//! The corpus is read from `RAPID_CORPUS` or `../shared/corpus`; without it
//! the test prints one line and passes.

#![allow(clippy::print_stdout)]

use std::collections::BTreeMap;
use std::path::Path;
use std::time::{Duration, Instant};

use rapid_analyzer::format::{FormatOptions, Style, format};
use rapid_analyzer::text::{Decoded, LineEnding, decode};
use rapid_tests::layout::{LineChanges, Origin, line_changes, origin};
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

fn leaves<'a>(node: Node<'a>, out: &mut Vec<Node<'a>>) {
    let mut stack = vec![node];
    while let Some(node) = stack.pop() {
        if node.child_count() == 0 || node.kind() == "string" {
            out.push(node);
            continue;
        }
        let mut cursor = node.walk();
        let children: Vec<Node<'a>> = node.children(&mut cursor).collect();
        stack.extend(children.into_iter().rev());
    }
}

fn tokens(tree: &Tree, text: &str) -> Vec<Token> {
    let mut all = Vec::new();
    leaves(tree.root_node(), &mut all);
    all.into_iter()
        .map(|node| {
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
            Token {
                kind: node.kind().to_owned(),
                text: t,
            }
        })
        .collect()
}

/// For each comment: the token before it on its line (or none) — a
/// trailing comment stays trailing after the same token, an own-line comment
/// stays on its own line.
fn comment_places(tree: &Tree, text: &str) -> Vec<(String, Option<String>)> {
    let mut out = Vec::new();
    let mut prev: Option<(usize, String)> = None; // end byte, text of the last leaf
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

/// The characters of a text that are not blanks or line breaks (in upper
/// case for the styles that may change keyword case).
fn ink(text: &str, fold: bool) -> String {
    text.chars()
        .filter(|c| !matches!(c, ' ' | '\t' | '\r' | '\n'))
        .map(|c| if fold { c.to_ascii_uppercase() } else { c })
        .collect()
}

/// The kinds of line break in a text.
fn line_endings(text: &str) -> BTreeMap<&'static str, usize> {
    let mut out = BTreeMap::new();
    let bytes = text.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        let kind = match b {
            b'\n' if i > 0 && bytes[i - 1] == b'\r' => continue,
            b'\n' => "LF",
            b'\r' if bytes.get(i + 1) == Some(&b'\n') => "CRLF",
            b'\r' => "CR",
            _ => continue,
        };
        *out.entry(kind).or_default() += 1;
    }
    out
}

/// What the checks compare a result with, computed once per file.
struct Original<'a> {
    text: &'a str,
    bytes: &'a [u8],
    tokens: Vec<Token>,
    comments: Vec<(String, Option<String>)>,
    ink: String,
    ink_folded: String,
}

/// Every safety check of one formatting, as messages.
fn check(original: &Original<'_>, out: &str, options: &FormatOptions) -> Vec<String> {
    let mut failures = Vec::new();
    let out_tree = parse(out);
    if out_tree.root_node().has_error() {
        return vec!["the output does not parse".to_owned()];
    }
    if original.tokens != tokens(&out_tree, out) {
        failures.push("the tokens changed".to_owned());
    }
    let fold = options.style != Style::AsWritten;
    let ink_before = if fold {
        &original.ink_folded
    } else {
        &original.ink
    };
    if *ink_before != ink(out, fold) {
        failures.push("a character other than a blank was lost or added".to_owned());
    }
    if original.comments != comment_places(&out_tree, out) {
        failures.push("a comment moved".to_owned());
    }
    if let Decoded::Text { encoding, .. } = decode(original.bytes) {
        match encoding.encode(out) {
            Ok(encoded) => match decode(&encoded) {
                Decoded::Text {
                    text: back,
                    encoding: again,
                } if back == out && again == encoding => {}
                _ => failures.push("the output does not read back in its encoding".to_owned()),
            },
            Err(_) => failures.push("the output cannot be written in its encoding".to_owned()),
        }
    }
    let endings = line_endings(out);
    let dominant = match LineEnding::detect(original.text).as_str() {
        "\r\n" => "CRLF",
        "\r" => "CR",
        _ => "LF",
    };
    if endings.keys().any(|&k| k != dominant) {
        failures.push(format!("line endings {endings:?} in a {dominant} text"));
    }
    failures
}

/// Formatting a result again changes nothing.
fn stable(out: &str, options: &FormatOptions) -> Option<String> {
    match format(out, options) {
        Ok(again) if again == out => None,
        Ok(_) => Some("not idempotent".to_owned()),
        Err(e) => Some(format!("the output does not format: {e}")),
    }
}

/// What the files of one share of the corpus gave.
#[derive(Default)]
struct Tally {
    unchanged: usize,
    formatted: usize,
    skipped: usize,
    time: Duration,
    failures: Vec<String>,
    /// By origin: files, files changed, changed lines.
    figures: BTreeMap<Origin, (usize, usize, LineChanges)>,
}

impl Tally {
    fn add(&mut self, other: Tally) {
        self.unchanged += other.unchanged;
        self.formatted += other.formatted;
        self.skipped += other.skipped;
        self.time += other.time;
        self.failures.extend(other.failures);
        for (origin, (files, changed, lines)) in other.figures {
            let entry = self.figures.entry(origin).or_default();
            entry.0 += files;
            entry.1 += changed;
            entry.2.add(&lines);
        }
    }
}

/// Every style (the first is the default) and narrow settings, where far
/// more calls are wrapped.
fn styles() -> [FormatOptions; 4] {
    [
        FormatOptions::default(),
        FormatOptions {
            style: Style::Tight,
            ..FormatOptions::default()
        },
        FormatOptions {
            style: Style::Spaced,
            ..FormatOptions::default()
        },
        FormatOptions {
            style: Style::Spaced,
            indent_width: Some(2),
            line_width: Some(60),
        },
    ]
}

/// Formats one file in every style and checks each result.
fn one_file(path: &Path, bytes: &[u8], tally: &mut Tally) {
    let Decoded::Text { text, .. } = decode(bytes) else {
        tally.skipped += 1;
        return;
    };
    let tree = parse(&text);
    if tree.root_node().has_error() {
        tally.skipped += 1;
        if format(&text, &FormatOptions::default()).is_ok() {
            tally.failures.push(format!(
                "{}: a file with errors was formatted",
                path.display()
            ));
        }
        return;
    }
    let original = Original {
        text: &text,
        bytes,
        tokens: tokens(&tree, &text),
        comments: comment_places(&tree, &text),
        ink: ink(&text, false),
        ink_folded: ink(&text, true),
    };
    for (n, options) in styles().iter().enumerate() {
        let start = Instant::now();
        let result = format(&text, options);
        tally.time += start.elapsed();
        let out = match result {
            Ok(out) => out,
            Err(e) => {
                tally
                    .failures
                    .push(format!("{} ({options:?}): {e}", path.display()));
                continue;
            }
        };
        // the narrow settings only for stability (they differ from the
        // spaced style only where calls are wrapped)
        let mut problems = if options.line_width.is_some() {
            Vec::new()
        } else {
            check(&original, &out, options)
        };
        problems.extend(stable(&out, options));
        for failure in problems {
            tally
                .failures
                .push(format!("{} ({options:?}): {failure}", path.display()));
        }
        if n > 0 {
            continue;
        }
        if out == text {
            tally.unchanged += 1;
        } else {
            tally.formatted += 1;
        }
        let origin = origin(path, &text);
        let mut not_indentation = Vec::new();
        let changes = line_changes(&text, &out, |line, old, new, _| {
            if origin == Origin::Backup && new.is_none_or(|n| n.trim() != old.trim()) {
                not_indentation.push(format!(
                    "{}:{}: a backup's line changed other than in its indentation",
                    path.display(),
                    line + 1
                ));
            }
        });
        tally.failures.extend(not_indentation);
        let entry = tally.figures.entry(origin).or_default();
        entry.0 += 1;
        entry.1 += usize::from(out != text);
        entry.2.add(&changes);
    }
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn formatting_the_corpus_is_safe_stable_and_keeps_backups_as_they_are() {
    let Some(files) = rapid_tests::corpus_files() else {
        println!("format corpus test skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    // the files in shares, one thread each
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get().min(4));
    let mut tally = Tally::default();
    std::thread::scope(|scope| {
        let shares: Vec<_> = (0..threads)
            .map(|k| {
                let files = &files;
                scope.spawn(move || {
                    let mut tally = Tally::default();
                    for (path, bytes) in files.iter().skip(k).step_by(threads) {
                        one_file(path, bytes, &mut tally);
                    }
                    tally
                })
            })
            .collect();
        for share in shares {
            tally.add(share.join().expect("a share of the corpus"));
        }
    });
    tally.failures.sort();
    let Tally {
        unchanged,
        formatted,
        skipped,
        time,
        failures,
        figures,
    } = tally;
    println!(
        "format corpus: {} files: {formatted} changed by the default style, {unchanged} \
         unchanged, {skipped} skipped (syntax errors or not text); {} formattings took {:.3} s \
         ({threads} threads)",
        files.len(),
        styles().len(),
        time.as_secs_f64()
    );
    for (origin, (files, changed, c)) in &figures {
        println!(
            "  {}: {changed} of {files} files, {} of {} lines changed ({:.2}%): \
             indentation {}, blank lines and breaks {}, other {}",
            origin.name(),
            c.changed(),
            c.lines,
            100.0 * c.changed() as f64 / c.lines.max(1) as f64,
            c.indentation,
            c.structure,
            c.trailing + c.case + c.spacing
        );
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(formatted + unchanged > 0, "nothing was formatted");
    if let Some((_, _, backups)) = figures.get(&Origin::Backup) {
        assert!(
            backups.changed() * 50 <= backups.lines,
            "the default style changes {} of {} lines of controller backups (more than 2%)",
            backups.changed(),
            backups.lines
        );
    }
}
