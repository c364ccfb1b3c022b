use super::*;

#[test]
fn configuration_applies_below_its_root() {
    assert_eq!(config_root("b/SYSPAR/EIO.cfg"), "b");
    assert_eq!(config_root("proj/EIO.cfg"), "proj");
    assert!(config_applies("b/SYSPAR/EIO.cfg", "b/RAPID/TASK1"));
    assert!(!config_applies(
        "b/SYSPAR/EIO.cfg",
        "b/RAPID/TASK1/x/RAPID/TASK1"
    ));
    // Beside modules outside a backup: their folder's, not a subfolder's.
    assert!(config_applies("cell/SYSPAR/EIO.cfg", "cell"));
    assert!(config_applies("SYSPAR/MOC.cfg", ""));
    assert!(!config_applies("cell/SYSPAR/EIO.cfg", "cell/old"));
    assert!(!config_applies("cell/SYSPAR/EIO.cfg", "cell2"));
    assert!(config_applies("MOC.cfg", ""));
    assert!(config_applies("cell/EIO.cfg", "cell/sub"));
}

#[test]
fn a_backups_robot_is_its_own() {
    let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n";
    let mut ws = Workspace::new();
    ws.set_config("b1/SYSPAR/MOC.cfg", moc);
    let robot = |key: &str| ws.robot_for(key).ok().flatten().is_some();
    assert!(robot("b1/RAPID/T_ROB1"));
    // A backup named like a prefix, or one kept in b1's HOME/, has its own.
    assert!(!robot("b10/RAPID/T_ROB1"));
    assert!(!robot("b1/HOME/old/b2/RAPID/T_ROB1"));
}

#[test]
fn a_multimove_task_moves_the_robot_of_its_unit_group() {
    let moc = "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT_GROUP:\n\n      -name \"rob1\" -robot \"ROB_1\"\n\n      -name \"rob2\" -robot \"ROB_2\"\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n\n      -name \"ROB_2\" -use_robot_type \"ROB2_2600_1.85_12_03\"\n";
    // T_ROB1 in RAPID/TASK1 moves robot 2 and PAINT in RAPID/TASK2 robot 1,
    // by their groups; T_ROB2 in RAPID/TASK3, without one, by its name.
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -MotionTask -UseMechanicalUnitGroup \"rob2\"\n\n      -Name \"PAINT\" -MotionTask -UseMechanicalUnitGroup \"ROB1\"\n\n      -Name \"T_ROB2\" -MotionTask\n";
    let mut ws = Workspace::new();
    ws.set_config("b/SYSPAR/MOC.cfg", moc);
    ws.set_config("b/SYSPAR/SYS.cfg", sys);
    let model = |key: &str| {
        ws.robot_for(key)
            .ok()
            .flatten()
            .map(|r| r.robot.model.name.clone())
    };
    assert_eq!(model("b/RAPID/TASK1").as_deref(), Some("IRB 2600-12/1.85"));
    assert_eq!(model("b/RAPID/TASK2").as_deref(), Some("IRB 120-3/0.58"));
    assert_eq!(model("b/RAPID/TASK3").as_deref(), Some("IRB 2600-12/1.85"));
    // A task folder named as its task, and a task of no robot of the two.
    assert_eq!(model("b/RAPID/PAINT").as_deref(), Some("IRB 120-3/0.58"));
    assert_eq!(model("b/RAPID/TASK4"), None);
}

#[test]
fn sys_cfg_entries_are_found_by_task_folder() {
    use crate::task::{TaskKind, TaskSettings};
    let entry = |name: &str, kind| TaskSettings {
        name: name.to_owned(),
        kind,
        entry: None,
        motion: false,
        unit_group: None,
    };
    let all = [
        entry("T_ROB1", TaskKind::Normal),
        entry("T_BACK", TaskKind::SemiStatic),
    ];
    let of = |key: &str| settings_by_folder(key, &all).map(|s| s.name);
    assert_eq!(of("b/RAPID/TASK2").as_deref(), Some("T_BACK"));
    assert_eq!(of("b/RAPID/TASK1").as_deref(), Some("T_ROB1"));
    assert_eq!(of("b/RAPID/t_back").as_deref(), Some("T_BACK"));
    assert_eq!(of("b/RAPID/TASK3"), None);
    assert_eq!(of("b/RAPID/TASK0"), None);
}

#[test]
fn an_edit_in_one_routine_rechecks_only_its_changed_statements() {
    let mut body = String::new();
    for i in 0..200 {
        body.push_str(&format!("    n := n + {i};\n    WaitTime 0.{i};\n"));
    }
    let text = format!(
        "MODULE A\n  VAR num n;\n  PROC main()\n{body}  ENDPROC\n  PROC other()\n    n := 1;\n  ENDPROC\nENDMODULE\n"
    );
    let mut ws = Workspace::new();
    ws.set_file("p/A.mod", text.clone());
    ws.set_file(
        "p/B.mod",
        "MODULE B\n  PROC helper()\n  ENDPROC\nENDMODULE\n".into(),
    );
    assert!(ws.diagnostics("p/A.mod").is_empty());
    let b = ws.diagnostics("p/B.mod");
    // One character changed in one statement of main.
    let edited = text.replacen("n := n + 7;", "n := n + 1000;", 1);
    ws.set_file("p/A.mod", edited);
    assert!(ws.diagnostics("p/A.mod").is_empty());
    let cache = &ws.checked["p/A.mod"].statements;
    assert_eq!(cache.reused(), 400, "every other statement is reused");
    // The other module's result is not recomputed at all.
    assert!(Arc::ptr_eq(&b, &ws.diagnostics("p/B.mod")));
}

/// Compound statements are cached whole unless a GOTO inside depends on
/// the routine's labels, which the cache key leaves out.
#[test]
fn a_goto_inside_a_compound_statement_follows_the_labels() {
    let text = |label: &str| {
        format!(
            "MODULE A\n  VAR num n;\n  PROC main()\n    {label}:\n    n := 1;\n    IF n > 0 THEN\n      n := 2;\n      GOTO again;\n    ENDIF\n  ENDPROC\nENDMODULE\n"
        )
    };
    let mut ws = Workspace::new();
    ws.set_file("p/A.mod", text("again"));
    assert!(ws.diagnostics("p/A.mod").is_empty());
    ws.set_file("p/A.mod", text("other"));
    let found = ws.diagnostics("p/A.mod");
    assert!(
        found.iter().any(|d| d.rule.name == "unknown-label"),
        "{found:?}"
    );
    let unit = ws.unit("p/A.mod").cloned().expect("the file");
    let task = ws.task_of("p/A.mod");
    assert_eq!(*found, diagnostics_of(&task, &unit));
}

/// An edit elsewhere leaves a compound statement's result cached, and the
/// workspace rebuilds the task from its known members.
#[test]
fn compound_statements_are_reused_whole() {
    let mut body = String::new();
    for i in 0..50 {
        body.push_str(&format!(
            "    IF n > {i} THEN\n      n := {i};\n    ENDIF\n"
        ));
    }
    let text = format!("MODULE A\n  VAR num n;\n  PROC main()\n{body}  ENDPROC\nENDMODULE\n");
    let mut ws = Workspace::new();
    ws.set_file("p/A.mod", text.clone());
    ws.set_file("p/B.mod", "MODULE B\nENDMODULE\n".into());
    assert!(ws.diagnostics("p/A.mod").is_empty());
    ws.set_file("p/A.mod", text.replacen("n := 7;", "n := 8;", 1));
    assert!(ws.members.contains_key("p"), "the task's members are kept");
    assert!(ws.diagnostics("p/A.mod").is_empty());
    assert_eq!(ws.task_of("p/A.mod").units.len(), 2);
    // The 49 other IF statements, whole.
    assert_eq!(ws.checked["p/A.mod"].statements.reused(), 49);
}

#[test]
fn a_persistent_changed_in_one_task_rechecks_the_other_tasks() {
    let module = |ty: &str| format!("MODULE M\n  PERS {ty} shared := 0;\nENDMODULE\n");
    let mut ws = Workspace::new();
    ws.set_file("b/RAPID/TASK1/PROGMOD/M.mod", module("num"));
    ws.set_file("b/RAPID/TASK2/PROGMOD/M.mod", module("num"));
    assert!(ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod").is_empty());
    ws.set_file("b/RAPID/TASK2/PROGMOD/M.mod", module("dnum"));
    let found = ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod");
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0].rule.name, "shared-persistent-mismatch");
    let related = &found[0].related[0];
    assert_eq!(related.file.as_deref(), Some("b/RAPID/TASK2/PROGMOD/M.mod"));
    ws.remove_file("b/RAPID/TASK2/PROGMOD/M.mod");
    assert!(ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod").is_empty());
}

#[test]
fn a_configuration_change_rechecks_the_files_it_applies_to() {
    let mut ws = Workspace::new();
    ws.set_file(
        "cell/M.mod",
        "MODULE M\n  PROC main()\n    SetDO doGrip, 1;\n  ENDPROC\nENDMODULE\n".into(),
    );
    ws.set_config(
        "cell/EIO.cfg",
        "EIO_SIGNAL:\n  -Name \"doOther\" -SignalType \"DO\"\n",
    );
    let first = ws.diagnostics("cell/M.mod");
    assert_eq!(first.len(), 1, "{first:?}");
    assert_eq!(first[0].rule.name, "unresolved-name");
    ws.set_config(
        "cell/EIO.cfg",
        "EIO_SIGNAL:\n  -Name \"doGrip\" -SignalType \"DO\"\n",
    );
    let again = ws.diagnostics("cell/M.mod");
    assert!(again.is_empty(), "{again:?}");
}

#[test]
fn results_are_reused_until_the_task_interface_changes() {
    let mut ws = Workspace::new();
    ws.set_file(
        "p/A.mod",
        "MODULE A\n  PROC main()\n    helper;\n  ENDPROC\nENDMODULE\n".into(),
    );
    ws.set_file(
        "p/B.mod",
        "MODULE B\n  PROC helper()\n  ENDPROC\nENDMODULE\n".into(),
    );
    let first = ws.diagnostics("p/A.mod");
    assert!(first.is_empty(), "{first:?}");
    // An edit inside B's routine body keeps B's interface: A's result is reused.
    ws.set_file(
        "p/B.mod",
        "MODULE B\n  PROC helper()\n    Stop;\n  ENDPROC\nENDMODULE\n".into(),
    );
    assert!(Arc::ptr_eq(&first, &ws.diagnostics("p/A.mod")));
    // Renaming the routine changes the interface: A is checked again.
    ws.set_file(
        "p/B.mod",
        "MODULE B\n  PROC helper2()\n  ENDPROC\nENDMODULE\n".into(),
    );
    let again = ws.diagnostics("p/A.mod");
    assert_eq!(again.len(), 1, "{again:?}");
    assert_eq!(again[0].rule.name, "unresolved-name");
}

#[test]
fn the_task_ids_of_a_backup_come_from_sys_cfg() {
    let mut ws = Workspace::new();
    ws.set_file(
        "b/RAPID/TASK1/PROGMOD/M.mod",
        "MODULE M\n  VAR taskid t;\n  PROC main()\n    t := T_PAINTId;\n    t := T_GLUEId;\n  ENDPROC\nENDMODULE\n".into(),
    );
    let before = ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod");
    assert_eq!(before.len(), 2, "{before:?}");
    ws.set_config(
        "b/SYSPAR/SYS.cfg",
        "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T_PAINT\" -Type \"NORMAL\"\n",
    );
    let after = ws.diagnostics("b/RAPID/TASK1/PROGMOD/M.mod");
    assert_eq!(after.len(), 1, "{after:?}");
    assert!(after[0].message.contains("T_GLUEId"), "{after:?}");
}

/// A module and a configuration of the extra paths are seen by every task
/// under their own path and are not among the files checked.
#[test]
fn extra_modules_and_configuration_join_every_task() {
    let mut ws = Workspace::new();
    let main = "MODULE Main\n  PROC main()\n    helper;\n    SetDO do1, 1;\n  ENDPROC\nENDMODULE\n";
    ws.set_file("p/a/Main.mod", main.into());
    ws.set_file("p/b/Main.mod", main.into());
    let codes = |ws: &mut Workspace, path: &str| -> Vec<String> {
        ws.diagnostics(path)
            .iter()
            .map(|d| d.rule.code.to_owned())
            .collect()
    };
    assert!(!codes(&mut ws, "p/a/Main.mod").is_empty());
    let lib = Unit::new(
        "lib/Lib.mod".to_owned(),
        "MODULE Lib\n  PROC helper()\n  ENDPROC\nENDMODULE\n".to_owned(),
        None,
    );
    ws.add_extra_unit(Arc::new(lib));
    ws.add_extra_config("EIO_SIGNAL:\n  -Name \"do1\" -SignalType \"DO\"\n");
    assert!(codes(&mut ws, "p/a/Main.mod").is_empty());
    assert!(codes(&mut ws, "p/b/Main.mod").is_empty());
    let task = ws.task_of("p/a/Main.mod");
    assert!(task.units.iter().any(|u| u.path == "lib/Lib.mod"));
    let checked: Vec<String> = ws.checks().iter().map(|(_, u)| u.path.clone()).collect();
    assert_eq!(checked, ["p/a/Main.mod", "p/b/Main.mod"]);
    assert!(ws.unit("lib/Lib.mod").is_none());
    ws.clear_extras();
    assert!(!codes(&mut ws, "p/b/Main.mod").is_empty());
}

/// Another module's constant values are an input of a file's check (a
/// division by a constant of zero), though not of the task's interface.
#[test]
fn results_are_checked_again_when_another_modules_constants_change() {
    let mut ws = Workspace::new();
    ws.set_file(
        "p/A.mod",
        "MODULE A\n  VAR num r;\n  PROC main()\n    r := 1 / parts;\n  ENDPROC\nENDMODULE\n".into(),
    );
    let constant = |n: u32| format!("MODULE B\n  CONST num parts := {n};\nENDMODULE\n");
    ws.set_file("p/B.mod", constant(2));
    assert!(ws.diagnostics("p/A.mod").is_empty());
    ws.set_file("p/B.mod", constant(0));
    let found = ws.diagnostics("p/A.mod");
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0].rule.name, "constant-error");
    ws.set_file("p/B.mod", constant(3));
    assert!(ws.diagnostics("p/A.mod").is_empty());
}

/// A check handed out runs outside the workspace and is taken back: the
/// result is cached for its text and task, its statement results serve
/// the next check, and the last result of an older text is what carries
/// over until a configuration change.
#[test]
fn checks_run_outside_the_workspace_and_are_taken_back() {
    let text = |call: &str| {
        format!("MODULE A\n  PROC main()\n    {call};\n    other;\n  ENDPROC\nENDMODULE\n")
    };
    let all = crate::rules::Selection::all();
    let mut ws = Workspace::new();
    ws.set_file("p/A.mod", text("one"));
    let unit = ws.unit("p/A.mod").cloned().expect("the file");
    let task = ws.task_of("p/A.mod");
    assert!(ws.cached("p/A.mod", &unit, &task, &all).is_none());
    let check = ws.check("p/A.mod", unit.clone(), task.clone(), all.clone());
    let result = check.run();
    assert_eq!(*result.diagnostics, diagnostics_of(&task, &unit));
    ws.finish(result, true);
    let first = ws.cached("p/A.mod", &unit, &task, &all).expect("cached");
    assert_eq!(first.len(), 2, "{first:?}");
    assert!(ws.previous("p/A.mod", &unit).is_none(), "the same text");
    // An edit: the old result carries over; the next check reuses the
    // statement it did not change, and takes the results (a second check
    // handed out meanwhile gets none).
    ws.set_file("p/A.mod", text("two"));
    let edited = ws.unit("p/A.mod").cloned().expect("the file");
    let task = ws.task_of("p/A.mod");
    assert!(ws.cached("p/A.mod", &edited, &task, &all).is_none());
    let (old_unit, old) = ws.previous("p/A.mod", &edited).expect("previous");
    assert!(Arc::ptr_eq(&old_unit, &unit) && Arc::ptr_eq(&old, &first));
    let check = ws.check("p/A.mod", edited.clone(), task.clone(), all.clone());
    let meanwhile = ws
        .check("p/A.mod", edited.clone(), task.clone(), all.clone())
        .run();
    ws.finish(meanwhile, true);
    assert_eq!(ws.checked["p/A.mod"].statements.reused(), 0, "taken");
    let result = check.run();
    assert_eq!(*result.diagnostics, diagnostics_of(&task, &edited));
    ws.finish(result, true);
    assert_eq!(ws.checked["p/A.mod"].statements.reused(), 1, "`other`");
    assert!(ws.cached("p/A.mod", &edited, &task, &all).is_some());
    // A result kept without its statement results.
    let result = ws
        .check("p/A.mod", edited.clone(), task.clone(), all.clone())
        .run();
    ws.finish(result, false);
    let next = ws
        .check("p/A.mod", edited.clone(), task.clone(), all.clone())
        .run();
    ws.finish(next, true);
    assert_eq!(ws.checked["p/A.mod"].statements.reused(), 0, "not kept");
    // After a configuration change, an older text's result is not carried.
    ws.set_file("p/A.mod", text("three"));
    ws.set_config(
        "p/EIO.cfg",
        "EIO_SIGNAL:\n  -Name \"do1\" -SignalType \"DO\"\n",
    );
    let newest = ws.unit("p/A.mod").cloned().expect("the file");
    assert!(ws.previous("p/A.mod", &newest).is_none());
    // Another selection of rules is another result.
    let w101 = crate::rules::Selection::of(|r| r.code == "W101");
    assert!(ws.cached("p/A.mod", &edited, &task, &w101).is_none());
    let only = ws
        .check("p/A.mod", edited.clone(), task.clone(), w101)
        .run();
    assert!(only.diagnostics.iter().all(|d| d.rule.code == "W101"));
}

/// A cached result holds the positions of the other files its findings
/// point at: an edit that moves them (without changing what they declare)
/// makes it stale.
#[test]
fn related_positions_follow_edits_of_the_other_file() {
    let a = "MODULE A\n  VAR num counter;\nENDMODULE\n";
    let b = "MODULE B\n  VAR num counter;\nENDMODULE\n";
    let mut ws = Workspace::new();
    ws.set_file("b/RAPID/TASK1/PROGMOD/A.mod", a.into());
    ws.set_file("b/RAPID/TASK1/PROGMOD/B.mod", b.into());
    let before = ws.diagnostics("b/RAPID/TASK1/PROGMOD/A.mod");
    assert_eq!(before[0].related[0].range, 19..26);
    ws.set_file("b/RAPID/TASK1/PROGMOD/B.mod", format!("! a comment\n{b}"));
    let cached = ws.diagnostics("b/RAPID/TASK1/PROGMOD/A.mod");
    let task = ws.task_of("b/RAPID/TASK1/PROGMOD/A.mod");
    let unit = ws.unit("b/RAPID/TASK1/PROGMOD/A.mod").cloned().expect("A");
    assert_eq!(*cached, diagnostics_of(&task, &unit));
    assert_eq!(cached[0].related[0].range, 31..38);
}

/// A `HOME/` module that `SYS.cfg` loads into a task joins it whatever the
/// order the files come in: the task folder may come after the module (a
/// server reads files in any order), one at a time or all at once.
#[test]
fn a_home_module_joins_its_task_whatever_the_order_of_the_files() {
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n  -Name \"T_ROB1\"\n#\nCAB_TASK_MODULES:\n  -File \"HOME:/Tool.sys\" -ModName \"Tool\" -Task \"T_ROB1\"\n";
    let main = "MODULE M\n  PROC main()\n    ToolOn;\n  ENDPROC\nENDMODULE\n";
    let tool = "MODULE Tool(SYSMODULE)\n  PROC ToolOn()\n  ENDPROC\nENDMODULE\n";
    let files = |b: &str| {
        [
            (format!("{b}/HOME/Tool.sys"), tool),
            (format!("{b}/RAPID/TASK1/PROGMOD/M.mod"), main),
        ]
    };
    let unresolved = |ws: &mut Workspace, b: &str| {
        ws.diagnostics(&format!("{b}/RAPID/TASK1/PROGMOD/M.mod"))
            .iter()
            .filter(|d| d.rule.code == "W101")
            .count()
    };
    for one_by_one in [true, false] {
        let mut ws = Workspace::new();
        ws.set_config("b/SYSPAR/SYS.cfg", sys);
        ws.set_config("c/SYSPAR/SYS.cfg", sys);
        let units = files("b")
            .into_iter()
            .chain(files("c"))
            .map(|(p, t)| Unit::new(p, t.to_owned(), None));
        if one_by_one {
            for u in units {
                ws.set_unit(u);
            }
        } else {
            ws.set_units(units);
        }
        assert_eq!(unresolved(&mut ws, "b"), 0, "one by one: {one_by_one}");
        assert_eq!(unresolved(&mut ws, "c"), 0, "one by one: {one_by_one}");
        // The task folder gone, the module is no longer its task's.
        ws.remove_file("c/RAPID/TASK1/PROGMOD/M.mod");
        assert_eq!(ws.task_key("c/HOME/Tool.sys"), "c/HOME");
    }
}

/// Oracle for the adoption's invalidation ([`Workspace::settle`] drops
/// only the tasks of the backups whose adoption changed): a workspace read
/// file by file in any order, with every file's task and diagnostics asked
/// for after each file (as requests do while the server indexes), ends
/// with the tasks and diagnostics of one given every file at once.
#[test]
fn a_workspace_read_between_requests_equals_one_read_at_once() {
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n  -Name \"T_ROB1\"\n#\nCAB_TASK_MODULES:\n  -File \"HOME:/Tool.sys\" -ModName \"Tool\" -Task \"T_ROB1\"\n";
    let main = "MODULE M\n  PROC main()\n    ToolOn;\n    Load \"HOME:/Lib.mod\";\n    %\"LibProc\"%;\n    BProc;\n  ENDPROC\nENDMODULE\n";
    let tool = "MODULE Tool(SYSMODULE)\n  PROC ToolOn()\n    LibProc;\n  ENDPROC\nENDMODULE\n";
    let lib = "MODULE Lib\n  PROC LibProc()\n    ToolOn;\n  ENDPROC\nENDMODULE\n";
    let spare = "MODULE Spare\n  PROC Other()\n    ToolOn;\n    main;\n  ENDPROC\nENDMODULE\n";
    let a = "MODULE A\n  PROC main()\n    BProc;\n    ToolOn;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC BProc()\n  ENDPROC\nENDMODULE\n";
    // (path, text, is a configuration); `b10` is named like a prefix of
    // `b1`, and `b1/HOME/old/b2` is a backup kept inside b1's HOME/.
    let files: Vec<(String, &str, bool)> = [
        ("b1/SYSPAR/SYS.cfg", sys, true),
        ("b1/HOME/Tool.sys", tool, false),
        ("b1/HOME/Lib.mod", lib, false),
        ("b1/HOME/Spare.mod", spare, false),
        ("b1/RAPID/TASK1/PROGMOD/M.mod", main, false),
        ("b1/HOME/old/b2/SYSPAR/SYS.cfg", sys, true),
        ("b1/HOME/old/b2/HOME/Tool.sys", tool, false),
        ("b1/HOME/old/b2/RAPID/TASK1/PROGMOD/M.mod", main, false),
        ("b10/HOME/Tool.sys", tool, false),
        ("b10/RAPID/TASK1/PROGMOD/M.mod", main, false),
        ("plain/A.mod", a, false),
        ("plain/B.mod", b, false),
    ]
    .into_iter()
    .map(|(p, t, c)| (p.to_owned(), t, c))
    .collect();
    let modules: Vec<&str> = files
        .iter()
        .filter(|f| !f.2)
        .map(|f| f.0.as_str())
        .collect();
    let add = |ws: &mut Workspace, (path, text, config): &(String, &str, bool)| {
        if *config {
            ws.set_config(path, text);
        } else {
            ws.set_unit(Unit::new(path.clone(), (*text).to_owned(), None));
        }
    };
    // Per module: its task's key and members, and its diagnostics.
    let seen = |ws: &mut Workspace, path: &str| {
        let task = ws.task_of(path);
        let mut members: Vec<String> = task.units.iter().map(|u| u.path.clone()).collect();
        members.sort();
        let diagnostics: Vec<(&str, std::ops::Range<usize>, String)> = ws
            .diagnostics(path)
            .iter()
            .map(|d| (d.rule.code, d.range.clone(), d.message.clone()))
            .collect();
        (ws.task_key(path), members, diagnostics)
    };
    let mut at_once = Workspace::new();
    for f in files.iter().filter(|f| f.2) {
        add(&mut at_once, f);
    }
    at_once.set_units(
        files
            .iter()
            .filter(|f| !f.2)
            .map(|(p, t, _)| Unit::new(p.clone(), (*t).to_owned(), None)),
    );
    let expected: Vec<_> = modules.iter().map(|p| seen(&mut at_once, p)).collect();
    // The adoption matters here: M.mod of b1 sees Tool.sys and Lib.mod.
    assert!(expected[3].1.contains(&"b1/HOME/Lib.mod".to_owned()));
    let n = files.len();
    let orders: Vec<Vec<usize>> = vec![
        (0..n).collect(),
        (0..n).rev().collect(),
        (0..n).map(|i| (i * 5) % n).collect(),
        (0..n).map(|i| (i * 7 + 3) % n).collect(),
    ];
    for order in orders {
        let mut ws = Workspace::new();
        for (step, &i) in order.iter().enumerate() {
            add(&mut ws, &files[i]);
            for &j in &order[..=step] {
                if !files[j].2 {
                    seen(&mut ws, &files[j].0);
                }
            }
        }
        for (path, want) in modules.iter().zip(&expected) {
            assert_eq!(
                &seen(&mut ws, path),
                want,
                "{path} read in the order {order:?}"
            );
        }
    }
}

#[test]
fn task_folders_are_named_by_each_sys_cfg_else_by_backinfo() {
    let mut ws = Workspace::new();
    ws.set_file(
        "b/RAPID/TASK1/PROGMOD/A.mod",
        "MODULE A\nENDMODULE\n".into(),
    );
    ws.set_file(
        "b/RAPID/TASK2/PROGMOD/B.mod",
        "MODULE B\nENDMODULE\n".into(),
    );
    ws.set_config(
        "b/BACKINFO/backinfo.txt",
        ">>TASK1: (T_LEFT,,)\n>>TASK2: (T_RIGHT,,)\n",
    );
    let names = ws.task_names_of("b");
    assert_eq!(
        names.get("t_left").map(String::as_str),
        Some("b/RAPID/TASK1")
    );
    assert_eq!(
        names.get("t_right").map(String::as_str),
        Some("b/RAPID/TASK2")
    );
    // SYS.cfg wins; each file names TASK1 first.
    let sys = |name: &str| format!("SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n  -Name \"{name}\"\n");
    ws.set_config("b/SYSPAR/SYS.cfg", &sys("T_ROB1"));
    ws.set_config("b/SYSPAR/SYS_old.cfg", &sys("T_OLD"));
    let names = ws.task_names_of("b");
    assert_eq!(
        names.get("t_rob1").map(String::as_str),
        Some("b/RAPID/TASK1")
    );
    assert_eq!(
        names.get("t_old").map(String::as_str),
        Some("b/RAPID/TASK1")
    );
    assert!(!names.contains_key("t_left"));
}
