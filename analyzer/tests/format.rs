//! Formatter fixtures: every `tests/format/NAME.in.mod` formats to
//! `tests/format/NAME.out.mod`, and the expected output is a fixed point.
//!
//! Options come from a first line `! fmt: indent-width=N line-width=N` of the
//! input (defaults otherwise). `UPDATE_EXPECT=1 cargo test -p rapid-analyzer
//! --test format` rewrites the expected files; review them in the diff.

use std::path::{Path, PathBuf};

use rapid_analyzer::format::{FormatOptions, format, verify};

fn options(input: &str) -> FormatOptions {
    let mut options = FormatOptions::default();
    let first = input.lines().next().unwrap_or_default();
    if let Some(settings) = first.trim().strip_prefix("! fmt:") {
        for setting in settings.split_whitespace() {
            let (key, value) = setting.split_once('=').expect("key=value");
            let value: usize = value.parse().expect("a number");
            match key {
                "indent-width" => options.indent_width = value,
                "line-width" => options.line_width = value,
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

/// The output does not depend on the blanks between tokens on a line: every
/// fixture, with the blanks between its tokens replaced at random (never
/// before a trailing comment, whose blanks are kept on purpose), formats to
/// the same text.
#[test]
fn blanks_between_tokens_do_not_matter() {
    let mut rng = Lcg(0x5eed);
    let mut parser = rapid_analyzer::syntax::parser();
    for input_path in fixtures() {
        let input = std::fs::read_to_string(&input_path).expect("readable input");
        let options = options(&input);
        let Ok(expected) = format(&input, &options) else {
            continue;
        };
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
        for round in 0..20 {
            let mut perturbed = String::new();
            let mut end = 0;
            for leaf in &leaves {
                let gap = &input[end..leaf.start_byte()];
                if end == 0 || gap.contains(['\n', '\r']) || leaf.kind() == "comment" {
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
}
