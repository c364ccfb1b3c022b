use super::fixture;
use crate::ide::hover;

fn hover_text(src: &str) -> String {
    let (task, unit, offset) = fixture(src);
    hover(&task, unit, offset)
        .map(|h| h.markdown)
        .unwrap_or_default()
}

#[test]
fn builtins_show_signature_and_documentation() {
    let h = hover_text(
        "MODULE m\n  PROC main()\n    Mo$0veL p, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(
        h.contains("PROC MoveL(\\switch Conc, robtarget ToPoint"),
        "{h}"
    );
    assert!(h.contains("Linear move"), "{h}");
    let h = hover_text("MODULE m\n  VAR robt$0arget p;\nENDMODULE\n");
    assert!(h.contains("RECORD robtarget"), "{h}");
    let h = hover_text(
        "MODULE m\n  PROC main()\n    MoveL p, v1$0000, fine, tool0;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(h.contains("speeddata v1000 :="), "{h}");
}

#[test]
fn user_symbols_show_declaration_and_doc_comment() {
    let src = "MODULE m\n  ! The gripper tool.\n  ! Calibrated 2024.\n  PERS tooldata tGripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]]; ! main tool\n  PROC main()\n    MoveL p, v100, fine, tGrip$0per;\n  ENDPROC\nENDMODULE\n";
    let h = hover_text(src);
    assert!(h.contains("PERS tooldata tGripper := [TRUE,"), "{h}");
    assert!(
        h.contains("The gripper tool.  \nCalibrated 2024.  \nmain tool"),
        "{h}"
    );
    let h = hover_text(
        "MODULE m\n  ! Moves home.\n  PROC goHome(\\switch fast)\n  ENDPROC\n  PROC main()\n    goH$0ome;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(h.contains("PROC goHome(\\switch fast)"), "{h}");
    assert!(h.contains("Moves home."), "{h}");
    let h = hover_text(
        "MODULE m\n  PROC p(INOUT num val{*})\n    val$0{1} := 1;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(
        h.contains("INOUT num val{*}") && h.contains("parameter of `p`"),
        "{h}"
    );
}

#[test]
fn long_declarations_are_shortened() {
    let long = (0..80)
        .map(|i| i.to_string())
        .collect::<Vec<_>>()
        .join(", ");
    let h = hover_text(&format!(
        "MODULE m\n  CONST num tab{{80}} := [{long}];\n  PROC main()\n    TPWrite \"\"\\Num:=ta$0b{{1}};\n  ENDPROC\nENDMODULE\n"
    ));
    assert!(h.contains(" ...") && h.len() < 600, "{h}");
}

#[test]
fn robtargets_are_decoded() {
    let src = "MODULE m\n  CONST robtarget p$010 := [[100, -20.5, 300], [0.7071068, 0, 0.7071068, 0], [0, -1, 2, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\nENDMODULE\n";
    let h = hover_text(src);
    assert!(h.contains("x = 100, y = -20.5, z = 300"), "{h}");
    assert!(h.contains("ry = 90°"), "{h}");
    assert!(h.contains("cf1 = 0, cf4 = -1, cf6 = 2, cfx = 0"), "{h}");
    assert!(h.contains("a = not used"), "{h}");
    let literal = "MODULE m\n  PROC main()\n    MoveL [[1, 2, 3], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 5$0]], v100, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let h = hover_text(literal);
    assert!(
        h.contains("x = 1, y = 2, z = 3") && h.contains("f = 5"),
        "{h}"
    );
}

#[test]
fn constant_expressions_show_their_value() {
    let h = hover_text(
        "MODULE m\n  CONST num half := 1 / 2;\n  PROC main()\n    TPWrite \"\"\\Num:=Sqrt(2)$0;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(h.contains("= 1.41421"), "{h}");
    let h = hover_text(
        "MODULE m\n  CONST num half := 1 / 2;\n  PROC main()\n    TPWrite \"\"\\Num:=ha$0lf;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(
        h.contains("CONST num half := 1 / 2;") && h.contains("= 0.5"),
        "{h}"
    );
    let h = hover_text(
        "MODULE m\n  CONST orient o := OrientZYX(90, 0, 0);\n  PROC main()\n    TPWrite \"\"\\Orient:=o$0;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(h.contains("rz = 90°"), "{h}");
}

#[test]
fn a_constants_value_shows_on_its_declaration_too() {
    let src = |decl: &str| {
        format!(
            "MODULE m\n  CONST num rows := 3;\n  {decl}\n  PROC main()\n    CONST num twi$0ce := rows * 2;\n    TPWrite \"\"\\Num:=slots;\n  ENDPROC\nENDMODULE\n"
        )
    };
    // The module constant, hovered at its declaration.
    let h = hover_text(
        &src("CONST num slots := rows * 4;")
            .replace("twi$0ce", "twice")
            .replace("num slots", "num sl$0ots"),
    );
    assert!(
        h.contains("CONST num slots := rows * 4;") && h.contains("`= 12` (num)"),
        "{h}"
    );
    // A routine's constant, at its declaration.
    let h = hover_text(&src("CONST num slots := rows * 4;"));
    assert!(h.contains("`= 6` (num)"), "{h}");
    // Data that are not constant show no value at their declaration.
    let h = hover_text(
        &src("VAR num slots := rows * 4;")
            .replace("twi$0ce", "twice")
            .replace("num slots", "num sl$0ots"),
    );
    assert!(h.contains("VAR num slots") && !h.contains("`= 12`"), "{h}");
}

#[test]
fn literal_initial_values_are_not_repeated() {
    let h = hover_text(
        "MODULE m\n  CONST num k := 2;\n  PROC main()\n    TPWrite \"\"\\Num:=k$0;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(
        h.contains("CONST num k := 2;") && !h.contains("`= 2`"),
        "{h}"
    );
}

/// The hover of `src` in a task whose controller runs `robotware` with `options`.
fn hover_on(src: &str, robotware: Option<(u16, u16)>, options: &[&str]) -> String {
    let (mut task, unit, offset) = fixture(src);
    task.set_catalogue(&crate::catalogue::Selection::new(
        robotware.map(|(major, minor)| crate::catalogue::Version::new(major, minor)),
        options.iter().map(|o| (*o).to_owned()),
    ));
    hover(&task, unit, offset)
        .map(|h| h.markdown)
        .unwrap_or_default()
}

#[test]
fn builtins_say_their_robotware_versions_and_option() {
    // A base built-in of every version says nothing of versions.
    let h = hover_text(
        "MODULE m\n  PROC main()\n    Mo$0veL p, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n",
    );
    assert!(!h.contains("RobotWare") && !h.contains("option"), "{h}");
    let format =
        "MODULE m\n  PROC main()\n    TPWrite StrFor$0mat(\"{1}\");\n  ENDPROC\nENDMODULE\n";
    let h = hover_text(format);
    assert!(h.ends_with("\n\n*RobotWare 7.0 and later*"), "{h}");
    let h = hover_on(format, Some((6, 8)), &[]);
    assert!(
        h.ends_with("\n\n*RobotWare 7.0 and later; not in RobotWare 6.08: added in 7.0*"),
        "{h}"
    );
    assert_eq!(
        hover_on(format, Some((7, 1)), &[]),
        hover_text(format),
        "a controller that has it"
    );
    let egm =
        "MODULE m\n  VAR egmident id;\n  PROC main()\n    EGMRe$0set id;\n  ENDPROC\nENDMODULE\n";
    let h = hover_text(egm);
    assert!(
        h.ends_with(
            "\n\n*RobotWare 6.00 and later; option Externally Guided Motion (EGM), not enabled here*"
        ),
        "{h}"
    );
    let h = hover_on(egm, Some((6, 15)), &["arc"]);
    assert!(h.ends_with("(EGM), not enabled here*"), "{h}");
    let h = hover_on(egm, Some((6, 15)), &["egm"]);
    assert!(
        h.ends_with("\n\n*RobotWare 6.00 and later; option Externally Guided Motion (EGM)*"),
        "{h}"
    );
}

#[test]
fn parameters_added_later_say_so() {
    let src = "MODULE m\n  VAR egmident id;\n  PROC main()\n    EGMSetupUC ROB_1, id, \"default\", \"dev\" \\AP$0TR;\n  ENDPROC\nENDMODULE\n";
    let h = hover_text(src);
    assert!(
        h.contains("parameter of `EGMSetupUC`") && h.ends_with("\n\n*added in RobotWare 6.07*"),
        "{h}"
    );
    // A controller that has it says the same; an older one has no such
    // parameter (its view drops it).
    let h = hover_on(src, Some((6, 15)), &["egm"]);
    assert!(h.ends_with("\n\n*added in RobotWare 6.07*"), "{h}");
}
