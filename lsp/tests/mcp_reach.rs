//! `rapid mcp`'s `reach` tool at the protocol level: the robot of the task
//! (MOC.cfg, rapid.toml, the argument), every solution and the one the
//! confdata selects, the controller's errors, and the same answers as
//! `rapid check` gives for moves to the same targets (an oracle: the
//! `check` tool's E601/E602/W601 messages carry the figures `reach`
//! answers). Bad arguments and tasks without a robot are refused.

mod support;

use rapid_robot::{Conf, Robot, model_by_name};
use serde_json::{Value, json};
use support::mcp::{Client, structured, summary};
use support::{Scratch, scratch, write};

const EXTAX: &str = "[9E9,9E9,9E9,9E9,9E9,9E9]";

/// A robtarget literal for tool0 of an IRB 120 (at the world's origin) at
/// joints `j`, with confdata `conf` (the joints' own when `None`).
fn target_at(j: [f64; 6], conf: Option<Conf>) -> String {
    let r = Robot::new(model_by_name("IRB 120-3/0.58").expect("modelled"));
    let pose = r.forward(&j).expect("finite");
    let c = conf.unwrap_or_else(|| r.conf_of(&j));
    let t = pose.translation.vector;
    let q = pose.rotation;
    format!(
        "[[{:.3},{:.3},{:.3}],[{:.6},{:.6},{:.6},{:.6}],[{},{},{},{}],{EXTAX}]",
        t.x, t.y, t.z, q.w, q.i, q.j, q.k, c.cf1, c.cf4, c.cf6, c.cfx
    )
}

/// Projects with a robot from MOC.cfg (`cell`, its base 500 mm along x and
/// axis 1 bounded to ±1.5 rad), from rapid.toml (`toml`, and `narrow` with
/// axis 5 bounded to ±20 degrees), none (`bare`), and an arm that is not
/// modelled (`yumi`).
fn projects(name: &str) -> Scratch {
    let dir = scratch(name);
    let moc = |robot_type: &str| {
        format!(
            "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_serial_number \"rob_1\"\\\n      -use_robot_type \"{robot_type}\" -base_frame_pos_x 0.5\n#\nARM:\n\n      -name \"rob1_1\" -use_arm_type \"ROB1_1\" -upper_joint_bound 1.5\\\n      -lower_joint_bound -1.5\n"
        )
    };
    let cell = format!(
        "MODULE Main\n  CONST robtarget pHome := [[874,0,630],[0.707107,0,0.707107,0],[0,0,0,0],{EXTAX}];\n  PERS tooldata tPen := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];\n  PERS wobjdata wTable := [FALSE,TRUE,\"\",[[600,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];\n  VAR num n := 1;\n  PROC main()\n    MoveJ pHome, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n"
    );
    let bent = target_at([0.0, 0.0, 0.0, 0.0, 60.0, 0.0], None);
    let twisted = target_at(
        [30.0, 10.0, 20.0, 40.0, 50.0, 10.0],
        Some(Conf {
            cf1: 0,
            cf4: 2,
            cf6: 0,
            cfx: 0,
        }),
    );
    let moves = format!(
        "MODULE Moves\n  CONST robtarget pFar := [[900,0,300],[0,0,1,0],[0,0,0,0],{EXTAX}];\n  CONST robtarget pBent := {bent};\n  CONST robtarget pTwisted := {twisted};\n  PROC main()\n    MoveL pFar, v100, fine, tool0;\n    MoveJ pBent, v100, fine, tool0;\n    MoveL pTwisted, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n"
    );
    let yumi = moc("ROB1_14000_0.5_0.5");
    write(
        &dir,
        &[
            ("cell/MOC.cfg", &moc("ROB1_120_0.58_3")),
            ("cell/Main.mod", &cell),
            (
                "toml/rapid.toml",
                "[controller]\nrobot = \"IRB 120-3/0.58\"\n",
            ),
            ("toml/Moves.mod", &moves),
            (
                "narrow/rapid.toml",
                "[controller]\nrobot = \"ROB1_120_0.58_3\"\njoint-limits = [[-165, 165], [-110, 110], [-110, 70], [-160, 160], [-20, 20], [-400, 400]]\n",
            ),
            ("narrow/Moves.mod", &moves),
            ("bare/Main.mod", &cell),
            ("yumi/MOC.cfg", &yumi),
            ("yumi/Main.mod", &cell),
        ],
    );
    dir
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

/// The selected solution's joints.
fn selected(r: &Value) -> Vec<f64> {
    let i = r["selected"].as_u64().unwrap_or_else(|| panic!("{r:#}")) as usize;
    r["solutions"][i]["joints"]
        .as_array()
        .expect("joints")
        .iter()
        .map(num)
        .collect()
}

/// The message of the one finding with `code` on the line that names
/// `target` in the `check` tool's answer.
fn finding(check: &Value, code: &str, target: &str) -> String {
    let named = format!("`{target}`");
    let found: Vec<&Value> = check["findings"]
        .as_array()
        .expect("findings")
        .iter()
        .filter(|f| f["code"] == code)
        .filter(|f| f["message"].as_str().is_some_and(|m| m.contains(&named)))
        .collect();
    assert_eq!(found.len(), 1, "{code}: {check:#}");
    found[0]["message"].as_str().expect("a message").to_owned()
}

#[test]
fn reach_answers_every_solution_and_the_one_confdata_selects() {
    let dir = projects("reach-solutions");
    let mut c = Client::start(&dir, &[], None);
    let answer = c.call("reach", json!({"path": "cell/Main.mod", "target": "pHome"}));
    let r = structured(&answer);
    assert_eq!(r["robot"]["name"], "IRB 120-3/0.58", "{r:#}");
    assert_eq!(r["robot"]["source"], "MOC.cfg");
    assert!(
        r["robot"]["origin"]
            .as_str()
            .is_some_and(|o| o.contains("ROB_1") && o.contains("ROB1_120_0.58_3")),
        "{r:#}"
    );
    // MOC.cfg's base frame and axis 1 bounds (1.5 rad).
    assert_eq!(r["robot"]["base_position"], json!([500.0, 0.0, 0.0]));
    assert!((num(&r["robot"]["limits"][0][1]) - 1.5f64.to_degrees()).abs() < 1e-6);
    assert_eq!(r["task"], "cell", "{r:#}");
    assert_eq!(r["tool"], "tool0");
    assert_eq!(r["conf_monitoring"], true);
    // [874,0,630] with the base 500 mm along x: the calibration position.
    for a in selected(r) {
        assert!(a.abs() < 1e-3, "{r:#}");
    }
    let solutions = r["solutions"].as_array().expect("solutions");
    assert!(solutions.len() >= 2, "{r:#}");
    // Every solution is distinct and within the working ranges.
    for (i, s) in solutions.iter().enumerate() {
        for (k, a) in s["joints"].as_array().expect("joints").iter().enumerate() {
            let [lo, hi] = [&r["robot"]["limits"][k][0], &r["robot"]["limits"][k][1]].map(num);
            assert!(num(a) >= lo - 0.01 && num(a) <= hi + 0.01, "{s}");
        }
        for t in &solutions[..i] {
            assert_ne!(s["joints"], t["joints"]);
        }
    }
    assert!(r.get("error").is_none(), "{r:#}");
    let text = summary(&answer);
    assert!(
        text.contains("the target's confdata selects this one"),
        "{text}"
    );
    assert!(text.contains("IRB 120-3/0.58"), "{text}");

    // A literal, through a tool and a work object: the work object 600 mm
    // along x puts the TCP at [974,0,630] in the world, the tool 100 mm
    // ahead of the flange (along x in this orientation) the flange at
    // [874,0,630], 374 mm ahead of the base: the calibration position again.
    let literal = format!("[[374,0,630],[0.707107,0,0.707107,0],[0,0,0,0],{EXTAX}]");
    let answer = c.call(
        "reach",
        json!({"path": "cell", "target": literal, "tool": "tPen", "wobj": "wTable"}),
    );
    let r = structured(&answer);
    for a in selected(r) {
        assert!(a.abs() < 1e-3, "{r:#}");
    }
    assert_eq!((&r["tool"], &r["wobj"]), (&json!("tPen"), &json!("wTable")));
    // Any constant expression of the task.
    let answer = c.call(
        "reach",
        json!({"path": "cell", "target": "Offs(pHome, 0, 0, -100)"}),
    );
    let r = structured(&answer);
    assert_eq!(r["target"]["position"], json!([874.0, 0.0, 530.0]), "{r:#}");
    // Offs keeps pHome's confdata, but 100 mm lower with the same
    // orientation axis 5 bends below zero (cfx bit 0): the controller
    // refuses the move with ConfL on, and makes it with ConfL off.
    let e = &r["error"];
    assert_eq!(
        (&e["kind"], &e["event"]),
        (&json!("configuration"), &json!(50080)),
        "{r:#}"
    );
    assert_eq!(
        e["reachable_conf"],
        json!({"cf1": 0, "cf4": 0, "cf6": 0, "cfx": 1})
    );
    let answer = c.call(
        "reach",
        json!({"path": "cell", "target": "Offs(pHome, 0, 0, -100)", "conf_monitoring": false}),
    );
    let r = structured(&answer);
    let j = selected(r);
    assert!(j[4] < 0.0, "{r:#}");
    assert_eq!(
        r["solutions"][r["selected"].as_u64().expect("selected") as usize]["conf"]["cfx"],
        1
    );
}

#[test]
fn reach_errors_are_the_controllers_and_agree_with_rapid_check() {
    let dir = projects("reach-errors");
    let mut c = Client::start(&dir, &[], None);
    let check = c.call("check", json!({"path": "toml", "select": ["E6", "W6"]}));
    let check = structured(&check).clone();

    // Out of reach: E601, event 50050, ERR_OUTSIDE_REACH, by as many mm
    // as the check says.
    let answer = c.call("reach", json!({"path": "toml", "target": "pFar"}));
    let r = structured(&answer);
    assert_eq!(r["robot"]["source"], "rapid.toml", "{r:#}");
    let e = &r["error"];
    assert_eq!(
        (&e["kind"], &e["rule"], &e["event"], &e["rapid_error"]),
        (
            &json!("out_of_reach"),
            &json!("E601"),
            &json!(50050),
            &json!("ERR_OUTSIDE_REACH")
        ),
        "{r:#}"
    );
    assert_eq!(e["title"], "Position outside reach");
    assert!(
        r.get("selected").is_none() && r["solutions"] == json!([]),
        "{r:#}"
    );
    let by = format!("{:.1} mm", num(&e["by_mm"]));
    let message = finding(&check, "E601", "pFar");
    assert!(message.contains(&by), "{by} / {message}");

    // In another configuration only: W601, event 50080, the configuration
    // that reaches it; the solutions are still listed.
    let answer = c.call("reach", json!({"path": "toml", "target": "pTwisted"}));
    let r = structured(&answer);
    let e = &r["error"];
    assert_eq!(
        (&e["kind"], &e["rule"]),
        (&json!("configuration"), &json!("W601"))
    );
    assert_eq!(e["event"], 50080);
    assert_eq!(
        e["reachable_conf"],
        json!({"cf1": 0, "cf4": 0, "cf6": 0, "cfx": 0}),
        "{r:#}"
    );
    assert!(!r["solutions"].as_array().expect("solutions").is_empty());
    let message = finding(&check, "W601", "pTwisted");
    assert!(
        message.contains("[0,2,0,0]") && message.contains("[0,0,0,0]"),
        "{message}"
    );
    // Without configuration monitoring the move goes.
    let answer = c.call(
        "reach",
        json!({"path": "toml", "target": "pTwisted", "conf_monitoring": false}),
    );
    let r = structured(&answer);
    assert!(r.get("error").is_none(), "{r:#}");
    assert!(summary(&answer).contains("a move uses this one"));

    // Beyond a working range (rapid.toml's axis 5 bounded to ±20): E602,
    // the axis and the excess as the check reports them.
    let check = c.call("check", json!({"path": "narrow", "select": ["E602"]}));
    let message = finding(structured(&check), "E602", "pBent");
    let answer = c.call(
        "reach",
        json!({"path": "narrow/Moves.mod", "target": "pBent"}),
    );
    let r = structured(&answer);
    let e = &r["error"];
    assert_eq!(
        (&e["kind"], &e["rule"]),
        (&json!("joint_limit"), &json!("E602"))
    );
    assert_eq!(e["rapid_error"], "ERR_ROBLIMIT");
    let axis = e["axis"].as_u64().expect("an axis");
    assert!(message.contains(&format!("axis {axis}")), "{message}");
    let by = format!(", {:.1} beyond", num(&e["by_degrees"]));
    assert!(message.contains(&by), "{by} / {message}");
}

#[test]
fn a_task_without_a_robot_needs_one_named() {
    let dir = projects("reach-robot");
    let mut c = Client::start(&dir, &[], None);
    let message = c.refused("reach", json!({"path": "bare", "target": "pHome"}));
    assert!(message.contains("has no robot"), "{message}");
    assert!(message.contains("`robot`"), "{message}");
    let answer = c.call(
        "reach",
        json!({"path": "bare", "target": "pHome", "robot": "IRB 140-6/0.81"}),
    );
    let r = structured(&answer);
    assert_eq!(
        (&r["robot"]["name"], &r["robot"]["source"]),
        (&json!("IRB 140-6/0.81"), &json!("argument")),
        "{r:#}"
    );
    // The task's robot is the one `rapid check` uses: another is refused,
    // the same one is fine.
    let message = c.refused(
        "reach",
        json!({"path": "cell", "target": "pHome", "robot": "IRB 140-6/0.81"}),
    );
    assert!(
        message.contains("the task's robot is the IRB 120-3/0.58"),
        "{message}"
    );
    let same = c.call(
        "reach",
        json!({"path": "cell", "target": "pHome", "robot": "IRB 120"}),
    );
    assert_eq!(structured(&same)["robot"]["source"], "MOC.cfg");
    // A controller whose robot is not modelled is not guessed at.
    let message = c.refused(
        "reach",
        json!({"path": "yumi", "target": "pHome", "robot": "IRB 120"}),
    );
    assert!(message.contains("not modelled"), "{message}");
}

#[test]
fn bad_reach_arguments_are_refused_with_what_was_expected() {
    let dir = projects("reach-bad");
    let mut c = Client::start(&dir, &["--root", "."], None);
    for (args, expected) in [
        (json!({"path": "cell"}), "missing field `target`"),
        (json!({"target": "pHome"}), "missing field `path`"),
        (
            json!({"path": "cell", "target": "pHome", "speed": 1}),
            "unknown field `speed`",
        ),
        (json!({"path": "cell", "target": "pNowhere"}), "pNowhere"),
        (json!({"path": "cell", "target": "42"}), "target:"),
        (json!({"path": "cell", "target": "[[1,2"}), "target: "),
        (
            json!({"path": "cell", "target": ""}),
            "target: the expression is empty",
        ),
        (json!({"path": "cell", "target": "n"}), "target:"),
        (
            json!({"path": "cell", "target": "pHome", "tool": "pHome"}),
            "tool:",
        ),
        (
            json!({"path": "cell", "target": "pHome", "wobj": "tPen"}),
            "wobj:",
        ),
        (
            json!({"path": "bare", "target": "pHome", "robot": "IRB 9999"}),
            "is not a modelled robot; known: IRB 120-3/0.58",
        ),
        (
            json!({"path": "bare", "target": "pHome", "robot": "IRB 14000"}),
            "not modelled",
        ),
        (
            json!({"path": "nowhere", "target": "pHome"}),
            "no such file or folder",
        ),
        (
            json!({"path": "/", "target": "pHome"}),
            "outside the folders this server may read",
        ),
    ] {
        let message = c.refused("reach", args.clone());
        assert!(message.contains(expected), "{args}: {message}");
    }
    // Still serving.
    let ok = c.call("reach", json!({"path": "cell", "target": "pHome"}));
    assert!(structured(&ok)["selected"].is_u64());
}
