use super::fixture;
use crate::ide::{CompletionKind, completion_documentation, completions, signature_help};

fn labels(src: &str) -> Vec<(String, CompletionKind)> {
    let (task, unit, offset) = fixture(src);
    let mut items = completions(&task, unit, offset);
    items.sort_by(|a, b| a.sort_text.cmp(&b.sort_text).then(a.label.cmp(&b.label)));
    items.into_iter().map(|i| (i.label, i.kind)).collect()
}

fn has(items: &[(String, CompletionKind)], label: &str) -> bool {
    items.iter().any(|(l, _)| l.eq_ignore_ascii_case(label))
}

const HEAD: &str = "MODULE m\n  RECORD part\n    num weight;\n    pos place;\n  ENDRECORD\n  VAR part parts{3};\n  PERS robtarget pHome := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  CONST speeddata vSlow := [10, 10, 10, 10];\n  PROC Grip(num force)\n  ENDPROC\n";

fn in_proc(body: &str) -> String {
    format!("{HEAD}  PROC main()\n    VAR num count;\n{body}\n  ENDPROC\nENDMODULE\n")
}

#[test]
fn statement_start_offers_instructions_procedures_keywords_and_snippets() {
    let items = labels(&in_proc("    Mo$0"));
    for l in [
        "MoveL", "Grip", "count", "RETURN", "IF", "FOR", "WHILE", "TEST",
    ] {
        assert!(has(&items, l), "{l} missing");
    }
    let (task, unit, offset) = fixture(&in_proc("    $0"));
    let all = completions(&task, unit, offset);
    let for_snippet = all
        .iter()
        .find(|i| i.label == "FOR")
        .unwrap_or_else(|| panic!("no FOR"));
    assert!(for_snippet.is_snippet);
    assert!(
        for_snippet
            .insert_text
            .as_deref()
            .unwrap_or_default()
            .contains("${1:i}")
    );
    assert_eq!(for_snippet.detail.as_deref(), Some("FOR i FROM 1 TO 10 DO"));
    // Functions are not statements.
    assert!(!has(&labels(&in_proc("    $0")), "Abs"));
}

#[test]
fn the_most_called_instructions_come_first_at_a_statement_start() {
    let items = labels(&in_proc("    $0"));
    assert_eq!(
        items.first().map(|i| i.0.as_str()),
        Some("MoveL"),
        "{:?}",
        &items[..5]
    );
    let moves: Vec<&str> = items
        .iter()
        .map(|i| i.0.as_str())
        .filter(|l| l.starts_with("Move"))
        .take(3)
        .collect();
    assert_eq!(moves, ["MoveL", "MoveJ", "MoveAbsJ"]);
    // The program's own procedures come before the rarer built-ins.
    let at = |label: &str| items.iter().position(|i| i.0 == label);
    assert!(at("Grip") < at("MotionSup"), "{items:?}");
    // Functions too, within what fits the expected type.
    let items = labels(&in_proc("    MoveL $0"));
    let at = |label: &str| items.iter().position(|i| i.0 == label);
    assert!(at("Offs") < at("MirPos"), "{items:?}");
}

#[test]
fn lists_without_details_are_the_lists_with_their_details_left_out() {
    for src in [
        in_proc("    $0"),
        in_proc("    MoveL $0"),
        in_proc("    count := $0"),
        "MODULE m\n  TRAP t\n  ENDTRAP\n  PROC main()\n    CONNECT i WITH $0\n  ENDPROC\nENDMODULE\n".to_owned(),
    ] {
        let (task, unit, offset) = fixture(&src);
        let mut full = crate::ide::completions(&task, unit, offset);
        assert!(full.iter().any(|i| i.detail.is_some()), "{src}");
        let lean = crate::ide::completions_for(&task, unit, offset, false, None);
        for (f, l) in full.iter_mut().zip(&lean) {
            if l.detail.is_none() {
                f.detail = None;
            }
        }
        assert_eq!(full, lean, "{src}");
        assert!(
            lean.iter()
                .filter(|i| i.kind != crate::ide::CompletionKind::Snippet)
                .all(|i| i.detail.is_none()),
            "{src}"
        );
    }
}

#[test]
fn the_usage_table_names_only_built_ins() {
    let cat = crate::catalogue::base();
    let mut section = "";
    for line in include_str!("../usage.txt").lines() {
        match line.trim() {
            "" => {}
            l if l.starts_with('#') => {}
            l if l.starts_with('[') => section = l,
            name if section == "[instructions]" => {
                assert!(cat.instruction(name).is_some(), "{name} is no instruction");
            }
            name => assert!(cat.function(name).is_some(), "{name} is no function"),
        }
    }
}

#[test]
fn arguments_offer_data_of_the_expected_type_first() {
    let items = labels(&in_proc("    MoveL $0"));
    assert_eq!(
        items.first().map(|i| i.0.as_str()),
        Some("pHome"),
        "{:?}",
        &items[..5]
    );
    let items = labels(&in_proc("    MoveL pHome, $0"));
    assert_eq!(items.first().map(|i| i.0.as_str()), Some("vSlow"));
    assert!(has(&items, "v1000"), "built-in speeds are offered");
    let items = labels(&in_proc("    count := Abs($0"));
    assert!(has(&items, "count") && has(&items, "Sqrt"));
}

#[test]
fn after_backslash_the_optional_arguments_left() {
    let items = labels(&in_proc("    MoveL \\Conc, pHome, vSlow \\$0"));
    assert!(has(&items, "V") && has(&items, "T"));
    assert!(!has(&items, "WObj"), "its place is after Zone and Tool");
    assert!(!has(&items, "Conc"), "already given");
    assert!(!has(&items, "ToPoint"), "not optional");
    let items = labels(&in_proc("    MoveL pHome, vSlow \\V:=100, fine \\$0"));
    assert!(!has(&items, "T"), "an alternative of \\V");
    assert!(
        items
            .iter()
            .all(|(_, k)| *k == CompletionKind::OptionalArgument)
    );
}

#[test]
fn after_a_dot_the_components() {
    let items = labels(&in_proc("    parts{1}.$0"));
    assert_eq!(
        items,
        vec![
            ("weight".into(), CompletionKind::Component),
            ("place".into(), CompletionKind::Component)
        ]
    );
    let items = labels(&in_proc("    parts{1}.place.$0"));
    let names: Vec<&str> = items.iter().map(|i| i.0.as_str()).collect();
    assert_eq!(names, vec!["x", "y", "z"]);
    let items = labels(&in_proc("    count := pHome.trans.x + pHome.$0"));
    assert!(has(&items, "rot") && has(&items, "extax"));
}

#[test]
fn types_after_storage_keywords_and_in_parameter_lists() {
    let items = labels(&in_proc("    VAR $0"));
    assert!(has(&items, "num") && has(&items, "part") && has(&items, "robtarget"));
    assert!(items.iter().all(|(_, k)| *k == CompletionKind::Type));
    assert!(
        labels(&in_proc("    VAR num $0")).is_empty(),
        "the name is free"
    );
    let items = labels(&format!("{HEAD}  PROC p(num a, $0\nENDMODULE\n"));
    assert!(has(&items, "part"));
}

#[test]
fn nothing_in_comments_and_strings() {
    assert!(labels(&in_proc("    ! MoveL $0")).is_empty());
    assert!(labels(&in_proc("    TPWrite \"Mo$0")).is_empty());
}

#[test]
fn module_level_offers_declarations() {
    let items = labels("MODULE m\n  $0\nENDMODULE\n");
    assert!(has(&items, "PROC") && has(&items, "VAR") && !has(&items, "MoveL"));
}

#[test]
fn documentation_is_resolved_lazily() {
    let doc = completion_documentation("MoveL", CompletionKind::Procedure).unwrap_or_default();
    assert!(doc.contains("PROC MoveL("), "{doc}");
    assert!(completion_documentation("robtarget", CompletionKind::Type).is_some());
    assert!(completion_documentation("nothing", CompletionKind::Procedure).is_none());
}

/// The label of the active parameter of the signature help at `$0`.
fn active_label(src: &str) -> String {
    let (task, unit, offset) = fixture(src);
    let help = signature_help(&task, unit, offset).unwrap_or_else(|| panic!("no help"));
    let active = help
        .active_parameter
        .unwrap_or_else(|| panic!("no active parameter in {}", help.label));
    help.label[help.parameters[active].0.clone()].to_owned()
}

#[test]
fn signature_help_marks_the_active_parameter_and_shows_types() {
    let (task, unit, offset) = fixture(&in_proc("    MoveL pHome, $0"));
    let help = signature_help(&task, unit, offset).unwrap_or_else(|| panic!("no help"));
    assert!(
        help.label.starts_with(
            "MoveL [\\switch Conc], robtarget ToPoint, [\\identno ID], speeddata Speed, \
             [\\num V] | [\\num T], zonedata Zone, [\\num Z], [\\stoppointdata Inpos], \
             PERS tooldata Tool, [\\PERS wobjdata WObj]"
        ),
        "{}",
        help.label
    );
    assert_eq!(
        active_label(&in_proc("    MoveL pHome, $0")),
        "speeddata Speed"
    );
    assert_eq!(
        active_label(&in_proc("    MoveL pHome, vSlow \\T:=$0")),
        "[\\num T]"
    );
    // After `\`, the optional parameter that can come there, not the first
    // one of the routine.
    assert_eq!(
        active_label(&in_proc("    MoveL pHome, vSlow, fine, tool0 \\$0")),
        "[\\PERS wobjdata WObj]"
    );
    assert_eq!(
        active_label(&in_proc("    MoveL pHome, vSlow, fine, tool0 \\Co$0")),
        "[\\switch Corr]"
    );
    assert_eq!(active_label(&in_proc("    MoveL \\$0")), "[\\switch Conc]");
    assert_eq!(
        active_label(&in_proc("    MoveL \\Conc, pHome, vSlow \\V:=100, z10, $0")),
        "PERS tooldata Tool"
    );
    let (task, unit, offset) = fixture(&in_proc("    count := Round(count \\Dec:=1$0"));
    let help = signature_help(&task, unit, offset).unwrap_or_else(|| panic!("no help"));
    assert_eq!(help.label, "Round(num Val, [\\num Dec])");
    let (task, unit, offset) = fixture(&in_proc("    Grip $0"));
    let help = signature_help(&task, unit, offset).unwrap_or_else(|| panic!("no help"));
    assert_eq!(help.label, "Grip num force");
    assert_eq!(help.active_parameter, Some(0));
}

#[test]
fn signature_help_binds_as_the_checker_does() {
    // Alternatives before a positional parameter are not positional: the
    // value after them goes to the next positional parameter.
    let pick = "MODULE m\n  PROC Pick(\\num A | \\num B, num force, \\switch Hold)\n  ENDPROC\n  PROC main()\n";
    let at = |call: &str| active_label(&format!("{pick}    {call}\n  ENDPROC\nENDMODULE\n"));
    assert_eq!(at("Pick $0"), "num force");
    assert_eq!(at("Pick \\A:=1, $0"), "num force");
    assert_eq!(at("Pick \\B:=1, 5 \\H$0"), "[\\switch Hold]");
    assert_eq!(
        active_label(&in_proc("    MoveL pHome, vSlow \\T:=2, $0")),
        "zonedata Zone"
    );
    // An optional argument written before its place does not move the
    // next value past the positional parameters it skipped: the checker
    // binds it to Speed, and so does the help.
    assert_eq!(
        active_label(&in_proc("    MoveL pHome, \\V:=100, $0")),
        "speeddata Speed"
    );
    // No positional parameter left.
    let (task, unit, offset) = fixture(&in_proc("    Grip 1, $0"));
    let help = signature_help(&task, unit, offset).unwrap_or_else(|| panic!("no help"));
    assert_eq!(help.active_parameter, None);
}

#[test]
fn after_backslash_only_the_parameters_that_may_come_next() {
    let all =
        |src: &str| -> Vec<String> { labels(&in_proc(src)).into_iter().map(|(l, _)| l).collect() };
    assert_eq!(
        all("    MoveL pHome, vSlow, fine, tool0\\$0"),
        ["WObj", "Corr", "TLoad"]
    );
    assert_eq!(
        all("    MoveL pHome, vSlow, fine, tool0\\WObj:=wobj0\\$0"),
        ["Corr", "TLoad"]
    );
    assert_eq!(all("    MoveL pHome, vSlow \\$0"), ["V", "T"]);
    assert_eq!(all("    MoveL pHome, vSlow, z10 \\$0"), ["Z", "Inpos"]);
    assert_eq!(all("    MoveL pHome \\$0"), ["ID"]);
    assert_eq!(all("    MoveL \\$0"), ["Conc"]);
    // typing the name: the same list (the editor filters it)
    assert_eq!(
        all("    MoveL pHome, vSlow, fine, tool0\\Co$0"),
        ["WObj", "Corr", "TLoad"]
    );
}

/// The items of the list asked for by typing `trigger` just before `$0`.
fn triggered(src: &str, trigger: char) -> Vec<String> {
    let (task, unit, offset) = fixture(src);
    let mut items = crate::ide::completions_for(&task, unit, offset, false, Some(trigger));
    items.sort_by(|a, b| a.sort_text.cmp(&b.sort_text).then(a.label.cmp(&b.label)));
    items.into_iter().map(|i| i.label).collect()
}

const CELL: &str = "MODULE m\n  PERS wobjdata wTable := [FALSE, TRUE, \"\", [[0,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];\n  PERS wobjdata wFixture := [FALSE, TRUE, \"\", [[0,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];\n  PERS loaddata lBox := [1, [0,0,1], [1,0,0,0], 0, 0, 0];\n  CONST robtarget pPick := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  CONST robtarget pPlace := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  VAR num count;\n  PROC main()\n    MoveL pPlace, v100, fine, tool0\\WObj:=wFixture;\n    MoveL pPlace, v100, fine, tool0\\WObj:=wFixture;\n    MoveJ pPick, v100, fine, tool0;\n";

fn in_cell(line: &str) -> String {
    format!("{CELL}    {line}\n  ENDPROC\nENDMODULE\n")
}

#[test]
fn a_typed_argument_offers_the_data_of_its_type_the_most_used_first() {
    // a blank after the instruction's name opens its first argument
    let items = triggered(&in_cell("MoveL $0"), ' ');
    assert_eq!(
        items.get(..2),
        Some(&["pPlace".to_owned(), "pPick".to_owned()][..]),
        "{items:?}"
    );
    assert!(
        items.iter().any(|i| i == "Offs"),
        "functions that give a robtarget"
    );
    assert!(
        !items.iter().any(|i| i == "count" || i == "Abs"),
        "{items:?}"
    );
    // the wobjdata in scope after \WObj:=, the loaddata after \TLoad:=
    let items = triggered(&in_cell("MoveL pPick, v100, fine, tool0\\WObj:=$0"), '=');
    assert_eq!(
        items.get(..3),
        Some(
            &[
                "wFixture".to_owned(),
                "wTable".to_owned(),
                "wobj0".to_owned()
            ][..]
        ),
        "{items:?}"
    );
    assert!(
        !items.iter().any(|i| i == "lBox" || i == "pPick"),
        "{items:?}"
    );
    let items = triggered(&in_cell("MoveL pPick, v100, fine, tool0\\TLoad:=$0"), '=');
    assert_eq!(items.first().map(String::as_str), Some("lBox"), "{items:?}");
    assert!(items.iter().all(|i| i != "wTable"), "{items:?}");
    // asked for without a trigger, the same
    assert_eq!(
        labels(&in_cell("MoveL pPick, v100, fine, tool0\\WObj:=$0"))
            .first()
            .map(|i| i.0.as_str()),
        Some("wFixture")
    );
    // a number is any expression: everything, numbers first
    let items = triggered(&in_cell("WaitTime $0"), ' ');
    assert_eq!(
        items.first().map(String::as_str),
        Some("count"),
        "{items:?}"
    );
    assert!(items.iter().any(|i| i == "Abs") && items.iter().any(|i| i == "pPick"));
}

#[test]
fn a_blank_or_an_equals_sign_asks_only_where_a_value_is_due() {
    for (src, trigger) in [
        (in_cell("IF count > 1 $0"), ' '),
        (in_cell("count $0"), ' '),
        (in_cell("MoveL pPick, v100, fine $0"), ' '),
        (in_cell("IF count = $0"), '='),
        (in_cell("! MoveL $0"), ' '),
        (in_cell("MoveL pPick, v100, fine, tool0\\WObj $0"), ' '),
    ] {
        assert_eq!(triggered(&src, trigger), Vec::<String>::new(), "{src}");
    }
    assert!(!triggered(&in_cell("MoveL pPick, $0"), ' ').is_empty());
    assert_eq!(
        triggered(&in_cell("count := $0"), '=')
            .first()
            .map(String::as_str),
        Some("count")
    );
}

#[test]
fn completion_never_panics() {
    let src = in_proc("    MoveL \\Conc, p.x{1, [2, \"a!\"], Abs(\\");
    let (task, unit, _) = fixture(&src);
    for offset in 0..src.len() + 3 {
        let _ = completions(&task, unit, offset);
        let _ = signature_help(&task, unit, offset);
    }
}

#[test]
fn labels_traps_and_declaration_values() {
    let items = labels(&in_proc("  again:\n    GOTO $0"));
    assert_eq!(items, vec![("again".into(), CompletionKind::Label)]);
    let src = format!(
        "{HEAD}  TRAP onStop\n  ENDTRAP\n  PROC main()\n    VAR intnum irq;\n    CONNECT irq WITH $0\n  ENDPROC\nENDMODULE\n"
    );
    assert_eq!(labels(&src), vec![("onStop".into(), CompletionKind::Trap)]);
    let items = labels(&in_proc("    VAR speeddata s := $0"));
    assert_eq!(items.first().map(|i| i.0.as_str()), Some("vSlow"));
}

#[test]
fn builtin_details_say_their_robotware_versions_and_option() {
    let (mut task, unit, offset) = fixture(&in_proc("    count := $0"));
    let detail = |task: &crate::task::Task, label: &str| -> String {
        completions(task, unit, offset)
            .into_iter()
            .find(|i| i.label == label)
            .and_then(|i| i.detail)
            .unwrap_or_default()
    };
    assert_eq!(detail(&task, "Abs"), "FUNC num Abs(num Input)");
    assert!(
        detail(&task, "StrFormat").ends_with("  (RobotWare 7.0 and later)"),
        "{}",
        detail(&task, "StrFormat")
    );
    assert!(
        detail(&task, "EGMGetState").ends_with(
            "  (RobotWare 6.00 and later; option Externally Guided Motion (EGM), not enabled here)"
        ),
        "{}",
        detail(&task, "EGMGetState")
    );
    task.set_catalogue(&crate::catalogue::Selection::new(
        Some(crate::catalogue::Version::new(6, 8)),
        Vec::new(),
    ));
    assert!(
        detail(&task, "StrFormat").ends_with("; not in RobotWare 6.08: added in 7.0)"),
        "{}",
        detail(&task, "StrFormat")
    );
    assert!(
        detail(&task, "EGMGetState").ends_with(
            "(RobotWare 6.00 and later; option Externally Guided Motion (EGM), not enabled here)"
        ),
        "{}",
        detail(&task, "EGMGetState")
    );
}
