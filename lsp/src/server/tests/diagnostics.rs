//! Publishing diagnostics: versions, codes (no links), tags, configuration,
//! incremental edits, debouncing, cross-file invalidation, pull diagnostics.

use serde_json::{Value, json};

use super::{TestClient, codes, temp_dir, until_codes};

const MAIN: &str =
    "MODULE Main\n  PROC main()\n    VAR num unused;\n    helper;\n  ENDPROC\nENDMODULE\n";
const LIB: &str = "MODULE Lib\n  PROC helper()\n  ENDPROC\nENDMODULE\n";

fn no_delay() -> Value {
    json!({"diagnosticsDelay": 0})
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn opened_files_get_diagnostics_with_version_code_and_tags() {
    let dir = temp_dir("diag-open");
    let mut client = TestClient::new(dir.to_path_buf(), no_delay()).await;
    let text = "MODULE Main\n  PROC main()\n    VAR num unused;\n    x = 1;\n    nothere;\n  ENDPROC\n  PROC main()\n  ENDPROC\nENDMODULE\n";
    let uri = client.open(&dir.join("Main.mod"), text);
    let params = client.diagnostics_for(&uri).await;
    insta::assert_json_snapshot!(client.redact(&params));
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn rule_severities_come_from_the_settings() {
    let dir = temp_dir("diag-settings");
    let options = json!({"diagnosticsDelay": 0, "rules": {"unused-data": "off", "W101": "error"}});
    let mut client = TestClient::new(dir.to_path_buf(), options).await;
    let text =
        "MODULE Main\n  PROC main()\n    VAR num unused;\n    nothere;\n  ENDPROC\nENDMODULE\n";
    let uri = client.open(&dir.join("Main.mod"), text);
    let params = client.diagnostics_for(&uri).await;
    assert_eq!(codes(&params), ["W101"]);
    assert_eq!(params["diagnostics"][0]["severity"], 1);
    // Changing the configuration republishes with the new severities.
    client.notify(
        "workspace/didChangeConfiguration",
        json!({"settings": {"rapid": {"diagnosticsDelay": 0, "rules": {"W101": "off"}}}}),
    );
    // (A publication from before the change may come first.)
    for _ in 0..5 {
        if codes(&client.diagnostics_for(&uri).await) == ["W201"] {
            client.shutdown().await;
            return;
        }
    }
    panic!("the new settings never applied");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn incremental_edits_with_crlf_and_non_ascii_text() {
    let dir = temp_dir("diag-edit");
    let mut client = TestClient::new(dir.to_path_buf(), no_delay()).await;
    let text = "MODULE Main\r\n    ! Größe 𝄞\r\n    PROC main()\r\n        Stop;\r\n    ENDPROC\r\nENDMODULE\r\n";
    let uri = client.open(&dir.join("Main.mod"), text);
    assert_eq!(
        codes(&client.diagnostics_for(&uri).await),
        Vec::<String>::new()
    );
    // Break the statement after the non-ASCII comment line: `Stop;` -> `Stop`
    client.change(
        &uri,
        2,
        json!([{"range": {"start": {"line": 3, "character": 12}, "end": {"line": 3, "character": 13}}, "text": ""}]),
    );
    let params = client.diagnostics_at(&uri, 2).await;
    assert_eq!(params["version"], 2);
    assert_eq!(codes(&params), ["E001"], "{params}");
    // Insert in the comment (UTF-16 column after the surrogate pair), then
    // put the semicolon back.
    client.change(
        &uri,
        3,
        json!([
            {"range": {"start": {"line": 1, "character": 14}, "end": {"line": 1, "character": 14}}, "text": "!"},
            {"range": {"start": {"line": 3, "character": 12}, "end": {"line": 3, "character": 12}}, "text": ";"}
        ]),
    );
    let params = client.diagnostics_at(&uri, 3).await;
    assert_eq!(params["version"], 3);
    assert_eq!(codes(&params), Vec::<String>::new(), "{params}");
    // The server's text is the editor's: already formatted, so formatting
    // has nothing to change (an edit in the wrong place would show here).
    let edits = client
        .call(
            "textDocument/formatting",
            json!({"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": true}}),
        )
        .await;
    assert_eq!(edits, json!([]), "the text is already formatted");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn typing_is_debounced_and_stale_results_never_win() {
    let dir = temp_dir("diag-debounce");
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 150})).await;
    let text = "MODULE Main\n  PROC main()\n    \n  ENDPROC\nENDMODULE\n";
    let uri = client.open(&dir.join("Main.mod"), text);
    // The first publication is immediate.
    assert_eq!(client.diagnostics_for(&uri).await["version"], 1);
    // Five keystrokes in a row: one publication, for the last version.
    for (i, c) in "Stop;".chars().enumerate() {
        let col = 4 + i;
        client.change(
            &uri,
            2 + i as i32,
            json!([{"range": {"start": {"line": 2, "character": col}, "end": {"line": 2, "character": col}}, "text": c.to_string()}]),
        );
    }
    let params = client.diagnostics_for(&uri).await;
    assert_eq!(params["version"], 6, "{params}");
    assert_eq!(codes(&params), Vec::<String>::new());
    // Anything else published for the file is for that version too (the
    // full check after the quick publication).
    let symbols = client
        .call(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": uri}}),
        )
        .await;
    assert!(symbols.is_array());
    let versions: Vec<Value> = client
        .received
        .iter()
        .filter(|m| m["method"] == "textDocument/publishDiagnostics")
        .map(|m| m["params"]["version"].clone())
        .collect();
    assert!(versions.iter().all(|v| *v == 6), "{versions:?}");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_interface_change_republishes_the_other_open_files_of_the_task() {
    let dir = temp_dir("diag-interface");
    let mut client = TestClient::new(dir.to_path_buf(), no_delay()).await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    let lib = client.open(&dir.join("Lib.mod"), LIB);
    // Main sees Lib's helper once Lib is open.
    loop {
        let params = client.diagnostics_for(&main).await;
        if codes(&params) == ["W201"] {
            break;
        }
    }
    // Rename the routine in Lib (unsaved): Main now has an unresolved name.
    client.change(
        &lib,
        2,
        json!([{"range": {"start": {"line": 1, "character": 13}, "end": {"line": 1, "character": 13}}, "text": "2"}]),
    );
    let params = client.diagnostics_for(&main).await;
    assert_eq!(codes(&params), ["W201", "W101"], "{params}");
    assert_eq!(params["version"], 1);
    client.shutdown().await;
}

/// A constant's value is not part of the interface, but other files'
/// checks read it: changing it republishes them too.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_constant_change_republishes_the_other_open_files_of_the_task() {
    let dir = temp_dir("diag-constant");
    let mut client = TestClient::new(dir.to_path_buf(), no_delay()).await;
    let main = client.open(
        &dir.join("Main.mod"),
        "MODULE Main\n  PROC main()\n    TPWrite \"\" \\Num:=1 / parts;\n  ENDPROC\nENDMODULE\n",
    );
    let lib = client.open(
        &dir.join("Lib.mod"),
        "MODULE Lib\n  CONST num parts := 2;\nENDMODULE\n",
    );
    until_codes(&mut client, &main, &[]).await;
    // `2` becomes `0` (unsaved): Main now divides by zero.
    client.change(
        &lib,
        2,
        json!([{"range": {"start": {"line": 1, "character": 21}, "end": {"line": 1, "character": 22}}, "text": "0"}]),
    );
    let params = until_codes(&mut client, &main, &["E413"]).await;
    assert_eq!(params["version"], 1);
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn pull_diagnostics_report_unchanged_results() {
    let dir = temp_dir("diag-pull");
    let capabilities = json!({
        "textDocument": {"diagnostic": {"dynamicRegistration": false}},
        "workspace": {"diagnostics": {"refreshSupport": true}},
    });
    let mut client =
        TestClient::with_capabilities(dir.to_path_buf(), capabilities, no_delay()).await;
    let uri = client.open(&dir.join("Main.mod"), MAIN);
    let first = client
        .call(
            "textDocument/diagnostic",
            json!({"textDocument": {"uri": uri}}),
        )
        .await;
    assert_eq!(first["kind"], "full");
    assert_eq!(
        first["items"].as_array().map(Vec::len),
        Some(2),
        "unused-data and unresolved-name: {first}"
    );
    let id = first["resultId"].clone();
    let again = client
        .call(
            "textDocument/diagnostic",
            json!({"textDocument": {"uri": uri}, "previousResultId": id}),
        )
        .await;
    assert_eq!(again, json!({"kind": "unchanged", "resultId": id}));
    // After an edit that changes the result, a full report again.
    client.change(
        &uri,
        2,
        json!([{"range": {"start": {"line": 2, "character": 4}, "end": {"line": 2, "character": 19}}, "text": ""}]),
    );
    let after = client
        .call(
            "textDocument/diagnostic",
            json!({"textDocument": {"uri": uri}, "previousResultId": id}),
        )
        .await;
    assert_eq!(after["kind"], "full");
    assert_eq!(after["items"].as_array().map(Vec::len), Some(1), "{after}");
    // Pull clients get no pushed diagnostics.
    assert!(
        !client
            .received
            .iter()
            .any(|m| m["method"] == "textDocument/publishDiagnostics")
    );
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn quick_fixes_come_from_the_diagnostics() {
    let dir = temp_dir("diag-fix");
    let mut client = TestClient::new(dir.to_path_buf(), no_delay()).await;
    let text = "MODULE Main\n  PROC main()\n    VAR num x;\n    x = 1;\n  ENDPROC\nENDMODULE\n";
    let uri = client.open(&dir.join("Main.mod"), text);
    let params = client.diagnostics_for(&uri).await;
    assert_eq!(codes(&params), ["W201", "E003"], "{params}");
    let actions = client
        .call(
            "textDocument/codeAction",
            json!({
                "textDocument": {"uri": uri},
                "range": {"start": {"line": 3, "character": 6}, "end": {"line": 3, "character": 6}},
                "context": {"diagnostics": params["diagnostics"]},
            }),
        )
        .await;
    insta::assert_json_snapshot!(client.redact(&actions));
    client.shutdown().await;
}
