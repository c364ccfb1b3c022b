use super::fixture;
use crate::ide::{CodeAction, ParameterHints, code_actions, inlay_hints};
use crate::workspace::diagnostics_of;

/// The text after applying the first action for the diagnostic `code`.
fn fixed(src: &str, code: &str) -> (String, CodeAction) {
    let (task, unit, _) = fixture(src);
    let u = &task.units[unit];
    let mut diags = u.syntax.clone();
    diags.extend(diagnostics_of(&task, u).iter().cloned());
    let i = diags
        .iter()
        .position(|d| d.rule.code == code)
        .unwrap_or_else(|| panic!("no {code} in {diags:#?}"));
    let actions = code_actions(&task, unit, diags[i].range.clone(), &diags);
    let action = actions
        .into_iter()
        .find(|a| a.diagnostic == Some(i))
        .unwrap_or_else(|| panic!("no action"));
    let mut text = u.text.clone();
    let mut edits = action.edits.clone();
    edits.sort_by_key(|e| std::cmp::Reverse(e.range.start));
    for e in edits {
        text.replace_range(e.range, &e.replacement);
    }
    (text, action)
}

#[test]
fn declare_an_unknown_variable_with_the_inferred_type() {
    let src = "MODULE m\n  PROC main()\n    VAR num n;\n    n := 1;\n    target := CRobT();\n  ENDPROC\nENDMODULE\n";
    let (text, a) = fixed(src, "W101");
    assert!(
        text.contains("    VAR robtarget target;\n    VAR num n;"),
        "{text}"
    );
    assert!(a.title.contains("robtarget"));
    let src = "MODULE m\n  PROC main()\n    MoveL p, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let (text, _) = fixed(src, "W101");
    assert!(
        text.contains("  PROC main()\n    VAR robtarget p;\n    MoveL"),
        "{text}"
    );
}

#[test]
fn equals_becomes_assignment() {
    let src = "MODULE m\n  VAR num n = 3;\nENDMODULE\n";
    let (text, _) = fixed(src, "E003");
    assert!(text.contains("VAR num n := 3;"), "{text}");
}

#[test]
fn unused_data_is_removed_with_its_line() {
    let src =
        "MODULE m\n  PROC main()\n    VAR num unused;\n    TPWrite \"x\";\n  ENDPROC\nENDMODULE\n";
    let (text, _) = fixed(src, "W201");
    assert_eq!(
        text,
        "MODULE m\n  PROC main()\n    TPWrite \"x\";\n  ENDPROC\nENDMODULE\n"
    );
}

#[test]
fn missing_return_is_added_before_endfunc() {
    let src = "MODULE m\n  RECORD pair\n    num a;\n    bool b;\n  ENDRECORD\n  FUNC pair make()\n    TPWrite \"x\";\n  ENDFUNC\nENDMODULE\n";
    let (text, _) = fixed(src, "E404");
    assert!(
        text.contains("    TPWrite \"x\";\n    RETURN [0, FALSE];\n  ENDFUNC"),
        "{text}"
    );
}

/// (the argument's text up to its end, the hint) of each parameter hint.
fn parameter_hints(src: &str, which: ParameterHints) -> Vec<(String, String)> {
    let (task, unit, _) = fixture(src);
    inlay_hints(&task, unit, 0..src.len(), which)
        .into_iter()
        .map(|h| {
            (
                src[h.offset..]
                    .split([',', ';', ')'])
                    .next()
                    .unwrap_or("")
                    .to_owned(),
                h.label,
            )
        })
        .collect()
}

#[test]
fn parameter_name_hints_for_positional_arguments() {
    let src = "MODULE m\n  PROC main()\n    MoveL p10, v100, fine, tool0;\n    MoveL ToPoint, v100 \\T:=2, z10, tool0;\n    TPWrite \"only one\";\n  ENDPROC\nENDMODULE\n";
    assert_eq!(
        parameter_hints(src, ParameterHints::All),
        vec![
            ("p10".into(), "ToPoint:".into()),
            ("v100".into(), "Speed:".into()),
            ("fine".into(), "Zone:".into()),
            ("tool0".into(), "Tool:".into()),
            ("v100 \\T:=2".into(), "Speed:".into()),
            ("z10".into(), "Zone:".into()),
            ("tool0".into(), "Tool:".into()),
        ]
    );
    assert!(parameter_hints(src, ParameterHints::None).is_empty());
}

#[test]
fn by_default_parameter_hints_only_where_the_argument_does_not_name_itself() {
    let src = "MODULE m\n  VAR robtarget pts{2};\n  PROC main()\n    MoveL p10, v100, fine, tool0;\n    MoveL pts{1}, v100, z10, tool0.tframe;\n    MoveL Offs(p10, 0, 0, 50), [100, 10, 500, 50], z10, (tool0);\n    SetDO doGrip, 1;\n    TPWrite \"only one\";\n  ENDPROC\nENDMODULE\n";
    assert_eq!(
        parameter_hints(src, ParameterHints::default()),
        vec![
            ("Offs(p10".into(), "ToPoint:".into()),
            ("0".into(), "XOffset:".into()),
            ("0".into(), "YOffset:".into()),
            ("50".into(), "ZOffset:".into()),
            ("[100".into(), "Speed:".into()),
            ("1".into(), "Value:".into()),
        ]
    );
}

#[test]
fn value_hints_after_computed_constants() {
    let src = "MODULE m\n  CONST num a := 5;\n  CONST num b := a * 1.5;\n  CONST num c := 3;\n  VAR num v := a + 1;\nENDMODULE\n";
    let (task, unit, _) = fixture(src);
    let hints: Vec<(usize, String)> = inlay_hints(&task, unit, 0..src.len(), ParameterHints::All)
        .into_iter()
        .map(|h| (h.offset, h.label))
        .collect();
    let after = src.find("a * 1.5").unwrap_or(0) + "a * 1.5".len();
    assert_eq!(hints, vec![(after, "= 7.5".to_owned())]);
}
