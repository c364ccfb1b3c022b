//! What `rapid mcp` refuses or bounds, at the protocol level: bad
//! arguments, paths outside `--root` and the client's roots, a huge input,
//! runs that would not end; and the same tools over streamable HTTP on
//! loopback.

mod support;

use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Command, Stdio};
use std::time::Duration;

use serde_json::{Value, json};
use support::mcp::{Client, PATIENCE, project, structured, summary};
use support::{scratch, write};

#[test]
fn runs_that_would_not_end_stop_at_their_budgets() {
    let dir = scratch("endless");
    write(
        &dir,
        &[(
            "loop/m.mod",
            "MODULE m\n  PROC main()\n    VAR num n;\n    WHILE TRUE DO\n      n := n + 1;\n      IF n MOD 100000 = 0 TPWrite \"n \" \\Num:=n;\n    ENDWHILE\n  ENDPROC\n  PROC waits()\n    WHILE TRUE DO\n      WaitTime 1;\n    ENDWHILE\n  ENDPROC\n  PROC recurses()\n    recurses;\n  ENDPROC\n  PROC test_endless()\n    main;\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let mut c = Client::start(&dir, &[], None);
    let ran = c.call(
        "run",
        json!({"path": "loop", "budgets": {"max_steps": 200000}}),
    );
    let r = structured(&ran);
    assert_eq!(r["status"], "budget", "{r:#}");
    assert!(
        r["trace"]["steps"].as_u64().is_some_and(|s| s <= 200_001),
        "{r:#}"
    );
    assert!(
        r["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("statements")),
        "{r:#}"
    );
    // The default budget stops it too.
    let ran = c.call("run", json!({"path": "loop"}));
    assert_eq!(structured(&ran)["status"], "budget");
    let waited = c.call(
        "run",
        json!({"path": "loop", "entry": "waits", "budgets": {"max_time": 30}}),
    );
    let r = structured(&waited);
    assert_eq!(r["status"], "budget", "{r:#}");
    assert!(
        r["trace"]["simulated_seconds"]
            .as_f64()
            .is_some_and(|t| t <= 31.0),
        "{r:#}"
    );
    let deep = c.call(
        "run",
        json!({"path": "loop", "entry": "recurses", "budgets": {"max_depth": 50}}),
    );
    assert_eq!(structured(&deep)["status"], "budget", "{deep:#}");
    let tested = c.call(
        "test",
        json!({"path": "loop", "budgets": {"max_steps": 100000}}),
    );
    let r = structured(&tested);
    assert_eq!(
        (r["errors"].clone(), r["success"].clone()),
        (json!(1), json!(false)),
        "{r:#}"
    );
    let message = c.refused(
        "run",
        json!({"path": "loop", "budgets": {"max_steps": 1_000_000_000_u64}}),
    );
    assert!(message.contains("max_steps"), "{message}");
}

#[test]
fn bad_arguments_are_refused_and_the_server_goes_on() {
    let dir = project("bad");
    let mut c = Client::start(&dir, &[], None);
    for (tool, args, expected) in [
        ("check", json!({"pth": "cell"}), "unknown field `pth`"),
        ("check", json!({"path": 12}), "invalid type"),
        ("check", json!({}), "give `path`, `text`, or both"),
        (
            "check",
            json!({"path": "cell", "min_severity": "fatal"}),
            "min_severity",
        ),
        (
            "check",
            json!({"path": "nowhere.mod"}),
            "no such file or folder",
        ),
        ("explain_rule", json!({}), "missing field `rule`"),
        (
            "run",
            json!({"path": "cell", "entry": "nothing"}),
            "no procedure nothing",
        ),
        (
            "test",
            json!({"path": "cell", "budgets": {"max_time": -1}}),
            "max_time",
        ),
    ] {
        let message = c.refused(tool, args);
        assert!(message.contains(expected), "{tool}: {message}");
    }
    let unknown = c.request("tools/call", json!({"name": "teleport", "arguments": {}}));
    assert!(
        unknown.get("error").is_some() || unknown["result"]["isError"] == true,
        "{unknown}"
    );
    let missing_arguments = c.request("tools/call", json!({"name": "check"}));
    assert!(
        missing_arguments.get("error").is_some() || missing_arguments["result"]["isError"] == true,
        "{missing_arguments}"
    );
    // A request that is not one: an error without an id (the SDK cannot
    // tell which request it was).
    c.send(
        &json!({"jsonrpc": "2.0", "id": 999, "method": "tools/call", "params": "not an object"}),
    );
    let bad = c
        .messages
        .recv_timeout(PATIENCE)
        .expect("an answer to a malformed request");
    assert_eq!(bad["error"]["code"], -32600, "{bad}");
    // Still serving.
    let ok = c.call("explain_rule", json!({"rule": "E001"}));
    assert_eq!(structured(&ok)["name"], "syntax-error");
}

#[test]
fn paths_outside_the_roots_are_refused_by_every_tool() {
    let dir = project("roots");
    let secret = dir.join("secret/Secret.mod");
    let secret = secret.to_str().expect("UTF-8");
    #[cfg(unix)]
    std::os::unix::fs::symlink(dir.join("secret"), dir.join("cell/linked")).expect("a link");
    let mut c = Client::start(&dir, &["--root", "cell"], None);
    for path in ["../secret/Secret.mod", secret, "/", "linked/Secret.mod"] {
        for (tool, args) in [
            ("check", json!({"path": path})),
            (
                "check",
                json!({"path": path, "text": "MODULE x\nENDMODULE\n"}),
            ),
            ("fix", json!({"path": path})),
            ("format", json!({"path": path})),
            ("list_symbols", json!({"path": path})),
            ("evaluate", json!({"expression": "1", "path": path})),
            ("run", json!({"path": path})),
            ("test", json!({"path": path})),
            ("reach", json!({"path": path, "target": "p10"})),
        ] {
            if cfg!(not(unix)) && path.starts_with("linked") {
                continue;
            }
            let message = c.refused(tool, args);
            assert!(
                message.contains("outside the folders this server may read"),
                "{tool} {path}: {message}"
            );
        }
    }
    // Inside, relative to the root: fine. The link's folder is not walked.
    let inside = c.call("check", json!({"path": "."}));
    assert_eq!(structured(&inside)["files_checked"], 3, "{inside:#}");
}

#[test]
fn client_roots_are_asked_for_and_bound_what_is_read() {
    let dir = project("client-roots");
    let cell = std::fs::canonicalize(dir.join("cell")).expect("real");
    let uri = format!("file://{}", cell.display());
    let mut c = Client::start(&dir, &[], Some(vec![uri]));
    let inside = c.call("check", json!({"path": "Main.mod"}));
    assert_eq!(structured(&inside)["files_checked"], 1, "{inside:#}");
    let message = c.refused("check", json!({"path": "../secret"}));
    assert!(message.contains("outside the folders"), "{message}");
    assert_eq!(c.roots_asked, 1);
    // Asked again after the client says they changed.
    c.roots = Some(vec![format!(
        "file://{}",
        std::fs::canonicalize(dir.join("secret"))
            .expect("real")
            .display()
    )]);
    c.notify("notifications/roots/list_changed", json!({}));
    // The notification and the next call are handled concurrently: the
    // server asks again once it has seen the notification.
    let mut now = Value::Null;
    for _ in 0..50 {
        now = c.call("check", json!({"path": "Secret.mod"}));
        if c.roots_asked == 2 {
            break;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    if structured(&now)["files_checked"] != 1 {
        now = c.call("check", json!({"path": "Secret.mod"}));
    }
    assert_eq!(structured(&now)["files_checked"], 1, "{now:#}");
    assert_eq!(c.roots_asked, 2);
}

#[test]
fn a_huge_input_is_answered_clearly() {
    let dir = project("huge");
    let mut c = Client::start(&dir, &[], None);
    // Larger than any module a controller loads: refused with the limit.
    let mut huge = String::from("MODULE huge\n");
    while huge.len() < 9 * 1024 * 1024 {
        huge.push_str("  ! a comment line that makes the module larger than a controller loads\n");
    }
    huge.push_str("ENDMODULE\n");
    let checked = c.call("check", json!({"text": huge}));
    let r = structured(&checked);
    assert_eq!(r["files_checked"], 0, "{}", summary(&checked));
    assert!(
        r["skipped"][0]
            .as_str()
            .is_some_and(|s| s.contains("more than the 8 MB")),
        "{}",
        summary(&checked)
    );
    // A large real-sized module (2 MB, 20,000 routines) is checked.
    let mut large = String::from("MODULE large\n");
    for i in 0..20_000 {
        large.push_str(&format!(
            "  PROC p{i}()\n    TPWrite \"{i}\";\n    p{};\n  ENDPROC\n",
            (i + 1) % 20_000
        ));
    }
    large.push_str("ENDMODULE\n");
    let checked = c.call("check", json!({"text": large, "limit": 5}));
    assert_eq!(
        structured(&checked)["files_checked"],
        1,
        "{}",
        summary(&checked)
    );
    assert_eq!(structured(&checked)["errors"], 0, "{}", summary(&checked));
    // A message past the transport's limit is dropped, and the server goes on.
    let line = format!(
        "{{\"jsonrpc\":\"2.0\",\"id\":77,\"method\":\"tools/call\",\"params\":{{\"name\":\"check\",\"arguments\":{{\"text\":\"{}\"}}}}}}",
        "x".repeat(65 * 1024 * 1024)
    );
    {
        let stdin = c.stdin.as_mut().expect("stdin");
        stdin.write_all(line.as_bytes()).expect("written");
        stdin.write_all(b"\n").expect("written");
    }
    let ok = c.call("explain_rule", json!({"rule": "W201"}));
    assert_eq!(structured(&ok)["code"], "W201");
}

/// One HTTP request over a fresh connection: status, headers, body.
fn http(addr: &str, body: &Value, session: Option<&str>) -> (u16, String, String) {
    let mut stream = std::net::TcpStream::connect(addr).expect("the server listens");
    stream.set_read_timeout(Some(PATIENCE)).expect("a timeout");
    let body = body.to_string();
    let mut head = format!(
        "POST /mcp HTTP/1.1\r\nHost: {addr}\r\nContent-Type: application/json\r\nAccept: application/json, text/event-stream\r\nContent-Length: {}\r\nConnection: close\r\n",
        body.len()
    );
    if let Some(s) = session {
        head.push_str(&format!(
            "Mcp-Session-Id: {s}\r\nMcp-Protocol-Version: 2025-06-18\r\n"
        ));
    }
    head.push_str("\r\n");
    stream.write_all(head.as_bytes()).expect("sent");
    stream.write_all(body.as_bytes()).expect("sent");
    let mut answer = String::new();
    let _ = stream.read_to_string(&mut answer);
    let (head, rest) = answer.split_once("\r\n\r\n").unwrap_or((&answer, ""));
    let status = head
        .split(' ')
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    (status, head.to_owned(), rest.to_owned())
}

/// The JSON-RPC message in a body (JSON, or an event stream, possibly
/// chunked).
fn message_in(body: &str) -> Value {
    body.lines()
        .filter_map(|l| l.strip_prefix("data:").map(str::trim).or(Some(l.trim())))
        .filter(|l| l.starts_with('{'))
        .filter_map(|l| serde_json::from_str::<Value>(l).ok())
        .find(|m| m.get("id").is_some())
        .unwrap_or(Value::Null)
}

#[test]
fn streamable_http_serves_the_same_tools_on_loopback_only() {
    let dir = project("http");
    let refused = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(["mcp", "--http", "0.0.0.0:0"])
        .output()
        .expect("runs");
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("loopback"));
    let mut child = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(["mcp", "--http", "127.0.0.1:0"])
        .current_dir(&*dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("starts");
    let mut stderr = BufReader::new(child.stderr.take().expect("stderr"));
    let mut line = String::new();
    stderr.read_line(&mut line).expect("the address");
    let addr = line
        .trim()
        .strip_prefix("rapid mcp: serving http://")
        .and_then(|s| s.strip_suffix("/mcp"))
        .unwrap_or_else(|| panic!("{line}"))
        .to_owned();
    let (status, head, body) = http(
        &addr,
        &json!({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {
            "protocolVersion": "2025-06-18", "capabilities": {},
            "clientInfo": {"name": "rapid-tests", "version": "0"}}}),
        None,
    );
    assert_eq!(status, 200, "{head}\n{body}");
    assert_eq!(
        message_in(&body)["result"]["serverInfo"]["name"],
        "rapid",
        "{body}"
    );
    let session = head
        .lines()
        .find_map(|l| {
            let (k, v) = l.split_once(':')?;
            k.eq_ignore_ascii_case("mcp-session-id")
                .then(|| v.trim().to_owned())
        })
        .expect("a session");
    let (status, _, _) = http(
        &addr,
        &json!({"jsonrpc": "2.0", "method": "notifications/initialized"}),
        Some(&session),
    );
    assert!((200..300).contains(&status), "{status}");
    let (status, _, body) = http(
        &addr,
        &json!({"jsonrpc": "2.0", "id": 2, "method": "tools/call", "params": {
            "name": "check", "arguments": {"path": "cell/Main.mod", "text": "MODULE Main\n  PROC main()\n    x = 1;\n  ENDPROC\nENDMODULE\n"}}}),
        Some(&session),
    );
    assert_eq!(status, 200, "{body}");
    let answer = message_in(&body);
    assert!(answer.to_string().contains("E003"), "{body}");
    let (status, _, body) = http(
        &addr,
        &json!({"jsonrpc": "2.0", "id": 3, "method": "tools/call", "params": {
            "name": "check", "arguments": {"path": "/etc"}}}),
        Some(&session),
    );
    assert_eq!(status, 200);
    assert!(
        message_in(&body)
            .to_string()
            .contains("outside the folders"),
        "{body}"
    );
    let _ = child.kill();
    let _ = child.wait();
}
