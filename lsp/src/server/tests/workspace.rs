//! The workspace: indexing with progress, watched files, closed files read
//! from disk, I/O configuration.

use serde_json::{Value, json};

use super::{TestClient, codes, temp_dir, until_codes, uri, write_files};

const MAIN: &str =
    "MODULE Main\n  PROC main()\n    helper;\n    SetDO doGrip, 1;\n  ENDPROC\nENDMODULE\n";
const LIB: &str = "MODULE Lib\n  PROC helper()\n  ENDPROC\nENDMODULE\n";
const EIO: &str =
    "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n  -Name \"doGrip\" -SignalType \"DO\" -Device \"d652\"\n";

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_workspace_is_indexed_with_progress() {
    let dir = temp_dir("ws-index");
    write_files(
        &dir,
        &[
            ("Lib.mod", LIB),
            ("EIO.cfg", EIO),
            ("Main.mod", MAIN),
            ("notes.txt", "x"),
        ],
    );
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    // Progress: created, begun, reported, ended.
    assert!(
        client
            .server_requests
            .iter()
            .any(|r| r["method"] == "window/workDoneProgress/create"),
        "{:?}",
        client.server_requests
    );
    let mut kinds = Vec::new();
    while let Some(i) = client
        .received
        .iter()
        .position(|m| m["method"] == "$/progress")
    {
        let m = client.received.remove(i).expect("present");
        kinds.push(
            m["params"]["value"]["kind"]
                .as_str()
                .unwrap_or("?")
                .to_owned(),
        );
    }
    assert_eq!(
        kinds.first().map(String::as_str),
        Some("begin"),
        "{kinds:?}"
    );
    assert_eq!(kinds.last().map(String::as_str), Some("end"), "{kinds:?}");
    assert!(kinds.iter().any(|k| k == "report"), "{kinds:?}");
    // A watcher for RAPID files and EIO.cfg was registered.
    let registration = client
        .server_requests
        .iter()
        .find(|r| r["method"] == "client/registerCapability")
        .expect("registered");
    insta::assert_json_snapshot!(registration["params"]);
    // Main, opened, sees Lib's routine and the configured signal from disk.
    let main = client.open(&dir.join("Main.mod"), MAIN);
    until_codes(&mut client, &main, &[]).await;
    // Definition goes to the closed file on disk.
    let def = client
        .call(
            "textDocument/definition",
            json!({"textDocument": {"uri": main}, "position": {"line": 2, "character": 6}}),
        )
        .await;
    assert_eq!(
        client.redact(&def)[0]["uri"],
        "file:///ROOT/Lib.mod",
        "{def}"
    );
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn files_changed_outside_the_editor_are_reloaded() {
    let dir = temp_dir("ws-watch");
    write_files(&dir, &[("Lib.mod", LIB), ("EIO.cfg", EIO)]);
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    until_codes(&mut client, &main, &[]).await;
    // Lib renames its routine on disk.
    write_files(
        &dir,
        &[(
            "Lib.mod",
            "MODULE Lib\n  PROC helper2()\n  ENDPROC\nENDMODULE\n",
        )],
    );
    client.notify(
        "workspace/didChangeWatchedFiles",
        json!({"changes": [{"uri": uri(&dir.join("Lib.mod")), "type": 2}]}),
    );
    until_codes(&mut client, &main, &["W101"]).await;
    // Lib is deleted, and the signal configuration too.
    std::fs::remove_file(dir.join("Lib.mod")).expect("rm");
    std::fs::remove_file(dir.join("EIO.cfg")).expect("rm");
    client.notify(
        "workspace/didChangeWatchedFiles",
        json!({"changes": [
            {"uri": uri(&dir.join("Lib.mod")), "type": 3},
            {"uri": uri(&dir.join("EIO.cfg")), "type": 3}
        ]}),
    );
    // Without a configuration, unknown signals are unresolved names.
    let params = client.diagnostics_for(&main).await;
    assert!(codes(&params).contains(&"W101".to_owned()), "{params}");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_closed_file_goes_back_to_its_text_on_disk() {
    let dir = temp_dir("ws-close");
    write_files(&dir, &[("Lib.mod", LIB), ("EIO.cfg", EIO)]);
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    let lib = client.open(&dir.join("Lib.mod"), LIB);
    until_codes(&mut client, &main, &[]).await;
    // An unsaved rename in Lib breaks Main...
    client.change(
        &lib,
        2,
        json!([{"range": {"start": {"line": 1, "character": 13}, "end": {"line": 1, "character": 13}}, "text": "2"}]),
    );
    until_codes(&mut client, &main, &["W101"]).await;
    // ...until Lib is closed without saving: the disk's text counts again,
    // and Lib is reported as it is on disk (clean).
    client.notify(
        "textDocument/didClose",
        json!({"textDocument": {"uri": lib}}),
    );
    let (mut lib_on_disk, mut main_fixed) = (false, false);
    while !(lib_on_disk && main_fixed) {
        let n = client.notification("textDocument/publishDiagnostics").await;
        let p = &n["params"];
        lib_on_disk |= p["uri"] == lib && p["version"] == Value::Null && codes(p).is_empty();
        main_fixed |= p["uri"] == main && codes(p).is_empty();
    }
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn unreadable_files_are_skipped_with_a_log_message() {
    let dir = temp_dir("ws-binary");
    write_files(&dir, &[("Lib.mod", LIB)]);
    std::fs::write(dir.join("Secret.mod"), b"\xFE\x01\x02encrypted").expect("write");
    std::fs::write(dir.join("Blob.sys"), b"MODULE\0\0\0").expect("write");
    std::fs::write(
        dir.join("Latin.mod"),
        b"MODULE Latin\n  ! Gr\xF6\xDFe\n  PROC latinProc()\n  ENDPROC\nENDMODULE\n",
    )
    .expect("write");
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let logs: Vec<String> = client
        .received
        .iter()
        .filter(|m| m["method"] == "window/logMessage")
        .filter_map(|m| m["params"]["message"].as_str().map(str::to_owned))
        .collect();
    assert!(
        logs.iter()
            .any(|l| l.contains("Secret.mod") && l.contains("encrypted")),
        "{logs:?}"
    );
    assert!(
        logs.iter()
            .any(|l| l.contains("Blob.sys") && l.contains("binary")),
        "{logs:?}"
    );
    // The Latin-1 file was read: its routine resolves.
    let main = client.open(
        &dir.join("Main.mod"),
        "MODULE Main\n  PROC main()\n    latinProc;\n  ENDPROC\nENDMODULE\n",
    );
    until_codes(&mut client, &main, &[]).await;
    // A request for the encrypted file is answered, with nothing.
    let hover = client
        .call(
            "textDocument/hover",
            json!({"textDocument": {"uri": uri(&dir.join("Secret.mod"))}, "position": {"line": 0, "character": 0}}),
        )
        .await;
    assert_eq!(hover, Value::Null);
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn rapid_toml_configures_the_rules_and_is_reloaded() {
    let dir = temp_dir("ws-toml");
    write_files(
        &dir,
        &[("rapid.toml", "[lint]\nignore = [\"unused-data\"]\n")],
    );
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let text =
        "MODULE Main\n  PROC main()\n    VAR num unused;\n    nothere;\n  ENDPROC\nENDMODULE\n";
    let main = client.open(&dir.join("Main.mod"), text);
    until_codes(&mut client, &main, &["W101"]).await;
    // The file changes: unresolved names are hints now, unused data is back.
    write_files(
        &dir,
        &[(
            "rapid.toml",
            "[lint.severity]\nunresolved-name = \"hint\"\n",
        )],
    );
    client.notify(
        "workspace/didChangeWatchedFiles",
        json!({"changes": [{"uri": uri(&dir.join("rapid.toml")), "type": 2}]}),
    );
    let params = until_codes(&mut client, &main, &["W201", "W101"]).await;
    assert_eq!(params["diagnostics"][1]["severity"], 4, "{params}");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn without_file_watching_the_disk_is_polled() {
    let dir = temp_dir("ws-poll");
    write_files(&dir, &[("Lib.mod", LIB), ("EIO.cfg", EIO)]);
    // A client that cannot watch files.
    let mut client =
        TestClient::with_capabilities(dir.to_path_buf(), json!({}), json!({"diagnosticsDelay": 0}))
            .await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    until_codes(&mut client, &main, &[]).await;
    assert!(
        !client
            .server_requests
            .iter()
            .any(|r| r["method"] == "client/registerCapability")
    );
    // Lib renames its routine on disk; nobody tells the server.
    std::thread::sleep(std::time::Duration::from_millis(20));
    write_files(
        &dir,
        &[(
            "Lib.mod",
            "MODULE Lib\n  PROC helper2()\n  ENDPROC\nENDMODULE\n",
        )],
    );
    until_codes(&mut client, &main, &["W101"]).await;
    // A new module declares `helper` again.
    write_files(
        &dir,
        &[("Helpers.mod", LIB.replace("Lib", "Helpers").as_str())],
    );
    until_codes(&mut client, &main, &[]).await;
    // It is renamed: still known, under its new name (the next check of
    // Main, after two rounds of polling, finds `helper`).
    std::fs::rename(dir.join("Helpers.mod"), dir.join("Renamed.mod")).expect("renamed");
    std::thread::sleep(std::time::Duration::from_secs(5));
    client.change(&main, 2, json!([{"range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}}, "text": "! renamed\n"}]));
    let params = client.diagnostics_at(&main, 2).await;
    assert_eq!(codes(&params), Vec::<String>::new(), "{params}");
    // Deleted: unresolved; re-created: resolved.
    std::fs::remove_file(dir.join("Renamed.mod")).expect("removed");
    until_codes(&mut client, &main, &["W101"]).await;
    write_files(
        &dir,
        &[("Renamed.mod", LIB.replace("Lib", "Renamed").as_str())],
    );
    until_codes(&mut client, &main, &[]).await;
    // The signal goes from EIO.cfg: unresolved.
    write_files(&dir, &[("EIO.cfg", "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n")]);
    until_codes(&mut client, &main, &["W101"]).await;
    // A rapid.toml appears and ignores the rule; then it is edited.
    write_files(&dir, &[("rapid.toml", "[lint]\nignore = [\"W101\"]\n")]);
    until_codes(&mut client, &main, &[]).await;
    std::thread::sleep(std::time::Duration::from_millis(20));
    write_files(
        &dir,
        &[(
            "rapid.toml",
            "[lint.severity]\nunresolved-name = \"error\"\n",
        )],
    );
    let params = until_codes(&mut client, &main, &["W101"]).await;
    assert_eq!(params["diagnostics"][0]["severity"], 1, "{params}");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_io_configuration_edited_in_the_editor_applies_at_once() {
    let dir = temp_dir("ws-eio-edit");
    write_files(&dir, &[("Lib.mod", LIB)]);
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let eio = client.open(&dir.join("EIO.cfg"), EIO);
    let main = client.open(&dir.join("Main.mod"), MAIN);
    until_codes(&mut client, &main, &[]).await;
    // Rename the signal in the configuration (unsaved): `doGrip` is unknown.
    let line = EIO
        .lines()
        .position(|l| l.contains("doGrip"))
        .expect("line");
    let col = EIO
        .lines()
        .nth(line)
        .and_then(|l| l.find("doGrip"))
        .expect("col")
        + 2;
    client.change(
        &eio,
        2,
        json!([{"range": {"start": {"line": line, "character": col}, "end": {"line": line, "character": col + 4}}, "text": "Hand"}]),
    );
    let params = client.diagnostics_for(&main).await;
    let params = if codes(&params).is_empty() {
        client.diagnostics_for(&main).await
    } else {
        params
    };
    assert!(!codes(&params).is_empty(), "{params}");
    // Renamed back: clean again.
    client.change(
        &eio,
        3,
        json!([{"range": {"start": {"line": line, "character": col}, "end": {"line": line, "character": col + 4}}, "text": "Grip"}]),
    );
    until_codes(&mut client, &main, &[]).await;
    client.shutdown().await;
}
