//! The reports of `rapid test`: human, JSON and JUnit XML.

use std::io::{self, Write};

use serde_json::json;

use super::{TestResult, Verdict};

fn counts(results: &[TestResult]) -> (usize, usize, usize) {
    let n = |v: Verdict| results.iter().filter(|r| r.verdict == v).count();
    (n(Verdict::Pass), n(Verdict::Fail), n(Verdict::Error))
}

fn label(v: Verdict) -> &'static str {
    match v {
        Verdict::Pass => "pass",
        Verdict::Fail => "fail",
        Verdict::Error => "error",
    }
}

/// A line per test; for a failure or an error, its message, where it
/// happened and the test's output; a summary.
pub fn human(out: &mut impl Write, results: &[TestResult]) -> io::Result<()> {
    for r in results {
        let head = match r.verdict {
            Verdict::Pass => "PASS ",
            Verdict::Fail => "FAIL ",
            Verdict::Error => "ERROR",
        };
        writeln!(
            out,
            "{head} {}.{} ({:.1} ms)",
            r.module,
            r.name,
            r.duration.as_secs_f64() * 1000.0
        )?;
        if r.verdict == Verdict::Pass {
            continue;
        }
        writeln!(out, "      {}", r.message)?;
        if let Some(at) = &r.failed_at {
            writeln!(out, "      --> {}:{}:{}", at.path, at.line, at.column)?;
        }
        if !r.output.is_empty() {
            writeln!(out, "      output:")?;
            for l in &r.output {
                writeln!(out, "        {l}")?;
            }
        }
    }
    let (pass, fail, error) = counts(results);
    if results.is_empty() {
        writeln!(
            out,
            "no tests found (procedures named test_..., or in modules whose name ends with _test)"
        )
    } else {
        let plural = |n: usize, word: &str| {
            if n == 1 {
                format!("{n} {word}")
            } else {
                format!("{n} {word}s")
            }
        };
        writeln!(
            out,
            "\n{}: {pass} passed, {fail} failed, {}",
            plural(results.len(), "test"),
            plural(error, "error")
        )
    }
}

/// `{"tests": [...], "passed", "failed", "errors"}`.
pub fn json(out: &mut impl Write, results: &[TestResult]) -> io::Result<()> {
    let tests: Vec<serde_json::Value> = results
        .iter()
        .map(|r| {
            json!({
                "module": r.module,
                "name": r.name,
                "file": r.at.path,
                "line": r.at.line,
                "result": label(r.verdict),
                "message": (r.verdict != Verdict::Pass).then_some(&r.message),
                "errno": r.outcome.errno.as_ref().map(|(n, name)| json!({"number": n, "name": name})),
                "at": r.failed_at.as_ref().map(|l| json!({"file": l.path, "line": l.line, "column": l.column})),
                "output": r.output,
                "ms": (r.duration.as_secs_f64() * 1e6).round() / 1e3,
            })
        })
        .collect();
    let (pass, fail, error) = counts(results);
    let doc = json!({ "tests": tests, "passed": pass, "failed": fail, "errors": error });
    writeln!(out, "{doc}")
}

/// Text for XML attributes and content (characters XML 1.0 forbids
/// become U+FFFD).
fn xml(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        let entity = match c {
            '&' => "&amp;",
            '<' => "&lt;",
            '>' => "&gt;",
            '"' => "&quot;",
            '\n' => "&#10;",
            '\t' | '\r' => {
                out.push(c);
                continue;
            }
            c if u32::from(c) < 0x20 || matches!(c, '\u{FFFE}' | '\u{FFFF}') => "\u{FFFD}",
            c => {
                out.push(c);
                continue;
            }
        };
        out.push_str(entity);
    }
    out
}

/// JUnit XML: a test suite per module, a test case per test; failures and
/// errors with their message and place, the output as `system-out`.
pub fn junit(out: &mut impl Write, results: &[TestResult]) -> io::Result<()> {
    let (_, fail, error) = counts(results);
    writeln!(out, r#"<?xml version="1.0" encoding="UTF-8"?>"#)?;
    writeln!(
        out,
        r#"<testsuites name="rapid test" tests="{}" failures="{fail}" errors="{error}">"#,
        results.len()
    )?;
    let mut modules: Vec<&str> = Vec::new();
    for r in results {
        if !modules.contains(&r.module.as_str()) {
            modules.push(&r.module);
        }
    }
    for module in modules {
        let of: Vec<&TestResult> = results.iter().filter(|r| r.module == module).collect();
        let n = |v: Verdict| of.iter().filter(|r| r.verdict == v).count();
        let time: f64 = of.iter().map(|r| r.duration.as_secs_f64()).sum();
        writeln!(
            out,
            r#"  <testsuite name="{}" tests="{}" failures="{}" errors="{}" time="{time:.3}">"#,
            xml(module),
            of.len(),
            n(Verdict::Fail),
            n(Verdict::Error)
        )?;
        for r in of {
            write!(
                out,
                r#"    <testcase name="{}" classname="{}" file="{}" line="{}" time="{:.3}""#,
                xml(&r.name),
                xml(module),
                xml(&r.at.path),
                r.at.line,
                r.duration.as_secs_f64()
            )?;
            if r.verdict == Verdict::Pass && r.output.is_empty() {
                writeln!(out, "/>")?;
                continue;
            }
            writeln!(out, ">")?;
            if r.verdict != Verdict::Pass {
                let tag = if r.verdict == Verdict::Fail {
                    "failure"
                } else {
                    "error"
                };
                let kind = r
                    .outcome
                    .errno
                    .as_ref()
                    .map_or(label(r.verdict), |(_, n)| n.as_str());
                let place = r
                    .failed_at
                    .as_ref()
                    .map(|l| format!("{}:{}", l.path, l.line))
                    .unwrap_or_default();
                writeln!(
                    out,
                    r#"      <{tag} message="{}" type="{}">{}</{tag}>"#,
                    xml(&r.message),
                    xml(kind),
                    xml(&place)
                )?;
            }
            if !r.output.is_empty() {
                writeln!(
                    out,
                    "      <system-out>{}</system-out>",
                    xml(&(r.output.join("\n") + "\n"))
                )?;
            }
            writeln!(out, "    </testcase>")?;
        }
        writeln!(out, "  </testsuite>")?;
    }
    writeln!(out, "</testsuites>")
}
