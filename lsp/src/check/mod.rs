//! `rapid check`: find RAPID files, analyse them, report what is wrong.
//!
//! The run ([`run`], in named steps): resolve `rapid.toml` and the flags
//! ([`LintSettings`]), find the files through the project loader
//! ([`crate::project`]), read and parse them in parallel, group them into
//! tasks with the modules and `EIO.cfg` of `extra-paths`, check every task
//! in parallel ([`check_files`]), keep what the settings and the inline
//! suppressions select ([`LintSettings::apply`]), optionally apply the
//! safe fixes and check again, and print the report in the chosen format.

mod baseline;
mod fix;
mod output;
mod run;
mod settings;
mod suppress;
#[cfg(test)]
mod tests;

use std::collections::{HashMap, HashSet};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rapid_analyzer::check::StmtCache;
use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use rapid_analyzer::rules::Selection;
use rapid_analyzer::task::Unit;
use rapid_analyzer::workspace::diagnostics_selected;
use rayon::prelude::*;

use crate::project::{Discovery, Environment, SourceFile, Sources};

pub use crate::project::Skip;
pub use fix::apply_safe_fixes;
pub use run::{load_in, report_in, run};
pub use settings::{LintSettings, Overrides, normalize};

/// Output formats of `rapid check`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// The source line with the problem underlined, and a summary.
    #[default]
    Human,
    /// One line per diagnostic: `file:line:column: severity[code] message (name)`.
    Concise,
    /// A JSON array of diagnostics.
    Json,
    /// SARIF 2.1.0, for GitHub code scanning and other SARIF viewers.
    Sarif,
    /// GitHub Actions workflow commands: annotations on the changed lines.
    Github,
    /// JUnit XML, for CI test reports: a test suite per file.
    Junit,
}

#[derive(Debug, Default, clap::Args)]
pub struct CheckArgs {
    /// Files or folders to check (default: the current folder).
    pub paths: Vec<PathBuf>,
    /// How to print the diagnostics.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
    /// The configuration file to use instead of the `rapid.toml` found
    /// upwards from the first path.
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Report only these rules (codes, code prefixes or names; replaces
    /// `select` of rapid.toml).
    #[arg(long, value_delimiter = ',', value_name = "RULE")]
    pub select: Vec<String>,
    /// Do not report these rules (added to `ignore` of rapid.toml).
    #[arg(long, value_delimiter = ',', value_name = "RULE")]
    pub ignore: Vec<String>,
    /// Leave out files and folders matching these globs (added to `exclude`
    /// of rapid.toml).
    #[arg(long, value_delimiter = ',', value_name = "GLOB")]
    pub exclude: Vec<String>,
    /// More folders holding modules or `EIO.cfg` of the program: analysed
    /// with the checked files, not reported (added to `extra-paths`).
    #[arg(long, value_name = "PATH")]
    pub extra_path: Vec<PathBuf>,
    /// Print how many diagnostics each rule gave instead of the diagnostics.
    #[arg(long)]
    pub statistics: bool,
    /// Exit with 0 even when errors were found (2 still means a usage,
    /// configuration or IO problem).
    #[arg(long, conflicts_with = "error_on_warnings")]
    pub exit_zero: bool,
    /// Exit with 1 when warnings were found, not only errors.
    #[arg(long)]
    pub error_on_warnings: bool,
    /// Apply the safe fixes, write the files back, and report what remains.
    #[arg(long)]
    pub fix: bool,
    /// Report only findings at least this severe (error, warning, info or
    /// hint). Syntax errors are always reported.
    #[arg(long, value_name = "LEVEL", value_parser = parse_severity)]
    pub min_severity: Option<Severity>,
    /// Report only findings that are not in this baseline file. When the
    /// file does not exist, it is written with today's findings and none is
    /// reported (see the README: adopting the linter on a project).
    #[arg(long, value_name = "FILE")]
    pub baseline: Option<PathBuf>,
    /// With `--baseline`: write the file again with today's findings.
    #[arg(long, requires = "baseline")]
    pub update_baseline: bool,
    /// Threads to check with (default: one per core).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Print the time each phase took to stderr (for benchmarks).
    #[arg(long, hide = true)]
    pub timings: bool,
}

fn parse_severity(s: &str) -> Result<Severity, String> {
    Severity::parse(s).ok_or_else(|| format!("`{s}` is not error, warning, info or hint"))
}

/// Phase timings of the last run, for `--timings`.
static TIMINGS: std::sync::Mutex<Vec<(&'static str, std::time::Duration)>> =
    std::sync::Mutex::new(Vec::new());

/// Records that `phase` took the time since `*since`, and restarts it.
fn lap(phase: &'static str, since: &mut std::time::Instant) {
    let now = std::time::Instant::now();
    if let Ok(mut t) = TIMINGS.lock() {
        t.push((phase, now - *since));
    }
    *since = now;
}

/// A file that was checked, with its diagnostics in source order.
pub struct Checked {
    pub file: SourceFile,
    pub diagnostics: Vec<Diagnostic>,
}

/// What happened to each file: checked, or skipped with a reason.
pub enum Outcome {
    Checked(Checked),
    Skipped(PathBuf, Skip),
}

/// The result of a run, as the formats print it.
pub struct Report {
    /// Files checked, in path order, with the diagnostics to report.
    pub checked: Vec<Checked>,
    /// Files not checked, with the reason.
    pub skipped: Vec<(PathBuf, String)>,
    /// Fixes applied by `--fix`.
    pub fixed: usize,
    /// Findings left out because the baseline holds them.
    pub baselined: usize,
}

/// A progress bar on stderr for long runs on a terminal; hidden in pipes,
/// files and CI logs.
fn progress_bar(files: usize) -> ProgressBar {
    const LONG_RUN: usize = 200;
    let visible =
        files >= LONG_RUN && std::io::stderr().is_terminal() && std::env::var_os("CI").is_none();
    if !visible {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(2 * files as u64), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template("{spinner} checking {bar:30} {pos}/{len}") {
        bar.set_style(style);
    }
    bar
}

/// Reads and checks every file of `found`, in parallel, keeping the order
/// of its files. Files are grouped into tasks as the analyzer does; its
/// `configs` are the I/O configuration files whose signals and mechanical
/// units the tasks below them may use; its `programs` are `.pgf` files that
/// group modules into a task. The rest of the checked files' tasks
/// (`context`, [`crate::project::context::task_context`]) and the modules and configuration
/// of `extra` join the tasks (the tasks they belong to when those are
/// checked, else, for `extra`, every checked task) but are not reported.
/// Diagnostics are the analyzer's for the rules `selection` has on for
/// each file (the settings' severities and suppressions are not applied).
///
/// The project is checked in parts that share no task
/// ([`crate::project::parts`]), each read, parsed, checked and dropped on
/// its own, so that memory follows the parts in progress, not the project.
/// A part keeps its files' syntax trees from the parse to the check while
/// the parts in progress keep less than [`KEEP_TREES`] bytes of text in
/// trees; a larger part releases each tree once its items are lowered and
/// parses each file again for its check.
pub fn check_files(
    env: &dyn Environment,
    found: &Discovery,
    context: &Discovery,
    extra: &Discovery,
    controller: &rapid_analyzer::controller::ControllerOverride,
    selection: &(dyn Fn(&std::path::Path) -> Selection + Sync),
    progress: &ProgressBar,
) -> Vec<Outcome> {
    let project = Project {
        env,
        found,
        context,
        extra,
        controller,
    };
    check_in_parts(&project, selection, progress, KEEP_TREES)
}

/// What [`check_files`] checks.
struct Project<'a> {
    env: &'a dyn Environment,
    found: &'a Discovery,
    context: &'a Discovery,
    extra: &'a Discovery,
    controller: &'a rapid_analyzer::controller::ControllerOverride,
}

/// [`check_files`], keeping the trees of parts in progress up to
/// `keep_trees` bytes of text.
fn check_in_parts(
    project: &Project<'_>,
    selection: &(dyn Fn(&std::path::Path) -> Selection + Sync),
    progress: &ProgressBar,
    keep_trees: u64,
) -> Vec<Outcome> {
    let Project {
        env,
        found,
        context,
        extra,
        controller: _,
    } = *project;
    let mut clock = std::time::Instant::now();
    // The checker needs the catalogue (some milliseconds to load): load it
    // on a thread that parsing leaves idle (a single large file is parsed
    // on one thread).
    rayon::spawn(|| {
        let _ = rapid_analyzer::catalogue::base();
    });
    let split = crate::project::parts::split(env, found, context);
    let extra = crate::project::parts::read_extra(env, extra, &split.names);
    lap("discovery of the parts, extra paths", &mut clock);
    let kept = AtomicU64::new(0);
    let mut results: Vec<PartResult> = split
        .parts
        .par_iter()
        .map(|part| {
            // Trees kept from parse to check while the parts in progress
            // keep few enough; else released and parsed again.
            let keep = kept.fetch_add(part.bytes, Ordering::Relaxed) + part.bytes <= keep_trees;
            if !keep {
                kept.fetch_sub(part.bytes, Ordering::Relaxed);
            }
            let result = check_part(project, part, &split, &extra, selection, keep, progress);
            if keep {
                kept.fetch_sub(part.bytes, Ordering::Relaxed);
            }
            result
        })
        .collect();
    lap("reading, parsing and checking", &mut clock);
    let mut outcomes: Vec<Option<Outcome>> = found.files.iter().map(|_| None).collect();
    for result in &mut results {
        for (position, outcome) in result.outcomes.drain(..) {
            if let Some(slot) = outcomes.get_mut(position) {
                *slot = Some(outcome);
            }
        }
    }
    outcomes
        .into_iter()
        .zip(&found.files)
        .map(|(o, path)| {
            o.unwrap_or_else(|| {
                Outcome::Skipped(
                    path.clone(),
                    Skip::Unreadable(crate::project::Unreadable::Io(std::io::Error::other(
                        "not read",
                    ))),
                )
            })
        })
        .collect()
}

/// The most bytes of text whose syntax trees the parts in progress keep
/// from their parse to their check (trees take about 20 times their text).
pub const KEEP_TREES: u64 = 2 * 1024 * 1024;

/// The outcome of each file of a part, by its place in the project's list.
struct PartResult {
    outcomes: Vec<(usize, Outcome)>,
}

/// Reads, parses and checks one part of the project ([`check_files`]).
fn check_part(
    project: &Project<'_>,
    part: &crate::project::parts::Part,
    split: &crate::project::parts::Split,
    extra: &crate::project::parts::Extra,
    selection: &(dyn Fn(&std::path::Path) -> Selection + Sync),
    keep: bool,
    progress: &ProgressBar,
) -> PartResult {
    let (env, controller) = (project.env, project.controller);
    let files = &part.found.files;
    let (read, units) = crate::project::read_and_parse_with(env, files, &|| progress.inc(1), !keep);
    let sources = Sources {
        found: Some(&part.found),
        context: Some(&part.context),
        extra: None,
    };
    let crate::project::Loaded {
        mut workspace,
        read,
        names,
        asked: checked_paths,
        keys: checked_keys,
    } = crate::project::assemble(env, &sources, controller, read, units);
    crate::project::parts::add_extra(&mut workspace, extra, &split.keys, &checked_keys);
    let mut by_path = check_loaded(
        &mut workspace,
        &checked_paths,
        &checked_keys,
        selection,
        progress,
    );
    let outcomes = read
        .into_iter()
        .zip(files)
        .zip(names)
        .zip(&part.positions)
        .map(|(((r, path), name), &position)| {
            let outcome = match r {
                Ok(file) => {
                    let diagnostics = name
                        .and_then(|name| by_path.remove(&name))
                        .unwrap_or_default();
                    Outcome::Checked(Checked { file, diagnostics })
                }
                Err(why) => {
                    progress.inc(1);
                    Outcome::Skipped(path.clone(), why)
                }
            };
            (position, outcome)
        })
        .collect();
    PartResult { outcomes }
}

/// The diagnostics of the files `checked_paths` of the tasks
/// `checked_keys` of a workspace, by the analyzer's name of the file; a
/// file whose tree was released is parsed again for its check only. A name
/// the checked files lack is one finding per task
/// ([`rapid_analyzer::check::once::per_task`]).
fn check_loaded(
    workspace: &mut rapid_analyzer::workspace::Workspace,
    checked_paths: &HashSet<String>,
    checked_keys: &std::collections::BTreeSet<String>,
    selection: &(dyn Fn(&std::path::Path) -> Selection + Sync),
    progress: &ProgressBar,
) -> HashMap<String, Vec<Diagnostic>> {
    let tasks = workspace.checks();
    let mut jobs: Vec<(&Arc<rapid_analyzer::task::Task>, &Arc<Unit>)> = tasks
        .iter()
        .filter(|(task, u)| checked_keys.contains(&task.key) && checked_paths.contains(&u.path))
        .map(|(task, u)| (task, u))
        .collect();
    // One job per checked file, largest first (a task may be one big
    // backup: its files are spread over the threads too).
    jobs.sort_by(|a, b| {
        b.1.text
            .len()
            .cmp(&a.1.text.len())
            .then(a.1.path.cmp(&b.1.path))
    });
    let mut by_path: HashMap<String, Vec<Diagnostic>> = jobs
        .par_iter()
        .map(|(task, u)| {
            let rules = selection(std::path::Path::new(&u.path));
            let found = if u.tree_loaded() {
                diagnostics_selected(task, u, StmtCache::default(), &rules).0
            } else {
                let loaded = u.loaded();
                let idx = task.index_of(u).unwrap_or(usize::MAX);
                let task = task.with_unit(idx, loaded.clone());
                diagnostics_selected(&task, &loaded, StmtCache::default(), &rules).0
            };
            progress.inc(1);
            (u.path.clone(), found)
        })
        .collect();
    let mut findings: Vec<(
        &Arc<rapid_analyzer::task::Task>,
        &Arc<Unit>,
        Vec<Diagnostic>,
    )> = jobs
        .iter()
        .filter_map(|(task, u)| Some((*task, *u, by_path.remove(&u.path)?)))
        .collect();
    let mut files: Vec<rapid_analyzer::check::once::FileFindings<'_>> = findings
        .iter_mut()
        .map(
            |(task, u, diagnostics)| rapid_analyzer::check::once::FileFindings {
                task: &task.key,
                path: &u.path,
                text: &u.text,
                diagnostics,
            },
        )
        .collect();
    rapid_analyzer::check::once::per_task(&mut files);
    drop(files);
    by_path.extend(findings.into_iter().map(|(_, u, d)| (u.path.clone(), d)));
    by_path
}

/// `files` without those that are the same file as an earlier one.
fn distinct_files(env: &dyn Environment, files: Vec<PathBuf>) -> Vec<PathBuf> {
    let names: Vec<String> = files.par_iter().map(|p| env.name(p)).collect();
    let mut seen = HashSet::with_capacity(files.len());
    files
        .into_iter()
        .zip(names)
        .filter_map(|(file, name)| seen.insert(name).then_some(file))
        .collect()
}

/// The path of a file as the analyzer sees it (it groups tasks by it): its
/// real place, whatever path named it ([`crate::project::source::analyzer_path`]).
/// Reports show the path as given.
pub fn unit_path(path: &Path) -> String {
    crate::project::source::analyzer_path(path)
}
