//! Search moves: `SearchL`, `SearchJ`, `SearchC` move the robot as the
//! other moves do ([`super::motion`]) while a wait watches the search
//! signal ([`crate::machine::SearchWait`]).

use super::motion::{do_move, motion_end, robtarget_value};
use super::{Args, Cx, Done};
use crate::machine::{
    FaultKind, R, SearchWait, SignalTest, Timeout, Wait, WaitKind, fault, named_error,
};

/// `SearchL`, `SearchJ`, `SearchC`: the robot moves toward `ToPoint`
/// while the search watches its signal: by default for a positive flank
/// (`ERR_SIGSUPSEARCH` when the signal is 1 already), `\NegFlank`,
/// `\Flanks` (either change), `\HighLevel`/`\LowLevel` (the level, at
/// once). At the hit, `SearchPoint` gets `ToPoint` with the TCP where the
/// straight path from the start is then (a `SearchJ`'s or `SearchC`'s
/// path is taken straight too); `\Stop`, `\PStop`, `\SStop` end the
/// move there (the arm stands at the hit, without a braking distance),
/// otherwise the robot goes on to `ToPoint`. No hit by the move's end:
/// `ERR_WHLSEARCH`. A move that takes no time (no modelled robot) hits
/// when the signal has the searched value as it arrives. Not simulated:
/// `\Sup`'s error on a second hit, a `PERS bool` in place of the signal.
pub(crate) fn search(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = cx.req(a, "Signal")?;
    if !crate::machine::is_signal(&s) {
        return fault(FaultKind::Unsupported(format!(
            "{} on a PERS bool (only a signal is simulated)",
            a.name
        )));
    }
    let (signal, _) = cx.m.signal_of(cx.sh, &s)?;
    let before = cx.sh.io.read(&signal).unwrap_or(0.0);
    let (wanted, edge) = if a.given("HighLevel") {
        (1.0, false)
    } else if a.given("LowLevel") {
        (0.0, false)
    } else if a.given("NegFlank") {
        (0.0, true)
    } else if a.given("Flanks") {
        (if before == 0.0 { 1.0 } else { 0.0 }, true)
    } else {
        (1.0, true)
    };
    let index = cx.robot_index(a)?;
    let tool = cx.tool(a, "Tool")?;
    let wobj = cx.wobj(a)?;
    let from = match cx.sh.robots.get(index).and_then(Option::as_ref) {
        Some(robot) => robot.robtarget(&tool, &wobj).ok(),
        None => None,
    };
    let timed = cx
        .sh
        .robots
        .get(index)
        .and_then(Option::as_ref)
        .is_some_and(|r| r.moves_take_time());
    if edge && before == wanted && timed {
        return fault(named_error(
            &cx.m.prog,
            "ERR_SIGSUPSEARCH",
            format!(
                "{}: {} was {} already when the search started",
                a.name,
                cx.arg_name(a, "Signal").unwrap_or_else(|| signal.clone()),
                crate::world::num_text(before)
            ),
        ));
    }
    let stop = ["Stop", "PStop", "SStop"].iter().any(|s| a.given(s));
    if timed
        && !edge
        && before == wanted
        && let Some(here) = &from
    {
        // The level holds already: the hit is where the robot stands.
        let point = cx.place_arg(a, "SearchPoint")?;
        cx.store(&point, robtarget_value(here)?)?;
        if stop {
            return Ok(Done::Next);
        }
        return do_move(cx, a, "ToPoint");
    }
    let start = cx.now().max(motion_end(cx));
    do_move(cx, a, "ToPoint")?;
    let end = motion_end(cx).max(start);
    let to = cx.req(a, "ToPoint")?;
    let point = cx.place_arg(a, "SearchPoint")?;
    let none = format!("{}: the search signal never did as asked", a.name);
    if end <= cx.now() {
        // No time to watch: the signal as the robot arrives.
        if before != wanted {
            return fault(named_error(&cx.m.prog, "ERR_WHLSEARCH", none));
        }
        cx.store(&point, to)?;
        return Ok(Done::Next);
    }
    let target = cx.robtarget(&to)?;
    let from = from.map_or(target.pose.trans, |t| t.pose.trans);
    Ok(Done::Wait(Box::new(Wait {
        kind: WaitKind::Search(Box::new(SearchWait {
            signal,
            test: SignalTest::Equal(wanted),
            start,
            end,
            from,
            to,
            point,
            stop,
            robot: index,
            target,
            tool,
            wobj,
        })),
        deadline: Some(end),
        on_timeout: Timeout::Error("ERR_WHLSEARCH", none),
        what: format!("{} (searching)", a.name),
    })))
}
