//! Position events: `TriggIO` and `TriggEquip` set up an output in a
//! `triggdata`, `TriggInt` an interrupt; `TriggL`, `TriggJ` and `TriggC`
//! move and set each of their events' outputs (or order their interrupts)
//! when the robot passes its point.
//!
//! What is modelled: an event `Distance` mm before the end of the move
//! (after its start with `\Start`) fires at that fraction of the move's
//! time, the TCP taken to move at a constant speed along the straight
//! line between the move's ends; with `\Time`, `Distance` seconds before
//! the end. `TriggEquip`'s `EquipLag` fires it that much earlier, and
//! `\DODelay` later. What is not: the speed's ramps and the zone's
//! corner path (both shift an event in time, not in order) and
//! `\ProcID`. `TriggEquip`'s `\Inhib` is read when the event is set up
//! (an inhibited event does not fire).

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, invalid};
use crate::world::WObj;

/// A `triggdata`: what happens (an output set, or an interrupt), and
/// where.
struct Event {
    /// The output's name, empty for an interrupt.
    signal: String,
    /// The output's value, or the interrupt's number.
    value: f64,
    distance: f64,
    start: bool,
    time: bool,
    /// Seconds after the point (`\DODelay`), or before it (`EquipLag`,
    /// negative).
    shift: f64,
    inhibited: bool,
}

fn store(cx: &mut Cx<'_>, a: &Args, e: Event) -> R<Done> {
    let p = cx.place_arg(a, "TriggData")?;
    let value = Value::Record {
        ty: "triggdata".to_owned(),
        fields: vec![
            ("signal".to_owned(), Value::Str(e.signal)),
            ("value".to_owned(), Value::Dnum(e.value)),
            ("distance".to_owned(), Value::Dnum(e.distance)),
            ("start".to_owned(), Value::Bool(e.start)),
            ("time".to_owned(), Value::Bool(e.time)),
            ("shift".to_owned(), Value::Dnum(e.shift)),
            ("inhibited".to_owned(), Value::Bool(e.inhibited)),
        ],
    };
    cx.store(&p, value)?;
    Ok(Done::Next)
}

/// The output of `\DOp`, `\GOp` or `\AOp`.
fn output(cx: &mut Cx<'_>, a: &Args) -> R<String> {
    if a.given("ProcID") {
        return crate::machine::fault(crate::machine::FaultKind::Unsupported(format!(
            "{} \\ProcID (a process event)",
            a.name
        )));
    }
    for p in ["DOp", "GOp", "AOp"] {
        if let Some(v) = cx.opt(a, p)? {
            return Ok(cx.m.signal_of(cx.sh, &v)?.0);
        }
    }
    invalid(format!("{}: give one of \\DOp, \\GOp, \\AOp", a.name))
}

/// `TriggIO TriggData, Distance [\Start] | [\Time] [\DOp] | [\GOp] |
/// [\AOp] | [\ProcID], SetValue [\DODelay]`.
pub(crate) fn trigg_io(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let event = Event {
        signal: output(cx, a)?,
        value: cx.num(a, "SetValue")?,
        distance: cx.num(a, "Distance")?,
        start: a.given("Start"),
        time: a.given("Time"),
        shift: cx.opt_num(a, "DODelay")?.unwrap_or(0.0),
        inhibited: false,
    };
    store(cx, a, event)
}

/// `TriggEquip TriggData, Distance [\Start], EquipLag [\DOp] | [\GOp] |
/// [\AOp] | [\ProcID], SetValue [\Inhib]`: the output is set `EquipLag`
/// seconds before the TCP reaches the point (after, when negative).
pub(crate) fn trigg_equip(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let inhibited = matches!(cx.opt(a, "Inhib")?, Some(Value::Bool(true)));
    let event = Event {
        signal: output(cx, a)?,
        value: cx.num(a, "SetValue")?,
        distance: cx.num(a, "Distance")?,
        start: a.given("Start"),
        time: false,
        shift: -cx.num(a, "EquipLag")?,
        inhibited,
    };
    store(cx, a, event)
}

/// `TriggInt TriggData, Distance [\Start] | [\Time], Interrupt`: the
/// interrupt (connected to its trap routine) is ordered when the robot
/// passes the point.
pub(crate) fn trigg_int(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id = super::io::interrupt_number(cx, a)?;
    let event = Event {
        signal: String::new(),
        value: f64::from(id),
        distance: cx.num(a, "Distance")?,
        start: a.given("Start"),
        time: a.given("Time"),
        shift: 0.0,
        inhibited: false,
    };
    store(cx, a, event)
}

fn event_of(v: &Value) -> Option<Event> {
    let num = |n| v.field(n).and_then(Value::as_f64);
    let flag = |n| matches!(v.field(n), Some(Value::Bool(true)));
    let Some(Value::Str(signal)) = v.field("signal") else {
        return None;
    };
    Some(Event {
        signal: signal.clone(),
        value: num("value")?,
        distance: num("distance")?,
        start: flag("start"),
        time: flag("time"),
        shift: num("shift").unwrap_or(0.0),
        inhibited: flag("inhibited"),
    })
}

/// `TriggL`, `TriggJ`, `TriggC`: the move, then each event's output set
/// when the robot passes its point.
pub(crate) fn trigg_move(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let mut events = Vec::new();
    for p in ["Trigg_1", "T2", "T3", "T4", "T5", "T6", "T7", "T8"] {
        let Some(v) = cx.opt(a, p)? else {
            continue;
        };
        match event_of(&v) {
            Some(e) => events.push(e),
            None => {
                return invalid(format!(
                    "{}: {p} is not set up (TriggIO, TriggEquip or TriggInt first)",
                    a.name
                ));
            }
        }
    }
    let index = cx.robot_index(a)?;
    let tool = cx.tool(a, "Tool")?;
    let tcp = |cx: &mut Cx<'_>| {
        cx.ask_robot(a, index, |r| r.robtarget(&tool, &WObj::default()))
            .map(|t| t.pose.trans)
    };
    let from = tcp(cx)?;
    let start = cx.now().max(super::motion::motion_end(cx));
    let done = super::motion::do_move_at(cx, a, "ToPoint", None)?;
    let end = super::motion::motion_end(cx).max(start);
    let to = tcp(cx)?;
    let length: f64 = (0..3)
        .map(|i| (to[i] - from[i]).powi(2))
        .sum::<f64>()
        .sqrt();
    let duration = end - start;
    for e in events.into_iter().filter(|e| !e.inhibited) {
        let at = if e.time {
            if e.start {
                start + e.distance
            } else {
                end - e.distance
            }
        } else {
            let fraction = if length > 0.0 {
                (e.distance / length).clamp(0.0, 1.0)
            } else {
                0.0
            };
            if e.start {
                start + fraction * duration
            } else {
                end - fraction * duration
            }
        };
        let delay = at + e.shift - cx.now();
        if e.signal.is_empty() {
            // A single timer due then: the trap runs as the robot passes.
            let now = cx.now();
            let mark = crate::machine::PathMark::now(&cx.sh.paths, index);
            cx.m.interrupts
                .add_path_timer(e.value as i32, now, delay.max(0.0), mark);
        } else {
            cx.sh.set_signal_on_path(index, &e.signal, e.value, delay);
        }
    }
    Ok(done)
}
