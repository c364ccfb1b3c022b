//! `rapid diff` on real backups: pairs of dated backups of the same cell
//! from the corpus (their figures go to `docs/diff-corpus.md`), and on each
//! backup used, two checks against changes made here:
//!
//! - rewritten (every module laid out in the formatter's `spaced` style
//!   with another indentation, keywords in upper case, line endings made
//!   CRLF), a backup compares equal to itself;
//! - with one target moved by 1.5 mm and one statement added before that
//!   rewrite, the report holds exactly those two changes (and the targets
//!   computed from the moved one, marked as such).
//!
//! `RAPID_BLESS=1 cargo test -p rapid-lsp --test diff_corpus` rewrites the
//! page; without it the test fails when the page is stale.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

mod support;
use support::*;

/// Dated backups of one cell, oldest first: (cell, backup folders below
/// the corpus).
const CELLS: &[(&str, &[&str])] = &[
    (
        "taeyangshim-stack__s25016: controller 1200-526406 (gantry, two welding robots)",
        &[
            "taeyangshim-stack__s25016/RAPID/planc/1200-526406_BACKUP_2025-12-08_1840_B3_afterPlanC/1200-526406_BACKUP_2025-12-08_1840_B3",
            "taeyangshim-stack__s25016/RAPID/SpGantry_1200_526406_BACKUP_2025-12-18",
            "taeyangshim-stack__s25016/RAPID/1200-526406_BACKUP_2025-12-23-1933",
            "taeyangshim-stack__s25016/RAPID/planc/1200-526406_BACKUP_2026-01-13-1856_B3_beforeplanC",
            "taeyangshim-stack__s25016/RAPID/1200-526406_BACKUP_2026-02-11-1959/1200-526406_BACKUP_2026-02-11-1959",
        ],
    ),
    (
        "ebruun__ECL_robotic_cell: IRB 4600 controller, legacy then current",
        &[
            "ebruun__ECL_robotic_cell/_controller_backups/4600-COMPAS_RRC_BACKUP_legacy",
            "ebruun__ECL_robotic_cell/_controller_backups/4600-COMPAS_RRC_BACKUP",
        ],
    ),
    (
        "ebruun__ECL_robotic_cell: IRB 7600 controller, legacy then current",
        &[
            "ebruun__ECL_robotic_cell/_controller_backups/7600-COMPAS_RRC_BACKUP_legacy",
            "ebruun__ECL_robotic_cell/_controller_backups/7600-COMPAS_RRC_BACKUP",
        ],
    ),
];

fn corpus() -> PathBuf {
    match std::env::var_os("RAPID_CORPUS") {
        Some(dir) => PathBuf::from(dir),
        None => {
            let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus");
            std::fs::canonicalize(&dir).unwrap_or(dir)
        }
    }
}

fn json(dir: &Path, args: &[&str]) -> serde_json::Value {
    let mut all = vec!["diff", "--format", "json"];
    all.extend_from_slice(args);
    let out = rapid(dir, &all);
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
    serde_json::from_slice(&out.stdout).expect("the report is JSON")
}

fn count(v: &serde_json::Value, key: &str) -> u64 {
    v["summary"][key].as_u64().unwrap_or(0)
}

fn modules(v: &serde_json::Value) -> Vec<&serde_json::Value> {
    let mut out = Vec::new();
    for t in v["tasks"].as_array().into_iter().flatten() {
        out.extend(t["modules"].as_array().into_iter().flatten());
    }
    out
}

/// Modules added, removed, changed.
fn module_counts(v: &serde_json::Value) -> [usize; 3] {
    let mut n = [0; 3];
    for m in modules(v) {
        match m["status"].as_str() {
            Some("added") => n[0] += 1,
            Some("removed") => n[1] += 1,
            _ => n[2] += 1,
        }
    }
    n
}

/// The largest move: (name, mm).
fn largest_move(v: &serde_json::Value) -> Option<(String, f64)> {
    modules(v)
        .iter()
        .flat_map(|m| m["data"].as_array().into_iter().flatten())
        .filter_map(|d| {
            let mm = d["motion"]["translation_mm"].as_f64()?;
            Some((d["name"].as_str().unwrap_or_default().to_owned(), mm))
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
}

/// Copies the RAPID modules, programs, configuration and backup
/// description of `from` into `to`.
fn copy_backup(from: &Path, to: &Path) -> usize {
    let mut n = 0;
    for path in walk(from) {
        let rel = path.strip_prefix(from).expect("below");
        let dest = to.join(rel);
        std::fs::create_dir_all(dest.parent().expect("a folder")).expect("folder");
        std::fs::copy(&path, &dest).expect("copied");
        n += 1;
    }
    n
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("a folder")
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            out.extend(walk(&p));
        } else {
            out.push(p);
        }
    }
    out
}

fn is_module(p: &Path) -> bool {
    let name = p.file_name().unwrap_or_default().to_string_lossy();
    rapid_analyzer::text::is_rapid_file_name(&name)
}

fn read(p: &Path) -> String {
    let bytes = std::fs::read(p).expect("read");
    match rapid_analyzer::text::decode(&bytes) {
        rapid_analyzer::text::Decoded::Text { text, .. } => text,
        _ => String::new(),
    }
}

/// The seeded changes made to a copy, and what the report must say.
struct Seeded {
    /// The `PERS robtarget` moved by 1.5 mm along x.
    target: Option<String>,
    /// The module whose first procedure got `TPWrite "seeded change";`.
    statement: Option<String>,
}

/// Moves the first literal `PERS robtarget` of the task modules by 1.5 mm
/// and adds a statement at the end of the first procedure.
fn seed(dir: &Path) -> Seeded {
    let mut seeded = Seeded {
        target: None,
        statement: None,
    };
    for path in walk(dir).into_iter().filter(|p| is_module(p)) {
        let in_task = path.to_string_lossy().contains("/RAPID/");
        if !in_task {
            continue;
        }
        let text = read(&path);
        let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
        let mut changed = false;
        if seeded.target.is_none()
            && let Some((i, name, line)) = lines.iter().enumerate().find_map(|(i, l)| {
                let t = l.trim_start();
                let t = t
                    .strip_prefix("TASK ")
                    .or_else(|| t.strip_prefix("LOCAL "))
                    .unwrap_or(t);
                let rest = t.strip_prefix("PERS robtarget ")?;
                let (name, value) = rest.split_once(":=")?;
                let name = name.trim();
                if name.contains('{') || !value.trim_start().starts_with("[[") {
                    return None;
                }
                let at = l.find("[[")? + 2;
                let end = at + l[at..].find(',')?;
                let x: f64 = l[at..end].trim().parse().ok()?;
                let moved = format!("{}{}{}", &l[..at], x + 1.5, &l[end..]);
                Some((i, name.to_owned(), moved))
            })
        {
            lines[i] = line;
            seeded.target = Some(name);
            changed = true;
        }
        if seeded.statement.is_none()
            && let Some(start) = lines.iter().position(|l| {
                let t = l.trim_start().to_ascii_uppercase();
                t.starts_with("PROC ") || t.starts_with("LOCAL PROC ")
            })
            && let Some(end) = lines[start..]
                .iter()
                .position(|l| l.trim().eq_ignore_ascii_case("ENDPROC"))
        {
            lines.insert(start + end, "TPWrite \"seeded change\";".to_owned());
            let module = text
                .lines()
                .find_map(|l| {
                    let t = l.trim_start();
                    let rest = t.get(..7).filter(|h| h.eq_ignore_ascii_case("MODULE "))?;
                    let _ = rest;
                    t[7..].split(['(', ' ']).next().map(str::to_owned)
                })
                .unwrap_or_default();
            seeded.statement = Some(module);
            changed = true;
        }
        if changed {
            std::fs::write(&path, lines.join("\n") + "\n").expect("written");
        }
    }
    seeded
}

/// Lays every module out in the `spaced` style, indented by 2, and makes
/// every line ending CRLF.
fn rewrite(dir: &Path) -> usize {
    std::fs::write(
        dir.join("rapid.toml"),
        "[format]\nstyle = \"spaced\"\nindent-width = 2\n",
    )
    .expect("written");
    let out = rapid(dir, &["fmt", "."]);
    assert!(matches!(out.status.code(), Some(0 | 1)), "{}", show(&out));
    std::fs::remove_file(dir.join("rapid.toml")).expect("removed");
    let mut n = 0;
    for path in walk(dir).into_iter().filter(|p| is_module(p)) {
        let bytes = std::fs::read(&path).expect("read");
        let text = String::from_utf8_lossy(&bytes);
        if !text.contains('\n') {
            continue;
        }
        let crlf = text.replace("\r\n", "\n").replace('\n', "\r\n");
        if std::str::from_utf8(&bytes).is_ok() {
            std::fs::write(&path, crlf).expect("written");
            n += 1;
        }
    }
    n
}

/// Checks that the report holds exactly the seeded changes; returns the
/// targets computed from the moved one.
fn check_seeded(v: &serde_json::Value, seeded: &Seeded, backup: &str) -> usize {
    let mut derived = 0;
    let mut moved = 0;
    let mut statements = 0;
    assert!(
        v["config"].as_array().is_none_or(Vec::is_empty),
        "{backup}: {v:#}"
    );
    for m in modules(v) {
        assert_eq!(m["status"], "changed", "{backup}: {m:#}");
        for d in m["data"].as_array().into_iter().flatten() {
            let mm = d["motion"]["translation_mm"].as_f64().unwrap_or(0.0);
            if Some(d["name"].as_str().unwrap_or_default()) == seeded.target.as_deref() {
                assert!((mm - 1.5).abs() < 1e-3, "{backup}: {d:#}");
                moved += 1;
            } else {
                assert_eq!(d["derived"], true, "{backup}: {d:#}");
                derived += 1;
            }
        }
        for r in m["routines"].as_array().into_iter().flatten() {
            assert_eq!(
                Some(m["name"].as_str().unwrap_or_default()),
                seeded.statement.as_deref()
            );
            let lines: Vec<(&str, &str)> = r["hunks"]
                .as_array()
                .into_iter()
                .flatten()
                .flat_map(|h| h["lines"].as_array().into_iter().flatten())
                .filter(|l| l["tag"] != "context")
                .map(|l| {
                    (
                        l["tag"].as_str().unwrap_or_default(),
                        l["text"].as_str().unwrap_or_default(),
                    )
                })
                .collect();
            assert_eq!(lines, [("added", "TPWrite \"seeded change\";")], "{backup}");
            statements += 1;
        }
        assert!(m["types"].as_array().is_none_or(Vec::is_empty), "{backup}");
    }
    assert_eq!(
        moved,
        usize::from(seeded.target.is_some()),
        "{backup}: {v:#}"
    );
    assert_eq!(
        statements,
        usize::from(seeded.statement.is_some()),
        "{backup}: {v:#}"
    );
    derived
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus of real RAPID code (set RAPID_CORPUS)")]
fn corpus_backups_of_one_cell() {
    let corpus = corpus();
    let mut page = String::from(
        "# `rapid diff` on real backups\n\n<!-- Generated by `RAPID_BLESS=1 cargo test -p rapid-lsp --test diff_corpus`. Do not edit. -->\n\nThe corpus (`../shared/corpus`, test input only) holds dated backups of a few cells. Each pair of consecutive backups of a cell is compared with `rapid diff OLD NEW`; the figures are its report's. Tasks are matched by their folder (`RAPID/TASK1`, a `HOME` folder), modules by name. Routines, positions and other data are counted in the modules changed (a module added or removed brings or takes all of its own).\n",
    );
    let mut seeded_rows = Vec::new();
    let mut backups = Vec::new();
    for (cell, dated) in CELLS {
        let _ = write!(
            page,
            "\n## {cell}\n\n| old → new | modules added / removed / changed | routines | positions moved (largest) | other data | configuration | built-ins |\n| --- | --- | ---: | --- | ---: | ---: | ---: |\n"
        );
        for pair in dated.windows(2) {
            let v = json(&corpus, &[pair[0], pair[1]]);
            let [added, removed, changed] = module_counts(&v);
            let largest = largest_move(&v)
                .map(|(n, mm)| format!(" (`{n}`, {mm:.1} mm)"))
                .unwrap_or_default();
            let short = |p: &str| p.rsplit('/').next().unwrap_or(p).to_owned();
            let _ = writeln!(
                page,
                "| `{}` → `{}` | {added} / {removed} / {changed} | {} | {}{largest} | {} | {} | {} |",
                short(pair[0]),
                short(pair[1]),
                count(&v, "routines"),
                count(&v, "moves"),
                count(&v, "data"),
                count(&v, "config"),
                count(&v, "builtins"),
            );
            // Each pair in the other direction: the same figures, mirrored.
            let back = json(&corpus, &[pair[1], pair[0]]);
            assert_eq!(module_counts(&back), [removed, added, changed], "{pair:?}");
            for key in ["routines", "moves", "data", "config"] {
                assert_eq!(count(&back, key), count(&v, key), "{pair:?} {key}");
            }
        }
        backups.extend(dated.iter().copied());
    }
    // Every backup compares equal to itself rewritten, and with two seeded
    // changes reports exactly them.
    let mut rewritten_modules = 0;
    for backup in &backups {
        let dir = scratch("diff-corpus");
        let (original, copy) = (dir.join("a"), dir.join("b"));
        copy_backup(&corpus.join(backup), &original);
        copy_backup(&corpus.join(backup), &copy);
        rewritten_modules += rewrite(&copy);
        let a = original.to_string_lossy().into_owned();
        let b = copy.to_string_lossy().into_owned();
        let same = json(&dir, &[&a, &b]);
        assert!(modules(&same).is_empty(), "{backup}: {same:#}");
        let _ = std::fs::remove_dir_all(&copy);
        copy_backup(&corpus.join(backup), &copy);
        let seeded = seed(&copy);
        rewrite(&copy);
        let v = json(&dir, &[&a, &b]);
        let derived = check_seeded(&v, &seeded, backup);
        let short = backup.rsplit('/').next().unwrap_or(backup);
        seeded_rows.push(format!(
            "| `{short}` | {} | {} | {derived} |",
            seeded
                .target
                .as_deref()
                .map_or("none".to_owned(), |t| format!("`{t}`")),
            seeded
                .statement
                .as_deref()
                .map_or("none".to_owned(), |m| format!("`{m}`")),
        ));
    }
    let _ = write!(
        page,
        "\n## Changes made here\n\nEach backup above was copied twice. One copy was rewritten: every module laid out by `rapid fmt` in the `spaced` style with an indentation of 2 (keywords in upper case, blanks inside lines set), and its line endings made CRLF ({rewritten_modules} modules in all). Compared with the original, every rewritten backup gives an empty report.\n\nThe other copy got two changes before the same rewrite: its first literal `PERS robtarget` moved by 1.5 mm along x, and `TPWrite \"seeded change\";` added at the end of its first procedure. Each report holds exactly those: the target moved by 1.5 mm (and the targets computed from it, marked as derived), the one routine with the one added line, nothing else.\n\n| backup | target moved | module with the added statement | derived targets |\n| --- | --- | --- | ---: |\n"
    );
    for row in &seeded_rows {
        let _ = writeln!(page, "{row}");
    }
    let doc = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/diff-corpus.md");
    if std::env::var_os("RAPID_BLESS").is_some() {
        std::fs::write(&doc, &page).expect("write docs/diff-corpus.md");
    } else {
        let current = std::fs::read_to_string(&doc).unwrap_or_default();
        assert!(
            current == page,
            "docs/diff-corpus.md is stale: run `RAPID_BLESS=1 cargo test -p rapid-lsp --test diff_corpus`"
        );
    }
}
