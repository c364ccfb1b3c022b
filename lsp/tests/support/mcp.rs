//! A scripted MCP client for the tests of `rapid mcp`: JSON-RPC messages,
//! one a line, over the built binary's stdio; every tool answer checked
//! against the tool's output schema.

use std::collections::HashMap;
use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

use serde_json::{Value, json};

use super::{Scratch, scratch, write};

/// How long an answer may take (a debug build on a busy machine).
pub const PATIENCE: Duration = Duration::from_secs(120);

pub struct Client {
    child: Child,
    pub stdin: Option<ChildStdin>,
    pub messages: Receiver<Value>,
    next: i64,
    /// The output schema of each tool, once listed.
    schemas: HashMap<String, Value>,
    /// The roots this client gives when the server asks (`None`: it has no
    /// roots capability).
    pub roots: Option<Vec<String>>,
    /// How many times the server asked for the roots.
    pub roots_asked: usize,
}

impl Client {
    pub fn start(dir: &Path, args: &[&str], roots: Option<Vec<String>>) -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rapid"))
            .arg("mcp")
            .args(args)
            .current_dir(dir)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("rapid mcp starts");
        let stdin = child.stdin.take();
        let stdout = child.stdout.take().expect("stdout");
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let Ok(line) = line else { break };
                match serde_json::from_str::<Value>(&line) {
                    Ok(v) => {
                        if tx.send(v).is_err() {
                            break;
                        }
                    }
                    Err(e) => panic!("not JSON on stdout: {e}: {line}"),
                }
            }
        });
        let mut client = Client {
            child,
            stdin,
            messages: rx,
            next: 1,
            schemas: HashMap::new(),
            roots,
            roots_asked: 0,
        };
        let capabilities = if client.roots.is_some() {
            json!({"roots": {"listChanged": true}})
        } else {
            json!({})
        };
        let init = client.request(
            "initialize",
            json!({
                "protocolVersion": "2025-06-18",
                "capabilities": capabilities,
                "clientInfo": {"name": "rapid-tests", "version": "0"}
            }),
        );
        assert_eq!(init["result"]["serverInfo"]["name"], "rapid", "{init}");
        client.notify("notifications/initialized", json!({}));
        let tools = client.request("tools/list", json!({}));
        for tool in tools["result"]["tools"].as_array().expect("tools") {
            let name = tool["name"].as_str().expect("a name").to_owned();
            client.schemas.insert(name, tool["outputSchema"].clone());
        }
        client
    }

    pub fn send(&mut self, message: &Value) {
        let stdin = self.stdin.as_mut().expect("stdin open");
        writeln!(stdin, "{message}").expect("the server reads");
        stdin.flush().expect("flushed");
    }

    pub fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// Sends a request and waits for its answer, answering the server's
    /// own requests (`roots/list`) meanwhile.
    pub fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next;
        self.next += 1;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        self.answer(id)
    }

    pub fn answer(&mut self, id: i64) -> Value {
        loop {
            let m = self
                .messages
                .recv_timeout(PATIENCE)
                .unwrap_or_else(|_| panic!("no answer to request {id}"));
            if m.get("method").is_some() && m.get("id").is_some() {
                self.serve(&m);
                continue;
            }
            if m["id"] == json!(id) {
                return m;
            }
        }
    }

    fn serve(&mut self, request: &Value) {
        let result = match (request["method"].as_str(), &self.roots) {
            (Some("roots/list"), Some(roots)) => {
                self.roots_asked += 1;
                let roots: Vec<Value> = roots.iter().map(|uri| json!({"uri": uri})).collect();
                json!({"result": {"roots": roots}})
            }
            (Some("ping"), _) => json!({"result": {}}),
            _ => json!({"error": {"code": -32601, "message": "not here"}}),
        };
        let mut reply = json!({"jsonrpc": "2.0", "id": request["id"].clone()});
        for (k, v) in result.as_object().expect("an object") {
            reply[k] = v.clone();
        }
        self.send(&reply);
    }

    /// Calls a tool; its result, whose `structuredContent` (when it
    /// succeeded) is valid against the tool's output schema.
    pub fn call(&mut self, tool: &str, arguments: Value) -> Value {
        let answer = self.request("tools/call", json!({"name": tool, "arguments": arguments}));
        let result = answer
            .get("result")
            .cloned()
            .unwrap_or_else(|| panic!("{tool}: a protocol error: {answer}"));
        if result["isError"] != json!(true) {
            let schema = self.schemas.get(tool).expect("a listed tool");
            let validator = jsonschema::validator_for(schema).expect("the schema compiles");
            let content = &result["structuredContent"];
            let errors: Vec<String> = validator
                .iter_errors(content)
                .map(|e| format!("{e} at {}", e.instance_path()))
                .collect();
            assert!(errors.is_empty(), "{tool}: {errors:#?}\n{content:#}");
            assert!(
                result["content"][0]["text"].as_str().is_some(),
                "{tool}: a summary"
            );
        }
        result
    }

    /// Calls a tool that must fail; its message.
    pub fn refused(&mut self, tool: &str, arguments: Value) -> String {
        let result = self.call(tool, arguments);
        assert_eq!(result["isError"], json!(true), "{tool}: {result:#}");
        result["content"][0]["text"]
            .as_str()
            .expect("a message")
            .to_owned()
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        drop(self.stdin.take());
        let _ = self.child.wait();
    }
}

pub fn structured(result: &Value) -> &Value {
    &result["structuredContent"]
}

pub fn summary(result: &Value) -> &str {
    result["content"][0]["text"].as_str().unwrap_or_default()
}

/// A small project: a task folder whose main module calls a routine of
/// another module, with an EIO.cfg, a test module, and a folder beside it
/// that the roots leave out.
pub fn project(name: &str) -> Scratch {
    let dir = scratch(name);
    write(
        &dir,
        &[
            (
                "cell/Main.mod",
                "MODULE Main\n  PERS tooldata tGripper := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];\n  PERS wobjdata wobjTable := [FALSE,TRUE,\"\",[[500,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];\n  CONST robtarget pHome := [[600,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  PROC main()\n    TPWrite \"sum \" \\Num:=Add(2, 3);\n    IF DInput(diStart) = 1 TPWrite \"started\";\n    MoveL Offs(pHome, 0, 0, 50), v100, fine, tGripper \\WObj:=wobjTable;\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "cell/Lib.mod",
                "MODULE Lib\n  FUNC num Add(num a, num b)\n    RETURN a + b;\n  ENDFUNC\n  FUNC num Ratio(num a, num b)\n    RETURN a / b;\n  ENDFUNC\nENDMODULE\n",
            ),
            (
                "cell/Lib_test.mod",
                "MODULE Lib_test\n  PROC adds()\n    AssertEqual Add(2, 2), 4;\n  ENDPROC\n  PROC divides()\n    AssertEqual Ratio(6, 3), 2 \\Message:=\"six by three\";\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "cell/EIO.cfg",
                "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"diStart\" -SignalType \"DI\" -Device \"d1\"\n      -Name \"doLamp\" -SignalType \"DO\" -Device \"d1\"\n",
            ),
            (
                "secret/Secret.mod",
                "MODULE Secret\n  PROC main()\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    dir
}
