//! `rapid diff` end to end: the built binary on the fixture pairs of
//! `tests/diff/` (one per kind of change, each an `old` and a `new` side),
//! in every format, and on git revisions of a scratch repository.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

mod support;
use support::*;

/// The fixture pairs.
fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/diff")
}

const CASES: &[&str] = &[
    "targets",
    "routines",
    "declarations",
    "modules",
    "layout",
    "config",
    "robotware",
    "thresholds",
    "reach",
];

fn diff(dir: &Path, args: &[&str]) -> Output {
    let mut all = vec!["diff"];
    all.extend_from_slice(args);
    rapid(dir, &all)
}

#[test]
fn every_kind_of_change_in_every_format() {
    for case in CASES {
        let (old, new) = (format!("{case}/old"), format!("{case}/new"));
        for format in ["human", "markdown", "json"] {
            let out = diff(
                &fixtures(),
                &[&old, &new, "--format", format, "--exit-code"],
            );
            let expected = if *case == "layout" { 0 } else { 1 };
            assert_eq!(out.status.code(), Some(expected), "{case}: {}", show(&out));
            assert!(out.stderr.is_empty(), "{case}: {}", show(&out));
            if format == "json" {
                let v: serde_json::Value =
                    serde_json::from_slice(&out.stdout).expect("the report is JSON");
                assert_eq!(v["old"], old.as_str());
            }
            insta::assert_snapshot!(format!("diff_{case}_{format}"), text(&out.stdout));
        }
    }
}

#[test]
fn one_thread_reports_what_many_do() {
    // Both sides and their files are read and reduced on the thread pool.
    for case in ["targets", "modules", "config"] {
        let (old, new) = (format!("{case}/old"), format!("{case}/new"));
        let args = ["diff", old.as_str(), new.as_str(), "--format", "json"];
        let many = rapid(&fixtures(), &args);
        let one = Command::new(env!("CARGO_BIN_EXE_rapid"))
            .args(args)
            .current_dir(fixtures())
            .env("RAYON_NUM_THREADS", "1")
            .stdin(Stdio::null())
            .output()
            .expect("the rapid binary runs");
        assert_eq!(text(&one.stdout), text(&many.stdout), "{case}");
    }
}

#[test]
fn the_fixture_sides_are_programs_the_checker_loads() {
    // The fixtures are real RAPID: a syntax error would make their
    // comparison meaningless.
    let out = rapid(
        &fixtures(),
        &["check", ".", "--select", "E0", "--format", "concise"],
    );
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
}

#[test]
fn small_moves_are_left_out_below_the_thresholds() {
    let args = [
        "thresholds/old",
        "thresholds/new",
        "--ignore-moves-below",
        "0.1mm",
        "--ignore-moves-below",
        "0.05deg",
        "--exit-code",
    ];
    let out = diff(&fixtures(), &args);
    assert_eq!(out.status.code(), Some(1), "{}", show(&out));
    let report = text(&out.stdout);
    // p3 moved 0.5 mm; p4's configuration changed; p1 and p2 are small.
    assert!(report.contains("p3") && report.contains("p4"), "{report}");
    assert!(
        !report.contains(" p1 ") && !report.contains(" p2 "),
        "{report}"
    );
    assert!(report.contains("2 smaller moves left out"), "{report}");
    // Only small moves: nothing changed beyond the thresholds.
    let out = diff(
        &fixtures(),
        &[
            "thresholds/old/Touch.mod",
            "thresholds/new/Touch.mod",
            "--ignore-moves-below",
            "1",
            "--ignore-moves-below",
            "1deg",
            "--exit-code",
        ],
    );
    assert_eq!(out.status.code(), Some(1), "{}", show(&out));
    assert!(text(&out.stdout).contains("conf [0,0,0,0] → [0,0,1,0]"));
}

#[test]
fn a_moved_target_says_whether_the_backups_robot_still_reaches_it() {
    // MOC.cfg names an IRB 120: the answer is the check's (E601 at the
    // same move), with the move's tool and work object.
    let out = diff(&fixtures(), &["reach/old", "reach/new", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("the report is JSON");
    let data = &v["tasks"][0]["modules"][0]["data"];
    let reach = |name: &str| {
        data.as_array()
            .and_then(|d| d.iter().find(|d| d["name"] == name))
            .map(|d| d["motion"]["reach"].clone())
            .unwrap_or_default()
    };
    assert_eq!(reach("pPick")["reachable"], true, "{}", show(&out));
    assert_eq!(
        reach("pPick")["detail"],
        "conf [0,0,0,0] on the IRB 120-3/0.58"
    );
    assert_eq!(reach("pPlace")["reachable"], false);
    let why = reach("pPlace")["detail"]
        .as_str()
        .unwrap_or_default()
        .to_owned();
    assert!(
        why.contains("329.2 mm out of the arm's reach") && why.contains("MoveL at Cell.mod:14"),
        "{why}"
    );
    assert!(reach("pSpare").is_null(), "no move uses pSpare");
    let check = rapid(&fixtures(), &["check", "reach/new", "--format", "concise"]);
    assert!(text(&check.stdout).contains("Cell.mod:14:11: error[E601] `pPlace` is 329.2 mm"));
    // Without a robot (no MOC.cfg), no answer.
    let out = diff(&fixtures(), &["reach/old/RAPID", "reach/new/RAPID"]);
    assert!(!text(&out.stdout).contains("reachable"), "{}", show(&out));
}

#[test]
fn the_exit_code_is_0_when_every_move_is_below_the_thresholds() {
    let dir = scratch("diff-exit-code");
    let module = |x: &str| {
        format!(
            "MODULE M\n  PERS robtarget p := [[{x},0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\nENDMODULE\n"
        )
    };
    std::fs::write(dir.join("old.mod"), module("100")).expect("written");
    std::fs::write(dir.join("new.mod"), module("100.05")).expect("written");
    let args = [
        "old.mod",
        "new.mod",
        "--exit-code",
        "--ignore-moves-below",
        "0.1mm",
    ];
    let out = diff(&dir, &args);
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
    assert!(
        text(&out.stdout).contains("1 smaller move left out"),
        "{}",
        show(&out)
    );
    let out = diff(
        &dir,
        &[
            "old.mod",
            "new.mod",
            "--exit-code",
            "--ignore-moves-below",
            "0.01mm",
        ],
    );
    assert_eq!(out.status.code(), Some(1), "{}", show(&out));
}

#[test]
fn bad_arguments_say_what_is_wrong() {
    let out = diff(&fixtures(), &["targets/old", "nowhere/new"]);
    assert_eq!(out.status.code(), Some(2), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("`targets/old` is a path here"),
        "{}",
        show(&out)
    );
    let out = diff(&fixtures(), &["a", "b", "--ignore-moves-below", "far"]);
    assert_eq!(out.status.code(), Some(2), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("not an amount like 0.1mm"),
        "{}",
        show(&out)
    );
}

fn git(dir: &Path, args: &[&str]) -> Output {
    let out = Command::new("git")
        .args([
            "-c",
            "user.name=t",
            "-c",
            "user.email=t@t",
            "-c",
            "commit.gpgsign=false",
        ])
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("git runs");
    assert!(out.status.success(), "git {args:?}: {}", show(&out));
    out
}

/// Copies a fixture side into `dir/cell`, replacing what was there.
fn put(dir: &Path, side: &Path) {
    let cell = dir.join("cell");
    let _ = std::fs::remove_dir_all(&cell);
    for path in all_files(side) {
        let rel = path.strip_prefix(side).expect("below the side");
        let to = cell.join(rel);
        std::fs::create_dir_all(to.parent().expect("a folder")).expect("folder");
        std::fs::copy(&path, &to).expect("copied");
    }
}

fn all_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).expect("a folder").flatten() {
        let p = entry.path();
        if p.is_dir() {
            out.extend(all_files(&p));
        } else {
            out.push(p);
        }
    }
    out
}

/// The report without its first line (which names the sides).
fn body(out: &Output) -> String {
    let t = text(&out.stdout);
    t.split_once('\n')
        .map_or(t.clone(), |(_, rest)| rest.to_owned())
}

#[test]
fn git_revisions_compare_as_their_folders_do() {
    let dir = scratch("diff-git");
    git(&dir, &["init", "-q"]);
    // Two commits of a backup (the targets and configuration fixtures
    // merged into one cell).
    for side in ["old", "new"] {
        put(&dir, &fixtures().join("config").join(side));
        let targets = fixtures().join("targets").join(side).join("Cell.mod");
        std::fs::copy(targets, dir.join("cell/RAPID/TASK1/PROGMOD/Cell.mod")).expect("copied");
        git(&dir, &["add", "-A"]);
        git(&dir, &["commit", "-q", "-m", side]);
    }
    std::fs::create_dir_all(dir.join("old")).expect("folder");
    git(&dir, &["worktree", "add", "-q", "old", "HEAD~1"]);
    let folders = diff(&dir, &["old/cell", "cell"]);
    let revisions = diff(&dir, &["HEAD~1", "HEAD", "--", "cell"]);
    assert_eq!(revisions.status.code(), Some(0), "{}", show(&revisions));
    assert!(body(&folders).contains("Cell.mod"), "{}", show(&folders));
    assert_eq!(body(&revisions), body(&folders));
    assert!(text(&revisions.stdout).starts_with("rapid diff HEAD~1:cell → HEAD:cell"));
    // `git difftool --dir-diff` as the README sets it up: folders of the
    // files that changed (the working tree's linked in), compared whole.
    let tool = format!(
        "difftool.rapid.cmd={} diff \"$LOCAL\" \"$REMOTE\"",
        env!("CARGO_BIN_EXE_rapid")
    );
    let out = git(
        &dir,
        &[
            "-c",
            &tool,
            "difftool",
            "--dir-diff",
            "--tool=rapid",
            "HEAD~1",
            "--",
            "cell",
        ],
    );
    let dir_diff = text(&out.stdout);
    let (_, dir_body) = dir_diff.split_once('\n').unwrap_or_default();
    assert_eq!(
        dir_body.replace("cell/", ""),
        body(&folders),
        "{}",
        show(&out)
    );
    // From inside the folder, a revision against the working tree.
    std::fs::write(
        dir.join("cell/RAPID/TASK1/PROGMOD/Extra.mod"),
        "MODULE Extra\nENDMODULE\n",
    )
    .expect("written");
    let sub = dir.join("cell");
    let worktree = diff(&sub, &["HEAD", "--format", "json", "--", "RAPID"]);
    let v: serde_json::Value = serde_json::from_slice(&worktree.stdout).expect("JSON");
    assert_eq!(v["new"], "RAPID (working tree)", "{}", show(&worktree));
    assert_eq!(
        v["tasks"][0]["modules"][0]["name"],
        "Extra",
        "{}",
        show(&worktree)
    );
    // Not a revision, not a path.
    let out = diff(&dir, &["nosuchrev", "HEAD"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("`nosuchrev` is neither"),
        "{}",
        show(&out)
    );
}

#[test]
fn git_diff_shows_the_semantic_diff_through_a_driver() {
    let dir = scratch("diff-driver");
    git(&dir, &["init", "-q"]);
    std::fs::write(dir.join(".gitattributes"), "*.mod diff=rapid\n").expect("written");
    for side in ["old", "new"] {
        let from = fixtures().join("targets").join(side).join("Cell.mod");
        std::fs::copy(from, dir.join("Cell.mod")).expect("copied");
        git(&dir, &["add", "-A"]);
        git(&dir, &["commit", "-q", "-m", side]);
    }
    let driver = format!("{} diff --git-driver", env!("CARGO_BIN_EXE_rapid"));
    let out = git(
        &dir,
        &[
            "-c",
            &format!("diff.rapid.command={driver}"),
            "diff",
            "HEAD~1",
            "HEAD",
        ],
    );
    let report = text(&out.stdout);
    assert!(
        report.starts_with("rapid diff a/Cell.mod → b/Cell.mod"),
        "{report}"
    );
    assert!(
        report.contains("pPick") && report.contains("5 mm"),
        "{report}"
    );
    // A file added: its module is added.
    std::fs::write(
        dir.join("New.mod"),
        "MODULE New\n  VAR num n := 1;\nENDMODULE\n",
    )
    .expect("written");
    git(&dir, &["add", "-A"]);
    let out = git(
        &dir,
        &[
            "-c",
            &format!("diff.rapid.command={driver}"),
            "diff",
            "--cached",
        ],
    );
    assert!(text(&out.stdout).contains("New added"), "{}", show(&out));
}
