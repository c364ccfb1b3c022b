//! The run of `rapid check`, as named steps: the settings
//! ([`settings_of`]), the files through the project loader
//! ([`discover_project`]), the check and the fix loop
//! ([`check_and_fix`]), the report ([`report_of`], [`write_report`]) and
//! the exit code ([`exit_code`]).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

use indicatif::ProgressBar;
use rapid_analyzer::diagnostic::Severity;

use super::{
    CheckArgs, Format, LintSettings, Outcome, Overrides, Report, TIMINGS, apply_safe_fixes,
    baseline, check_files, lap, normalize, output, progress_bar,
};
use crate::config::Config;
use crate::project::{Discovery, Disk, Environment, NamedOnce, context, discover_in};

pub fn run(args: CheckArgs) -> ExitCode {
    // 4 KiB pages: the parts of a project are released and their memory
    // reused (`crate::alloc::no_huge_pages`). Huge pages stay on where the
    // kernel refuses; the check is the same.
    let _ = crate::alloc::no_huge_pages();
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
    // Each file's real path is resolved once for the whole run.
    let env = NamedOnce::new(&Disk);
    let setup = settings_of(&env, &args)?;
    let project = discover_project(&env, &args, &setup, stderr);
    lap("configuration and discovery", &mut clock);
    let (outcomes, fixed, fix_failed) = check_and_fix(&env, &args, &setup, &project, stderr);
    clock = std::time::Instant::now();
    let (mut report, read_failed) = report_of(outcomes, fixed, &setup.settings, stderr);
    if let Some(path) = &args.baseline {
        apply_baseline(path, args.update_baseline, &mut report, stderr)?;
    }
    lap("selection and suppressions", &mut clock);
    write_report(&args, &report, &setup.root)?;
    lap("output", &mut clock);
    if args.timings {
        print_timings(started, stderr);
    }
    Ok(exit_code(
        &args,
        &report,
        project.failed || fix_failed || read_failed,
    ))
}

/// `rapid check`'s steps 1 to 4 in `env`, without fixes, baseline or
/// output (for `rapid mcp`): the report, the folder of `rapid.toml` (else
/// the current folder), and whether a path or a file could not be read;
/// what a run says on stderr goes to `notes`.
pub fn report_in(
    env: &dyn Environment,
    args: &CheckArgs,
    notes: &mut impl Write,
) -> Result<(Report, PathBuf, bool), String> {
    let setup = settings_of(env, args)?;
    let project = discover_project(env, args, &setup, notes);
    let (outcomes, fixed, _) = check_and_fix(env, args, &setup, &project, notes);
    let (report, read_failed) = report_of(outcomes, fixed, &setup.settings, notes);
    Ok((report, setup.root, project.failed || read_failed))
}

/// `rapid check`'s steps 1 and 2 and the project they load, without
/// checking (for `rapid mcp`'s `reach`): the workspace with the
/// configuration, extra paths and robot a check of `args.paths` has, and
/// the files found (the order of the workspace's `read`).
pub fn load_in(
    env: &dyn Environment,
    args: &CheckArgs,
    notes: &mut impl Write,
) -> Result<(crate::project::Loaded, Vec<PathBuf>), String> {
    let setup = settings_of(env, args)?;
    let project = discover_project(env, args, &setup, notes);
    let controller = setup.config.controller.resolve().unwrap_or_default();
    let sources = crate::project::Sources {
        found: Some(&project.found),
        context: Some(&project.context),
        extra: Some(&project.extra),
    };
    let loaded = crate::project::load(env, &sources, &controller);
    Ok((loaded, project.found.files))
}

/// What the run is configured with.
struct Setup {
    /// The paths to check (the current folder when none is given).
    paths: Vec<PathBuf>,
    config: Config,
    /// The folder of `rapid.toml` (else the current folder), absolute.
    root: PathBuf,
    settings: Arc<LintSettings>,
}

/// Step 1: `rapid.toml` (found upwards from the first path, or
/// `--config`) and the flags over it.
fn settings_of(env: &dyn Environment, args: &CheckArgs) -> Result<Setup, String> {
    let paths = if args.paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        args.paths.clone()
    };
    let (config, config_path) = crate::config::resolve_in(env, args.config.as_deref(), &paths[0])
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
    Ok(Setup {
        paths,
        config,
        root,
        settings: Arc::new(settings),
    })
}

/// The files of a run, as the project loader finds them.
struct Project {
    /// The files to check, with the programs and configuration found.
    found: Discovery,
    /// The rest of their tasks.
    context: Discovery,
    /// The extra paths' modules and configuration.
    extra: Discovery,
    /// Whether a path could not be walked (exit 2).
    failed: bool,
}

/// Step 2: the files to check, the rest of their tasks and the extra
/// paths; what could not be walked is said on `stderr`.
fn discover_project(
    env: &dyn Environment,
    args: &CheckArgs,
    setup: &Setup,
    stderr: &mut impl Write,
) -> Project {
    let paths = &setup.paths;
    let for_walk = setup.settings.clone();
    let mut found = discover_in(
        env,
        paths,
        Arc::new(move |p: &Path, dir: bool| for_walk.is_excluded(p, dir)),
        None,
    );
    // A file named twice (`rapid check . PROGMOD`, a link) is checked once.
    found.files = super::distinct_files(env, std::mem::take(&mut found.files));
    let mut failed = false;
    for (path, why) in &found.errors {
        let _ = writeln!(stderr, "rapid: {}: {why}", output::display_path(path));
        failed = true;
    }
    for (path, why) in &found.warnings {
        let _ = writeln!(stderr, "rapid: {}: {why}", output::display_path(path));
    }
    let extra_paths: Vec<PathBuf> = setup
        .config
        .extra_paths
        .iter()
        .map(|p| setup.root.join(p))
        .chain(args.extra_path.iter().cloned())
        .collect();
    let extra = discover_in(env, &extra_paths, Arc::new(|_, _| false), None);
    let for_context = setup.settings.clone();
    let context = context::task_context(
        env,
        &found.files,
        &found.programs,
        paths,
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
    Project {
        found,
        context,
        extra,
        failed,
    }
}

/// Step 3: checks the files, and with `--fix` applies the safe fixes and
/// checks again (a fix can make room for another, or reveal one): the
/// outcomes, the number of fixes and whether writing one failed.
fn check_and_fix(
    env: &dyn Environment,
    args: &CheckArgs,
    setup: &Setup,
    project: &Project,
    stderr: &mut impl Write,
) -> (Vec<Outcome>, usize, bool) {
    let progress: ProgressBar = progress_bar(project.found.files.len());
    let controller = setup.config.controller.resolve().unwrap_or_default();
    let check = || {
        check_files(
            env,
            &project.found,
            &project.context,
            &project.extra,
            &controller,
            &|path: &std::path::Path| setup.settings.selection_for(path),
            &progress,
        )
    };
    let mut outcomes = check();
    let mut fixed = 0;
    let mut failed = false;
    if args.fix {
        for _ in 0..4 {
            let (n, write_failed) = fix_outcomes(&mut outcomes, &setup.settings, stderr);
            failed |= write_failed;
            fixed += n;
            if n == 0 {
                break;
            }
            outcomes = check();
        }
    }
    progress.finish_and_clear();
    (outcomes, fixed, failed)
}

/// Step 4: the report: each checked file's diagnostics as the settings and
/// inline suppressions select them, and the files skipped (said on
/// `stderr`; whether one is an IO error, exit 2).
fn report_of(
    outcomes: Vec<Outcome>,
    fixed: usize,
    settings: &LintSettings,
    stderr: &mut impl Write,
) -> (Report, bool) {
    let mut failed = false;
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
    (report, failed)
}

/// Step 5: prints the report in the chosen format.
fn write_report(args: &CheckArgs, report: &Report, root: &Path) -> Result<(), String> {
    // Colours as the real stdout allows, through a buffer: stdout is
    // line-buffered even into a pipe, a system call for every line of the
    // report (31,000 for 6,000 findings).
    let stdout = std::io::stdout();
    let colours = anstream::AutoStream::choice(&stdout);
    let mut buffered = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
    let mut out = anstream::AutoStream::new(&mut buffered as &mut dyn Write, colours);
    let written = if args.statistics {
        output::statistics(&mut out, report, args.format == Format::Json)
    } else {
        match args.format {
            Format::Human => {
                output::human(&mut out, report, colours != anstream::ColorChoice::Never)
            }
            Format::Concise => output::concise(&mut out, report),
            Format::Json => output::json(&mut out, report),
            Format::Sarif => output::sarif(&mut out, report, root),
            Format::Github => output::github(&mut out, report),
            Format::Junit => output::junit(&mut out, report),
        }
    };
    if let Err(e) = written.and_then(|()| out.flush())
        && e.kind() != std::io::ErrorKind::BrokenPipe
    {
        return Err(format!("cannot write the report: {e}"));
    }
    Ok(())
}

/// `--timings`: the time each phase took.
fn print_timings(started: std::time::Instant, stderr: &mut impl Write) {
    if let Ok(t) = TIMINGS.lock() {
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
}

/// Step 6: 2 for a usage, configuration or IO problem (`failed`), 1 for
/// findings at the threshold (errors, or warnings with
/// `--error-on-warnings`) unless `--exit-zero`, else 0.
fn exit_code(args: &CheckArgs, report: &Report, failed: bool) -> ExitCode {
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
    if failed {
        ExitCode::from(2)
    } else if !args.exit_zero && worst.is_some_and(|w| w >= threshold) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
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
