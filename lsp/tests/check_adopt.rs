//! `rapid check` on an existing project: a baseline of today's findings, a
//! severity floor, syntax errors that no selection hides, the same findings
//! whatever folder the command runs from, and files that hold no module.

use std::path::Path;

mod support;
use support::*;

/// (file name, line, code) of each finding of `rapid check ARGS --format
/// json` run in `dir`, sorted.
fn findings(dir: &Path, args: &[&str]) -> Vec<(String, u64, String)> {
    let mut all = vec!["check", "--format", "json"];
    all.extend_from_slice(args);
    let out = rapid(dir, &all);
    let json: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", show(&out)));
    let mut found: Vec<(String, u64, String)> = json
        .as_array()
        .expect("an array")
        .iter()
        .map(|d| {
            let file = d["file"].as_str().expect("file").replace('\\', "/");
            let name = file.rsplit('/').next().unwrap_or_default().to_owned();
            (
                name,
                d["line"].as_u64().expect("line"),
                d["code"].as_str().expect("code").to_owned(),
            )
        })
        .collect();
    found.sort();
    found
}

const MAIN: &str = "MODULE Main
    PROC main()
        VAR num unused;
        Missing;
        helper;
    ENDPROC
ENDMODULE
";

const SHARED: &str = "MODULE Shared(SYSMODULE)
    PROC helper()
        TPWrite \"shared\";
    ENDPROC
ENDMODULE
";

#[test]
fn the_same_findings_whatever_folder_the_check_runs_from() {
    let dir = scratch("real-place");
    write(
        &dir,
        &[
            ("BACKUP/RAPID/TASK1/PROGMOD/Main.mod", MAIN),
            ("BACKUP/RAPID/TASK1/SYSMOD/Shared.sys", SHARED),
        ],
    );
    let task = dir.join("BACKUP/RAPID/TASK1");
    let from_parent = findings(&dir, &["BACKUP"]);
    assert_eq!(
        from_parent,
        [
            ("Main.mod".to_owned(), 3, "W201".to_owned()),
            ("Main.mod".to_owned(), 4, "W101".to_owned()),
        ],
        "helper comes from SYSMOD of the same task"
    );
    assert_eq!(findings(&task, &[]), from_parent, "from inside the task");
    assert_eq!(findings(&task.join("PROGMOD"), &[]), from_parent);
    assert_eq!(findings(&task, &["PROGMOD", "SYSMOD"]), from_parent);
    assert_eq!(
        findings(&task.join("PROGMOD"), &["Main.mod"]),
        from_parent,
        "one file named alone still belongs to its task"
    );
    let absolute = task.join("PROGMOD/Main.mod");
    assert_eq!(
        findings(&dir, &[absolute.to_str().expect("a path")]),
        from_parent
    );
    // A file named twice, and a folder overlapping an extra path, are read
    // once (a module loaded twice would clash with itself: E107).
    assert_eq!(findings(&task, &[".", "PROGMOD"]), from_parent);
    assert_eq!(
        findings(&task, &["PROGMOD", "--extra-path", "."]),
        from_parent
    );
    assert_eq!(
        findings(
            &task,
            &["PROGMOD", "--extra-path", task.to_str().expect("a path")]
        ),
        from_parent
    );
}

#[test]
fn a_baseline_records_todays_findings_and_reports_only_new_ones() {
    let dir = scratch("baseline");
    write(&dir, &[("src/Main.mod", MAIN)]);
    // The first run records; nothing is reported and the exit is clean.
    let out = rapid(&dir, &["check", "src", "--baseline", "rapid-baseline.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("recorded 3 findings in rapid-baseline.json"),
        "{}",
        show(&out)
    );
    assert!(
        text(&out.stdout).contains("3 findings in the baseline not shown"),
        "{}",
        show(&out)
    );
    let recorded = std::fs::read_to_string(dir.join("rapid-baseline.json")).expect("written");
    assert!(
        recorded.contains("\"file\": \"src/Main.mod\"") && !recorded.contains("\"line\": 4"),
        "paths relative to the baseline, no line numbers: {recorded}"
    );
    let again = findings(&dir, &["src", "--baseline", "rapid-baseline.json"]);
    assert!(again.is_empty(), "{again:?}");
    // Unrelated edits: lines added above, other indentation. Still nothing
    // new; then a new finding is the only one reported, from any folder.
    let edited = MAIN
        .replace(
            "    PROC main()",
            "    VAR num counter := 0;\n\n    PROC main()",
        )
        .replace("        Missing;", "  Missing;")
        .replace("        helper;", "        helper;\n        Another;");
    write(&dir, &[("src/Main.mod", &edited)]);
    let new = findings(&dir, &["src", "--baseline", "rapid-baseline.json"]);
    assert_eq!(new, [("Main.mod".to_owned(), 8, "W101".to_owned())]);
    let from_src = findings(&dir.join("src"), &["--baseline", "../rapid-baseline.json"]);
    assert_eq!(from_src, new);
    // Recording again takes today's findings.
    let out = rapid(
        &dir,
        &[
            "check",
            "src",
            "--baseline",
            "rapid-baseline.json",
            "--update-baseline",
        ],
    );
    assert!(
        text(&out.stderr).contains("recorded 4 findings"),
        "{}",
        show(&out)
    );
    assert!(findings(&dir, &["src", "--baseline", "rapid-baseline.json"]).is_empty());
    // A broken baseline is an error with its place.
    write(
        &dir,
        &[("broken.json", "{\"rapid-baseline\": 1, \"findings\": [}")],
    );
    let out = rapid(&dir, &["check", "src", "--baseline", "broken.json"]);
    assert_eq!(out.status.code(), Some(2), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("broken.json:1:"),
        "{}",
        show(&out)
    );
}

#[test]
fn a_severity_floor_and_syntax_errors_that_nothing_hides() {
    let dir = scratch("floor");
    let broken = MAIN.replace("helper;", "helper");
    write(&dir, &[("src/Main.mod", &broken)]);
    let all = findings(&dir, &["src"]);
    assert!(
        all.iter().any(|f| f.2 == "W201") && all.iter().any(|f| f.2 == "E002"),
        "{all:?}"
    );
    let floor = findings(&dir, &["src", "--min-severity", "error"]);
    assert!(floor.iter().all(|f| f.2.starts_with('E')), "{floor:?}");
    assert!(floor.iter().any(|f| f.2 == "E002"), "{floor:?}");
    for args in [
        &["src", "--select", "W201"][..],
        &["src", "--ignore", "E"],
        &["src", "--ignore", "missing-token,syntax-error"],
    ] {
        let found = findings(&dir, args);
        assert!(
            found.contains(&("Main.mod".to_owned(), 5, "E002".to_owned())),
            "{args:?}: {found:?}"
        );
    }
    write(
        &dir,
        &[(
            "rapid.toml",
            "[lint]\nselect = [\"W\"]\n[lint.severity]\nE002 = \"hint\"\n",
        )],
    );
    let out = rapid(&dir, &["check", "src", "--format", "concise"]);
    assert!(
        text(&out.stdout).contains("error[E002]"),
        "still an error: {}",
        show(&out)
    );
    let out = rapid(&dir, &["check", "src", "--min-severity", "loud"]);
    assert_eq!(out.status.code(), Some(2), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("`loud` is not error, warning, info or hint"),
        "{}",
        show(&out)
    );
}

#[test]
fn files_without_a_module_are_reported() {
    let dir = scratch("no-module");
    write(
        &dir,
        &[
            ("Empty.mod", ""),
            ("Comments.mod", "! nothing here yet\n"),
            ("Loose.mod", "VAR num n := 1;\nPROC main()\nENDPROC\n"),
        ],
    );
    let out = rapid(&dir, &["check", "--format", "concise"]);
    let report = text(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{}", show(&out));
    for line in [
        "Empty.mod:1:1: error[E001] the file is empty: a module starts with `MODULE name` and ends with `ENDMODULE`",
        "Comments.mod:1:1: error[E001] the file holds no module: a module starts with `MODULE name` and ends with `ENDMODULE`",
        "Loose.mod:1:1: error[E001] expected `MODULE name` before `VAR`: declarations and routines go inside a module",
    ] {
        assert!(report.contains(line), "{line}\n{}", show(&out));
    }
}
