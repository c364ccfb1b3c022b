//! The language server, `rapid check` and `rapid eval` load a project
//! through one loader: the same files make the same tasks in all three. A
//! `.pgf` program lists a module of another folder, and an extra path of
//! `rapid.toml` (outside the workspace folder) holds a module and an
//! `EIO.cfg` the program uses.

use std::collections::BTreeMap;
use std::path::Path;

use serde_json::{Value, json};

mod support;
use support::editor::{Editor, file_uri};
use support::{rapid, scratch, write};

const FILES: &[(&str, &str)] = &[
    ("src/rapid.toml", "extra-paths = [\"../shared\"]\n"),
    (
        "src/app/App.pgf",
        "<?xml version=\"1.0\"?>\n<Program>\n  <Module>Main.mod</Module>\n  <Module>../lib/Tools.sys</Module>\n</Program>\n",
    ),
    (
        "src/app/Main.mod",
        "MODULE Main\n  CONST num total := kBase + 1;\n  PROC main()\n    tool;\n    helper;\n    SetDO doGrip, 1;\n  ENDPROC\nENDMODULE\n",
    ),
    (
        "src/lib/Tools.sys",
        "MODULE Tools(SYSMODULE)\n  CONST num kBase := 41;\n  PROC tool()\n  ENDPROC\nENDMODULE\n",
    ),
    (
        "src/other/Other.mod",
        "MODULE Other\n  PROC main()\n    tool;\n    helper;\n  ENDPROC\nENDMODULE\n",
    ),
    (
        "shared/Shared.mod",
        "MODULE Shared\n  PROC helper()\n  ENDPROC\nENDMODULE\n",
    ),
    (
        "shared/EIO.cfg",
        "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n  -Name \"doGrip\" -SignalType \"DO\"\n",
    ),
];

/// The modules checked, relative to `src`.
const MODULES: &[&str] = &["app/Main.mod", "lib/Tools.sys", "other/Other.mod"];

/// Code, line and message of each finding.
type Finding = (String, u64, String);

fn check_findings(src: &Path) -> BTreeMap<String, Vec<Finding>> {
    let out = rapid(src, &["check", "--format", "json", "--exit-zero", "."]);
    let found: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    let mut by_file: BTreeMap<String, Vec<Finding>> = BTreeMap::new();
    for d in found.as_array().into_iter().flatten() {
        let file = d["file"].as_str().unwrap_or_default();
        by_file
            .entry(file.trim_start_matches("./").to_owned())
            .or_default()
            .push((
                d["code"].as_str().unwrap_or_default().to_owned(),
                d["line"].as_u64().unwrap_or(0),
                d["message"].as_str().unwrap_or_default().to_owned(),
            ));
    }
    for findings in by_file.values_mut() {
        findings.sort();
    }
    by_file
}

fn server_findings(editor: &mut Editor, src: &Path) -> BTreeMap<String, Vec<Finding>> {
    let mut by_file = BTreeMap::new();
    for name in MODULES {
        let path = src.join(name);
        let text = std::fs::read_to_string(&path).expect("fixture");
        let uri = file_uri(&path);
        editor.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "rapid", "version": 1, "text": text}}),
        );
        let report = editor.call(
            "textDocument/diagnostic",
            json!({"textDocument": {"uri": uri}}),
        );
        let mut findings: Vec<Finding> = report["items"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|d| {
                (
                    d["code"].as_str().unwrap_or_default().to_owned(),
                    d["range"]["start"]["line"].as_u64().unwrap_or(0) + 1,
                    d["message"].as_str().unwrap_or_default().to_owned(),
                )
            })
            .collect();
        findings.sort();
        if !findings.is_empty() {
            by_file.insert((*name).to_owned(), findings);
        }
    }
    by_file
}

#[test]
fn the_server_rapid_check_and_rapid_eval_group_files_into_the_same_tasks() {
    let dir = scratch("grouping");
    write(&dir, FILES);
    let src = dir.join("src");

    // rapid check: the program's task sees Tools.sys (another folder) and
    // the extra path; Other.mod, a task of its own, sees only the extra path.
    let check = check_findings(&src);
    assert_eq!(
        check.keys().collect::<Vec<_>>(),
        ["other/Other.mod"],
        "{check:#?}"
    );
    assert_eq!(check["other/Other.mod"].len(), 1, "{check:#?}");
    assert!(check["other/Other.mod"][0].2.contains("tool"), "{check:#?}");

    // The language server, on the same folder: the same findings.
    let mut editor = Editor::start();
    let init = editor.call(
        "initialize",
        json!({
            "processId": null,
            "rootUri": file_uri(&src),
            "workspaceFolders": [{"uri": file_uri(&src), "name": "grouping"}],
            "capabilities": {},
            "initializationOptions": {"diagnosticsDelay": 0},
        }),
    );
    assert_eq!(init["serverInfo"]["name"], "rapid");
    editor.notify("initialized", json!({}));
    editor.wait_for(|m| {
        m["method"] == "window/logMessage"
            && m["params"]["message"]
                .as_str()
                .is_some_and(|s| s.starts_with("indexed "))
    });
    assert_eq!(server_findings(&mut editor, &src), check);
    assert_eq!(editor.call("shutdown", Value::Null), Value::Null);
    editor.notify("exit", Value::Null);
    assert!(editor.child.wait().expect("exit").success());

    // rapid eval --file: the module's task is the program's, so a constant
    // of Tools.sys is known.
    let out = rapid(&src, &["eval", "--file", "app/Main.mod", "total + kBase"]);
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "83\n",
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = rapid(&src, &["eval", "--file", "other/Other.mod", "kBase"]);
    assert_eq!(out.status.code(), Some(1));
}
