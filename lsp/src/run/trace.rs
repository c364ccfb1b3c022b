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
/// at any moment (a time slider and a play button; between two moves'
/// ends the drawing interpolates the chain), each axis's angle over time
/// with its limits, and the moves that end within 5 degrees of a limit or
/// with axis 5 within 5 degrees of zero (a wrist singularity) marked on the
/// path and listed with their lines.
pub fn html(moves: &[Move], title: &str) -> String {
    html_with_arm(moves, None, title)
}

/// [`html`] with the arm that made the moves.
pub fn html_with_arm(moves: &[Move], arm: Option<&rapid_robot::Robot>, title: &str) -> String {
    let data = json_with_arm(moves, arm).to_string().replace("</", "<\\/");
    let title = title
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    PAGE.replace("{{TITLE}}", &title).replace("{{DATA}}", &data)
}

const PAGE: &str = r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{{TITLE}}: robot path</title>
<style>
body{margin:0;font:13px system-ui,sans-serif;background:#fafafa;color:#222}
header{padding:6px 12px;border-bottom:1px solid #ddd;display:flex;gap:16px;align-items:center}
canvas{display:block;width:100vw;height:calc(100vh - 34px);cursor:grab}
#tip{position:fixed;pointer-events:none;background:#fff;border:1px solid #aaa;padding:4px 6px;display:none;white-space:pre}
.key span{display:inline-block;width:18px;height:3px;margin:0 4px 3px 10px;vertical-align:middle}
</style></head><body>
<header><b>{{TITLE}}</b><span id="count"></span><span class="key">
<span style="background:#1f77b4"></span>MoveL<span style="background:#ff7f0e"></span>MoveJ
<span style="background:#2ca02c"></span>MoveC<span style="background:#9467bd"></span>Search/other</span>
<span>drag: turn, wheel: zoom</span></header>
<div id="timebar" style="display:none;padding:4px 12px;border-bottom:1px solid #ddd">
<button id="play">play</button> <input id="t" type="range" min="0" max="1000" value="1000" style="width:50%;vertical-align:middle"> <span id="now"></span></div>
<canvas id="c"></canvas><canvas id="j" style="display:none;height:240px"></canvas>
<div id="problems" style="padding:4px 12px"></div><div id="tip"></div>
<script>
const data = {{DATA}};
const moves = data.moves.filter(m => m.pos);
document.getElementById('count').textContent = data.moves.length + ' moves';
const colour = i => i.startsWith('MoveL') || i.startsWith('TriggL') ? '#1f77b4'
  : i.startsWith('MoveJ') || i.startsWith('TriggJ') ? '#ff7f0e'
  : i.startsWith('MoveC') || i.startsWith('TriggC') ? '#2ca02c' : '#9467bd';
const c = document.getElementById('c'), g = c.getContext('2d'), tip = document.getElementById('tip');
let yaw = -0.6, pitch = 0.5, zoom = 1, drag = null, shown = [];
const pts = moves.map(m => m.pos).concat(moves.filter(m => m.via).map(m => m.via));
const lo = [0,1,2].map(k => Math.min(...pts.map(p => p[k]), 0));
const hi = [0,1,2].map(k => Math.max(...pts.map(p => p[k]), 0));
const mid = [0,1,2].map(k => (lo[k] + hi[k]) / 2);
const size = Math.max(...[0,1,2].map(k => hi[k] - lo[k]), 1);
function project(p) {
  const x = p[0] - mid[0], y = p[1] - mid[1], z = p[2] - mid[2];
  const x1 = x * Math.cos(yaw) - y * Math.sin(yaw), y1 = x * Math.sin(yaw) + y * Math.cos(yaw);
  const y2 = y1 * Math.sin(pitch) + z * Math.cos(pitch);
  const s = Math.min(c.width, c.height) * 0.8 * zoom / size;
  return [c.width / 2 + x1 * s, c.height / 2 - y2 * s];
}
function line(a, b, col, w) { g.strokeStyle = col; g.lineWidth = w; g.beginPath(); g.moveTo(...a); g.lineTo(...b); g.stroke(); }
function draw() {
  c.width = c.clientWidth * devicePixelRatio; c.height = c.clientHeight * devicePixelRatio;
  g.clearRect(0, 0, c.width, c.height);
  const o = project(mid.map(() => 0)), L = size / 4;
  line(o, project([L,0,0]), '#d62728', 1); line(o, project([0,L,0]), '#2ca02c', 1); line(o, project([0,0,L]), '#1f77b4', 1);
  shown = [];
  let prev = null;
  for (const m of moves) {
    const p = project(m.pos);
    if (prev) {
      if (m.via) { const v = project(m.via); line(prev, v, colour(m.instruction), 2); line(v, p, colour(m.instruction), 2); }
      else line(prev, p, colour(m.instruction), 2);
    }
    g.fillStyle = colour(m.instruction); g.beginPath(); g.arc(p[0], p[1], 4 * devicePixelRatio, 0, 7); g.fill();
    shown.push([p, m]); prev = p;
  }
}
c.onmousedown = e => { drag = [e.clientX, e.clientY]; };
window.onmouseup = () => { drag = null; };
c.onmousemove = e => {
  if (drag) { yaw += (e.clientX - drag[0]) / 200; pitch += (e.clientY - drag[1]) / 200; drag = [e.clientX, e.clientY]; draw(); return; }
  const x = e.offsetX * devicePixelRatio, y = e.offsetY * devicePixelRatio;
  const hit = shown.find(([p]) => Math.hypot(p[0] - x, p[1] - y) < 8 * devicePixelRatio);
  if (!hit) { tip.style.display = 'none'; return; }
  const m = hit[1], f = v => v.toFixed(1);
  tip.textContent = (m.target || '(expression)') + '  ' + m.instruction + '\n' + m.file + ':' + m.line
    + '\n[' + m.pos.map(f).join(', ') + ']' + (m.speed_name ? '  ' + m.speed_name : '') + (m.zone ? '  ' + m.zone : '');
  tip.style.left = (e.clientX + 12) + 'px'; tip.style.top = (e.clientY + 12) + 'px'; tip.style.display = 'block';
};
c.onwheel = e => { e.preventDefault(); zoom *= e.deltaY < 0 ? 1.1 : 0.9; draw(); };
// The arm: a chain drawn at the slider's time, the axes over time.
const robot = data.robot, armed = data.moves.filter(m => m.arm);
const end = armed.length ? Math.max(...armed.map(m => m.end)) : 0;
const problem = m => {
  if (!m.joints || !robot) return null;
  const out = [];
  m.joints.forEach((a, i) => { const [lo, hi] = robot.limits[i], d = Math.min(a - lo, hi - a);
    if (d < 5) out.push('axis ' + (i + 1) + ' ' + d.toFixed(1) + ' deg from its limit'); });
  if (Math.abs(m.joints[4]) < 5) out.push('axis 5 at ' + m.joints[4].toFixed(1) + ' deg: near a wrist singularity');
  return out.length ? out.join(', ') : null;
};
let t = end;
function armAt(t) {
  let prev = armed[0];
  for (const m of armed) {
    if (t <= m.end) {
      const f = m.end > m.start ? Math.min(Math.max((t - m.start) / (m.end - m.start), 0), 1) : 1;
      const a = prev === m ? m.arm : prev.arm;
      return [m.arm.map((p, k) => p.map((x, i) => a[k][i] + (x - a[k][i]) * f)), m];
    }
    prev = m;
  }
  return [prev.arm, prev];
}
function drawArm() {
  if (!armed.length) return;
  const [chain, m] = armAt(t);
  const pts = chain.map(project);
  for (let k = 1; k < pts.length; k++) line(pts[k - 1], pts[k], '#444', 5 * devicePixelRatio);
  g.fillStyle = '#444';
  for (const p of pts) { g.beginPath(); g.arc(p[0], p[1], 5 * devicePixelRatio, 0, 7); g.fill(); }
  document.getElementById('now').textContent = t.toFixed(3) + ' s of ' + end.toFixed(3) + ' s: '
    + m.instruction + ' ' + (m.target || '') + ' (' + m.file + ':' + m.line + ')  axes ['
    + m.joints.map(a => a.toFixed(1)).join(', ') + ']';
}
function drawJoints() {
  const k = document.getElementById('j'), h = k.getContext('2d');
  k.width = k.clientWidth * devicePixelRatio; k.height = k.clientHeight * devicePixelRatio;
  const rowH = k.height / 6, x = s => 40 * devicePixelRatio + (k.width - 50 * devicePixelRatio) * (end ? s / end : 0);
  h.font = (10 * devicePixelRatio) + 'px sans-serif';
  for (let i = 0; i < 6; i++) {
    const [lo, hi] = robot.limits[i], y = a => (i + 1) * rowH - 3 - (a - lo) / (hi - lo) * (rowH - 6);
    h.strokeStyle = '#d62728'; h.setLineDash([4, 3]); h.lineWidth = 1;
    for (const b of [lo, hi]) { h.beginPath(); h.moveTo(x(0), y(b)); h.lineTo(x(end), y(b)); h.stroke(); }
    h.setLineDash([]); h.strokeStyle = '#1f77b4'; h.lineWidth = 1.5 * devicePixelRatio; h.beginPath();
    armed.forEach((m, n) => { if (n === 0) h.moveTo(x(m.start), y(m.joints[i])); h.lineTo(x(m.end), y(m.joints[i])); });
    h.stroke(); h.fillStyle = '#222'; h.fillText('axis ' + (i + 1), 2, i * rowH + rowH / 2);
  }
  h.strokeStyle = '#000'; h.beginPath(); h.moveTo(x(t), 0); h.lineTo(x(t), k.height); h.stroke();
}
if (robot && armed.length) {
  const found = data.moves.map(m => [m, problem(m)]).filter(([, p]) => p);
  document.getElementById('timebar').style.display = 'block';
  const jc = document.getElementById('j'); jc.style.display = 'block'; jc.style.width = '100vw';
  c.style.height = 'calc(100vh - 340px)';
  const slider = document.getElementById('t');
  const plain = draw;
  draw = () => { plain(); for (const [m] of found) if (m.pos) { const p = project(m.pos);
    g.strokeStyle = '#d62728'; g.lineWidth = 2 * devicePixelRatio; g.beginPath(); g.arc(p[0], p[1], 9 * devicePixelRatio, 0, 7); g.stroke(); }
    drawArm(); drawJoints(); };
  const redraw = () => draw();
  slider.oninput = () => { t = end * slider.value / 1000; redraw(); };
  let timer = null;
  document.getElementById('play').onclick = () => {
    if (timer) { clearInterval(timer); timer = null; return; }
    if (t >= end) t = 0;
    timer = setInterval(() => { t = Math.min(end, t + 0.04); slider.value = end ? 1000 * t / end : 0; redraw();
      if (t >= end) { clearInterval(timer); timer = null; } }, 40);
  };
  const list = document.getElementById('problems');
  list.textContent = found.length ? 'Problems:' : 'No move ends near a limit or a wrist singularity.';
  for (const [m, p] of found) { const d = document.createElement('div');
    d.textContent = m.file + ':' + m.line + '  ' + m.instruction + ' ' + (m.target || '') + ': ' + p; list.appendChild(d); }
  window.onresize = redraw; redraw();
}
</script></body></html>
"#;

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
        let page = html(&[m], "a<b");
        assert!(page.contains("a&lt;b: robot path"));
        assert!(page.contains(r#"<\/script><b>"#));
        assert!(!page.contains("{{DATA}}"));
    }
}
