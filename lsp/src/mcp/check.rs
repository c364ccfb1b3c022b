//! The `check`, `fix` and `format` tools: `rapid check`'s run
//! ([`crate::check::report_in`]) and `rapid fmt`'s formatter on files of
//! the roots, or on an unsaved text laid over its file.

use std::path::{Path, PathBuf};

use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::roots::{Confined, resolve, resolve_unsaved};
use super::{Answer, shown};
use crate::check::{CheckArgs, Checked, Format, apply_safe_fixes, report_in};

/// The arguments of `check`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CheckParams {
    /// A module or a folder (a task, a backup, a project) to check; relative
    /// paths start at the first root. With `text`: the file the text is the
    /// unsaved content of (it need not exist yet), or the folder of the task
    /// it joins; the rest of that task is read from disk.
    pub path: Option<String>,
    /// The text of a module to check instead of the file's content.
    pub text: Option<String>,
    /// Report only these rules (codes like `W201`, prefixes like `E`, or
    /// names like `unused-data`); default: the project's `rapid.toml`.
    #[serde(default)]
    pub select: Vec<String>,
    /// Do not report these rules (added to `rapid.toml`'s `ignore`).
    #[serde(default)]
    pub ignore: Vec<String>,
    /// Report only findings at least this severe: `error`, `warning`,
    /// `info` or `hint`.
    pub min_severity: Option<String>,
    /// At most this many findings in the answer (default 200); the counts
    /// are always complete.
    pub limit: Option<usize>,
}

/// A finding, located for people: 1-based lines, columns in characters,
/// the end exclusive.
#[derive(Debug, Serialize, JsonSchema)]
pub struct Finding {
    /// The file, relative to the root it lies in; `<text>` for a text
    /// that belongs to no file.
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
    /// `error`, `warning`, `info` or `hint`.
    pub severity: String,
    /// The rule's stable code (`E201`); `explain_rule` documents it.
    pub code: String,
    /// The rule's name (`unresolved-name`).
    pub name: String,
    pub message: String,
    /// The rule's repair, when it has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fix: Option<FixInfo>,
}

/// A repair of a finding.
#[derive(Debug, Serialize, JsonSchema)]
pub struct FixInfo {
    pub title: String,
    /// Safe fixes keep the program's meaning: the `fix` tool applies them.
    pub safe: bool,
    /// The edits, in the file's text before any fix.
    pub edits: Vec<EditInfo>,
}

/// Replace the text from (line, column) to (end_line, end_column).
#[derive(Debug, Serialize, JsonSchema)]
pub struct EditInfo {
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
    pub replacement: String,
}

/// The answer of `check`.
#[derive(Debug, Serialize, JsonSchema)]
pub struct CheckReport {
    /// Modules checked.
    pub files_checked: usize,
    pub errors: usize,
    pub warnings: usize,
    /// Findings of severity `info` or `hint`.
    pub notes: usize,
    /// The findings, by file and position (at most `limit`).
    pub findings: Vec<Finding>,
    /// Whether findings were left out for the limit.
    pub truncated: bool,
    /// Files not checked (encrypted, binary, too large, unreadable), with
    /// why.
    pub skipped: Vec<String>,
    /// What the run said on the way (paths that could not be read...).
    pub messages: Vec<String>,
}

/// What a request checks: the environment (the roots, with the text laid
/// over its file), the path to check, and the text's file.
struct Target {
    env: Confined,
    path: PathBuf,
    text_file: Option<PathBuf>,
}

/// Where `text` belongs: the file `path` names (or a file named after its
/// module in the folder `path` names), else a file of no folder.
fn target(roots: &[PathBuf], path: Option<&str>, text: Option<&str>) -> Result<Target, String> {
    let mut env = Confined::new(roots.to_vec());
    let Some(text) = text else {
        let path = path.ok_or("give `path`, `text`, or both")?;
        let path = resolve(roots, path)?;
        return Ok(Target {
            env,
            path,
            text_file: None,
        });
    };
    let file = match path {
        Some(path) => {
            let path = resolve_unsaved(roots, path)?;
            if path.is_dir() {
                path.join(format!("{}.mod", module_name(text)))
            } else {
                path
            }
        }
        None => unsaved_file(text),
    };
    env.lay(file.clone(), text.to_owned());
    Ok(Target {
        env,
        path: file.clone(),
        text_file: Some(file),
    })
}

/// A text's place when it belongs to no task: a file in a folder that
/// does not exist, so that no other module joins it.
fn unsaved_file(text: &str) -> PathBuf {
    std::env::temp_dir()
        .join(format!("rapid-mcp-{}-unsaved", std::process::id()))
        .join(format!("{}.mod", module_name(text)))
}

/// The name of the first module of `text` (`untitled` without one, or for
/// a text too large to be a module, which is not parsed).
fn module_name(text: &str) -> String {
    if text.len() as u64 > crate::project::MAX_FILE_BYTES {
        return "untitled".to_owned();
    }
    let unit = rapid_analyzer::task::Unit::new("<text>".to_owned(), text.to_owned(), None);
    unit.items
        .modules
        .first()
        .map(|m| m.name.clone())
        .filter(|n| n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') && !n.is_empty())
        .unwrap_or_else(|| "untitled".to_owned())
}

/// `rapid check`'s arguments for a request.
fn check_args(path: PathBuf, p: &CheckParams) -> Result<CheckArgs, String> {
    let min_severity =
        match &p.min_severity {
            Some(s) => Some(Severity::parse(s).ok_or_else(|| {
                format!("min_severity: `{s}` is not error, warning, info or hint")
            })?),
            None => None,
        };
    Ok(CheckArgs {
        paths: vec![path],
        format: Format::Json,
        select: p.select.clone(),
        ignore: p.ignore.clone(),
        min_severity,
        ..CheckArgs::default()
    })
}

/// A check's report: the files checked with their findings, the files
/// skipped and what was said.
struct Run {
    checked: Vec<Checked>,
    skipped: Vec<(PathBuf, String)>,
    messages: Vec<String>,
}

fn run_check(target: &Target, params: &CheckParams) -> Result<Run, String> {
    let args = check_args(target.path.clone(), params)?;
    let mut said = Vec::new();
    let (report, _root, _failed) = report_in(&target.env, &args, &mut said)?;
    let messages = String::from_utf8_lossy(&said)
        .lines()
        .map(|l| l.strip_prefix("rapid: ").unwrap_or(l).to_owned())
        .filter(|l| !l.is_empty())
        .collect();
    Ok(Run {
        checked: report.checked,
        skipped: report.skipped,
        messages,
    })
}

/// The finding `d` of the file `c`.
fn finding(roots: &[PathBuf], c: &Checked, d: &Diagnostic, text_file: Option<&Path>) -> Finding {
    let at = |offset: usize| c.file.human(offset);
    let (line, column) = at(d.range.start);
    let (end_line, end_column) = at(d.range.end);
    Finding {
        file: file_label(roots, &c.file.path, text_file),
        line,
        column,
        end_line,
        end_column,
        severity: d.severity.as_str().to_owned(),
        code: d.rule.code.to_owned(),
        name: d.rule.name.to_owned(),
        message: d.message.clone(),
        fix: d
            .fix
            .as_ref()
            .filter(|f| !f.edits.is_empty())
            .map(|f| FixInfo {
                title: f.title.clone(),
                safe: f.is_safe(),
                edits: f
                    .edits
                    .iter()
                    .map(|e| {
                        let (line, column) = at(e.range.start.min(c.file.text.len()));
                        let (end_line, end_column) = at(e.range.end.min(c.file.text.len()));
                        EditInfo {
                            line,
                            column,
                            end_line,
                            end_column,
                            replacement: e.replacement.clone(),
                        }
                    })
                    .collect(),
            }),
    }
}

fn file_label(roots: &[PathBuf], path: &Path, text_file: Option<&Path>) -> String {
    if text_file.is_some_and(|t| t == path) && !roots.iter().any(|r| path.starts_with(r)) {
        return "<text>".to_owned();
    }
    shown(roots, path)
}

/// `check`: the findings of a path or a text.
pub fn check(roots: &[PathBuf], params: CheckParams) -> Result<Answer<CheckReport>, String> {
    let target = target(roots, params.path.as_deref(), params.text.as_deref())?;
    let run = run_check(&target, &params)?;
    let limit = params.limit.unwrap_or(200);
    let mut report = CheckReport {
        files_checked: run.checked.len(),
        errors: 0,
        warnings: 0,
        notes: 0,
        findings: Vec::new(),
        truncated: false,
        skipped: run
            .skipped
            .iter()
            .map(|(p, why)| format!("{}: {why}", shown(roots, p)))
            .collect(),
        messages: run.messages,
    };
    for c in &run.checked {
        for d in &c.diagnostics {
            match d.severity {
                Severity::Error => report.errors += 1,
                Severity::Warning => report.warnings += 1,
                _ => report.notes += 1,
            }
            if report.findings.len() < limit {
                report
                    .findings
                    .push(finding(roots, c, d, target.text_file.as_deref()));
            } else {
                report.truncated = true;
            }
        }
    }
    let summary = check_summary(&report);
    Ok(Answer::new(summary, report))
}

fn check_summary(r: &CheckReport) -> String {
    let mut out = format!(
        "{} file{} checked: {} error{}, {} warning{}, {} note{}\n",
        r.files_checked,
        plural(r.files_checked),
        r.errors,
        plural(r.errors),
        r.warnings,
        plural(r.warnings),
        r.notes,
        plural(r.notes)
    );
    for f in &r.findings {
        let fix = match &f.fix {
            Some(fix) if fix.safe => format!(" [fix: {}]", fix.title),
            Some(fix) => format!(" [suggestion: {}]", fix.title),
            None => String::new(),
        };
        out.push_str(&format!(
            "{}:{}:{}: {}[{}] {} ({}){fix}\n",
            f.file, f.line, f.column, f.severity, f.code, f.message, f.name
        ));
    }
    if r.truncated {
        out.push_str("(more findings left out: raise `limit`)\n");
    }
    for s in r.skipped.iter().chain(&r.messages) {
        out.push_str(&format!("note: {s}\n"));
    }
    out
}

pub fn plural(n: usize) -> &'static str {
    if n == 1 { "" } else { "s" }
}

/// The arguments of `fix`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FixParams {
    /// The module text to repair; without it, the file at `path` is read
    /// (and not written: the answer holds the new text).
    pub text: Option<String>,
    /// The file the text belongs to (it need not exist), or the folder of
    /// its task: its task's other modules are read from disk, so names they
    /// declare are known. Without it the text is checked alone.
    pub path: Option<String>,
}

/// The answer of `fix`.
#[derive(Debug, Serialize, JsonSchema)]
pub struct FixReport {
    /// The text with every safe fix applied.
    pub text: String,
    /// How many fixes were applied.
    pub fixed: usize,
    /// Whether the text changed.
    pub changed: bool,
    /// What is still found in the new text (safe fixes that overlapped are
    /// applied in later passes; what remains needs a person or an unsafe
    /// suggestion).
    pub remaining: Vec<Finding>,
}

/// `fix`: the safe fixes of a text applied, in up to four passes (a fix can
/// make room for another); nothing is written.
pub fn fix(roots: &[PathBuf], params: FixParams) -> Result<Answer<FixReport>, String> {
    let path = match params.text {
        Some(_) => None,
        None => params
            .path
            .as_deref()
            .map(|p| resolve(roots, p))
            .transpose()?,
    };
    let original = text_of(roots, params.text.as_deref(), path.as_deref())?;
    let check_params = CheckParams {
        path: params.path.clone(),
        text: None,
        select: Vec::new(),
        ignore: Vec::new(),
        min_severity: None,
        limit: None,
    };
    let mut text = original.clone();
    let mut fixed = 0;
    let mut remaining = Vec::new();
    for pass in 0..5 {
        let target = target(roots, params.path.as_deref(), Some(&text))?;
        let run = run_check(&target, &check_params)?;
        let mine = run
            .checked
            .iter()
            .find(|c| Some(&c.file.path) == target.text_file.as_ref());
        let Some(mine) = mine else {
            let why = run.skipped.first().map_or_else(
                || "the text was not checked".to_owned(),
                |(_, why)| why.clone(),
            );
            return Err(why);
        };
        let applied = if pass < 4 {
            apply_safe_fixes(&mine.file.text, &mine.diagnostics)
        } else {
            None
        };
        match applied {
            Some((new, n)) => {
                text = new;
                fixed += n;
            }
            None => {
                remaining = mine
                    .diagnostics
                    .iter()
                    .map(|d| finding(roots, mine, d, target.text_file.as_deref()))
                    .collect();
                break;
            }
        }
    }
    let report = FixReport {
        changed: text != original,
        text,
        fixed,
        remaining,
    };
    let mut summary = format!(
        "applied {} fix{}; {} finding{} remain{}\n",
        report.fixed,
        if report.fixed == 1 { "" } else { "es" },
        report.remaining.len(),
        plural(report.remaining.len()),
        if report.remaining.len() == 1 { "s" } else { "" }
    );
    for f in &report.remaining {
        summary.push_str(&format!(
            "{}:{}: {}[{}] {}\n",
            f.line, f.column, f.severity, f.code, f.message
        ));
    }
    if report.changed {
        summary.push_str("\nThe repaired text:\n");
        summary.push_str(&report.text);
    }
    Ok(Answer::new(summary, report))
}

/// The text a request gives, else the text of the file at `path`.
fn text_of(roots: &[PathBuf], text: Option<&str>, path: Option<&Path>) -> Result<String, String> {
    match (text, path) {
        (Some(text), _) => Ok(text.to_owned()),
        (None, Some(path)) => crate::project::read_source(&Confined::new(roots.to_vec()), path)
            .map(|file| file.text)
            .map_err(|why| format!("{}: {why}", shown(roots, path))),
        (None, None) => Err("give `text`, `path`, or both".to_owned()),
    }
}

/// The arguments of `format`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FormatParams {
    /// The module text to format; without it, the file at `path` is read
    /// (and not written).
    pub text: Option<String>,
    /// The file the text belongs to: the `[format]` settings of the
    /// `rapid.toml` above it apply.
    pub path: Option<String>,
    /// `as-written` (indentation only), `tight` (`a:=b+1;`) or `spaced`
    /// (`a := b + 1;`); default: `rapid.toml`'s, else `as-written`.
    pub style: Option<String>,
}

/// The answer of `format`.
#[derive(Debug, Serialize, JsonSchema)]
pub struct FormatReport {
    /// The formatted text.
    pub text: String,
    pub changed: bool,
    /// How many lines differ.
    pub changed_lines: usize,
}

/// `format`: the text laid out as `rapid fmt` would; nothing is written.
pub fn format(roots: &[PathBuf], params: FormatParams) -> Result<Answer<FormatReport>, String> {
    let env = Confined::new(roots.to_vec());
    let path = params
        .path
        .as_deref()
        .map(|p| match params.text {
            Some(_) => resolve_unsaved(roots, p),
            None => resolve(roots, p),
        })
        .transpose()?;
    let text = text_of(roots, params.text.as_deref(), path.as_deref())?;
    let start = path
        .clone()
        .unwrap_or_else(|| roots.first().cloned().unwrap_or_default());
    let (config, _) = crate::config::resolve_in(&env, None, &start).map_err(|e| e.to_string())?;
    let mut options = config.format.options();
    if let Some(style) = &params.style {
        options.style = match style.as_str() {
            "as-written" => rapid_analyzer::format::Style::AsWritten,
            "tight" => rapid_analyzer::format::Style::Tight,
            "spaced" => rapid_analyzer::format::Style::Spaced,
            other => {
                return Err(format!(
                    "style: `{other}` is not as-written, tight or spaced"
                ));
            }
        };
    }
    let formatted = rapid_analyzer::format::format(&text, &options).map_err(|e| e.to_string())?;
    let changed_lines = similar::TextDiff::from_lines(&text, &formatted)
        .iter_all_changes()
        .filter(|c| c.tag() == similar::ChangeTag::Insert)
        .count();
    let report = FormatReport {
        changed: formatted != text,
        text: formatted,
        changed_lines,
    };
    let summary = if report.changed {
        format!(
            "{} line{} changed:\n{}",
            report.changed_lines,
            plural(report.changed_lines),
            report.text
        )
    } else {
        "already formatted".to_owned()
    };
    Ok(Answer::new(summary, report))
}
