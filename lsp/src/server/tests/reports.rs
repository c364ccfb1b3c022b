//! Diagnostics as editors of projects need them: pushed to clients that
//! pull but cannot be told to pull again (Neovim 0.11), for every file of
//! the workspace and not only the open ones (pushed, or answered to
//! `workspace/diagnostic`), and for a file opened without a workspace
//! folder, with the rest of its task found from its place.

use serde_json::{Value, json};

use super::{TestClient, doc_pos, pos, temp_dir, until_codes, uri, write_files};

const MAIN: &str =
    "MODULE Main\n  PROC main()\n    VAR num unused;\n    helper;\n  ENDPROC\nENDMODULE\n";
const LIB: &str = "MODULE Lib\n  PROC helper()\n  ENDPROC\nENDMODULE\n";
const OTHER: &str =
    "MODULE Other\n  PROC other()\n    helper;\n    missing;\n  ENDPROC\nENDMODULE\n";

/// What Neovim 0.11 declares: pull diagnostics, no refresh.
fn neovim_caps() -> Value {
    json!({
        "textDocument": {"diagnostic": {"dynamicRegistration": false}},
        "workspace": {"didChangeWatchedFiles": {"dynamicRegistration": true}},
        "general": {"positionEncodings": ["utf-16"]},
    })
}

/// What VS Code declares: pull diagnostics and refresh.
fn vscode_caps() -> Value {
    json!({
        "textDocument": {"diagnostic": {"dynamicRegistration": true}},
        "workspace": {
            "diagnostics": {"refreshSupport": true},
            "didChangeWatchedFiles": {"dynamicRegistration": true},
        },
        "general": {"positionEncodings": ["utf-16"]},
    })
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_client_that_cannot_be_told_to_pull_again_gets_pushed_diagnostics() {
    let dir = temp_dir("rep-neovim");
    write_files(&dir, &[("Main.mod", MAIN), ("Lib.mod", LIB)]);
    let mut client = TestClient::with_capabilities(
        dir.to_path_buf(),
        neovim_caps(),
        json!({"diagnosticsDelay": 0}),
    )
    .await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    let lib = client.open(&dir.join("Lib.mod"), LIB);
    until_codes(&mut client, &main, &["W201"]).await;
    // An edit in Lib (unsaved) that renames the routine: Main's diagnostics
    // are pushed again, for Main's version.
    client.change(
        &lib,
        2,
        json!([{"range": {"start": {"line": 1, "character": 13}, "end": {"line": 1, "character": 13}}, "text": "2"}]),
    );
    let params = until_codes(&mut client, &main, &["W201", "W101"]).await;
    assert_eq!(params["version"], 1);
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_file_opened_while_indexing_is_reported_again_once_its_task_is_known() {
    let dir = temp_dir("rep-early");
    write_files(&dir, &[("Lib.mod", LIB)]);
    let mut client = TestClient::start(dir.to_path_buf());
    let response = client
        .request(
            "initialize",
            json!({"processId": null, "rootUri": uri(&dir), "capabilities": neovim_caps(),
                   "initializationOptions": {"diagnosticsDelay": 0}}),
        )
        .await;
    assert!(response.get("result").is_some(), "{response}");
    // Opened before the workspace is indexed: helper may be unknown at
    // first; once Lib is read, Main's diagnostics are pushed again.
    client.notify("initialized", json!({}));
    let main = client.open(&dir.join("Main.mod"), MAIN);
    let params = until_codes(&mut client, &main, &["W201"]).await;
    assert_eq!(params["version"], 1);
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn pull_diagnostics_are_declared_only_to_clients_that_take_refreshes() {
    for (caps, pulls) in [(neovim_caps(), false), (vscode_caps(), true)] {
        let dir = temp_dir("rep-caps");
        let mut client = TestClient::start(dir.to_path_buf());
        let response = client
            .request(
                "initialize",
                json!({"processId": null, "rootUri": uri(&dir), "capabilities": caps}),
            )
            .await;
        let provider = &response["result"]["capabilities"]["diagnosticProvider"];
        assert_eq!(!provider.is_null(), pulls, "{response}");
        if pulls {
            assert_eq!(provider["workspaceDiagnostics"], true, "{response}");
        }
        client.notify("initialized", json!({}));
        client.shutdown().await;
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn after_indexing_every_file_is_reported_and_edits_reach_the_closed_ones() {
    let dir = temp_dir("rep-push");
    write_files(
        &dir,
        &[("Main.mod", MAIN), ("Lib.mod", LIB), ("Other.mod", OTHER)],
    );
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let other = uri(&dir.join("Other.mod"));
    let main = uri(&dir.join("Main.mod"));
    // Not open: reported from disk, without a version.
    let reported = client
        .until_all(&[(&other, &["W101"]), (&main, &["W201"])])
        .await;
    assert!(
        reported.iter().all(|p| p["version"] == Value::Null),
        "{reported:?}"
    );
    // Renaming helper in the open Lib: the closed Other and Main follow.
    let lib = client.open(&dir.join("Lib.mod"), LIB);
    client.change(
        &lib,
        2,
        json!([{"range": {"start": {"line": 1, "character": 13}, "end": {"line": 1, "character": 13}}, "text": "2"}]),
    );
    until_codes(&mut client, &other, &["W101", "W101"]).await;
    // Closing Lib without saving: back to the text on disk.
    client.notify(
        "textDocument/didClose",
        json!({"textDocument": {"uri": lib}}),
    );
    until_codes(&mut client, &other, &["W101"]).await;
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_pulling_client_gets_the_closed_files_from_workspace_diagnostics() {
    let dir = temp_dir("rep-pull");
    write_files(
        &dir,
        &[("Main.mod", MAIN), ("Lib.mod", LIB), ("Other.mod", OTHER)],
    );
    let mut client = TestClient::with_capabilities(
        dir.to_path_buf(),
        vscode_caps(),
        json!({"diagnosticsDelay": 0}),
    )
    .await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    let first = client
        .call("workspace/diagnostic", json!({"previousResultIds": []}))
        .await;
    let items = first["items"].as_array().expect("items");
    let uris: Vec<&str> = items.iter().filter_map(|i| i["uri"].as_str()).collect();
    let other = uri(&dir.join("Other.mod"));
    assert!(uris.contains(&other.as_str()), "{first}");
    assert!(
        !uris.contains(&main.as_str()),
        "open files are pulled one by one: {first}"
    );
    let report = items
        .iter()
        .find(|i| i["uri"] == other)
        .expect("Other is reported");
    assert_eq!(report["kind"], "full");
    assert_eq!(report["items"][0]["code"], "W101", "{report}");
    // Asked again with the ids it has: nothing changed.
    let previous: Vec<Value> = items
        .iter()
        .map(|i| json!({"uri": i["uri"], "value": i["resultId"]}))
        .collect();
    let again = client
        .call(
            "workspace/diagnostic",
            json!({"previousResultIds": previous}),
        )
        .await;
    assert!(
        again["items"]
            .as_array()
            .expect("items")
            .iter()
            .all(|i| i["kind"] == "unchanged"),
        "{again}"
    );
    // A file deleted from disk is reported empty once.
    std::fs::remove_file(dir.join("Other.mod")).expect("removed");
    client.notify(
        "workspace/didChangeWatchedFiles",
        json!({"changes": [{"uri": other, "type": 3}]}),
    );
    let mut cleared = false;
    for _ in 0..50 {
        let after = client
            .call(
                "workspace/diagnostic",
                json!({"previousResultIds": previous}),
            )
            .await;
        if after["items"]
            .as_array()
            .expect("items")
            .iter()
            .any(|i| i["uri"] == other && i["kind"] == "full" && i["items"] == json!([]))
        {
            cleared = true;
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    assert!(cleared, "the deleted file was not cleared");
    assert!(
        !client
            .received
            .iter()
            .any(|m| m["method"] == "textDocument/publishDiagnostics"),
        "a pulling client gets nothing pushed"
    );
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_file_opened_without_a_workspace_folder_gets_its_task_from_its_place() {
    let dir = temp_dir("rep-implicit");
    let task = "BACKUP/RAPID/TASK1";
    write_files(
        &dir,
        &[
            (&format!("{task}/PROGMOD/Main.mod"), MAIN),
            (
                &format!("{task}/SYSMOD/Lib.sys"),
                "MODULE Lib(SYSMODULE)\n  PROC helper()\n  ENDPROC\nENDMODULE\n",
            ),
            ("BACKUP/RAPID/TASK2/PROGMOD/Far.mod", OTHER),
            ("BACKUP/BACKINFO/backinfo.txt", "x"),
        ],
    );
    let mut client = TestClient::start(dir.to_path_buf());
    let response = client
        .request(
            "initialize",
            json!({"processId": null, "rootUri": null, "capabilities": neovim_caps(),
                   "initializationOptions": {"diagnosticsDelay": 0}}),
        )
        .await;
    assert!(response.get("result").is_some(), "{response}");
    client.notify("initialized", json!({}));
    let path = dir.join(format!("{task}/PROGMOD/Main.mod"));
    let main = client.open(&path, MAIN);
    client.indexed().await;
    // helper comes from SYSMOD of the same task once it is loaded.
    until_codes(&mut client, &main, &["W201"]).await;
    let found = client
        .call(
            "textDocument/definition",
            doc_pos(&main, pos(MAIN, "helper;", 2)),
        )
        .await;
    let target = found[0]["uri"].as_str().unwrap_or_default();
    assert!(target.ends_with("SYSMOD/Lib.sys"), "{found}");
    // The file's context is its whole backup: the other task is loaded
    // too, as a task of its own (its routine is found in its file).
    let far = uri(&dir.join("BACKUP/RAPID/TASK2/PROGMOD/Far.mod"));
    let symbols = client
        .call("workspace/symbol", json!({"query": "other"}))
        .await;
    assert!(symbols.to_string().contains(&far), "{symbols}");
    client.shutdown().await;
}
