//! `rapid fmt`: lay RAPID files out as `docs/formatting.md` describes.
//!
//! Files are found as `rapid check` finds them (honouring `.gitignore` and
//! the `exclude` globs of `rapid.toml`). Files keep their encoding (Latin-1
//! stays Latin-1, a UTF-8 BOM stays) and their line endings; a file with
//! syntax errors is left untouched. A path that is no regular file when it
//! is opened (a FIFO, a device) is refused without waiting on it. Exit
//! codes: 0 when all went well, 1 when `--check` or `--diff` found files to
//! change or a file was left unformatted because of a syntax error, 2 on a
//! bad configuration or a file that could not be read or written.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

use rapid_analyzer::format::{FormatError, FormatOptions, format, verify};
use rayon::prelude::*;

use crate::check::{LintSettings, Overrides, normalize};
use crate::config;
use crate::project::discover_with;
use crate::project::source::{SourceFile, Unreadable};

#[derive(Debug, clap::Args)]
pub struct FmtArgs {
    /// Files or folders to format (default: the current folder); `-` reads
    /// standard input and writes the result to standard output.
    pub paths: Vec<PathBuf>,
    /// Write nothing: list the files that would change, each with the
    /// number of its lines that would, and exit with 1 if there are any.
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
    let mode = if args.diff {
        Mode::Diff
    } else if args.check {
        Mode::Check
    } else {
        Mode::Write
    };
    let tally = settle(outcomes, mode, write_back, &mut out, &mut stderr);
    let _ = out.flush();
    let _ = writeln!(stderr, "{}", tally.summary(mode));
    if usage_error || tally.usage_error {
        ExitCode::from(2)
    } else if tally.failed > 0 || (mode != Mode::Write && tally.changed > 0) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// What `rapid fmt` does with the files it formatted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    Write,
    Check,
    Diff,
}

/// What happened to the files, for the summary and the exit status.
#[derive(Debug, Default, PartialEq, Eq)]
struct Tally {
    /// Files changed (written, or that would be), and their changed lines.
    changed: usize,
    lines: usize,
    unchanged: usize,
    /// Files not formatted (syntax errors, nesting too deep).
    failed: usize,
    /// Files formatted but not written back.
    unwritten: usize,
    /// A file could not be read or written.
    usage_error: bool,
}

impl Tally {
    fn summary(&self, mode: Mode) -> String {
        let verb = if mode == Mode::Write {
            "reformatted"
        } else {
            "would be reformatted"
        };
        let mut summary = format!("{} {} {verb}", self.changed, files(self.changed));
        if self.changed > 0 {
            let lines = self.lines;
            summary.push_str(&format!(" ({lines} {})", plural(lines, "line", "lines")));
        }
        summary.push_str(&format!(", {} left unchanged", self.unchanged));
        if self.failed > 0 {
            summary.push_str(&format!(", {} not formatted (errors above)", self.failed));
        }
        if self.unwritten > 0 {
            summary.push_str(&format!(
                ", {} could not be written (errors above)",
                self.unwritten
            ));
        }
        summary
    }
}

/// Writes, lists or diffs each formatted file, reports each failure, and
/// counts them: a file that could not be written back is not counted as
/// reformatted.
fn settle(
    outcomes: Vec<Outcome>,
    mode: Mode,
    write: impl Fn(&SourceFile, &str) -> Result<(), String>,
    out: &mut impl Write,
    err: &mut impl Write,
) -> Tally {
    let mut tally = Tally::default();
    for outcome in outcomes {
        match outcome {
            Outcome::Formatted(file, new) => {
                if new == file.text {
                    tally.unchanged += 1;
                    continue;
                }
                let n = changed_lines(&file.text, &new);
                match mode {
                    Mode::Diff => {
                        let name = file.path.display().to_string();
                        let _ = write!(out, "{}", unified_diff(&file.text, &new, &name));
                    }
                    Mode::Check => {
                        let _ = writeln!(out, "{}: {}", file.path.display(), would_change(n));
                    }
                    Mode::Write => {
                        if let Err(e) = write(&file, &new) {
                            let _ = writeln!(err, "rapid: {}: {e}", file.path.display());
                            tally.usage_error = true;
                            tally.unwritten += 1;
                            continue;
                        }
                    }
                }
                tally.changed += 1;
                tally.lines += n;
            }
            Outcome::Failed(path, Failure::Unreadable(why)) => {
                if matches!(why, Unreadable::Io(_)) {
                    tally.usage_error = true;
                }
                let _ = writeln!(err, "rapid: {}: {why}", path.display());
            }
            Outcome::Failed(path, Failure::Format(e)) => {
                tally.failed += 1;
                let _ = writeln!(err, "rapid: {}", describe(&path.display().to_string(), &e));
            }
        }
    }
    tally
}

/// `file:line:column: message` for a syntax error, `file: message` otherwise.
fn describe(name: &str, e: &FormatError) -> String {
    match e {
        FormatError::Syntax { .. } => format!("{name}:{e}"),
        FormatError::Internal { .. } | FormatError::Unsupported { .. } => format!("{name}: {e}"),
    }
}

fn files(n: usize) -> &'static str {
    plural(n, "file", "files")
}

fn plural(n: usize, one: &'static str, more: &'static str) -> &'static str {
    if n == 1 { one } else { more }
}

/// `3 lines would change`.
fn would_change(n: usize) -> String {
    format!("{n} {} would change", plural(n, "line", "lines"))
}

/// How many lines of `old` are not in `new` as they are.
fn changed_lines(old: &str, new: &str) -> usize {
    similar::TextDiff::from_lines(old, new)
        .ops()
        .iter()
        .filter(|op| !matches!(op, similar::DiffOp::Equal { .. }))
        .map(|op| op.old_range().len())
        .sum()
}

fn format_file(path: &Path, options: &FormatOptions, check: bool) -> Outcome {
    let file = match read_regular(path)
        .and_then(|bytes| SourceFile::from_bytes(path.to_owned(), &bytes))
    {
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

/// Opens `path` without waiting (a FIFO opened to read or write waits for
/// the other end), and refuses anything but a regular file: the path was a
/// file when it was found, but may have been replaced since.
fn open_regular(path: &Path, options: &mut std::fs::OpenOptions) -> std::io::Result<std::fs::File> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path)?;
    let kind = file.metadata()?.file_type();
    if !kind.is_file() {
        return Err(std::io::Error::other(
            "not a regular file (a FIFO, a device or a folder), left alone",
        ));
    }
    Ok(file)
}

/// The bytes of a regular file.
fn read_regular(path: &Path) -> Result<Vec<u8>, Unreadable> {
    let mut file =
        open_regular(path, std::fs::OpenOptions::new().read(true)).map_err(Unreadable::Io)?;
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes).map_err(Unreadable::Io)?;
    Ok(bytes)
}

/// Writes the file back in its encoding (only if it is still a regular
/// file).
fn write_back(file: &SourceFile, new: &str) -> Result<(), String> {
    let bytes = file.encoding.encode(new).map_err(|at| {
        format!(
            "cannot write a character at byte {at} in {}",
            file.encoding.name()
        )
    })?;
    let write = || -> std::io::Result<()> {
        let mut out = open_regular(&file.path, std::fs::OpenOptions::new().write(true))?;
        out.set_len(0)?;
        out.write_all(&bytes)?;
        out.flush()
    };
    write().map_err(|e| format!("cannot write it: {e}"))
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
        if changed {
            let n = changed_lines(&file.text, &new);
            writeln!(stdout, "<stdin>: {}", would_change(n))
        } else {
            Ok(())
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    fn formatted(name: &str, old: &str, new: &str) -> Outcome {
        let file = SourceFile::from_bytes(PathBuf::from(name), old.as_bytes()).expect("text");
        Outcome::Formatted(file, new.to_owned())
    }

    #[test]
    fn files_that_could_not_be_written_are_not_counted_as_reformatted() {
        let outcomes = vec![
            formatted("a.mod", "A\nb\n", "A\n    b\n"),
            formatted("b.mod", "A\nb\nc\n", "A\n    b\n    c\n"),
            formatted("c.mod", "same\n", "same\n"),
        ];
        let fail_b = |file: &SourceFile, _: &str| {
            if file.path.ends_with("b.mod") {
                Err("cannot write it: no space left".to_owned())
            } else {
                Ok(())
            }
        };
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let tally = settle(outcomes, Mode::Write, fail_b, &mut out, &mut err);
        assert_eq!(
            tally,
            Tally {
                changed: 1,
                lines: 1,
                unchanged: 1,
                unwritten: 1,
                usage_error: true,
                ..Tally::default()
            }
        );
        assert_eq!(
            String::from_utf8_lossy(&err),
            "rapid: b.mod: cannot write it: no space left\n"
        );
        assert_eq!(
            tally.summary(Mode::Write),
            "1 file reformatted (1 line), 1 left unchanged, 1 could not be written (errors above)"
        );
    }

    #[test]
    fn check_counts_the_lines_that_would_change() {
        let outcomes = vec![formatted("a.mod", "A\nb\nc\nd\n", "A\n  b\nc\n  d\n")];
        let never = |_: &SourceFile, _: &str| -> Result<(), String> { panic!("no write") };
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let tally = settle(outcomes, Mode::Check, never, &mut out, &mut err);
        assert_eq!(
            String::from_utf8_lossy(&out),
            "a.mod: 2 lines would change\n"
        );
        assert_eq!(
            tally.summary(Mode::Check),
            "1 file would be reformatted (2 lines), 0 left unchanged"
        );
    }

    /// A path replaced by a FIFO after it was found is refused at once, to
    /// read and to write: opening a FIFO waits for the other end.
    #[cfg(unix)]
    #[test]
    fn a_fifo_is_refused_without_waiting() {
        let dir = std::env::temp_dir().join(format!("rapid-fmt-fifo-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a folder");
        let fifo = dir.join("pipe.mod");
        let _ = std::fs::remove_file(&fifo);
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .expect("mkfifo runs");
        assert!(made.success());
        let (send, receive) = std::sync::mpsc::channel();
        let path = fifo.clone();
        std::thread::spawn(move || {
            let read = read_regular(&path).map(|_| ());
            let file = SourceFile::from_bytes(path, b"MODULE M\nENDMODULE\n").expect("text");
            let written = write_back(&file, "MODULE M\nENDMODULE\n");
            let _ = send.send((read.map_err(|e| e.to_string()), written));
        });
        let (read, written) = receive
            .recv_timeout(std::time::Duration::from_secs(20))
            .expect("no wait on a FIFO");
        let _ = std::fs::remove_dir_all(&dir);
        let read = read.expect_err("a FIFO is not read");
        assert!(read.contains("not a regular file"), "{read}");
        assert!(written.is_err(), "a FIFO is not written");
    }
}
