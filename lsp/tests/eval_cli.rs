//! `rapid eval` end to end: the built binary, its output and exit codes.

use std::path::Path;
use std::process::{Command, Output};

fn repo() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

fn rapid(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rapid"))
        .arg("eval")
        .args(args)
        .current_dir(repo())
        .output()
        .expect("the rapid binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Runs `rapid eval ARGS` and returns (exit code, stdout, stderr).
fn eval(args: &[&str]) -> (Option<i32>, String, String) {
    let out = rapid(args);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// Each case: the arguments and the expected stdout (exit code 0).
#[test]
fn values_print_as_rapid_writes_them() {
    let cases: &[(&[&str], &str)] = &[
        (&["Sqrt(2) * Sin(30)"], "0.707107"),
        (&["OrientZYX(90, 0, 0)"], "[0.707107,0,0,0.707107]"),
        (&["10 DIV 3"], "3"),
        (&["-7 MOD 3"], "-1"),
        (&["ValToStr(1/3)"], "\"0.333333\""),
        (&["\"ab\" + \"c\""], "\"abc\""),
        (&["NOT TRUE OR TRUE"], "TRUE"),
        (&["[1, 2, 3]"], "[1,2,3]"),
        (&["pi"], "3.14159"),
        (&["v100.v_tcp * 2"], "200"),
        (&["NumToStr(2/3, 2)"], "\"0.67\""),
        (&["0xFF + 1"], "256"),
        (
            &[
                "--file",
                "examples/palletizer/MainModule.mod",
                "Offs(pPickAbove, 0, 0, 100)",
            ],
            "[[812.5,-402.1,555],[0.00469,0.70712,-0.70706,0.00421],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]",
        ),
        (
            &[
                "--file",
                "examples/palletizer/MainModule.mod",
                "nRows * nCols * nLayers",
            ],
            "24",
        ),
        (
            &[
                "--file",
                "examples/palletizer",
                "pPalletOrigin.trans.z + boxHeight",
            ],
            "300",
        ),
    ];
    for (args, expected) in cases {
        let (code, stdout, stderr) = eval(args);
        assert_eq!(code, Some(0), "{args:?}: {stderr}");
        assert_eq!(stdout.trim_end(), *expected, "{args:?}");
        assert!(stderr.is_empty(), "{args:?}: {stderr}");
    }
}

#[test]
fn run_time_errors_go_to_stderr_with_exit_1() {
    let cases: &[(&str, &str)] = &[
        ("1 / 0", "error: ERR_DIVZERO: "),
        ("10 DIV (2 - 2)", "error: ERR_DIVZERO: "),
        ("Sqrt(-1)", "error: ERR_ARGVALERR: "),
        ("StrPart(\"abc\", 5, 2)", "error: ERR_OUTOFBND: "),
        ("2.5 MOD 2", "error: ERR_NOTINTVAL: "),
    ];
    for (expr, expected) in cases {
        let (code, stdout, stderr) = eval(&[expr]);
        assert_eq!(code, Some(1), "{expr}");
        assert!(stdout.is_empty(), "{expr}: {stdout}");
        assert!(stderr.starts_with(expected), "{expr}: {stderr}");
    }
}

#[test]
fn names_that_are_not_constant() {
    let (code, _, stderr) = eval(&["nobody + 1"]);
    assert_eq!(code, Some(1));
    assert!(stderr.contains("unknown-name"), "{stderr}");

    let args = [
        "--file",
        "examples/palletizer/MainModule.mod",
        "nPlaced + 1",
    ];
    let (code, _, stderr) = eval(&args);
    assert_eq!(code, Some(1));
    assert!(stderr.contains("not-constant"), "{stderr}");

    let args = [
        "--initial",
        "--file",
        "examples/palletizer/MainModule.mod",
        "nPlaced + 1",
    ];
    let (code, stdout, stderr) = eval(&args);
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stdout, "1\n");
    assert!(stderr.contains("initial value of `nPlaced`"), "{stderr}");
}

#[test]
fn json_output() {
    let (code, stdout, _) = eval(&["--format", "json", "Sqrt(2)"]);
    assert_eq!(code, Some(0));
    let v: serde_json::Value = serde_json::from_str(&stdout).expect("json");
    assert_eq!(v, serde_json::json!({"type": "num", "value": "1.41421"}));

    let (code, stdout, _) = eval(&["--format", "json", "[[1, 2], [3, 4]]"]);
    assert_eq!(code, Some(0));
    let v: serde_json::Value = serde_json::from_str(&stdout).expect("json");
    assert_eq!(
        v,
        serde_json::json!({"type": "num{2,2}", "value": "[[1,2],[3,4]]"})
    );

    let (code, stdout, _) = eval(&["--format", "json", "1 / 0"]);
    assert_eq!(code, Some(1));
    let v: serde_json::Value = serde_json::from_str(&stdout).expect("json");
    assert_eq!(v["error"]["code"], "ERR_DIVZERO");
    assert_eq!(v["error"]["runtime"], true);
    assert!(v["error"]["message"].is_string());

    let args = [
        "--format",
        "json",
        "--file",
        "examples/palletizer/MainModule.mod",
        "jHome.robax.rax_5",
    ];
    let (code, stdout, _) = eval(&args);
    assert_eq!(code, Some(0));
    let v: serde_json::Value = serde_json::from_str(&stdout).expect("json");
    assert_eq!(v, serde_json::json!({"type": "num", "value": "30"}));
}

#[test]
fn expressions_that_do_not_parse_say_where() {
    let (code, stdout, stderr) = eval(&["1 +"]);
    assert_eq!(code, Some(2));
    assert!(stdout.is_empty());
    assert!(stderr.contains("does not parse at column 4"), "{stderr}");

    let (code, _, stderr) = eval(&["Sqrt(2))"]);
    assert_eq!(code, Some(2));
    assert!(stderr.contains("column 8"), "{stderr}");

    let (code, _, stderr) = eval(&["  "]);
    assert_eq!(code, Some(2));
    assert!(stderr.contains("empty"), "{stderr}");

    let (code, _, stderr) = eval(&["1; ENDMODULE"]);
    assert_eq!(code, Some(2), "{stderr}");
}

#[test]
fn parse_errors_say_what_was_expected_in_the_expression() {
    for (expr, said) in [
        (
            "Sqrt(",
            "column 6: expected an argument or `)` after the `(` of column 5, found the end of the expression",
        ),
        (
            "1 +",
            "column 4: expected an operand after `+`, found the end of the expression",
        ),
        (
            "Abs(-3))",
            "column 8: unexpected `)`: no bracket before it to close",
        ),
        (
            "Offs(p, 1, 2,)",
            "column 13: expected an argument after `,`, found `)`",
        ),
        (
            "Sqrt(2]",
            "column 7: expected `)` to close the `(` of column 5, found `]`",
        ),
        ("\"abc", "column 1: this string has no closing `\"`"),
        (
            "Max(1 2)",
            "column 6: missing `,` between the arguments `1` and `2`",
        ),
        (
            "1 2",
            "column 3: unexpected `2`: the expression is complete before it",
        ),
    ] {
        let (code, _, stderr) = eval(&[expr]);
        assert_eq!(code, Some(2), "{expr}: {stderr}");
        assert!(stderr.contains(said), "{expr}: {stderr}");
        assert!(
            !stderr.contains("MODULE") && !stderr.contains("`;`"),
            "the synthetic module shows through: {stderr}"
        );
    }
}

#[test]
fn dnum_values_keep_their_digits_to_the_output() {
    for (expr, out) in [
        ("DnumToStr(16777216e6, 0)", "\"16777216000000\"\n"),
        ("DnumToStr(1234567890123, 0)", "\"1234567890123\"\n"),
        ("DnumToStr(2.675, 2)", "\"2.68\"\n"),
    ] {
        let (code, stdout, stderr) = eval(&[expr]);
        assert_eq!((code, stdout.as_str()), (Some(0), out), "{expr}: {stderr}");
    }
}

#[test]
fn usage_errors_exit_2() {
    let (code, _, stderr) = eval(&["--file", "no/such/file.mod", "1"]);
    assert_eq!(code, Some(2));
    assert!(stderr.contains("no/such/file.mod"), "{stderr}");

    let (code, _, _) = eval(&[]);
    assert_eq!(code, Some(2));
}

#[test]
fn json_syntax_errors() {
    let (code, stdout, _) = eval(&["--format", "json", "Sqrt(2"]);
    assert_eq!(code, Some(2));
    let v: serde_json::Value = serde_json::from_str(&stdout).expect("json");
    assert_eq!(v["error"]["code"], "syntax-error");
    assert_eq!(v["error"]["column"], 7);
}

#[test]
fn a_program_in_a_folder_named_in_any_script() {
    // Task grouping once sliced folder names inside a character.
    for folder in ["josé/robot", "机器人程序/RAPID/TASK1/PROGMOD"] {
        let dir = std::env::temp_dir()
            .join(format!("rapid-eval-{}", std::process::id()))
            .join(folder);
        std::fs::create_dir_all(&dir).expect("folder");
        let module = dir.join("Main.mod");
        std::fs::write(&module, "MODULE Main\n  CONST num k := 3;\nENDMODULE\n").expect("written");
        for file in [&module, &dir] {
            let file = file.to_string_lossy();
            let (code, out, err) = eval(&["--file", &file, "k * 2"]);
            assert_eq!(
                (code, out.trim(), err.as_str()),
                (Some(0), "6", ""),
                "{file}"
            );
        }
        let _ = std::fs::remove_dir_all(
            std::env::temp_dir().join(format!("rapid-eval-{}", std::process::id())),
        );
    }
}

#[test]
fn an_expression_nested_too_deep_is_refused_with_a_message() {
    // (An argument holds at most 128 KB.)
    let deep = format!("{}1{}", "(".repeat(30_000), ")".repeat(30_000));
    let (code, out, err) = eval(&[&deep]);
    assert!(
        !err.contains("overflow") && !err.contains("panicked"),
        "{err}"
    );
    assert_eq!(code, Some(2), "{out}{err}");
    assert!(err.contains("nest"), "{err}");
}

/// The sizes of a `VAR` or `PERS` array are its declaration's: `Dim` of it
/// is known before the program runs (a name of Latin-1 letters too).
#[test]
fn dim_of_a_variable_array_is_its_declared_size() {
    let dir = std::env::temp_dir().join(format!("rapid-eval-dim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("folder");
    let module = dir.join("Grid.mod");
    std::fs::write(
        &module,
        "MODULE Grid\n  CONST num nRows := 4;\n  VAR num grid{nRows, 3};\n  PERS num pÖl{2} := [1, 2];\nENDMODULE\n",
    )
    .expect("written");
    let file = module.to_string_lossy();
    for (expr, want) in [("Dim(grid, 1) * Dim(grid, 2)", "12"), ("Dim(PÖL, 1)", "2")] {
        let (code, out, err) = eval(&["--file", &file, expr]);
        assert_eq!(
            (code, out.trim(), err.as_str()),
            (Some(0), want, ""),
            "{expr}"
        );
    }
    let (code, _, err) = eval(&["--file", &file, "Dim(grid, 3)"]);
    assert_eq!(code, Some(1));
    assert!(err.contains("ERR_ILLDIM"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
