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
