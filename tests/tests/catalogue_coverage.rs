//! Coverage of the built-in catalogue on real code: every routine called in the corpus
//! that the corpus does not declare itself must be in the catalogue
//! (`catalogue/data/*.toml`, base language or an option package) or a reviewed gap (a
//! module absent from the corpus); and every name the checker cannot resolve (data,
//! routines and types) must be such a gap, never a RobotWare or option name.
//!
//! The corpus is read from `RAPID_CORPUS` or `../shared/corpus` next to the workspace;
//! when neither exists the test prints one line and passes.

#![allow(clippy::print_stdout)]

use std::collections::{BTreeMap, HashSet};
use std::path::{Path, PathBuf};

use rapid_analyzer::catalogue::base;

/// Routines the corpus calls whose declaring module is simply not in the corpus (user or
/// project code, not RobotWare: they are never catalogued), and calls in files that are
/// not programs. Reviewed: (name, reason).
const CORPUS_GAPS: &[(&str, &str)] = &[
    (
        "ACAL_BaseChange",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "ACAL_CalSeq",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "ACAL_CheckSetup",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "ACAL_ComputeBase",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "ACAL_RecordPoint",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "ACAL_Vectorize",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "ACALu_Clear",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "ACALu_Initialize",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "ArcMoveAbsJ",
        "abb-robot-welder: a service module of the welder not in the corpus (possibly Arc torch services; no public signature)",
    ),
    (
        "ASFMu_Clear",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "ASFMu_Initialize",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "AtParkPos",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "AtSafePos",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "AtServPos",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "AtStation",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "CX_GetFile",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "CX_GetOnline",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "CX_GetValue",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "CX_InitComm",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "CX_LoadFile",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "CX_SetOnline",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "CX_SetupCamera",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "CX_ShowErrStatus",
        "DiceRobot: the camera (CX_*) helper module is not in the corpus",
    ),
    (
        "GetAproachTarget",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "GetBaseFramePosZ",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "GetEulerAngleString",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "GetGantryOffsetDirection",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "GetParkPos",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "GetQuadrant",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "GetQuadrantGantryOffset",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "GetSafePos",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "GetServPos",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "HomeJointAdd",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "HomeJointCount",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "HomeJointParkDef",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "HomeJointSafeDef",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "HomeJointServDef",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "Laser_Initialize",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "LASER_ON",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "LoadGantryOffset",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "LogAppend",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "Logging",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "MoveMechCleanJ",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "MoveSprayJ",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "MoveToPark",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "MoveToSafe",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "MoveToServ",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "MoveWireCutJ",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "NextStation",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "OFrameChange",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "OptSearch_1D",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "ppaDropWobj",
        "s25016: a welding project module not in the corpus (possibly Arc torch services; no public signature)",
    ),
    (
        "RefreshDisp",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "ScanSeamByLaser",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "SeamFind",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "SetFileHandlerLogLevel",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "SetTPHandlerLogLevel",
        "zwj12 add-in packages: shared vendor modules (logging, stations, calibration) not in the corpus",
    ),
    (
        "Softwaresync",
        "Kraker1: a sync helper module not in the corpus",
    ),
    (
        "StnIndGetIndex",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "StnIndGetStation",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "TextResGet",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "TextResTabGet",
        "zwj12 ZhongXun: vendor modules (logging, display, laser scan, gantry) not in the corpus",
    ),
    (
        "r_RRC_InitSockets",
        "COMPAS RRC (ETH Zurich): its socket module is not in the corpus",
    ),
    (
        "r_RRC_CheckAndRecFrmClient",
        "COMPAS RRC (ETH Zurich): its socket module is not in the corpus",
    ),
    (
        "r_RRC_PackSendDataToClient",
        "COMPAS RRC (ETH Zurich): its socket module is not in the corpus",
    ),
    (
        "attemptSystemRoutine",
        "panin-anan grinding project: helper module not in the corpus",
    ),
    (
        "attemptNonBlockingSystemRoutine",
        "panin-anan grinding project: helper module not in the corpus",
    ),
    (
        "initializeSystemModule",
        "panin-anan grinding project: helper module not in the corpus",
    ),
    (
        "state_server_main",
        "ROS-Industrial abb_driver: ROS_stateServer.mod not in the corpus",
    ),
    (
        "joint_trajectory_server_main",
        "ROS-Industrial abb_driver: ROS_motionServer.mod not in the corpus",
    ),
    (
        "FitSphere",
        "FLo-ABB ToolCenterCalculations: math helper module not in the corpus",
    ),
    (
        "Rand",
        "FLo-ABB CycleTime: random-number helper not in the corpus (not a RobotWare function)",
    ),
    (
        "condition",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "something",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "getValue",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "doSomething",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "doDefault",
        "intellij-rapid code-style preview text, not a program",
    ),
    (
        "Routine",
        "intellij-rapid code-style preview text (its declaration does not parse: known broken)",
    ),
];

/// Routine names declared in a tree, and (name, is_function) of every call by name.
fn walk(
    tree: &tree_sitter::Tree,
    text: &str,
    declared: &mut HashSet<String>,
    calls: &mut Vec<(String, bool)>,
) {
    let mut cursor = tree.walk();
    loop {
        let node = cursor.node();
        let kind = node.kind();
        let name = node
            .child_by_field_name("name")
            .filter(|n| n.kind() == "identifier")
            .and_then(|n| n.utf8_text(text.as_bytes()).ok());
        match (kind, name) {
            ("procedure_declaration" | "function_declaration" | "trap_declaration", Some(n)) => {
                declared.insert(n.to_lowercase());
            }
            ("procedure_call", Some(n)) => calls.push((n.to_owned(), false)),
            ("function_call", Some(n)) => calls.push((n.to_owned(), true)),
            _ => {}
        }
        if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return;
            }
        }
    }
}

#[derive(Default)]
struct Count {
    calls: usize,
    files: HashSet<PathBuf>,
    spelling: String,
}

#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn every_called_builtin_is_catalogued_or_a_reviewed_option_routine() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        println!("catalogue_coverage: no corpus (set RAPID_CORPUS); skipped");
        return;
    };
    let cat = base();

    let mut parser = tree_sitter::Parser::new();
    parser
        .set_language(&tree_sitter_rapid::LANGUAGE.into())
        .expect("the RAPID grammar loads");

    let mut declared = HashSet::new();
    let mut called: BTreeMap<String, Count> = BTreeMap::new();
    let mut files = 0usize;
    for path in rapid_tests::rapid_paths(&dir, true) {
        let text = rapid_tests::decode_text(&std::fs::read(&path).expect("readable corpus file"));
        if text
            .trim_start_matches(['\u{feff}', ' ', '\t', '\r', '\n'])
            .starts_with('<')
        {
            continue; // an XML program descriptor
        }
        files += 1;
        let tree = parser.parse(&text, None).expect("a tree");
        let mut calls = Vec::new();
        walk(&tree, &text, &mut declared, &mut calls);
        for (name, _) in calls {
            let entry = called.entry(name.to_lowercase()).or_default();
            entry.calls += 1;
            entry.files.insert(path.clone());
            if entry.spelling.is_empty() {
                entry.spelling = name;
            }
        }
    }

    let gaps: HashSet<String> = CORPUS_GAPS.iter().map(|(n, _)| n.to_lowercase()).collect();
    let (mut builtin, mut option, mut own, mut gap) = ((0, 0), (0, 0), (0, 0), (0, 0));
    let mut unknown = Vec::new();
    for (lower, count) in &called {
        if declared.contains(lower) {
            own = (own.0 + 1, own.1 + count.calls);
        } else if let Some(r) = cat.routine(lower) {
            if r.origin.package.is_some() {
                option = (option.0 + 1, option.1 + count.calls);
            } else {
                builtin = (builtin.0 + 1, builtin.1 + count.calls);
            }
        } else if gaps.contains(lower) {
            gap = (gap.0 + 1, gap.1 + count.calls);
        } else {
            unknown.push(format!(
                "{} ({} calls in {} files)",
                count.spelling,
                count.calls,
                count.files.len()
            ));
        }
    }
    println!(
        "catalogue_coverage: {files} files; {} distinct routine names called ({} calls): \
         {} declared in the corpus ({} calls), {} built-in ({} calls), \
         {} option/vendor ({} calls), {} missing from the corpus ({} calls), {} unknown",
        called.len(),
        called.values().map(|c| c.calls).sum::<usize>(),
        own.0,
        own.1,
        builtin.0,
        builtin.1,
        option.0,
        option.1,
        gap.0,
        gap.1,
        unknown.len()
    );
    assert!(files > 0, "no RAPID files under {}", dir.display());
    // A gap entry that no longer matches anything must leave the list.
    let stale: Vec<&str> = CORPUS_GAPS
        .iter()
        .filter(|(n, _)| {
            !called.contains_key(&n.to_lowercase()) || declared.contains(&n.to_lowercase())
        })
        .map(|(n, _)| *n)
        .collect();
    assert!(stale.is_empty(), "stale CORPUS_GAPS entries: {stale:?}");
    assert!(
        unknown.is_empty(),
        "called but neither declared, catalogued nor a reviewed gap:\n{}",
        unknown.join("\n")
    );
}

/// Every argument passed by name (`\Name` or `Name :=`) to a catalogued routine names one
/// of its parameters.
#[test]
#[cfg_attr(no_corpus, ignore = "no corpus: set RAPID_CORPUS (see the README)")]
fn named_arguments_of_builtins_are_parameters() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        println!("catalogue_coverage: no corpus (set RAPID_CORPUS); skipped");
        return;
    };
    let cat = base();
    let mut parser = tree_sitter::Parser::new();
    parser
        .set_language(&tree_sitter_rapid::LANGUAGE.into())
        .expect("the RAPID grammar loads");
    let mut declared = HashSet::new();
    let mut uses: Vec<(String, String, PathBuf)> = Vec::new();
    for path in rapid_tests::rapid_paths(&dir, true) {
        let text = rapid_tests::decode_text(&std::fs::read(&path).expect("readable corpus file"));
        if text
            .trim_start_matches(['\u{feff}', ' ', '\t', '\r', '\n'])
            .starts_with('<')
        {
            continue;
        }
        let tree = parser.parse(&text, None).expect("a tree");
        let mut calls = Vec::new();
        walk(&tree, &text, &mut declared, &mut calls);
        named_arguments(&tree, &text, &mut uses, &path);
    }
    let mut bad: BTreeMap<String, usize> = BTreeMap::new();
    let mut checked = 0usize;
    for (routine, arg, _) in &uses {
        if declared.contains(&routine.to_lowercase()) {
            continue;
        }
        let Some(r) = cat.routine(routine).filter(|r| r.signature_known) else {
            continue;
        };
        checked += 1;
        if !r.params.iter().any(|p| p.name.eq_ignore_ascii_case(arg)) {
            *bad.entry(format!("{}\\{}", r.name, arg)).or_default() += 1;
        }
    }
    println!(
        "catalogue_coverage: {checked} named arguments of built-in routines, {} unknown names",
        bad.len()
    );
    let list: Vec<String> = bad.iter().map(|(k, n)| format!("{k} ({n})")).collect();
    assert!(
        list.is_empty(),
        "named arguments that are not parameters:\n{}",
        list.join("\n")
    );
}

fn named_arguments(
    tree: &tree_sitter::Tree,
    text: &str,
    out: &mut Vec<(String, String, PathBuf)>,
    path: &Path,
) {
    let mut cursor = tree.walk();
    loop {
        let node = cursor.node();
        if matches!(node.kind(), "procedure_call" | "function_call")
            && let Some(name) = node
                .child_by_field_name("name")
                .filter(|n| n.kind() == "identifier")
                .and_then(|n| n.utf8_text(text.as_bytes()).ok())
            && let Some(args) = node.child_by_field_name("arguments")
        {
            let mut c = args.walk();
            for arg in args.children_by_field_name("argument", &mut c) {
                if let Some(a) = arg
                    .child_by_field_name("name")
                    .and_then(|n| n.utf8_text(text.as_bytes()).ok())
                {
                    out.push((name.to_owned(), a.to_owned(), path.to_path_buf()));
                }
            }
        }
        if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return;
            }
        }
    }
}

/// Repositories whose unresolved routine names (calls the checker finds nowhere) all come
/// from modules absent from the corpus: project code, never catalogued. Every called name
/// is also accounted for one by one by the first test; data and type names are reviewed
/// one by one in `catalogue_coverage/reviewed.rs`. Reviewed: (corpus folder, what is
/// missing).
const UNRESOLVED_GAPS: &[(&str, &str)] = &[
    (
        "Alienspartner__ABB-and-Keyence",
        "the Keyence communication module is not in the repository",
    ),
    (
        "BossyMr__intellij-rapid",
        "code-style preview text of an editor plugin, not a program",
    ),
    (
        "FLo-ABB__RAPID-Scripts-and-Demos",
        "math helper modules (FitSphere, Rand) not in the repository",
    ),
    (
        "Fabio-Coder__Robo_ABB_Injetora-Rotinas_de_ajuste",
        "the cell's user and system modules (usr_*, s_*) are not in the repository",
    ),
    (
        "GIS-EPFL__Robots",
        "COMPAS RRC channel and buffer modules not in the repository",
    ),
    (
        "OrebroUniversity__yumi",
        "the ROS socket helper module is not in the repository",
    ),
    ("SDEBEUL__Kraker1", "a sync helper, not in the repository"),
    (
        "ebruun__ECL_robotic_cell",
        "COMPAS RRC channel and buffer modules not in the repository",
    ),
    (
        "evenator__masters",
        "the ROS driver's server modules and the Linked motor service module",
    ),
    (
        "kangoananya__gkr_timber",
        "COMPAS RRC modules and project routines declared in modules not in the repository",
    ),
    (
        "liamjosephnolan__DiceRobot",
        "the camera (CX_*) helper module is not in the repository",
    ),
    (
        "panin-anan__abb_SAMXL_Grinding_RAPID",
        "the grinding project's helper module is not in the repository",
    ),
    (
        "ravenorb__abb-robot-welder",
        "the welder's service module is not in the repository",
    ),
    (
        "rparak__ABB-RobotStudio-YUMI-Tower-of_Hanoi",
        "the solver module is in a station file, not in the repository",
    ),
    (
        "taeyangshim-stack__s25016",
        "welding project modules (weld modes, wire cut, PickMaster hooks) not in the repository",
    ),
    (
        "zwj12__AddInPackages",
        "add-in packages whose shared modules (Logging, process data, task lists) are not in the repository",
    ),
    (
        "zwj12__ZhongXunRapid",
        "the vendor's text resource, display and laser scan modules are not in the repository",
    ),
];

#[path = "catalogue_coverage/reviewed.rs"]
mod reviewed;

use reviewed::{REVIEWED, Why};

/// The namespace a W101 finding asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Space {
    Data,
    Type,
    Routine,
}

/// A reviewed name: (repository, namespace, lower-case name).
type Key = (String, Space, String);

/// The reviewed data and type names: key -> group;
/// and the list's defects (a name listed twice, a group without a note or names).
fn reviewed_index() -> (BTreeMap<Key, usize>, Vec<String>) {
    let mut index = BTreeMap::new();
    let mut twice = Vec::new();
    for (i, group) in REVIEWED.iter().enumerate() {
        if group.note.is_empty() || (group.data.is_empty() && group.types.is_empty()) {
            twice.push(format!("a group of {} without a note or names", group.repo));
        }
        let names = group
            .data
            .iter()
            .map(|n| (Space::Data, n))
            .chain(group.types.iter().map(|n| (Space::Type, n)));
        for (space, name) in names {
            let key = (group.repo.to_owned(), space, name.to_lowercase());
            if index.insert(key, i).is_some() {
                twice.push(format!("{name} ({space:?}) in {}", group.repo));
            }
        }
    }
    (index, twice)
}

/// Every name the checker cannot resolve on the corpus is accounted for, and none is a
/// RobotWare built-in or option name: a routine comes from a module the corpus lacks (a
/// reviewed repository), a data or type name is listed one by one in
/// `catalogue_coverage/reviewed.rs` with why it is not a built-in. A listed name that is no
/// longer reported must leave the list.
#[test]
fn unresolved_names_are_reviewed_gaps_never_builtins() {
    let Some(dir) = rapid_tests::corpus_dir() else {
        println!("catalogue_coverage: no corpus (set RAPID_CORPUS); skipped");
        return;
    };
    let cat = base();
    let loaded = rapid_tests::workspace_inputs(&dir);
    let mut ws = loaded.workspace();
    let (index, twice) = reviewed_index();
    assert!(twice.is_empty(), "malformed reviewed list: {twice:?}");

    let mut total = 0usize;
    let mut builtin = BTreeMap::new();
    let mut unaccounted: BTreeMap<String, usize> = BTreeMap::new();
    let mut matched: BTreeMap<Key, usize> = BTreeMap::new();
    let mut routine_repos: BTreeMap<&str, usize> = BTreeMap::new();
    for (path, _) in &loaded.modules {
        let repo = path.split('/').next().unwrap_or_default();
        for d in ws.diagnostics(path).iter() {
            if d.rule.code != "W101" {
                continue;
            }
            let Some(name) = d.message.split('`').nth(1) else {
                continue;
            };
            total += 1;
            let space = if d.message.starts_with("no data named") {
                Space::Data
            } else if d.message.starts_with("no data type named") {
                Space::Type
            } else {
                Space::Routine
            };
            // A built-in of the namespace the use asks for (a routine name
            // used as data is rightly unresolved).
            let known = match space {
                Space::Data => cat.datum(name).is_some(),
                Space::Type => cat.datatype(name).is_some(),
                Space::Routine => cat.routine(name).is_some(),
            };
            if known {
                *builtin.entry(name.to_owned()).or_insert(0usize) += 1;
            }
            if space == Space::Routine {
                if let Some((gap, _)) = UNRESOLVED_GAPS.iter().find(|(r, _)| *r == repo) {
                    *routine_repos.entry(gap).or_default() += 1;
                } else {
                    *unaccounted
                        .entry(format!("routine `{name}` in {path}"))
                        .or_default() += 1;
                }
                continue;
            }
            let key = (repo.to_owned(), space, name.to_lowercase());
            if index.contains_key(&key) {
                *matched.entry(key).or_default() += 1;
            } else {
                let what = if space == Space::Data { "data" } else { "type" };
                *unaccounted
                    .entry(format!("{what} `{name}` in {path}"))
                    .or_default() += 1;
            }
        }
    }

    // Figures by reason: distinct names and findings.
    let mut by_why: BTreeMap<Why, (usize, usize)> = BTreeMap::new();
    for (key, group) in &index {
        let entry = by_why.entry(REVIEWED[*group].why).or_default();
        entry.0 += 1;
        entry.1 += matched.get(key).copied().unwrap_or(0);
    }
    let figures: Vec<String> = Why::ALL
        .iter()
        .map(|why| {
            let (names, findings) = by_why.get(why).copied().unwrap_or_default();
            format!("{}: {names} names ({findings} findings)", why.label())
        })
        .collect();
    println!(
        "catalogue_coverage: {total} unresolved-name findings; {} routine findings in {} reviewed repositories; \
         data and type names reviewed: {}",
        routine_repos.values().sum::<usize>(),
        routine_repos.len(),
        figures.join("; ")
    );

    assert!(
        builtin.is_empty(),
        "unresolved names that the catalogue knows: {builtin:?}"
    );
    let listed: Vec<&String> = unaccounted.keys().take(60).collect();
    assert!(
        unaccounted.is_empty(),
        "{} unresolved names neither catalogued nor reviewed (add them to the catalogue with \
         a source, or to catalogue_coverage/reviewed.rs with the reason):\n{listed:#?}",
        unaccounted.len()
    );
    let stale: Vec<String> = index
        .keys()
        .filter(|key| !matched.contains_key(*key))
        .map(|(repo, space, name)| format!("{name} ({space:?}) in {repo}"))
        .collect();
    assert!(
        stale.is_empty(),
        "reviewed names no longer reported (remove them from catalogue_coverage/reviewed.rs): {stale:?}"
    );
    let stale_repos: Vec<&str> = UNRESOLVED_GAPS
        .iter()
        .map(|(repo, _)| *repo)
        .filter(|repo| !routine_repos.contains_key(repo))
        .collect();
    assert!(
        stale_repos.is_empty(),
        "UNRESOLVED_GAPS repositories without an unresolved routine: {stale_repos:?}"
    );
}
