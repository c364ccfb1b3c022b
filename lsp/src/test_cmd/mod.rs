//! `rapid test`: finds the test routines of the tasks under the paths and
//! runs each on a fresh simulated controller.
//!
//! The convention: a test is a procedure without parameters that is named
//! `test_...` (any letter case), or any procedure without parameters in a
//! module whose name ends with `_test`. A module's procedure `setup` runs
//! before each of its tests and `teardown` after each (also when the test
//! failed). The assertion module `RapidAssert` (`RapidAssert.sys`, shipped
//! inside `rapid`) is loaded with every task that does not declare its
//! routines itself.
//!
//! A test passes when it returns (or `EXIT`s); it fails on an error no
//! handler takes (an assertion's `ERR_ASSERT` among them), with its line
//! and `ERRNO`; anything else (an unsupported instruction, a budget run
//! out, `Stop`, a program that cannot run) is an error. Exit status: 0
//! when every test passed, 1 when one failed or had an error (or none was
//! found), 2 for usage errors.

pub mod report;

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use rapid_analyzer::items::RoutineKind;
use rapid_runtime::world::{InstantRobot, World};
use rapid_runtime::{
    Config, Controller, Outcome, Program, SignalChange, Status, Stream, TaskKind, TaskSpec,
};

use crate::run::{LimitArgs, Sandbox, load};

/// The assertion module shipped with `rapid test`.
pub const ASSERT_MODULE: &str = include_str!("RapidAssert.sys");
/// The path the assertion module is known by in messages.
pub const ASSERT_PATH: &str = "<rapid>/RapidAssert.sys";

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A line per test, the failures explained, a summary.
    Human,
    /// One JSON document with every test.
    Json,
    /// JUnit XML, for CI dashboards.
    Junit,
}

#[derive(Debug, clap::Args)]
pub struct TestArgs {
    /// Modules and folders (default: the current folder).
    pub paths: Vec<PathBuf>,
    /// Print the assertion module (RapidAssert.sys) and exit: save it with
    /// your tests so that `rapid check` and the editor know its routines.
    #[arg(long)]
    pub assert_module: bool,
    /// How to report.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
    /// Run only the tests whose name (or `module.name`) contains this text
    /// (any letter case).
    #[arg(long, value_name = "TEXT")]
    pub filter: Option<String>,
    /// Set a signal for every test: NAME=VALUE[@SECONDS] (repeatable).
    #[arg(long = "set", value_name = "SIG=V[@T]")]
    pub set: Vec<String>,
    /// The folder file instructions work in (default: a fresh temporary
    /// folder per test, holding a copy of the controller's `HOME`).
    #[arg(long, value_name = "DIR")]
    pub sandbox: Option<PathBuf>,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// What happened to one test.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    Pass,
    Fail,
    Error,
}

pub struct TestResult {
    pub module: String,
    pub name: String,
    pub at: rapid_runtime::Location,
    pub verdict: Verdict,
    pub outcome: Outcome,
    /// A sentence for a failure or an error (the assertion's message for
    /// `ERR_ASSERT`).
    pub message: String,
    /// Where it failed: the innermost line outside the assertion module.
    pub failed_at: Option<rapid_runtime::Location>,
    pub output: Vec<String>,
    pub duration: Duration,
}

pub fn run(args: TestArgs) -> ExitCode {
    match run_inner(args) {
        Ok(code) => code,
        Err(message) => {
            let _ = writeln!(anstream::stderr(), "rapid: test: {message}");
            ExitCode::from(2)
        }
    }
}

fn run_inner(args: TestArgs) -> Result<ExitCode, String> {
    if args.assert_module {
        let mut out = std::io::stdout().lock();
        return match out.write_all(ASSERT_MODULE.as_bytes()) {
            Ok(()) => Ok(ExitCode::SUCCESS),
            Err(e) => Err(format!("cannot write the module: {e}")),
        };
    }
    let sets = args
        .set
        .iter()
        .map(|s| load::parse_set(s))
        .collect::<Result<Vec<_>, _>>()?;
    let paths = if args.paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        args.paths.clone()
    };
    let found = load::tasks(&paths)?;
    for (path, why) in &found.skipped {
        let _ = writeln!(anstream::stderr(), "rapid: test: {}: {why}", path.display());
    }
    let options = TestOptions {
        filter: args.filter.clone(),
        sets,
        limits: args.limits.limits(),
        sandbox: args.sandbox.clone(),
        home_roots: None,
    };
    let results = run_tests(&found.tasks, &options, &mut |e| {
        let _ = writeln!(anstream::stderr(), "rapid: test: {e}");
    })?;
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let written = match args.format {
        Format::Human => report::human(&mut out, &results),
        Format::Json => report::json(&mut out, &results),
        Format::Junit => report::junit(&mut out, &results),
    };
    if let Err(e) = written.and_then(|()| out.flush())
        && e.kind() != std::io::ErrorKind::BrokenPipe
    {
        return Err(format!("cannot write the report: {e}"));
    }
    let all_passed = !results.is_empty() && results.iter().all(|r| r.verdict == Verdict::Pass);
    Ok(if all_passed {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// How to run tests.
#[derive(Clone, Debug, Default)]
pub struct TestOptions {
    /// Only the tests whose name (or `module.name`) contains this text.
    pub filter: Option<String>,
    /// Scripted signal changes, for every test.
    pub sets: Vec<SignalChange>,
    pub limits: rapid_runtime::Limits,
    /// The folder file instructions work in (default: a fresh temporary
    /// folder per test, holding a copy of the controller's `HOME`).
    pub sandbox: Option<PathBuf>,
    /// The folders the controller's `HOME` may be copied from (`None`:
    /// wherever it is).
    pub home_roots: Option<Vec<PathBuf>>,
}

/// Runs the tests of `tasks` (the library entry point of `rapid test`):
/// each task with the assertion module, each test on a fresh controller.
/// The tests of a task the controller would not load are errors, and
/// `load_error` is told each of its errors.
pub fn run_tests(
    tasks: &[Arc<rapid_analyzer::task::Task>],
    options: &TestOptions,
    load_error: &mut dyn FnMut(&rapid_runtime::LoadError),
) -> Result<Vec<TestResult>, String> {
    let mut results = Vec::new();
    for (task, program) in tasks.iter().flat_map(programs_of) {
        let first = results.len();
        run_task_tests(&task, options, load_error, &mut results)?;
        // A folder of alternative programs: each test says which it ran in.
        if let Some(program) = program {
            for r in &mut results[first..] {
                r.module = format!("{} [{program}]", r.module);
            }
        }
    }
    Ok(results)
}

/// The programs a task holds: itself, or, for a folder of alternative
/// programs (modules that cannot be loaded together, as `rapid check`
/// tells them apart), each view with the file name of the module it is
/// made for. A module the alternatives share runs its tests in each.
fn programs_of(
    task: &Arc<rapid_analyzer::task::Task>,
) -> Vec<(Arc<rapid_analyzer::task::Task>, Option<String>)> {
    let views = load::views(task, |_| true);
    if views.is_empty() {
        return vec![(task.clone(), None)];
    }
    views
        .into_iter()
        .map(|(unit, view)| {
            let name = unit.path.rsplit(['/', '\\']).next().unwrap_or(&unit.path);
            (view, Some(name.to_owned()))
        })
        .collect()
}

/// The tests of one task (or view), added to `results`.
fn run_task_tests(
    task: &Arc<rapid_analyzer::task::Task>,
    options: &TestOptions,
    load_error: &mut dyn FnMut(&rapid_runtime::LoadError),
    results: &mut Vec<TestResult>,
) -> Result<(), String> {
    let home = load::home_within(&task.key, options.home_roots.as_deref());
    let task = load::with_modules(task, &[(ASSERT_PATH, ASSERT_MODULE)]);
    let check = rapid_runtime::load_check(&task);
    let program = load::program(task, &options.sets, &check);
    let errors = check.errors;
    let tests = discover(&program, options.filter.as_deref());
    if let Some(first) = errors.first() {
        // The controller would not load the task: none of its tests runs.
        for e in &errors {
            load_error(e);
        }
        for test in &tests {
            results.push(not_loaded(test, first));
        }
        return Ok(());
    }
    for test in tests {
        results.push(run_test(&program, &test, options, home.as_deref())?);
    }
    Ok(())
}

/// A test routine, with the module's `setup` and `teardown`.
pub struct Test {
    pub id: u32,
    pub name: String,
    pub module: String,
    pub at: rapid_runtime::Location,
    pub setup: Option<u32>,
    pub teardown: Option<u32>,
}

/// The tests of a program, by the convention above, in the task's order.
pub fn discover(program: &Program, filter: Option<&str>) -> Vec<Test> {
    let routines = program.routines();
    let hook = |module: &str, name: &str| {
        routines
            .iter()
            .find(|r| {
                r.module == module
                    && r.kind == RoutineKind::Proc
                    && r.params == 0
                    && r.name.eq_ignore_ascii_case(name)
            })
            .map(|r| r.id)
    };
    let filter = filter.map(str::to_ascii_lowercase);
    routines
        .iter()
        .filter(|r| r.kind == RoutineKind::Proc && r.params == 0 && r.at.path != ASSERT_PATH)
        .filter(|r| {
            let name = r.name.to_ascii_lowercase();
            let in_test_module = r.module.to_ascii_lowercase().ends_with("_test");
            name.starts_with("test_") || (in_test_module && name != "setup" && name != "teardown")
        })
        .filter(|r| {
            filter.as_ref().is_none_or(|f| {
                format!("{}.{}", r.module, r.name)
                    .to_ascii_lowercase()
                    .contains(f.as_str())
            })
        })
        .map(|r| Test {
            id: r.id,
            name: r.name.clone(),
            module: r.module.clone(),
            at: r.at.clone(),
            setup: hook(&r.module, "setup"),
            teardown: hook(&r.module, "teardown"),
        })
        .collect()
}

fn run_test(
    program: &Arc<Program>,
    test: &Test,
    options: &TestOptions,
    home: Option<&std::path::Path>,
) -> Result<TestResult, String> {
    let sandbox = Sandbox::seeded(options.sandbox.clone(), home)?;
    let config = Config {
        limits: options.limits.clone(),
        signals: options.sets.clone(),
        sandbox: Some(sandbox.path.clone()),
        trace: false,
        ..Config::default()
    };
    let lines: Arc<Mutex<Vec<(Stream, String)>>> = Arc::default();
    let sink = lines.clone();
    let out = move |s: Stream, line: &str| {
        if let Ok(mut l) = sink.lock() {
            l.push((s, line.to_owned()));
        }
    };
    let started = Instant::now();
    let world = World::simulated(&config, Box::new(out));
    let mut c = Controller::new(config, world);
    c.add_task(TaskSpec {
        name: "T_ROB1".to_owned(),
        program: program.clone(),
        entry: None,
        kind: TaskKind::Normal,
        robot: Some(Box::new(InstantRobot::new())),
    });
    let mut run = |routine: u32| -> Outcome {
        if let Err(why) = c.start_routine(0, routine) {
            return Outcome {
                status: Status::Invalid,
                message: why,
                errno: None,
                at: None,
                stack: Vec::new(),
            };
        }
        c.run();
        c.tasks()
            .first()
            .and_then(|t| t.outcome().cloned())
            .unwrap_or_else(|| Outcome {
                status: Status::Invalid,
                message: "the test did not end".to_owned(),
                errno: None,
                at: None,
                stack: Vec::new(),
            })
    };
    let mut outcome = run(test.setup.unwrap_or(test.id));
    if test.setup.is_some() && outcome.is_success() {
        outcome = run(test.id);
    }
    if let Some(t) = test.teardown {
        let after = run(t);
        if outcome.is_success() {
            outcome = after;
        }
    }
    let duration = started.elapsed();
    drop(sandbox);
    let lines = lines.lock().map(|l| l.clone()).unwrap_or_default();
    Ok(judge(test, outcome, lines, duration))
}

/// The result of a test of a task the controller would not load.
fn not_loaded(test: &Test, error: &rapid_runtime::LoadError) -> TestResult {
    let outcome = Outcome {
        status: Status::Invalid,
        message: format!("the controller would not load the task: {error}"),
        errno: None,
        at: Some(error.at.clone()),
        stack: Vec::new(),
    };
    judge(test, outcome, Vec::new(), Duration::ZERO)
}

fn judge(
    test: &Test,
    outcome: Outcome,
    lines: Vec<(Stream, String)>,
    duration: Duration,
) -> TestResult {
    let verdict = match outcome.status {
        Status::Finished | Status::Exited | Status::Halted => Verdict::Pass,
        Status::Error => Verdict::Fail,
        _ => Verdict::Error,
    };
    let assertion = outcome
        .errno
        .as_ref()
        .is_some_and(|(_, n)| n.eq_ignore_ascii_case("ERR_ASSERT"));
    let message = match verdict {
        Verdict::Pass => String::new(),
        _ if assertion => lines
            .iter()
            .rev()
            .find(|(s, _)| *s == Stream::EventLog)
            .map(|(_, l)| {
                l.split_once("Assertion failed: ")
                    .map_or(l.as_str(), |(_, m)| m)
                    .to_owned()
            })
            .unwrap_or_else(|| "assertion failed".to_owned()),
        _ => match (&outcome.status, &outcome.errno) {
            (Status::Stopped, _) => "the test stopped (Stop)".to_owned(),
            (_, Some((_, name))) => format!("{name}: {}", outcome.message),
            _ => outcome.message.clone(),
        },
    };
    let failed_at = outcome
        .stack
        .iter()
        .find(|f| f.at.path != ASSERT_PATH)
        .map(|f| f.at.clone())
        .or_else(|| outcome.at.clone());
    TestResult {
        module: test.module.clone(),
        name: test.name.clone(),
        at: test.at.clone(),
        verdict,
        message,
        failed_at: if verdict == Verdict::Pass {
            None
        } else {
            failed_at
        },
        output: lines.into_iter().map(|(_, l)| l).collect(),
        outcome,
        duration,
    }
}
