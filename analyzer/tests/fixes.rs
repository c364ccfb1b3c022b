//! Fix fixtures: each `tests/fixes/<rule-name>[_case].mod` is analysed as a
//! task of one module; the first diagnostic of that rule that carries a fix
//! must announce the fix its first line describes, and applying the fix must
//! give exactly `<same name>.fixed`.
//!
//! The first line reads `! fix: <safe|unsafe>, <preferred|->: <title>`.
//! `RAPID_BLESS=1` writes the `.fixed` files from what the fixes give (review
//! them like code).

use std::path::{Path, PathBuf};

use rapid_analyzer::diagnostic::Fix;
use rapid_analyzer::workspace::Workspace;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixes")
}

/// How the fix describes itself, in the first line's words.
fn describe(fix: &Fix) -> String {
    format!(
        "! fix: {}, {}: {}",
        if fix.is_safe() { "safe" } else { "unsafe" },
        if fix.preferred { "preferred" } else { "-" },
        fix.title
    )
}

/// The text with `fix` applied.
fn apply(text: &str, fix: &Fix) -> String {
    let mut out = text.to_owned();
    let mut edits = fix.edits.clone();
    edits.sort_by_key(|e| std::cmp::Reverse(e.range.start));
    for e in edits {
        out.replace_range(e.range, &e.replacement);
    }
    out
}

/// The problem with one fixture, if any.
fn check(path: &Path) -> Option<String> {
    let name = path.file_name()?.to_string_lossy().into_owned();
    let rule = name.split(['_', '.']).next()?.to_owned();
    let text = std::fs::read_to_string(path).ok()?;
    let mut ws = Workspace::new();
    ws.set_file(&name, text.clone());
    let diags = ws.diagnostics(&name);
    let Some(fix) = diags
        .iter()
        .filter(|d| d.rule.name == rule)
        .find_map(|d| d.fix.as_ref())
    else {
        return Some(format!(
            "{name}: no [{rule}] diagnostic with a fix in {diags:#?}"
        ));
    };
    let header = text.lines().next().unwrap_or_default();
    if describe(fix) != header {
        return Some(format!(
            "{name}: the fix is\n  {}\nnot\n  {header}",
            describe(fix)
        ));
    }
    let fixed = apply(&text, fix);
    let expected_path = path.with_extension("fixed");
    if std::env::var_os("RAPID_BLESS").is_some() {
        std::fs::write(&expected_path, &fixed).ok()?;
        return None;
    }
    let expected = std::fs::read_to_string(&expected_path).unwrap_or_default();
    (fixed != expected).then(|| {
        format!(
            "{name}: fixed text differs from its .fixed file:\n{fixed}\n-- expected --\n{expected}"
        )
    })
}

#[test]
fn every_fix_gives_its_fixed_text() {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(root())
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    paths.retain(|p| p.extension().is_some_and(|e| e == "mod"));
    paths.sort();
    assert!(paths.len() >= 10, "fixtures are missing: {paths:?}");
    let failures: Vec<String> = paths.iter().filter_map(|p| check(p)).collect();
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn every_rule_that_builds_a_fix_has_a_fixture() {
    let list = |dir: PathBuf| -> Vec<String> {
        std::fs::read_dir(dir)
            .map(|d| {
                d.filter_map(|e| e.ok())
                    .map(|e| e.file_name().to_string_lossy().into_owned())
                    .collect()
            })
            .unwrap_or_default()
    };
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/rules");
    let fixtures = list(root());
    let mut builders = 0;
    for file in list(src.clone()) {
        let text = std::fs::read_to_string(src.join(&file)).unwrap_or_default();
        if !text.contains("-> Fix") && !text.contains("-> Option<Fix>") {
            continue;
        }
        builders += 1;
        let rule = file.trim_end_matches(".rs").replace('_', "-");
        assert!(
            fixtures.iter().any(|n| n.starts_with(&rule)),
            "rules/{file} builds a fix but tests/fixes has no {rule}*.mod"
        );
    }
    assert!(builders >= 5, "{builders} fix builders found");
}
