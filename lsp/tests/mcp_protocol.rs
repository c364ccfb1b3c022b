//! `rapid mcp` at the protocol level: a scripted JSON-RPC client drives the
//! built binary over stdio (and once over streamable HTTP) through every
//! tool, the resources and the prompts; bad arguments, paths outside the
//! roots (`--root` and the client's roots), a huge input and runs that
//! would not end. Every tool answer's `structuredContent` is validated
//! against the tool's `outputSchema`.

mod support;

use std::collections::HashMap;
use std::io::{BufRead, BufReader, Read, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

use serde_json::{Value, json};
use support::{scratch, write};

/// How long an answer may take (a debug build on a busy machine).
const PATIENCE: Duration = Duration::from_secs(120);

struct Client {
    child: Child,
    stdin: Option<ChildStdin>,
    messages: Receiver<Value>,
    next: i64,
    /// The output schema of each tool, once listed.
    schemas: HashMap<String, Value>,
    /// The roots this client gives when the server asks (`None`: it has no
    /// roots capability).
    roots: Option<Vec<String>>,
    /// How many times the server asked for the roots.
    roots_asked: usize,
}

impl Client {
    fn start(dir: &Path, args: &[&str], roots: Option<Vec<String>>) -> Client {
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

    fn send(&mut self, message: &Value) {
        let stdin = self.stdin.as_mut().expect("stdin open");
        writeln!(stdin, "{message}").expect("the server reads");
        stdin.flush().expect("flushed");
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// Sends a request and waits for its answer, answering the server's
    /// own requests (`roots/list`) meanwhile.
    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next;
        self.next += 1;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        self.answer(id)
    }

    fn answer(&mut self, id: i64) -> Value {
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
    fn call(&mut self, tool: &str, arguments: Value) -> Value {
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
    fn refused(&mut self, tool: &str, arguments: Value) -> String {
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

fn structured(result: &Value) -> &Value {
    &result["structuredContent"]
}

fn summary(result: &Value) -> &str {
    result["content"][0]["text"].as_str().unwrap_or_default()
}

/// A small project: a task folder whose main module calls a routine of
/// another module, with an EIO.cfg, a test module, and a folder beside it
/// that the roots leave out.
fn project(name: &str) -> support::Scratch {
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

#[test]
fn every_tool_is_listed_with_its_schemas_and_annotations() {
    let dir = project("list");
    let mut c = Client::start(&dir, &[], None);
    let tools = c.request("tools/list", json!({}));
    let tools = tools["result"]["tools"].as_array().expect("tools");
    let mut names: Vec<&str> = tools.iter().filter_map(|t| t["name"].as_str()).collect();
    names.sort_unstable();
    assert_eq!(
        names,
        [
            "check",
            "evaluate",
            "explain_rule",
            "fix",
            "format",
            "list_symbols",
            "lookup_builtin",
            "run",
            "test"
        ]
    );
    for t in tools {
        assert_eq!(t["inputSchema"]["type"], "object", "{t}");
        assert_eq!(t["outputSchema"]["type"], "object", "{t}");
        assert!(
            t["description"].as_str().is_some_and(|d| d.len() > 40),
            "{t}"
        );
        // No tool writes or reaches beyond the machine.
        assert_eq!(t["annotations"]["readOnlyHint"], true, "{t}");
        assert_eq!(t["annotations"]["openWorldHint"], false, "{t}");
    }
}

#[test]
fn check_reads_a_whole_task_and_an_unsaved_text_in_its_task() {
    let dir = project("check");
    let mut c = Client::start(&dir, &["--root", "."], None);
    let folder = c.call("check", json!({"path": "cell"}));
    let r = structured(&folder);
    assert_eq!(r["files_checked"], 3, "{r:#}");
    assert_eq!(r["errors"], 0, "{r:#}");
    // The unsaved text of Main, broken: the rest of its task is read from
    // disk (Add is known), and the findings point into the text.
    let text = "MODULE Main\n  PROC main()\n    VAR num n;\n    n := Add(1, 2) + Missing;\n    n = n + 1;\n  ENDPROC\nENDMODULE\n";
    let unsaved = c.call("check", json!({"path": "cell/Main.mod", "text": text}));
    let r = structured(&unsaved);
    let codes: Vec<&str> = r["findings"]
        .as_array()
        .expect("findings")
        .iter()
        .filter_map(|f| f["code"].as_str())
        .collect();
    assert!(codes.contains(&"E003"), "{r:#}");
    let missing = r["findings"]
        .as_array()
        .and_then(|f| {
            f.iter()
                .find(|f| f["message"].as_str().is_some_and(|m| m.contains("Missing")))
        })
        .expect("the unknown name is reported");
    assert_eq!(
        (missing["line"].clone(), missing["column"].clone()),
        (json!(4), json!(22))
    );
    assert_eq!(missing["file"], "cell/Main.mod");
    assert!(
        !summary(&unsaved).contains("`Add`"),
        "Add is declared in Lib.mod: {}",
        summary(&unsaved)
    );
    let e003 = r["findings"]
        .as_array()
        .and_then(|f| f.iter().find(|f| f["code"] == "E003"))
        .expect("E003");
    assert_eq!(e003["fix"]["safe"], true, "{e003:#}");
    assert_eq!(e003["fix"]["edits"][0]["replacement"], ":=");
    // The file on disk is unchanged, and a text of a new file joins the
    // task of its folder.
    assert!(std::fs::read_to_string(dir.join("cell/Main.mod")).is_ok_and(|t| t.contains("Offs")));
    let new = c.call(
        "check",
        json!({"path": "cell", "text": "MODULE Extra\n  PROC p()\n    TPWrite \"\" \\Num:=Add(1, 1);\n  ENDPROC\nENDMODULE\n"}),
    );
    assert_eq!(structured(&new)["errors"], 0, "{new:#}");
    assert_eq!(structured(&new)["warnings"], 0, "{new:#}");
    assert!(!dir.join("cell/Extra.mod").exists());
    // Alone, the same text does not know Add.
    let alone = c.call(
        "check",
        json!({"text": "MODULE Extra\n  PROC p()\n    TPWrite \"\" \\Num:=Add(1, 1);\n  ENDPROC\nENDMODULE\n"}),
    );
    assert!(summary(&alone).contains("<text>:3:"), "{}", summary(&alone));
    // Rule selection and severities.
    let selected = c.call(
        "check",
        json!({"path": "cell/Main.mod", "text": text, "select": ["E003"]}),
    );
    assert_eq!(
        structured(&selected)["findings"].as_array().map(Vec::len),
        Some(1)
    );
    let limited = c.call(
        "check",
        json!({"path": "cell/Main.mod", "text": text, "limit": 1}),
    );
    assert_eq!(structured(&limited)["truncated"], true);
}

#[test]
fn fix_applies_the_safe_fixes_and_says_what_remains() {
    let dir = project("fix");
    let mut c = Client::start(&dir, &[], None);
    let text = "MODULE Main\n  PROC main()\n    VAR num n;\n    n = 1;\n    n = n + Add(1, 2);\n    TPWrite \"n\" \\Num:=n;\n  ENDPROC\nENDMODULE\n";
    let fixed = c.call("fix", json!({"path": "cell/Main.mod", "text": text}));
    let r = structured(&fixed);
    assert_eq!(r["fixed"], 2, "{r:#}");
    assert_eq!(r["changed"], true);
    assert!(
        r["text"]
            .as_str()
            .is_some_and(|t| t.contains("n := 1;") && t.contains("n := n + Add(1, 2);"))
    );
    assert_eq!(r["remaining"], json!([]), "{r:#}");
    // Without a text: the file's, not written.
    let from_file = c.call("fix", json!({"path": "cell/Lib.mod"}));
    assert_eq!(structured(&from_file)["changed"], false);
    let message = c.refused("fix", json!({}));
    assert!(message.contains("give `text`"), "{message}");
}

#[test]
fn format_lays_a_text_out_and_refuses_broken_code() {
    let dir = project("format");
    let mut c = Client::start(&dir, &[], None);
    let formatted = c.call(
        "format",
        json!({"text": "MODULE m\nPROC main()\nx:=1;\nENDPROC\nENDMODULE\n", "style": "spaced"}),
    );
    assert_eq!(
        structured(&formatted)["text"],
        "MODULE m\n    PROC main()\n        x := 1;\n    ENDPROC\nENDMODULE\n"
    );
    let message = c.refused(
        "format",
        json!({"text": "MODULE m\nPROC main(\nENDMODULE\n"}),
    );
    assert!(message.contains("syntax error"), "{message}");
    let message = c.refused(
        "format",
        json!({"text": "MODULE m\nENDMODULE\n", "style": "wide"}),
    );
    assert!(
        message.contains("not as-written, tight or spaced"),
        "{message}"
    );
}

#[test]
fn rules_builtins_and_expressions_are_looked_up() {
    let dir = project("lookup");
    let mut c = Client::start(&dir, &[], None);
    let rule = c.call("explain_rule", json!({"rule": "unused-data"}));
    assert_eq!(structured(&rule)["code"], "W201");
    assert!(
        structured(&rule)["documentation"]
            .as_str()
            .is_some_and(|d| d.contains("### Why"))
    );
    let message = c.refused("explain_rule", json!({"rule": "W999"}));
    assert!(message.contains("no rule"), "{message}");

    let movel = c.call("lookup_builtin", json!({"name": "movel"}));
    let r = structured(&movel);
    assert_eq!(
        (r["name"].clone(), r["kind"].clone()),
        (json!("MoveL"), json!("instruction"))
    );
    let tool = r["parameters"]
        .as_array()
        .and_then(|p| p.iter().find(|p| p["name"] == "Tool"))
        .expect("Tool");
    assert_eq!(
        (tool["mode"].clone(), tool["type"].clone()),
        (json!("PERS"), json!("tooldata"))
    );
    assert!(r["robotware"].as_str().is_some_and(|v| v.contains('-')));
    let option = c.call("lookup_builtin", json!({"name": "ArcLStart"}));
    assert!(
        structured(&option)["option"]
            .as_str()
            .is_some_and(|o| o.contains("arc")),
        "{option:#}"
    );
    let message = c.refused("lookup_builtin", json!({"name": "MoveLL"}));
    assert!(
        message.contains("did you mean") && message.contains("MoveL"),
        "{message}"
    );
    let message = c.refused(
        "lookup_builtin",
        json!({"name": "MoveL", "robotware": "six"}),
    );
    assert!(message.contains("six"), "{message}");

    let value = c.call(
        "evaluate",
        json!({"expression": "Offs(pHome, 0, 0, 50)", "path": "cell/Main.mod"}),
    );
    assert_eq!(structured(&value)["type"], "robtarget");
    assert!(
        structured(&value)["value"]
            .as_str()
            .is_some_and(|v| v.starts_with("[[600,0,450]")),
        "{value:#}"
    );
    let value = c.call("evaluate", json!({"expression": "10 DIV 3"}));
    assert_eq!(structured(&value)["value"], "3");
    let message = c.refused("evaluate", json!({"expression": "1 / 0"}));
    assert!(message.contains("ERR_DIVZERO"), "{message}");
    let message = c.refused("evaluate", json!({"expression": "Sqrt(2"}));
    assert!(message.contains("column"), "{message}");
}

#[test]
fn symbols_are_listed_per_task_with_data_of_a_type_and_signals() {
    let dir = project("symbols");
    let mut c = Client::start(&dir, &[], None);
    let all = c.call("list_symbols", json!({"path": "cell"}));
    let task = &structured(&all)["tasks"][0];
    assert_eq!(task["task"], "cell");
    let routines: Vec<&str> = task["routines"]
        .as_array()
        .expect("routines")
        .iter()
        .filter_map(|r| r["name"].as_str())
        .collect();
    assert!(
        ["main", "Add", "Ratio", "adds"]
            .iter()
            .all(|r| routines.contains(r)),
        "{routines:?}"
    );
    assert_eq!(task["signals_configured"], true);
    let signals: Vec<&str> = task["signals"]
        .as_array()
        .expect("signals")
        .iter()
        .filter_map(|s| s["name"].as_str())
        .collect();
    assert_eq!(signals, ["distart", "dolamp"]);
    let wobj = c.call(
        "list_symbols",
        json!({"path": "cell/Main.mod", "kinds": ["data"], "type": "WOBJDATA"}),
    );
    let data = structured(&wobj)["tasks"][0]["data"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    assert_eq!(data.len(), 1, "{wobj:#}");
    assert_eq!(
        (
            data[0]["name"].clone(),
            data[0]["storage"].clone(),
            data[0]["file"].clone(),
            data[0]["line"].clone()
        ),
        (
            json!("wobjTable"),
            json!("PERS"),
            json!("cell/Main.mod"),
            json!(3)
        )
    );
    let message = c.refused("list_symbols", json!({"path": "cell", "kinds": ["types"]}));
    assert!(
        message.contains("not routines, data or signals"),
        "{message}"
    );
}

#[test]
fn run_answers_output_errors_with_lines_and_a_trace_summary() {
    let dir = project("run");
    let mut c = Client::start(&dir, &[], None);
    let ran = c.call(
        "run",
        json!({"path": "cell", "signals": [{"name": "diStart", "value": 1}]}),
    );
    let r = structured(&ran);
    assert_eq!(r["status"], "finished", "{r:#}");
    assert_eq!(r["output"], json!(["sum 5", "started"]));
    assert_eq!(r["trace"]["moves"], 1);
    // pHome shifted up, in the work object 500 mm along x.
    assert_eq!(
        r["trace"]["first_moves"][0]["pos"],
        json!([1100.0, 0.0, 450.0])
    );
    write(
        &dir,
        &[(
            "broken/m.mod",
            "MODULE m\n  PROC main()\n    TPWrite \"before\";\n    Divide 0;\n  ENDPROC\n  PROC Divide(num d)\n    TPWrite \"\" \\Num:=1 / d;\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let failed = c.call("run", json!({"path": "broken/m.mod"}));
    let r = structured(&failed);
    assert_eq!(
        (r["status"].clone(), r["success"].clone()),
        (json!("error"), json!(false))
    );
    assert_eq!(r["error"]["errno"], "ERR_DIVZERO", "{r:#}");
    assert_eq!(
        (
            r["error"]["at"]["file"].clone(),
            r["error"]["at"]["line"].clone()
        ),
        (json!("broken/m.mod"), json!(7))
    );
    assert_eq!(r["error"]["stack"][0]["routine"], "Divide");
    assert_eq!(r["output"], json!(["before"]));
    let message = c.refused("run", json!({"path": "cell", "entry": "Add"}));
    assert!(
        message.contains("not a procedure without parameters"),
        "{message}"
    );
    let message = c.refused(
        "run",
        json!({"path": "cell", "signals": [{"name": "di 1", "value": 1}]}),
    );
    assert!(message.contains("not a signal name"), "{message}");
    let message = c.refused("run", json!({"path": "cell", "budgets": {"max_steps": 0}}));
    assert!(message.contains("max_steps"), "{message}");
}

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
fn test_runs_the_tests_of_a_task_with_results() {
    let dir = project("tests");
    let mut c = Client::start(&dir, &[], None);
    let tested = c.call("test", json!({"path": "cell"}));
    let r = structured(&tested);
    assert_eq!(
        (r["passed"].clone(), r["failed"].clone()),
        (json!(2), json!(0)),
        "{r:#}"
    );
    assert_eq!(r["success"], true);
    write(
        &dir,
        &[(
            "cell/Lib_test.mod",
            "MODULE Lib_test\n  PROC adds()\n    AssertEqual Add(2, 2), 5 \\Message:=\"two and two\";\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let tested = c.call("test", json!({"path": "cell", "filter": "adds"}));
    let r = structured(&tested);
    assert_eq!(r["failed"], 1, "{r:#}");
    let t = &r["tests"][0];
    assert_eq!(
        (t["result"].clone(), t["at"]["line"].clone()),
        (json!("fail"), json!(3)),
        "{t:#}"
    );
    assert!(
        t["message"]
            .as_str()
            .is_some_and(|m| m.contains("two and two")),
        "{t:#}"
    );
    assert!(summary(&tested).contains("FAIL"), "{}", summary(&tested));
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
    let unknown = c.request("tools/call", json!({"name": "reach", "arguments": {}}));
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

#[test]
fn resources_and_prompts_are_served() {
    let dir = project("resources");
    let mut c = Client::start(&dir, &[], None);
    let list = c.request("resources/list", json!({}));
    let uris: Vec<&str> = list["result"]["resources"]
        .as_array()
        .expect("resources")
        .iter()
        .filter_map(|r| r["uri"].as_str())
        .collect();
    for uri in [
        "rapid://rules",
        "rapid://builtins",
        "rapid://rules/W201",
        "rapid://test/RapidAssert.sys",
    ] {
        assert!(uris.contains(&uri), "{uri}: {uris:?}");
    }
    let templates = c.request("resources/templates/list", json!({}));
    assert!(
        templates.to_string().contains("rapid://builtins/{name}"),
        "{templates}"
    );
    for (uri, expected) in [
        ("rapid://rules/W201", "unused-data"),
        ("rapid://rules/unused-data", "W201"),
        ("rapid://builtins/Offs", "FUNC robtarget Offs("),
        ("rapid://builtins", "MoveL"),
        ("rapid://rules", "E001"),
        ("rapid://test/RapidAssert.sys", "PROC AssertEqual"),
    ] {
        let read = c.request("resources/read", json!({"uri": uri}));
        let text = read["result"]["contents"][0]["text"]
            .as_str()
            .unwrap_or_default();
        assert!(text.contains(expected), "{uri}: {read}");
    }
    let missing = c.request(
        "resources/read",
        json!({"uri": "rapid://builtins/NoSuchThing"}),
    );
    assert!(missing.get("error").is_some(), "{missing}");
    let prompts = c.request("prompts/list", json!({}));
    let names: Vec<&str> = prompts["result"]["prompts"]
        .as_array()
        .expect("prompts")
        .iter()
        .filter_map(|p| p["name"].as_str())
        .collect();
    assert_eq!(names, ["check-and-fix", "write-test"]);
    let prompt = c.request(
        "prompts/get",
        json!({"name": "write-test", "arguments": {"path": "cell/Lib.mod", "routine": "Ratio"}}),
    );
    let text = prompt["result"]["messages"][0]["content"]["text"]
        .as_str()
        .unwrap_or_default();
    assert!(
        text.contains("Ratio_test") && text.contains("`test`"),
        "{prompt}"
    );
    let prompt = c.request(
        "prompts/get",
        json!({"name": "check-and-fix", "arguments": {"path": "cell/Main.mod"}}),
    );
    assert!(prompt.to_string().contains("cell/Main.mod"), "{prompt}");
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
