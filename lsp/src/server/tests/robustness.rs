//! Bad input gets an error or an empty answer, and the server goes on.

use serde_json::{Value, json};

use super::{TestClient, doc_pos, temp_dir, uri};

const TEXT: &str = "MODULE Main\n  PROC main()\n    Stop;\n  ENDPROC\nENDMODULE\n";

/// The server still answers properly.
async fn still_serving(client: &mut TestClient, uri: &str) {
    let symbols = client
        .request(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": uri}}),
        )
        .await;
    assert!(symbols.get("result").is_some(), "{symbols}");
}

fn error_code(response: &Value) -> i64 {
    response["error"]["code"]
        .as_i64()
        .unwrap_or_else(|| panic!("an error: {response}"))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn malformed_messages_and_unknown_methods() {
    let dir = temp_dir("bad-json");
    let mut client = TestClient::new(dir.to_path_buf(), json!({})).await;
    let uri = client.open(&dir.join("Main.mod"), TEXT);
    // Not JSON at all: a parse error, answered with a null id.
    let junk = b"{\"jsonrpc\": \"2.0\", \"id\": 99, \"method\": ";
    let mut bytes = format!("Content-Length: {}\r\n\r\n", junk.len()).into_bytes();
    bytes.extend(junk);
    client.send_raw(bytes);
    // Invalid UTF-8 in the body.
    let bad = b"{\"jsonrpc\":\"2.0\",\"method\":\"x\xff\xfe\"}";
    let mut bytes = format!("Content-Length: {}\r\n\r\n", bad.len()).into_bytes();
    bytes.extend(bad);
    client.send_raw(bytes);
    // Valid JSON, but not a JSON-RPC message.
    client.send(&json!({"hello": "world"}));
    still_serving(&mut client, &uri).await;
    let errors: Vec<i64> = client
        .received
        .iter()
        .filter(|m| m.get("error").is_some())
        .map(error_code)
        .collect();
    assert_eq!(errors.len(), 3, "{:?}", client.received);
    assert!(
        errors.iter().all(|&c| c == -32700 || c == -32600),
        "{errors:?}"
    );
    // An unknown request: method not found. An unknown notification: ignored.
    let response = client.request("rapid/noSuchMethod", json!({})).await;
    assert_eq!(error_code(&response), -32601);
    client.notify("rapid/noSuchNotification", json!({}));
    // The same for the optional `$/` methods (the framework used to leave
    // such a request unanswered).
    let response = client.request("$/noSuchRequest", json!({})).await;
    assert_eq!(error_code(&response), -32601, "{response}");
    client.notify("$/noSuchNotification", json!({}));
    // Wrong parameters for a known method.
    let response = client
        .request("textDocument/hover", json!({"nonsense": true}))
        .await;
    assert_eq!(error_code(&response), -32602);
    still_serving(&mut client, &uri).await;
    assert!(client.shutdown().await);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn unknown_and_deleted_files_get_empty_answers() {
    let dir = temp_dir("bad-file");
    let mut client = TestClient::new(dir.to_path_buf(), json!({})).await;
    let missing = uri(&dir.join("Nope.mod"));
    for method in [
        "textDocument/hover",
        "textDocument/definition",
        "textDocument/completion",
        "textDocument/signatureHelp",
        "textDocument/references",
    ] {
        let mut params = doc_pos(&missing, json!({"line": 0, "character": 0}));
        if method == "textDocument/references" {
            params["context"] = json!({"includeDeclaration": true});
        }
        let result = client.call(method, params).await;
        assert_eq!(result, Value::Null, "{method}");
    }
    for method in [
        "textDocument/documentSymbol",
        "textDocument/foldingRange",
        "textDocument/semanticTokens/full",
        "textDocument/formatting",
    ] {
        let mut params = json!({"textDocument": {"uri": missing}});
        if method == "textDocument/formatting" {
            params["options"] = json!({"tabSize": 4, "insertSpaces": true});
        }
        assert_eq!(client.call(method, params).await, Value::Null, "{method}");
    }
    // Changes and closes of documents never opened are ignored.
    client.change(&missing, 2, json!([{"text": "MODULE X\nENDMODULE\n"}]));
    client.notify(
        "textDocument/didClose",
        json!({"textDocument": {"uri": missing}}),
    );
    // A non-file URI works like any other document.
    let untitled = "untitled:Untitled-1";
    client.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": untitled, "languageId": "rapid", "version": 1, "text": TEXT}}),
    );
    let params = client.diagnostics_for(untitled).await;
    assert_eq!(params["diagnostics"], json!([]));
    still_serving(&mut client, untitled).await;
    assert!(client.shutdown().await);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn positions_past_the_end_are_clamped() {
    let dir = temp_dir("bad-pos");
    let mut client = TestClient::new(dir.to_path_buf(), json!({})).await;
    let uri = client.open(&dir.join("Main.mod"), TEXT);
    for position in [
        json!({"line": 2, "character": 500}),
        json!({"line": 99, "character": 0}),
        json!({"line": 4294967295u32, "character": 4294967295u32}),
    ] {
        for method in [
            "textDocument/hover",
            "textDocument/completion",
            "textDocument/definition",
        ] {
            let response = client
                .request(method, doc_pos(&uri, position.clone()))
                .await;
            assert!(
                response.get("result").is_some(),
                "{method} {position}: {response}"
            );
        }
    }
    // An edit whose range lies past the end appends at the end.
    client.change(
        &uri,
        2,
        json!([{"range": {"start": {"line": 50, "character": 3}, "end": {"line": 60, "character": 0}}, "text": "! end\n"}]),
    );
    let params = client.diagnostics_at(&uri, 2).await;
    assert_eq!(params["version"], 2);
    still_serving(&mut client, &uri).await;
    assert!(client.shutdown().await);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_huge_file_is_kept_but_not_analysed() {
    let dir = temp_dir("bad-huge");
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let mut text = String::from("MODULE Huge\n");
    let line = "  ! ........................................................................\n";
    while text.len() < 50 * 1024 * 1024 {
        text.push_str(line);
    }
    text.push_str("ENDMODULE\n");
    let uri = client.open(&dir.join("Huge.mod"), &text);
    let params = client.diagnostics_for(&uri).await;
    let message = params["diagnostics"][0]["message"].as_str().unwrap_or("");
    assert!(message.contains("too large"), "{message}");
    let hover = client
        .call(
            "textDocument/hover",
            doc_pos(&uri, json!({"line": 5, "character": 4})),
        )
        .await;
    assert_eq!(hover, Value::Null);
    // Edits still apply.
    client.change(
        &uri,
        2,
        json!([{"range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}}, "text": "! top\n"}]),
    );
    let params = client.diagnostics_at(&uri, 2).await;
    assert_eq!(params["version"], 2);
    let small = client.open(&dir.join("Small.mod"), TEXT);
    still_serving(&mut client, &small).await;
    assert!(client.shutdown().await);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_panicking_handler_answers_an_error_and_the_server_goes_on() {
    let dir = temp_dir("bad-panic");
    let mut client = TestClient::new(dir.to_path_buf(), json!({})).await;
    let uri = client.open(&dir.join("Main.mod"), TEXT);
    let response = client.request("rapid/testPanic", Value::Null).await;
    assert_eq!(error_code(&response), -32603, "{response}");
    // The panic is logged.
    loop {
        let log = client.notification("window/logMessage").await;
        if log["params"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("deliberate test panic"))
        {
            break;
        }
    }
    still_serving(&mut client, &uri).await;
    assert!(client.shutdown().await);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn shutdown_and_exit_follow_the_protocol() {
    // Requests before initialize are refused.
    let dir = temp_dir("bad-lifecycle");
    let mut client = TestClient::start(dir.to_path_buf());
    let response = client
        .request(
            "textDocument/hover",
            doc_pos("file:///x.mod", json!({"line": 0, "character": 0})),
        )
        .await;
    assert_eq!(error_code(&response), -32002);
    drop(client);

    // After shutdown, requests are invalid; exit then ends the server with
    // success.
    let dir = temp_dir("bad-lifecycle2");
    let mut client = TestClient::new(dir.to_path_buf(), json!({})).await;
    assert_eq!(client.call("shutdown", Value::Null).await, Value::Null);
    let response = client
        .request(
            "textDocument/hover",
            doc_pos("file:///x.mod", json!({"line": 0, "character": 0})),
        )
        .await;
    assert_eq!(error_code(&response), -32600);
    client.notify("exit", Value::Null);
    assert!(client.finish().await);

    // Exit without shutdown: the server stops, reporting an unclean exit.
    let dir = temp_dir("bad-lifecycle3");
    let mut client = TestClient::new(dir.to_path_buf(), json!({})).await;
    client.notify("exit", Value::Null);
    assert!(!client.finish().await);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn position_encoding_is_negotiated() {
    let dir = temp_dir("encoding");
    let mut client = TestClient::start(dir.to_path_buf());
    let init = client
        .call(
            "initialize",
            json!({"capabilities": {"general": {"positionEncodings": ["utf-8", "utf-16"]}}}),
        )
        .await;
    assert_eq!(init["capabilities"]["positionEncoding"], "utf-8");
    client.notify("initialized", json!({}));
    // In UTF-8, columns are bytes: `é` counts two.
    let text = "MODULE Main\n  PROC main()\n    TPWrite \"é\" + nothere;\n  ENDPROC\nENDMODULE\n";
    let uri = client.open(&dir.join("Main.mod"), text);
    let params = client.diagnostics_for(&uri).await;
    assert_eq!(
        params["diagnostics"][0]["range"]["start"],
        json!({"line": 2, "character": 19}),
        "{params}"
    );
    // Replace the two bytes of `é` by `e`.
    client.change(
        &uri,
        2,
        json!([{"range": {"start": {"line": 2, "character": 13}, "end": {"line": 2, "character": 15}}, "text": "e"}]),
    );
    let params = client.diagnostics_at(&uri, 2).await;
    assert_eq!(
        params["diagnostics"][0]["range"]["start"],
        json!({"line": 2, "character": 18}),
        "{params}"
    );
    assert!(client.shutdown().await);

    // Without the offer, UTF-16.
    let dir = temp_dir("encoding2");
    let mut client = TestClient::start(dir.to_path_buf());
    let init = client.call("initialize", json!({"capabilities": {}})).await;
    assert_eq!(init["capabilities"]["positionEncoding"], "utf-16");
}
