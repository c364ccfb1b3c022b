//! The comparison on small programs written for each kind of change.

use super::*;
use crate::workspace::Workspace;

/// A side made of module files (path, text), one task per folder.
fn side(files: &[(&str, &str)]) -> Snapshot {
    let mut ws = Workspace::new();
    for (path, text) in files {
        ws.set_file(path, (*text).to_owned());
    }
    Snapshot {
        tasks: snapshot::tasks_of(&mut ws, &|k| k.to_owned(), &|p| p.to_owned()),
        ..Snapshot::default()
    }
}

fn module(body: &str) -> String {
    format!("MODULE Main\n{body}ENDMODULE\n")
}

fn diff(old: &str, new: &str) -> Report {
    let (o, n) = (module(old), module(new));
    compare(
        &side(&[("a/Main.mod", &o)]),
        &side(&[("b/Main.mod", &n)]),
        &Options::default(),
    )
}

fn data_of(r: &Report) -> Vec<&DataDiff> {
    r.tasks
        .iter()
        .flat_map(|t| &t.modules)
        .flat_map(|m| &m.data)
        .collect()
}

const PROGRAM: &str =
    "  CONST robtarget pA := [[100,0,50],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS num nCount := 3;
  VAR speeddata vSlow := [100, 50, 5000, 1000];
  PROC main()
    VAR num i;
    VAR num k := 2;
    IF nCount > 2 THEN
      MoveL pA, vSlow, fine, tool0;
    ELSE
      nCount := nCount + 1;
    ENDIF
  ENDPROC
";

#[test]
fn layout_keyword_case_line_endings_and_data_order_change_nothing() {
    let reformatted = "  pers NUM nCount:=3;\r\n  var speeddata vSlow:=[100,50,5000.0,1000];\r\n\tCONST robtarget pA := [[100, 0, 50.0], [1, 0, 0, 0],\r\n    [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\r\nproc MAIN()\r\n  var num k:=2;\r\n  var num I;\r\n if NCOUNT>2 then MoveL pA,vSlow,\r\n   fine,tool0;\r\n else\r\n nCount:=nCount+1;\r\n endif\r\nendproc\r\n";
    let r = diff(PROGRAM, reformatted);
    assert!(r.is_empty(), "{r:#?}");
}

#[test]
fn a_moved_target_says_how_far_it_moved_and_turned() {
    let moved = PROGRAM.replace(
        "[[100,0,50],[1,0,0,0],[0,0,0,0]",
        "[[103,4,50],[0.707107,0,0,0.707107],[0,-1,0,0]",
    );
    let r = diff(PROGRAM, &moved);
    let d = data_of(&r);
    assert_eq!(d.len(), 1, "{d:#?}");
    assert_eq!(d[0].name, "pA");
    assert_eq!(d[0].changed, ["value"]);
    let m = d[0].motion.as_ref().expect("a motion");
    assert!((m.translation_mm.unwrap_or(0.0) - 5.0).abs() < 1e-6);
    assert!((m.rotation_deg.unwrap_or(0.0) - 90.0).abs() < 1e-3);
    assert_eq!(m.conf, Some(("[0,0,0,0]".into(), "[0,-1,0,0]".into())));
    assert!(m.external_axes.is_empty() && d[0].fields.is_empty());
}

#[test]
fn moves_are_sorted_by_size_and_small_ones_left_out_on_request() {
    let old = "  PERS robtarget p1 := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget p2 := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget p3 := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS num n := 1;
";
    let new = "  PERS robtarget p1 := [[0,0,0.05],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget p2 := [[0,20,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget p3 := [[3,0,0],[1,0,0,0],[0,0,0,0],[100,9E9,9E9,9E9,9E9,9E9]];
  PERS num n := 2;
";
    let r = diff(old, new);
    let names: Vec<&str> = data_of(&r).iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["p2", "p3", "p1", "n"]);
    let p3 = data_of(&r)[1].motion.clone().expect("p3 moved");
    assert_eq!(p3.external_axes.len(), 1);
    assert_eq!(p3.external_axes[0].path, "extax.eax_a");
    let options = Options {
        moves_below_mm: 0.1,
        rotations_below_deg: 0.0,
    };
    let r = compare(
        &side(&[("a/Main.mod", &module(old))]),
        &side(&[("b/Main.mod", &module(new))]),
        &options,
    );
    let names: Vec<&str> = data_of(&r).iter().map(|d| d.name.as_str()).collect();
    // p3's external axis is always reported; p1's 0.05 mm is not.
    assert_eq!(names, ["p2", "p3", "n"]);
    assert_eq!(r.ignored_moves, 1);
    assert_eq!(r.summary().moves, 2);
    assert_eq!(r.summary().data, 1);
}

#[test]
fn a_changed_statement_is_a_hunk_with_its_context() {
    let new = PROGRAM.replace("MoveL pA, vSlow, fine", "MoveJ pA, vSlow, z10");
    let r = diff(PROGRAM, &new);
    let m = &r.tasks[0].modules[0];
    assert!(m.data.is_empty());
    assert_eq!(m.routines.len(), 1);
    let h = &m.routines[0].hunks;
    assert_eq!(h.len(), 1);
    let lines: Vec<(Tag, u16, &str)> = h[0]
        .lines
        .iter()
        .map(|l| (l.tag, l.depth, l.text.as_str()))
        .collect();
    assert_eq!(
        lines,
        [
            (Tag::Context, 1, "VAR num k := 2;"),
            (Tag::Context, 1, "IF nCount > 2 THEN"),
            (Tag::Removed, 2, "MoveL pA, vSlow, fine, tool0;"),
            (Tag::Added, 2, "MoveJ pA, vSlow, z10, tool0;"),
            (Tag::Context, 1, "ELSE"),
            (Tag::Context, 2, "nCount := nCount + 1;"),
        ]
    );
    assert_eq!(h[0].lines[2].old_line, Some(9));
}

#[test]
fn declarations_change_in_storage_type_and_value_and_come_and_go() {
    let old = "  PERS num a := 1;\n  VAR num b := 1;\n  CONST num c := 1;\n  LOCAL VAR num gone;\n  PROC p()\n  ENDPROC\n";
    let new = "  VAR num a := 1;\n  VAR dnum b := 1;\n  CONST num c := 2;\n  VAR num come;\n  PROC q()\n  ENDPROC\n";
    let r = diff(old, new);
    let d = data_of(&r);
    let got: Vec<(&str, Status, Vec<&str>)> = d
        .iter()
        .map(|d| (d.name.as_str(), d.status, d.changed.clone()))
        .collect();
    assert_eq!(
        got,
        [
            ("a", Status::Changed, vec!["storage"]),
            ("b", Status::Changed, vec!["type"]),
            ("c", Status::Changed, vec!["value"]),
            ("come", Status::Added, vec![]),
            ("gone", Status::Removed, vec![]),
        ]
    );
    assert_eq!(
        d[4].old.as_ref().map(|s| s.declaration.as_str()),
        Some("LOCAL VAR num gone")
    );
    assert_eq!(
        d[2].fields,
        [FieldChange {
            path: String::new(),
            old: "1".into(),
            new: "2".into()
        }]
    );
    let routines: Vec<(&str, Status)> = r.tasks[0].modules[0]
        .routines
        .iter()
        .map(|x| (x.name.as_str(), x.status))
        .collect();
    assert_eq!(routines, [("p", Status::Removed), ("q", Status::Added)]);
    // An empty routine is its two lines.
    let q: Vec<&str> = r.tasks[0].modules[0].routines[1].hunks[0]
        .lines
        .iter()
        .map(|l| l.text.as_str())
        .collect();
    assert_eq!(q, ["PROC q()", "ENDPROC"]);
}

#[test]
fn records_are_compared_by_field_and_arrays_by_element() {
    let old = "  VAR speeddata v := [100, 50, 5000, 1000];\n  PERS num reg{3} := [1, 2, 3];\n  PERS pos grid{2,2} := [[[0,0,0],[0,0,0]],[[0,0,0],[0,0,0]]];\n";
    let new = "  VAR speeddata v := [150, 50, 5000, 1000];\n  PERS num reg{3} := [1, 5, 3];\n  PERS pos grid{2,2} := [[[0,0,0],[0,0,0]],[[0,0,0],[0,0,7]]];\n";
    let r = diff(old, new);
    let d = data_of(&r);
    let names: Vec<&str> = d.iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["grid{2,2}", "reg{2}", "v"]);
    assert_eq!(
        d[0].motion.as_ref().and_then(|m| m.translation_mm),
        Some(7.0)
    );
    assert_eq!(
        d[2].fields,
        [FieldChange {
            path: "v_tcp".into(),
            old: "100".into(),
            new: "150".into()
        }]
    );
    assert_eq!(
        d[1].new.as_ref().map(|s| s.declaration.as_str()),
        Some("PERS num reg{3}{2}")
    );
}

#[test]
fn data_of_a_type_known_by_name_only_are_one_value_and_arrays_stop_at_their_dimensions() {
    // `welddata` (an option's type whose components no source documents)
    // evaluates as an aggregate; it is one data object, not an array, and
    // an array of it goes only as deep as its declared dimension.
    let old = "  PERS welddata w := [10, 0, [1, 0, 25, 275]];\n  PERS welddata ws{2} := [[10, 0], [12, 0]];\n";
    let new = "  PERS welddata w := [12, 0, [1, 0, 25, 275]];\n  PERS welddata ws{2} := [[10, 0], [14, 0]];\n";
    let r = diff(old, new);
    let names: Vec<&str> = data_of(&r).iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["w", "ws{2}"]);
}

#[test]
fn a_target_computed_from_a_moved_one_moved_too() {
    let old = "  CONST robtarget p0 := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  CONST robtarget p1 := Offs(p0, 0, 0, 100);\n";
    let new = old.replacen("[[0,0,0]", "[[10,0,0]", 1);
    let r = diff(old, &new);
    let d = data_of(&r);
    assert_eq!(d.len(), 2);
    assert!(
        d.iter()
            .all(|d| d.motion.as_ref().and_then(|m| m.translation_mm) == Some(10.0))
    );
    let derived: Vec<(&str, bool)> = d.iter().map(|d| (d.name.as_str(), d.derived)).collect();
    assert_eq!(derived, [("p0", false), ("p1", true)]);
}

#[test]
fn tools_work_objects_and_joints_are_measured() {
    let old = "  PERS tooldata t := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata w := [FALSE,TRUE,\"\",[[100,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS jointtarget j := [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
";
    let new = "  PERS tooldata t := [TRUE,[[0,0,110],[1,0,0,0]],[1.5,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata w := [FALSE,TRUE,\"\",[[100,0,0],[0.707107,0,0,0.707107]],[[10,0,0],[1,0,0,0]]];
  PERS jointtarget j := [[0,0,0,0,32.5,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
";
    let r = diff(old, new);
    let d = data_of(&r);
    let by = |n: &str| d.iter().find(|x| x.name == n).expect("there");
    let t = by("t");
    let tm = t.motion.as_ref().expect("moved");
    assert_eq!(tm.translation_mm, Some(10.0));
    assert_eq!(tm.frames[0].path, "tframe");
    assert_eq!(
        t.fields,
        [FieldChange {
            path: "tload.mass".into(),
            old: "1".into(),
            new: "1.5".into()
        }]
    );
    // The object frame moved 10 mm along the user frame's turned x axis.
    let w = by("w").motion.as_ref().expect("moved");
    assert!((w.translation_mm.unwrap_or(0.0) - 10.0).abs() < 1e-3);
    assert!((w.rotation_deg.unwrap_or(0.0) - 90.0).abs() < 1e-3);
    let frames: Vec<&str> = w.frames.iter().map(|f| f.path.as_str()).collect();
    assert_eq!(frames, ["uframe", "oframe"]);
    let j = by("j").motion.as_ref().expect("moved");
    assert_eq!(j.joints_deg, Some(2.5));
    assert_eq!(j.joints[0].path, "robax.rax_5");
}

#[test]
fn tasks_and_modules_match_by_name_whatever_their_files() {
    let main = module("  PROC main()\n  ENDPROC\n");
    let old = side(&[
        ("x/RAPID/TASK1/PROGMOD/Main.mod", &main),
        (
            "x/RAPID/TASK2/PROGMOD/Other.mod",
            "MODULE Other\nENDMODULE\n",
        ),
    ]);
    let new = side(&[
        ("y/RAPID/TASK1/PROGMOD/renamed.mod", &main),
        (
            "y/RAPID/TASK3/PROGMOD/Other.mod",
            "MODULE Other\nENDMODULE\n",
        ),
    ]);
    // Named by their folder below the side's root, as `rapid diff` does.
    let rename = |s: Snapshot| Snapshot {
        tasks: s
            .tasks
            .into_iter()
            .map(|mut t| {
                t.name = t.name[2..].to_owned();
                t
            })
            .collect(),
        ..s
    };
    let r = compare(&rename(old), &rename(new), &Options::default());
    let tasks: Vec<(&str, Status)> = r
        .tasks
        .iter()
        .map(|t| (t.name.as_str(), t.status))
        .collect();
    assert_eq!(
        tasks,
        [
            ("RAPID/TASK2", Status::Removed),
            ("RAPID/TASK3", Status::Added)
        ]
    );
}

#[test]
fn configuration_is_compared_by_instance_and_attribute() {
    let old = crate::cfg::parse(
        "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n  -Name \"diA\" -SignalType \"DI\" -Device \"d1\" -DeviceMap \"0\"\n  -Name \"doGone\" -SignalType \"DO\"\n#\nARM:\n  -name \"rob1_1\" -upper_joint_bound 2.96706 -lower_joint_bound -2.96706\n",
    );
    let new = crate::cfg::parse(
        "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n  -Name \"doNew\" -SignalType \"DO\" -Device \"d1\" -DeviceMap \"4\"\n\n  -Name \"diA\" -SignalType \"DI\" -Device \"d1\" \\\n  -DeviceMap \"1\"\n#\nARM:\n  -name \"rob1_1\" -upper_joint_bound 2.96706000 -lower_joint_bound -2.8\n",
    );
    let r = config::compare_configs(&[("EIO.cfg".into(), old)], &[("eio.CFG".into(), new)]);
    assert_eq!(r.len(), 1);
    let got: Vec<(&str, Status, Option<&str>, Vec<&str>)> = r[0]
        .instances
        .iter()
        .map(|i| {
            (
                i.instance.as_str(),
                i.status,
                i.label,
                i.attributes.iter().map(|a| a.name.as_str()).collect(),
            )
        })
        .collect();
    assert_eq!(
        got,
        [
            (
                "doNew",
                Status::Added,
                None,
                vec!["Name", "SignalType", "Device", "DeviceMap"]
            ),
            ("diA", Status::Changed, Some("remapped"), vec!["DeviceMap"]),
            (
                "rob1_1",
                Status::Changed,
                Some("joint limit"),
                vec!["lower_joint_bound"]
            ),
            ("doGone", Status::Removed, None, vec!["Name", "SignalType"]),
        ]
    );
}

#[test]
fn built_ins_whose_signature_changed_between_versions() {
    let text = module("  PROC p()\n    EGMSetupUC ROB_1, egmId, \"c\", \"d\" \\Pose;\n  ENDPROC\n");
    let mut old = side(&[("a/Main.mod", &text)]);
    let mut new = side(&[("b/Main.mod", &text)]);
    old.robotware = Some(Version::new(6, 0));
    new.robotware = Some(Version::new(6, 10));
    let r = compare(&old, &new, &Options::default());
    assert!(r.tasks.is_empty());
    let b = r.builtins.expect("two versions");
    assert_eq!(
        (b.old_robotware.as_str(), b.new_robotware.as_str()),
        ("6.00", "6.10")
    );
    let names: Vec<&str> = b.changed.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["EGMSetupUC"]);
    assert!(b.changed[0].new.contains("APTR") && !b.changed[0].old.contains("APTR"));
}

#[test]
fn a_file_the_same_on_both_sides_is_compared_by_its_values_only() {
    let a = "MODULE A\n  CONST robtarget pTool := Offs(pBase, 0, 0, 10);\n  PROC p()\n    MoveL pTool, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let b_old = "MODULE B\n  CONST robtarget pBase := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\nENDMODULE\n";
    let b_new = b_old.replace("[[0,0,0]", "[[0,0,4]");
    // Reduced as `rapid diff` does: A.mod's text is the same on both sides.
    let reduce = |b: &str| {
        let mut ws = Workspace::new();
        ws.set_file("t/A.mod", a.to_owned());
        ws.set_file("t/B.mod", b.to_owned());
        let per_file = ws
            .checks()
            .iter()
            .map(|(task, unit)| {
                let depth = if unit.path.ends_with("A.mod") {
                    snapshot::Depth::SameText
                } else {
                    snapshot::Depth::Full
                };
                (
                    "t".to_owned(),
                    snapshot::unit_modules(task, unit, &unit.path, depth),
                )
            })
            .collect();
        Snapshot {
            tasks: snapshot::group(per_file),
            ..Snapshot::default()
        }
    };
    let fast = compare(&reduce(b_old), &reduce(&b_new), &Options::default());
    let full = compare(
        &side(&[("t/A.mod", a), ("t/B.mod", b_old)]),
        &side(&[("t/A.mod", a), ("t/B.mod", &b_new)]),
        &Options::default(),
    );
    let names = |r: &Report| -> Vec<(String, bool)> {
        data_of(r)
            .iter()
            .map(|d| (d.name.clone(), d.derived))
            .collect()
    };
    assert_eq!(
        names(&fast),
        [("pTool".into(), true), ("pBase".into(), false)]
    );
    assert_eq!(names(&fast), names(&full));
    assert!(fast.tasks[0].modules.iter().all(|m| m.routines.is_empty()));
}
