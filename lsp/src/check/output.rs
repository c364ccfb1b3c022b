//! The report formats of `rapid check`.

use std::io::{self, Write};

use annotate_snippets::{AnnotationKind, Level, Renderer, Snippet};
use rapid_analyzer::diagnostic::{Diagnostic, Severity};

use super::Checked;

/// A diagnostic located for people: 1-based lines, columns in characters,
/// the end exclusive.
#[derive(Debug, serde::Serialize)]
pub struct Located<'a> {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
    pub severity: &'static str,
    pub code: &'static str,
    pub name: &'static str,
    pub message: &'a str,
}

pub fn locate<'a>(checked: &Checked, d: &'a Diagnostic) -> Located<'a> {
    let (line, column) = checked.file.human(d.range.start);
    let (end_line, end_column) = checked.file.human(d.range.end);
    Located {
        file: checked.file.path.display().to_string(),
        line,
        column,
        end_line,
        end_column,
        severity: d.severity.as_str(),
        code: d.rule.code,
        name: d.rule.name,
        message: &d.message,
    }
}

pub fn json(out: &mut impl Write, checked: &[Checked]) -> io::Result<()> {
    let all: Vec<Located<'_>> = checked
        .iter()
        .flat_map(|c| c.diagnostics.iter().map(move |d| locate(c, d)))
        .collect();
    serde_json::to_writer_pretty(&mut *out, &all)?;
    writeln!(out)
}

pub fn concise(out: &mut impl Write, checked: &[Checked]) -> io::Result<()> {
    for c in checked {
        for d in &c.diagnostics {
            let l = locate(c, d);
            writeln!(
                out,
                "{}:{}:{}: {}[{}] {} ({})",
                l.file, l.line, l.column, l.severity, l.code, l.message, l.name
            )?;
        }
    }
    Ok(())
}

pub fn human(out: &mut impl Write, checked: &[Checked]) -> io::Result<()> {
    let renderer = Renderer::styled();
    let mut counts = [0usize; 4];
    for c in checked {
        for d in &c.diagnostics {
            counts[d.severity as usize] += 1;
            let rendered = render_one(&renderer, c, d);
            writeln!(out, "{rendered}\n")?;
        }
    }
    let [hints, infos, warnings, errors] = counts;
    let files = checked.len();
    let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
    let mut parts = vec![plural(errors, "error"), plural(warnings, "warning")];
    if infos > 0 {
        parts.push(plural(infos, "note"));
    }
    if hints > 0 {
        parts.push(plural(hints, "hint"));
    }
    writeln!(
        out,
        "Checked {}: {}.",
        plural(files, "file"),
        parts.join(", ")
    )
}

/// One diagnostic with the source lines it covers (at most a few), so a
/// 9,000-line module is not handed whole to the renderer for each finding.
fn render_one(renderer: &Renderer, c: &Checked, d: &Diagnostic) -> String {
    const MOST_LINES: usize = 6;
    let file = &c.file;
    let first = file.lines.line_col(d.range.start).line;
    let last = file
        .lines
        .line_col(d.range.end)
        .line
        .min(first + MOST_LINES - 1);
    let start = file.lines.line_range(first, &file.text).start;
    let end = file.lines.line_range(last, &file.text).end;
    let source = file.text.get(start..end).unwrap_or_default();
    let span_start = d.range.start.saturating_sub(start).min(source.len());
    let span_end = d
        .range
        .end
        .saturating_sub(start)
        .clamp(span_start, source.len());
    let level = match d.severity {
        Severity::Error => Level::ERROR,
        Severity::Warning => Level::WARNING,
        Severity::Info => Level::INFO,
        Severity::Hint => Level::HELP,
    };
    let path = file.path.display().to_string();
    let title = format!("{} [{}]", d.message, d.rule.name);
    let report = [level.primary_title(title).id(d.rule.code).element(
        Snippet::source(source)
            .line_start(first + 1)
            .path(path)
            .annotation(AnnotationKind::Primary.span(span_start..span_end)),
    )];
    renderer.render(&report)
}
