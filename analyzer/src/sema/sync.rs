//! Where a routine's task moves in synchronised mode (MultiMove): between
//! `SyncMoveOn` and `SyncMoveOff` the moves of the listed tasks run
//! together. A forward walk of the routine's lowered body
//! ([`crate::body`]) follows, on each path, whether the task is
//! synchronised; the MultiMove rules read the result.
//!
//! The walk knows only the routine: at its start the mode is unknown (the
//! caller may have turned it on), and a call of a routine of the task that
//! itself turns the mode on or off, or a call by late binding, makes it
//! unknown again. A routine with `GOTO` is not followed. Error handlers are
//! not walked; `RAISE` and `EXIT` end a path without a finding.

use std::collections::BTreeSet;
use std::ops::Range;

use crate::body::{ArgValue, Body, Call, Callee, Stmt, StmtKind};
use crate::names::same;

/// The mode on the paths that reach a point: each is possible.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
struct Mode {
    /// Not known (the routine's start, after a call that may change it).
    unknown: bool,
    /// Not synchronised: after `SyncMoveOff` or `SyncMoveUndo`.
    off: bool,
    /// Synchronised by these `SyncMoveOn`s (indexes into [`SyncFlow::ons`]).
    on: BTreeSet<usize>,
}

impl Mode {
    fn join(&mut self, other: &Mode) {
        self.unknown |= other.unknown;
        self.off |= other.off;
        self.on.extend(other.on.iter().copied());
    }

    /// Synchronised on every path.
    fn surely_on(&self) -> bool {
        !self.unknown && !self.off && !self.on.is_empty()
    }

    fn unknown() -> Mode {
        Mode {
            unknown: true,
            ..Mode::default()
        }
    }
}

/// A move of a synchronised section.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct SyncedMove {
    /// The instruction's name as written, and its range.
    pub name: String,
    pub range: Range<usize>,
    /// Whether it has an `\ID` argument.
    pub has_id: bool,
    /// The `SyncMoveOn` before it.
    pub on: Range<usize>,
}

/// What the MultiMove instructions of one routine do on its paths.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct SyncFlow {
    /// Each `SyncMoveOn`: the range of its name.
    pub ons: Vec<Range<usize>>,
    /// Whether the routine turns the mode off itself (`SyncMoveOff`).
    pub turns_off: bool,
    /// A `SyncMoveOn` reached on a path that is synchronised already, with
    /// the `SyncMoveOn` that made it so.
    pub on_again: Vec<(Range<usize>, Range<usize>)>,
    /// A `SyncMoveOff` reached on a path that an earlier `SyncMoveOff` of
    /// the routine already ended.
    pub off_again: Vec<Range<usize>>,
    /// `SyncMoveOn`s from which a path reaches the routine's end still
    /// synchronised.
    pub left_on: Vec<Range<usize>>,
    /// The moves made while the task is synchronised on every path.
    pub moves: Vec<SyncedMove>,
}

/// How the walk sees the calls of a routine.
pub(crate) trait CallKinds {
    /// Is this call the built-in instruction `name` (not a routine of the
    /// task that hides it)?
    fn is_builtin(&self, call: &Call, name: &str) -> bool;
    /// Is this call a move instruction (a built-in that takes `\ID`)?
    fn is_move(&self, call: &Call) -> bool;
    /// May this call change the mode (a routine of the task that uses
    /// `SyncMoveOn` or `SyncMoveOff`, or a call by late binding)?
    fn may_change_mode(&self, call: &Call) -> bool;
}

/// The synchronisation of `body`'s paths; `None` for a routine with
/// `GOTO`, whose paths are not followed.
pub(crate) fn flow(body: &Body, calls: &dyn CallKinds) -> Option<SyncFlow> {
    let mut has_goto = false;
    body.walk(&mut |s| has_goto |= matches!(s.kind, StmtKind::Goto(_)));
    if has_goto {
        return None;
    }
    let mut walk = Walk {
        calls,
        out: SyncFlow::default(),
        returns: Mode::default(),
    };
    let end = walk.list(&body.stmts, Mode::unknown());
    let mut end = end.unwrap_or_default();
    end.join(&walk.returns);
    let mut out = walk.out;
    out.left_on = end
        .on
        .iter()
        .filter_map(|&i| out.ons.get(i).cloned())
        .collect();
    out.on_again.sort_by_key(|(a, _)| a.start);
    out.on_again.dedup_by_key(|(a, _)| a.start);
    out.off_again.sort_by_key(|r| r.start);
    out.off_again.dedup();
    out.moves.sort_by_key(|m| m.range.start);
    out.moves.dedup_by_key(|m| m.range.start);
    Some(out)
}

struct Walk<'a> {
    calls: &'a dyn CallKinds,
    out: SyncFlow,
    /// The mode where `RETURN` leaves the routine.
    returns: Mode,
}

impl Walk<'_> {
    /// The mode after `list` entered in `mode`; `None` when no path gets
    /// through it (it returns, raises or exits on every path).
    fn list(&mut self, list: &[Stmt], mode: Mode) -> Option<Mode> {
        let mut mode = mode;
        for s in list {
            mode = self.stmt(s, mode)?;
        }
        Some(mode)
    }

    fn stmt(&mut self, s: &Stmt, mode: Mode) -> Option<Mode> {
        match &s.kind {
            StmtKind::Call(call) => Some(self.call(call, mode)),
            StmtKind::If {
                branches,
                otherwise,
                ..
            } => {
                let mut out: Option<Mode> = None;
                for b in branches {
                    join_into(&mut out, self.list(&b.body, mode.clone()));
                }
                match otherwise {
                    Some(o) => join_into(&mut out, self.list(o, mode)),
                    None => join_into(&mut out, Some(mode)),
                }
                out
            }
            StmtKind::Test { cases, default, .. } => {
                let mut out: Option<Mode> = None;
                for c in cases {
                    join_into(&mut out, self.list(&c.body, mode.clone()));
                }
                match default {
                    Some(d) => join_into(&mut out, self.list(d, mode)),
                    None => join_into(&mut out, Some(mode)),
                }
                out
            }
            StmtKind::For { body, .. } | StmtKind::While { body, .. } => {
                // Zero or more rounds: until the modes stop growing (the
                // set of modes is finite).
                let mut at = mode;
                loop {
                    let mut next = at.clone();
                    if let Some(after) = self.list(body, at.clone()) {
                        next.join(&after);
                    }
                    if next == at {
                        return Some(at);
                    }
                    at = next;
                }
            }
            StmtKind::Return(_) => {
                self.returns.join(&mode);
                None
            }
            StmtKind::Raise(_) | StmtKind::Exit => None,
            // A statement that could not be read may be anything.
            StmtKind::Invalid => Some(Mode::unknown()),
            _ => Some(mode),
        }
    }

    fn call(&mut self, call: &Call, mode: Mode) -> Mode {
        let builtin = |name: &str| self.calls.is_builtin(call, name);
        if builtin("SyncMoveOn") {
            let here = call.callee_range.clone();
            if let Some(&first) = mode.on.iter().next() {
                let earlier = self.out.ons.get(first).cloned().unwrap_or_default();
                self.out.on_again.push((here.clone(), earlier));
            }
            let index = match self.out.ons.iter().position(|r| *r == here) {
                Some(i) => i,
                None => {
                    self.out.ons.push(here);
                    self.out.ons.len() - 1
                }
            };
            return Mode {
                on: BTreeSet::from([index]),
                ..Mode::default()
            };
        }
        if builtin("SyncMoveOff") || builtin("SyncMoveUndo") {
            if builtin("SyncMoveOff") {
                self.out.turns_off = true;
                if mode.off {
                    self.out.off_again.push(call.callee_range.clone());
                }
            }
            return Mode {
                off: true,
                ..Mode::default()
            };
        }
        if self.calls.is_move(call) {
            if mode.surely_on() {
                let on = mode
                    .on
                    .iter()
                    .next()
                    .and_then(|&i| self.out.ons.get(i).cloned())
                    .unwrap_or_default();
                self.out.moves.push(SyncedMove {
                    name: callee_name(call).to_owned(),
                    range: call.callee_range.clone(),
                    has_id: has_arg(call, "ID"),
                    on,
                });
            }
            return mode;
        }
        if self.calls.may_change_mode(call) {
            return Mode::unknown();
        }
        mode
    }
}

fn join_into(out: &mut Option<Mode>, m: Option<Mode>) {
    match (out.as_mut(), m) {
        (Some(o), Some(m)) => o.join(&m),
        (None, Some(m)) => *out = Some(m),
        (_, None) => {}
    }
}

/// The name a call is written with (empty for late binding).
pub(crate) fn callee_name(call: &Call) -> &str {
    match &call.callee {
        Callee::Name(n) => n,
        Callee::Late(_) => "",
    }
}

/// Does the call have the argument `name` (`\ID:=...`, `ID:=...`)?
pub(crate) fn has_arg(call: &Call, name: &str) -> bool {
    call.args
        .iter()
        .any(|a| a.name.as_deref().is_some_and(|n| same(n, name)) && a.value != ArgValue::Invalid)
}

/// A point where a task meets others: `SyncMoveOn` or `WaitSyncTask`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct SyncPoint {
    /// `SyncMoveOn` or `WaitSyncTask`.
    pub kind: &'static str,
    /// The `syncident` named, folded.
    pub ident: String,
    /// The `tasks` data named as the task list, folded.
    pub list: String,
    pub path: String,
    pub range: Range<usize>,
}

/// A straight run of statements from `SyncMoveOn` to `SyncMoveOff` (no
/// branch, loop or call of the task's routines between), with the moves
/// it makes with `\ID`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Section {
    /// The `syncident`s of its `SyncMoveOn` and `SyncMoveOff`, folded.
    pub on: String,
    pub off: String,
    pub moves: usize,
    pub path: String,
    /// The range of its `SyncMoveOn`'s name.
    pub range: Range<usize>,
}

/// What one task's modules say about synchronisation.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub(crate) struct TaskSyncs {
    pub points: Vec<SyncPoint>,
    pub sections: Vec<Section>,
    /// The `tasks` data of the task: folded name and the task names of its
    /// initial value, as written.
    pub lists: Vec<(String, Vec<String>)>,
    /// Every module of the task is here (see [`crate::task::Task::complete`]):
    /// a point it lacks is lacking, not in a module elsewhere.
    pub complete: bool,
}

impl TaskSyncs {
    /// The task names of the task list `list`, if its value is known.
    pub(crate) fn list(&self, list: &str) -> Option<&[String]> {
        self.lists
            .iter()
            .find(|(n, _)| n == list)
            .map(|(_, names)| names.as_slice())
    }
}

/// The tasks of a controller and how they meet.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub(crate) struct ControllerSyncs {
    /// Each task: its key, its names (folded: its folder's, and its
    /// `SYS.cfg` name), and its synchronisation.
    pub tasks: Vec<(String, Vec<String>, TaskSyncs)>,
}

impl ControllerSyncs {
    /// The task named `name` (in any letter case).
    pub(crate) fn named(&self, name: &str) -> Option<&(String, Vec<String>, TaskSyncs)> {
        self.tasks
            .iter()
            .find(|(_, names, _)| names.iter().any(|n| same(n, name)))
    }

    /// The other tasks of the task list `list` (seen from a task of the
    /// names `own`) that are here, with their names as the list writes them.
    pub(crate) fn partners<'a>(
        &'a self,
        own: &'a [String],
        list: &'a [String],
    ) -> impl Iterator<Item = (&'a String, &'a TaskSyncs)> + 'a {
        list.iter()
            .filter(|t| !own.iter().any(|n| same(n, t)))
            .filter_map(|t| Some((t, &self.named(t)?.2)))
    }

    /// The task of key `key`.
    pub(crate) fn of_key(&self, key: &str) -> Option<&(String, Vec<String>, TaskSyncs)> {
        self.tasks.iter().find(|(k, _, _)| k == key)
    }
}

/// Does the text name a MultiMove or synchronisation instruction (in any
/// letter case)? Only the routines that do are lowered to look for them.
pub(crate) fn mentions_sync(text: &str) -> bool {
    // Both words hold a `y`, rare in RAPID text: look only around each `y`
    // (this runs on the text of every routine).
    let bytes = text.as_bytes();
    let at = |start: usize, word: &str| {
        bytes
            .get(start..start + word.len())
            .is_some_and(|x| x.eq_ignore_ascii_case(word.as_bytes()))
    };
    bytes.iter().enumerate().any(|(i, c)| {
        (*c | 0x20) == b'y'
            && ((i >= 1 && at(i - 1, "syncmove")) || (i >= 5 && at(i - 5, "waitsynctask")))
    })
}

/// The synchronisation of the modules `units` of one task, read by name
/// (`SyncMoveOn`, `SyncMoveOff`, `WaitSyncTask`) from the routines that
/// mention them.
pub(crate) fn task_syncs<'u>(
    units: impl Iterator<Item = &'u std::sync::Arc<crate::task::Unit>>,
) -> TaskSyncs {
    use crate::names::fold;
    let mut out = TaskSyncs::default();
    let cat = crate::catalogue::base();
    let units: Vec<_> = units.collect();
    let user_routines: std::collections::HashSet<String> = units
        .iter()
        .flat_map(|u| u.items.modules.iter())
        .flat_map(|m| m.routines.iter().map(|r| fold(&r.name)))
        .collect();
    for unit in &units {
        for m in &unit.items.modules {
            for d in &m.data {
                if d.ty.as_ref().is_some_and(|t| same(&t.name, "tasks")) {
                    let value = d
                        .init
                        .clone()
                        .and_then(|r| unit.text.get(r))
                        .unwrap_or_default();
                    let names = crate::lex::string_literals(value)
                        .into_iter()
                        .map(|(_, s)| s.trim().to_owned())
                        .collect();
                    out.lists.push((fold(&d.name), names));
                }
            }
        }
        for body in unit.sync_bodies() {
            let is_user = |c: &Call| user_routines.contains(&fold(callee_name(c)));
            let builtin = |c: &Call, name: &str| same(callee_name(c), name) && !is_user(c);
            let mut lists: Vec<&[Stmt]> = Vec::new();
            all_lists(&body.stmts, &mut lists);
            for list in lists {
                for (i, s) in list.iter().enumerate() {
                    let StmtKind::Call(call) = &s.kind else {
                        continue;
                    };
                    let kind = ["SyncMoveOn", "WaitSyncTask"]
                        .into_iter()
                        .find(|k| builtin(call, k));
                    let Some(kind) = kind else { continue };
                    let names = positional_names(call);
                    let (Some(ident), Some(list_name)) = (names.first(), names.get(1)) else {
                        continue;
                    };
                    out.points.push(SyncPoint {
                        kind,
                        ident: fold(ident),
                        list: fold(list_name),
                        path: unit.path.clone(),
                        range: call.callee_range.clone(),
                    });
                    if kind != "SyncMoveOn" {
                        continue;
                    }
                    // The straight run to SyncMoveOff.
                    let mut moves = 0;
                    for next in &list[i + 1..] {
                        let StmtKind::Call(c) = &next.kind else {
                            if matches!(next.kind, StmtKind::Assign { .. }) {
                                continue;
                            }
                            break;
                        };
                        if builtin(c, "SyncMoveOff") {
                            if let Some(off) = positional_names(c).first() {
                                out.sections.push(Section {
                                    on: fold(ident),
                                    off: fold(off),
                                    moves,
                                    path: unit.path.clone(),
                                    range: call.callee_range.clone(),
                                });
                            }
                            break;
                        }
                        if is_user(c) || cat.instruction(callee_name(c)).is_none() {
                            break;
                        }
                        moves += usize::from(has_arg(c, "ID"));
                    }
                }
            }
        }
    }
    out
}

/// `list` and every statement list its statements hold.
fn all_lists<'a>(list: &'a [Stmt], out: &mut Vec<&'a [Stmt]>) {
    out.push(list);
    for s in list {
        for inner in s.kind.lists() {
            all_lists(inner, out);
        }
    }
}

/// The names given as a call's positional arguments, in order (`None`
/// for one that is not a plain name).
fn positional_names(call: &Call) -> Vec<String> {
    call.args
        .iter()
        .filter(|a| a.name.is_none() && !a.optional)
        .map_while(|a| match &a.value {
            ArgValue::Expr(rapid_evaluator::Expr::Name(n)) => Some(n.clone()),
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::task::Unit;

    /// Built-ins by name: everything but `user_*` routines.
    struct ByName;

    impl CallKinds for ByName {
        fn is_builtin(&self, call: &Call, name: &str) -> bool {
            same(callee_name(call), name)
        }
        fn is_move(&self, call: &Call) -> bool {
            ["MoveL", "MoveJ", "MoveAbsJ"]
                .iter()
                .any(|m| same(callee_name(call), m))
        }
        fn may_change_mode(&self, call: &Call) -> bool {
            callee_name(call).starts_with("user_sync")
        }
    }

    /// A flow with its places as line numbers.
    #[derive(Debug, Default)]
    struct Lines {
        left_on: Vec<usize>,
        on_again: Vec<(usize, usize)>,
        off_again: Vec<usize>,
        /// Line, has `\ID`, line of its `SyncMoveOn`.
        moves: Vec<(usize, bool, usize)>,
    }

    fn flow_of(body: &str) -> Lines {
        let text = format!("MODULE M\n  PROC p()\n{body}\n  ENDPROC\nENDMODULE\n");
        let unit = Unit::new("m.mod".into(), text.clone(), None);
        let bodies = crate::body::routine_bodies(&unit);
        let f = flow(&bodies[0], &ByName).expect("no GOTO");
        let line = |r: &Range<usize>| text[..r.start].lines().count();
        Lines {
            left_on: f.left_on.iter().map(line).collect(),
            on_again: f.on_again.iter().map(|(a, b)| (line(a), line(b))).collect(),
            off_again: f.off_again.iter().map(line).collect(),
            moves: f
                .moves
                .iter()
                .map(|m| (line(&m.range), m.has_id, line(&m.on)))
                .collect(),
        }
    }

    #[test]
    fn paired_on_every_path() {
        let f = flow_of(
            "    SyncMoveOn s1, all;\n    MoveL p, v, fine, t;\n    MoveL p \\ID:=10, v, fine, t;\n    SyncMoveOff s2;",
        );
        assert!(f.on_again.is_empty() && f.off_again.is_empty() && f.left_on.is_empty());
        assert_eq!(f.moves, [(4, false, 3), (5, true, 3)]);
    }

    #[test]
    fn a_branch_without_sync_move_off_leaves_the_routine_synchronised() {
        let f = flow_of(
            "    SyncMoveOn s1, all;\n    IF x THEN\n      SyncMoveOff s2;\n    ENDIF\n    MoveL p, v, fine, t;",
        );
        assert_eq!(f.left_on, [3]);
        // synchronised on one path only: not every move is known to be
        assert!(f.moves.is_empty());
        let f = flow_of(
            "    SyncMoveOn s1, all;\n    IF x THEN\n      SyncMoveOff s2;\n    ENDIF\n    SyncMoveOn s3, all;\n    SyncMoveOff s4;",
        );
        assert_eq!(f.on_again, [(7, 3)]);
    }

    #[test]
    fn loops_calls_and_returns() {
        // on and off in each round
        let f = flow_of(
            "    WHILE TRUE DO\n      SyncMoveOn s1, all;\n      MoveL p \\ID:=1, v, fine, t;\n      SyncMoveOff s2;\n    ENDWHILE",
        );
        assert!(f.on_again.is_empty() && f.left_on.is_empty());
        // a RETURN in synchronised mode
        let f = flow_of("    SyncMoveOn s1, all;\n    IF x RETURN;\n    SyncMoveOff s2;");
        assert_eq!(f.left_on, [3]);
        // a routine of the task that may turn it off
        let f = flow_of("    SyncMoveOn s1, all;\n    user_sync_off;\n    MoveL p, v, fine, t;");
        assert!(f.moves.is_empty());
        // twice off
        let f = flow_of("    SyncMoveOff s1;\n    SyncMoveOff s2;");
        assert_eq!(f.off_again, [4]);
        // the start is unknown: no finding
        let f = flow_of("    SyncMoveOff s1;\n    MoveL p, v, fine, t;");
        assert!(f.off_again.is_empty() && f.moves.is_empty());
    }

    #[test]
    fn mentions_sync_in_any_case_anywhere() {
        for text in [
            "SyncMoveOn s1, all;",
            "syncmoveoff s2;",
            "  WAITSYNCTASK s3, all;",
            "x := 1; WaitSyncTask",
            "PROC p()\n  SYNCMOVEUNDO;\nENDPROC",
        ] {
            assert!(mentions_sync(text), "{text}");
        }
        for text in [
            "",
            "y",
            "yyyy",
            "Sync",
            "MoveSync",
            "WaitSync",
            "synctask",
            "WaitTime 1;",
        ] {
            assert!(!mentions_sync(text), "{text}");
        }
    }
}
