//! `rapid check` and `rapid rules` end to end: the built binary on small
//! programs written into scratch folders.

use std::path::Path;

mod support;
use support::*;

const MAIN: &str = "MODULE Main\n\
    PROC main()\n\
        VAR num x;\n\
        VAR num unused;\n\
        x = 1;\n\
        helper \"a\";\n\
        Missing;\n\
        TPWrite \"\" \\Num:=x;\n\
    ENDPROC\n\
ENDMODULE\n";

const LIB: &str = "MODULE Lib\n\
    PROC helper(string s)\n\
        TPWrite s;\n\
    ENDPROC\n\
ENDMODULE\n";

/// A task with one error (E003), an unused datum (W201) and an unknown
/// routine (W101).
fn program(name: &str) -> Scratch {
    let dir = scratch(name);
    write(&dir, &[("prog/Main.mod", MAIN), ("prog/Lib.mod", LIB)]);
    dir
}

/// The (code, line) of each diagnostic, from `--format json`.
fn findings(dir: &Path, args: &[&str]) -> Vec<(String, u64)> {
    let mut all = vec!["check", "--format", "json"];
    all.extend_from_slice(args);
    let out = rapid(dir, &all);
    let json: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", show(&out)));
    json.as_array()
        .expect("an array")
        .iter()
        .map(|d| {
            (
                d["code"].as_str().expect("code").to_owned(),
                d["line"].as_u64().expect("line"),
            )
        })
        .collect()
}

fn codes(found: &[(String, u64)]) -> Vec<&str> {
    found.iter().map(|(c, _)| c.as_str()).collect()
}

#[test]
fn every_format_on_a_small_program() {
    let dir = program("formats");
    for format in ["human", "concise", "json", "github", "junit"] {
        let out = rapid(&dir, &["check", "prog", "--format", format]);
        insta::assert_snapshot!(format!("format_{format}"), show(&out));
    }
}

/// Removes ANSI colour sequences (`ESC [ ... m`).
fn strip_colours(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(i) = rest.find('\u{1b}') {
        out.push_str(&rest[..i]);
        rest = &rest[i..];
        rest = rest.find('m').map_or("", |m| &rest[m + 1..]);
    }
    out.push_str(rest);
    out
}

#[test]
fn human_output_is_coloured_only_when_asked_and_says_the_same() {
    let dir = program("colours");
    let plain = rapid(&dir, &["check", "prog"]);
    let coloured = std::process::Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(["check", "prog"])
        .current_dir(&dir)
        .env_remove("NO_COLOR")
        .env("CLICOLOR_FORCE", "1")
        .output()
        .expect("the rapid binary runs");
    let (plain, coloured) = (text(&plain.stdout), text(&coloured.stdout));
    assert!(!plain.contains('\u{1b}'), "{plain}");
    assert!(coloured.contains("\u{1b}["), "{coloured}");
    assert_eq!(strip_colours(&coloured), plain);
}

#[test]
fn sarif_is_valid_against_the_schema_and_has_what_github_reads() {
    let dir = program("sarif");
    let out = rapid(&dir, &["check", "--format", "sarif"]);
    assert_eq!(out.status.code(), Some(1), "{}", show(&out));
    let log: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let schema: serde_json::Value =
        serde_json::from_str(include_str!("data/sarif-schema-2.1.0.json"))
            .expect("the schema is JSON");
    let validator = jsonschema::validator_for(&schema).expect("the schema compiles");
    let errors: Vec<String> = validator
        .iter_errors(&log)
        .map(|e| format!("{} at {}", e, e.instance_path()))
        .collect();
    assert!(errors.is_empty(), "{errors:#?}");
    // The schema allows much; GitHub code scanning needs these.
    let run = &log["runs"][0];
    let rules = run["tool"]["driver"]["rules"].as_array().expect("rules");
    let w201 = rules
        .iter()
        .find(|r| r["id"] == "W201")
        .expect("W201 is described");
    assert_eq!(w201["name"], "unused-data");
    assert_eq!(w201["defaultConfiguration"]["level"], "note");
    // No links until the project has a public home: the documentation is
    // in `help` (and `rapid rules`, docs/diagnostics.md).
    assert!(w201.get("helpUri").is_none(), "{w201}");
    assert!(
        run["tool"]["driver"].get("informationUri").is_none(),
        "{}",
        run["tool"]["driver"]["name"]
    );
    assert!(!String::from_utf8_lossy(&out.stdout).contains("example.invalid"));
    assert!(
        w201["help"]["markdown"]
            .as_str()
            .expect("help")
            .contains("### Example")
    );
    assert!(
        !w201["fullDescription"]["text"]
            .as_str()
            .expect("text")
            .is_empty()
    );
    let results = run["results"].as_array().expect("results");
    let codes: Vec<&str> = results
        .iter()
        .map(|r| r["ruleId"].as_str().expect("id"))
        .collect();
    assert_eq!(codes, ["W201", "E003", "W101"]);
    let e003 = &results[1];
    assert_eq!(e003["level"], "error");
    let index = e003["ruleIndex"].as_u64().expect("index") as usize;
    assert_eq!(rules[index]["id"], "E003");
    let location = &e003["locations"][0]["physicalLocation"];
    assert_eq!(location["artifactLocation"]["uri"], "prog/Main.mod");
    assert_eq!(location["artifactLocation"]["uriBaseId"], "%SRCROOT%");
    assert_eq!(
        location["region"],
        serde_json::json!({"startLine": 5, "startColumn": 3, "endLine": 5, "endColumn": 4})
    );
    assert!(
        run["originalUriBaseIds"]["%SRCROOT%"]["uri"]
            .as_str()
            .expect("root")
            .starts_with("file:///")
    );
    assert!(e003["partialFingerprints"]["rapidLineHash/v1"].is_string());
}

#[test]
fn output_is_deterministic_whatever_the_threads() {
    let dir = scratch("determinism");
    for i in 0..24 {
        let task = i % 3;
        write(
            &dir,
            &[(
                &format!("t{task}/M{i}.mod"),
                &format!(
                    "MODULE M{i}\n    PROC p{i}()\n        VAR num a{i};\n        q{i};\n        n{i} := {i};\n    ENDPROC\nENDMODULE\n"
                ),
            )],
        );
    }
    for format in ["human", "sarif", "junit"] {
        let one = rapid(&dir, &["check", "--format", format, "--threads", "1"]);
        let two = rapid(&dir, &["check", "--format", format, "--threads", "2"]);
        let again = rapid(&dir, &["check", "--format", format, "--threads", "2"]);
        assert!(!one.stdout.is_empty());
        assert_eq!(text(&one.stdout), text(&two.stdout), "{format}");
        assert_eq!(text(&two.stdout), text(&again.stdout), "{format}");
    }
    let found = findings(&dir, &[]);
    assert_eq!(found.len(), 24 * 3, "{found:?}");
}

#[test]
fn a_large_module_reports_the_same_on_one_thread_and_two() {
    // Over 128 KiB, checked with one thread and with two: the same report.
    // In every routine, or every few
    // statements or declarations, the last ones included: unused data, a
    // constant error, an unknown routine, a routine used as data.
    let many = |i: usize| {
        format!(
            "    PROC p{i}()\n        VAR num unused{i};\n        CONST num zero{i} := 0;\n        n := k DIV zero{i};\n        missing{i} n;\n        TPWrite \"<EXP> {i}\";\n        n := n + p{i};\n    ENDPROC\n"
        )
    };
    let long = |i: usize| {
        let label = if i.is_multiple_of(50) {
            format!("        l{i}:\n")
        } else {
            String::new()
        };
        // Jumps forwards and backwards across the middle.
        let jump = if i % 50 == 7 {
            format!(
                "        IF n = 0 GOTO l{};\n",
                (i + 1_000) % 2_000 / 50 * 50
            )
        } else {
            String::new()
        };
        format!(
            "{label}        n := k DIV 0;\n        missing{i} n;\n        IF n > {i} THEN\n            n := n + p;\n        ENDIF\n{jump}"
        )
    };
    let data = |i: usize| {
        format!(
            "    LOCAL CONST num c{i} := {i} DIV 0;\n    CONST robtarget p{i} := [[{i},0,0],[1,0,0,0],[0,0,0,0],\n        [9E9,9E9,9E9,9E9,9E9,9E9]];\n"
        )
    };
    let shapes: [(&str, &dyn Fn(usize) -> String); 3] =
        [("many", &many), ("long", &long), ("data", &data)];
    for (name, shape) in shapes {
        let dir = scratch(&format!("large-{name}"));
        let mut module = String::from("MODULE Large\n    CONST num k := 3;\n    VAR num n;\n");
        if name == "long" {
            // Data used early or late in a long routine are used.
            module.push_str(
                "    PROC main()\n        VAR num unused;\n        VAR num early;\n        VAR num late;\n        early := 1;\n",
            );
        }
        let mut i = 0;
        while module.len() < 200 * 1024 || (name == "long" && i < 2_000) {
            module.push_str(&shape(i));
            i += 1;
        }
        if name == "long" {
            module.push_str("        late := 2;\n    ENDPROC\n    PROC p()\n    ENDPROC\n");
        }
        module.push_str("ENDMODULE\n");
        write(&dir, &[("cell/Large.mod", &module)]);
        let one = rapid(&dir, &["check", "--format", "json", "--threads", "1"]);
        let two = rapid(&dir, &["check", "--format", "json", "--threads", "2"]);
        assert_eq!(text(&one.stdout), text(&two.stdout), "{name}");
        let found = findings(&dir, &["--threads", "2"]);
        let mut counts = std::collections::BTreeMap::new();
        for (code, _) in &found {
            *counts.entry(code.as_str()).or_insert(0) += 1;
        }
        let want = match name {
            "many" => vec![("E413", i), ("W101", 2 * i), ("W201", i)],
            // `missing{i}` each once, the routine `p` used as data once.
            "long" => vec![("E413", i), ("W101", i + 1), ("W201", 1)],
            _ => vec![("E413", i), ("W201", i)],
        };
        assert_eq!(counts, want.into_iter().collect(), "{name}");
        let last_line = module.lines().count() as u64 - 2;
        assert!(
            found.iter().any(|(_, line)| *line + 8 >= last_line),
            "{name}"
        );
    }
}

#[test]
fn exit_codes_follow_the_flags() {
    let dir = program("exit");
    let code = |args: &[&str]| rapid(&dir, args).status.code();
    assert_eq!(code(&["check"]), Some(1));
    assert_eq!(code(&["check", "--exit-zero"]), Some(0));
    // A syntax error (E003) cannot be ignored: the module would not load.
    assert_eq!(code(&["check", "--ignore", "E003"]), Some(1));
    // Lib alone has neither errors nor warnings (Main is its task's context).
    assert_eq!(code(&["check", "prog/Lib.mod"]), Some(0));
    assert_eq!(
        code(&["check", "prog/Lib.mod", "--error-on-warnings"]),
        Some(0)
    );
    assert_eq!(
        code(&[
            "check",
            "--select",
            "W201",
            "--ignore",
            "W101",
            "--error-on-warnings",
            "--min-severity",
            "error"
        ]),
        Some(1)
    );
    assert_eq!(code(&["check", "--select", "E999"]), Some(2));
    assert_eq!(code(&["check", "no-such-folder"]), Some(2));
    assert_eq!(code(&["check", "--format", "yaml"]), Some(2));
}

#[test]
fn select_ignore_and_severity_from_the_command_line_and_rapid_toml() {
    let dir = program("config");
    assert_eq!(codes(&findings(&dir, &[])), ["W201", "E003", "W101"]);
    // Syntax errors (E003 here) are reported whatever the selection says.
    assert_eq!(
        codes(&findings(&dir, &["--select", "W"])),
        ["W201", "E003", "W101"]
    );
    assert_eq!(
        codes(&findings(&dir, &["--ignore", "unused-data,E0"])),
        ["E003", "W101"]
    );
    write(
        &dir,
        &[(
            "rapid.toml",
            "[lint]\nignore = [\"W1\"]\n[lint.severity]\nunused-data = \"error\"\n",
        )],
    );
    assert_eq!(codes(&findings(&dir, &[])), ["W201", "E003"]);
    let json = rapid(&dir, &["check", "--format", "json"]);
    let first: serde_json::Value = serde_json::from_slice(&json.stdout).expect("JSON");
    assert_eq!(first[0]["severity"], "error", "{}", show(&json));
    // Found upwards from a checked sub-folder too.
    assert_eq!(codes(&findings(&dir, &["prog/Main.mod"])), ["W201", "E003"]);
    // The command line's --select replaces the file's select; its ignore adds.
    assert_eq!(codes(&findings(&dir, &["--select", "W1,E"])), ["E003"]);
}

#[test]
fn per_path_overrides_and_excludes() {
    let dir = scratch("overrides");
    write(
        &dir,
        &[
            ("new/Main.mod", MAIN),
            ("new/Lib.mod", LIB),
            ("legacy/Main.mod", MAIN),
            ("legacy/Lib.mod", LIB),
            ("backup_old/Main.mod", MAIN),
            ("new/gen/Main.mod", MAIN),
            (
                "rapid.toml",
                "exclude = [\"backup_old/**\"]\n\n[[lint.overrides]]\npaths = [\"legacy/**\"]\nignore = [\"W1\"]\n\
                 [lint.overrides.severity]\nunused-data = \"error\"\n",
            ),
        ],
    );
    let out = rapid(
        &dir,
        &[
            "check",
            "--format",
            "concise",
            "--exclude",
            "gen",
            "--exit-zero",
        ],
    );
    insta::assert_snapshot!(show(&out));
    // An excluded file named explicitly (as pre-commit does) is left out.
    let out = rapid(&dir, &["check", "backup_old/Main.mod"]);
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("no RAPID files found"),
        "{}",
        show(&out)
    );
}

#[test]
fn configuration_errors_name_the_file_line_and_key() {
    let dir = program("bad-config");
    write(
        &dir,
        &[(
            "rapid.toml",
            "[lint]\nselect = [\"E\"]\nignored = [\"W\"]\n",
        )],
    );
    let out = rapid(&dir, &["check"]);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(
        err.contains("rapid.toml:3: unknown field `ignored`"),
        "{err}"
    );
    write(
        &dir,
        &[("rapid.toml", "[lint]\nselect = [\"E\", \"unused-dat\"]\n")],
    );
    let out = rapid(&dir, &["check"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr)
            .contains("rapid.toml:2: `select`: no rule has the code or name `unused-dat`"),
        "{}",
        show(&out)
    );
    // --config names another file; the found one is not read.
    write(&dir, &[("other.toml", "[lint]\nselect = [\"E003\"]\n")]);
    assert_eq!(
        codes(&findings(&dir, &["--config", "other.toml"])),
        ["E003"]
    );
    let out = rapid(&dir, &["check", "--config", "missing.toml"]);
    assert_eq!(out.status.code(), Some(2), "{}", show(&out));
}

#[test]
fn inline_suppressions() {
    let dir = scratch("suppress");
    write(
        &dir,
        &[(
            "p/Main.mod",
            "MODULE Main\n\
                 ! rapid: ignore-module[unresolved-name]\n\
                 PROC main()\n\
                     VAR num x; ! rapid: ignore[W201]\n\
                     ! rapid: ignore[E003, E001]\n\
                     x = 1;\n\
                     VAR num y;\n\
                     Missing;\n\
                     y = 2;\n\
                 ENDPROC\n\
                 ENDMODULE\n",
        )],
    );
    let found = findings(&dir, &[]);
    assert!(
        found.iter().all(|(c, line)| c != "W101" && *line != 4),
        "{found:?}"
    );
    // A syntax error is reported even where a comment suppresses its rule.
    assert!(found.contains(&("E003".to_owned(), 6)), "{found:?}");
    assert!(found.contains(&("E003".to_owned(), 9)), "{found:?}");
}

#[test]
fn extra_paths_join_the_task_but_are_not_reported() {
    let dir = scratch("extra");
    write(
        &dir,
        &[
            (
                "src/Main.mod",
                "MODULE Main\n    PROC main()\n        helper;\n        SetDO doGrip, 1;\n    ENDPROC\nENDMODULE\n",
            ),
            (
                "controller/Shared.sys",
                "MODULE Shared(SYSMODULE)\n    PROC helper()\n        VAR num unused;\n    ENDPROC\nENDMODULE\n",
            ),
            (
                "controller/EIO.cfg",
                "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"doGrip\" -SignalType \"DO\" -Device \"d652\"\n",
            ),
        ],
    );
    let alone = findings(&dir, &["src"]);
    assert!(alone.iter().any(|(c, _)| c == "W101"), "{alone:?}");
    let with_extra = findings(&dir, &["src", "--extra-path", "controller"]);
    assert!(with_extra.is_empty(), "{with_extra:?}");
    write(&dir, &[("rapid.toml", "extra-paths = [\"controller\"]\n")]);
    let from_config = findings(&dir, &["src"]);
    assert!(from_config.is_empty(), "{from_config:?}");
}

#[test]
fn fix_applies_safe_fixes_in_the_files_encoding_and_line_endings() {
    let dir = scratch("fix");
    // Latin-1, CRLF, no final newline.
    let source: &[u8] = b"MODULE M\r\n  ! caf\xE9\r\n  PROC main()\r\n    VAR num x;\r\n    x = 1;\r\n    TPWrite \"\" \\Num:=x;\r\n    Missing;\r\n  ENDPROC\r\nENDMODULE";
    std::fs::write(dir.join("M.mod"), source).expect("written");
    let out = rapid(&dir, &["check", "--fix", "--format", "concise"]);
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
    let fixed = std::fs::read(dir.join("M.mod")).expect("read");
    let at = source
        .windows(6)
        .position(|w| w == b"x = 1;")
        .expect("the assignment");
    let expected = [&source[..at], b"x := 1;", &source[at + 6..]].concat();
    assert_eq!(fixed, expected, "{}", text(&fixed));
    assert!(
        text(&out.stderr).contains("M.mod: fixed 1 problem"),
        "{}",
        show(&out)
    );
    // What remains is printed; the fixed problem is not.
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("W101") && !stdout.contains("E003"),
        "{stdout}"
    );
    // Nothing left to fix: the file is not touched.
    let out = rapid(&dir, &["check", "--fix"]);
    assert!(!text(&out.stderr).contains("fixed"), "{}", show(&out));
}

#[test]
fn statistics_count_per_rule() {
    let dir = program("statistics");
    let out = rapid(&dir, &["check", "--statistics"]);
    assert_eq!(out.status.code(), Some(1));
    insta::assert_snapshot!(show(&out));
    let out = rapid(&dir, &["check", "--statistics", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(json.as_array().map(Vec::len), Some(3), "{json}");
}

#[test]
fn rules_lists_and_describes() {
    let dir = scratch("rules");
    let out = rapid(&dir, &["rules"]);
    assert_eq!(out.status.code(), Some(0));
    let list = text(&out.stdout);
    for rule in ["E001  syntax-error", "W201  unused-data"] {
        assert!(list.contains(rule), "{list}");
    }
    let out = rapid(&dir, &["rules", "unused-data"]);
    let one = text(&out.stdout);
    assert!(
        one.starts_with("W201 unused-data (default severity: hint)\n"),
        "{one}"
    );
    assert!(one.contains("### Why"), "{one}");
    assert_eq!(text(&rapid(&dir, &["rules", "w201"]).stdout), one);
    let out = rapid(&dir, &["rules", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let all = json.as_array().expect("array");
    assert_eq!(all.len(), list.lines().count());
    assert!(
        all.iter()
            .all(|r| r["code"].is_string() && r["doc"].is_string())
    );
    let out = rapid(&dir, &["rules", "E003", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(json["name"], "equals-for-assignment");
    let out = rapid(&dir, &["rules", "nonsense"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("no rule has the code or name `nonsense`"));
}

#[test]
fn sarif_related_locations_point_into_checked_files() {
    let dir = scratch("sarif-related");
    write(
        &dir,
        &[
            (
                "p/RAPID/TASK1/PROGMOD/A.mod",
                "MODULE A\n    PROC helper()\n    ENDPROC\nENDMODULE\n",
            ),
            (
                "p/RAPID/TASK1/PROGMOD/B.mod",
                "MODULE B\n    PROC helper()\n    ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let out = rapid(&dir, &["check", "--format", "sarif"]);
    let log: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let results = log["runs"][0]["results"].as_array().expect("results");
    let a = results
        .iter()
        .find(|r| {
            r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
                == "p/RAPID/TASK1/PROGMOD/A.mod"
        })
        .unwrap_or_else(|| panic!("a result in A: {log}"));
    let related = &a["relatedLocations"][0]["physicalLocation"];
    assert_eq!(
        related["artifactLocation"]["uri"], "p/RAPID/TASK1/PROGMOD/B.mod",
        "{a}"
    );
    assert_eq!(related["region"]["startLine"], 2, "{a}");
}
