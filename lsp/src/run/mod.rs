//! `rapid run`: runs a task's entry routine on the simulated controller.
//!
//! The program's output (`TPWrite`, `ErrWrite`) goes to stdout, one line
//! each; how the run ended goes to stderr when it did not end normally,
//! with the error's name, message, line and the active routines. Exit
//! status: 0 when the run ends normally (its end, `EXIT`, `Stop`), 1 when
//! it ends otherwise, 2 for usage errors and programs that cannot be
//! loaded.

pub mod load;
pub mod trace;

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;

use rapid_runtime::{Config, Limits, Machine, Outcome, Status, Stream};

#[derive(Debug, clap::Args)]
pub struct RunArgs {
    /// A module (run with the rest of its task) or a task's folder.
    pub path: PathBuf,
    /// The procedure to run.
    #[arg(long, default_value = "main", value_name = "NAME")]
    pub entry: String,
    /// Set a signal: NAME=VALUE at the start, NAME=VALUE@SECONDS later
    /// (repeatable). Signals that EIO.cfg does not declare are declared by
    /// their name: di*, do*, ai*, ao*, gi*, go* (else a digital input).
    #[arg(long = "set", value_name = "SIG=V[@T]")]
    pub set: Vec<String>,
    /// Write the motion as JSON.
    #[arg(long, value_name = "FILE")]
    pub trace: Option<PathBuf>,
    /// Draw the motion in 3D in a self-contained HTML page.
    #[arg(long, value_name = "FILE.html")]
    pub plot: Option<PathBuf>,
    /// The folder file instructions work in (default: a fresh temporary
    /// folder, removed after the run).
    #[arg(long, value_name = "DIR")]
    pub sandbox: Option<PathBuf>,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// The budgets of a run.
#[derive(Debug, Clone, clap::Args)]
pub struct LimitArgs {
    /// Stop after this many statements.
    #[arg(long, default_value_t = Limits::default().max_steps, value_name = "N")]
    pub max_steps: u64,
    /// Stop after this many seconds of simulated time.
    #[arg(long, default_value_t = Limits::default().max_time, value_name = "SECONDS")]
    pub max_time: f64,
    /// Stop beyond this many nested routine calls.
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

pub fn run(args: RunArgs) -> ExitCode {
    let mut stderr = anstream::stderr();
    match run_inner(args) {
        Ok(code) => code,
        Err(message) => {
            let _ = writeln!(stderr, "rapid: run: {message}");
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
    let task = load::one_task(&args.path, &args.entry)?;
    let out = |_: Stream, line: &str| {
        let stdout = std::io::stdout();
        let mut lock = stdout.lock();
        let _ = writeln!(lock, "{line}");
    };
    let ran = run_routine(
        task,
        &args.entry,
        sets,
        Budget {
            limits: args.limits.limits(),
            sandbox: args.sandbox.clone(),
            trace: args.trace.is_some() || args.plot.is_some(),
        },
        Box::new(out),
    )?;
    if let Some(path) = &args.trace {
        let text = serde_json::to_string_pretty(&trace::json(&ran.moves)).unwrap_or_default();
        std::fs::write(path, text + "\n").map_err(|e| format!("{}: {e}", path.display()))?;
    }
    if let Some(path) = &args.plot {
        let title = args.path.display().to_string();
        std::fs::write(path, trace::html(&ran.moves, &title))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    report(&ran.outcome);
    Ok(if ran.outcome.is_success() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// What a run may use: its budgets, the folder its file instructions work
/// in (a fresh temporary one, removed after the run, when `None`), and
/// whether its moves are recorded.
pub struct Budget {
    pub limits: Limits,
    pub sandbox: Option<PathBuf>,
    pub trace: bool,
}

/// A run that ended: how, the moves (when traced), the statements it took
/// and the simulated time it reached.
pub struct Ran {
    pub outcome: Outcome,
    pub moves: Vec<rapid_runtime::Move>,
    pub steps: u64,
    pub clock: f64,
}

/// Runs the procedure `entry` of `task` with the signal script `sets`,
/// each output line going to `out` as it comes (for `rapid run` and
/// `rapid mcp`). An error when the procedure is missing or takes
/// parameters, or the sandbox cannot be made.
pub fn run_routine(
    task: Arc<rapid_analyzer::task::Task>,
    entry: &str,
    sets: Vec<rapid_runtime::SignalChange>,
    budget: Budget,
    out: Box<dyn rapid_runtime::Output>,
) -> Result<Ran, String> {
    let key = task.key.clone();
    let program = load::program(task, &sets);
    let id = program
        .find_routine(entry)
        .ok_or_else(|| match key.as_str() {
            "" => format!("no procedure {entry} in the task"),
            key => format!("{key}: no procedure {entry} in the task"),
        })?;
    if let Some(r) = program.routines().into_iter().find(|r| r.id == id)
        && (r.params > 0 || r.kind != rapid_analyzer::items::RoutineKind::Proc)
    {
        return Err(format!(
            "{}: {} is not a procedure without parameters",
            r.at, r.name
        ));
    }
    let sandbox = Sandbox::new(budget.sandbox)?;
    let config = Config {
        limits: budget.limits,
        signals: sets,
        sandbox: Some(sandbox.path.clone()),
        trace: budget.trace,
    };
    rapid_runtime::on_large_stack(move || {
        let mut m = Machine::new(program, config, out);
        let outcome = m.run(id);
        Ran {
            outcome,
            moves: m.moves().to_vec(),
            steps: m.steps(),
            clock: m.clock(),
        }
    })
    .ok_or_else(|| "the interpreter failed (this is a bug in rapid)".to_owned())
}

/// How the run ended, on stderr (nothing for a normal end).
pub fn report(outcome: &Outcome) {
    let mut err = anstream::stderr();
    for line in describe(outcome) {
        let _ = writeln!(err, "{line}");
    }
}

/// The lines that say how a run ended: the error and where, then the
/// active routines.
pub fn describe(o: &Outcome) -> Vec<String> {
    let mut lines = Vec::new();
    let head = match o.status {
        Status::Finished | Status::Exited => return lines,
        Status::Stopped => "stopped (Stop)".to_owned(),
        Status::Error => match &o.errno {
            Some((_, name)) => format!("error: {name}: {}", o.message),
            None => format!("error: {}", o.message),
        },
        Status::Unsupported => format!("error: {}", o.message),
        Status::Invalid => format!("error: the program cannot run: {}", o.message),
        Status::Budget => format!("error: {}", o.message),
        Status::Deadlock => format!("error: {}", o.message),
    };
    lines.push(head);
    if let Some(at) = &o.at {
        lines.push(format!("  --> {}:{}:{}", at.path, at.line, at.column));
    }
    for f in &o.stack {
        lines.push(format!("  in {} ({})", f.routine, f.at));
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

impl Drop for Sandbox {
    fn drop(&mut self) {
        if self.temporary {
            let _ = std::fs::remove_dir_all(&self.path);
        }
    }
}
