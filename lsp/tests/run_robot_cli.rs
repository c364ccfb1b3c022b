//! `rapid run` with a modelled robot end to end: the robot rapid.toml,
//! MOC.cfg or `--robot` names, move times in the trace, `--report`, a
//! move out of reach, and the note when no robot is known.

mod support;

use support::{rapid_out as run, scratch, write};

/// An IRB 120 program: a joint move home, 100 mm at v100 in a routine
/// (1.01 s by hand: ramps of 0.5 mm at 10 m/s², 99 mm at 100 mm/s), and a
/// wait.
const CELL: &str = "MODULE Cell
  CONST jointtarget zero := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p10 := [[374,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[374,100,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveAbsJ zero, v1000, fine, tool0;
    MoveJ p10, v1000, fine, tool0;
    Side;
    Side;
    WaitTime 0.5;
  ENDPROC
  PROC Side()
    MoveL p20, v100, fine, tool0;
    MoveL p10, v100, fine, tool0;
  ENDPROC
ENDMODULE
";

#[test]
fn rapid_toml_names_the_robot_and_the_report_gives_the_cycle() {
    let dir = scratch("run-robot-report");
    write(
        &dir,
        &[
            ("Cell.mod", CELL),
            ("rapid.toml", "[controller]\nrobot = \"IRB 120-3/0.58\"\n"),
        ],
    );
    let (code, out, err) = run(
        &dir,
        &[
            "run", "Cell.mod", "--report", "--trace", "t.json", "--plot", "p.html",
        ],
    );
    assert_eq!((code, err.as_str()), (Some(0), ""), "{out}");
    // MoveJ p10 from zero: axis 5 turns 80.62 degrees at up to 320 deg/s
    // with 0.2 s ramps, (80.62 - 64) / 320 + 0.4 = 0.452 s; four MoveL of
    // 1.01 s and the wait: 0.452 + 4.04 + 0.5.
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "cycle time of main: 4.992 s", "{out}");
    assert_eq!(
        lines[1].split_whitespace().collect::<Vec<_>>(),
        ["routine", "calls", "seconds"]
    );
    assert_eq!(
        lines[2].split_whitespace().collect::<Vec<_>>(),
        ["Side", "2", "4.040"]
    );
    assert!(lines[3].starts_with("closest to a limit: axis 5 at 81.30 degrees, 38.70 from its limit 120.00 (MoveL p20, Cell.mod:13)"), "{out}");
    let trace: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("t.json")).expect("a trace"))
            .expect("JSON");
    let moves = trace["moves"].as_array().expect("moves");
    assert_eq!(moves.len(), 6);
    let side = &moves[2];
    assert_eq!(side["instruction"], "MoveL");
    let (start, end) = (
        side["start"].as_f64().expect("start"),
        side["end"].as_f64().expect("end"),
    );
    assert!((end - start - 1.01).abs() < 1e-6, "{side}");
    let joints: Vec<f64> = side["joints"]
        .as_array()
        .expect("joints")
        .iter()
        .filter_map(serde_json::Value::as_f64)
        .collect();
    // p20 is 100 mm to the left of p10: axis 1 turns atan(100 / 374).
    assert!(
        (joints[0] - 100f64.atan2(374.0).to_degrees()).abs() < 1e-3,
        "{joints:?}"
    );
    // The arm's chain for the plot: base, shoulder, elbow, wrist, flange
    // (tool0, at p20); the IRB 120's shoulder is 290 mm up.
    let arm = &side["arm"];
    assert_eq!(arm[0], serde_json::json!([0.0, 0.0, 0.0]));
    assert!(
        (arm[1][2].as_f64().expect("z") - 290.0).abs() < 1e-6,
        "{arm}"
    );
    let flange: Vec<f64> = (0..3).map(|k| arm[4][k].as_f64().expect("mm")).collect();
    assert!(
        (flange[0] - 374.0).abs() < 1e-3
            && (flange[1] - 100.0).abs() < 1e-3
            && (flange[2] - 500.0).abs() < 1e-3,
        "{flange:?}"
    );
    assert_eq!(trace["robot"]["name"], "IRB 120-3/0.58");
    assert_eq!(
        trace["robot"]["limits"][4],
        serde_json::json!([-120.0, 120.0])
    );
    let page = std::fs::read_to_string(dir.join("p.html")).expect("a page");
    assert!(page.contains(r#""robot":{"limits":"#) && page.contains(r#""arm":[[0.0,0.0,0.0]"#));
}

#[test]
fn a_move_out_of_reach_stops_at_its_line_with_the_event() {
    let dir = scratch("run-robot-reach");
    write(
        &dir,
        &[(
            "Far.mod",
            "MODULE Far\n  CONST robtarget far := [[1374,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  PROC main()\n    TPWrite \"go\";\n    MoveJ far, v1000, fine, tool0;\n    TPWrite \"there\";\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let (code, out, err) = run(&dir, &["run", "Far.mod", "--robot", "IRB 120-3/0.58"]);
    assert_eq!((code, out.as_str()), (Some(1), "go\n"));
    assert!(
        err.starts_with("error: 50050 Position outside reach: MoveJ: the position is "),
        "{err}"
    );
    assert!(err.contains("  --> Far.mod:5:5\n"), "{err}");
    // Without a robot the move arrives at once, and a note says so.
    let (code, out, err) = run(&dir, &["run", "Far.mod"]);
    assert_eq!((code, out.as_str()), (Some(0), "go\nthere\n"));
    assert_eq!(
        err,
        "rapid: run: note: no robot is named (MOC.cfg, rapid.toml [controller] robot or --robot): moves take no time and reach every target\n"
    );
    let (code, _, err) = run(&dir, &["run", "Far.mod", "--robot", "IRB 99"]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("--robot: `IRB 99` is not a modelled robot"),
        "{err}"
    );
}

#[test]
fn a_moc_cfg_beside_the_modules_names_the_robot() {
    let dir = scratch("run-robot-moc");
    write(
        &dir,
        &[
            ("Cell.mod", CELL),
            (
                "MOC.cfg",
                "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n",
            ),
        ],
    );
    let (code, out, err) = run(&dir, &["run", ".", "--report"]);
    assert_eq!((code, err.as_str()), (Some(0), ""), "{out}");
    assert!(out.starts_with("cycle time of main: 4.992 s\n"), "{out}");
}

/// The controller's configuration beside the modules (`MOC.cfg` and
/// `EIO.cfg` in their folder, or in a `SYSPAR/` folder there) counts
/// however the module is named: `Cell.mod`, `./Cell.mod`, its absolute
/// path or the folder, for `rapid run` and `rapid check` alike.
#[test]
fn configuration_beside_the_modules_counts_however_the_module_is_named() {
    const MODULE: &str = "MODULE Cell
  CONST robtarget p10 := [[374,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[1374,0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ p10, v1000, fine, tool0;
    SetDO do1, 1;
  ENDPROC
  PROC away()
    MoveJ far, v1000, fine, tool0;
  ENDPROC
ENDMODULE
";
    const MOC: &str = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n";
    const EIO: &str =
        "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"do1\" -SignalType \"DO\"\n";
    for folder in ["", "SYSPAR/"] {
        let dir = scratch(&format!("run-robot-named-{}", folder.len()));
        let (moc, eio) = (format!("{folder}MOC.cfg"), format!("{folder}EIO.cfg"));
        write(
            &dir,
            &[
                ("Cell.mod", MODULE),
                (moc.as_str(), MOC),
                (eio.as_str(), EIO),
            ],
        );
        let absolute = dir.join("Cell.mod").display().to_string();
        for named in ["Cell.mod", "./Cell.mod", absolute.as_str(), "."] {
            let shown = if named == absolute { named } else { "Cell.mod" };
            // MOC.cfg names the robot: the move takes its time; EIO.cfg
            // declares do1: no note that it is taken from its use.
            let (code, out, err) = run(&dir, &["run", named, "--report"]);
            assert_eq!(
                (code, err.as_str()),
                (Some(0), ""),
                "{folder}{named}: {out}"
            );
            assert!(
                out.starts_with("cycle time of main: 0.452 s\n"),
                "{folder}{named}: {out}"
            );
            assert!(out.contains(&format!("(MoveJ p10, {shown}:5)")), "{out}");
            // `rapid check` knows the robot (`far` is out of its reach)
            // and the signal (no I103).
            let (code, out, err) = run(&dir, &["check", "--format", "concise", named]);
            assert_eq!(code, Some(1), "{folder}{named}: {out}{err}");
            let codes: Vec<&str> = out
                .lines()
                .filter_map(|l| l.split_once(": ")?.1.split_once('[')?.1.split_once(']'))
                .map(|(c, _)| c)
                .collect();
            assert_eq!(codes, ["E601"], "{folder}{named}: {out}");
        }
    }
}

/// A move `StopMove` holds is two records in the trace: up to where the
/// arm stopped (1.25 s into 200 mm at v100 on an IRB 1600, 2.01 s: y
/// 124.4 by hand), then the rest, after the trap's own moves, to the
/// target; a move dropped with `ClearPath` ends where it stopped.
#[test]
fn a_stopped_move_is_split_in_the_trace() {
    let dir = scratch("run-robot-stop-move");
    let program = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../runtime/tests/programs/stop_move_in_a_trap.mod"),
    )
    .expect("the fixture");
    write(&dir, &[("Stop.mod", &program)]);
    let (code, _, err) = run(
        &dir,
        &[
            "run",
            "Stop.mod",
            "--robot",
            "IRB 1600-10/1.45",
            "--trace",
            "t.json",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    let trace: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("t.json")).expect("a trace"))
            .expect("JSON");
    let moves = trace["moves"].as_array().expect("moves");
    let rows: Vec<(f64, f64, f64)> = moves
        .iter()
        .map(|m| {
            let t = |k: &str| (m[k].as_f64().expect("seconds") * 1000.0).round() / 1000.0;
            (t("start"), t("end"), m["pos"][1].as_f64().expect("y"))
        })
        .collect();
    let y: Vec<i64> = rows.iter().map(|r| (r.2 * 10.0).round() as i64).collect();
    // MoveJ; MoveL stopped at 124.4; 25 mm up and back; the rest to 200;
    // the move back stopped at 150.2 and dropped.
    assert_eq!(y, [0, 1244, 1244, 1244, 2000, 1502], "{rows:?}");
    for pair in rows.windows(2) {
        assert!(pair[0].1 <= pair[1].0 + 1e-9, "moves overlap: {rows:?}");
    }
    assert!((rows[1].1 - rows[1].0 - 1.25).abs() < 1e-3, "{rows:?}");
    assert!((rows[4].1 - rows[4].0 - 0.76).abs() < 0.01, "{rows:?}");
}
