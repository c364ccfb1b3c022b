//! The `run` and `test` tools: `rapid run`'s and `rapid test`'s library
//! entry points ([`crate::run::run_loaded`], [`crate::test_cmd::run_tests`])
//! on tasks the project loader reads from the roots, as `rapid run`
//! loads them ([`load::controller_in`]: a backup's tasks together). Every run is bounded
//! (statements, simulated time, call depth, with budgets smaller than the
//! command line's by default and a ceiling on what a request may ask),
//! its file instructions work in a fresh temporary sandbox folder, and its
//! output is kept up to a number of lines.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use rapid_runtime::{Limits, Outcome, SignalChange, Status, Stream};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::roots::{Confined, resolve};
use super::{Answer, shown};
use crate::run::{Budget, load};
use crate::test_cmd::Verdict;

/// Statements a run may take unless the request says otherwise.
const DEFAULT_STEPS: u64 = 1_000_000;
/// The most statements a request may ask for.
const MAX_STEPS: u64 = 50_000_000;
/// Simulated seconds, by default and at most.
const DEFAULT_TIME: f64 = 600.0;
const MAX_TIME: f64 = 86_400.0;
/// Output lines kept from one run or test.
const OUTPUT_LINES: usize = 1000;

/// A signal set by the run's script.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SignalSet {
    /// The signal (from `EIO.cfg`; else declared by its name: `di*`,
    /// `do*`, `ai*`, `ao*`, `gi*`, `go*`).
    pub name: String,
    pub value: f64,
    /// When, in simulated seconds from the start (default 0).
    #[serde(default)]
    pub at: f64,
}

/// The budgets of a request.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Budgets {
    /// Statements (and loop iterations) before the run is stopped (default
    /// 1,000,000; at most 50,000,000).
    pub max_steps: Option<u64>,
    /// Simulated seconds before the run is stopped (default 600; at most
    /// 86,400).
    pub max_time: Option<f64>,
    /// Nested routine calls (default and at most 500).
    pub max_depth: Option<u32>,
}

impl Budgets {
    fn limits(&self) -> Result<Limits, String> {
        let steps = self.max_steps.unwrap_or(DEFAULT_STEPS);
        if steps == 0 || steps > MAX_STEPS {
            return Err(format!(
                "max_steps: {steps} is not between 1 and {MAX_STEPS}"
            ));
        }
        let time = self.max_time.unwrap_or(DEFAULT_TIME);
        if !(time > 0.0 && time <= MAX_TIME) {
            return Err(format!(
                "max_time: {time} is not between 0 and {MAX_TIME} seconds"
            ));
        }
        let depth_max = Limits::default().max_depth;
        let depth = self.max_depth.unwrap_or(depth_max);
        if depth == 0 || depth > depth_max {
            return Err(format!(
                "max_depth: {depth} is not between 1 and {depth_max}"
            ));
        }
        Ok(Limits {
            max_steps: steps,
            max_time: time,
            max_depth: depth,
            ..Limits::default()
        })
    }
}

fn script(signals: &[SignalSet]) -> Result<Vec<SignalChange>, String> {
    signals
        .iter()
        .map(|s| {
            load::parse_set(&format!("{}={}@{}", s.name, s.value, s.at))
                .map_err(|e| e.replace("--set ", "signals: "))
        })
        .collect()
}

/// Output lines, the first [`OUTPUT_LINES`] kept.
#[derive(Default)]
struct Lines {
    kept: Vec<(Stream, String)>,
    left_out: usize,
}

fn sink(lines: &Arc<Mutex<Lines>>) -> Box<dyn rapid_runtime::Output> {
    let lines = lines.clone();
    Box::new(move |stream: Stream, text: &str| {
        if let Ok(mut l) = lines.lock() {
            if l.kept.len() < OUTPUT_LINES {
                l.kept.push((stream, text.to_owned()));
            } else {
                l.left_out += 1;
            }
        }
    })
}

/// The arguments of `run`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RunParams {
    /// A module (run with the rest of its task), a task's folder, or a
    /// controller backup (its tasks run together, as `SYS.cfg` says).
    pub path: String,
    /// The procedure to run (without parameters; default `main`, or the
    /// entry routine `SYS.cfg` gives a backup's task).
    pub entry: Option<String>,
    /// Only this task of a backup (as `rapid run --task`).
    pub task: Option<String>,
    /// The signal script: values at the start and later.
    #[serde(default)]
    pub signals: Vec<SignalSet>,
    /// The run's budgets.
    #[serde(default)]
    pub budgets: Budgets,
    /// The operator's answers to the pendant's questions (`TPReadFK`,
    /// `UIMessageBox`...), in order: a key's number or label, a number, a
    /// button or list item, text; `@SECONDS VALUE` answers after a
    /// simulated delay, `-` never answers. A question without an answer
    /// stops the run waiting for the operator.
    #[serde(default)]
    pub answers: Vec<String>,
}

/// Where something happened.
#[derive(Debug, Serialize, JsonSchema)]
pub struct Place {
    pub file: String,
    pub line: usize,
    pub column: usize,
}

/// An active routine when the run stopped.
#[derive(Debug, Serialize, JsonSchema)]
pub struct Frame {
    pub routine: String,
    pub file: String,
    pub line: usize,
}

/// How a run that did not end normally stopped.
#[derive(Debug, Serialize, JsonSchema)]
pub struct RunError {
    pub message: String,
    /// The error's name (`ERR_DIVZERO`) for a RAPID error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub errno: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub at: Option<Place>,
    /// The routines active, innermost first.
    pub stack: Vec<Frame>,
}

/// A move of the robot.
#[derive(Debug, Serialize, JsonSchema)]
pub struct MoveInfo {
    pub instruction: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target: Option<String>,
    pub file: String,
    pub line: usize,
    /// The TCP's position in world coordinates, mm (none for `MoveAbsJ`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pos: Option<[f64; 3]>,
}

/// What the run did.
#[derive(Debug, Serialize, JsonSchema)]
pub struct TraceSummary {
    /// Statements executed.
    pub steps: u64,
    /// Simulated seconds at the end.
    pub simulated_seconds: f64,
    /// Moves, in all.
    pub moves: usize,
    /// Moves per instruction (`MoveL`: 12).
    pub by_instruction: BTreeMap<String, usize>,
    /// The first moves (at most 50).
    pub first_moves: Vec<MoveInfo>,
}

/// How one task of the run ended.
#[derive(Debug, Serialize, JsonSchema)]
pub struct TaskEnd {
    /// The task's name (`T_ROB1` for a lone program).
    pub name: String,
    /// As [`RunReport::status`], for this task.
    pub status: String,
    pub success: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<RunError>,
}

/// The answer of `run`.
#[derive(Debug, Serialize, JsonSchema)]
pub struct RunReport {
    /// `finished`, `exited`, `stopped`, `error`, `unsupported`, `invalid`,
    /// `budget` (a budget ran out), `deadlock` (a wait nothing can end),
    /// `operator` (a question nobody answered) or `halted` (a background
    /// task stopped when the others ended): of the first task that did not
    /// end normally (one waiting for another only when no task stopped
    /// otherwise), else of the first task.
    pub status: String,
    /// Whether every task ended normally (its end, `EXIT`, `Stop`).
    pub success: bool,
    /// Each task's end, in the controller's order (one for a lone
    /// program).
    pub tasks: Vec<TaskEnd>,
    /// Notes on the run: the signals no configuration declares, taken
    /// from their use.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    /// The pendant's and the event log's lines, in order.
    pub output: Vec<String>,
    /// Output lines left out past the first 1000.
    pub output_left_out: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<RunError>,
    pub trace: TraceSummary,
}

fn status_name(s: Status) -> &'static str {
    match s {
        Status::Finished => "finished",
        Status::Exited => "exited",
        Status::Stopped => "stopped",
        Status::Error => "error",
        Status::Unsupported => "unsupported",
        Status::Invalid => "invalid",
        Status::Budget => "budget",
        Status::Deadlock => "deadlock",
        Status::Halted => "halted",
        Status::Operator => "operator",
    }
}

fn place(roots: &[PathBuf], at: &rapid_runtime::Location) -> Place {
    Place {
        file: shown(roots, std::path::Path::new(&at.path)),
        line: at.line,
        column: at.column,
    }
}

fn run_error(roots: &[PathBuf], o: &Outcome) -> Option<RunError> {
    if matches!(o.status, Status::Finished | Status::Exited | Status::Halted) {
        return None;
    }
    Some(RunError {
        message: o.message.clone(),
        errno: o.errno.as_ref().map(|(_, name)| name.clone()),
        at: o.at.as_ref().map(|at| place(roots, at)),
        stack: o
            .stack
            .iter()
            .map(|f| Frame {
                routine: f.routine.clone(),
                file: shown(roots, std::path::Path::new(&f.at.path)),
                line: f.at.line,
            })
            .collect(),
    })
}

pub fn run(roots: &[PathBuf], params: RunParams) -> Result<Answer<RunReport>, String> {
    let limits = params.budgets.limits()?;
    let sets = script(&params.signals)?;
    let path = resolve(roots, &params.path)?;
    let env = Confined::new(roots.to_vec());
    let loaded = load::controller_in(&env, &path, params.task.as_deref(), params.entry.as_deref())
        .map_err(|e| shorten(&e, roots))?;
    let lines: Arc<Mutex<Lines>> = Arc::default();
    let ran = crate::run::run_loaded(
        &loaded,
        sets,
        Budget {
            limits,
            sandbox: None,
            home_roots: Some(roots.to_vec()),
            trace: true,
            answers: params.answers,
        },
        sink(&lines),
    )
    .map_err(|e| shorten(&e, roots))?;
    let (output, left_out) = lines
        .lock()
        .map(|l| (l.kept.iter().map(|(_, t)| t.clone()).collect(), l.left_out))
        .unwrap_or_default();
    let mut by_instruction = BTreeMap::new();
    let moves = &ran.report.moves;
    for m in moves {
        *by_instruction.entry(m.instruction.clone()).or_insert(0) += 1;
    }
    let tasks: Vec<TaskEnd> = ran
        .report
        .tasks
        .iter()
        .map(|(name, o)| TaskEnd {
            name: name.clone(),
            status: status_name(o.status).to_owned(),
            success: o.is_success(),
            error: run_error(roots, o),
        })
        .collect();
    // The task that stopped the run: one that did not end normally, one
    // left waiting for it (a deadlock) only when none other.
    let ended = &ran.report.tasks;
    let first = ended
        .iter()
        .position(|(_, o)| !o.is_success() && o.status != Status::Deadlock)
        .or_else(|| ended.iter().position(|(_, o)| !o.is_success()))
        .unwrap_or(0);
    let (status, error) = match ran.report.tasks.get(first) {
        Some((_, o)) => (status_name(o.status).to_owned(), run_error(roots, o)),
        None => ("finished".to_owned(), None),
    };
    let report = RunReport {
        status,
        success: ran.report.is_success(),
        tasks,
        notes: ran.report.notes.clone(),
        output,
        output_left_out: left_out,
        error,
        trace: TraceSummary {
            steps: ran.steps,
            simulated_seconds: ran.report.clock,
            moves: moves.len(),
            by_instruction,
            first_moves: moves
                .iter()
                .take(50)
                .map(|m| MoveInfo {
                    instruction: m.instruction.clone(),
                    target: m.target.clone(),
                    file: shown(roots, std::path::Path::new(&m.at.path)),
                    line: m.at.line,
                    pos: m.pos.map(|p| p.map(|x| (x * 1000.0).round() / 1000.0)),
                })
                .collect(),
        },
    };
    Ok(Answer::new(
        run_summary(&report, &ran.report, roots),
        report,
    ))
}

fn run_summary(r: &RunReport, ran: &crate::run::RunReport, roots: &[PathBuf]) -> String {
    let mut out = String::new();
    for l in &r.output {
        out.push_str(l);
        out.push('\n');
    }
    if r.output_left_out > 0 {
        out.push_str(&format!(
            "({} more output lines left out)\n",
            r.output_left_out
        ));
    }
    for line in ran.notes.iter().chain(&ran.describe()) {
        out.push_str(&shorten(line, roots));
        out.push('\n');
    }
    out.push_str(&format!(
        "run {}: {} statements, {:.3} s simulated, {} move{}\n",
        r.status,
        r.trace.steps,
        r.trace.simulated_seconds,
        r.trace.moves,
        super::check::plural(r.trace.moves)
    ));
    out
}

/// A line with the roots' paths made relative.
fn shorten(line: &str, roots: &[PathBuf]) -> String {
    roots.iter().fold(line.to_owned(), |l, r| {
        l.replace(&format!("{}{}", r.display(), std::path::MAIN_SEPARATOR), "")
    })
}

/// The arguments of `test`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TestParams {
    /// A module (its task) or a folder (every task under it). Tests are
    /// procedures without parameters named `test_...`, or any such
    /// procedure of a module whose name ends with `_test`; a module's
    /// `setup` and `teardown` run around each. The assertion module
    /// `RapidAssert` (`AssertEqual`, `AssertTrue`, `AssertNear`...) is
    /// loaded with every task that lacks it.
    pub path: String,
    /// Only tests whose `module.name` contains this text.
    pub filter: Option<String>,
    /// A signal script for every test.
    #[serde(default)]
    pub signals: Vec<SignalSet>,
    /// The budgets of each test.
    #[serde(default)]
    pub budgets: Budgets,
}

/// One test's result.
#[derive(Debug, Serialize, JsonSchema)]
pub struct TestInfo {
    pub module: String,
    pub name: String,
    pub file: String,
    pub line: usize,
    /// `pass`, `fail` (an error no handler took, a failed assertion) or
    /// `error` (a budget, an unsupported instruction, `Stop`).
    pub result: String,
    /// Why it failed (the assertion's message).
    #[serde(skip_serializing_if = "String::is_empty")]
    pub message: String,
    /// Where it failed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub at: Option<Place>,
    /// Its output lines.
    pub output: Vec<String>,
    pub milliseconds: f64,
}

/// The answer of `test`.
#[derive(Debug, Serialize, JsonSchema)]
pub struct TestReport {
    pub tests: Vec<TestInfo>,
    pub passed: usize,
    pub failed: usize,
    pub errors: usize,
    /// Every test passed (and there was one).
    pub success: bool,
}

pub fn test(roots: &[PathBuf], params: TestParams) -> Result<Answer<TestReport>, String> {
    let limits = params.budgets.limits()?;
    let sets = script(&params.signals)?;
    let path = resolve(roots, &params.path)?;
    let env = Confined::new(roots.to_vec());
    let found = load::tasks_in(&env, std::slice::from_ref(&path))?;
    let results = crate::test_cmd::run_tests(
        &found.tasks,
        &crate::test_cmd::TestOptions {
            filter: params.filter.clone(),
            sets,
            limits,
            sandbox: None,
            home_roots: Some(roots.to_vec()),
        },
        &mut |_| {},
    )?;
    let count = |v: Verdict| results.iter().filter(|r| r.verdict == v).count();
    let report = TestReport {
        passed: count(Verdict::Pass),
        failed: count(Verdict::Fail),
        errors: count(Verdict::Error),
        success: !results.is_empty() && results.iter().all(|r| r.verdict == Verdict::Pass),
        tests: results
            .iter()
            .map(|r| TestInfo {
                module: r.module.clone(),
                name: r.name.clone(),
                file: shown(roots, std::path::Path::new(&r.at.path)),
                line: r.at.line,
                result: match r.verdict {
                    Verdict::Pass => "pass",
                    Verdict::Fail => "fail",
                    Verdict::Error => "error",
                }
                .to_owned(),
                message: r.message.clone(),
                at: r.failed_at.as_ref().map(|at| place(roots, at)),
                output: r.output.iter().take(OUTPUT_LINES).cloned().collect(),
                milliseconds: r.duration.as_secs_f64() * 1e3,
            })
            .collect(),
    };
    let mut human = Vec::new();
    let _ = crate::test_cmd::report::human(&mut human, &results);
    let summary = shorten(&String::from_utf8_lossy(&human), roots);
    Ok(Answer::new(summary, report))
}
