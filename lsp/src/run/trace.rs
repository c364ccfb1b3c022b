//! The motion of a run: `--trace FILE` writes it as JSON, `--plot
//! FILE.html` draws it in 3D in a self-contained page.

use rapid_runtime::Move;
use serde_json::{Value, json};

/// The moves as JSON: `{"moves": [{"instruction", "target", "file",
/// "line", "pos", "orient", "via", "joints", "speed", "speed_name",
/// "zone", "tool", "wobj", "start", "end"}]}`, and `"task"` when several
/// tasks ran (positions in mm in world coordinates, joints in degrees at
/// the move's end, start and end in simulated seconds,
/// orientations as quaternions `[q1, q2, q3, q4]`; absent fields are null).
pub fn json(moves: &[Move]) -> Value {
    let moves: Vec<Value> = moves
        .iter()
        .map(|m| {
            let mut o = json!({
                "instruction": m.instruction,
                "target": m.target,
                "file": m.at.path,
                "line": m.at.line,
                "pos": m.pos.map(|p| p.map(round)),
                "orient": m.orient.map(|q| q.map(round)),
                "via": m.via.map(|p| p.map(round)),
                "joints": m.joints.as_ref().map(|j| j.iter().map(|x| round(*x)).collect::<Vec<_>>()),
                "speed": m.speed,
                "speed_name": m.speed_name,
                "zone": m.zone,
                "tool": m.tool,
                "wobj": m.wobj,
                "start": round(m.start),
                "end": round(m.end),
            });
            if let Some(task) = &m.task {
                o["task"] = json!(task);
            }
            o
        })
        .collect();
    json!({ "moves": moves })
}

/// Six decimals are far below what a robot repeats.
fn round(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

/// The trace with the arm that made the moves: `"robot": {"name",
/// "limits"}` and, for each move whose joints are known, `"arm"`: the
/// chain's points in world coordinates (base, shoulder, elbow, wrist,
/// flange).
pub fn json_with_arm(moves: &[Move], arm: Option<&rapid_robot::Robot>) -> Value {
    let mut v = json(moves);
    let Some(robot) = arm else {
        return v;
    };
    v["robot"] = json!({ "name": robot.model.name, "limits": robot.limits.0 });
    if let Some(list) = v["moves"].as_array_mut() {
        for (o, m) in list.iter_mut().zip(moves) {
            let Some(j) = m
                .joints
                .as_ref()
                .and_then(|j| <[f64; 6]>::try_from(j.as_slice()).ok())
            else {
                continue;
            };
            let Some(p) = robot.arm().points(&j) else {
                continue;
            };
            let world = |q: rapid_evaluator::nalgebra::Point3<f64>| {
                let w = robot.base * q;
                [round(w.x), round(w.y), round(w.z)]
            };
            let origin = rapid_evaluator::nalgebra::Point3::origin();
            o["arm"] = json!([
                world(origin),
                world(p.shoulder),
                world(p.elbow),
                world(p.wrist),
                world(p.flange)
            ]);
        }
    }
    v
}

/// A page that draws the path: targets as points, the path between them
/// coloured by move type (drag to turn, wheel to zoom, hover a point for
/// its target's name and line). With the arm: the arm as a kinematic chain
/// at any moment (a time slider and a play button; between two moves' ends
/// the drawing interpolates the chain), each axis's angle over time with
/// its limits, and the moves that end within 5 degrees of a limit or with
/// axis 5 within 5 degrees of zero (a wrist singularity) marked on the path
/// and listed with their lines. The arm is the one that made the moves.
pub fn html_with_arm(moves: &[Move], arm: Option<&rapid_robot::Robot>, title: &str) -> String {
    page(&json_with_arm(moves, arm), title, None)
}

/// Where a debugger stopped a run, for the page to follow it: the
/// simulated time, the line, and the task whose moves count.
pub struct Stopped<'a> {
    pub now: f64,
    /// The file and line the program stopped at (`None` at the end).
    pub at: Option<(&'a str, usize)>,
    /// The stopped task's name (its last move is the current one), when
    /// several tasks run.
    pub task: Option<&'a str>,
    /// Counts the states, for the page to see a new one.
    pub seq: u64,
    pub ended: bool,
}

/// The trace with the arm ([`json_with_arm`]) at a debugger's stop: also
/// `"now"`, `"current"` (the index of the stopped task's last move: the
/// one that brought the robot where it is), `"at"` (`{"file", "line"}`),
/// `"seq"` and `"ended"`. The page draws the arm at `now` and highlights
/// the current move.
pub fn followed(moves: &[Move], arm: Option<&rapid_robot::Robot>, stop: &Stopped<'_>) -> Value {
    let mut v = json_with_arm(moves, arm);
    let current = moves
        .iter()
        .rposition(|m| stop.task.is_none() || m.task.is_none() || m.task.as_deref() == stop.task);
    v["now"] = json!(round(stop.now));
    v["current"] = json!(current);
    v["at"] = match stop.at {
        Some((file, line)) => json!({ "file": file, "line": line }),
        None => Value::Null,
    };
    v["seq"] = json!(stop.seq);
    v["ended"] = json!(stop.ended);
    v
}

/// The page of `data` (a trace, [`json_with_arm`] or [`followed`]); with
/// `live`, the name of a script beside it ([`live_script`]) that the page,
/// opened as a file, reads again and again to follow a debugger.
pub fn page(data: &Value, title: &str, live: Option<&str>) -> String {
    let data = script_safe(&data.to_string());
    let live = script_safe(&json!(live).to_string());
    let title = title
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    // One pass: what is put in is not searched again.
    let mut out = String::with_capacity(PAGE.len() + data.len());
    let mut rest = PAGE;
    while let Some(i) = rest.find("{{") {
        out.push_str(&rest[..i]);
        rest = &rest[i..];
        let slot = [
            ("{{TITLE}}", &title),
            ("{{LIVE}}", &live),
            ("{{DATA}}", &data),
        ]
        .into_iter()
        .find(|(name, _)| rest.starts_with(name));
        match slot {
            Some((name, value)) => {
                out.push_str(value);
                rest = &rest[name.len()..];
            }
            None => {
                out.push_str("{{");
                rest = &rest[2..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// The script a followed page reads: it hands the page the state `data`.
pub fn live_script(data: &Value) -> String {
    format!("rapidFollow({});\n", script_safe(&data.to_string()))
}

/// JSON that cannot end the `<script>` element it is written into.
fn script_safe(json: &str) -> String {
    json.replace("</", "<\\/")
}

/// The page (`plot.html`): its script draws `{{DATA}}` and follows `{{LIVE}}`.
const PAGE: &str = include_str!("plot.html");

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_runtime::Location;

    fn mv(instruction: &str, pos: [f64; 3]) -> Move {
        Move {
            instruction: instruction.to_owned(),
            target: Some("p10".to_owned()),
            at: Location {
                path: "m.mod".to_owned(),
                line: 4,
                column: 5,
            },
            pos: Some(pos),
            orient: Some([1.0, 0.0, 0.0, 0.0]),
            via: None,
            joints: None,
            speed: Some(100.0),
            speed_name: Some("v100".to_owned()),
            start: 0.0,
            end: 0.0,
            zone: Some("fine".to_owned()),
            tool: Some("tool0".to_owned()),
            wobj: None,
            task: None,
        }
    }

    #[test]
    fn the_trace_names_each_move_with_its_line() {
        let j = json(&[mv("MoveL", [1.0, 2.0, 3.000_000_4])]);
        assert_eq!(
            j.to_string(),
            r#"{"moves":[{"end":0.0,"file":"m.mod","instruction":"MoveL","joints":null,"line":4,"orient":[1.0,0.0,0.0,0.0],"pos":[1.0,2.0,3.0],"speed":100.0,"speed_name":"v100","start":0.0,"target":"p10","tool":"tool0","via":null,"wobj":null,"zone":"fine"}]}"#
        );
    }

    #[test]
    fn the_page_holds_its_data_and_cannot_be_broken_out_of() {
        let mut m = mv("MoveJ", [0.0; 3]);
        m.target = Some("</script><b>".to_owned());
        let page = html_with_arm(&[m], None, "a<b");
        assert!(page.contains("a&lt;b: robot path"));
        assert!(page.contains(r#"<\/script><b>"#));
        assert!(!page.contains("{{DATA}}"));
    }

    #[test]
    fn a_followed_state_names_the_stop_and_the_last_move_of_the_stopped_task() {
        let mut a = mv("MoveJ", [0.0; 3]);
        a.task = Some("T_ROB1".to_owned());
        let mut b = mv("MoveL", [1.0; 3]);
        b.task = Some("T_ROB2".to_owned());
        let stop = Stopped {
            now: 1.234_567_89,
            at: Some(("m.mod", 7)),
            task: Some("T_ROB1"),
            seq: 3,
            ended: false,
        };
        let v = followed(&[a, b], None, &stop);
        assert_eq!(v["current"], 0);
        assert_eq!(v["now"], 1.234_568);
        assert_eq!(v["at"], json!({"file": "m.mod", "line": 7}));
        assert_eq!(
            (v["seq"].clone(), v["ended"].clone()),
            (json!(3), json!(false))
        );
        let none = followed(&[], None, &stop);
        assert_eq!(none["current"], Value::Null);
        // The page reads the state script beside it; what is put in the
        // page is not read as a slot again.
        let page = page(&v, "{{DATA}} x", Some("p.live.js"));
        assert!(page.contains(r#"const live = "p.live.js";"#));
        assert!(page.contains("<title>{{DATA}} x: robot path</title>"));
        assert!(live_script(&v).starts_with("rapidFollow({"));
    }
}
