use super::*;

#[test]
fn tasks_and_their_modules_come_from_sys_cfg() {
    let cfg = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T_ROB1\" -Type \"NORMAL\" \\\n   -MotionTask \n\n  -Name \"T_PLC\" -Type \"SEMISTATIC\" -Entry \"plc\"\n#\nCAB_TASK_MODULES:\n\n  -File \"HOME:/user.sys\" -ModName \"user\" -AllTask\n  -File \"RELEASE:/options/x.sys\" -ModName \"x\" \\\n   -Task \"T_ROB1\" -Hidden\n#\nCAB_EXEC_HOOKS:\n  -Routine \"r\" -Shelf \"POWER_ON\"\n";
    let config = parse_config(cfg);
    assert_eq!(config.tasks, ["T_ROB1", "T_PLC"]);
    let kinds: Vec<(TaskKind, bool)> = config
        .task_settings
        .iter()
        .map(|t| (t.kind, t.motion))
        .collect();
    assert_eq!(
        kinds,
        [(TaskKind::Normal, true), (TaskKind::SemiStatic, false)]
    );
    assert_eq!(
        config.task_modules,
        [
            TaskModule {
                file: "HOME:/user.sys".into(),
                task: None
            },
            TaskModule {
                file: "RELEASE:/options/x.sys".into(),
                task: Some("T_ROB1".into())
            },
        ]
    );
    assert_eq!(config.task_modules[0].home_path(), Some("user.sys"));
    assert_eq!(config.task_modules[1].home_path(), None);
    assert_eq!(config.task_modules[1].file_name(), "x.sys");
    assert_eq!(config.task_settings[1].entry.as_deref(), Some("plc"));
}

#[test]
fn folder_names_in_any_script_are_grouped_without_a_panic() {
    // Folder names whose fourth byte is inside a character.
    for (path, key) in [
        ("/home/josé/robot/Main.mod", "/home/josé/robot"),
        ("/home/josé/RAPID/TASK1/Main.mod", "/home/josé/RAPID/TASK1"),
        (
            "/机器人程序/RAPID/TASK1/PROGMOD/A.mod",
            "/机器人程序/RAPID/TASK1",
        ),
        ("/機械/RAPID/タスク1/A.mod", "/機械/RAPID/タスク1"),
        ("/b/RAPID/TASKé/A.mod", "/b/RAPID/TASKé"),
        ("/b/RAPID/tasK2/A.mod", "/b/RAPID/tasK2"),
    ] {
        assert_eq!(task_key(path), key, "{path}");
    }
    assert_eq!(controller_of("/机器人/RAPID/TASK1"), Some("/机器人/RAPID/"));
    // Any folder under `RAPID/` is a task folder (`T_ROB1`, `TASKé`).
    assert_eq!(controller_of("/b/RAPID/josé"), Some("/b/RAPID/"));
    assert_eq!(controller_of("/b/RAPID/机器人程"), Some("/b/RAPID/"));
    assert_eq!(controller_of("/b/josé"), None);
}

#[test]
fn signals_come_from_the_signal_section() {
    let cfg = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n  -Name \"diA\" -SignalType \"DI\"\\\n  -Device \"d1\"\n  -Name doB -SignalType \"DO\"\n#\nEIO_CROSS:\n  -Name \"notASignal\"\n";
    let signals = parse_eio_signals(cfg);
    assert_eq!(signals.get("dia"), Some(&"signaldi"));
    assert_eq!(signals.get("dob"), Some(&"signaldo"));
    assert!(!signals.contains_key("notasignal"));
}

/// The interface is the hash of what the task's files and controller
/// declare: each of them changes it, the order of a map does not.
#[test]
fn the_interface_covers_each_declared_input() {
    let unit = |text: &str| Arc::new(Unit::new("p/A.mod".into(), text.into(), None));
    let a = unit("MODULE A\n  VAR num n;\nENDMODULE\n");
    let signals = |names: &[&str]| -> Signals {
        names
            .iter()
            .map(|n| ((*n).to_owned(), "signaldo"))
            .collect()
    };
    let base = || {
        Task::new(
            "p".into(),
            vec![a.clone()],
            Some(signals(&["do1", "do2", "do3"])),
        )
    };
    let reference = base().interface;
    // The same inputs, the signals inserted in another order.
    let again = Task::new(
        "p".into(),
        vec![a.clone()],
        Some(signals(&["do3", "do1", "do2"])),
    );
    assert_eq!(again.interface, reference);
    let mut changed = vec![
        Task::new(
            "p".into(),
            vec![unit("MODULE A\n  VAR num m;\nENDMODULE\n")],
            None,
        )
        .interface,
        Task::new("p".into(), vec![a.clone()], None).interface,
        Task::new("p".into(), vec![a.clone()], Some(signals(&["do1", "do2"]))).interface,
    ];
    let mut t = base();
    t.set_controller_names(["rob1".to_owned()].into(), HashSet::new());
    changed.push(t.interface);
    let mut t = base();
    t.set_controller_names(HashSet::new(), ["t_rob1id".to_owned()].into());
    changed.push(t.interface);
    let mut t = base();
    t.set_catalogue(&crate::catalogue::Selection::default());
    changed.push(t.interface);
    let mut t = base();
    t.set_shared(Arc::default(), 1);
    changed.push(t.interface);
    for (i, h) in changed.iter().enumerate() {
        assert_ne!(*h, reference, "change {i}");
        assert!(!changed[..i].contains(h), "change {i}");
    }
}

/// A unit checked with its tree parsed again ([`Task::with_unit`],
/// [`Unit::loaded`]) reports what it reports with the tree kept, and the
/// trees that were released stay released: the other modules whose
/// constants the check evaluates, and those a hover and a reference search
/// read, are parsed for the call only.
#[test]
fn released_trees_stay_released() {
    let data =
        "MODULE Data\n  CONST num n := 3;\n  CONST num k := n * 2;\n  VAR num arr{k};\nENDMODULE\n";
    let main = "MODULE Main\n  PROC main()\n    VAR num x;\n    x := 10 / (k - 6);\n    x := arr{n};\n    Undeclared;\n  ENDPROC\nENDMODULE\n";
    let kept: Vec<Arc<Unit>> = [("t/data.mod", data), ("t/main.mod", main)]
        .into_iter()
        .map(|(p, t)| Arc::new(Unit::new(p.into(), t.into(), None)))
        .collect();
    let released: Vec<Arc<Unit>> = [("t/data.mod", data), ("t/main.mod", main)]
        .into_iter()
        .map(|(p, t)| {
            let mut u = Unit::new(p.into(), t.into(), None);
            u.release_tree();
            Arc::new(u)
        })
        .collect();
    let expected = crate::check::check_unit(&Task::new("t".into(), kept, None), 1);
    assert!(!expected.is_empty());
    let task = Task::new("t".into(), released.clone(), None);
    let none_loaded = || released.iter().all(|u| !u.tree_loaded());
    // main.mod open (its tree in memory), data.mod released
    let open_main = task.with_unit(1, released[1].loaded());
    assert_eq!(crate::check::check_unit(&open_main, 1), expected);
    assert!(none_loaded(), "check");
    let at = main.find("arr").unwrap_or_default();
    assert!(crate::ide::hover(&open_main, 1, at).is_some());
    assert!(none_loaded(), "hover");
    // data.mod open, main.mod released
    let open_data = task.with_unit(0, released[0].loaded());
    let n = data.find("n :=").unwrap_or_default();
    assert_eq!(crate::ide::references(&open_data, 0, n, true, &[]).len(), 3);
    assert!(none_loaded(), "references");
}

/// A task with more modules or signals is the same controller's task: the
/// catalogue view, controller names and grouping stay.
#[test]
fn extra_units_and_signals_keep_the_controller() {
    let unit = |path: &str, text: &str| Arc::new(Unit::new(path.into(), text.into(), None));
    let mut task = Task::new(
        "b/RAPID/TASK1".into(),
        vec![unit(
            "b/RAPID/TASK1/A.mod",
            "MODULE A\n  PROC main()\n  ENDPROC\nENDMODULE\n",
        )],
        None,
    );
    let version = crate::catalogue::Version::parse("5.0").expect("a version");
    task.set_catalogue(&crate::catalogue::Selection::new(Some(version), Vec::new()));
    task.set_controller_names(["rob1".to_owned()].into(), ["t_rob1id".to_owned()].into());
    task.grouping = Grouping::Backup;
    let more = task.with_extra_units([unit(
        "<t>/B.sys",
        "MODULE B\n  PROC helper()\n  ENDPROC\nENDMODULE\n",
    )]);
    assert!(std::ptr::eq(more.catalogue, task.catalogue));
    assert_eq!(more.mecunits, task.mecunits);
    assert_eq!(more.task_ids, task.task_ids);
    assert_eq!(more.grouping, Grouping::Backup);
    assert_eq!(more.units.len(), 2);
    assert!(more.globals.contains_key("helper") && more.globals.contains_key("main"));
    let wired = more.with_signals(&[("di_part".to_owned(), "signaldi")]);
    assert_eq!(
        wired.signals.as_ref().and_then(|s| s.get("di_part")),
        Some(&"signaldi")
    );
    assert!(std::ptr::eq(wired.catalogue, task.catalogue));
    assert_ne!(wired.interface, more.interface);
}
