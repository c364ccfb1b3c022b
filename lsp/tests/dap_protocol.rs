//! `rapid dap` at the protocol level: a client drives the built binary
//! over stdin and stdout through a debugging session (breakpoint with a
//! condition, stack, scopes, variables, evaluate, set variable, step over,
//! step out, continue, a run-time error stopping at its line, pause), the
//! path page a launch with `plot` writes, and a backup's two tasks as two
//! threads.

mod support;

use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

use serde_json::{Value, json};
use support::{scratch, write};

struct Client {
    child: Child,
    stdin: ChildStdin,
    messages: Receiver<Value>,
    seq: i64,
    /// Events received while waiting for something else.
    events: Vec<Value>,
}

fn read_message(input: &mut impl BufRead) -> Option<Value> {
    let mut length = 0;
    loop {
        let mut line = String::new();
        if input.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim();
        if line.is_empty() {
            break;
        }
        if let Some(n) = line.strip_prefix("Content-Length:") {
            length = n.trim().parse().ok()?;
        }
    }
    let mut body = vec![0; length];
    input.read_exact(&mut body).ok()?;
    serde_json::from_slice(&body).ok()
}

impl Client {
    fn start() -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rapid"))
            .arg("dap")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("rapid dap starts");
        let stdin = child.stdin.take().expect("stdin");
        let stdout = child.stdout.take().expect("stdout");
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            let mut input = BufReader::new(stdout);
            while let Some(m) = read_message(&mut input) {
                if tx.send(m).is_err() {
                    break;
                }
            }
        });
        Client {
            child,
            stdin,
            messages: rx,
            seq: 0,
            events: Vec::new(),
        }
    }

    fn next(&mut self) -> Value {
        self.messages
            .recv_timeout(Duration::from_secs(30))
            .expect("a message from the adapter within 30 s")
    }

    /// Sends a request and returns its response (events meanwhile are kept).
    fn request(&mut self, command: &str, arguments: Value) -> Value {
        self.seq += 1;
        let body =
            json!({"seq": self.seq, "type": "request", "command": command, "arguments": arguments})
                .to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).expect("written");
        self.stdin.flush().expect("flushed");
        loop {
            let m = self.next();
            if m["type"] == "response" && m["request_seq"] == self.seq {
                assert_eq!(m["command"], command);
                return m;
            }
            self.events.push(m);
        }
    }

    fn ok(&mut self, command: &str, arguments: Value) -> Value {
        let r = self.request(command, arguments);
        assert_eq!(r["success"], true, "{r}");
        r["body"].clone()
    }

    /// Waits for an event (or takes one received earlier).
    fn event(&mut self, name: &str) -> Value {
        if let Some(i) = self.events.iter().position(|e| e["event"] == name) {
            return self.events.remove(i)["body"].clone();
        }
        loop {
            let m = self.next();
            if m["type"] == "event" && m["event"] == name {
                return m["body"].clone();
            }
            self.events.push(m);
        }
    }

    fn top_line(&mut self) -> (String, u64) {
        let st = self.ok("stackTrace", json!({"threadId": 1}));
        let f = &st["stackFrames"][0];
        (
            f["name"].as_str().unwrap_or("").to_owned(),
            f["line"].as_u64().unwrap_or(0),
        )
    }

    /// The variables of a scope of frame 0, as name = value.
    fn scope(&mut self, name: &str) -> Vec<String> {
        let scopes = self.ok("scopes", json!({"frameId": 0}));
        let r = scopes["scopes"]
            .as_array()
            .and_then(|s| s.iter().find(|s| s["name"] == name))
            .map(|s| s["variablesReference"].clone())
            .expect("the scope");
        let vars = self.ok("variables", json!({"variablesReference": r}));
        vars["variables"]
            .as_array()
            .expect("variables")
            .iter()
            .map(|v| {
                format!(
                    "{} = {}",
                    v["name"].as_str().unwrap_or(""),
                    v["value"].as_str().unwrap_or("")
                )
            })
            .collect()
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

const PROGRAM: &str = "MODULE dbg
  VAR num total := 0;
  PROC main()
    VAR num i := 0;
    FOR k FROM 1 TO 3 DO
      total := Add2(total, k);
    ENDFOR
    TPWrite \"total \"\\Num:=total;
    i := 1 / (total - 28);
  ENDPROC
  FUNC num Add2(num a, num b)
    VAR num r;
    r := a + b * 2;
    RETURN r;
  ENDFUNC
ENDMODULE
";

#[test]
fn a_debugging_session_breaks_inspects_changes_steps_and_stops_on_errors() {
    let dir = scratch("dap-session");
    write(&dir, &[("dbg.mod", PROGRAM)]);
    let path = std::fs::canonicalize(dir.join("dbg.mod")).expect("the module");
    let path = path.to_string_lossy().into_owned();
    let mut c = Client::start();
    let caps = c.ok("initialize", json!({"adapterID": "rapid"}));
    assert_eq!(caps["supportsConditionalBreakpoints"], true);
    c.event("initialized");
    c.ok("launch", json!({"program": path}));
    let bps = c.ok(
        "setBreakpoints",
        json!({"source": {"path": path}, "breakpoints": [{"line": 13, "condition": "b = 2"}]}),
    );
    assert_eq!(bps["breakpoints"][0]["verified"], true);
    c.ok("configurationDone", json!({}));

    // The breakpoint in Add2, on its second call.
    assert_eq!(c.event("stopped")["reason"], "breakpoint");
    let st = c.ok("stackTrace", json!({"threadId": 1}));
    let frames: Vec<(String, u64)> = st["stackFrames"]
        .as_array()
        .expect("frames")
        .iter()
        .map(|f| {
            (
                f["name"].as_str().unwrap_or("").to_owned(),
                f["line"].as_u64().unwrap_or(0),
            )
        })
        .collect();
    assert_eq!(
        frames,
        vec![("Add2".to_owned(), 13), ("main".to_owned(), 6)]
    );
    assert_eq!(st["stackFrames"][0]["source"]["path"], path.as_str());
    assert_eq!(c.scope("Locals"), vec!["a = 2", "b = 2", "r = 0"]);
    assert_eq!(c.scope("Module"), vec!["total = 2"]);
    let e = c.ok(
        "evaluate",
        json!({"expression": "a + b * 10", "frameId": 0}),
    );
    assert_eq!(e["result"], "22");
    let e = c.ok("evaluate", json!({"expression": "k", "frameId": 1}));
    assert_eq!(e["result"], "2");
    let bad = c.request(
        "evaluate",
        json!({"expression": "nothing + 1", "frameId": 0}),
    );
    assert_eq!(bad["success"], false);
    let scopes = c.ok("scopes", json!({"frameId": 0}));
    let locals = scopes["scopes"][0]["variablesReference"].clone();
    let set = c.ok(
        "setVariable",
        json!({"variablesReference": locals, "name": "b", "value": "10"}),
    );
    assert_eq!(set["value"], "10");

    // Step over: the RETURN, with r computed from the changed b.
    c.ok("next", json!({"threadId": 1}));
    assert_eq!(c.event("stopped")["reason"], "step");
    assert_eq!(c.top_line(), ("Add2".to_owned(), 14));
    assert_eq!(c.scope("Locals"), vec!["a = 2", "b = 10", "r = 22"]);

    // Step out: back in main, at the loop's next call.
    c.ok("stepOut", json!({"threadId": 1}));
    c.event("stopped");
    assert_eq!(c.top_line(), ("main".to_owned(), 6));
    assert_eq!(c.scope("Module"), vec!["total = 22"]);
    let vars = c.scope("Locals");
    assert!(vars.contains(&"k = 3".to_owned()), "{vars:?}");

    // Continue: the output, then the division by zero stops at its line.
    c.ok("continue", json!({"threadId": 1}));
    let stopped = c.event("stopped");
    assert_eq!(stopped["reason"], "exception");
    assert!(
        stopped["text"]
            .as_str()
            .unwrap_or("")
            .starts_with("ERR_DIVZERO"),
        "{stopped}"
    );
    assert_eq!(c.top_line(), ("main".to_owned(), 9));
    let out = c.event("output");
    assert_eq!(out["output"], "total 28\n");
    c.ok("continue", json!({"threadId": 1}));
    assert_eq!(c.event("exited")["exitCode"], 1);
    c.event("terminated");
    c.ok("disconnect", json!({}));
}

#[test]
fn a_running_program_pauses_and_ends_on_disconnect() {
    let dir = scratch("dap-pause");
    write(
        &dir,
        &[(
            "spin.mod",
            "MODULE spin\n  PROC main()\n    VAR num n := 0;\n    WHILE TRUE DO\n      n := n + 1;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let path = dir.join("spin.mod").to_string_lossy().into_owned();
    let mut c = Client::start();
    c.ok("initialize", json!({"adapterID": "rapid"}));
    c.ok(
        "launch",
        json!({"program": path, "stopOnEntry": true, "maxSteps": 1_000_000_000_000u64}),
    );
    c.ok("configurationDone", json!({}));
    assert_eq!(c.event("stopped")["reason"], "entry");
    assert_eq!(c.top_line(), ("main".to_owned(), 4));
    c.ok("continue", json!({"threadId": 1}));
    std::thread::sleep(Duration::from_millis(200));
    c.ok("pause", json!({"threadId": 1}));
    assert_eq!(c.event("stopped")["reason"], "pause");
    let (name, line) = c.top_line();
    assert_eq!(name, "main");
    assert!(line == 4 || line == 5, "{line}");
    // The program's sandbox folder (named by the adapter's process id) is
    // gone by the answer to `disconnect`.
    let sandboxes = |pid: u32| {
        std::fs::read_dir(std::env::temp_dir())
            .map(|d| {
                d.filter_map(Result::ok)
                    .filter(|e| {
                        e.file_name()
                            .to_string_lossy()
                            .starts_with(&format!("rapid-run-{pid}-"))
                    })
                    .count()
            })
            .unwrap_or(0)
    };
    let pid = c.child.id();
    assert_eq!(sandboxes(pid), 1, "the running program's sandbox");
    c.ok("disconnect", json!({}));
    assert_eq!(sandboxes(pid), 0, "removed before the answer");
    let status = c.child.wait().expect("the adapter ends");
    assert!(status.success());
}

#[test]
fn a_launch_with_plot_writes_the_path_page_when_the_program_ends() {
    let dir = scratch("dap-plot");
    write(
        &dir,
        &[(
            "moves.mod",
            "MODULE moves\n  CONST robtarget p1 := [[100, 0, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  PROC main()\n    MoveJ p1, v1000, z50, tool0;\n    MoveL Offs(p1, 0, 50, 0), v100, fine, tool0;\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let path = dir.join("moves.mod").to_string_lossy().into_owned();
    let page = dir.join("path.html");
    let mut c = Client::start();
    c.ok("initialize", json!({"adapterID": "rapid"}));
    c.ok(
        "launch",
        json!({"program": path, "plot": page.to_string_lossy()}),
    );
    c.ok("configurationDone", json!({}));
    assert_eq!(c.event("exited")["exitCode"], 0);
    c.event("terminated");
    c.ok("disconnect", json!({}));
    let html = std::fs::read_to_string(&page).expect("the path page");
    assert!(html.contains("moves.mod (main)"), "no title");
    assert!(
        html.contains(r#""instruction":"MoveJ""#) && html.contains(r#""instruction":"MoveL""#),
        "the moves are missing: {html}"
    );
    assert!(
        html.contains("[100.0,50.0,300.0]"),
        "the MoveL target: {html}"
    );
}

const SQUARE: &str = "MODULE Square
  CONST robtarget pCorner := [[500, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveL pCorner, v200, fine, tool0;
    MoveL Offs(pCorner, 100, 0, 0), v200, fine, tool0;
    MoveL Offs(pCorner, 100, 100, 0), v200, fine, tool0;
    TPWrite \"done\";
  ENDPROC
ENDMODULE
";

/// `robot` names the arm (as `rapid run --robot`): the moves take time and
/// the path page follows the debugger: at each stop the page, its script
/// and a `rapidPath` event give the moves so far with the arm, the time,
/// the line and the move that brought the robot there.
#[test]
fn the_path_page_follows_the_debugger_with_the_robot_the_launch_names() {
    let dir = scratch("dap-follow");
    write(&dir, &[("Square.mod", SQUARE)]);
    let path = std::fs::canonicalize(dir.join("Square.mod")).expect("the module");
    let path = path.to_string_lossy().into_owned();
    let page = dir.join("square.html");
    let mut c = Client::start();
    c.ok("initialize", json!({"adapterID": "rapid"}));
    c.event("initialized");
    c.ok(
        "launch",
        json!({"program": path, "plot": page.to_string_lossy(), "robot": "IRB 1200-7/0.7"}),
    );
    c.ok(
        "setBreakpoints",
        json!({"source": {"path": path}, "breakpoints": [{"line": 6}]}),
    );
    c.ok("configurationDone", json!({}));
    assert_eq!(c.event("stopped")["reason"], "breakpoint");
    let first = c.event("rapidPath");
    assert_eq!(first["page"], page.to_string_lossy().as_ref());
    let state = &first["state"];
    assert_eq!(state["at"], json!({"file": path, "line": 6}));
    // Two moves made: the robot is at the end of the second (line 5).
    assert_eq!(state["moves"].as_array().map(Vec::len), Some(2));
    assert_eq!(state["current"], 1);
    assert_eq!(state["moves"][1]["line"], 5);
    let now = state["now"].as_f64().expect("the time");
    assert_eq!(now, state["moves"][1]["end"].as_f64().expect("its end"));
    // 100 mm at 200 mm/s take more than half a second.
    assert!(now > 0.5, "{now}");
    assert_eq!(state["robot"]["name"], "IRB 1200-7/0.7");
    assert!(state["moves"][1]["arm"].is_array(), "{state}");
    assert_eq!(state["ended"], false);
    let html = std::fs::read_to_string(&page).expect("the page at the stop");
    assert!(html.contains(r#"const live = "square.live.js";"#));
    assert!(html.contains(r#""current":1"#), "the page holds the stop");
    let live = std::fs::read_to_string(dir.join("square.live.js")).expect("the script");
    assert!(
        live.starts_with("rapidFollow({") && live.contains(r#""line":6"#),
        "{live}"
    );

    // A step: the next state, one move on.
    c.ok("next", json!({"threadId": 1}));
    c.event("stopped");
    let next = c.event("rapidPath");
    let state = &next["state"];
    assert_eq!(
        state["seq"].as_u64(),
        first["state"]["seq"].as_u64().map(|n| n + 1)
    );
    assert_eq!(state["at"]["line"], 7);
    assert_eq!(
        (state["current"].clone(), state["moves"][2]["line"].clone()),
        (json!(2), json!(6))
    );
    assert!(state["now"].as_f64() > Some(now));

    // The end: the last state, and the page the program leaves.
    c.ok("continue", json!({"threadId": 1}));
    assert_eq!(c.event("exited")["exitCode"], 0);
    let last = c.event("rapidPath");
    assert_eq!(
        (last["state"]["ended"].clone(), last["state"]["at"].clone()),
        (json!(true), Value::Null)
    );
    c.event("terminated");
    c.ok("disconnect", json!({}));
    let html = std::fs::read_to_string(&page).expect("the page");
    assert!(html.contains(r#""ended":true"#) && html.contains(r#""arm":[[0.0,0.0,0.0]"#));
}

/// A `robot` no model has fails the launch; without one, a note says the
/// moves take no time.
#[test]
fn a_launch_names_a_robot_that_is_modelled_or_gets_a_note() {
    let dir = scratch("dap-robot");
    write(&dir, &[("Square.mod", SQUARE)]);
    let path = dir.join("Square.mod").to_string_lossy().into_owned();
    let mut c = Client::start();
    c.ok("initialize", json!({"adapterID": "rapid"}));
    let bad = c.request("launch", json!({"program": path, "robot": "IRB 99"}));
    assert_eq!(bad["success"], false);
    let message = bad["message"].as_str().unwrap_or_default();
    assert!(
        message.starts_with("launch: robot: `IRB 99` is not a modelled robot"),
        "{message}"
    );
    c.ok("launch", json!({"program": path}));
    c.ok("configurationDone", json!({}));
    assert_eq!(c.event("exited")["exitCode"], 0);
    let said: Vec<&str> = c
        .events
        .iter()
        .filter(|e| e["event"] == "output")
        .filter_map(|e| e["body"]["output"].as_str())
        .collect();
    assert_eq!(
        said,
        [
            "done\n",
            "rapid: dap: note: no robot is named (MOC.cfg, rapid.toml [controller] robot or --robot): moves take no time and reach every target\n"
        ]
    );
    c.ok("disconnect", json!({}));
}

const CELL_SYS: &str = "SYS:CFG_1.0:6:0::
#
CAB_TASKS:

      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask

      -Name \"T_ROB2\" -Type \"NORMAL\" -MotionTask
";

const CELL_ROB1: &str = "MODULE Main1
  PERS num nShared := 0;
  PROC main()
    VAR num n := 1;
    WaitUntil nShared = 5;
    TPWrite \"one saw \"\\Num:=nShared;
  ENDPROC
ENDMODULE
";

const CELL_ROB2: &str = "MODULE Main2
  PERS num nShared := 0;
  PROC main()
    VAR num m := 2;
    WaitTime 1;
    nShared := 5;
    TPWrite \"two set it\";
  ENDPROC
ENDMODULE
";

#[test]
fn the_tasks_of_a_backup_are_threads_inspected_each_on_its_own() {
    let dir = scratch("dap-tasks");
    write(
        &dir,
        &[
            ("cell/SYSPAR/SYS.cfg", CELL_SYS),
            ("cell/RAPID/TASK1/PROGMOD/Main1.mod", CELL_ROB1),
            ("cell/RAPID/TASK2/PROGMOD/Main2.mod", CELL_ROB2),
        ],
    );
    let cell = dir.join("cell").to_string_lossy().into_owned();
    let main2 = std::fs::canonicalize(dir.join("cell/RAPID/TASK2/PROGMOD/Main2.mod"))
        .expect("the module")
        .to_string_lossy()
        .into_owned();
    let mut c = Client::start();
    c.ok("initialize", json!({"adapterID": "rapid"}));
    c.event("initialized");
    c.ok("launch", json!({"program": cell}));
    c.ok(
        "setBreakpoints",
        json!({"source": {"path": main2}, "breakpoints": [{"line": 6}]}),
    );
    c.ok("configurationDone", json!({}));

    // T_ROB2 stops at its breakpoint (after its WaitTime); T_ROB1 waits.
    let stopped = c.event("stopped");
    assert_eq!(stopped["reason"], "breakpoint");
    assert_eq!(stopped["threadId"], 2);
    assert_eq!(stopped["allThreadsStopped"], true);
    let threads = c.ok("threads", json!({}));
    assert_eq!(
        threads["threads"],
        json!([{"id": 1, "name": "T_ROB1"}, {"id": 2, "name": "T_ROB2"}])
    );
    let frame = |c: &mut Client, thread: u64| {
        let st = c.ok("stackTrace", json!({"threadId": thread}));
        let f = st["stackFrames"][0].clone();
        (
            f["id"].as_u64().unwrap_or(0),
            f["name"].as_str().unwrap_or("").to_owned(),
            f["line"].as_u64().unwrap_or(0),
            f["source"]["name"].as_str().unwrap_or("").to_owned(),
        )
    };
    let (two, name, line, file) = frame(&mut c, 2);
    assert_eq!(
        (name.as_str(), line, file.as_str()),
        ("main", 6, "Main2.mod")
    );
    let (one, name, line, file) = frame(&mut c, 1);
    assert_eq!(
        (name.as_str(), line, file.as_str()),
        ("main", 5, "Main1.mod")
    );
    assert_ne!(one, two);
    // Each task's frame sees its own routine data and the shared one.
    let e = c.ok("evaluate", json!({"expression": "m", "frameId": two}));
    assert_eq!(e["result"], "2");
    let e = c.ok("evaluate", json!({"expression": "n", "frameId": one}));
    assert_eq!(e["result"], "1");
    let bad = c.request("evaluate", json!({"expression": "m", "frameId": one}));
    assert_eq!(bad["success"], false);
    let e = c.ok("evaluate", json!({"expression": "nShared", "frameId": one}));
    assert_eq!(e["result"], "0");

    // A step of T_ROB2 sets the shared persistent: T_ROB1 sees it.
    c.ok("next", json!({"threadId": 2}));
    let stopped = c.event("stopped");
    assert_eq!(
        (stopped["reason"].clone(), stopped["threadId"].clone()),
        (json!("step"), json!(2))
    );
    let (one, ..) = frame(&mut c, 1);
    let e = c.ok("evaluate", json!({"expression": "nShared", "frameId": one}));
    assert_eq!(e["result"], "5");

    // Continue: both tasks end; their lines say which task printed them.
    c.ok("continue", json!({"threadId": 2}));
    assert_eq!(c.event("exited")["exitCode"], 0);
    c.event("terminated");
    let mut lines = Vec::new();
    while let Some(i) = c.events.iter().position(|e| e["event"] == "output") {
        lines.push(
            c.events.remove(i)["body"]["output"]
                .as_str()
                .unwrap_or("")
                .to_owned(),
        );
    }
    lines.sort();
    assert_eq!(lines, vec!["[T_ROB1] one saw 5\n", "[T_ROB2] two set it\n"]);
    c.ok("disconnect", json!({}));
}
