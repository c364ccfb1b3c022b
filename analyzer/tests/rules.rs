//! Rule fixtures: every file or folder under `tests/fixtures/<rule-name>/`
//! is analysed with a [`Workspace`], and the diagnostics found must be
//! exactly those its comments expect.
//!
//! A fixture is a `.mod`/`.sys` file (a task of one module), or a folder (a
//! task of several modules, or a backup with `RAPID/TASKn` folders; `.cfg`
//! files in it are configuration, `.pgf` files program lists). Expectations
//! are trailing comments on the offending line:
//!
//! ```text
//! n := "ten";  ! error: [type-mismatch]
//! x := 1;      ! warning: [unused-data] error: [type-mismatch]
//! ! ^ error: [type-mismatch]      (applies to the line above)
//! ```
//!
//! Every rule of `RULES` needs a fixture that expects it and a fixture whose
//! name contains `pass` in its folder that is clean of it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use rapid_analyzer::rules::RULES;
use rapid_analyzer::text::LineIndex;
use rapid_analyzer::workspace::Workspace;

/// (file, 1-based line, severity, rule name)
type Finding = (String, usize, String, String);

struct Fixture {
    /// Path relative to the fixtures folder: `rule-name/file.mod` or
    /// `rule-name/folder`.
    name: String,
    /// Files: (workspace path, text).
    files: Vec<(String, String)>,
}

impl Fixture {
    /// A workspace of the fixture's files: configurations, program files
    /// and modules.
    fn workspace(&self) -> Workspace {
        let mut ws = Workspace::new();
        for (path, text) in &self.files {
            let lower = path.to_ascii_lowercase();
            if lower.ends_with(".cfg") || rapid_analyzer::controller::is_controller_info_name(path)
            {
                ws.set_config(path, text);
            } else if lower.ends_with(".pgf") {
                ws.set_program(path, text);
            } else if is_module(Path::new(path)) {
                ws.set_file(path, text.clone());
            }
        }
        ws
    }
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures")
}

fn is_module(path: &Path) -> bool {
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    rapid_analyzer::text::is_rapid_file_name(&name)
}

fn read_tree(dir: &Path, base: &Path, out: &mut Vec<(String, String)>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("a fixture folder")
        .map(|e| e.expect("an entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            read_tree(&path, base, out);
        } else {
            let rel = path
                .strip_prefix(base)
                .expect("below the root")
                .to_string_lossy()
                .replace('\\', "/");
            let text = std::fs::read_to_string(&path).expect("UTF-8 fixture");
            out.push((rel, text));
        }
    }
}

fn fixtures() -> Vec<Fixture> {
    let base = root();
    let mut groups: Vec<PathBuf> = std::fs::read_dir(&base)
        .expect("tests/fixtures")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.is_dir())
        .collect();
    groups.sort();
    let mut out = Vec::new();
    for group in groups {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(&group)
            .expect("a rule folder")
            .map(|e| e.expect("an entry").path())
            .collect();
        entries.sort();
        for entry in entries {
            let name = entry
                .strip_prefix(&base)
                .expect("below the root")
                .to_string_lossy()
                .replace('\\', "/");
            let mut files = Vec::new();
            if entry.is_dir() {
                read_tree(&entry, &base, &mut files);
            } else if is_module(&entry) {
                read_tree_file(&entry, &base, &mut files);
            } else {
                continue;
            }
            out.push(Fixture { name, files });
        }
    }
    out
}

fn read_tree_file(path: &Path, base: &Path, out: &mut Vec<(String, String)>) {
    let rel = path
        .strip_prefix(base)
        .expect("below the root")
        .to_string_lossy()
        .replace('\\', "/");
    out.push((rel, std::fs::read_to_string(path).expect("UTF-8 fixture")));
}

/// The expectations written in a file's comments.
fn expected_in(file: &str, text: &str) -> BTreeSet<Finding> {
    let mut out = BTreeSet::new();
    for (i, line) in text.lines().enumerate() {
        let Some(at) = ["! error:", "! warning:", "! info:", "! hint:", "! ^"]
            .iter()
            .filter_map(|m| line.find(m))
            .min()
        else {
            continue;
        };
        let mut rest = &line[at + 1..];
        let mut line_no = i + 1;
        if let Some(r) = rest.trim_start().strip_prefix('^') {
            rest = r;
            line_no -= 1;
        }
        let mut severity = String::new();
        for word in rest.split_whitespace() {
            if let Some(sev) = word.strip_suffix(':') {
                assert!(
                    Severity::parse(sev).is_some(),
                    "{file}:{}: unknown severity {sev}",
                    i + 1
                );
                severity = sev.to_owned();
            } else if let Some(rule) = word.strip_prefix('[').and_then(|w| w.strip_suffix(']')) {
                assert!(
                    rapid_analyzer::rules::find(rule).is_some_and(|r| r.name == rule),
                    "{file}:{}: no rule named {rule}",
                    i + 1
                );
                assert!(!severity.is_empty(), "{file}:{}: severity first", i + 1);
                out.insert((file.to_owned(), line_no, severity.clone(), rule.to_owned()));
            } else {
                break;
            }
        }
    }
    out
}

/// Runs a fixture: (findings, rendered diagnostics by finding).
fn run(fixture: &Fixture) -> (BTreeSet<Finding>, BTreeMap<Finding, String>) {
    let mut ws = fixture.workspace();
    let mut found = BTreeSet::new();
    let mut rendered = BTreeMap::new();
    for (path, text) in &fixture.files {
        if !is_module(Path::new(path)) {
            continue;
        }
        let index = LineIndex::new(text);
        for d in ws.diagnostics(path).iter() {
            let (line, _) = index.human(d.range.start, text);
            let f = (
                path.clone(),
                line,
                d.severity.as_str().to_owned(),
                d.rule.name.to_owned(),
            );
            rendered.insert(f.clone(), render(path, text, &index, d, &fixture.files));
            found.insert(f);
        }
    }
    (found, rendered)
}

/// A diagnostic as `file:line:col: severity[code name]: message`, with its
/// fix and its related locations (in their own files, found in `files`).
fn render(
    path: &str,
    text: &str,
    index: &LineIndex,
    d: &Diagnostic,
    files: &[(String, String)],
) -> String {
    let (line, col) = index.human(d.range.start, text);
    let mut s = format!(
        "{path}:{line}:{col}: {}[{} {}]: {}",
        d.severity.as_str(),
        d.rule.code,
        d.rule.name,
        d.message
    );
    if let Some(fix) = &d.fix {
        s.push_str(&format!(
            "\n    fix{}{}: {}",
            if fix.is_safe() { " (safe)" } else { "" },
            if fix.preferred { " (preferred)" } else { "" },
            fix.title
        ));
        for e in &fix.edits {
            s.push_str(&format!(
                "\n      {:?} -> {:?}",
                text.get(e.range.clone()).unwrap_or_default(),
                e.replacement
            ));
        }
    }
    for r in &d.related {
        let file = r.file.as_deref().unwrap_or(path);
        let (l, c) = match files.iter().find(|(p, _)| p == file) {
            Some((_, other)) if file != path => LineIndex::new(other).human(r.range.start, other),
            _ => index.human(r.range.start, text),
        };
        s.push_str(&format!("\n    {file}:{l}:{c}: {}", r.message));
    }
    s
}

#[test]
fn fixtures_report_exactly_what_they_expect() {
    let all = fixtures();
    assert!(all.len() >= RULES.len(), "fixtures are missing");
    let mut failures = Vec::new();
    for fixture in &all {
        let expected: BTreeSet<Finding> = fixture
            .files
            .iter()
            .flat_map(|(p, t)| expected_in(p, t))
            .collect();
        let (found, rendered) = run(fixture);
        if expected != found {
            let mut msg = format!("== {}", fixture.name);
            for f in expected.difference(&found) {
                msg.push_str(&format!(
                    "\n  missing    {}:{} {}: [{}]",
                    f.0, f.1, f.2, f.3
                ));
            }
            for f in found.difference(&expected) {
                msg.push_str(&format!(
                    "\n  unexpected {}",
                    rendered.get(f).map_or("", String::as_str)
                ));
            }
            failures.push(msg);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_rule_has_a_failing_and_a_passing_fixture() {
    let all = fixtures();
    let mut problems = Vec::new();
    for rule in RULES {
        let in_folder: Vec<&Fixture> = all
            .iter()
            .filter(|f| f.name.split('/').next() == Some(rule.name))
            .collect();
        let expects = all.iter().any(|f| {
            f.files
                .iter()
                .any(|(p, t)| expected_in(p, t).iter().any(|e| e.3 == rule.name))
        });
        if !expects {
            problems.push(format!(
                "{} {}: no fixture expects it",
                rule.code, rule.name
            ));
        }
        let passes = in_folder.iter().any(|f| {
            f.name
                .rsplit('/')
                .next()
                .is_some_and(|n| n.contains("pass"))
                && !f
                    .files
                    .iter()
                    .any(|(p, t)| expected_in(p, t).iter().any(|e| e.3 == rule.name))
        });
        if !passes {
            problems.push(format!(
                "{} {}: no fixtures/{}/*pass* clean of it",
                rule.code, rule.name, rule.name
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Rendered messages of a few fixtures, reviewed like code.
#[test]
fn rendered_messages() {
    let all = fixtures();
    for name in [
        "type-mismatch/fail.mod",
        "argument-count/fail.mod",
        "equals-for-assignment/fail.mod",
        "missing-return/fail.mod",
        "unused-data/fail.mod",
        "ambiguous-global/fail",
        "ambiguous-global/folder_pairs",
        "unresolved-name/fail_repeated.mod",
        "unresolved-name/fail_suggestions.mod",
        "duplicate-module/fail_backup",
    ] {
        let fixture = all
            .iter()
            .find(|f| f.name == name)
            .unwrap_or_else(|| panic!("fixture {name}"));
        let (_, rendered) = run(fixture);
        let text: Vec<&str> = rendered.values().map(String::as_str).collect();
        insta::assert_snapshot!(name.replace(['/', '.'], "_"), text.join("\n"));
    }
}

/// `RAPID_FIXTURE=path cargo test --test rules show -- --nocapture` prints
/// what a fixture reports, for writing expectations.
#[test]
fn show() {
    let Some(want) = std::env::var_os("RAPID_FIXTURE") else {
        return;
    };
    let want = want.to_string_lossy().into_owned();
    for f in fixtures().iter().filter(|f| f.name.contains(&want)) {
        let (_, rendered) = run(f);
        eprintln!("== {}", f.name);
        for r in rendered.values() {
            eprintln!("{r}");
        }
    }
}

/// The statement cache never changes a result: after an edit (a blank line
/// inserted before each line of a routine in turn), the workspace's cached
/// re-check equals a fresh check of the edited text.
#[test]
fn cached_rechecks_equal_fresh_checks() {
    let mut compared = 0;
    for fixture in fixtures() {
        let mut ws = fixture.workspace();
        for (path, text) in &fixture.files {
            if !is_module(Path::new(path)) {
                continue;
            }
            ws.diagnostics(path);
            let starts: Vec<usize> = text
                .match_indices('\n')
                .map(|(i, _)| i + 1)
                .filter(|&i| i < text.len())
                .collect();
            for (k, at) in starts.iter().enumerate().step_by(3) {
                let mut edited = text.clone();
                edited.insert_str(*at, if k % 2 == 0 { "\n" } else { "  " });
                ws.set_file(path, edited.clone());
                let cached = ws.diagnostics(path);
                let task = ws.task_of(path);
                let unit = ws.unit(path).expect("the file").clone();
                let fresh = rapid_analyzer::workspace::diagnostics_of(&task, &unit);
                assert_eq!(*cached, fresh, "{path} edited at byte {at}");
                compared += 1;
            }
            ws.set_file(path, text.clone());
        }
    }
    assert!(compared > 100, "only {compared} comparisons");
}

/// Switching rules off in the checker equals filtering its findings
/// afterwards: on every fixture, for each rule it reports, checking without
/// that rule gives every other finding, and checking only that rule gives
/// exactly its findings; a statement cache made with every rule on does
/// not leak a switched-off rule's findings.
#[test]
fn a_selection_checks_what_filtering_afterwards_keeps() {
    use rapid_analyzer::check::StmtCache;
    use rapid_analyzer::rules::Selection;
    use rapid_analyzer::workspace::{diagnostics_cached, diagnostics_selected};
    let key = |d: &Diagnostic| (d.rule.code, d.range.clone(), d.message.clone());
    let mut compared = 0;
    for fixture in fixtures() {
        let mut ws = fixture.workspace();
        for (path, _) in &fixture.files {
            if !is_module(Path::new(path)) {
                continue;
            }
            let task = ws.task_of(path);
            let unit = ws.unit(path).expect("the file").clone();
            let (all, mut cache) = diagnostics_cached(&task, &unit, StmtCache::default());
            let codes: BTreeSet<&str> = all
                .iter()
                .filter(|d| !unit.syntax.contains(d))
                .map(|d| d.rule.code)
                .collect();
            for code in codes {
                let keys = |ds: &[Diagnostic], keep: &dyn Fn(&str) -> bool| -> Vec<_> {
                    ds.iter().filter(|d| keep(d.rule.code)).map(key).collect()
                };
                let without = Selection::of(|r| r.code != code);
                // The cache of the check before (another selection).
                let (found, next) = diagnostics_selected(&task, &unit, cache, &without);
                cache = next;
                assert_eq!(
                    keys(&found, &|_| true),
                    keys(&all, &|c| c != code),
                    "{path} without {code}"
                );
                let only = Selection::of(|r| r.code == code);
                let (found, _) = diagnostics_selected(&task, &unit, StmtCache::default(), &only);
                let syntax: Vec<_> = unit.syntax.iter().map(key).collect();
                let found: Vec<_> = keys(&found, &|_| true)
                    .into_iter()
                    .filter(|k| !syntax.contains(k))
                    .collect();
                assert_eq!(found, keys(&all, &|c| c == code), "{path} only {code}");
                compared += 1;
            }
        }
    }
    assert!(compared > 50, "only {compared} comparisons");
}

/// The position of a byte offset, for tree-sitter.
fn point_at(text: &str, at: usize) -> tree_sitter::Point {
    let before = &text[..at];
    tree_sitter::Point {
        row: before.matches('\n').count(),
        column: at - before.rfind('\n').map_or(0, |i| i + 1),
    }
}

/// Replaces `path`'s text as an editor does: the old tree edited, then an
/// incremental parse.
fn edit_file(ws: &mut Workspace, path: &str, new: String) {
    let unit = ws.unit(path).expect("the file").clone();
    let old = &unit.text;
    let prefix = old
        .bytes()
        .zip(new.bytes())
        .take_while(|(a, b)| a == b)
        .count();
    let suffix = old
        .bytes()
        .rev()
        .zip(new.bytes().rev())
        .take_while(|(a, b)| a == b)
        .count()
        .min(old.len().min(new.len()) - prefix);
    // On character boundaries of both texts.
    let mut start = prefix;
    while !old.is_char_boundary(start) || !new.is_char_boundary(start) {
        start -= 1;
    }
    let (mut old_end, mut new_end) = (old.len() - suffix, new.len() - suffix);
    while !old.is_char_boundary(old_end) || !new.is_char_boundary(new_end) {
        old_end += 1;
        new_end += 1;
    }
    let mut tree = unit.tree().clone();
    tree.edit(&tree_sitter::InputEdit {
        start_byte: start,
        old_end_byte: old_end,
        new_end_byte: new_end,
        start_position: point_at(old, start),
        old_end_position: point_at(old, old_end),
        new_end_position: point_at(&new, new_end),
    });
    ws.set_unit(rapid_analyzer::task::Unit::new(
        path.to_owned(),
        new,
        Some(&tree),
    ));
}

/// One edit of a kind the statement cache must survive, at line `line`
/// (taken modulo the line count): a character typed at the start of the line,
/// the line deleted, the line doubled (a statement added), a label and a
/// GOTO, a data type changed (`num` to `bool`, first after the line), a
/// character inside a string and inside a comment, a line break (the line
/// count changes), blanks.
fn edit_of_kind(text: &str, kind: usize, line: usize) -> Option<String> {
    let starts: Vec<usize> = std::iter::once(0)
        .chain(text.match_indices('\n').map(|(i, _)| i + 1))
        .filter(|&i| i < text.len())
        .collect();
    let at = *starts.get(line % starts.len().max(1))?;
    let end = text[at..].find('\n').map_or(text.len(), |i| at + i + 1);
    let mut new = text.to_owned();
    match kind % 10 {
        0 => new.insert(at, 'x'),
        1 => new.replace_range(at..end, ""),
        2 => new.insert_str(at, &text[at..end]),
        3 => new.insert_str(at, "lbl1:\n"),
        4 => new.insert_str(at, "GOTO lbl1;\n"),
        5 => {
            let i = at + text[at..].find("num")?;
            new.replace_range(i..i + 3, "bool");
        }
        6 => {
            let i = at + text[at..].find('"')?;
            new.insert(i + 1, 'q');
        }
        7 => {
            let i = at + text[at..].find('!')?;
            new.insert_str(i + 1, " x:");
        }
        8 => new.insert(at, '\n'),
        _ => new.insert_str(at, "  "),
    }
    Some(new)
}

/// Edits of every kind the statement cache special-cases, chained (each on
/// the result of the previous ones), in every module of a fixture in turn,
/// parsed incrementally: after each, every module's cached re-check equals a
/// fresh check.
#[test]
fn chained_edits_recheck_like_fresh_checks() {
    let mut compared = 0;
    for fixture in fixtures() {
        let mut ws = fixture.workspace();
        let modules: Vec<String> = fixture
            .files
            .iter()
            .map(|(path, _)| path)
            .filter(|path| is_module(Path::new(path)))
            .cloned()
            .collect();
        if modules.is_empty() {
            continue;
        }
        for path in &modules {
            ws.diagnostics(path);
        }
        for step in 0..40 {
            let path = &modules[step % modules.len()];
            let text = ws.unit(path).expect("the file").text.clone();
            let Some(new) = edit_of_kind(&text, step, step * 7 + step / 10) else {
                continue;
            };
            edit_file(&mut ws, path, new);
            for p in &modules {
                let cached = ws.diagnostics(p);
                let task = ws.task_of(p);
                let unit = ws.unit(p).expect("the file").clone();
                let fresh = rapid_analyzer::workspace::diagnostics_of(&task, &unit);
                assert_eq!(
                    *cached,
                    fresh,
                    "{p} after edit {step} (kind {}) of {path}",
                    step % 10
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 500, "only {compared} comparisons");
}

/// `check::move_reaches` (what `rapid diff` says of a moved target's
/// reach) is the motion check's own answer: on the fixtures of its three
/// rules, every move it finds unreachable is a diagnostic at that target,
/// and every such diagnostic a move it finds unreachable.
#[test]
fn move_reaches_agree_with_the_motion_rules() {
    let motion = [
        "target-out-of-reach",
        "joint-out-of-range",
        "configuration-mismatch",
    ];
    let mut judged = 0;
    for fixture in fixtures() {
        if !motion.iter().any(|m| fixture.name.starts_with(m)) {
            continue;
        }
        let mut ws = fixture.workspace();
        for task in ws.tasks() {
            let reaches = rapid_analyzer::check::move_reaches(&task, &|_| true);
            judged += reaches.len();
            for (i, unit) in task.units.iter().enumerate() {
                let failed: BTreeSet<usize> = reaches
                    .iter()
                    .filter(|r| r.unit == i && r.result.is_err())
                    .map(|r| r.offset)
                    .collect();
                let mut reported: BTreeSet<usize> = ws
                    .diagnostics(&unit.path)
                    .iter()
                    .filter(|d| motion.contains(&d.rule.name))
                    .map(|d| d.range.start)
                    .collect();
                // A joint target (`MoveAbsJ`) is checked against the
                // working ranges, with no position to reach: not logged.
                reported.retain(|at| {
                    let line_start = unit.text[..*at].rfind('\n').map_or(0, |n| n + 1);
                    !unit.text[line_start..*at]
                        .to_ascii_lowercase()
                        .contains("moveabsj")
                });
                assert_eq!(failed, reported, "{} {}", fixture.name, unit.path);
            }
        }
    }
    assert!(judged > 3, "the fixtures judge moves ({judged})");
}
