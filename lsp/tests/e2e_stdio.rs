//! End to end: start `rapid lsp`, speak to it over stdio as an editor would,
//! on the two-module example in `examples/palletizer/`.

use std::path::{Path, PathBuf};

use serde_json::{Value, json};

mod support;
use support::editor::{Editor, file_uri};

#[test]
fn an_editor_session_on_the_palletizer_example() {
    let root: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/palletizer")
        .canonicalize()
        .expect("example");
    let main_path = root.join("MainModule.mod");
    let text = std::fs::read_to_string(&main_path).expect("example text");
    let main = file_uri(&main_path);
    let cell = file_uri(&root.join("Cell.sys"));

    let mut editor = Editor::start();
    let init = editor.call(
        "initialize",
        json!({
            "processId": null,
            "rootUri": file_uri(&root),
            "workspaceFolders": [{"uri": file_uri(&root), "name": "palletizer"}],
            "capabilities": {"window": {"workDoneProgress": true}},
            "initializationOptions": {"diagnosticsDelay": 0},
        }),
    );
    assert_eq!(init["serverInfo"]["name"], "rapid");
    // The server runs without transparent huge pages (steady latency).
    if let Ok(status) = std::fs::read_to_string(format!("/proc/{}/status", editor.child.id()))
        && let Some(line) = status.lines().find(|l| l.starts_with("THP_enabled:"))
    {
        assert_eq!(line.split_whitespace().nth(1), Some("0"), "{line}");
    }
    editor.notify("initialized", json!({}));
    editor.wait_for(|m| {
        m["method"] == "window/logMessage"
            && m["params"]["message"]
                .as_str()
                .is_some_and(|s| s.starts_with("indexed 2 "))
    });
    editor.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": main, "languageId": "rapid", "version": 1, "text": text}}),
    );
    // The example is clean: its names come from Cell.sys and EIO.cfg.
    assert_eq!(editor.diagnostics(&main, 1), json!([]));

    let line = text
        .lines()
        .position(|l| l.contains("MoveAbsJ jHome"))
        .expect("line") as u32;
    let character = text
        .lines()
        .nth(line as usize)
        .and_then(|l| l.find("tGripper"))
        .expect("col") as u32
        + 2;
    let at =
        json!({"textDocument": {"uri": main}, "position": {"line": line, "character": character}});

    let hover = editor.call("textDocument/hover", at.clone());
    let shown = hover["contents"]["value"].as_str().unwrap_or_default();
    assert!(
        shown.contains("tooldata") && shown.contains("tGripper"),
        "{hover}"
    );

    let definition = editor.call("textDocument/definition", at);
    assert_eq!(definition[0]["uri"], cell, "{definition}");
    assert_eq!(definition[0]["range"]["start"]["line"], 8, "{definition}");

    let completion = editor.call(
        "textDocument/completion",
        json!({"textDocument": {"uri": main}, "position": {"line": line, "character": 8}}),
    );
    let labels: Vec<&str> = completion["items"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|i| i["label"].as_str())
        .collect();
    assert!(
        labels.contains(&"PickBox") && labels.contains(&"MoveL"),
        "{labels:?}"
    );

    // Typing a call to a routine that does not exist: a warning, at once.
    editor.notify(
        "textDocument/didChange",
        json!({
            "textDocument": {"uri": main, "version": 2},
            "contentChanges": [{"range": {"start": {"line": line, "character": 8}, "end": {"line": line, "character": 8}}, "text": "NoSuchRoutine;\n        "}],
        }),
    );
    // (Syntax diagnostics may come first, then the full check's.)
    let diagnostics = loop {
        let d = editor.diagnostics(&main, 2);
        if d.as_array().is_some_and(|a| !a.is_empty()) {
            break d;
        }
    };
    assert_eq!(diagnostics[0]["code"], "W101", "{diagnostics}");
    assert_eq!(
        diagnostics[0]["range"]["start"]["line"], line,
        "{diagnostics}"
    );

    assert_eq!(editor.call("shutdown", Value::Null), Value::Null);
    editor.notify("exit", Value::Null);
    let status = editor.child.wait().expect("exit");
    assert!(status.success(), "{status}");
}
