//! Formatter fixtures: every `tests/format/NAME.in.mod` formats to
//! `tests/format/NAME.out.mod`, and the expected output is a fixed point.
//!
//! Options come from a first line `! fmt: style=S indent-width=N
//! line-width=N` of the input (defaults otherwise). `UPDATE_EXPECT=1 cargo test -p rapid-analyzer
//! --test format` rewrites the expected files; review them in the diff.

use std::path::{Path, PathBuf};

use rapid_analyzer::format::{FormatError, FormatOptions, Style, format, verify};

fn options(input: &str) -> FormatOptions {
    let mut options = FormatOptions::default();
    let first = input.lines().next().unwrap_or_default();
    if let Some(settings) = first.trim().strip_prefix("! fmt:") {
        for setting in settings.split_whitespace() {
            let (key, value) = setting.split_once('=').expect("key=value");
            let number = || Some(value.parse::<usize>().expect("a number"));
            match key {
                "style" => options.style = Style::from_name(value).expect("a style"),
                "indent-width" => options.indent_width = number(),
                "line-width" => options.line_width = number(),
                other => panic!("unknown fixture setting {other}"),
            }
        }
    }
    options
}

fn fixtures() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/format");
    let mut inputs: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("the fixture folder")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.to_string_lossy().ends_with(".in.mod"))
        .collect();
    inputs.sort();
    inputs
}

#[test]
fn fixtures_format_to_their_expected_output() {
    let update = std::env::var_os("UPDATE_EXPECT").is_some();
    let inputs = fixtures();
    assert!(update || inputs.len() >= 10, "fixtures are missing");
    let mut failures = Vec::new();
    for input_path in inputs {
        let name = input_path.to_string_lossy().replace(".in.mod", "");
        let expected_path = PathBuf::from(format!("{name}.out.mod"));
        let input = std::fs::read_to_string(&input_path).expect("readable input");
        let options = options(&input);
        let got = match format(&input, &options) {
            Ok(got) => got,
            Err(e) => format!("ERROR {e}\n"),
        };
        if update {
            std::fs::write(&expected_path, &got).expect("writable expectation");
            continue;
        }
        let expected = std::fs::read_to_string(&expected_path).unwrap_or_default();
        if got != expected {
            failures.push(format!(
                "{}: got\n{got}\n--- expected\n{expected}",
                input_path.display()
            ));
            continue;
        }
        if !got.starts_with("ERROR") {
            let again = format(&got, &options).expect("the output formats");
            if again != got {
                failures.push(format!(
                    "{}: not idempotent:\n{again}",
                    input_path.display()
                ));
            }
            if let Err(e) = verify(&input, &got) {
                failures.push(format!("{}: {e}", input_path.display()));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

/// A small deterministic pseudo-random sequence (no dependency needed).
struct Lcg(u64);

impl Lcg {
    fn below(&mut self, n: u64) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 33) % n
    }
}

/// Node kinds that start lines of their own (statements, declarations,
/// clauses): a line whose first token starts none of them (and is no
/// comment and no closing keyword) continues the line before.
const LINE_KINDS: &[&str] = &[
    "module",
    "data_declaration",
    "record_declaration",
    "alias_declaration",
    "procedure_declaration",
    "function_declaration",
    "trap_declaration",
    "assignment",
    "procedure_call",
    "if_statement",
    "compact_if_statement",
    "for_statement",
    "while_statement",
    "test_statement",
    "label",
    "goto_statement",
    "return_statement",
    "raise_statement",
    "exit_statement",
    "retry_statement",
    "trynext_statement",
    "connect_statement",
    "elseif_clause",
    "else_clause",
    "test_case",
    "default_case",
    "error_handler",
    "backward_handler",
    "undo_handler",
    "record_component",
    "module_header",
    "header_entry",
];

/// In a `PERS` declaration after its name (those blanks are kept).
fn in_pers_value(leaf: tree_sitter::Node<'_>) -> bool {
    let mut n = leaf;
    while let Some(p) = n.parent() {
        if p.kind() == "data_declaration" {
            let pers = p
                .child_by_field_name("storage")
                .is_some_and(|s| s.kind() == "pers");
            let after_name = p
                .child_by_field_name("name")
                .is_some_and(|name| leaf.start_byte() >= name.end_byte());
            return pers && after_name;
        }
        n = p;
    }
    false
}

fn continues_a_line(leaf: tree_sitter::Node<'_>) -> bool {
    if leaf.kind() == "comment" || leaf.kind() == "%%%" {
        return false;
    }
    if !leaf.is_named() && leaf.kind().bytes().all(|b| b.is_ascii_alphabetic()) {
        return false;
    }
    let mut n = leaf;
    while let Some(p) = n.parent() {
        if p.start_byte() != leaf.start_byte() {
            break;
        }
        n = p;
        if LINE_KINDS.contains(&n.kind()) {
            return false;
        }
    }
    true
}

/// In the styles that set the blanks inside lines, the output does not
/// depend on them: every such fixture, with the blanks between its tokens
/// replaced at random, formats to the same text. Left alone: the blanks
/// before a trailing comment and in a `PERS` declaration after its name
/// (kept on purpose), and those on the lines of a
/// statement that goes over several lines (a continuation line keeps its
/// alignment under a token of the lines before, which depends on them).
#[test]
fn blanks_between_tokens_do_not_matter() {
    let mut rng = Lcg(0x5eed);
    let mut parser = rapid_analyzer::syntax::parser();
    let mut tried = 0;
    for input_path in fixtures() {
        let input = std::fs::read_to_string(&input_path).expect("readable input");
        let options = options(&input);
        if options.style == Style::AsWritten {
            continue;
        }
        let Ok(expected) = format(&input, &options) else {
            continue;
        };
        tried += 1;
        let tree = rapid_analyzer::syntax::parse(&mut parser, &input, None).expect("a tree");
        let mut leaves = Vec::new();
        let mut stack = vec![tree.root_node()];
        while let Some(node) = stack.pop() {
            if node.child_count() == 0 || node.kind() == "string" {
                leaves.push(node);
            } else {
                let mut cursor = node.walk();
                let children: Vec<_> = node.children(&mut cursor).collect();
                stack.extend(children.into_iter().rev());
            }
        }
        if leaves.iter().any(|l| l.kind() == "trailing_text") {
            continue;
        }
        // rows that are part of a statement over several lines
        let mut multi_line = std::collections::HashSet::new();
        let mut previous_row = None;
        for leaf in &leaves {
            let row = leaf.start_position().row;
            if previous_row != Some(row) && continues_a_line(*leaf) {
                multi_line.insert(row);
                multi_line.insert(previous_row.unwrap_or(row));
            }
            previous_row = Some(row);
        }
        for round in 0..20 {
            let mut perturbed = String::new();
            let mut end = 0;
            for leaf in &leaves {
                let gap = &input[end..leaf.start_byte()];
                if end == 0
                    || gap.contains(['\n', '\r'])
                    || leaf.kind() == "comment"
                    || multi_line.contains(&leaf.start_position().row)
                    || in_pers_value(*leaf)
                {
                    perturbed.push_str(gap);
                } else {
                    let n = rng.below(4) as usize + usize::from(!gap.is_empty());
                    for _ in 0..n {
                        perturbed.push(if rng.below(3) == 0 { '\t' } else { ' ' });
                    }
                }
                perturbed.push_str(&input[leaf.byte_range()]);
                end = leaf.end_byte();
            }
            perturbed.push_str(&input[end..]);
            let got = format(&perturbed, &options).expect("the perturbed input formats");
            assert_eq!(
                got,
                expected,
                "{} (round {round}), input:\n{perturbed}",
                input_path.display()
            );
        }
    }
    assert!(tried >= 5, "too few fixtures in the styles that set blanks");
}

/// Generated code can nest deeper than anything the formatter lays out:
/// 100,000 nested expressions, statements, calls, indexes or aggregates are
/// left as they are with a message, in every style, without exhausting the
/// stack (the test threads' stacks are the default 2 MiB).
#[test]
fn very_deep_nesting_is_left_alone_with_a_message() {
    let n = 100_000;
    let wrap = |open: &str, close: &str| format!("{}1{}", open.repeat(n), close.repeat(n));
    let statement = |s: String| format!("MODULE M\nPROC p()\n{s}\nENDPROC\nENDMODULE\n");
    let cases = [
        (
            "expressions",
            statement(format!("x := {};", wrap("(", ")"))),
        ),
        ("calls", statement(format!("x := {};", wrap("Abs(", ")")))),
        ("indexes", statement(format!("x := {};", wrap("a{", "}")))),
        ("aggregates", statement(format!("x := {};", wrap("[", "]")))),
        (
            "statements",
            statement(format!(
                "{}x := 1;\n{}",
                "IF a THEN\n".repeat(n),
                "ENDIF\n".repeat(n)
            )),
        ),
    ];
    for (what, text) in cases {
        for style in [Style::AsWritten, Style::Tight, Style::Spaced] {
            let options = FormatOptions {
                style,
                ..FormatOptions::default()
            };
            match format(&text, &options) {
                Err(e) => assert!(matches!(e, FormatError::Unsupported { .. }), "{what}: {e}"),
                Ok(_) => panic!("{what}: formatted"),
            }
        }
    }
}
