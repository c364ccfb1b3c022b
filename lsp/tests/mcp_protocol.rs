//! `rapid mcp` at the protocol level, tool by tool: a scripted JSON-RPC
//! client ([`support::mcp`]) drives the built binary over stdio through
//! every tool, the resources and the prompts. Every tool answer's
//! `structuredContent` is validated against the tool's `outputSchema`.
//! What the server refuses (bad arguments, paths outside the roots, a huge
//! input, runs that would not end) and HTTP: `mcp_safety.rs`.

mod support;

use serde_json::json;
use support::mcp::{Client, project, structured, summary};
use support::write;
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
            "reach",
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
    // Two versions of one program: the module named runs, the folder asks.
    let version = |v: &str| {
        format!("MODULE Prog\n  PROC main()\n    TPWrite \"{v}\";\n  ENDPROC\nENDMODULE\n")
    };
    let (v1, v2) = (version("v1"), version("v2"));
    write(
        &dir,
        &[("versions/Prog_v1.mod", &v1), ("versions/Prog_v2.mod", &v2)],
    );
    let ran = c.call("run", json!({"path": "versions/Prog_v2.mod"}));
    assert_eq!(structured(&ran)["output"], json!(["v2"]));
    let message = c.refused("run", json!({"path": "versions"}));
    assert!(message.contains("2 alternative programs"), "{message}"); // A backup that loads its part programs from its HOME, as `rapid run`
    // runs it: the parts are not there at the start, and HOME is copied.
    let part = |n: u32| {
        format!(
            "MODULE Part{n}\n  PROC RunPart()\n    TPWrite \"part {n}\";\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (p1, p2) = (part(1), part(2));
    write(
        &dir,
        &[
            (
                "backup/RAPID/TASK1/PROGMOD/Main.mod",
                "MODULE Main\n  PROC main()\n    Load \"HOME:/Part1.mod\";\n    %\"RunPart\"%;\n    UnLoad \"HOME:/Part1.mod\";\n    Load \"HOME:/Part2.mod\";\n    %\"RunPart\"%;\n    UnLoad \"HOME:/Part2.mod\";\n  ENDPROC\nENDMODULE\n",
            ),
            ("backup/HOME/Part1.mod", &p1),
            ("backup/HOME/Part2.mod", &p2),
        ],
    );
    let answer = c.call("run", json!({"path": "backup/RAPID/TASK1"}));
    let ran = structured(&answer);
    // The program's lines (the traced loads, `[Load at ...]`, aside).
    let lines: Vec<&str> = ran["output"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|l| l.as_str())
        .filter(|l| !l.starts_with('['))
        .collect();
    assert_eq!(lines, ["part 1", "part 2"], "{ran:#}");
}

#[test]
fn run_takes_a_backup_s_tasks_together_as_rapid_run_does() {
    let dir = project("run-backup");
    let mut c = Client::start(&dir, &[], None);
    let sync = |me: &str, other: &str| {
        format!(
            "MODULE {me}Main\n  VAR syncident ready;\n  PERS tasks both{{2}} := [[\"T_ROB1\"],[\"T_PLC\"]];\n  PROC main()\n    TPWrite \"{me} up\";\n    WaitSyncTask ready, both;\n    TPWrite \"{me} past {other}\";\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (rob, plc) = (sync("Rob", "Plc"), sync("Plc", "Rob"));
    let plc_broken = plc.replace(
        "WaitSyncTask",
        "TPWrite \"\" \\Num:=1 / 0;\n    WaitSyncTask",
    );
    write(
        &dir,
        &[
            (
                "bk/SYSPAR/SYS.cfg",
                "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n\n      -Name \"T_PLC\" -Type \"NORMAL\"\n",
            ),
            ("bk/RAPID/TASK1/PROGMOD/RobMain.mod", &rob),
            ("bk/RAPID/TASK2/PROGMOD/PlcMain.mod", &plc),
        ],
    );
    let answer = c.call("run", json!({"path": "bk"}));
    let ran = structured(&answer);
    assert_eq!(ran["status"], "finished", "{ran:#}");
    let names: Vec<&str> = ran["tasks"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|t| t["name"].as_str())
        .collect();
    assert_eq!(names, ["T_ROB1", "T_PLC"], "{ran:#}");
    let mut lines: Vec<&str> = ran["output"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|l| l.as_str())
        .collect();
    // Both tasks pass the meeting point only when both reached it.
    assert_eq!(lines.len(), 4, "{ran:#}");
    assert!(lines[..2].iter().all(|l| l.ends_with(" up")), "{ran:#}");
    lines.sort_unstable();
    assert_eq!(
        lines,
        [
            "[T_PLC] Plc past Rob",
            "[T_PLC] Plc up",
            "[T_ROB1] Rob past Plc",
            "[T_ROB1] Rob up"
        ]
    );
    // One task alone, as `rapid run --task`.
    let answer = c.call("run", json!({"path": "bk", "task": "T_ROB1"}));
    let alone = structured(&answer);
    assert_eq!(alone["tasks"][0]["name"], "T_ROB1", "{alone:#}");
    // A task's error is the run's, named by its task; the other waits.
    write(&dir, &[("bk/RAPID/TASK2/PROGMOD/PlcMain.mod", &plc_broken)]);
    let failed = c.call("run", json!({"path": "bk"}));
    let r = structured(&failed);
    assert_eq!(
        (r["status"].clone(), r["success"].clone()),
        (json!("error"), json!(false)),
        "{r:#}"
    );
    assert_eq!(r["tasks"][1]["error"]["errno"], "ERR_DIVZERO", "{r:#}");
    assert_eq!(r["error"]["errno"], "ERR_DIVZERO", "{r:#}");
    let shown = summary(&failed);
    assert!(shown.contains("[T_PLC] error: ERR_DIVZERO"), "{shown}");
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
