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

/// A page that draws the path: targets as points, the path between them
/// coloured by move type (drag to turn, wheel to zoom, hover a point for
/// its target's name and line).
pub fn html(moves: &[Move], title: &str) -> String {
    let data = json(moves).to_string().replace("</", "<\\/");
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
<canvas id="c"></canvas><div id="tip"></div>
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
window.onresize = draw; draw();
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
            r#"{"moves":[{"file":"m.mod","instruction":"MoveL","joints":null,"line":4,"orient":[1.0,0.0,0.0,0.0],"pos":[1.0,2.0,3.0],"speed":100.0,"speed_name":"v100","target":"p10","tool":"tool0","via":null,"wobj":null,"zone":"fine"}]}"#
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
