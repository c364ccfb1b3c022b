//! The virtual controller: one world shared by every task (the clock,
//! signals, persistents, files, robots, the pendant) and one machine per
//! task, under a deterministic scheduler. Tasks take turns statement by
//! statement, in the order they were added (so the same program prints the
//! same lines every run); when every task waits, the clock moves to the
//! next thing that can end a wait (a signal scripted to change, a timer,
//! the end of a `WaitTime` or a move, a poll of `WaitUntil`); when nothing
//! can, the run is a deadlock, reported with each task's line.

mod debug;
mod sync;

use std::sync::Arc;

use rapid_analyzer::names::{NameMap, fold};
use rapid_evaluator::Value;

pub(crate) use debug::Debug;
pub use debug::Resume;
pub(crate) use sync::Sync;

use crate::machine::{Init, Machine, Outcome, Status, Stop, Yield};
use crate::program::Program;
use crate::world::{FileSystem, Io, Pendant, Robot, Sockets, World};
use crate::{Config, Limits, Move, Output, Stream};

pub use rapid_analyzer::task::TaskKind;

/// A task to run.
pub struct TaskSpec {
    /// The task's name (`T_ROB1`).
    pub name: String,
    pub program: Arc<Program>,
    /// The routine it starts in (a procedure without parameters); `None`:
    /// loaded, not started.
    pub entry: Option<u32>,
    pub kind: TaskKind,
    /// The robot it moves (a motion task), if any.
    pub robot: Option<Box<dyn Robot>>,
}

/// What the controller shares between its tasks.
pub(crate) struct Shared {
    pub clock: f64,
    pub limits: Limits,
    pub trace: bool,
    /// Statements run, by every task.
    pub steps: u64,
    /// The persistents the tasks share (and their state), by index.
    pub pers: Vec<Value>,
    pub pers_init: Vec<Init>,
    /// How many declarations each persistent has (in every task's program).
    pers_users: Vec<u32>,
    /// Each persistent's value came from a declaration that gives one
    /// (`PERS num n := 5;`), not from one that gives none (`PERS num n;`,
    /// which takes the value another task's declaration gives).
    pers_valued: Vec<bool>,
    pers_names: NameMap<u32>,
    pub io: Box<dyn Io>,
    /// Signal changes the controller makes later (pulses, `\SDelay`, the
    /// events of a robot's path): time, signal, value, and the robot
    /// whose path sets it (a `StopMove` holds its changes); earliest first.
    pub timed: Vec<(f64, String, f64, Option<crate::machine::PathMark>)>,
    /// Every signal change so far, for the tasks' interrupts.
    pub events: Vec<(String, f64)>,
    pub sync: Sync,
    pub files: Box<dyn FileSystem>,
    pub open: crate::builtins::files::OpenFiles,
    pub pendant: Box<dyn Pendant>,
    pub sockets: Box<dyn Sockets>,
    /// The mechanical units `DeactUnit` deactivated (folded names).
    pub inactive_units: Vec<String>,
    /// The I/O devices `IODisable` disabled (folded names).
    pub disabled_io_units: Vec<String>,
    /// The configuration (`WriteCfgData` changes it) and identity.
    pub system: crate::world::System,
    /// The controller's event log (`ErrWrite`), for `IError`.
    pub event_log: Vec<crate::interrupts::LogEntry>,
    /// FlexPendant applications `UIShow` opened.
    pub ui_instances: u32,
    output: Box<dyn Output>,
    /// Each task's robot, by task index.
    pub robots: Vec<Option<Box<dyn Robot>>>,
    /// When each task's robot ends its last move.
    pub motion_until: Vec<f64>,
    /// Each task's robot's path: its level (`StorePath` raises it) and
    /// what `StopMove` stopped.
    pub(crate) paths: Vec<crate::machine::PathState>,
    /// The tasks' message queues (RAPID Message Queue).
    pub(crate) rmq: crate::rmq::Queues,
    pub moves: Vec<Move>,
    /// The moves made, traced or not.
    pub move_count: u64,
    /// The routines that returned, with when they ran (when tracing).
    pub routine_times: Vec<crate::RoutineTime>,
    /// Each task's name, by index.
    pub names: Vec<String>,
    /// Each task's kind, by index.
    pub(crate) kinds: Vec<TaskKind>,
    pub debug: Debug,
    /// A task stopped the program (`Stop \AllMoveTasks`,
    /// `SystemStopAction`): why the other normal tasks stop.
    pub(crate) stop_normal: Option<String>,
    /// The user text tables `TextTabInstall` installed.
    pub(crate) text_tables: Vec<crate::builtins::texts::TextTable>,
}

impl Shared {
    /// The index of the shared persistent `name` (made on first use).
    /// Each call is one more declaration of it ([`Self::release_persistent`]).
    pub(crate) fn persistent(&mut self, name: &str) -> u32 {
        let key = fold(name);
        if let Some(&i) = self.pers_names.get(&key) {
            if let Some(n) = self.pers_users.get_mut(i as usize) {
                *n += 1;
            }
            return i;
        }
        let i = self.pers.len() as u32;
        self.pers.push(Value::Num(0.0));
        self.pers_init.push(Init::Pending);
        self.pers_users.push(1);
        self.pers_valued.push(false);
        self.pers_names.insert(key, i);
        i
    }

    /// A declaration of persistent `i` is gone (its module unloaded): with
    /// none left, the controller forgets the persistent, and the next
    /// module that declares it starts it at its declared value.
    pub(crate) fn release_persistent(&mut self, i: u32) {
        let i = i as usize;
        if let Some(n) = self.pers_users.get_mut(i) {
            *n = n.saturating_sub(1);
            if *n == 0
                && let Some(s) = self.pers_init.get_mut(i)
            {
                *s = Init::Pending;
                if let Some(v) = self.pers_valued.get_mut(i) {
                    *v = false;
                }
            }
        }
    }

    /// A persistent's starting value: the first task that sets it wins,
    /// but a declaration that gives a value (`valued`) wins over those
    /// that give none.
    pub(crate) fn set_persistent(&mut self, i: u32, v: Value, valued: bool) {
        let i = i as usize;
        if matches!(self.pers_init.get(i), Some(Init::Ready)) && !self.takes_value(i, valued) {
            return;
        }
        if let Some(slot) = self.pers.get_mut(i) {
            *slot = v;
        }
        if let Some(s) = self.pers_init.get_mut(i) {
            *s = Init::Ready;
        }
        if let Some(s) = self.pers_valued.get_mut(i) {
            *s = valued;
        }
    }

    /// Does a declaration of persistent `i` that gives a value (`valued`)
    /// replace the value it has (from a declaration that gave none)?
    pub(crate) fn takes_value(&self, i: usize, valued: bool) -> bool {
        valued && self.pers_valued.get(i) == Some(&false)
    }

    /// Sets a signal; a change is an event for the interrupts.
    pub(crate) fn set_signal(&mut self, name: &str, value: f64) {
        let old = self.io.read(name);
        self.io.write(name, value);
        if old.is_some_and(|o| o != value) {
            self.events.push((name.to_owned(), value));
        }
    }

    /// Sets a signal `delay` seconds from now.
    pub(crate) fn set_signal_later(&mut self, name: &str, value: f64, delay: f64) {
        self.set_signal_at(name, value, delay, None);
    }

    /// Sets a signal `delay` seconds from now as robot `robot` passes a
    /// point of its path (set now when that is not later): a `StopMove`
    /// holds it with the move ([`crate::machine::PathMark`]).
    pub(crate) fn set_signal_on_path(&mut self, robot: usize, name: &str, value: f64, delay: f64) {
        if delay > 0.0 {
            let mark = crate::machine::PathMark::now(&self.paths, robot);
            self.set_signal_at(name, value, delay, Some(mark));
        } else {
            self.set_signal(name, value);
        }
    }

    fn set_signal_at(
        &mut self,
        name: &str,
        value: f64,
        delay: f64,
        mark: Option<crate::machine::PathMark>,
    ) {
        let at = self.clock + delay.max(0.0);
        let pos = self.timed.partition_point(|c| c.0 <= at);
        self.timed.insert(pos, (at, name.to_owned(), value, mark));
    }

    /// A line the program prints, from task `task` (named when several
    /// tasks run).
    pub(crate) fn print(&mut self, task: &str, stream: Stream, text: &str) {
        if self.names.len() > 1 {
            self.output.line(stream, &format!("[{task}] {text}"));
        } else {
            self.output.line(stream, text);
        }
    }

    /// The time of the next change from outside or of the controller's
    /// own.
    fn next_event(&self) -> Option<f64> {
        let timed = self
            .timed
            .iter()
            .filter_map(|c| crate::machine::due_on(c.0, c.3.as_ref(), &self.paths))
            .reduce(f64::min);
        match (self.io.next_change(), timed) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// Moves the clock to `t`, applying the changes due by then; with
    /// sockets open to real peers, no sooner than real time allows
    /// ([`crate::world::Sockets::pace`]).
    pub(crate) fn advance_to(&mut self, t: f64) {
        if t > self.clock {
            self.sockets.pace(self.clock, t);
        }
        self.jump_to(t);
    }

    /// [`Self::advance_to`] without keeping pace with real time (the run
    /// ends there).
    fn jump_to(&mut self, t: f64) {
        for (name, value) in self.io.advance(t) {
            self.events.push((name, value));
        }
        // The changes due by then, in the order they come (a path's are
        // later by the time a `StopMove` held it; a dropped move's never
        // come).
        let paths = &self.paths;
        let mut changes = Vec::new();
        self.timed.retain(|(at, name, value, mark)| {
            if mark.is_some_and(|m| m.dropped(paths)) {
                return false;
            }
            match crate::machine::due_on(*at, mark.as_ref(), paths) {
                Some(due) if due <= t => {
                    changes.push((due, name.clone(), *value));
                    false
                }
                _ => true,
            }
        });
        changes.sort_by(|a, b| a.0.total_cmp(&b.0));
        for (_, name, value) in changes {
            self.set_signal(&name, value);
        }
        self.clock = self.clock.max(t);
    }

    /// Why a task name names no task: the controller's tasks.
    pub(crate) fn no_such_task(&self, name: &str) -> String {
        format!(
            "there is no task {name} in the controller (its tasks: {})",
            self.names.join(", ")
        )
    }

    /// The index of the task named `name`.
    pub(crate) fn task_named(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n.eq_ignore_ascii_case(name))
    }
}

/// What running the controller came to.
#[derive(Clone, Debug)]
pub enum Event {
    /// A debugger stops task `task` (its index).
    Stopped { task: usize, stop: Stop },
    /// Every task ended: see [`Controller::outcomes`].
    Ended,
    /// The statements given are used up; the run goes on.
    Running,
}

/// A controller with its tasks.
pub struct Controller {
    sh: Shared,
    tasks: Vec<Machine>,
    /// Each task's entry routine (`None`: loaded, not started), by index.
    entries: Vec<Option<u32>>,
    started: bool,
}

/// How many statements a lone task runs between the scheduler's checks.
const LONE_SLICE: u32 = 4096;

impl Controller {
    pub fn new(config: Config, world: World) -> Controller {
        Controller {
            sh: Shared {
                clock: 0.0,
                limits: config.limits.clone(),
                trace: config.trace,
                steps: 0,
                pers: Vec::new(),
                pers_init: Vec::new(),
                pers_users: Vec::new(),
                pers_valued: Vec::new(),
                pers_names: NameMap::default(),
                io: world.io,
                timed: Vec::new(),
                events: Vec::new(),
                sync: Sync::default(),
                files: world.files,
                inactive_units: Vec::new(),
                disabled_io_units: Vec::new(),
                ui_instances: 0,
                event_log: Vec::new(),
                system: config.system.clone(),
                open: Default::default(),
                pendant: world.pendant,
                sockets: world.sockets,
                output: world.output,
                robots: Vec::new(),
                motion_until: Vec::new(),
                paths: Vec::new(),
                rmq: Default::default(),
                moves: Vec::new(),
                move_count: 0,
                routine_times: Vec::new(),
                names: Vec::new(),
                kinds: Vec::new(),
                debug: Debug::default(),
                stop_normal: None,
                text_tables: Vec::new(),
            },
            tasks: Vec::new(),
            entries: Vec::new(),
            started: false,
        }
    }

    /// Adds a task (its data initialised as the controller loads it); its
    /// index.
    pub fn add_task(&mut self, spec: TaskSpec) -> usize {
        for (name, kind) in spec.program.signals() {
            self.sh.io.declare(&name, kind);
        }
        let index = self.tasks.len();
        self.sh.names.push(spec.name.clone());
        self.sh.kinds.push(spec.kind);
        self.sh.robots.push(spec.robot);
        self.sh.motion_until.push(0.0);
        self.sh.paths.push(crate::machine::PathState::default());
        self.sh.rmq.add_task();
        let m = Machine::new(spec.program, spec.name, index + 1, &mut self.sh);
        self.tasks.push(m);
        self.entries.push(spec.entry);
        index
    }

    /// The tasks.
    pub fn tasks(&self) -> &[Machine] {
        &self.tasks
    }

    /// The simulated time, in seconds since the run started.
    pub fn clock(&self) -> f64 {
        self.sh.clock
    }

    /// Statements run so far, by every task.
    pub fn steps(&self) -> u64 {
        self.sh.steps
    }

    /// The moves made so far (with [`Config::trace`]).
    pub fn moves(&self) -> &[Move] {
        &self.sh.moves
    }

    /// How many moves the robots made (traced or not).
    pub fn move_count(&self) -> u64 {
        self.sh.move_count
    }

    /// The calls that returned, with the simulated time each took (with
    /// tracing on).
    pub fn routine_times(&self) -> &[crate::RoutineTime] {
        &self.sh.routine_times
    }

    /// Each task's outcome (`None`: not started, or still running).
    pub fn outcomes(&self) -> Vec<(String, Option<Outcome>)> {
        self.tasks
            .iter()
            .map(|t| (t.name.clone(), t.outcome().cloned()))
            .collect()
    }

    /// Starts routine `routine` of task `task` now (as a test harness runs
    /// one routine after another on the same data).
    pub fn start_routine(&mut self, task: usize, routine: u32) -> Result<(), String> {
        self.begin();
        self.started = true;
        let now = self.sh.clock;
        match self.tasks.get_mut(task) {
            Some(m) => {
                m.start(routine)?;
                if let Some(f) = m.frames.last_mut() {
                    f.entered = now;
                }
                Ok(())
            }
            None => Err("no such task".to_owned()),
        }
    }

    /// Starts every task's entry routine: the static and semistatic tasks
    /// first, as a controller starts them when it starts, then the normal
    /// ones. An entry that cannot start ends its task at once.
    fn start(&mut self) {
        if self.started {
            return;
        }
        self.begin();
        self.started = true;
        let mut order: Vec<usize> = (0..self.tasks.len()).collect();
        order.sort_by_key(|&i| self.sh.kinds[i] == TaskKind::Normal);
        for i in order {
            let Some(entry) = self.entries[i] else {
                continue;
            };
            if let Err(why) = self.tasks[i].start(entry) {
                self.tasks[i].finish(Outcome {
                    status: Status::Invalid,
                    message: why,
                    errno: None,
                    at: None,
                    stack: Vec::new(),
                });
            }
        }
    }

    /// The world as the run begins: the signal values scripted for the
    /// start.
    fn begin(&mut self) {
        if !self.started {
            let now = self.sh.clock;
            self.sh.advance_to(now);
        }
    }

    /// Runs to the end (no debugger).
    pub fn run(&mut self) -> Event {
        loop {
            match self.run_for(u64::MAX) {
                Event::Running => continue,
                other => return other,
            }
        }
    }

    /// Runs at most `statements` statements (of every task), until a
    /// debugger stop or the end.
    pub fn run_for(&mut self, statements: u64) -> Event {
        self.start();
        let limit = self.sh.steps.saturating_add(statements);
        loop {
            if self.normal_tasks_ended() {
                self.halt_others();
                return Event::Ended;
            }
            if self.sh.steps >= limit {
                return Event::Running;
            }
            // The static and semistatic tasks (started first, as a
            // controller starts them) before the normal ones.
            let mut running: Vec<usize> = (0..self.tasks.len())
                .filter(|&i| self.tasks[i].is_running())
                .collect();
            running.sort_by_key(|&i| self.sh.kinds[i] == TaskKind::Normal);
            let slice = if running.len() == 1 { LONE_SLICE } else { 1 };
            let mut ran = false;
            for i in running {
                match self.tasks[i].run_slice(&mut self.sh, slice) {
                    Yield::Slice | Yield::Done | Yield::Evaluated => ran = true,
                    Yield::Blocked => {}
                    Yield::Stopped(stop) => return Event::Stopped { task: i, stop },
                }
                if let Some(why) = self.sh.stop_normal.take() {
                    self.stop_normal_tasks(&why);
                }
            }
            if !ran && let Some(e) = self.advance_clock() {
                return e;
            }
            self.forget_seen_events();
        }
    }

    /// Drops the signal events every task has seen.
    fn forget_seen_events(&mut self) {
        if self.sh.events.len() < 1024 {
            return;
        }
        let seen = self
            .tasks
            .iter()
            .map(|t| t.events_seen)
            .min()
            .unwrap_or(0)
            .min(self.sh.events.len());
        self.sh.events.drain(..seen);
        for t in &mut self.tasks {
            t.events_seen -= seen;
        }
    }

    /// Have the normal tasks all ended (or, without normal tasks, every
    /// task)?
    fn normal_tasks_ended(&self) -> bool {
        let normal: Vec<&Machine> = self
            .tasks
            .iter()
            .zip(&self.sh.kinds)
            .filter(|(_, k)| **k == TaskKind::Normal)
            .map(|(t, _)| t)
            .collect();
        if normal.is_empty() {
            self.tasks.iter().all(Machine::is_done)
        } else {
            normal.iter().all(|t| t.is_done())
        }
    }

    /// A task stopped the program: the normal tasks still running stop
    /// where they are.
    fn stop_normal_tasks(&mut self, why: &str) {
        for (t, kind) in self.tasks.iter_mut().zip(&self.sh.kinds) {
            if *kind == TaskKind::Normal && t.is_running() {
                t.finish(Outcome {
                    status: Status::Stopped,
                    message: why.to_owned(),
                    errno: None,
                    at: t.location(),
                    stack: t.stack_frames(),
                });
            }
        }
    }

    /// The program has ended: the static and semistatic tasks still
    /// running are halted with it.
    fn halt_others(&mut self) {
        for t in &mut self.tasks {
            if t.is_running() {
                t.finish(Outcome {
                    status: Status::Halted,
                    message: "halted when the normal tasks ended".to_owned(),
                    errno: None,
                    at: t.location(),
                    stack: t.stack_frames(),
                });
            }
        }
    }

    /// Every running task waits: the clock moves to the next time that can
    /// end a wait; a deadlock or the end of the time budget ends the tasks
    /// that wait.
    fn advance_clock(&mut self) -> Option<Event> {
        let waiting: Vec<usize> = (0..self.tasks.len())
            .filter(|&i| self.tasks[i].is_running())
            .collect();
        if waiting.is_empty() {
            return None;
        }
        let earlier = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        // What can end a wait (`real`), and the next time anything is
        // looked at again (`any`: also the polls of conditions that
        // nothing will change).
        let mut real = self.sh.next_event();
        let mut any = real;
        for &i in &waiting {
            let t = &self.tasks[i];
            let timer = t.interrupts.next_due(&self.sh.paths);
            real = earlier(real, timer);
            any = earlier(any, timer);
            let wake = t.wake_time(&self.sh);
            if t.waits_on_time(&self.sh) {
                real = earlier(real, wake);
            }
            any = earlier(any, wake);
        }
        let (Some(_), Some(t)) = (real, any) else {
            return self.deadlock(&waiting);
        };
        let t = t.max(self.sh.clock);
        let max = self.sh.limits.max_time;
        if t > max {
            self.sh.jump_to(max);
            for i in waiting {
                let during = match self.tasks[i].waiting_for() {
                    Some(what) => format!(" ({what} waits)"),
                    None => String::new(),
                };
                let f = crate::machine::Fault {
                    kind: crate::machine::FaultKind::Budget(format!(
                        "the simulated time budget ({max} s) ran out{during}"
                    )),
                    skip_depth: None,
                    fatal: true,
                    trace: None,
                    reported: false,
                };
                if let Some(Yield::Stopped(stop)) = self.tasks[i].handle(&mut self.sh, Box::new(f))
                {
                    return Some(Event::Stopped { task: i, stop });
                }
            }
            return None;
        }
        self.sh.advance_to(t);
        for task in &mut self.tasks {
            task.interrupts.expire(t, &self.sh.paths);
        }
        None
    }

    /// Nothing can end the waits: each waiting task ends in a deadlock.
    fn deadlock(&mut self, waiting: &[usize]) -> Option<Event> {
        let lone = self.tasks.len() == 1;
        let report: Vec<String> = waiting
            .iter()
            .map(|&i| {
                let t = &self.tasks[i];
                let at = t.location().map(|l| l.to_string()).unwrap_or_default();
                let what = t.waiting_for().unwrap_or_default();
                format!("{} at {at} ({what})", t.name)
            })
            .collect();
        let others = if lone {
            let hint = if self.tasks[0].waits_on_signals() {
                " (script a signal change with --set NAME=VALUE@SECONDS)"
            } else if self.tasks[0].waits_on_held_move(&self.sh) {
                " (StopMove holds the robot, and no StartMove comes)"
            } else {
                ""
            };
            format!("nothing the simulation runs can change it{hint}")
        } else {
            format!("every task waits: {}", report.join("; "))
        };
        for &i in waiting {
            let f = self.tasks[i].deadlock(&others);
            if let Some(Yield::Stopped(stop)) = self.tasks[i].handle(&mut self.sh, f) {
                return Some(Event::Stopped { task: i, stop });
            }
        }
        None
    }

    // The debugger's side.

    /// Attaches a debugger: stops are looked for from now on.
    pub fn debug(&mut self, stop_on_entry: bool) {
        self.sh.debug.active = true;
        self.sh.debug.entry = stop_on_entry;
    }

    /// The breakpoint lines of a module file (its path as the task names
    /// it).
    pub fn set_breakpoints(&mut self, path: &str, lines: &[u32]) {
        self.sh.debug.set_breakpoints(path, lines);
    }

    /// How to go on after a stop.
    pub fn resume(&mut self, how: Resume) {
        let task = match how {
            Resume::Continue => None,
            Resume::StepIn { task } | Resume::StepOver { task } | Resume::StepOut { task } => {
                Some(task)
            }
        };
        let depth = task
            .and_then(|t| self.tasks.get(t))
            .map_or(0, Machine::depth);
        self.sh.debug.resume(how, depth);
    }

    /// Asks for a stop at the next statement of any task.
    pub fn pause(&mut self) {
        self.sh.debug.pause = true;
    }

    /// A pause asked for that no statement has met yet (every task waits):
    /// it stops now, in the first task that runs.
    pub fn take_pause(&mut self) -> Option<Event> {
        if !std::mem::take(&mut self.sh.debug.pause) {
            return None;
        }
        let task = self.tasks.iter().position(Machine::is_running)?;
        Some(Event::Stopped {
            task,
            stop: Stop::Pause,
        })
    }

    /// Ends every task now (a debugger's terminate): they stop as `Stop`
    /// stops them.
    pub fn terminate(&mut self) {
        for t in &mut self.tasks {
            if t.is_running() {
                t.finish(Outcome {
                    status: Status::Stopped,
                    message: String::new(),
                    errno: None,
                    at: t.location(),
                    stack: t.stack_frames(),
                });
            }
        }
    }

    pub(crate) fn parts(&mut self, task: usize) -> Option<(&mut Machine, &mut Shared)> {
        let m = self.tasks.get_mut(task)?;
        Some((m, &mut self.sh))
    }

    pub(crate) fn shared(&self) -> &Shared {
        &self.sh
    }
}
