//! Waits: a frame whose instruction waits keeps what it waits for as
//! data ([`Wait`]); the task is blocked until it holds (or times out), and
//! the trap routines of interrupts still run meanwhile, on top of the
//! waiting frame.

use rapid_evaluator::Value;

use super::{Boundary, FaultKind, Machine, Place, R, fault, named_error};
use crate::code::Pc;
use crate::controller::Shared;

/// What a frame waits for.
#[derive(Clone, Debug)]
pub(crate) struct Wait {
    pub kind: WaitKind,
    /// `\MaxTime`, `\TimeOut`: when the wait gives up.
    pub deadline: Option<f64>,
    pub on_timeout: Timeout,
    /// The instruction and what it waits for, for a deadlock's report.
    pub what: String,
}

/// A robot's path: how many `StorePath` deep its moves are made, and the
/// move `StopMove` stopped.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct PathState {
    pub level: u32,
    pub stopped: Option<Stopped>,
    /// The seconds each path level has stood under `StopMove`s that are
    /// over, and how many of its stopped moves `ClearPath` dropped: what
    /// the events of a path ([`PathMark`]) are measured by (levels past
    /// the last share its entry).
    held_for: [f64; LEVELS],
    cleared: [u32; LEVELS],
}

/// The path levels [`PathState`] keeps apart (a trap's `StorePath` makes
/// the second).
const LEVELS: usize = 4;

/// The entry of path level `level` in [`PathState`]'s per-level arrays.
fn level_slot(level: u32) -> usize {
    (level as usize).min(LEVELS - 1)
}

/// Where an event of a robot's path (a `TriggIO` output, `MoveLDO`'s
/// signal, a world zone's output, a `TriggInt` interrupt) stands: the
/// robot, the path level its move was made on, and that level's
/// [`PathState::held_for`] and [`PathState::cleared`] when the event was
/// planned. While a `StopMove` holds that level the event waits, then it
/// comes as much later as the level stood; a `ClearPath` of the level
/// drops it. (A trap's moves on the level `StorePath` opened are not held
/// by the stop of the level below.)
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PathMark {
    robot: usize,
    level: u32,
    held_for: f64,
    cleared: u32,
}

impl PathMark {
    /// The mark of an event of the move robot `robot` makes now.
    pub(crate) fn now(paths: &[PathState], robot: usize) -> PathMark {
        let path = paths.get(robot).copied().unwrap_or_default();
        let slot = level_slot(path.level);
        PathMark {
            robot,
            level: path.level,
            held_for: path.held_for[slot],
            cleared: path.cleared[slot],
        }
    }

    /// Its move was dropped (`ClearPath`): the event never comes.
    pub(crate) fn dropped(&self, paths: &[PathState]) -> bool {
        paths
            .get(self.robot)
            .is_some_and(|p| p.cleared[level_slot(self.level)] != self.cleared)
    }

    /// When an event planned for `at` comes: `None` while its level
    /// stands, or for ever once its move was dropped.
    pub(crate) fn due(&self, at: f64, paths: &[PathState]) -> Option<f64> {
        let path = paths.get(self.robot).copied().unwrap_or_default();
        if path.holds(self.level) || self.dropped(paths) {
            return None;
        }
        Some(at + (path.held_for[level_slot(self.level)] - self.held_for))
    }
}

/// When an event planned for `at` comes, on a path (`Some` mark) or not.
pub(crate) fn due_on(at: f64, mark: Option<&PathMark>, paths: &[PathState]) -> Option<f64> {
    match mark {
        Some(m) => m.due(at, paths),
        None => Some(at),
    }
}

/// A move stopped by `StopMove`: the path level it was made on, and the
/// seconds of it left (0 when none was under way, or after `ClearPath`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stopped {
    pub level: u32,
    pub left: f64,
    /// When it stopped, the arm's joints then, and the trace's record of
    /// the move (split in two when it goes on).
    pub at: f64,
    pub joints: Option<[f64; 6]>,
    pub record: Option<usize>,
}

impl PathState {
    /// Do the moves of path level `level` stand (stopped, not started
    /// again)?
    pub(crate) fn holds(&self, level: u32) -> bool {
        self.stopped.is_some_and(|s| s.level == level)
    }

    /// A stop of path level `level` is over after `seconds`: its events
    /// come that much later.
    pub(crate) fn held(&mut self, level: u32, seconds: f64) {
        self.held_for[level_slot(level)] += seconds;
    }

    /// `ClearPath` dropped the stopped move of level `level`, and its
    /// events.
    pub(crate) fn clear(&mut self, level: u32) {
        self.cleared[level_slot(level)] += 1;
    }
}

impl Wait {
    /// Until the task's robot `robot` ends the moves of path level
    /// `level` (a move, `WaitRob`): while `StopMove` holds them, the wait
    /// goes on.
    pub(crate) fn motion(robot: usize, level: u32, what: String) -> Wait {
        Wait {
            kind: WaitKind::Move { robot, level },
            deadline: None,
            on_timeout: Timeout::Error("ERR_WAIT_MAXTIME", String::new()),
            what,
        }
    }

    /// Until the clock reaches `until` (no deadline of its own).
    pub(crate) fn until(until: f64, what: String) -> Wait {
        Wait {
            kind: WaitKind::Time(until),
            deadline: None,
            on_timeout: Timeout::Error("ERR_WAIT_MAXTIME", String::new()),
            what,
        }
    }
}

#[derive(Clone, Debug)]
pub(crate) enum WaitKind {
    /// Until the clock reaches this time (`WaitTime`, the rest of a
    /// flying search's move).
    Time(f64),
    /// Until the robot (its entry in [`Shared::motion_until`]) ends its
    /// moves of path level `level`, unless `StopMove` holds them.
    Move { robot: usize, level: u32 },
    /// Until the signal compares with the value as asked.
    Signal { name: String, test: SignalTest },
    /// A `WaitUntil` condition is checked again at this time (from
    /// `again`); `clock`: the condition read the clock; `steps`: the
    /// statements the controller had run when it was found false.
    Poll {
        next: f64,
        again: Pc,
        clock: bool,
        steps: u64,
    },
    /// At a rendezvous of tasks (`WaitSyncTask`, `SyncMoveOn`,
    /// `SyncMoveOff`): its key in [`crate::controller::Sync`] and the
    /// round this task arrived in.
    Sync {
        key: String,
        round: u64,
        sync_move: Option<bool>,
    },
    /// Until the task's robot stands still (at `at`, the end of its
    /// motion), then at the rendezvous `key` of the tasks `numbers`
    /// (`WaitSyncTask \InPos`).
    InPos {
        at: f64,
        key: String,
        numbers: Vec<usize>,
        names: Vec<String>,
    },
    /// Until the bool at the place is `FALSE`, which is then set
    /// (`WaitTestAndSet`).
    Semaphore(Place),
    /// Until the deadline, which fails the wait (a socket nobody
    /// answers).
    Never,
    /// Until the operator answers, or a break signal breaks the dialog
    /// (`TPReadFK`, `UIMessageBox`...).
    Operator(Box<OperatorWait>),
    /// A search move (`SearchL`...) until its signal does as asked (then
    /// the hit is stored), or the move's end (the wait's deadline).
    Search(Box<SearchWait>),
    /// Until the task's message queue holds a message (of the data type
    /// `wanted`, folded, when given), which is then stored at the place
    /// (`RMQReadWait`, `RMQSendWait`).
    Message { to: Place, wanted: Option<String> },
}

/// A search move under way.
#[derive(Clone, Debug)]
pub(crate) struct SearchWait {
    pub signal: String,
    pub test: SignalTest,
    /// When the move starts and ends (simulated seconds).
    pub start: f64,
    pub end: f64,
    /// The TCP where the move starts, and `ToPoint`, in the move's work
    /// object: the hit lies between them, by the time it comes.
    pub from: [f64; 3],
    pub to: Value,
    /// `SearchPoint`.
    pub point: Place,
    /// `\Stop`, `\PStop`, `\SStop`: the move ends at the hit.
    pub stop: bool,
    /// The task's robot (its entry in [`Shared::motion_until`]).
    pub robot: usize,
    /// `ToPoint`, the tool and the work object, to stop the arm at the hit.
    pub target: crate::world::RobTarget,
    pub tool: crate::world::Tool,
    pub wobj: crate::world::WObj,
}

impl SearchWait {
    /// Where the straight path from the start to `ToPoint` is at time `t`.
    fn hit_trans(&self, t: f64) -> [f64; 3] {
        let span = self.end - self.start;
        let f = if span > 0.0 {
            ((t - self.start) / span).clamp(0.0, 1.0)
        } else {
            1.0
        };
        let to = self.target.pose.trans;
        std::array::from_fn(|i| self.from[i] + f * (to[i] - self.from[i]))
    }

    /// `ToPoint` with the TCP where the straight path from the start is
    /// at time `t`.
    fn hit_at(&self, t: f64) -> Value {
        let [x, y, z] = self.hit_trans(t);
        let mut v = self.to.clone();
        if v.field("trans").is_some() {
            let pos = Value::pos(x as f32, y as f32, z as f32);
            if let Value::Record { fields, .. } = &mut v
                && let Some((_, slot)) = fields.iter_mut().find(|(n, _)| n == "trans")
            {
                *slot = pos;
            }
        }
        v
    }
}

/// A question to the operator that waits for its answer.
#[derive(Clone, Debug)]
pub(crate) struct OperatorWait {
    /// When the answer comes (`None`: it never does).
    pub at: Option<f64>,
    /// The answer's value.
    pub answer: Value,
    /// Where the answer goes; `None`: it is the result of the function
    /// that asked.
    pub to: Option<Place>,
    /// A second answer stored with the first (`UIListView`'s `\Result`:
    /// the button pressed after choosing an item).
    pub also: Option<(Place, Value)>,
    /// `\DIBreak`, `\DOBreak`: the signal, the value that breaks, and
    /// the error.
    pub breaks: Vec<(String, SignalTest, &'static str)>,
    /// `\BreakFlag`: gets the error instead of a raise.
    pub flag: Option<Place>,
    /// A function's result after a break or a time-out with a flag.
    pub fallback: Value,
}

#[derive(Clone, Copy, Debug)]
pub(crate) enum SignalTest {
    Equal(f64),
    Below(f64),
    Above(f64),
}

impl SignalTest {
    pub(crate) fn holds(self, v: f64) -> bool {
        match self {
            SignalTest::Equal(x) => v == x,
            SignalTest::Below(x) => v < x,
            SignalTest::Above(x) => v > x,
        }
    }
}

/// What happens when a wait times out.
#[derive(Clone, Debug)]
pub(crate) enum Timeout {
    /// The error (`ERR_WAIT_MAXTIME`...), with a message.
    Error(&'static str, String),
    /// `\TimeFlag`: the flag is set and the program goes on.
    Flag(Place),
}

/// Does a message of the type `wanted` (folded; any when `None`) come?
fn accepts(wanted: Option<&str>, m: &crate::rmq::Message) -> bool {
    wanted.is_none_or(|w| m.key == w)
}

/// When the moves of path level `level` of robot `robot` end: never while
/// `StopMove` holds them.
fn motion_end(sh: &Shared, robot: usize, level: u32) -> f64 {
    if sh.paths.get(robot).is_some_and(|p| p.holds(level)) {
        return f64::INFINITY;
    }
    sh.motion_until.get(robot).copied().unwrap_or(0.0)
}

/// Where a blocked task stands.
pub(crate) enum Blocked {
    /// It waits.
    Waiting,
    /// It can run.
    Ready,
}

impl Machine {
    /// Checks the innermost frame's wait: still waiting, or done (then the
    /// frame goes on; a timeout may fail it).
    pub(crate) fn check_wait(&mut self, sh: &mut Shared) -> R<Blocked> {
        let Some(w) = self.frames.last().and_then(|f| f.wait.clone()) else {
            return Ok(Blocked::Ready);
        };
        let now = sh.clock;
        let done = match &w.kind {
            WaitKind::Time(t) => now >= *t,
            WaitKind::Move { robot, level } => motion_end(sh, *robot, *level) <= now,
            WaitKind::Signal { name, test } => sh.io.read(name).is_some_and(|v| test.holds(v)),
            WaitKind::Poll { next, .. } => now >= *next,
            WaitKind::Sync { key, round, .. } => sh.sync.released(key, *round),
            WaitKind::Semaphore(p) => matches!(self.get(sh, p), Some(Value::Bool(false))),
            WaitKind::InPos {
                at,
                key,
                numbers,
                names,
            } => {
                if now < *at {
                    false
                } else {
                    // In position: the task arrives at the rendezvous now.
                    let (round, complete) = sh.sync.arrive(key, self.number, numbers, names);
                    if !complete {
                        if let Some(f) = self.frames.last_mut()
                            && let Some(wait) = f.wait.as_mut()
                        {
                            wait.kind = WaitKind::Sync {
                                key: key.clone(),
                                round,
                                sync_move: None,
                            };
                        }
                        return self.check_timeout(sh);
                    }
                    true
                }
            }
            WaitKind::Never => false,
            WaitKind::Message { wanted, .. } => {
                let own = self.number.saturating_sub(1);
                sh.rmq.has(own, |m| accepts(wanted.as_deref(), m))
            }
            WaitKind::Search(search) => sh
                .io
                .read(&search.signal)
                .is_some_and(|v| search.test.holds(v)),
            WaitKind::Operator(o) => {
                let broken = o
                    .breaks
                    .iter()
                    .find(|(s, test, _)| sh.io.read(s).is_some_and(|v| test.holds(v)));
                if let Some((signal, _, error)) = broken {
                    let message = format!("{}: {signal} broke the dialog", w.what);
                    return self.operator_break(sh, o, error, message);
                }
                let timed_out = w.deadline.is_some_and(|d| now >= d);
                if timed_out && o.at.is_none_or(|a| a > now) {
                    let message = format!("{}: no answer within \\MaxTime", w.what);
                    return self.operator_break(sh, o, "ERR_TP_MAXTIME", message);
                }
                o.at.is_some_and(|a| now >= a)
            }
        };
        if done {
            self.end_wait(sh, &w)?;
            // A flying search that hit waits on for the move's end.
            if self.frames.last().is_some_and(|f| f.wait.is_some()) {
                return Ok(Blocked::Waiting);
            }
            return Ok(Blocked::Ready);
        }
        self.check_timeout(sh)
    }

    /// The wait goes on unless its deadline has come (then the timeout's
    /// flag or error).
    fn check_timeout(&mut self, sh: &mut Shared) -> R<Blocked> {
        let Some(w) = self.frames.last().and_then(|f| f.wait.clone()) else {
            return Ok(Blocked::Ready);
        };
        let now = sh.clock;
        if let Some(d) = w.deadline
            && now >= d
        {
            self.clear_wait();
            if let WaitKind::Sync { key, .. } = &w.kind {
                sh.sync.leave(key, self.number);
            }
            return match w.on_timeout {
                Timeout::Flag(p) => {
                    self.store(sh, &p, Value::Bool(true))?;
                    Ok(Blocked::Ready)
                }
                Timeout::Error(name, message) => fault(named_error(&self.prog, name, message)),
            };
        }
        Ok(Blocked::Waiting)
    }

    fn clear_wait(&mut self) {
        if let Some(f) = self.frames.last_mut() {
            f.wait = None;
        }
    }

    /// The wait holds: what it does then.
    fn end_wait(&mut self, sh: &mut Shared, w: &super::Wait) -> R<()> {
        self.clear_wait();
        match &w.kind {
            WaitKind::Poll { again, .. } => {
                if let Some(f) = self.frames.last_mut() {
                    f.pc = *again;
                    f.boundary = Boundary::None;
                }
            }
            WaitKind::Semaphore(p) => self.store(sh, p, Value::Bool(true))?,
            WaitKind::Message { to, wanted } => {
                let own = self.number.saturating_sub(1);
                if let Some(h) = sh.rmq.take(own, |m| accepts(wanted.as_deref(), m)) {
                    self.store(sh, to, crate::rmq::message_value(h))?;
                }
            }
            WaitKind::Search(search) => {
                let now = sh.clock;
                self.store(sh, &search.point, search.hit_at(now))?;
                if search.stop {
                    // The robot stops at the hit.
                    if let Some(until) = sh.motion_until.get_mut(search.robot) {
                        *until = until.min(now);
                    }
                    let hit = crate::world::RobTarget {
                        pose: crate::world::Pose {
                            trans: search.hit_trans(now),
                            rot: search.target.pose.rot,
                        },
                        ..search.target
                    };
                    if let Some(Some(robot)) = sh.robots.get_mut(search.robot)
                        && let Ok(joints) = robot.calc_joints(&hit, &search.tool, &search.wobj)
                    {
                        robot.stop_at(&joints, now);
                    }
                } else if search.end > now {
                    // A flying search: the robot goes on to ToPoint.
                    self.block(super::Wait::until(
                        search.end,
                        "the search move (the robot moves on)".to_owned(),
                    ));
                }
            }
            WaitKind::Operator(o) => {
                if let Some((p, v)) = &o.also {
                    self.store(sh, p, v.clone())?;
                }
                match &o.to {
                    Some(p) => self.store(sh, p, o.answer.clone())?,
                    None => self.vals.push(o.answer.clone()),
                }
            }
            WaitKind::Sync {
                sync_move: Some(on),
                ..
            } => {
                self.sync_move = if *on {
                    sh.sync.group_of(self.number)
                } else {
                    None
                };
            }
            _ => {}
        }
        Ok(())
    }

    /// A dialog ends without an answer (a break signal, `\MaxTime`): the
    /// error in `\BreakFlag` (a function gives its fallback), else
    /// raised.
    fn operator_break(
        &mut self,
        sh: &mut Shared,
        o: &OperatorWait,
        error: &'static str,
        message: String,
    ) -> R<Blocked> {
        self.clear_wait();
        let Some(flag) = &o.flag else {
            return fault(named_error(&self.prog, error, message));
        };
        let errno = self.prog.errnum(error);
        self.store(sh, flag, Value::Num(errno))?;
        if o.to.is_none() {
            self.vals.push(o.fallback.clone());
        }
        Ok(Blocked::Ready)
    }

    /// The innermost frame waits for `w`.
    pub(crate) fn block(&mut self, w: Wait) {
        if let Some(f) = self.frames.last_mut() {
            f.wait = Some(Box::new(w));
        }
    }

    /// Can the task's wait end with time alone (the end of a `WaitTime`,
    /// a deadline, a condition that reads the clock or whose data another
    /// task changed since it was found false)? If no task's can, and
    /// nothing comes from outside, the run is a deadlock.
    pub(crate) fn waits_on_time(&self, sh: &Shared) -> bool {
        match self.frames.last().and_then(|f| f.wait.as_ref()) {
            Some(w) => match &w.kind {
                WaitKind::Time(_) | WaitKind::InPos { .. } => true,
                WaitKind::Move { robot, level } => {
                    motion_end(sh, *robot, *level).is_finite() || w.deadline.is_some()
                }
                WaitKind::Poll { clock, steps, .. } => {
                    *clock || w.deadline.is_some() || *steps != sh.steps
                }
                WaitKind::Operator(o) => o.at.is_some() || w.deadline.is_some(),
                _ => w.deadline.is_some(),
            },
            None => false,
        }
    }

    /// When the task's wait should be looked at again: the end of a
    /// `WaitTime` or a move, the next poll, a deadline.
    pub(crate) fn wake_time(&self, sh: &Shared) -> Option<f64> {
        let w = self.frames.last()?.wait.as_ref()?;
        let own = match &w.kind {
            WaitKind::Time(t) | WaitKind::InPos { at: t, .. } => Some(*t),
            WaitKind::Move { robot, level } => {
                Some(motion_end(sh, *robot, *level)).filter(|t| t.is_finite())
            }
            WaitKind::Poll { next, .. } => Some(*next),
            WaitKind::Operator(o) => o.at,
            _ => None,
        };
        match (own, w.deadline) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// What the task waits for, for a report.
    pub(crate) fn waiting_for(&self) -> Option<String> {
        self.frames
            .last()
            .and_then(|f| f.wait.as_ref())
            .map(|w| w.what.clone())
    }

    /// Does the task wait for a signal (`WaitDI`...), or for a condition
    /// (`WaitUntil`), which a scripted signal change may end?
    pub(crate) fn waits_on_signals(&self) -> bool {
        self.frames
            .last()
            .and_then(|f| f.wait.as_ref())
            .is_some_and(|w| matches!(w.kind, WaitKind::Signal { .. } | WaitKind::Poll { .. }))
    }

    /// Does the task wait for a move `StopMove` holds?
    pub(crate) fn waits_on_held_move(&self, sh: &Shared) -> bool {
        self.frames
            .last()
            .and_then(|f| f.wait.as_ref())
            .is_some_and(|w| match w.kind {
                WaitKind::Move { robot, level } => {
                    sh.paths.get(robot).is_some_and(|p| p.holds(level))
                }
                _ => false,
            })
    }

    /// The deadlock of this task: it waits, and nothing can end the wait.
    pub(crate) fn deadlock(&self, others: &str) -> Box<super::Fault> {
        let what = self.waiting_for().unwrap_or_else(|| "the task".to_owned());
        let message = format!("{what} waits forever: {others}");
        Box::new(super::Fault {
            kind: FaultKind::Deadlock(message),
            skip_depth: None,
            fatal: true,
            trace: None,
            reported: false,
        })
    }
}

impl Machine {
    /// `WaitUntil` starts: its `\MaxTime`, `\PollRate` and `\TimeFlag` to
    /// its state's hidden slots (from `w.state`), the time flag cleared.
    pub(crate) fn wait_until_start(
        &mut self,
        sh: &mut Shared,
        base: usize,
        w: &crate::code::WaitUntil,
    ) -> R<()> {
        let flag = if w.time_flag { self.places.pop() } else { None };
        let number = |m: &mut Machine| -> R<Option<f64>> {
            match m.vals.pop() {
                Some(v) => Ok(m.scalar(sh, v)?.as_f64()),
                None => Ok(None),
            }
        };
        let poll = if w.poll_rate { number(self)? } else { None };
        let max = if w.max_time { number(self)? } else { None };
        let s = base + w.state as usize;
        let slots = [
            super::Slot::Val(Value::Dnum(sh.clock)),
            max.map_or(super::Slot::Absent, |m| super::Slot::Val(Value::Dnum(m))),
            super::Slot::Val(Value::Dnum(poll.unwrap_or(0.1).max(0.01))),
            flag.clone().map_or(super::Slot::Absent, super::Slot::Ref),
        ];
        for (k, v) in slots.into_iter().enumerate() {
            if let Some(slot) = self.slots.get_mut(s + k) {
                *slot = v;
            }
        }
        if let Some(p) = flag {
            self.store(sh, &p, Value::Bool(false))?;
        }
        self.read_clock = false;
        Ok(())
    }

    /// A `WaitUntil` condition was evaluated: go on (`true`) when it holds
    /// or the wait timed out with a time flag, else the frame waits for
    /// the next poll (at most until `\MaxTime`).
    pub(crate) fn wait_until_check(
        &mut self,
        sh: &mut Shared,
        base: usize,
        w: &crate::code::WaitUntil,
        holds: bool,
        again: Pc,
    ) -> R<bool> {
        if holds {
            return Ok(true);
        }
        let s = base + w.state as usize;
        let num = |m: &Machine, k: usize| match m.slots.get(s + k) {
            Some(super::Slot::Val(v)) => v.as_f64(),
            _ => None,
        };
        let start = num(self, 0).unwrap_or(sh.clock);
        let poll = num(self, 2).unwrap_or(0.1);
        let deadline = num(self, 1).map(|m| start + m);
        if deadline.is_some_and(|d| sh.clock >= d) {
            return match self.slots.get(s + 3).cloned() {
                Some(super::Slot::Ref(p)) => {
                    self.store(sh, &p, Value::Bool(true))?;
                    Ok(true)
                }
                _ => fault(named_error(
                    &self.prog,
                    "ERR_WAIT_MAXTIME",
                    "WaitUntil: the condition did not happen within \\MaxTime".to_owned(),
                )),
            };
        }
        let mut next = sh.clock + poll;
        if let Some(d) = deadline {
            next = next.min(d);
        }
        let clock = std::mem::take(&mut self.read_clock);
        self.block(Wait {
            kind: WaitKind::Poll {
                next,
                again,
                clock,
                steps: sh.steps,
            },
            // Reached only through the poll (`next` is never later), which
            // evaluates the condition once more first.
            deadline,
            on_timeout: Timeout::Error("ERR_WAIT_MAXTIME", String::new()),
            what: "WaitUntil".to_owned(),
        });
        Ok(false)
    }
}
