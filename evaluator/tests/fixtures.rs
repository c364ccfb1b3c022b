//! Data-driven tests: every `fixtures/*.txt` file holds lines of
//!
//! ```text
//! <RAPID expression> [:: <expected type>] => <printed value or error code>
//! ```
//!
//! plus RAPID declarations (`CONST robtarget p := [...];`, `RECORD ...`) that
//! build up the file's environment, and `@initial-values on|off`. The
//! expected text is what `Value`'s `Display` prints (RAPID's `ValToStr`
//! form), optionally followed by ` (initial value of a, b)`, or the
//! `ErrorCode::name()` of the expected error (`ERR_DIVZERO`).

mod support;

use std::fmt::Write as _;

use rapid_evaluator::{MapEnv, Options, eval_with};

fn run_file(name: &str, text: &str, failures: &mut String) -> usize {
    let mut env = MapEnv::new();
    let mut options = Options::default();
    let mut rows = 0;
    for (n, raw) in text.lines().enumerate() {
        let line = raw.trim();
        let at = format!("{name}:{}", n + 1);
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Some(rest) = line.strip_prefix("@initial-values ") {
            options.allow_initial_values = rest.trim() == "on";
            continue;
        }
        let first = line
            .split_whitespace()
            .next()
            .unwrap_or("")
            .to_ascii_uppercase();
        if ["CONST", "VAR", "PERS", "RECORD", "ALIAS"].contains(&first.as_str()) {
            if let Err(e) = support::declare(&mut env, line) {
                let _ = writeln!(failures, "{at}: bad declaration: {e}");
            }
            continue;
        }
        let Some((lhs, expected)) = line.rsplit_once(" => ") else {
            let _ = writeln!(failures, "{at}: no ` => ` in `{line}`");
            continue;
        };
        let (src, ty) = match lhs.split_once(" :: ") {
            Some((e, t)) => (e, Some(t)),
            None => (lhs, None),
        };
        let expr = match support::parse_expr(src) {
            Ok(e) => e,
            Err(e) => {
                let _ = writeln!(failures, "{at}: cannot read `{src}`: {e}");
                continue;
            }
        };
        let ty = match ty.map(support::parse_type).transpose() {
            Ok(t) => t,
            Err(e) => {
                let _ = writeln!(failures, "{at}: bad type: {e}");
                continue;
            }
        };
        rows += 1;
        let got = match eval_with(&expr, ty.as_ref(), &env, &options) {
            Ok(ev) if ev.initial_values_used.is_empty() => ev.value.to_string(),
            Ok(ev) => format!(
                "{} (initial value of {})",
                ev.value,
                ev.initial_values_used.join(", ")
            ),
            Err(e) => {
                if e.message.trim().is_empty() {
                    let _ = writeln!(failures, "{at}: error without a message");
                }
                e.code.name().to_string()
            }
        };
        if got != expected.trim() {
            let _ = writeln!(
                failures,
                "{at}: `{src}`\n    expected: {}\n    got:      {got}",
                expected.trim()
            );
        }
    }
    rows
}

#[test]
fn fixtures() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("fixture dir")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "txt"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no fixture files");
    let mut failures = String::new();
    let mut total = 0;
    for f in &files {
        let text = std::fs::read_to_string(f).expect("read fixture");
        let name = f.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        let rows = run_file(name, &text, &mut failures);
        assert!(rows > 0, "{name} has no rows");
        total += rows;
    }
    assert!(failures.is_empty(), "{total} rows, failures:\n{failures}");
}
