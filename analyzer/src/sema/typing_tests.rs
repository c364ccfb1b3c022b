//! The oracle of [`type_of`]: at every expression of every rule fixture,
//! and of a sample of the corpus when it is there, the type [`type_of`]
//! gives equals the type the checker gives while it checks (the checker
//! applies the same typing rules and reports where they say no).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::type_of;
use crate::sema::scope::Scope;
use crate::task::{Task, Unit};
use crate::ty::Ty;

/// Every expression of `task`'s units whose two types differ, as
/// `path:offset: text: sema vs checker`; and how many were compared.
fn differences(task: &Task) -> (Vec<String>, usize) {
    let mut out = Vec::new();
    let mut compared = 0;
    for (ui, u) in task.units.iter().enumerate() {
        let mut cursor = u.tree().walk();
        'walk: loop {
            let n = cursor.node();
            if crate::lower::is_expression(crate::syntax_util::kind(n)) && !n.is_missing() {
                compared += 1;
                let sema = Scope::at(task, ui, n.start_byte())
                    .map_or(Ty::Unknown, |scope| type_of(&scope, n, None));
                let checker = crate::check::checker_type_of(task, ui, n);
                if sema != checker {
                    out.push(format!(
                        "{}:{}: `{}`: type_of says {sema:?}, the checker {checker:?}",
                        u.path,
                        n.start_byte(),
                        &u.text[n.byte_range()]
                    ));
                }
            }
            if cursor.goto_first_child() {
                continue;
            }
            while !cursor.goto_next_sibling() {
                if !cursor.goto_parent() {
                    break 'walk;
                }
            }
        }
    }
    (out, compared)
}

fn files_under(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            files_under(&p, out);
        } else if p.extension().and_then(|e| e.to_str()).is_some_and(|e| {
            ["mod", "sys", "modx", "sysx", "prg"].contains(&e.to_ascii_lowercase().as_str())
        }) {
            out.push(p);
        }
    }
}

/// Checks each file as a task of its own.
fn check_files(files: &[PathBuf]) -> usize {
    let mut all = Vec::new();
    let mut compared = 0;
    for f in files {
        let Ok(bytes) = std::fs::read(f) else {
            continue;
        };
        let text = String::from_utf8_lossy(&bytes).into_owned();
        let unit = Arc::new(Unit::new(f.to_string_lossy().into_owned(), text, None));
        let task = Task::new("t".to_owned(), vec![unit], None);
        let (diffs, n) = differences(&task);
        compared += n;
        all.extend(diffs);
    }
    assert!(
        all.is_empty(),
        "{} differences:\n{}",
        all.len(),
        all.join("\n")
    );
    compared
}

#[test]
fn type_of_agrees_with_the_checker_on_the_fixtures() {
    let mut files = Vec::new();
    files_under(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures"),
        &mut files,
    );
    assert!(files.len() > 50, "fixtures not found");
    let compared = check_files(&files);
    assert!(compared > 1_000, "only {compared} expressions compared");
}

/// Every 20th corpus file of at most 40 kB (the oracle enters the scope
/// at every expression).
#[test]
fn type_of_agrees_with_the_checker_on_a_corpus_sample() {
    let root = std::env::var_os("RAPID_CORPUS")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus"));
    let mut files = Vec::new();
    files_under(&root, &mut files);
    if files.is_empty() {
        eprintln!("no corpus at {}: skipped", root.display());
        return;
    }
    let sample: Vec<PathBuf> = files
        .into_iter()
        .filter(|f| std::fs::metadata(f).is_ok_and(|m| m.len() <= 40_000))
        .step_by(20)
        .collect();
    let compared = check_files(&sample);
    assert!(compared > 1_000, "only {compared} expressions compared");
}
