//! Constant values at a cursor (`consteval::value_at`), for hovers: small
//! tasks of one or more modules, a cursor marker `$0`, and the expected
//! rendering of the value found there.
//!
//! A fixture is one module, or several each introduced by a line
//! `//- NAME.mod`. The expectation reads `TEXT => TYPE = VALUE`, with
//! ` (initial value)` for PERS data, ` euler [z, y, x]` for orientations, or
//! `TEXT => TYPE ! ERR_CODE` for a run-time error; `none` when nothing is
//! shown.

use std::sync::Arc;

use rapid_analyzer::consteval::{ConstValue, value_at, value_of_range};
use rapid_analyzer::task::{Task, Unit};

/// Builds the task and returns it with the cursor's unit and offset.
fn task_of(fixture: &str) -> (Task, usize, usize) {
    let mut files: Vec<(String, String)> = Vec::new();
    if fixture.trim_start().starts_with("//- ") {
        for chunk in fixture.split("//- ").filter(|c| !c.trim().is_empty()) {
            let (name, text) = chunk.split_once('\n').expect("a header line");
            files.push((format!("task/{}", name.trim()), text.to_owned()));
        }
    } else {
        files.push(("task/main.mod".to_owned(), fixture.to_owned()));
    }
    let mut cursor = None;
    let mut units = Vec::new();
    for (i, (path, text)) in files.into_iter().enumerate() {
        let text = match text.find("$0") {
            Some(at) => {
                cursor = Some((i, at));
                text.replacen("$0", "", 1)
            }
            None => text,
        };
        units.push(Arc::new(Unit::new(path, text, None)));
    }
    let (unit, offset) = cursor.expect("a $0 marker");
    (Task::new("task".into(), units, None), unit, offset)
}

fn render(task: &Task, unit: usize, v: Option<ConstValue>) -> String {
    let Some(v) = v else {
        return "none".to_owned();
    };
    let text = &task.units[unit].text[v.range.clone()];
    let mut out = format!("{text} => {}", v.ty);
    match &v.error {
        Some((code, message)) => {
            assert!(!message.is_empty());
            out.push_str(&format!(" ! {code}"));
        }
        None => out.push_str(&format!(" = {}", v.value)),
    }
    if v.initial_value_only {
        out.push_str(" (initial value)");
    }
    if let Some([z, y, x]) = v.euler_zyx {
        out.push_str(&format!(" euler [{z:.1}, {y:.1}, {x:.1}]"));
    }
    out
}

fn check(fixture: &str, expected: &str) {
    let (task, unit, offset) = task_of(fixture);
    let got = render(&task, unit, value_at(&task, unit, offset));
    assert_eq!(got, expected, "in\n{fixture}");
}

#[test]
fn a_constant_shows_its_value() {
    check(
        "MODULE m\n  CONST num a := 2;\n  CONST num b := a * 3 + 1;\n  PROC p()\n    TPWrite \"\" \\Num:=b$0;\n  ENDPROC\nENDMODULE\n",
        "b => num = 7",
    );
}

#[test]
fn operations_and_calls_around_the_cursor() {
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := Sqrt(2$0) * Sin(30);\n  ENDPROC\nENDMODULE\n",
        "Sqrt(2) => num = 1.41421",
    );
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := Sqrt(2) *$0 Sin(30);\n  ENDPROC\nENDMODULE\n",
        "Sqrt(2) * Sin(30) => num = 0.707107",
    );
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := 10 DIV$0 3;\n  ENDPROC\nENDMODULE\n",
        "10 DIV 3 => num = 3",
    );
}

#[test]
fn a_literal_that_reads_as_itself_is_skipped() {
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := 2$05;\n  ENDPROC\nENDMODULE\n",
        "none",
    );
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := 0x$0FF;\n  ENDPROC\nENDMODULE\n",
        "0xFF => num = 255",
    );
}

#[test]
fn constants_chain_across_modules_in_their_own_scope() {
    check(
        "//- a.mod\nMODULE a\n  LOCAL CONST num k := 10;\n  CONST num fromA := k * 2;\nENDMODULE\n//- b.mod\nMODULE b\n  CONST num k := 1000;\n  CONST num fromB := fromA + k;\n  PROC p()\n    TPWrite \"\" \\Num:=fromB$0;\n  ENDPROC\nENDMODULE\n",
        "fromB => num = 1020",
    );
}

#[test]
fn routine_constants_hide_module_ones() {
    check(
        "MODULE m\n  CONST num n := 1;\n  PROC p()\n    CONST num n := 5;\n    TPWrite \"\" \\Num:=n$0 + 1;\n  ENDPROC\nENDMODULE\n",
        "n => num = 5",
    );
}

#[test]
fn persistent_data_show_their_initial_value_labelled() {
    check(
        "MODULE m\n  PERS num count := 42;\n  VAR num x;\n  PROC p()\n    x := count$0 + 1;\n  ENDPROC\nENDMODULE\n",
        "count => num = 42 (initial value)",
    );
    check(
        "MODULE m\n  PERS num count := 42;\n  VAR num x;\n  PROC p()\n    x := count +$0 1;\n  ENDPROC\nENDMODULE\n",
        "count + 1 => num = 43 (initial value)",
    );
}

#[test]
fn variables_and_parameters_are_not_constant() {
    check(
        "MODULE m\n  VAR num v := 3;\n  VAR num x;\n  PROC p()\n    x := v$0 + 1;\n  ENDPROC\nENDMODULE\n",
        "none",
    );
    check(
        "MODULE m\n  VAR num x;\n  PROC p(num n)\n    x := n$0 * 2;\n  ENDPROC\nENDMODULE\n",
        "none",
    );
    check(
        "MODULE m\n  CONST num i := 7;\n  VAR num x;\n  PROC p()\n    FOR i FROM 1 TO 3 DO\n      x := i$0;\n    ENDFOR\n  ENDPROC\nENDMODULE\n",
        "none",
    );
}

#[test]
fn a_user_record_aggregate_takes_its_declared_type() {
    check(
        "MODULE m\n  RECORD slot\n    num row;\n    num col;\n  ENDRECORD\n  CONST num rows := 4;\n  CONST slot last := [rows *$0 2, 3];\nENDMODULE\n",
        "rows * 2 => num = 8",
    );
    check(
        "MODULE m\n  RECORD slot\n    num row;\n    num col;\n  ENDRECORD\n  CONST num rows := 4;\n  CONST slot last := [rows * 2, 3]$0;\nENDMODULE\n",
        "[rows * 2, 3] => slot = [8,3]",
    );
    check(
        "MODULE m\n  RECORD slot\n    num row;\n    num col;\n  ENDRECORD\n  CONST slot first := [1, 2];\n  VAR num x;\n  PROC p()\n    x := first.col$0;\n  ENDPROC\nENDMODULE\n",
        "first.col => num = 2",
    );
}

#[test]
fn an_aggregate_argument_takes_the_parameter_type() {
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := VectMagn([3, 4, 0]$0);\n  ENDPROC\nENDMODULE\n",
        "[3, 4, 0] => pos = [3,4,0]",
    );
    check(
        "MODULE m\n  PROC p()\n    Show [1, 2]$0;\n  ENDPROC\n  PROC Show(pos p)\n  ENDPROC\nENDMODULE\n",
        "none",
    );
}

#[test]
fn robtarget_offsets() {
    check(
        "MODULE m\n  CONST robtarget pHome := [[100,200,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  PROC p()\n    MoveL Offs$0(pHome, 0, 0, 100), v100, fine, tool0;\n  ENDPROC\nENDMODULE\n",
        "Offs(pHome, 0, 0, 100) => robtarget = [[100,200,400],[1,0,0,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]] euler [0.0, 0.0, 0.0]",
    );
}

#[test]
fn orientations_come_with_euler_angles() {
    check(
        "MODULE m\n  CONST orient o := OrientZYX(90, 0, 0)$0;\nENDMODULE\n",
        "OrientZYX(90, 0, 0) => orient = [0.707107,0,0,0.707107] euler [90.0, 0.0, 0.0]",
    );
}

#[test]
fn run_time_errors_are_values_too() {
    check(
        "MODULE m\n  CONST num zero := 0;\n  VAR num x;\n  PROC p()\n    x := 1 /$0 zero;\n  ENDPROC\nENDMODULE\n",
        "1 / zero => num ! ERR_DIVZERO",
    );
    check(
        "MODULE m\n  VAR string s;\n  PROC p()\n    s := StrPart$0(\"abc\", 5, 2);\n  ENDPROC\nENDMODULE\n",
        "StrPart(\"abc\", 5, 2) => string ! ERR_OUTOFBND",
    );
}

#[test]
fn user_functions_hide_built_ins() {
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := Abs$0(-3);\n  ENDPROC\n  FUNC num Abs(num v)\n    RETURN 0;\n  ENDFUNC\nENDMODULE\n",
        "none",
    );
}

#[test]
fn predefined_data_come_from_the_catalogue() {
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := v100$0.v_tcp;\n  ENDPROC\nENDMODULE\n",
        "v100 => speeddata = [100,500,5000,1000]",
    );
    check(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := 2 * pi$0;\n  ENDPROC\nENDMODULE\n",
        "pi => num = 3.14159",
    );
}

#[test]
fn a_range_gives_the_expression_it_spans() {
    let (task, unit, _) = task_of(
        "MODULE m\n  VAR num x;\n  PROC p()\n    x := 1 + 2 * 3;$0\n  ENDPROC\nENDMODULE\n",
    );
    let text = &task.units[unit].text;
    let start = text.find("2 * 3").expect("the expression");
    let got = render(&task, unit, value_of_range(&task, unit, start..start + 5));
    assert_eq!(got, "2 * 3 => num = 6");
    let got = render(
        &task,
        unit,
        value_of_range(&task, unit, start - 1..start + 5),
    );
    assert_eq!(got, "2 * 3 => num = 6");
    let got = render(&task, unit, value_of_range(&task, unit, start..start + 3));
    assert_eq!(got, "none");
}

#[test]
fn outside_expressions_nothing_is_shown() {
    check(
        "MODULE m\n  CONST num a := 2;\n  PROC p$0()\n  ENDPROC\nENDMODULE\n",
        "none",
    );
    check("MODULE m\n  CONST num a$0 := 2 + 1;\nENDMODULE\n", "none");
    check("MODULE m\n  ! 1 + 1$0\nENDMODULE\n", "none");
}

#[test]
fn cyclic_constants_do_not_hang() {
    check(
        "MODULE m\n  CONST num a := b + 1;\n  CONST num b := a$0 + 1;\nENDMODULE\n",
        "none",
    );
    check(
        "MODULE m\n  CONST num a{a} := [1];\n  CONST num b := a$0{1};\nENDMODULE\n",
        "a => num{*} = [1]",
    );
}

#[test]
fn every_offset_of_broken_code_is_safe() {
    let fixture = "//- a.mod\nMODULE a\n  RECORD r\n    num x;\n    pos p;\n  ENDRECORD\n  CONST r k := [1, [2, 3, 4]];\n  CONST num n{2} := [k.x, k.p.y / 0];\n  PERS string s := \"a\" + \"b\";\n  CONST num cyc := cyc + 1;\n  PROC p(num v, \\switch sw)\n    VAR num w := Round(v \\Dec:=2);\n    CONST num c := n{3} + <EXP>;\n    w := Offs(<ARG>, 1, 2) + [1,2;\n    FOR i FROM 1 TO Dim(n, 1) DO\n      w := StrPart(s, i, 1) + ;\n    ENDFOR\n  ENDPROC\n  FUNC num f(num a)\n    RETURN Abs(a) * -(1 DIV 0);\n  ENDFUNC\nENDMODULE\n//- b.mod\nMODULE b\n  CONST num z := k.p.z * n{1}$0;\nENDMODULE\n";
    let (task, _, _) = task_of(fixture);
    let mut shown = 0;
    for (u, unit) in task.units.iter().enumerate() {
        for offset in 0..=unit.text.len() + 1 {
            if let Some(v) = value_at(&task, u, offset) {
                assert!(v.range.start <= offset.max(1) && offset <= v.range.end + 1);
                shown += 1;
            }
            let _ = value_of_range(&task, u, offset.saturating_sub(3)..offset);
        }
    }
    assert!(shown > 10, "only {shown} offsets show a value");
}

#[test]
fn aggregates_and_numbers_take_the_type_of_their_target() {
    check(
        "MODULE m\n  VAR pos p;\n  PROC q()\n    p := [1, 2, 3]$0;\n  ENDPROC\nENDMODULE\n",
        "[1, 2, 3] => pos = [1,2,3]",
    );
    check(
        "MODULE m\n  FUNC pose f()\n    RETURN [[0, 0, 10], [1, 0, 0, 0]]$0;\n  ENDFUNC\nENDMODULE\n",
        "[[0, 0, 10], [1, 0, 0, 0]] => pose = [[0,0,10],[1,0,0,0]] euler [0.0, 0.0, 0.0]",
    );
    check(
        "MODULE m\n  VAR dnum d;\n  PROC q()\n    d := 4294967295 DIV$0 2;\n  ENDPROC\nENDMODULE\n",
        "4294967295 DIV 2 => dnum = 2147483647",
    );
    check(
        "MODULE m\n  CONST num grid{2, 2} := [[1, 2], [3, 4]]$0;\nENDMODULE\n",
        "[[1, 2], [3, 4]] => num{2,2} = [[1,2],[3,4]]",
    );
}

#[test]
fn deep_nesting_is_refused_without_a_crash() {
    let depth = 3000;
    let fixture = format!(
        "MODULE m\n  CONST num x := {}1$0{};\n  CONST num y := 2 + 3;\nENDMODULE\n",
        "(".repeat(depth),
        ")".repeat(depth)
    );
    let (task, unit, offset) = task_of(&fixture);
    // The expression nests deeper than the analyzer reads (`nesting-too-
    // deep`): neither its centre nor the whole has a value, and nothing
    // overflows the stack; the module's other constants still have theirs.
    let inner = value_at(&task, unit, offset);
    let outer = value_at(&task, unit, offset - 1 - depth);
    assert_eq!(inner, None);
    assert_eq!(outer, None);
    let codes: Vec<&str> = task.units[unit]
        .syntax
        .iter()
        .map(|d| d.rule.code)
        .collect();
    assert_eq!(codes, ["W001"]);
    let text = &task.units[unit].text;
    let y = text.rfind("2 + 3").map_or(0, |at| at + "2 + 3".len());
    let y = value_at(&task, unit, y);
    assert_eq!(y.map(|v| v.value), Some("5".to_owned()));
}
