//! In-process protocol tests: the server runs on in-memory pipes and a test
//! client speaks JSON-RPC to it, frames and all, as an editor would.

mod diagnostics;
mod features;
mod reports;
mod robustness;
mod workspace;

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::time::Duration;

use serde_json::{Value, json};
use tokio::sync::mpsc::{UnboundedReceiver, UnboundedSender};

use super::transport::pipe;

/// A test editor.
pub struct TestClient {
    to_server: Option<UnboundedSender<Vec<u8>>>,
    from_server: UnboundedReceiver<Vec<u8>>,
    buf: Vec<u8>,
    /// Notifications and server requests received and not yet looked at.
    pub received: VecDeque<Value>,
    /// Every server-to-client request, in order.
    pub server_requests: Vec<Value>,
    next_id: i64,
    server: Option<tokio::task::JoinHandle<bool>>,
    pub root: PathBuf,
    /// A scratch folder deleted with the client (see [`TestClient::keep`]).
    folder: Option<Scratch>,
}

const TIMEOUT: Duration = Duration::from_secs(20);

#[path = "../../../tests/support/scratch.rs"]
mod scratch;
pub use scratch::{Scratch, scratch as temp_dir};

/// Writes `files` (path relative to `dir`, text) and returns `dir`.
pub fn write_files(dir: &Path, files: &[(&str, &str)]) {
    for (name, text) in files {
        let path = dir.join(name);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent).expect("folder");
        }
        std::fs::write(path, text).expect("write");
    }
}

pub fn uri(path: &Path) -> String {
    tower_lsp_server::ls_types::Uri::from_file_path(path)
        .expect("absolute path")
        .as_str()
        .to_owned()
}

impl TestClient {
    /// Keeps `folder` (the workspace of a client made in a helper) until
    /// the client is dropped.
    pub fn keep(&mut self, folder: Scratch) {
        self.folder = Some(folder);
    }

    /// Starts a server on pipes, without initializing it.
    pub fn start(root: PathBuf) -> TestClient {
        let (to_server, server_in) = pipe();
        let (server_out, from_server) = pipe();
        let server = tokio::spawn(super::serve_with_test_methods(server_in, server_out));
        TestClient {
            to_server: Some(to_server.tx),
            from_server: from_server.into_receiver(),
            buf: Vec::new(),
            received: VecDeque::new(),
            server_requests: Vec::new(),
            next_id: 0,
            server: Some(server),
            root,
            folder: None,
        }
    }

    /// Starts and initializes a server with a workspace folder `root`,
    /// typical client capabilities and `options`.
    pub async fn new(root: PathBuf, options: Value) -> TestClient {
        let capabilities = json!({
            "window": {"workDoneProgress": true},
            "workspace": {"didChangeWatchedFiles": {"dynamicRegistration": true}},
            "general": {"positionEncodings": ["utf-16"]},
        });
        TestClient::with_capabilities(root, capabilities, options).await
    }

    pub async fn with_capabilities(
        root: PathBuf,
        capabilities: Value,
        options: Value,
    ) -> TestClient {
        let mut client = TestClient::start(root.clone());
        let response = client
            .request(
                "initialize",
                json!({
                    "processId": null,
                    "rootUri": uri(&root),
                    "workspaceFolders": [{"uri": uri(&root), "name": "test"}],
                    "capabilities": capabilities,
                    "initializationOptions": options,
                }),
            )
            .await;
        assert!(response.get("result").is_some(), "{response}");
        client.notify("initialized", json!({}));
        // Tests start from a settled state: the workspace indexed (and the
        // publications that follow it scheduled).
        client.indexed().await;
        client
    }

    pub fn send_raw(&mut self, bytes: Vec<u8>) {
        if let Some(tx) = &self.to_server {
            let _ = tx.send(bytes);
        }
    }

    pub fn send(&mut self, message: &Value) {
        let body = serde_json::to_vec(message).expect("json");
        let mut bytes = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
        bytes.extend(body);
        self.send_raw(bytes);
    }

    pub fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// Sends a request and waits for its response (the whole message).
    pub async fn request(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        self.response(id).await
    }

    /// The result of a request that must succeed.
    pub async fn call(&mut self, method: &str, params: Value) -> Value {
        let response = self.request(method, params).await;
        match response.get("result") {
            Some(result) => result.clone(),
            None => panic!("{method} failed: {response}"),
        }
    }

    pub async fn response(&mut self, id: i64) -> Value {
        loop {
            let message = self.read().await;
            if message.get("id") == Some(&json!(id)) && message.get("method").is_none() {
                return message;
            }
            self.received.push_back(message);
        }
    }

    /// Reads the next message, answering server requests on the way.
    async fn read(&mut self) -> Value {
        loop {
            if let Some(message) = self.parse_frame() {
                if message.get("method").is_some() && message.get("id").is_some() {
                    self.server_requests.push(message.clone());
                    let id = message["id"].clone();
                    self.send(&json!({"jsonrpc": "2.0", "id": id, "result": null}));
                }
                return message;
            }
            match tokio::time::timeout(TIMEOUT, self.from_server.recv()).await {
                Ok(Some(chunk)) => self.buf.extend(chunk),
                Ok(None) => panic!("the server closed its output"),
                Err(_) => panic!("no message from the server within {TIMEOUT:?}"),
            }
        }
    }

    fn parse_frame(&mut self) -> Option<Value> {
        let text = String::from_utf8_lossy(&self.buf);
        let header_end = text.find("\r\n\r\n")?;
        let length: usize = text[..header_end]
            .lines()
            .find_map(|l| l.strip_prefix("Content-Length: "))?
            .trim()
            .parse()
            .ok()?;
        let start = header_end + 4;
        if self.buf.len() < start + length {
            return None;
        }
        let body: Vec<u8> = self.buf.drain(..start + length).skip(start).collect();
        Some(serde_json::from_slice(&body).expect("server sent valid JSON"))
    }

    /// Waits for the next notification of `method` (earlier ones of other
    /// methods stay queued).
    pub async fn notification(&mut self, method: &str) -> Value {
        if let Some(i) = self.received.iter().position(|m| m["method"] == method) {
            return self.received.remove(i).expect("present");
        }
        loop {
            let message = self.read().await;
            if message["method"] == method {
                return message;
            }
            self.received.push_back(message);
        }
    }

    /// The next diagnostics published for `uri`.
    pub async fn diagnostics_for(&mut self, uri: &str) -> Value {
        loop {
            let n = self.notification("textDocument/publishDiagnostics").await;
            if n["params"]["uri"] == uri {
                return n["params"].clone();
            }
        }
    }

    /// Waits until the workspace is indexed (the server logs it).
    pub async fn indexed(&mut self) {
        let mut others = Vec::new();
        loop {
            let n = self.notification("window/logMessage").await;
            if n["params"]["message"]
                .as_str()
                .is_some_and(|m| m.starts_with("indexed "))
            {
                break;
            }
            others.push(n);
        }
        self.received.extend(others);
    }

    pub fn open(&mut self, path: &Path, text: &str) -> String {
        let uri = uri(path);
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "rapid", "version": 1, "text": text}}),
        );
        uri
    }

    pub fn change(&mut self, uri: &str, version: i32, changes: Value) {
        self.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": changes}),
        );
    }

    /// Shuts down and exits; returns the server's verdict (clean exit).
    pub async fn shutdown(mut self) -> bool {
        let response = self.request("shutdown", Value::Null).await;
        assert_eq!(response["result"], Value::Null, "{response}");
        self.notify("exit", Value::Null);
        self.finish().await
    }

    /// Waits for the server to stop.
    pub async fn finish(&mut self) -> bool {
        let server = self.server.take().expect("running");
        tokio::time::timeout(TIMEOUT, server)
            .await
            .expect("server stops")
            .expect("server task")
    }

    /// Replaces the workspace folder in a JSON value, for snapshots.
    pub fn redact(&self, value: &Value) -> Value {
        let text = value.to_string();
        let root_uri = uri(&self.root);
        let text = text.replace(&root_uri, "file:///ROOT").replace(
            &self
                .root
                .to_string_lossy()
                .replace('\\', "\\\\")
                .to_string(),
            "/ROOT",
        );
        serde_json::from_str(&text).expect("json")
    }
}

impl Drop for TestClient {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

/// A position in `text` of the `n`th occurrence of `needle` (0-based line,
/// UTF-16 character), plus `shift` characters.
pub fn pos(text: &str, needle: &str, shift: usize) -> Value {
    let at = text
        .find(needle)
        .unwrap_or_else(|| panic!("{needle:?} not found"));
    let before = &text[..at];
    let line = before.matches('\n').count();
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let character = text[line_start..at].encode_utf16().count() + shift;
    json!({"line": line, "character": character})
}

/// The codes of published diagnostics, in order.
pub fn codes(params: &Value) -> Vec<String> {
    params["diagnostics"]
        .as_array()
        .expect("diagnostics")
        .iter()
        .map(|d| d["code"].as_str().unwrap_or("?").to_owned())
        .collect()
}

/// Diagnostics published for `uri` until they have the codes `want`.
pub async fn until_codes(client: &mut TestClient, uri: &str, want: &[&str]) -> Value {
    for _ in 0..20 {
        let params = client.diagnostics_for(uri).await;
        if codes(&params) == want {
            return params;
        }
    }
    panic!("diagnostics of {uri} never became {want:?}");
}

pub fn doc_pos(uri: &str, position: Value) -> Value {
    json!({"textDocument": {"uri": uri}, "position": position})
}

impl TestClient {
    /// Publications until each file of `want` had the codes it wants (in
    /// any order: the files' publications interleave); the last of each.
    pub async fn until_all(&mut self, want: &[(&str, &[&str])]) -> Vec<Value> {
        let mut last: Vec<Option<Value>> = vec![None; want.len()];
        for _ in 0..100 {
            if want
                .iter()
                .zip(&last)
                .all(|((_, wanted), got)| got.as_ref().is_some_and(|p| codes(p) == *wanted))
            {
                return last.into_iter().flatten().collect();
            }
            let n = self.notification("textDocument/publishDiagnostics").await;
            if let Some(i) = want.iter().position(|(u, _)| n["params"]["uri"] == *u) {
                last[i] = Some(n["params"].clone());
            }
        }
        panic!("diagnostics never became {want:?}: {last:?}");
    }

    /// The diagnostics published for `uri` at `version` or later.
    pub async fn diagnostics_at(&mut self, uri: &str, version: i64) -> Value {
        loop {
            let params = self.diagnostics_for(uri).await;
            if params["version"].as_i64().is_some_and(|v| v >= version) {
                return params;
            }
        }
    }
}
