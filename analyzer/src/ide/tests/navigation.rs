use super::{fixture, slice, unit_of};
use crate::ide::{
    definition, document_highlights, prepare_rename, references, rename, type_definition,
};

/// (path, line text of the target) for each location.
fn targets(
    src: &str,
    f: impl Fn(&crate::task::Task, usize, usize) -> Vec<crate::ide::Location>,
) -> Vec<(String, String)> {
    let (task, unit, offset) = fixture(src);
    f(&task, unit, offset)
        .into_iter()
        .map(|l| {
            let u = unit_of(&task, &l.path);
            (l.path.clone(), slice(&task, u, l.range))
        })
        .collect()
}

#[test]
fn definition_of_data_routine_param_local_and_for_variable() {
    let src = "MODULE m\n  VAR num count := 0;\n  PROC main(num n)\n    VAR num k;\n    FOR i FROM 1 TO 3 DO\n      count := count + i$0;\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
    assert_eq!(
        targets(src, definition),
        vec![("t/main.mod".into(), "i".into())]
    );
    let t = |needle: &str| {
        let s = src
            .replacen("$0", "", 1)
            .replacen(needle, &format!("{needle}$0"), 1);
        let (task, unit, offset) = fixture(&s);
        definition(&task, unit, offset)
            .into_iter()
            .map(|l| (l.range.start, slice(&task, unit, l.full_range)))
            .collect::<Vec<_>>()
    };
    assert_eq!(t("count := c")[0].1, "VAR num count := 0;");
    assert_eq!(t("main(num n")[0].1, "n");
    assert_eq!(t("VAR num k")[0].1, "VAR num k;");
}

#[test]
fn definition_across_modules_and_of_builtins() {
    let src = "==> a.mod\nMODULE a\n  PROC main()\n    Grip$0 1;\n    MoveL p, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n==> b.mod\nMODULE b\n  PROC Grip(num x)\n  ENDPROC\nENDMODULE\n";
    assert_eq!(
        targets(src, definition),
        vec![("t/b.mod".into(), "Grip".into())]
    );
    let builtin = src
        .replacen("Grip$0", "Grip", 1)
        .replacen("MoveL", "Mo$0veL", 1);
    assert_eq!(targets(&builtin, definition), vec![]);
}

#[test]
fn type_definition_of_user_records() {
    let src = "MODULE m\n  RECORD part\n    num weight;\n  ENDRECORD\n  VAR part p1;\n  PROC main()\n    p1$0.weight := 2;\n  ENDPROC\nENDMODULE\n";
    assert_eq!(
        targets(src, type_definition),
        vec![("t/main.mod".into(), "part".into())]
    );
    let comp = src.replacen("p1$0.weight", "p1.wei$0ght", 1);
    assert_eq!(
        targets(&comp, definition),
        vec![("t/main.mod".into(), "weight".into())]
    );
    let builtin = "MODULE m\n  VAR num x;\n  PROC main()\n    x$0 := 1;\n  ENDPROC\nENDMODULE\n";
    assert_eq!(targets(builtin, type_definition), vec![]);
}

#[test]
fn references_are_case_insensitive_across_modules() {
    let src = "==> a.mod\nMODULE a\n  VAR num counter$0;\n  PROC main()\n    COUNTER := Counter + 1;\n  ENDPROC\nENDMODULE\n==> b.mod\nMODULE b\n  PROC other()\n    VAR num counter;\n    counter := 2;\n    TPWrite \"\"\\Num:=counter;\n  ENDPROC\n  PROC third()\n    counter := 3;\n  ENDPROC\nENDMODULE\n";
    let (task, unit, offset) = fixture(src);
    let refs: Vec<(String, usize)> = references(&task, unit, offset, true, &[])
        .into_iter()
        .map(|l| (l.path, l.range.start))
        .collect();
    // The declaration, two uses in main, one in b.third (b.other has its own).
    assert_eq!(refs.len(), 4, "{refs:?}");
    assert_eq!(refs.iter().filter(|(p, _)| p == "t/b.mod").count(), 1);
    assert_eq!(references(&task, unit, offset, false, &[]).len(), 3);
}

#[test]
fn highlights_tell_writes_from_reads() {
    let src = "MODULE m\n  PROC main()\n    VAR num n$0;\n    n := n + 1;\n    TPWrite \"\"\\Num:=n;\n  ENDPROC\nENDMODULE\n";
    let (task, unit, offset) = fixture(src);
    let hl: Vec<bool> = document_highlights(&task, unit, offset)
        .into_iter()
        .map(|(_, w)| w)
        .collect();
    assert_eq!(hl, vec![true, true, false, false]);
}

#[test]
fn rename_edits_every_use_and_refuses_clashes() {
    let src = "==> a.mod\nMODULE a\n  VAR num cnt$0;\n  PROC main()\n    VAR num other;\n    cnt := 1;\n  ENDPROC\nENDMODULE\n==> b.mod\nMODULE b\n  PROC p()\n    CNT := 2;\n  ENDPROC\nENDMODULE\n";
    let (task, unit, offset) = fixture(src);
    let edits = rename(&task, unit, offset, "total", &[]).unwrap_or_else(|e| panic!("{e}"));
    let summary: Vec<(String, usize)> = edits.iter().map(|(p, e)| (p.clone(), e.len())).collect();
    assert_eq!(summary, vec![("t/a.mod".into(), 2), ("t/b.mod".into(), 1)]);
    assert!(
        rename(&task, unit, offset, "other", &[]).is_err(),
        "clashes with routine data"
    );
    assert!(
        rename(&task, unit, offset, "MoveL", &[]).is_err(),
        "a built-in"
    );
    assert!(
        rename(&task, unit, offset, "ENDIF", &[]).is_err(),
        "a reserved word"
    );
    assert!(rename(&task, unit, offset, "1abc", &[]).is_err());
    assert!(rename(&task, unit, offset, &"a".repeat(33), &[]).is_err());
    assert!(
        rename(&task, unit, offset, "CNT", &[]).is_ok(),
        "same name, new case"
    );
}

#[test]
fn prepare_rename_refuses_builtins_and_keywords() {
    let src = "MODULE m\n  PROC main()\n    MoveL$0 p, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let (task, unit, offset) = fixture(src);
    assert!(prepare_rename(&task, unit, offset).is_err());
    let (task, unit, offset) = fixture(&src.replacen("MoveL$0", "MoveL", 1).replacen(
        "PROC main",
        "PR$0OC main",
        1,
    ));
    assert!(prepare_rename(&task, unit, offset).is_err());
    let (task, unit, offset) = fixture(
        &src.replacen("MoveL$0", "MoveL", 1)
            .replacen("main", "ma$0in", 1),
    );
    assert_eq!(
        prepare_rename(&task, unit, offset).map(|r| slice(&task, unit, r)),
        Ok("main".to_owned())
    );
}

#[test]
fn nothing_panics_on_odd_offsets() {
    let src = "MODULE m\n  PROC main()\n    MoveL p, v1$0\n  ENDPROC\nENDMODULE\n";
    let (task, unit, _) = fixture(src);
    for offset in 0..task.units[0].text.len() + 5 {
        let _ = definition(&task, unit, offset);
        let _ = references(&task, unit, offset, true, &[]);
        let _ = prepare_rename(&task, unit, offset);
        let _ = crate::ide::hover(&task, unit, offset);
    }
}

#[test]
fn renaming_a_parameter_renames_named_arguments() {
    let src = "==> a.mod\nMODULE a\n  PROC Grip(\\switch fa$0st, num force)\n    IF Present(fast) TPWrite \"f\";\n  ENDPROC\nENDMODULE\n==> b.mod\nMODULE b\n  PROC main()\n    Grip \\fast, force:=2;\n    Grip 1;\n  ENDPROC\nENDMODULE\n";
    let (task, unit, offset) = fixture(src);
    let edits = rename(&task, unit, offset, "quick", &[]).unwrap_or_else(|e| panic!("{e}"));
    let summary: Vec<(String, usize)> = edits.iter().map(|(p, e)| (p.clone(), e.len())).collect();
    assert_eq!(summary, vec![("t/a.mod".into(), 2), ("t/b.mod".into(), 1)]);
}

#[test]
fn arguments_of_reference_parameters_are_writes() {
    let src = "MODULE m\n  PROC bump(INOUT num v, num by)\n    v := v + by;\n  ENDPROC\n  PROC main()\n    VAR num n$0;\n    bump n, n;\n    Incr n;\n  ENDPROC\nENDMODULE\n";
    let (task, unit, offset) = fixture(src);
    let hl: Vec<bool> = document_highlights(&task, unit, offset)
        .into_iter()
        .map(|(_, w)| w)
        .collect();
    assert_eq!(hl, vec![true, true, false, true]);
}
