//! `rapid check`: find RAPID files, analyse them, report what is wrong.
//!
//! The run: resolve `rapid.toml` and the flags ([`LintSettings`]), find the
//! files ([`discover`]), read and parse them in parallel, group them into
//! tasks with the modules and `EIO.cfg` of `extra-paths`, check every task
//! in parallel, keep what the settings and the inline suppressions select
//! ([`LintSettings::apply`]), optionally apply the safe fixes and check
//! again, and print the report in the chosen format.

mod baseline;
pub mod context;
mod discover;
mod fix;
mod output;
mod settings;
mod suppress;

use std::collections::{BTreeSet, HashMap, HashSet};
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use rapid_analyzer::task::Unit;
use rapid_analyzer::workspace::{Workspace, diagnostics_of};
use rayon::prelude::*;

use crate::source::{SourceFile, Unreadable};

pub use discover::{Discovery, discover, discover_with};
pub use fix::apply_safe_fixes;
pub use settings::{LintSettings, Overrides, normalize};

/// Output formats of `rapid check`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// The source line with the problem underlined, and a summary.
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

#[derive(Debug, clap::Args)]
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

/// Files larger than this are not modules a controller would load; they are
/// skipped with a message rather than parsed.
pub const MAX_FILE_BYTES: u64 = 8 * 1024 * 1024;

/// A file that was checked, with its diagnostics in source order.
pub struct Checked {
    pub file: SourceFile,
    pub diagnostics: Vec<Diagnostic>,
}

/// Why a file was not checked.
#[derive(Debug)]
pub enum Skip {
    Unreadable(Unreadable),
    TooLarge(u64),
}

impl Skip {
    /// An IO error fails the run (exit 2); an encrypted or binary file does not.
    pub fn is_error(&self) -> bool {
        matches!(self, Skip::Unreadable(Unreadable::Io(_)))
    }
}

impl std::fmt::Display for Skip {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Skip::Unreadable(why) => why.fmt(f),
            Skip::TooLarge(bytes) => write!(
                f,
                "skipped: {:.1} MB is more than the {} MB a module may have here",
                *bytes as f64 / 1e6,
                MAX_FILE_BYTES / (1024 * 1024)
            ),
        }
    }
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

pub fn run(args: CheckArgs) -> ExitCode {
    let mut stderr = anstream::stderr();
    match run_inner(args, &mut stderr) {
        Ok(code) => code,
        Err(message) => {
            let _ = writeln!(stderr, "rapid: {message}");
            ExitCode::from(2)
        }
    }
}

fn run_inner(args: CheckArgs, stderr: &mut impl Write) -> Result<ExitCode, String> {
    if let Some(n) = args.threads {
        // Fails only if the pool was built already, which it is not here.
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build_global();
    }
    let mut clock = std::time::Instant::now();
    let started = clock;
    let paths = if args.paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        args.paths.clone()
    };
    let (config, config_path) = crate::config::resolve_with_path(args.config.as_deref(), &paths[0])
        .map_err(|e| e.to_string())?;
    let root = match config_path.as_deref().and_then(Path::parent).map(|dir| {
        if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        }
    }) {
        Some(dir) => normalize(&std::path::absolute(dir).map_err(|e| e.to_string())?),
        None => normalize(&std::env::current_dir().map_err(|e| e.to_string())?),
    };
    let settings = LintSettings::new(
        &config,
        root.clone(),
        &Overrides {
            select: args.select.clone(),
            ignore: args.ignore.clone(),
            exclude: args.exclude.clone(),
            min_severity: args.min_severity,
        },
    )
    .map_err(|e| e.to_string())?;
    let settings = Arc::new(settings);
    let for_walk = settings.clone();
    let mut found = discover_with(
        &paths,
        Arc::new(move |p: &Path, dir: bool| for_walk.is_excluded(p, dir)),
    );
    // A file named twice (`rapid check . PROGMOD`, a link) is checked once.
    found.files = distinct_files(std::mem::take(&mut found.files));
    let mut failed = false;
    for (path, why) in &found.errors {
        let _ = writeln!(stderr, "rapid: {}: {why}", output::display_path(path));
        failed = true;
    }
    for (path, why) in &found.warnings {
        let _ = writeln!(stderr, "rapid: {}: {why}", output::display_path(path));
    }
    let extra_paths: Vec<PathBuf> = config
        .extra_paths
        .iter()
        .map(|p| root.join(p))
        .chain(args.extra_path.iter().cloned())
        .collect();
    let extra = discover(&extra_paths);
    let for_context = settings.clone();
    let context = context::task_context(
        &found.files,
        &paths,
        Arc::new(move |p: &Path, dir: bool| for_context.is_excluded(p, dir)),
    );
    for (path, why) in &extra.errors {
        let _ = writeln!(stderr, "rapid: {} (extra path): {why}", path.display());
        failed = true;
    }
    if found.files.is_empty() && found.errors.is_empty() {
        let _ = writeln!(
            stderr,
            "rapid: no RAPID files found in {}",
            paths
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }

    lap("configuration and discovery", &mut clock);
    let progress = progress_bar(found.files.len());
    let controller = config.controller.resolve().unwrap_or_default();
    let mut outcomes = check_files(&found, &context, &extra, &controller, &progress);
    let mut fixed = 0;
    if args.fix {
        // A fix can make room for another (or reveal one): a few passes.
        for _ in 0..4 {
            let (n, write_failed) = fix_outcomes(&mut outcomes, &settings, stderr);
            failed |= write_failed;
            fixed += n;
            if n == 0 {
                break;
            }
            outcomes = check_files(&found, &context, &extra, &controller, &progress);
        }
    }
    progress.finish_and_clear();
    clock = std::time::Instant::now();

    let mut report = Report {
        checked: Vec::with_capacity(outcomes.len()),
        skipped: Vec::new(),
        fixed,
        baselined: 0,
    };
    for outcome in outcomes {
        match outcome {
            Outcome::Checked(mut c) => {
                let diagnostics = std::mem::take(&mut c.diagnostics);
                c.diagnostics =
                    settings.apply(&c.file.path, &c.file.text, &c.file.lines, diagnostics);
                report.checked.push(c);
            }
            Outcome::Skipped(path, why) => {
                failed |= why.is_error();
                let _ = writeln!(stderr, "rapid: {}: {why}", output::display_path(&path));
                report.skipped.push((path, why.to_string()));
            }
        }
    }

    if let Some(path) = &args.baseline {
        apply_baseline(path, args.update_baseline, &mut report, stderr)?;
    }
    lap("selection and suppressions", &mut clock);
    // Colours as the real stdout allows, through a buffer: stdout is
    // line-buffered even into a pipe, a system call for every line of the
    // report (31,000 for 6,000 findings).
    let stdout = std::io::stdout();
    let colours = anstream::AutoStream::choice(&stdout);
    let mut buffered = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
    let mut out = anstream::AutoStream::new(&mut buffered as &mut dyn Write, colours);
    let written = if args.statistics {
        output::statistics(&mut out, &report, args.format == Format::Json)
    } else {
        match args.format {
            Format::Human => {
                output::human(&mut out, &report, colours != anstream::ColorChoice::Never)
            }
            Format::Concise => output::concise(&mut out, &report),
            Format::Json => output::json(&mut out, &report),
            Format::Sarif => output::sarif(&mut out, &report, &root),
            Format::Github => output::github(&mut out, &report),
            Format::Junit => output::junit(&mut out, &report),
        }
    };
    if let Err(e) = written.and_then(|()| out.flush())
        && e.kind() != std::io::ErrorKind::BrokenPipe
    {
        return Err(format!("cannot write the report: {e}"));
    }
    lap("output", &mut clock);
    if args.timings
        && let Ok(t) = TIMINGS.lock()
    {
        for (phase, took) in t.iter() {
            let _ = writeln!(stderr, "{:>9.2} ms  {phase}", took.as_secs_f64() * 1e3);
        }
        let total = started.elapsed().as_secs_f64() * 1e3;
        let _ = writeln!(
            stderr,
            "{total:>9.2} ms  total ({} threads)",
            rayon::current_num_threads()
        );
    }
    let worst = report
        .checked
        .iter()
        .flat_map(|c| &c.diagnostics)
        .map(|d| d.severity)
        .max();
    let threshold = if args.error_on_warnings {
        Severity::Warning
    } else {
        Severity::Error
    };
    Ok(if failed {
        ExitCode::from(2)
    } else if !args.exit_zero && worst.is_some_and(|w| w >= threshold) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// `--baseline`: leaves out the findings the file holds, or records them
/// in it when it does not exist yet (or `update` says so).
fn apply_baseline(
    path: &Path,
    update: bool,
    report: &mut Report,
    stderr: &mut impl Write,
) -> Result<(), String> {
    let shown = output::display_path(path);
    match baseline::Baseline::read(path)? {
        Some(known) if !update => {
            let filtered = known.filter(&mut report.checked);
            report.baselined = filtered.known;
            if filtered.gone > 0 {
                let s = if filtered.gone == 1 { "" } else { "s" };
                let _ = writeln!(
                    stderr,
                    "rapid: {} finding{s} of the baseline {shown} no longer found; \
                     `--update-baseline` records the baseline again",
                    filtered.gone
                );
            }
        }
        _ => {
            let n = baseline::record(path, &report.checked)?;
            let s = if n == 1 { "" } else { "s" };
            let _ = writeln!(
                stderr,
                "rapid: recorded {n} finding{s} in {shown}; runs with `--baseline {shown}` \
                 report only findings that are not in it"
            );
            report.baselined = n;
            for c in &mut report.checked {
                c.diagnostics.clear();
            }
        }
    }
    Ok(())
}

/// Applies the safe fixes of the reported diagnostics to each file and
/// writes it back in its encoding. Returns the fixes applied, and whether
/// a file could not be written.
fn fix_outcomes(
    outcomes: &mut [Outcome],
    settings: &LintSettings,
    stderr: &mut impl Write,
) -> (usize, bool) {
    let mut total = 0;
    let mut failed = false;
    for outcome in outcomes.iter_mut() {
        let Outcome::Checked(c) = outcome else {
            continue;
        };
        if c.diagnostics.iter().all(|d| d.fix.is_none()) {
            continue;
        }
        let reported = settings.apply(
            &c.file.path,
            &c.file.text,
            &c.file.lines,
            c.diagnostics.clone(),
        );
        let Some((text, n)) = apply_safe_fixes(&c.file.text, &reported) else {
            continue;
        };
        let path = output::display_path(&c.file.path);
        match c.file.encoding.encode(&text) {
            Ok(bytes) => match std::fs::write(&c.file.path, bytes) {
                Ok(()) => {
                    total += n;
                    let s = if n == 1 { "" } else { "s" };
                    let _ = writeln!(stderr, "rapid: {path}: fixed {n} problem{s}");
                }
                Err(e) => {
                    failed = true;
                    let _ = writeln!(stderr, "rapid: {path}: cannot write the fixes: {e}");
                }
            },
            Err(at) => {
                let _ = writeln!(
                    stderr,
                    "rapid: {path}: fixes not written: the character at byte {at} cannot be written in {}",
                    c.file.encoding.name()
                );
            }
        }
    }
    (total, failed)
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
/// (`context`, [`context::task_context`]) and the modules and configuration
/// of `extra` join the tasks (the tasks they belong to when those are
/// checked, else, for `extra`, every checked task) but are not reported.
/// Diagnostics are the analyzer's, unfiltered.
pub fn check_files(
    found: &Discovery,
    context: &Discovery,
    extra: &Discovery,
    controller: &rapid_analyzer::controller::ControllerOverride,
    progress: &ProgressBar,
) -> Vec<Outcome> {
    let files = &found.files;
    let mut clock = std::time::Instant::now();
    // The checker needs the catalogue (some milliseconds to load): load it
    // on a thread that parsing leaves idle (a single large file is parsed
    // on one thread).
    rayon::spawn(|| {
        let _ = rapid_analyzer::catalogue::base();
    });
    // Read, decode and parse each file in one parallel pass, largest files
    // first so that no big module is left to one thread at the end.
    let mut order: Vec<(u64, usize)> = files
        .iter()
        .enumerate()
        .map(|(i, p)| (std::fs::metadata(p).map_or(0, |m| m.len()), i))
        .collect();
    order.sort_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut parsed: Vec<(usize, Result<SourceFile, Skip>, Option<Unit>)> = order
        .par_iter()
        .map(|&(_, i)| {
            let read = read_source(&files[i]);
            let unit = read
                .as_ref()
                .ok()
                .map(|f| Unit::new(unit_path(&f.path), f.text.clone(), None));
            progress.inc(1);
            (i, read, unit)
        })
        .collect();
    parsed.sort_by_key(|(i, _, _)| *i);
    // The analyzer's name of each file read, to find its diagnostics.
    let names: Vec<Option<String>> = parsed
        .iter()
        .map(|(_, _, u)| u.as_ref().map(|u| u.path.clone()))
        .collect();
    let (read, units): (Vec<_>, Vec<_>) = parsed.into_iter().map(|(_, r, u)| (r, u)).unzip();
    lap("reading, decoding, parsing and item trees", &mut clock);
    let mut workspace = Workspace::new();
    workspace.set_controller(controller.clone());
    for path in found.programs.iter().chain(&context.programs) {
        if let Ok(bytes) = crate::source::read_regular(path) {
            workspace.set_program(&unit_path(path), &String::from_utf8_lossy(&bytes));
        }
    }
    for path in found.configs.iter().chain(&context.configs) {
        if let Ok(bytes) = crate::source::read_regular(path) {
            let text = String::from_utf8_lossy(&bytes);
            workspace.set_config(&unit_path(path), &text);
        }
    }
    // A module that could not be read (encrypted, binary, too large)
    // leaves its task incomplete.
    for (r, path) in read.iter().zip(files) {
        if r.is_err() {
            workspace.set_unreadable(&unit_path(path));
        }
    }
    let checked_paths: HashSet<String> = units.iter().flatten().map(|u| u.path.clone()).collect();
    let checked_keys: BTreeSet<String> = checked_paths
        .iter()
        .map(|p| workspace.task_key(p))
        .collect();
    // Skipped files are not checked: the second half of the bar is shorter.
    progress.set_length((files.len() + checked_paths.len()) as u64);
    add_context(&mut workspace, context, &checked_paths, &checked_keys);
    add_extra(&mut workspace, extra, &checked_paths, &checked_keys);
    for unit in units.into_iter().flatten() {
        workspace.set_unit(unit);
    }
    let tasks = workspace.checks();
    lap("extra paths, configuration and task indexes", &mut clock);
    // One job per checked file, largest first (a task may be one big
    // backup: its files are spread over the threads too).
    let mut jobs: Vec<(&Arc<rapid_analyzer::task::Task>, &Arc<Unit>)> = tasks
        .iter()
        .filter(|(task, u)| checked_keys.contains(&task.key) && checked_paths.contains(&u.path))
        .map(|(task, u)| (task, u))
        .collect();
    jobs.sort_by(|a, b| {
        b.1.text
            .len()
            .cmp(&a.1.text.len())
            .then(a.1.path.cmp(&b.1.path))
    });
    let mut by_path: HashMap<String, Vec<Diagnostic>> = jobs
        .par_iter()
        .map(|(task, u)| {
            let d = (u.path.clone(), diagnostics_of(task, u));
            progress.inc(1);
            d
        })
        .collect();
    // A name the checked files lack is one finding per task, with every
    // other use as a related location.
    {
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
    }
    lap("checking (analyzer)", &mut clock);
    // Freeing every tree and index costs tens of milliseconds on a large
    // project and the process ends soon after: let the exit reclaim them.
    drop(jobs);
    std::mem::forget(tasks);
    std::mem::forget(workspace);
    read.into_iter()
        .zip(files)
        .zip(names)
        .map(|((r, path), name)| match r {
            Ok(file) => {
                let diagnostics = name
                    .and_then(|name| by_path.remove(&name))
                    .unwrap_or_default();
                Outcome::Checked(Checked { file, diagnostics })
            }
            Err(why) => Outcome::Skipped(path.clone(), why),
        })
        .collect()
}

fn read_source(path: &Path) -> Result<SourceFile, Skip> {
    let meta = std::fs::metadata(path).map_err(|e| Skip::Unreadable(Unreadable::Io(e)))?;
    if !meta.is_file() {
        let e = std::io::Error::other(format!(
            "{}, not a file",
            crate::source::kind_of(&meta.file_type())
        ));
        return Err(Skip::Unreadable(Unreadable::Io(e)));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(Skip::TooLarge(meta.len()));
    }
    SourceFile::read(path).map_err(Skip::Unreadable)
}

/// Adds the modules of the checked files' tasks that were not checked
/// themselves (their programs and configuration are in already).
fn add_context(
    workspace: &mut Workspace,
    context: &Discovery,
    checked_paths: &HashSet<String>,
    checked_keys: &BTreeSet<String>,
) {
    let units: Vec<Unit> = context
        .files
        .par_iter()
        .filter_map(|p| {
            let path = unit_path(p);
            if checked_paths.contains(&path) || !checked_keys.contains(&workspace.task_key(&path)) {
                return None;
            }
            let file = read_source(p).ok()?;
            Some(Unit::new(path, file.text, None))
        })
        .collect();
    for unit in units {
        workspace.set_unit(unit);
    }
}

/// Adds the modules and I/O configuration of the extra paths. A module
/// whose own task is checked joins it; any other joins every checked task,
/// under a path of its own inside the task (its diagnostics are not
/// computed, so the path is never shown).
fn add_extra(
    workspace: &mut Workspace,
    extra: &Discovery,
    checked_paths: &HashSet<String>,
    checked_keys: &BTreeSet<String>,
) {
    let units: Vec<Unit> = extra
        .files
        .par_iter()
        .filter(|p| !checked_paths.contains(&unit_path(p)))
        .filter_map(|p| {
            let file = read_source(p).ok()?;
            Some(Unit::new(unit_path(&file.path), file.text, None))
        })
        .collect();
    for (i, unit) in units.into_iter().enumerate() {
        if checked_keys.contains(&workspace.task_key(&unit.path)) {
            workspace.set_unit(unit);
            continue;
        }
        let name = unit
            .path
            .rsplit(['/', '\\'])
            .next()
            .unwrap_or_default()
            .to_owned();
        for key in checked_keys {
            let path = format!("{key}/extra-{i}-{name}");
            workspace.set_unit(Unit::from_tree(
                path,
                unit.text.clone(),
                Some(unit.tree().clone()),
            ));
        }
    }
    for (i, path) in extra.configs.iter().enumerate() {
        if let Ok(bytes) = crate::source::read_regular(path) {
            let text = String::from_utf8_lossy(&bytes);
            for key in checked_keys {
                // Below `SYSPAR`, a configuration applies to the folder above.
                workspace.set_config(&format!("{key}/SYSPAR/extra-{i}-EIO.cfg"), &text);
            }
        }
    }
}

/// `files` without those that are the same file as an earlier one.
fn distinct_files(files: Vec<PathBuf>) -> Vec<PathBuf> {
    let names: Vec<String> = files.par_iter().map(|p| unit_path(p)).collect();
    let mut seen = HashSet::with_capacity(files.len());
    files
        .into_iter()
        .zip(names)
        .filter_map(|(file, name)| seen.insert(name).then_some(file))
        .collect()
}

/// The path of a file as the analyzer sees it (it groups tasks by it): its
/// real place, whatever path named it ([`crate::source::analyzer_path`]).
/// Reports show the path as given.
pub fn unit_path(path: &Path) -> String {
    crate::source::analyzer_path(path)
}
