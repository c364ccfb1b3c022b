//! The same findings whatever folder is checked: a generated tree of
//! controller backups (a repository of dated backups of one dual-arm cell,
//! backups whose names are prefixes of each other, a backup kept inside
//! another's `HOME/`, backups side by side, a backup inside a project
//! folder next to a plain folder of modules) is checked from its root,
//! from each backup, each task folder, each `HOME/` folder and each module
//! alone; every module's findings must be the same each time.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde_json::Value;

mod support;
use support::{rapid, scratch, write};

/// A backup of a dual-arm cell (tasks `T_ROB_L` and `T_ROB_R`), varied by
/// `k`: its RobotWare options, its signals, and a type of a shared
/// persistent.
fn dual_arm_backup(dir: &str, k: usize) -> Vec<(String, String)> {
    let socket = if k % 2 == 1 {
        "\n616-1 PC Interface\n"
    } else {
        "\n"
    };
    let extra_signal = if k.is_multiple_of(3) {
        "\n      -Name \"diExtra\" -SignalType \"DI\" -Device \"d652\"\n"
    } else {
        ""
    };
    let shared = if k % 4 == 1 { "bool" } else { "num" };
    let shared_value = if k % 4 == 1 { "FALSE" } else { "0" };
    let files = [
        (
            "BACKINFO/backinfo.txt",
            format!(">>SYSTEM_ID:\nCell {k}\n\n>>PRODUCTS_ID:\nRobotWare Version: 6.1{}.00.00\n\n>>OPTIONS:{socket}623-1 Multitasking\n", k % 5),
        ),
        (
            "SYSPAR/SYS.cfg",
            "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB_L\" -Type \"NORMAL\" -MotionTask\n\n      -Name \"T_ROB_R\" -Type \"NORMAL\" -MotionTask\n#\nCAB_TASK_MODULES:\n\n      -File \"HOME:/Base.sys\" -ModName \"Base\" -AllTask\n\n      -File \"HOME:/Tools.sys\" -ModName \"Tools\" -Task \"T_ROB_L\"\n".to_owned(),
        ),
        (
            "SYSPAR/EIO.cfg",
            format!("EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"doGrip_L\" -SignalType \"DO\" -Device \"d652\"\n\n      -Name \"doGrip_R\" -SignalType \"DO\" -Device \"d652\"\n{extra_signal}"),
        ),
        (
            "SYSPAR/MOC.cfg",
            "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT:\n\n      -name \"ROB_L\"\n\n      -name \"ROB_R\"\n".to_owned(),
        ),
        (
            "RAPID/T_ROB_L/SYSMOD/user.sys",
            "MODULE user(SYSMODULE)\n  VAR num reg1;\nENDMODULE\n".to_owned(),
        ),
        ("RAPID/T_ROB_L/SYSMOD/Tools.sys", TOOLS.to_owned()),
        (
            "RAPID/T_ROB_L/PROGMOD/Main_L.mod",
            format!(
                "MODULE Main_L\n  CONST string sHand := \"HOME:/Hand_L.sys\";\n  PERS {shared} nShared := {shared_value};\n  PERS num nCount := 0;\n  VAR num nSpare;\n  PROC main()\n    Load \\Dynamic, sHand;\n    %\"HandOpen\"%;\n    nCount := Twice(nCount);\n    CountTool;\n    SetDO doGrip_L, 1;\n    IF diExtra = 1 nCount := 0;\n    MoveJ CRobT(), v1000, fine, tool0;\n  ENDPROC\nENDMODULE\n"
            ),
        ),
        (
            "RAPID/T_ROB_R/PROGMOD/Main_R.mod",
            format!(
                "MODULE Main_R\n  PERS num nShared := 0;\n  PERS num nCount := 0;\n  VAR socketdev sock;\n  PROC main()\n    Load \\Dynamic, \"HOME:/Hand_R.sys\";\n    %\"HandOpen\"%;\n    nCount := Twice(nCount + {k});\n    CountTool;\n    SetDO doGrip_R, 1;\n    SocketCreate sock;\n    extra_r;\n  ENDPROC\nENDMODULE\n"
            ),
        ),
        ("HOME/Hand_L.sys", hand("L")),
        ("HOME/Hand_R.sys", hand("R")),
        (
            "HOME/Base.sys",
            "MODULE Base(SYSMODULE)\n  FUNC num Twice(num x)\n    RETURN 2 * x;\n  ENDFUNC\nENDMODULE\n".to_owned(),
        ),
        ("HOME/Tools.sys", TOOLS.to_owned()),
        (
            "HOME/Spare.mod",
            "MODULE Spare\n  PROC spare()\n    nCount := nCount + 1;\n    Twice 1;\n  ENDPROC\nENDMODULE\n".to_owned(),
        ),
        (
            "HOME/T_ROB_R/Extra.mod",
            "MODULE Extra\n  PROC extra_r()\n    nCount := nCount + 2;\n    SetDO doGrip_R, 0;\n  ENDPROC\nENDMODULE\n".to_owned(),
        ),
        (
            "HOME/Project/Supervisor.mod",
            "MODULE Supervisor\n  PERS string stList{2} := [\"HOME:/Spare.mod\", \"HOME:/Hand_L.sys\"];\nENDMODULE\n".to_owned(),
        ),
    ];
    files
        .into_iter()
        .map(|(p, t)| (format!("{dir}/{p}"), t))
        .collect()
}

const TOOLS: &str = "MODULE Tools(SYSMODULE)\n  PERS num nTools := 0;\n  PROC CountTool()\n    nTools := nTools + 1;\n  ENDPROC\nENDMODULE\n";

/// A hand's driver: both declare the same names, each arm loads its own.
fn hand(side: &str) -> String {
    format!(
        "MODULE Hand_{side}(SYSMODULE)\n  PERS num nHandState := 0;\n  PROC HandOpen()\n    nHandState := 1;\n    SetDO doGrip_{side}, 0;\n    nCount := nCount + 1;\n  ENDPROC\nENDMODULE\n"
    )
}

/// A backup of one task (`RAPID/TASK1`), with its own signals.
fn small_backup(dir: &str, signal: &str) -> Vec<(String, String)> {
    [
        (
            "SYSPAR/EIO.cfg",
            format!("EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"{signal}\" -SignalType \"DO\" -Device \"d652\"\n"),
        ),
        (
            "RAPID/TASK1/PROGMOD/Main_L.mod",
            "MODULE Main_L\n  PERS num nCount := 0;\n  PROC main()\n    SetDO doOld, 1;\n    SetDO doProject, 1;\n    SetDO doGrip_L, 1;\n    nCount := nCount + 1;\n  ENDPROC\nENDMODULE\n".to_owned(),
        ),
        (
            "RAPID/TASK1/SYSMOD/user.sys",
            "MODULE user(SYSMODULE)\n  VAR num reg1;\nENDMODULE\n".to_owned(),
        ),
    ]
    .into_iter()
    .map(|(p, t)| (format!("{dir}/{p}"), t))
    .collect()
}

/// The whole tree, with the folders to check it from besides its root.
fn tree() -> Vec<(String, String)> {
    let mut files = Vec::new();
    // Dated backups of one cell; `_1`, `_10` and `_11` are prefixes of
    // each other.
    for k in [1, 2, 3, 10, 11] {
        files.extend(dual_arm_backup(&format!("cell/Backups/BACKUP_{k}"), k));
    }
    // A backup kept in another's HOME/.
    files.extend(small_backup(
        "cell/Backups/BACKUP_2/HOME/Old/OLD_BACKUP",
        "doOld",
    ));
    // Backups side by side, and a project folder with a loose EIO.cfg (for
    // its plain folder, not its backup), a backup and plain modules.
    files.extend(dual_arm_backup("side/A_BACKUP", 4));
    files.extend(dual_arm_backup("side/A_BACKUP_2", 5));
    files.extend(small_backup("proj/backup", "doBackup"));
    files.push((
        "proj/EIO.cfg".to_owned(),
        "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"doProject\" -SignalType \"DO\" -Device \"d652\"\n".to_owned(),
    ));
    files.push((
        "proj/Main.mod".to_owned(),
        "MODULE Main\n  PROC main()\n    SetDO doProject, 1;\n    SetDO doOld, 1;\n    helper;\n  ENDPROC\nENDMODULE\n".to_owned(),
    ));
    files.push((
        "proj/Helper.mod".to_owned(),
        "MODULE Helper\n  PROC helper()\n    nCount := 1;\n  ENDPROC\nENDMODULE\n".to_owned(),
    ));
    files
}

/// Severity, code, line, column and message of each finding, by file.
type Findings = BTreeMap<PathBuf, Vec<(String, String, u64, u64, String)>>;

fn check(dir: &Path, what: &Path) -> Findings {
    let out = rapid(
        dir,
        &[
            "check",
            "--format",
            "json",
            "--exit-zero",
            &what.to_string_lossy(),
        ],
    );
    let found: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    let mut by_file = Findings::new();
    for d in found.as_array().into_iter().flatten() {
        let s = |k: &str| d[k].as_str().unwrap_or_default().to_owned();
        let file = dir.join(s("file"));
        let file = std::fs::canonicalize(&file).unwrap_or(file);
        by_file.entry(file).or_default().push((
            s("severity"),
            s("code"),
            d["line"].as_u64().unwrap_or(0),
            d["column"].as_u64().unwrap_or(0),
            s("message"),
        ));
    }
    for list in by_file.values_mut() {
        list.sort();
    }
    by_file
}

/// The findings of the files below `folder`.
fn below(all: &Findings, folder: &Path) -> Findings {
    all.iter()
        .filter(|(f, _)| f.starts_with(folder))
        .map(|(f, d)| (f.clone(), d.clone()))
        .collect()
}

#[test]
fn a_tree_of_backups_gives_the_same_findings_from_any_folder() {
    let dir = scratch("backup-tree");
    let files = tree();
    let refs: Vec<(&str, &str)> = files
        .iter()
        .map(|(p, t)| (p.as_str(), t.as_str()))
        .collect();
    write(&dir, &refs);
    // `RAPID_TREE_OUT=DIR` keeps a copy, to measure other builds on it.
    if let Some(out) = std::env::var_os("RAPID_TREE_OUT") {
        write(Path::new(&out), &refs);
    }
    let root = std::fs::canonicalize(&*dir).expect("the scratch folder");
    let all = check(&root, Path::new("."));

    // What the tree is made to show, checked from the root.
    let count = |code: &str| all.values().flatten().filter(|d| d.1 == code).count();
    let total: usize = all.values().map(Vec::len).sum();
    assert!(total > 40, "{total} findings: {all:#?}");
    // Each arm loads its own hand: no ambiguous names; the SYS.cfg
    // original of Tools is the module T_ROB_L holds, not a second one.
    assert_eq!(count("E107"), 0, "{all:#?}");
    assert_eq!(count("W207"), 0, "{all:#?}");
    let of = |file: &str| all.get(&root.join(file)).cloned().unwrap_or_default();
    let has = |file: &str, code: &str, sev: &str, text: &str| {
        of(file)
            .iter()
            .any(|d| d.1 == code && d.0 == sev && d.4.contains(text))
    };
    // T_ROB_R does not load Tools: an error in a complete backup; Base is
    // loaded into every task; the hand of T_ROB_L comes by a constant.
    let main_r = "cell/Backups/BACKUP_1/RAPID/T_ROB_R/PROGMOD/Main_R.mod";
    let main_l = "cell/Backups/BACKUP_1/RAPID/T_ROB_L/PROGMOD/Main_L.mod";
    assert!(
        has(main_r, "W101", "error", "`CountTool`"),
        "{:#?}",
        of(main_r)
    );
    assert!(
        !has(main_r, "W101", "error", "`Twice`"),
        "{:#?}",
        of(main_r)
    );
    assert!(
        !has(main_r, "W101", "error", "`extra_r`"),
        "{:#?}",
        of(main_r)
    );
    assert!(of("cell/Backups/BACKUP_1/HOME/Hand_L.sys").is_empty());
    // Signals and options are each backup's own: diExtra only in
    // BACKUP_3; Socket Messaging (616-1 PC Interface) in the odd ones.
    assert!(
        has(main_l, "W101", "error", "`diExtra`"),
        "{:#?}",
        of(main_l)
    );
    let main_l_3 = "cell/Backups/BACKUP_3/RAPID/T_ROB_L/PROGMOD/Main_L.mod";
    assert!(
        !has(main_l_3, "W101", "error", "`diExtra`"),
        "{:#?}",
        of(main_l_3)
    );
    let main_r_10 = "cell/Backups/BACKUP_10/RAPID/T_ROB_R/PROGMOD/Main_R.mod";
    assert!(
        has(main_r_10, "I102", "info", "`SocketCreate`"),
        "{:#?}",
        of(main_r_10)
    );
    assert!(
        !has(main_r, "I102", "info", "`SocketCreate`"),
        "{:#?}",
        of(main_r)
    );
    // The persistent shared by the arms has two types in BACKUP_1.
    assert!(
        has(main_l, "E108", "error", "nShared")
            || of(main_l).iter().any(|d| d.4.contains("nShared")),
        "{:#?}",
        of(main_l)
    );
    // A module that no task loads is checked alone: a note.
    assert!(has(
        "cell/Backups/BACKUP_1/HOME/Spare.mod",
        "W101",
        "info",
        "`nCount`"
    ));
    // The backup kept in BACKUP_2's HOME/ has its own signals only; the
    // project's loose EIO.cfg is for its plain folder, not its backup.
    let old = "cell/Backups/BACKUP_2/HOME/Old/OLD_BACKUP/RAPID/TASK1/PROGMOD/Main_L.mod";
    assert!(!has(old, "W101", "error", "`doOld`"), "{:#?}", of(old));
    assert!(has(old, "W101", "error", "`doGrip_L`"), "{:#?}", of(old));
    let proj_backup = "proj/backup/RAPID/TASK1/PROGMOD/Main_L.mod";
    assert!(
        has(proj_backup, "W101", "error", "`doProject`"),
        "{:#?}",
        of(proj_backup)
    );
    assert!(
        !of("proj/Main.mod")
            .iter()
            .any(|d| d.4.contains("`doProject`"))
    );

    // Every folder and file checked alone gives its files' findings.
    let mut places: Vec<PathBuf> = Vec::new();
    for (path, _) in &files {
        let p = Path::new(path);
        let lower = path.to_ascii_lowercase();
        if [".mod", ".sys"].iter().any(|e| lower.ends_with(e)) {
            places.push(p.to_owned());
        }
        for dir in p.ancestors().skip(1) {
            if !dir.as_os_str().is_empty() && !places.contains(&dir.to_owned()) {
                places.push(dir.to_owned());
            }
        }
    }
    // Two at a time: each check is a process.
    let next = std::sync::atomic::AtomicUsize::new(0);
    let differences = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| {
                while let Some(place) =
                    places.get(next.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
                {
                    let here = check(&root, place);
                    let want = below(&all, &root.join(place));
                    if here != want {
                        differences.lock().expect("the list").push(format!(
                            "{}:\n  from the root: {want:#?}\n  from here: {here:#?}",
                            place.display()
                        ));
                    }
                }
            });
        }
    });
    let differences = differences.into_inner().expect("the list");
    assert!(places.len() > 100, "{} places", places.len());
    assert!(
        differences.is_empty(),
        "{} of {} places differ:\n{}",
        differences.len(),
        places.len(),
        differences.join("\n")
    );
}
