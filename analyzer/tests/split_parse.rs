//! A module parsed as two parts (`split_parse`, as `rapid check` parses a
//! large file on two threads) has the items, diagnostics and constant values
//! of the same module parsed as a whole.

use std::collections::BTreeSet;
use std::sync::Arc;

use rapid_analyzer::check::{check_unit_split, merge_unit_check};
use rapid_analyzer::consteval::value_at;
use rapid_analyzer::diagnostic::Diagnostic;
use rapid_analyzer::split_parse::{parse_ranges, plan};
use rapid_analyzer::task::{Task, Unit};
use rapid_analyzer::workspace::{Workspace, diagnostics_of};

const PATH: &str = "cell/Big.mod";

/// A module whose routines (early and late) hold findings of many rules:
/// constant errors through routine constants, placeholders, long strings,
/// labels, unknown names, unused data, and data declared between routines.
fn module() -> String {
    let mut text = String::from(
        "MODULE Big(NOSTEPIN)\n  CONST num k := 4;\n  VAR num n;\n  RECORD pair\n    num a;\n    num b;\n  ENDRECORD\n",
    );
    let long = "x".repeat(90);
    for i in 0..24 {
        let local = if i % 3 == 0 { "LOCAL " } else { "" };
        text.push_str(&format!(
            "  ! routine {i}\n  {local}PROC p{i}()\n    CONST num z{i} := 0;\n    VAR num unused{i};\n    VAR pair q;\n    n := k DIV z{i};\n    again:\n    n := n + 1;\n    IF n < {i} GOTO again;\n    missing{i} n;\n    TPWrite \"{long}\";\n    q.c := 1;\n  ENDPROC\n"
        ));
        if i % 5 == 0 {
            text.push_str(&format!(
                "  VAR num between{i} := 1;\n  FUNC num f{i}(num x)\n    RETURN x * <EXP>;\n  ENDFUNC\n  TRAP t{i}\n    n := 0;\n  ENDTRAP\n"
            ));
        }
    }
    text.push_str("ENDMODULE\n");
    text
}

fn split_unit(text: &str) -> Unit {
    let plan = plan(text, 0.5).expect("the module splits");
    let main = parse_ranges(text, &plan.main).expect("main tree");
    let part = parse_ranges(text, &plan.part).expect("part tree");
    let unit = Unit::from_split(PATH.into(), text.into(), main, part, plan.chunk, plan.kind);
    assert!(unit.is_split(), "the trees fit together");
    unit
}

fn task_of(unit: Unit) -> Arc<Task> {
    let mut ws = Workspace::new();
    ws.set_unit(unit);
    ws.tasks().into_iter().next().expect("a task")
}

/// (code, range, message, fix) of each diagnostic: what a failure shows.
type Finding = (&'static str, std::ops::Range<usize>, String, String);

fn findings(diagnostics: &[Diagnostic]) -> Vec<Finding> {
    diagnostics
        .iter()
        .map(|d| {
            let fix = format!("{:?}", d.fix);
            (d.rule.code, d.range.clone(), d.message.clone(), fix)
        })
        .collect()
}

/// The diagnostics of the task's only unit, checked whole and in shares.
fn diagnostics(task: &Task) -> (Vec<Finding>, Vec<Finding>) {
    let unit = &task.units[0];
    let whole = diagnostics_of(task, unit);
    let results = check_unit_split(task, 0, 5)
        .iter()
        .map(|s| s.run())
        .collect();
    let mut shared = unit.syntax.clone();
    shared.extend(merge_unit_check(task, 0, results));
    shared.sort_by_key(|d| (d.range.start, d.range.end));
    (findings(&whole), findings(&shared))
}

/// Parses `text` whole and in two parts, and checks that the two units have
/// the same items and diagnostics (each checked whole and in shares); gives
/// both tasks and the rule codes found in the second part.
fn compare(text: &str) -> (Arc<Task>, Arc<Task>, BTreeSet<&'static str>) {
    let split = split_unit(text);
    let (chunk, _) = split.part().expect("a second tree");
    let whole = Unit::new(PATH.into(), text.to_owned(), None);
    assert_eq!(split.items, whole.items);
    assert_eq!(split.interface, whole.interface);
    assert_eq!(split.constants, whole.constants);
    let (whole_task, split_task) = (task_of(whole), task_of(split));
    let (expected, expected_shared) = diagnostics(&whole_task);
    assert_eq!(expected, expected_shared);
    let (found, found_shared) = diagnostics(&split_task);
    assert_eq!(found, expected);
    assert_eq!(found_shared, expected);
    let late = expected
        .iter()
        .filter(|(_, range, ..)| chunk.contains(&range.start))
        .map(|(code, ..)| *code)
        .collect();
    (whole_task, split_task, late)
}

#[test]
fn a_module_parsed_in_two_parts_checks_as_a_whole() {
    let text = module();
    let (whole_task, split_task, late) = compare(&text);
    // The comparison means something: the later routines have findings of
    // many rules.
    // constant-error, incomplete-code, string-too-long, unresolved-name,
    // unknown-component, unused-data, unused-routine
    for rule in ["E413", "E412", "E411", "W101", "E105", "W201", "W203"] {
        assert!(
            late.contains(rule),
            "no {rule} in the later routines: {late:?}"
        );
    }

    // Constant values in both trees.
    for at in [
        text.find("k DIV z0").expect("early"),
        text.rfind("k DIV z").expect("late"),
        text.rfind("z23 := 0").expect("late constant"),
    ] {
        assert!(
            split_task.units[0]
                .tree_at(at)
                .root_node()
                .byte_range()
                .contains(&at)
        );
        assert_eq!(
            value_at(&split_task, 0, at),
            value_at(&whole_task, 0, at),
            "at {at}"
        );
    }
}

/// One long generated routine (the usual shape of a large module written by
/// a CAM tool), with jumps across the whole of it, nested blocks, findings
/// on both sides and an error handler; and a function whose every path must
/// return.
fn long_routine() -> String {
    let mut text = String::from(
        "MODULE Gen\n  VAR num n;\n  CONST num zero := 0;\n  PROC main()\n    VAR num i;\n    VAR num idle;\n    top:\n",
    );
    let long = "y".repeat(85);
    for i in 0..60 {
        text.push_str(&match i % 6 {
            0 => format!("    n := n + {i};\n    m{i}:\n"),
            1 => format!("    IF n > {i} THEN\n      n := 0;\n      GOTO top;\n    ELSE\n      n := 1 DIV zero;\n    ENDIF\n"),
            2 => format!("    FOR j FROM 1 TO 3 DO\n      n := n * j; ! step;\n    ENDFOR\n    IF n < 0 GOTO m{};\n", (i + 30) % 60 / 6 * 6),
            3 => format!("    TPWrite \"{long}\";\n    unknown{i} n;\n"),
            4 => format!("    GOTO m{};\n    n := <EXP>;\n", (i + 20) % 60 / 6 * 6),
            _ => format!("    MoveL Offs(p{i},\n      0, 0, {i}), v100, fine, tool0;\n"),
        });
    }
    text.push_str("    GOTO nowhere;\n  ERROR\n    RETRY;\n  ENDPROC\n");
    text.push_str("  FUNC num f()\n    RETURN 1;\n  ENDFUNC\nENDMODULE\n");
    text
}

#[test]
fn a_long_routine_parsed_in_two_parts_checks_as_a_whole() {
    let text = long_routine();
    let plan = plan(&text, 0.5).expect("the routine splits");
    assert_eq!(plan.kind, rapid_analyzer::split_parse::PartKind::Statements);
    let (whole_task, _, late) = compare(&text);
    // constant-error, incomplete-code, string-too-long, unresolved-name
    for rule in ["E413", "E412", "E411", "W101"] {
        assert!(
            late.contains(rule),
            "no {rule} in the later statements: {late:?}"
        );
    }
    // The jumps across the split are fine; only the missing label is not.
    let (expected, _) = diagnostics(&whole_task);
    let labels: Vec<_> = expected
        .iter()
        .filter(|(code, ..)| *code == "E104" || *code == "E406")
        .collect();
    assert_eq!(labels.len(), 1, "{labels:?}");
}

/// Splits `text`, whose main part (or else second part) has a syntax error,
/// and checks that the unit is the whole parse's: its tree, syntax errors
/// and items.
fn assert_parsed_again_whole(text: &str, error_in_main: bool) {
    let broken = plan(text, 0.5).expect("the lines still split");
    let main = parse_ranges(text, &broken.main).expect("main tree");
    let part = parse_ranges(text, &broken.part).expect("part tree");
    let errors = (main.root_node().has_error(), part.root_node().has_error());
    assert_eq!(errors, (error_in_main, !error_in_main));
    let back = Unit::from_split(
        PATH.into(),
        text.into(),
        main,
        part,
        broken.chunk,
        broken.kind,
    );
    assert!(!back.is_split());
    let whole = Unit::new(PATH.into(), text.into(), None);
    assert_eq!(
        back.tree().root_node().to_sexp(),
        whole.tree().root_node().to_sexp()
    );
    assert!(!whole.syntax.is_empty());
    assert_eq!(back.syntax, whole.syntax);
    assert_eq!(back.items, whole.items);
}

#[test]
fn trees_that_do_not_fit_are_parsed_again_whole() {
    // A syntax error in a later routine: the file is parsed again whole,
    // so that the error is reported as a whole parse finds it.
    let text = module().replace(
        "    again:\n    n := n + 1;\n    IF n < 20",
        "    n := := 1;\n    again:\n    IF n < 20",
    );
    assert_parsed_again_whole(&text, false);
    // The error in the main part: parsed again from the second tree.
    let text = module().replacen("    n := k DIV z0;\n", "    n := k DIV DIV z0;\n", 1);
    assert_parsed_again_whole(&text, true);

    // Trees swapped: declarations on the wrong side.
    let text = module();
    let fine = plan(&text, 0.5).expect("a plan");
    let main = parse_ranges(&text, &fine.main).expect("main tree");
    let part = parse_ranges(&text, &fine.part).expect("part tree");
    let back = Unit::from_split(PATH.into(), text.clone(), part, main, fine.chunk, fine.kind);
    assert!(!back.is_split());
    let whole = Unit::new(PATH.into(), text, None);
    assert_eq!(
        back.tree().root_node().to_sexp(),
        whole.tree().root_node().to_sexp()
    );
}

#[test]
fn a_long_routine_checked_in_parts_reports_as_checked_whole() {
    // Between 128 and 256 KB: two parts of 2,000 statements. A RETURN ends
    // the first part, so the second starts unreachable; data are used in
    // one part only, in the handler only, or nowhere.
    let mut text = String::from(
        "MODULE Gen\n  VAR num n;\n  PROC main()\n    VAR num early;\n    VAR num late;\n    VAR num handler;\n    VAR num never;\n",
    );
    let pad = "x".repeat(40);
    for i in 0..4000 {
        text.push_str(&match i {
            0 => "    early := 1;\n".to_owned(),
            1999 => "    RETURN;\n".to_owned(),
            2003 => "    back:\n".to_owned(),
            3999 => "    late := 2;\n".to_owned(),
            _ => format!("    n := n + {i}; ! {pad}\n"),
        });
    }
    text.push_str("  ERROR\n    handler := 1;\n    GOTO back;\n  ENDPROC\nENDMODULE\n");
    assert!(text.len() > 128 * 1024 && text.len() < 256 * 1024);
    let task = task_of(Unit::new(PATH.into(), text, None));
    let (whole, shared) = diagnostics(&task);
    assert_eq!(shared, whole);
    let codes: Vec<(&str, String)> = whole.iter().map(|(c, _, m, _)| (*c, m.clone())).collect();
    assert_eq!(
        codes,
        vec![
            ("W201", "`never` is declared but never used".to_owned()),
            (
                "W204",
                "this code can never run: it follows RETURN".to_owned()
            ),
        ],
        "{whole:?}"
    );
}
