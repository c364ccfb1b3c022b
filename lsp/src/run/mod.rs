//! `rapid run`: runs a controller's tasks on the virtual controller: a
//! backup's (or a folder of task folders') every task together, the
//! static and semistatic ones first, else the one task of a module or a
//! folder.
//!
//! The program's output (`TPWrite`, `ErrWrite`, `UIMsgWrite`) goes to
//! stdout, one line each (named by its task, `[T_ROB2] ...`, when several
//! run); what the pendant shows without a line (`TPErase`, `TPShow`,
//! `UIShow`) is traced to stderr (`[TPErase at m.mod:4] ...`); how the run
//! ended goes to stderr when it did not end normally, with the error's
//! name, message, line and the active routines. A program the controller
//! would not load (a syntax error, what the checker finds it would refuse)
//! does not run: its errors go to stderr. Exit status: 0 when every task
//! ends normally (its end, `EXIT`, `Stop`), 1 when one ends otherwise, 2
//! for usage errors and programs that cannot be loaded.
//!
//! [`execute`] is the same run as a library call (for `rapid mcp`): loaded
//! tasks ([`load::controller`]) and options in, the output to a sink (any
//! `FnMut(Stream, &str)`), each task's outcome back, or why the program
//! cannot start ([`NotRun`]).

#[cfg(test)]
mod corpus;
pub mod load;
mod missing;
mod multimove;
pub mod operator;
pub mod robot;
pub mod sockets;
mod task_names;
pub mod trace;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use rapid_runtime::world::World;
use rapid_runtime::{
    Config, Controller, Limits, Move, Outcome, Output, SignalChange, Status, Stream, TaskSpec,
};

#[derive(Debug, clap::Args)]
pub struct RunArgs {
    /// A module (run with the rest of its task), a task's folder, or a
    /// backup (every task of it).
    pub path: PathBuf,
    /// The procedure to run (default: a task's `SYS.cfg` entry, else
    /// `main`; with several tasks, their `SYS.cfg` entries win).
    #[arg(long, value_name = "NAME")]
    pub entry: Option<String>,
    /// Run only the task of this name (of a backup, or of a folder of
    /// task folders).
    #[arg(long, value_name = "NAME")]
    pub task: Option<String>,
    /// Set a signal: NAME=VALUE at the start, NAME=VALUE@SECONDS later
    /// (repeatable). Signals that no EIO.cfg declares are taken from their
    /// use in the program (with a note), else from their name: di*, do*,
    /// ai*, ao*, gi*, go* (else a digital input).
    #[arg(long = "set", value_name = "SIG=V[@T]")]
    pub set: Vec<String>,
    /// Write the motion as JSON.
    #[arg(long, value_name = "FILE")]
    pub trace: Option<PathBuf>,
    /// Draw the motion in 3D in a self-contained HTML page.
    #[arg(long, value_name = "FILE.html")]
    pub plot: Option<PathBuf>,
    /// The robot model that moves (`IRB 120-3/0.58`, or a MOC.cfg robot
    /// type), instead of the one MOC.cfg or rapid.toml names.
    #[arg(long, value_name = "NAME")]
    pub robot: Option<String>,
    /// After the run, print the cycle time of the entry routine and of
    /// each routine it called, and the axis closest to its limit.
    #[arg(long)]
    pub report: bool,
    /// The folder file instructions work in (default: a fresh temporary
    /// folder holding a copy of the controller's HOME, a backup's
    /// `HOME` folder, removed after the run).
    #[arg(long, value_name = "DIR")]
    pub sandbox: Option<PathBuf>,
    /// The operator's answers to the pendant's questions (`TPReadFK`,
    /// `UIMessageBox`...), one a line, in order: a function key's number
    /// or label, a number, a button or list item (`UIListView` with
    /// `\Result` and buttons: the item, confirmed with the first button;
    /// a button alone; or `ITEM, BUTTON`), text; `@SECONDS VALUE` answers
    /// after that many simulated seconds, `-` never answers; `#` starts a
    /// comment.
    #[arg(long, value_name = "FILE")]
    pub answers: Option<PathBuf>,
    /// One more answer, after those of --answers (repeatable).
    #[arg(long = "answer", value_name = "VALUE")]
    pub answer: Vec<String>,
    /// Sockets: where the host reaches an address the program names
    /// (repeatable; the default is the loopback interface, same port).
    #[arg(long = "socket-map", value_name = "ADDR:PORT=HOST:PORT")]
    pub socket_map: Vec<String>,
    /// List the instructions and functions of the tasks that the
    /// simulation does not support (where a run would stop), without
    /// running.
    #[arg(long)]
    pub list_unsupported: bool,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// The budgets of a run.
#[derive(Debug, Clone, clap::Args)]
pub struct LimitArgs {
    /// Stop after this many statements (of every task together).
    #[arg(long, default_value_t = Limits::default().max_steps, value_name = "N")]
    pub max_steps: u64,
    /// Stop after this many seconds of simulated time.
    #[arg(long, default_value_t = Limits::default().max_time, value_name = "SECONDS")]
    pub max_time: f64,
    /// Stop beyond this many nested routine calls (RAPID recursion).
    #[arg(long, default_value_t = Limits::default().max_depth, value_name = "N")]
    pub max_depth: u32,
}

impl LimitArgs {
    pub fn limits(&self) -> Limits {
        Limits {
            max_steps: self.max_steps,
            max_time: self.max_time,
            max_depth: self.max_depth,
            ..Limits::default()
        }
    }
}

/// How to run loaded tasks.
#[derive(Clone, Debug)]
pub struct RunOptions {
    /// Scripted signal changes.
    pub sets: Vec<SignalChange>,
    pub limits: Limits,
    /// The folder file instructions work in.
    pub sandbox: Option<PathBuf>,
    /// Record the moves (and the routines' times).
    pub trace: bool,
    /// The operator's answers.
    pub operator: operator::OperatorOptions,
    /// The host's sockets, reaching the addresses the program names as
    /// mapped; `None`: the simulated network, where nobody answers.
    pub socket_map: Option<Vec<sockets::SocketMap>>,
    /// The robot model of every motion task (`--robot`), instead of the
    /// task's own (MOC.cfg, rapid.toml).
    pub robot: Option<String>,
}

/// How a run ended.
#[derive(Clone, Debug)]
pub struct RunReport {
    /// Each task's name and outcome, in the controller's order.
    pub tasks: Vec<(String, Outcome)>,
    /// The moves made (with [`RunOptions::trace`]).
    pub moves: Vec<Move>,
    /// Notes on the run: the signals taken from their use.
    pub notes: Vec<String>,
    /// The calls that returned, with their times (with
    /// [`RunOptions::trace`]).
    pub routine_times: Vec<rapid_runtime::RoutineTime>,
    /// The moves the robots made.
    pub move_count: u64,
    /// The simulated time reached, in seconds.
    pub clock: f64,
}

impl RunReport {
    /// Did every task end normally?
    pub fn is_success(&self) -> bool {
        self.tasks.iter().all(|(_, o)| o.is_success())
    }

    /// The lines that say how the tasks ended (nothing for normal ends),
    /// each task's named when several ran.
    pub fn describe(&self) -> Vec<String> {
        let several = self.tasks.len() > 1;
        let mut out = Vec::new();
        for (name, o) in &self.tasks {
            for line in describe(o) {
                out.push(if several {
                    format!("[{name}] {line}")
                } else {
                    line
                });
            }
        }
        if let Some(help) = self.unnamed_tasks_help() {
            out.push(help);
        }
        out
    }

    /// A task name that names no task, on a controller whose tasks have
    /// their folders' names (`TASK1`...: a backup kept without `SYS.cfg`
    /// and `BACKINFO`, its program's use naming some or none): where their
    /// names come from.
    fn unnamed_tasks_help(&self) -> Option<String> {
        let unknown = self.tasks.iter().any(|(_, o)| {
            o.errno
                .as_ref()
                .is_some_and(|(_, name)| name == "ERR_TASKNAME")
        });
        let folders = self
            .tasks
            .iter()
            .any(|(t, _)| task_names::folder_number(t).is_some());
        (unknown && folders).then(|| {
            "  = help: the tasks have their folders' names, but those the program's use names (T_ROBn is TASKn): a backup's SYS.cfg or BACKINFO names them, else rapid.toml does ([controller] tasks = [\"T_ROB1\", ...] names TASK1, TASK2... in turn)".to_owned()
        })
    }
}

/// Why a run could not start.
#[derive(Clone, Debug)]
pub enum NotRun {
    /// The controller would not load the program: the checker's errors,
    /// one line each (`file:line:column: error[CODE] message (name)`).
    LoadErrors(Vec<String>),
    /// Anything else (no such entry routine...).
    Other(String),
}

impl std::fmt::Display for NotRun {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NotRun::LoadErrors(lines) => {
                writeln!(f, "the controller would not load the program:")?;
                for l in lines {
                    writeln!(f, "{l}")?;
                }
                Ok(())
            }
            NotRun::Other(m) => f.write_str(m),
        }
    }
}

/// Runs loaded tasks together on a virtual controller (the library
/// entry point of `rapid run`): each task's entry routine starts (the
/// static and semistatic tasks first), the program's lines go to
/// `output`, and each task's outcome comes back. A program the controller
/// would not load is not run.
pub fn execute(
    loaded: &load::Loaded,
    options: &RunOptions,
    output: Box<dyn Output>,
) -> Result<RunReport, NotRun> {
    let (mut controller, notes) = build(loaded, options, output)?;
    controller.run();
    let mut report = report_of(&controller);
    report.notes = notes;
    Ok(report)
}

/// The virtual controller of loaded tasks, ready to run (each task's
/// entry routine starts with the first statement run): for [`execute`],
/// and for a debugger that drives it itself. With it, the notes of the
/// signals no configuration declares, which the run takes from their use.
pub fn build(
    loaded: &load::Loaded,
    options: &RunOptions,
    output: Box<dyn Output>,
) -> Result<(Controller, Vec<String>), NotRun> {
    let mut errors = Vec::new();
    let mut notes = loaded.notes.clone();
    let mut checks = Vec::new();
    for t in &loaded.tasks {
        let check = t.load_check();
        errors.extend(check.errors.iter().map(ToString::to_string));
        notes.extend(check.signals.iter().map(ToString::to_string));
        checks.push(check);
    }
    if !errors.is_empty() {
        return Err(NotRun::LoadErrors(errors));
    }
    share_taken_signals(&mut checks);
    let config = Config {
        limits: options.limits.clone(),
        signals: options.sets.clone(),
        sandbox: options.sandbox.clone(),
        trace: options.trace,
        system: loaded.system.clone(),
        ..Config::default()
    };
    let mut world = World::simulated(&config, output);
    world.pendant = options.operator.pendant().map_err(NotRun::Other)?;
    if let Some(map) = &options.socket_map {
        world.sockets = Box::new(sockets::HostSockets::new(map.clone()));
    }
    let mut controller = Controller::new(config, world);
    let mut started = 0;
    for (t, check) in loaded.tasks.iter().zip(&checks) {
        let program = load::program(t.task.clone(), &options.sets, check);
        let entry = program.find_routine(&t.entry);
        if let Some(id) = entry
            && let Some(r) = program.routines().into_iter().find(|r| r.id == id)
            && (r.params > 0 || r.kind != rapid_analyzer::items::RoutineKind::Proc)
        {
            return Err(NotRun::Other(format!(
                "{}: {} is not a procedure without parameters",
                r.at, r.name
            )));
        }
        if entry.is_some() {
            started += 1;
        } else if loaded.tasks.len() == 1 {
            return Err(NotRun::Other(format!(
                "{}: no procedure {} in the task",
                t.task.key, t.entry
            )));
        }
        controller.add_task(TaskSpec {
            name: t.name.clone(),
            program,
            entry,
            kind: t.kind,
            robot: t
                .motion
                .then(|| robot::robot_of(t, options.robot.as_deref())),
        });
    }
    if started == 0 {
        let entries: Vec<&str> = loaded.tasks.iter().map(|t| t.entry.as_str()).collect();
        return Err(NotRun::Other(format!(
            "no task has its entry routine ({})",
            entries.join(", ")
        )));
    }
    Ok((controller, notes))
}

/// What a run may use: its budgets, the folder its file instructions work
/// in (a fresh temporary one holding a copy of the controller's `HOME`,
/// removed after the run, when `None`), and
/// whether its moves are recorded.
pub struct Budget {
    pub limits: Limits,
    pub sandbox: Option<PathBuf>,
    /// The folders the controller's `HOME` may be copied from into the
    /// temporary sandbox (`None`: wherever it is).
    pub home_roots: Option<Vec<PathBuf>>,
    pub trace: bool,
    /// The operator's answers, one a question ([`operator`]'s forms).
    pub answers: Vec<String>,
}

/// A run that ended: each task's outcome and the moves (when traced), the
/// statements it took and the simulated time it reached.
pub struct Ran {
    pub report: RunReport,
    pub steps: u64,
}

/// Runs `loaded` as [`execute`] does, on the simulated network, with the
/// signal script `sets` and the operator's `answers` of `budget`, each
/// output line going to `out` as it comes (for `rapid mcp`). An error
/// when the controller would not load the program, an entry routine is
/// missing or takes parameters, or the sandbox cannot be made.
pub fn run_loaded(
    loaded: &load::Loaded,
    sets: Vec<SignalChange>,
    budget: Budget,
    out: Box<dyn Output>,
) -> Result<Ran, String> {
    let home = loaded
        .tasks
        .first()
        .and_then(|t| load::home_within(&t.task.key, budget.home_roots.as_deref()));
    let sandbox = Sandbox::seeded(budget.sandbox, home.as_deref())?;
    let options = RunOptions {
        sets,
        limits: budget.limits,
        sandbox: Some(sandbox.path.clone()),
        trace: budget.trace,
        operator: operator::OperatorOptions::listed(budget.answers),
        // The simulated network: a request opens no sockets of the host.
        socket_map: None,
        robot: None,
    };
    let (mut controller, notes) = build(loaded, &options, out).map_err(|e| e.to_string())?;
    controller.run();
    let mut report = report_of(&controller);
    report.notes = notes;
    Ok(Ran {
        report,
        steps: controller.steps(),
    })
}

/// Each started task's outcome, and the moves.
pub fn report_of(controller: &Controller) -> RunReport {
    RunReport {
        tasks: controller
            .outcomes()
            .into_iter()
            .filter_map(|(name, o)| Some((name, o?)))
            .collect(),
        moves: controller.moves().to_vec(),
        notes: Vec::new(),
        routine_times: controller.routine_times().to_vec(),
        move_count: controller.move_count(),
        clock: controller.clock(),
    }
}

pub fn run(args: RunArgs) -> ExitCode {
    let mut stderr = anstream::stderr();
    match run_inner(args) {
        Ok(code) => code,
        Err(message) => {
            let _ = write!(stderr, "rapid: run: {message}");
            if !message.ends_with('\n') {
                let _ = writeln!(stderr);
            }
            ExitCode::from(2)
        }
    }
}

fn run_inner(args: RunArgs) -> Result<ExitCode, String> {
    let sets = args
        .set
        .iter()
        .map(|s| load::parse_set(s))
        .collect::<Result<Vec<_>, _>>()?;
    let loaded = load::controller(&args.path, args.task.as_deref(), args.entry.as_deref())?;
    if args.list_unsupported {
        for note in &loaded.notes {
            eprintln!("{note}");
        }
        list_unsupported(&loaded, &sets);
        return Ok(ExitCode::SUCCESS);
    }
    let sandbox = Sandbox::seeded(args.sandbox.clone(), loaded.home.as_deref())?;
    let options = RunOptions {
        sets,
        limits: args.limits.limits(),
        sandbox: Some(sandbox.path.clone()),
        trace: args.trace.is_some() || args.plot.is_some() || args.report,
        robot: args.robot.clone(),
        operator: operator::OperatorOptions::from_args(args.answers.as_deref(), &args.answer)?,
        socket_map: Some(
            args.socket_map
                .iter()
                .map(|m| sockets::parse_map(m))
                .collect::<Result<_, _>>()?,
        ),
    };
    let notes = robot::notes(&loaded.tasks, args.robot.as_deref())?;
    // The program's lines to stdout; the trace of what the pendant shows
    // (TPErase, TPShow, UIShow) to stderr, apart from them.
    let out = |stream: Stream, line: &str| {
        if stream == Stream::Trace {
            let _ = writeln!(std::io::stderr().lock(), "{line}");
        } else {
            let _ = writeln!(std::io::stdout().lock(), "{line}");
        }
    };
    let report = execute(&loaded, &options, Box::new(out)).map_err(|e| e.to_string())?;
    let arm = robot::drawn_arm(&loaded.tasks, args.robot.as_deref());
    let arm = arm.as_ref();
    if let Some(path) = &args.trace {
        let text = serde_json::to_string_pretty(&trace::json_with_arm(&report.moves, arm))
            .unwrap_or_default();
        std::fs::write(path, text + "\n").map_err(|e| format!("{}: {e}", path.display()))?;
    }
    if let Some(path) = &args.plot {
        let title = args.path.display().to_string();
        std::fs::write(path, trace::html_with_arm(&report.moves, arm, &title))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    let mut err = anstream::stderr();
    if report.move_count > 0 {
        for note in notes {
            let _ = writeln!(err, "rapid: run: {note}");
        }
    }
    for line in report.notes.iter().chain(&report.describe()) {
        let _ = writeln!(err, "{line}");
    }
    if args.report {
        let tasks: Vec<_> = loaded
            .tasks
            .iter()
            .filter(|t| report.tasks.iter().any(|(n, _)| *n == t.name))
            .map(|t| {
                let limits = t
                    .motion
                    .then(|| robot::arm_of(t, args.robot.as_deref()).ok())
                    .flatten()
                    .map(|r| r.limits.0);
                robot::Reported {
                    name: t.name.clone(),
                    limits,
                    entry: t.entry.clone(),
                }
            })
            .collect();
        let text = robot::report(&tasks, &report.routine_times, &report.moves, report.clock);
        let _ = write!(std::io::stdout().lock(), "{text}");
    }
    Ok(if report.is_success() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// The signals the tasks take from their use, for every task: a
/// controller's I/O configuration is one for all its tasks, so a name one
/// task uses as a signal (`GInput(giPart)`) is that signal where another
/// only reads it (`nPart := giPart`). A name taken as two kinds is the
/// stronger ([`rapid_runtime::SignalKind::strength`]), as within a task.
fn share_taken_signals(checks: &mut [rapid_runtime::LoadCheck]) {
    if checks.len() < 2 {
        return;
    }
    let mut all: Vec<rapid_runtime::TakenSignal> = Vec::new();
    for s in checks.iter().flat_map(|c| &c.signals) {
        match all
            .iter_mut()
            .find(|a| a.name.eq_ignore_ascii_case(&s.name))
        {
            Some(a) if s.kind.strength() > a.kind.strength() => a.kind = s.kind,
            Some(_) => {}
            None => all.push(s.clone()),
        }
    }
    for c in checks {
        c.signals.clone_from(&all);
    }
}

/// `--list-unsupported`: each call the simulation does not support, one
/// line each (`file:line:column: NAME`, named by its task when several),
/// then how many.
fn list_unsupported(loaded: &load::Loaded, sets: &[SignalChange]) {
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let several = loaded.tasks.len() > 1;
    let mut count = 0;
    for t in &loaded.tasks {
        let check = t.load_check();
        let program = load::program(t.task.clone(), sets, &check);
        for (name, at) in program.unsupported() {
            count += 1;
            let task = if several {
                format!(" [{}]", t.name)
            } else {
                String::new()
            };
            let _ = writeln!(out, "{}:{}:{}: {name}{task}", at.path, at.line, at.column);
        }
    }
    let _ = writeln!(
        out,
        "{count} call{} the simulation does not support",
        if count == 1 { "" } else { "s" }
    );
}

/// The lines that say how a run ended: the error and where, then the
/// active routines.
pub fn describe(o: &Outcome) -> Vec<String> {
    let mut lines = Vec::new();
    let head = match o.status {
        Status::Finished | Status::Exited | Status::Halted => return lines,
        Status::Stopped if o.message.is_empty() => "stopped (Stop)".to_owned(),
        Status::Stopped => format!("stopped: {}", o.message),
        Status::Error => match &o.errno {
            Some((_, name)) => format!("error: {name}: {}", o.message),
            None => format!("error: {}", o.message),
        },
        Status::Unsupported => format!("error: {}", o.message),
        Status::Invalid => format!("error: the program cannot run: {}", o.message),
        Status::Budget => format!("error: {}", o.message),
        Status::Deadlock => format!("error: deadlock: {}", o.message),
        Status::Operator => format!("stopped: {}", o.message),
    };
    lines.push(head);
    if let Some(at) = &o.at {
        lines.push(format!("  --> {}:{}:{}", at.path, at.line, at.column));
    }
    for f in &o.stack {
        lines.push(format!("  in {} ({})", f.routine, f.at));
    }
    if o.status == Status::Unsupported && o.message.contains(rapid_runtime::world::NO_KINEMATICS) {
        lines.push(
            "  = help: name a modelled robot with --robot (e.g. --robot \"IRB 1600-10/1.45\"), `robot` under [controller] in rapid.toml, or a backup's MOC.cfg".to_owned(),
        );
    }
    lines
}

/// The folder file instructions work in: the one given, or a temporary
/// one removed when the run is over.
pub struct Sandbox {
    pub path: PathBuf,
    temporary: bool,
}

impl Sandbox {
    /// [`Sandbox::new`]; a temporary folder starts as a copy of the
    /// controller's `home` (a backup's `HOME`), so file instructions read
    /// what the controller's `HOME:` held and never change the backup. A
    /// folder given is used as it is.
    pub fn seeded(given: Option<PathBuf>, home: Option<&Path>) -> Result<Sandbox, String> {
        let given_one = given.is_some();
        let sandbox = Sandbox::new(given)?;
        if let Some(home) = home.filter(|_| !given_one) {
            copy_folder(home, &sandbox.path)
                .map_err(|e| format!("{}: cannot copy into the sandbox: {e}", home.display()))?;
        }
        Ok(sandbox)
    }

    pub fn new(given: Option<PathBuf>) -> Result<Sandbox, String> {
        if let Some(path) = given {
            if !path.is_dir() {
                return Err(format!("--sandbox {}: not a folder", path.display()));
            }
            return Ok(Sandbox {
                path,
                temporary: false,
            });
        }
        let stamp = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        let path = std::env::temp_dir().join(format!("rapid-run-{}-{stamp}", std::process::id()));
        std::fs::create_dir_all(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        Ok(Sandbox {
            path,
            temporary: true,
        })
    }
}

/// Copies the files and folders of `from` into `to` (links are left out).
fn copy_folder(from: &Path, to: &Path) -> std::io::Result<()> {
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let kind = entry.file_type()?;
        let target = to.join(entry.file_name());
        if kind.is_dir() {
            std::fs::create_dir_all(&target)?;
            copy_folder(&entry.path(), &target)?;
        } else if kind.is_file() {
            std::fs::copy(entry.path(), &target)?;
        }
    }
    Ok(())
}

impl Drop for Sandbox {
    fn drop(&mut self) {
        if self.temporary {
            let _ = std::fs::remove_dir_all(&self.path);
        }
    }
}
