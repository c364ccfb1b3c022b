//! `rapid check`: find RAPID files, analyse them, report what is wrong.

mod discover;
mod output;

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use std::collections::HashMap;

use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use rapid_analyzer::task::Unit;
use rapid_analyzer::workspace::{Workspace, diagnostics_of};
use rayon::prelude::*;

use crate::source::{SourceFile, Unreadable};

pub use discover::discover;

/// Output formats of `rapid check`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// The source line with the problem underlined, and a summary.
    Human,
    /// One line per diagnostic: `file:line:column: severity[code] message`.
    Concise,
    /// A JSON array of diagnostics.
    Json,
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// Files or folders to check (default: the current folder).
    pub paths: Vec<PathBuf>,
    /// How to print the diagnostics.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
}

/// A file that was checked, with its diagnostics in source order.
pub struct Checked {
    pub file: SourceFile,
    pub diagnostics: Vec<Diagnostic>,
}

/// What happened to each file: checked, or skipped with a reason.
pub enum Outcome {
    Checked(Checked),
    Skipped(PathBuf, Unreadable),
}

pub fn run(args: CheckArgs) -> ExitCode {
    let paths = if args.paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        args.paths
    };
    let found = discover(&paths);
    let mut stderr = anstream::stderr();
    let mut usage_error = false;
    for (path, why) in &found.errors {
        let _ = writeln!(stderr, "rapid: {}: {why}", path.display());
        usage_error = true;
    }
    let outcomes = check_files(&found.files, &found.configs);
    let mut checked = Vec::with_capacity(outcomes.len());
    for outcome in outcomes {
        match outcome {
            Outcome::Checked(c) => checked.push(c),
            Outcome::Skipped(path, why) => {
                if matches!(why, Unreadable::Io(_)) {
                    usage_error = true;
                }
                let _ = writeln!(stderr, "rapid: {}: {why}", path.display());
            }
        }
    }
    let stdout = std::io::stdout();
    let mut out = anstream::AutoStream::auto(stdout.lock());
    let written = match args.format {
        Format::Human => output::human(&mut out, &checked),
        Format::Concise => output::concise(&mut out, &checked),
        Format::Json => output::json(&mut out, &checked),
    };
    if let Err(e) = written.and_then(|()| out.flush())
        && e.kind() != std::io::ErrorKind::BrokenPipe
    {
        let _ = writeln!(stderr, "rapid: cannot write the report: {e}");
        return ExitCode::from(2);
    }
    let errors = checked
        .iter()
        .flat_map(|c| &c.diagnostics)
        .any(|d| d.severity == Severity::Error);
    if usage_error {
        ExitCode::from(2)
    } else if errors {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Reads and checks every file, in parallel, keeping the order of `files`.
/// Files are grouped into tasks as the analyzer does; `configs` are the I/O
/// configuration files whose signals the tasks below them may use.
pub fn check_files(files: &[PathBuf], configs: &[PathBuf]) -> Vec<Outcome> {
    let read: Vec<Result<SourceFile, Unreadable>> =
        files.par_iter().map(|p| SourceFile::read(p)).collect();
    let units: Vec<Option<Unit>> = read
        .par_iter()
        .map(|r| {
            r.as_ref()
                .ok()
                .map(|f| Unit::new(unit_path(&f.path), f.text.clone(), None))
        })
        .collect();
    let mut workspace = Workspace::new();
    for path in configs {
        if let Ok(bytes) = std::fs::read(path) {
            let text = String::from_utf8_lossy(&bytes);
            workspace.set_config(&unit_path(path), &text);
        }
    }
    for unit in units.into_iter().flatten() {
        workspace.set_unit(unit);
    }
    let tasks = workspace.tasks();
    let mut by_path: HashMap<String, Vec<Diagnostic>> = tasks
        .par_iter()
        .flat_map_iter(|task| {
            task.units
                .iter()
                .map(|u| (u.path.clone(), diagnostics_of(task, u)))
                .collect::<Vec<_>>()
        })
        .collect();
    read.into_iter()
        .zip(files)
        .map(|(r, path)| match r {
            Ok(file) => {
                let diagnostics = by_path.remove(&unit_path(&file.path)).unwrap_or_default();
                Outcome::Checked(Checked { file, diagnostics })
            }
            Err(why) => Outcome::Skipped(path.clone(), why),
        })
        .collect()
}

/// The path of a file as the analyzer sees it (it groups tasks by it).
fn unit_path(path: &std::path::Path) -> String {
    path.to_string_lossy().into_owned()
}
