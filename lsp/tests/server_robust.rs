//! The language server, as a process over stdio, against what a client may
//! send: files nested 100,000 levels deep, positions that do not exist, bad
//! frames and unknown methods; it must still answer a hover normally. And
//! its diagnostics must equal `rapid check`'s on the same files, with and
//! without file watching (the oracle).

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Duration;

use serde_json::{Value, json};

mod support;
use support::editor::{Editor, file_uri};
use support::{rapid, scratch};

#[path = "../../tests/src/adversarial.rs"]
#[allow(dead_code)]
mod adversarial;

const NORMAL: &str = "MODULE Normal\n  CONST num k := 3;\n  PROC main()\n    TPWrite \"k\" \\Num:=k;\n  ENDPROC\nENDMODULE\n";

fn initialize(editor: &mut Editor, root: &Path, watching: bool) {
    let mut capabilities = json!({});
    if watching {
        capabilities["workspace"] = json!({"didChangeWatchedFiles": {"dynamicRegistration": true}});
    }
    let init = editor.call(
        "initialize",
        json!({
            "processId": null,
            "rootUri": file_uri(root),
            "workspaceFolders": [{"uri": file_uri(root), "name": "robust"}],
            "capabilities": capabilities,
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
}

fn open(editor: &mut Editor, path: &Path, text: &str) -> String {
    let uri = file_uri(path);
    editor.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "rapid", "version": 1, "text": text}}),
    );
    uri
}

fn hover_k(editor: &mut Editor, normal: &str) -> Value {
    editor.call(
        "textDocument/hover",
        json!({"textDocument": {"uri": normal}, "position": {"line": 3, "character": 22}}),
    )
}

#[test]
fn the_server_survives_anything_a_client_sends_and_still_answers_a_hover() {
    let dir = scratch("survive");
    std::fs::write(dir.join("Normal.mod"), NORMAL).expect("written");
    let mut editor = Editor::start();
    initialize(&mut editor, &dir, false);
    let normal = open(&mut editor, &dir.join("Normal.mod"), NORMAL);
    let before = hover_k(&mut editor, &normal);
    assert!(
        before["contents"]["value"]
            .as_str()
            .is_some_and(|v| v.contains("CONST num k")),
        "{before}"
    );

    // Deep files, each in a folder of its own outside the workspace (so
    // that a debug build does not parse them twice at once), one after the
    // other.
    let outside = scratch("survive-deep");
    // Every kind of the generator: calls, sums, products, parentheses,
    // signs, NOTs, indexes, aggregates, components, IFs (block and compact),
    // WHILEs, FORs, TESTs, constant values, routine arguments, unclosed and
    // stray brackets.
    for input in adversarial::deep(100_000) {
        let folder = outside.join(&input.name);
        std::fs::create_dir_all(&folder).expect("folder");
        let uri = open(&mut editor, &folder.join("Deep.mod"), &input.text);
        let (name, uri, text) = (&input.name, &uri, &input.text);
        // A full request on each: the nesting warning is among its
        // diagnostics (unclosed brackets make errors, not depth).
        let report = editor.call(
            "textDocument/diagnostic",
            json!({"textDocument": {"uri": uri}}),
        );
        let codes: Vec<&str> = report["items"]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(|d| d["code"].as_str())
            .collect();
        if !["unclosed", "stray", "compact"]
            .iter()
            .any(|k| name.contains(k))
        {
            assert!(codes.contains(&"W001"), "{name}: {codes:?}");
        }
        let lines = text.lines().count() as u32;
        for (line, character) in [(4, 40_000), (lines / 2, 3)] {
            let at = json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}});
            editor.call("textDocument/hover", at.clone());
            editor.call(
                "textDocument/selectionRange",
                json!({"textDocument": {"uri": uri}, "positions": [at["position"]]}),
            );
        }
        for method in [
            "textDocument/semanticTokens/full",
            "textDocument/foldingRange",
        ] {
            editor.call(method, json!({"textDocument": {"uri": uri}}));
        }
        // An edit in the middle of the deep part, then at the start.
        let mid = json!({"line": lines / 2, "character": 0});
        editor.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": 2}, "contentChanges": [
                {"range": {"start": mid, "end": mid}, "text": "("},
                {"range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}}, "text": "! edited\n"},
            ]}),
        );
    }

    // Positions that do not exist, and parameters of the wrong shape.
    for position in [
        json!({"line": 4_000_000_000u32, "character": 4_000_000_000u32}),
        json!({"line": -1, "character": 0}),
        json!({"line": "two", "character": 0}),
        json!(null),
    ] {
        let answer = editor.request(
            "textDocument/hover",
            json!({"textDocument": {"uri": normal}, "position": position}),
        );
        assert!(
            answer.get("result").is_some() || answer.get("error").is_some(),
            "{answer}"
        );
    }
    let answer = editor.request("textDocument/hover", json!({"textDocument": {"uri": "file:///nowhere/X.mod"}, "position": {"line": 0, "character": 0}}));
    assert!(answer.get("result").is_some(), "{answer}");

    // Bad frames: no header, a bad length, a short length, bad UTF-8, JSON
    // nested deeper than any parser takes, a JSON array.
    editor.send_raw(b"garbage without any header\r\n\r\n");
    editor.send_raw(b"Content-Length: lots\r\n\r\n{}");
    editor.send_raw(b"Content-Length: 5\r\n\r\n{\"jsonrpc\":\"2.0\"}");
    editor.send_raw(b"Content-Length: 4\r\n\r\n\xff\xfe\xfd\xfc");
    let nested = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    editor.send_raw(format!("Content-Length: {}\r\n\r\n{nested}", nested.len()).as_bytes());
    editor.send_raw(b"Content-Length: 2\r\n\r\n[]");
    editor.send_raw(&vec![b'x'; 100_000]);
    editor.send_raw(b"\r\n\r\n");

    // Unknown methods: requests get MethodNotFound, notifications nothing.
    for method in ["$/noSuchRequest", "rapid/noSuchRequest", "$/setTrace/extra"] {
        let answer = editor.request(method, json!({}));
        assert_eq!(answer["error"]["code"], -32601, "{method}: {answer}");
    }
    editor.notify("$/noSuchNotification", json!({}));
    editor.notify("rapid/noSuchNotification", json!({}));

    // A normal hover, normally answered.
    let after = hover_k(&mut editor, &normal);
    assert_eq!(after, before);
    assert!(editor.alive());
    assert_eq!(editor.call("shutdown", Value::Null), Value::Null);
    editor.notify("exit", Value::Null);
    let status = editor.child.wait().expect("exit");
    assert!(status.success(), "{status}");
}

/// A finding as both tools can say it: code, 1-based start and end (line,
/// character column; the inputs hold no character outside the BMP, where
/// UTF-16 and character columns differ), message.
type Finding = (String, u64, u64, u64, u64, String);

/// `rapid check --format json` of `dir`, by file name.
fn check_findings(dir: &Path) -> BTreeMap<String, Vec<Finding>> {
    let out = rapid(dir, &["check", "--format", "json", "--exit-zero", "."]);
    let found: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    let mut by_file: BTreeMap<String, Vec<Finding>> = BTreeMap::new();
    for d in found.as_array().into_iter().flatten() {
        let file = d["file"]
            .as_str()
            .unwrap_or_default()
            .trim_start_matches("./")
            .to_owned();
        let n = |k: &str| d[k].as_u64().unwrap_or(0);
        by_file.entry(file).or_default().push((
            d["code"].as_str().unwrap_or_default().to_owned(),
            n("line"),
            n("column"),
            n("end_line"),
            n("end_column"),
            d["message"].as_str().unwrap_or_default().to_owned(),
        ));
    }
    by_file
}

fn server_findings(report: &Value) -> Vec<Finding> {
    let mut out: Vec<Finding> = report["items"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|d| {
            let p = |k: &str, f: &str| d["range"][k][f].as_u64().unwrap_or(0) + 1;
            (
                d["code"].as_str().unwrap_or_default().to_owned(),
                p("start", "line"),
                p("start", "character"),
                p("end", "line"),
                p("end", "character"),
                d["message"].as_str().unwrap_or_default().to_owned(),
            )
        })
        .collect();
    out.sort();
    out
}

#[test]
fn the_server_reports_what_rapid_check_reports_with_and_without_watching() {
    let dir = scratch("oracle");
    // Generated inputs near the limit and past it, chains, duplicates, odd
    // text, and damaged copies; each a task of its own, plus one task of
    // several modules that use each other.
    let mut inputs = adversarial::deep(400);
    inputs.extend(adversarial::deep(100));
    inputs.extend(adversarial::chains(200));
    let mut rng = adversarial::Rng::new(7);
    let damaged: Vec<adversarial::Input> = inputs
        .iter()
        .map(|i| adversarial::Input {
            name: format!("{}-damaged", i.name),
            text: adversarial::mutate(&i.text, &mut rng),
        })
        .collect();
    inputs.extend(damaged);
    let mut files = Vec::new();
    for input in &inputs {
        let folder = dir.join(&input.name);
        std::fs::create_dir_all(&folder).expect("folder");
        std::fs::write(folder.join("M.mod"), &input.text).expect("written");
        files.push((format!("{}/M.mod", input.name), input.text.clone()));
    }
    let shared = dir.join("shared");
    std::fs::create_dir_all(&shared).expect("folder");
    for (name, text) in [
        (
            "Lib.mod",
            "MODULE Lib\n  PERS num count := 0;\n  PROC helper(num n)\n    count := count + n;\n  ENDPROC\nENDMODULE\n",
        ),
        (
            "Main.mod",
            "MODULE Main\n  PROC main()\n    helper 1;\n    helper \"two\";\n    nothere;\n    count := count + 1;\n  ENDPROC\nENDMODULE\n",
        ),
    ] {
        std::fs::write(shared.join(name), text).expect("written");
        files.push((format!("shared/{name}"), text.to_owned()));
    }
    let expected = check_findings(&dir);
    for watching in [true, false] {
        let mut editor = Editor::start();
        initialize(&mut editor, &dir, watching);
        for (name, text) in &files {
            // Editors read a file as rapid check does: without its
            // byte-order mark.
            let text = text.strip_prefix('\u{feff}').unwrap_or(text);
            let uri = open(&mut editor, &dir.join(name), text);
            let report = editor.call(
                "textDocument/diagnostic",
                json!({"textDocument": {"uri": uri}}),
            );
            let mut want = expected.get(name).cloned().unwrap_or_default();
            want.sort();
            assert_eq!(
                server_findings(&report),
                want,
                "{name}, watching: {watching}"
            );
        }
        assert_eq!(editor.call("shutdown", Value::Null), Value::Null);
        editor.notify("exit", Value::Null);
        assert!(editor.child.wait().expect("exit").success());
    }
}

/// Long enough for a debug build to finish what it is doing, far below
/// "for ever": the server leaves requests still running after a short
/// grace.
const EXIT_LIMIT: Duration = Duration::from_secs(30);

#[test]
fn the_server_exits_when_its_input_closes_or_exit_comes_even_with_work_in_flight() {
    let dir = scratch("exit");
    std::fs::write(dir.join("Normal.mod"), NORMAL).expect("written");
    // A heavy file (outside the workspace, so that only the cases that
    // open it read it): requests on it are in flight when the client goes.
    let heavy = adversarial::chains(40_000)
        .into_iter()
        .find(|i| i.name.starts_with("labels"))
        .expect("labels");
    let outside = scratch("exit-heavy");
    for how in [
        "eof",
        "eof-in-flight",
        "exit",
        "exit-in-flight",
        "exit-without-shutdown",
    ] {
        let mut editor = Editor::start();
        initialize(&mut editor, &dir, false);
        let normal = open(&mut editor, &dir.join("Normal.mod"), NORMAL);
        assert!(hover_k(&mut editor, &normal).is_object(), "{how}");
        if how.ends_with("in-flight") {
            let uri = open(&mut editor, &outside.join("Heavy.mod"), &heavy.text);
            for _ in 0..8 {
                editor.notify_request(
                    "textDocument/semanticTokens/full",
                    json!({"textDocument": {"uri": uri}}),
                );
                editor.notify_request(
                    "textDocument/references",
                    json!({"textDocument": {"uri": uri}, "position": {"line": 2, "character": 3}, "context": {"includeDeclaration": true}}),
                );
            }
        }
        let clean = how.starts_with("exit") && how != "exit-without-shutdown";
        if clean {
            assert_eq!(editor.call("shutdown", Value::Null), Value::Null);
        }
        if how.starts_with("exit") {
            // The input stays open: the exit alone must end the process.
            editor.notify("exit", Value::Null);
        } else {
            editor.close_input();
        }
        let status = editor.exit_within(EXIT_LIMIT);
        let status = status.unwrap_or_else(|| panic!("{how}: still running"));
        assert_eq!(status.success(), clean, "{how}: {status}");
    }
}

#[test]
#[cfg(unix)]
fn the_server_exits_when_the_process_that_started_it_is_gone() {
    let dir = scratch("parent");
    std::fs::write(dir.join("Normal.mod"), NORMAL).expect("written");
    // The client process: it ends while the server's input stays open
    // (an editor that crashed, with the pipe held by a grandchild).
    let mut parent = std::process::Command::new("sleep")
        .arg("5")
        .spawn()
        .expect("sleep starts");
    let mut editor = Editor::start();
    let init = editor.call(
        "initialize",
        json!({"processId": parent.id(), "rootUri": file_uri(&dir), "capabilities": {}}),
    );
    assert_eq!(init["serverInfo"]["name"], "rapid");
    editor.notify("initialized", json!({}));
    parent.wait().expect("sleep ends");
    let status = editor.exit_within(EXIT_LIMIT);
    let status = status.unwrap_or_else(|| panic!("the server runs on without its client"));
    assert!(status.success(), "{status}");
}
