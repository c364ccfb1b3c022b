use crate::body::{ArgValue, Body, Call, Stmt, StmtKind};
use crate::check::Cx;
use crate::diagnostic::{Diagnostic, Related};
use crate::names::same;
use crate::sema::sync::{CallKinds, callee_name, has_arg};
use rapid_evaluator::Expr;

crate::declare_rule! {
    /// A fly-by point just before `SyncMoveOn`, `SyncMoveOff` or `WaitSyncTask \InPos`.
    ///
    /// ### What it checks
    /// The tasks of a MultiMove system start and end synchronised movement, and
    /// meet at `WaitSyncTask \InPos`, standing still: the move just before such
    /// an instruction (in the same statement list) ends in a stop point (`fine`,
    /// or a move with `\Inpos`). A move whose zone is one of RobotWare's fly-by
    /// zones (`z0` to `z200`) is reported; zones of the program's own data are
    /// not judged.
    ///
    /// ### Why
    /// With a fly-by point the robot does not stop where the tasks meet: the
    /// controller turns it into a stop point with a warning, or the tasks meet
    /// at different positions than programmed.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v1000, z50, tool1;   ! z50: should be fine
    /// SyncMoveOn sync1, all_tasks;
    /// ```
    pub static RULE = ("W502", "sync-without-stop-point", Warning);
}

/// Checks the move before each synchronisation point of `body`.
pub(crate) fn check(cx: &mut Cx<'_>, body: &Body, calls: &crate::check::multimove::TaskCalls<'_>) {
    let mut found = Vec::new();
    visit(&body.stmts, &mut |list| {
        for pair in list.windows(2) {
            let [before, here] = pair else { continue };
            let (StmtKind::Call(prev), StmtKind::Call(sync)) = (&before.kind, &here.kind) else {
                continue;
            };
            let point = ["SyncMoveOn", "SyncMoveOff"]
                .into_iter()
                .find(|n| calls.is_builtin(sync, n))
                .or_else(|| {
                    (calls.is_builtin(sync, "WaitSyncTask") && has_arg(sync, "InPos"))
                        .then_some("WaitSyncTask \\InPos")
                });
            let Some(point) = point else { continue };
            if !calls.is_move(prev) || has_arg(prev, "Inpos") {
                continue;
            }
            if let Some((zone, range)) = fly_by_zone(cx, calls, prev) {
                found.push((
                    point,
                    sync.callee_range.clone(),
                    callee_name(prev).to_owned(),
                    zone,
                    range,
                ));
            }
        }
    });
    for (point, at, mv, zone, zone_range) in found {
        let d = Diagnostic::new(
            &RULE,
            at,
            format!("the `{mv}` before {point} ends in the fly-by zone `{zone}`: the tasks meet at a stop point (`fine`)"),
        )
        .with_related(Related {
            file: None,
            range: zone_range,
            message: format!("`{zone}` is a fly-by point"),
        });
        cx.report_with(d);
    }
}

/// Calls `f` with every statement list of `list` (itself and the ones its
/// statements hold).
fn visit(list: &[Stmt], f: &mut impl FnMut(&[Stmt])) {
    f(list);
    for s in list {
        for inner in s.kind.lists() {
            visit(inner, f);
        }
    }
}

/// The zone of a move when it is one of RobotWare's fly-by zones (a
/// predefined `zonedata` whose `finep` is FALSE, not hidden by the
/// program's data), with the argument's range.
fn fly_by_zone(
    cx: &Cx<'_>,
    calls: &crate::check::multimove::TaskCalls<'_>,
    call: &Call,
) -> Option<(String, std::ops::Range<usize>)> {
    let routine = calls.builtin(call)?;
    // Only moves whose parameters are documented: one whose parameters
    // come from loaded code (the Arc instructions) is not checked.
    if !routine.signature_known {
        return None;
    }
    // The Zone argument: by name, or the positional argument at Zone's
    // place among the required parameters.
    let required: Vec<&str> = routine
        .params
        .iter()
        .filter(|p| !p.optional && !p.switch)
        .map(|p| p.name.as_str())
        .collect();
    let at = required.iter().position(|p| same(p, "Zone"))?;
    let arg = call
        .args
        .iter()
        .find(|a| a.name.as_deref().is_some_and(|n| same(n, "Zone")))
        .or_else(|| call.args.iter().filter(|a| a.name.is_none()).nth(at))?;
    let ArgValue::Expr(Expr::Name(zone)) = &arg.value else {
        return None;
    };
    let key = crate::names::fold(zone);
    if cx.task.globals.contains_key(&key) || cx.task.locals.contains_key(&key) {
        return None;
    }
    let datum = cx.task.catalogue.datum(zone)?;
    let fly_by = same(&datum.ty, "zonedata")
        && datum.value.as_deref().is_some_and(|v| {
            v.trim_start_matches(['[', ' '])
                .to_ascii_uppercase()
                .starts_with("FALSE")
        });
    fly_by.then(|| (zone.clone(), arg.range.clone()))
}
