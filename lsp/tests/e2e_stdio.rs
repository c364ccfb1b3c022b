//! End to end: start `rapid lsp`, speak to it over stdio as an editor would,
//! on the two-module example in `examples/palletizer/`.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

use serde_json::{Value, json};

struct Editor {
    child: Child,
    stdin: ChildStdin,
    messages: Receiver<Value>,
    next_id: i64,
    queued: Vec<Value>,
}

impl Editor {
    fn start() -> Editor {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rapid"))
            .args(["lsp", "--stdio"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("rapid lsp starts");
        let stdin = child.stdin.take().expect("stdin");
        let stdout = child.stdout.take().expect("stdout");
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(stdout);
            loop {
                let mut length = None;
                loop {
                    let mut line = String::new();
                    if reader.read_line(&mut line).unwrap_or(0) == 0 {
                        return;
                    }
                    let line = line.trim_end();
                    if line.is_empty() {
                        break;
                    }
                    if let Some(v) = line.strip_prefix("Content-Length: ") {
                        length = v.parse::<usize>().ok();
                    }
                }
                let mut body = vec![0; length.expect("a Content-Length header")];
                reader.read_exact(&mut body).expect("body");
                let value: Value = serde_json::from_slice(&body).expect("JSON");
                if tx.send(value).is_err() {
                    return;
                }
            }
        });
        Editor {
            child,
            stdin,
            messages: rx,
            next_id: 0,
            queued: Vec::new(),
        }
    }

    fn send(&mut self, message: Value) {
        let body = message.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).expect("write");
        self.stdin.flush().expect("flush");
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    fn next(&mut self) -> Value {
        let message = self
            .messages
            .recv_timeout(Duration::from_secs(30))
            .expect("a message from the server");
        if message.get("method").is_some() && message.get("id").is_some() {
            // A request from the server (progress, registration): accept it.
            let id = message["id"].clone();
            self.send(json!({"jsonrpc": "2.0", "id": id, "result": null}));
        }
        message
    }

    fn call(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let m = self.next();
            if m["id"] == id && m.get("method").is_none() {
                assert!(m.get("error").is_none(), "{method}: {m}");
                return m["result"].clone();
            }
            self.queued.push(m);
        }
    }

    fn wait_for(&mut self, pred: impl Fn(&Value) -> bool) -> Value {
        if let Some(i) = self.queued.iter().position(&pred) {
            return self.queued.remove(i);
        }
        loop {
            let m = self.next();
            if pred(&m) {
                return m;
            }
            self.queued.push(m);
        }
    }

    fn diagnostics(&mut self, uri: &str, version: i64) -> Value {
        self.wait_for(|m| {
            m["method"] == "textDocument/publishDiagnostics"
                && m["params"]["uri"] == uri
                && m["params"]["version"].as_i64() >= Some(version)
        })["params"]["diagnostics"]
            .clone()
    }
}

fn file_uri(path: &Path) -> String {
    let path = path.to_string_lossy().replace('\\', "/");
    if path.starts_with('/') {
        format!("file://{path}")
    } else {
        format!("file:///{path}")
    }
}

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
