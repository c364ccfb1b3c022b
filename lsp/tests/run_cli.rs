//! `rapid run` and `rapid test` end to end: the built binary, its output,
//! its files and its exit codes.

mod support;

use std::path::Path;

use support::{rapid_out as run, scratch, write};

fn repo() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// Test timings vary: `(1.2 ms)` becomes `(T ms)`, `"ms":1.2` `"ms":T`.
fn untimed(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(i) = rest.find(" ms)") {
        let start = rest[..i].rfind('(').unwrap_or(i);
        out.push_str(&rest[..start]);
        out.push_str("(T ms)");
        rest = &rest[i + 4..];
    }
    out.push_str(rest);
    out
}

#[test]
fn the_palletizer_example_runs_to_its_end() {
    let (code, out, err) = run(
        repo(),
        &["run", "examples/palletizer", "--set", "diBoxPresent=1"],
    );
    assert_eq!(
        (code, out.as_str(), err.as_str()),
        (
            Some(0),
            "Pallet complete: 24\n",
            "rapid: run: note: no robot is named (MOC.cfg, rapid.toml [controller] robot or --robot): moves take no time and reach every target\n"
        )
    );
}

#[test]
fn a_box_that_never_comes_ends_in_retries() {
    let (code, out, err) = run(repo(), &["run", "examples/palletizer/MainModule.mod"]);
    assert_eq!(code, Some(1));
    assert_eq!(out.lines().count(), 5, "{out}");
    assert!(out.lines().all(|l| l == "No box arrived within 30 s"));
    insta::assert_snapshot!(err);
}

#[test]
fn an_unhandled_error_names_itself_its_line_and_the_routines() {
    let dir = scratch("run-error");
    write(
        &dir,
        &[(
            "m.mod",
            "MODULE m\n  VAR num zero := 0;\n  PROC main()\n    TPWrite \"start\";\n    Divide 1;\n  ENDPROC\n  PROC Divide(num x)\n    x := x / zero;\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let (code, out, err) = run(&dir, &["run", "m.mod"]);
    assert_eq!((code, out.as_str()), (Some(1), "start\n"));
    assert_eq!(
        err,
        "error: ERR_DIVZERO: division by zero\n  --> m.mod:8:5\n  in Divide (m.mod:8)\n  in main (m.mod:5)\n"
    );
}

#[test]
fn usage_errors_exit_with_2() {
    let dir = scratch("run-usage");
    write(
        &dir,
        &[("m.mod", "MODULE m\n  PROC main()\n  ENDPROC\nENDMODULE\n")],
    );
    let (code, _, err) = run(&dir, &["run", "m.mod", "--entry", "nothing"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("no procedure nothing"), "{err}");
    let (code, _, err) = run(&dir, &["run", "m.mod", "--set", "di1"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("NAME=VALUE"), "{err}");
    let (code, _, err) = run(&dir, &["run", "missing.mod"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("missing.mod"), "{err}");
}

#[test]
fn the_trace_and_the_plot_hold_every_move() {
    let dir = scratch("run-trace");
    let (code, _, err) = run(
        repo(),
        &[
            "run",
            "examples/palletizer",
            "--set",
            "diBoxPresent=1",
            "--trace",
            &dir.join("t.json").to_string_lossy(),
            "--plot",
            &dir.join("p.html").to_string_lossy(),
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    let trace: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("t.json")).expect("a trace"))
            .expect("JSON");
    let moves = trace["moves"].as_array().expect("moves");
    // 24 boxes: 3 moves to pick, 3 to place; home at the start and the end.
    assert_eq!(moves.len(), 24 * 6 + 2);
    assert_eq!(moves[1]["instruction"], "MoveJ");
    assert_eq!(moves[1]["line"], 55);
    assert_eq!(moves[2]["target"], "pPickAbove");
    let page = std::fs::read_to_string(dir.join("p.html")).expect("a page");
    assert!(page.contains("\"pPickAbove\"") && page.contains("<canvas"));
}

const TESTS: &str = "MODULE Calc_test
  VAR num calls := 0;

  PROC setup()
    calls := calls + 1;
  ENDPROC

  PROC adds()
    AssertEqual 1 + 2, 3;
  ENDPROC

  PROC compares_strings()
    AssertEqualStr \"a\" + \"b\", \"abc\"\\Message:=\"joined\";
  ENDPROC

  PROC divides()
    VAR num x;
    x := 1 / (calls - 1);
  ENDPROC

  PROC talks()
    EGMGetId egm;
  ENDPROC

  VAR egmident egm;
ENDMODULE
";

#[test]
fn tests_pass_fail_and_err_with_their_lines() {
    let dir = scratch("test-report");
    write(&dir, &[("Calc_test.mod", TESTS)]);
    let (code, out, err) = run(&dir, &["test"]);
    assert_eq!(code, Some(1), "{err}");
    insta::assert_snapshot!(untimed(&out));
    let (_, out, _) = run(&dir, &["test", "--format", "json", "--filter", "strings"]);
    let doc: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    assert_eq!(doc["failed"], 1);
    assert_eq!(doc["tests"][0]["errno"]["name"], "ERR_ASSERT");
    assert_eq!(doc["tests"][0]["at"]["line"], 13);
    let (_, out, _) = run(&dir, &["test", "--format", "junit"]);
    assert!(
        out.contains(r#"<testsuites name="rapid test" tests="4" failures="2" errors="1">"#),
        "{out}"
    );
    assert!(out.contains(r#"<failure message="joined: expected &quot;abc&quot;, got &quot;ab&quot;" type="ERR_ASSERT">"#), "{out}");
    let (code, out, _) = run(&dir, &["test", "--filter", "adds"]);
    assert_eq!(code, Some(0));
    assert!(
        out.ends_with("1 test: 1 passed, 0 failed, 0 errors\n"),
        "{out}"
    );
}

#[test]
fn the_example_tests_pass_with_the_shipped_assertion_module() {
    let (code, out, _) = run(repo(), &["test", "--assert-module"]);
    assert_eq!(code, Some(0));
    let copy = std::fs::read_to_string(repo().join("examples/testing/RapidAssert.sys"))
        .expect("the example's copy");
    assert_eq!(
        out, copy,
        "regenerate it: rapid test --assert-module > examples/testing/RapidAssert.sys"
    );
    let (code, out, err) = run(repo(), &["test", "examples/testing"]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(
        out.ends_with("4 tests: 4 passed, 0 failed, 0 errors\n"),
        "{out}"
    );
}

#[test]
fn a_program_file_names_the_modules_it_lists() {
    let dir = scratch("run-program-file");
    write(
        &dir,
        &[
            (
                "app/App.pgf",
                "<?xml version=\"1.0\"?>\n<Program>\n  <Module>Main.mod</Module>\n  <Module>Lib.sys</Module>\n</Program>\n",
            ),
            (
                "app/Main.mod",
                "MODULE Main\n  PROC main()\n    Greet;\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "app/Lib.sys",
                "MODULE Lib(SYSMODULE)\n  PROC Greet()\n    TPWrite \"hello\";\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "empty/None.pgf",
                "<?xml version=\"1.0\"?>\n<Program>\n  <Module>Gone.mod</Module>\n</Program>\n",
            ),
        ],
    );
    let (code, out, err) = run(&dir, &["run", "app/App.pgf"]);
    assert_eq!((code, out.as_str(), err.as_str()), (Some(0), "hello\n", ""));
    let (code, out, _) = run(&dir, &["run", "--list-unsupported", "app/App.pgf"]);
    assert_eq!(
        (code, out.as_str()),
        (Some(0), "0 calls the simulation does not support\n")
    );
    let (code, out, err) = run(&dir, &["check", "app/App.pgf"]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(out.contains("Checked 2 files"), "{out}");
    let (code, _, err) = run(&dir, &["run", "empty/None.pgf"]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("None.pgf") && err.contains("lists no module that exists"),
        "{err}"
    );
}

#[test]
fn of_alternative_programs_the_named_one_runs_and_a_folder_asks_which() {
    let dir = scratch("run-alternatives");
    let version =
        |v: &str| format!("MODULE Prog\n  PROC main()\n    Greet \"{v}\";\n  ENDPROC\nENDMODULE\n");
    let (v1, v2) = (version("v1"), version("v2"));
    write(
        &dir,
        &[
            ("cell/Prog_v1.mod", &v1),
            ("cell/Prog_v2.mod", &v2),
            (
                "cell/Lib.sys",
                "MODULE Lib(SYSMODULE)\n  PROC Greet(string s)\n    TPWrite s;\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    for v in ["v1", "v2"] {
        let (code, out, err) = run(&dir, &["run", &format!("cell/Prog_{v}.mod")]);
        assert_eq!(
            (code, out.as_str(), err.as_str()),
            (Some(0), &*format!("{v}\n"), "")
        );
    }
    let (code, out, err) = run(&dir, &["run", "cell"]);
    assert_eq!((code, out.as_str()), (Some(2), ""));
    assert!(
        err.contains("2 alternative programs") && err.contains("Prog_v1.mod, cell/Prog_v2.mod"),
        "{err}"
    );
}

#[test]
fn a_folder_of_per_task_programs_runs_each_in_the_task_its_name_gives() {
    let dir = scratch("run-per-task");
    let program = |task: &str| {
        format!(
            "MODULE Pick_{task}\n  VAR syncident ready;\n  TASK PERS tasks both{{2}} := [[\"T_ROB1\"], [\"T_ROB2\"]];\n  PROC main()\n    WaitSyncTask ready, both;\n    Greet;\n  ENDPROC\nENDMODULE\n"
        )
    };
    write(
        &dir,
        &[
            ("pick/Pick_T_ROB1.mod", &program("T_ROB1")),
            ("pick/Pick_T_ROB2.mod", &program("T_ROB2")),
            (
                "pick/Lib.sys",
                "MODULE Lib(SYSMODULE)\n  PROC Greet()\n    TPWrite \"in \" + GetTaskName();\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let (code, out, err) = run(&dir, &["run", "pick"]);
    assert_eq!(
        (code, out.as_str(), err.as_str()),
        (Some(0), "[T_ROB1] in T_ROB1\n[T_ROB2] in T_ROB2\n", "")
    );
    // One task alone waits for the other, which is not there.
    let (code, _, err) = run(&dir, &["run", "pick", "--task", "T_ROB2"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("there is no task T_ROB1"), "{err}");
}

#[test]
fn a_folder_of_several_tasks_names_them_as_paths_to_give() {
    let dir = scratch("run-several-tasks");
    let module = |m: &str| {
        format!("MODULE {m}\n  PROC main()\n    TPWrite \"{m}\";\n  ENDPROC\nENDMODULE\n")
    };
    write(
        &dir,
        &[
            ("cell/A.mod", &module("A")),
            ("cell/sub/B.mod", &module("B")),
            ("cell/sub2/C.mod", &module("C")),
        ],
    );
    // The folder's own modules are the task the folder names.
    let (code, out, err) = run(&dir.join("cell"), &["run", "."]);
    assert_eq!((code, out.as_str()), (Some(0), "A\n"), "{err}");
    let (code, out, err) = run(&dir, &["run", "cell/"]);
    assert_eq!((code, out.as_str()), (Some(0), "A\n"), "{err}");
    let (code, out, _) = run(&dir, &["run", "cell/sub"]);
    assert_eq!((code, out.as_str()), (Some(0), "B\n"));
    // A folder without modules of its own names the tasks it holds.
    std::fs::remove_file(dir.join("cell/A.mod")).expect("removed");
    let (code, _, err) = run(&dir.join("cell"), &["run", "."]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("the folder holds 2 tasks; name one of them (e.g. sub, sub2)"),
        "{err}"
    );
}

#[test]
fn a_data_name_declared_nowhere_may_be_a_signal_that_set_declares() {
    let dir = scratch("run-undeclared-signal");
    write(
        &dir,
        &[(
            "m.mod",
            "MODULE m\n  VAR num layers;\n  PROC main()\n    layers := giLayers;\n    TPWrite \"layers \"\\Num:=layers;\n    Missing;\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let (code, _, err) = run(&dir, &["run", "m.mod"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("`giLayers` is declared nowhere")
            && err.contains("--set giLayers=VALUE declares it"),
        "{err}"
    );
    let (code, out, err) = run(&dir, &["run", "m.mod", "--set", "giLayers=3"]);
    assert_eq!((code, out.as_str()), (Some(1), "layers 3\n"), "{err}");
    // A routine is no signal: no such hint.
    assert!(
        err.contains("`Missing` is declared nowhere") && !err.contains("--set Missing"),
        "{err}"
    );
}

#[test]
fn the_tests_of_alternative_programs_run_in_each_program() {
    let dir = scratch("test-alternatives");
    let version = |v: u32| {
        format!(
            "MODULE Prog\n  FUNC num version()\n    RETURN {v};\n  ENDFUNC\n  PROC main()\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (v1, v2) = (version(1), version(2));
    write(
        &dir,
        &[
            ("Prog_v1.mod", &v1),
            ("Prog_v2.mod", &v2),
            (
                "Prog_test.mod",
                "MODULE Prog_test\n  PROC is_two()\n    AssertEqual version(), 2;\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let (code, out, err) = run(&dir, &["test", "--format", "json"]);
    assert_eq!(code, Some(1), "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let verdicts: Vec<(String, String)> = doc["tests"]
        .as_array()
        .expect("tests")
        .iter()
        .map(|t| (t["module"].to_string(), t["result"].to_string()))
        .collect();
    assert_eq!(
        verdicts,
        [
            (
                r#""Prog_test [Prog_v1.mod]""#.to_owned(),
                r#""fail""#.to_owned()
            ),
            (
                r#""Prog_test [Prog_v2.mod]""#.to_owned(),
                r#""pass""#.to_owned()
            ),
        ],
        "{out}"
    );
}

#[test]
fn a_call_that_needs_an_arm_says_how_to_name_one() {
    let dir = scratch("run-needs-arm");
    write(
        &dir,
        &[(
            "k.mod",
            "MODULE k\n  PROC main()\n    VAR jointtarget j;\n    j := CalcJointT([[500,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], tool0);\n    TPWrite \"axis 1 \"\\Num:=Round(j.robax.rax_1);\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let (code, _, err) = run(&dir, &["run", "k.mod"]);
    assert_eq!(code, Some(1));
    assert!(
        err.contains("CalcJointT (the simulated robot has no kinematic model)")
            && err.contains("= help: name a modelled robot with --robot"),
        "{err}"
    );
    let (code, out, err) = run(&dir, &["run", "k.mod", "--robot", "IRB 1600-10/1.45"]);
    assert_eq!((code, out.as_str()), (Some(0), "axis 1 0\n"), "{err}");
}
