//! `rapid fmt`: rewrite RAPID files in the canonical layout.
//!
//! Files are found as `rapid check` finds them (honouring `.gitignore` and
//! the `exclude` globs of `rapid.toml`). Files keep their encoding (Latin-1 stays Latin-1, a UTF-8 BOM stays) and
//! their line endings; a file with syntax errors is left untouched. Exit
//! codes: 0 when all went well, 1 when `--check` or `--diff` found files to
//! change or a file was left unformatted because of a syntax error, 2 on a
//! bad configuration or a file that could not be read or written.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

use rapid_analyzer::format::{FormatError, FormatOptions, format, verify};
use rayon::prelude::*;

use crate::check::{LintSettings, Overrides, discover_with, normalize};
use crate::config;
use crate::source::{SourceFile, Unreadable};

#[derive(Debug, clap::Args)]
pub struct FmtArgs {
    /// Files or folders to format (default: the current folder); `-` reads
    /// standard input and writes the result to standard output.
    pub paths: Vec<PathBuf>,
    /// Write nothing: list the files that would change and exit with 1 if
    /// there are any.
    #[arg(long)]
    pub check: bool,
    /// Write nothing: print the changes as a unified diff and exit with 1 if
    /// there are any.
    #[arg(long)]
    pub diff: bool,
    /// The configuration file (default: the nearest `rapid.toml` above the
    /// first path).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Parse every result again and make sure its tokens are the original's
    /// (slower; a safety check).
    #[arg(long)]
    pub verify: bool,
}

/// What happened to one file.
enum Outcome {
    /// Formatted: the original and the new text (equal if nothing changed).
    Formatted(SourceFile, String),
    /// Left as it is, with the reason.
    Failed(PathBuf, Failure),
}

enum Failure {
    Unreadable(Unreadable),
    Format(FormatError),
}

pub fn run(args: FmtArgs) -> ExitCode {
    let mut stderr = anstream::stderr();
    let stdin = args.paths.iter().any(|p| p.as_os_str() == "-");
    if stdin && args.paths.len() > 1 {
        let _ = writeln!(
            stderr,
            "rapid: `-` (standard input) cannot be mixed with paths"
        );
        return ExitCode::from(2);
    }
    let paths = if args.paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        args.paths.clone()
    };
    let first = if stdin {
        Path::new(".")
    } else {
        paths[0].as_path()
    };
    let (config, config_path) = match config::resolve_with_path(args.config.as_deref(), first) {
        Ok(found) => found,
        Err(e) => {
            let _ = writeln!(stderr, "rapid: {e}");
            return ExitCode::from(2);
        }
    };
    let options = config.format.options();
    if stdin {
        return run_stdin(&args, &options);
    }
    // `exclude` in rapid.toml leaves files out, as for `rapid check`
    let root = match config_path.as_deref().and_then(Path::parent) {
        Some(dir) => std::path::absolute(dir),
        None => std::env::current_dir(),
    };
    let settings = match root.map_err(|e| e.to_string()).and_then(|root| {
        LintSettings::new(&config, normalize(&root), &Overrides::default())
            .map_err(|e| e.to_string())
    }) {
        Ok(settings) => Arc::new(settings),
        Err(e) => {
            let _ = writeln!(stderr, "rapid: {e}");
            return ExitCode::from(2);
        }
    };
    let found = discover_with(
        &paths,
        Arc::new(move |p: &Path, dir: bool| settings.is_excluded(p, dir)),
    );
    let mut usage_error = false;
    for (path, why) in &found.errors {
        let _ = writeln!(stderr, "rapid: {}: {why}", path.display());
        usage_error = true;
    }
    for (path, why) in &found.warnings {
        let _ = writeln!(stderr, "rapid: {}: {why}", path.display());
    }
    let outcomes: Vec<Outcome> = found
        .files
        .par_iter()
        .map(|path| format_file(path, &options, args.verify))
        .collect();

    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let (mut changed, mut unchanged, mut failed) = (0usize, 0usize, 0usize);
    for outcome in outcomes {
        match outcome {
            Outcome::Formatted(file, new) => {
                if new == file.text {
                    unchanged += 1;
                    continue;
                }
                changed += 1;
                if args.diff {
                    let name = file.path.display().to_string();
                    let _ = write!(out, "{}", unified_diff(&file.text, &new, &name));
                } else if args.check {
                    let _ = writeln!(out, "{}", file.path.display());
                } else if let Err(e) = write_back(&file, &new) {
                    let _ = writeln!(stderr, "rapid: {}: {e}", file.path.display());
                    usage_error = true;
                }
            }
            Outcome::Failed(path, Failure::Unreadable(why)) => {
                if matches!(why, Unreadable::Io(_)) {
                    usage_error = true;
                }
                let _ = writeln!(stderr, "rapid: {}: {why}", path.display());
            }
            Outcome::Failed(path, Failure::Format(e)) => {
                failed += 1;
                let _ = writeln!(
                    stderr,
                    "rapid: {}",
                    describe(&path.display().to_string(), &e)
                );
            }
        }
    }
    let _ = out.flush();
    let verb = if args.check || args.diff {
        "would be reformatted"
    } else {
        "reformatted"
    };
    let mut summary = format!(
        "{changed} {} {verb}, {unchanged} left unchanged",
        files(changed)
    );
    if failed > 0 {
        summary.push_str(&format!(", {failed} not formatted (errors above)"));
    }
    let _ = writeln!(stderr, "{summary}");
    if usage_error {
        ExitCode::from(2)
    } else if failed > 0 || ((args.check || args.diff) && changed > 0) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// `file:line:column: message` for a syntax error, `file: message` otherwise.
fn describe(name: &str, e: &FormatError) -> String {
    match e {
        FormatError::Syntax { .. } => format!("{name}:{e}"),
        FormatError::Internal { .. } | FormatError::Unsupported { .. } => format!("{name}: {e}"),
    }
}

fn files(n: usize) -> &'static str {
    if n == 1 { "file" } else { "files" }
}

fn format_file(path: &Path, options: &FormatOptions, check: bool) -> Outcome {
    let file = match SourceFile::read(path) {
        Ok(file) => file,
        Err(why) => return Outcome::Failed(path.to_owned(), Failure::Unreadable(why)),
    };
    match format_checked(&file.text, options, check) {
        Ok(new) => Outcome::Formatted(file, new),
        Err(e) => Outcome::Failed(path.to_owned(), Failure::Format(e)),
    }
}

fn format_checked(text: &str, options: &FormatOptions, check: bool) -> Result<String, FormatError> {
    let new = format(text, options)?;
    if check {
        verify(text, &new)?;
    }
    Ok(new)
}

/// Writes the file back in its encoding.
fn write_back(file: &SourceFile, new: &str) -> Result<(), String> {
    let bytes = file.encoding.encode(new).map_err(|at| {
        format!(
            "cannot write a character at byte {at} in {}",
            file.encoding.name()
        )
    })?;
    std::fs::write(&file.path, bytes).map_err(|e| format!("cannot write it: {e}"))
}

fn run_stdin(args: &FmtArgs, options: &FormatOptions) -> ExitCode {
    let mut stderr = anstream::stderr();
    let mut bytes = Vec::new();
    if let Err(e) = std::io::stdin().read_to_end(&mut bytes) {
        let _ = writeln!(stderr, "rapid: cannot read standard input: {e}");
        return ExitCode::from(2);
    }
    let file = match SourceFile::from_bytes(PathBuf::from("<stdin>"), &bytes) {
        Ok(file) => file,
        Err(why) => {
            let _ = writeln!(stderr, "rapid: <stdin>: {why}");
            return ExitCode::from(2);
        }
    };
    let new = match format_checked(&file.text, options, args.verify) {
        Ok(new) => new,
        Err(e) => {
            let _ = writeln!(stderr, "rapid: {}", describe("<stdin>", &e));
            // the input goes through unchanged, so a pipe loses nothing
            if !args.check && !args.diff {
                let _ = std::io::stdout().write_all(&bytes);
            }
            return ExitCode::from(1);
        }
    };
    let mut stdout = std::io::stdout().lock();
    let changed = new != file.text;
    let written = if args.diff {
        if changed {
            stdout.write_all(unified_diff(&file.text, &new, "<stdin>").as_bytes())
        } else {
            Ok(())
        }
    } else if args.check {
        Ok(())
    } else {
        match file.encoding.encode(&new) {
            Ok(out) => stdout.write_all(&out),
            Err(_) => stdout.write_all(new.as_bytes()),
        }
    };
    if let Err(e) = written.and_then(|()| stdout.flush())
        && e.kind() != std::io::ErrorKind::BrokenPipe
    {
        let _ = writeln!(stderr, "rapid: cannot write standard output: {e}");
        return ExitCode::from(2);
    }
    if (args.check || args.diff) && changed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// A unified diff with three lines of context, `a/` and `b/` headers naming
/// the file.
fn unified_diff(old: &str, new: &str, name: &str) -> String {
    similar::TextDiff::from_lines(old, new)
        .unified_diff()
        .context_radius(3)
        .header(&format!("a/{name}"), &format!("b/{name}"))
        .to_string()
}
