//! The report formats of `rapid check`.

use std::collections::{BTreeMap, HashMap};
use std::fmt::Write as _;
use std::io::{self, Write};
use std::path::Path;

use annotate_snippets::{AnnotationKind, Level, Renderer, Snippet};
use rapid_analyzer::diagnostic::{Diagnostic, Rule, Severity};
use rapid_analyzer::rules::{RULES, anchor};
use serde_json::{Value, json};

use super::{Checked, Report, normalize};

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
    /// Whether `--fix` can fix it.
    pub fixable: bool,
}

pub fn locate<'a>(checked: &Checked, d: &'a Diagnostic) -> Located<'a> {
    let (line, column) = checked.file.human(d.range.start);
    let (end_line, end_column) = checked.file.human(d.range.end);
    Located {
        file: display_path(&checked.file.path),
        line,
        column,
        end_line,
        end_column,
        severity: d.severity.as_str(),
        code: d.rule.code,
        name: d.rule.name,
        message: &d.message,
        fixable: d.fix.as_ref().is_some_and(|f| f.is_safe()),
    }
}

fn all(report: &Report) -> impl Iterator<Item = (&Checked, &Diagnostic)> {
    report
        .checked
        .iter()
        .flat_map(|c| c.diagnostics.iter().map(move |d| (c, d)))
}

/// The project's home (from the package metadata; may be empty).
const REPOSITORY: &str = env!("CARGO_PKG_REPOSITORY");

/// Where the rule is documented, when the package names its repository.
pub fn help_uri(rule: &Rule) -> Option<String> {
    (!REPOSITORY.is_empty()).then(|| {
        format!(
            "{}/blob/main/docs/diagnostics.md#{}",
            REPOSITORY.trim_end_matches('/'),
            anchor(rule)
        )
    })
}

pub fn json(out: &mut impl Write, report: &Report) -> io::Result<()> {
    let all: Vec<Located<'_>> = all(report).map(|(c, d)| locate(c, d)).collect();
    serde_json::to_writer_pretty(&mut *out, &all)?;
    writeln!(out)
}

pub fn concise(out: &mut impl Write, report: &Report) -> io::Result<()> {
    for (c, d) in all(report) {
        let l = locate(c, d);
        writeln!(
            out,
            "{}:{}:{}: {}[{}] {} ({})",
            l.file, l.line, l.column, l.severity, l.code, l.message, l.name
        )?;
    }
    Ok(())
}

/// Counts per rule, most frequent first.
pub fn statistics(out: &mut impl Write, report: &Report, as_json: bool) -> io::Result<()> {
    let mut counts: BTreeMap<&'static str, (usize, &'static Rule, usize)> = BTreeMap::new();
    for (_, d) in all(report) {
        let entry = counts.entry(d.rule.code).or_insert((0, d.rule, 0));
        entry.0 += 1;
        if d.fix.as_ref().is_some_and(|f| f.is_safe()) {
            entry.2 += 1;
        }
    }
    let mut rows: Vec<_> = counts.into_values().collect();
    rows.sort_by(|a, b| b.0.cmp(&a.0).then(a.1.code.cmp(b.1.code)));
    if as_json {
        let rows: Vec<Value> = rows
            .iter()
            .map(|(n, rule, fixable)| {
                json!({"code": rule.code, "name": rule.name, "count": n, "fixable": fixable})
            })
            .collect();
        serde_json::to_writer_pretty(&mut *out, &rows)?;
        return writeln!(out);
    }
    for (n, rule, fixable) in rows {
        let fix = if fixable > 0 {
            format!(" ({fixable} fixable)")
        } else {
            String::new()
        };
        writeln!(out, "{n:>6}  {}  {}{fix}", rule.code, rule.name)?;
    }
    Ok(())
}

/// `styled`: the output shows colours (rendering plain text costs a third of
/// rendering styled text and stripping the styles again).
pub fn human(out: &mut impl Write, report: &Report, styled: bool) -> io::Result<()> {
    let renderer = if styled {
        Renderer::styled()
    } else {
        Renderer::plain()
    };
    let mut counts = [0usize; 4];
    let mut fixable = 0;
    let by_path = checked_by_path(report);
    for (c, d) in all(report) {
        counts[d.severity as usize] += 1;
        fixable += usize::from(d.fix.as_ref().is_some_and(|f| f.is_safe()));
        let rendered = render_one(&renderer, c, d, &related_note(&by_path, c, d));
        writeln!(out, "{rendered}\n")?;
    }
    let [hints, infos, warnings, errors] = counts;
    let files = report.checked.len();
    let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
    let mut parts = vec![plural(errors, "error"), plural(warnings, "warning")];
    if infos > 0 {
        parts.push(plural(infos, "note"));
    }
    if hints > 0 {
        parts.push(plural(hints, "hint"));
    }
    let mut line = format!("Checked {}: {}.", plural(files, "file"), parts.join(", "));
    if !report.skipped.is_empty() {
        let _ = write!(line, " Skipped {}.", plural(report.skipped.len(), "file"));
    }
    if report.fixed > 0 {
        let _ = write!(line, " Fixed {}.", plural(report.fixed, "problem"));
    }
    if report.baselined > 0 {
        let _ = write!(
            line,
            " {} in the baseline not shown.",
            plural(report.baselined, "finding")
        );
    }
    if fixable > 0 {
        let _ = write!(line, " {fixable} fixable with `--fix`.");
    }
    writeln!(out, "{line}")
}

/// One diagnostic with the source lines it covers (at most a few), so a
/// 9,000-line module is not handed whole to the renderer for each finding.
fn render_one(renderer: &Renderer, c: &Checked, d: &Diagnostic, note: &str) -> String {
    const MOST_LINES: usize = 6;
    let file = &c.file;
    let first = file.lines.line_col(d.range.start).line;
    let last = file
        .lines
        .line_col(d.range.end)
        .line
        .min(first + MOST_LINES - 1);
    let mut start = file.lines.line_range(first, &file.text).start;
    let mut end = file.lines.line_range(last, &file.text).end;
    // A long line (generated code has lines of megabytes) is shown around
    // the finding only: the renderer reads what it is given, per finding.
    let (mut before, mut after) = ("", "");
    if end - start > MOST_BYTES {
        let line_end = file.lines.line_range(first, &file.text).end;
        let from = floor_boundary(
            &file.text,
            d.range.start.saturating_sub(MOST_BYTES / 4).max(start),
        );
        let to = floor_boundary(
            &file.text,
            (d.range.end.max(d.range.start) + MOST_BYTES / 4)
                .min(d.range.start + MOST_BYTES / 2)
                .min(line_end),
        );
        if from > start {
            before = "…";
        }
        if to < end {
            after = "…";
        }
        (start, end) = (from, to.max(from));
    }
    let source = format!(
        "{before}{}{after}",
        file.text.get(start..end).unwrap_or_default()
    );
    let span_start = (d.range.start.saturating_sub(start) + before.len()).min(source.len());
    let span_end = (d.range.end.saturating_sub(start) + before.len())
        .clamp(span_start, source.len() - after.len());
    let level = match d.severity {
        Severity::Error => Level::ERROR,
        Severity::Warning => Level::WARNING,
        Severity::Info => Level::INFO,
        Severity::Hint => Level::HELP,
    };
    let path = display_path(&file.path);
    let title = format!("{} [{}]", d.message, d.rule.name);
    let mut group = level.primary_title(title).id(d.rule.code).element(
        Snippet::source(&source)
            .line_start(first + 1)
            .path(path)
            .annotation(AnnotationKind::Primary.span(span_start..span_end)),
    );
    if !note.is_empty() {
        group = group.element(Level::NOTE.message(note));
    }
    renderer.render(&[group])
}

/// The checked files by the name the analyzer knows them by (for related
/// locations in other files).
fn checked_by_path(report: &Report) -> HashMap<String, &Checked> {
    report
        .checked
        .iter()
        .map(|c| (super::unit_path(&c.file.path), c))
        .collect()
}

/// The related locations of a finding as one note: `used here too: 12:5,
/// Lib.mod:40:9 and 7 more` (a place in the finding's own file is its line
/// and column); places in files that were not checked are left out.
fn related_note(by_path: &HashMap<String, &Checked>, c: &Checked, d: &Diagnostic) -> String {
    const SHOWN: usize = 3;
    let mut groups: Vec<(&str, Vec<String>)> = Vec::new();
    for r in &d.related {
        let target = match &r.file {
            None => c,
            Some(path) => match by_path.get(path.as_str()) {
                Some(t) => t,
                None => continue,
            },
        };
        let (line, column) = target.file.human(r.range.start);
        // In the finding's own file, the line and column say enough.
        let place = if std::ptr::eq(target, c) {
            format!("{line}:{column}")
        } else {
            format!("{}:{line}:{column}", display_path(&target.file.path))
        };
        match groups.iter_mut().find(|(m, _)| *m == r.message) {
            Some((_, places)) => places.push(place),
            None => groups.push((&r.message, vec![place])),
        }
    }
    let mut notes = Vec::new();
    for (message, places) in groups {
        let more = places.len().saturating_sub(SHOWN);
        let mut shown = places
            .into_iter()
            .take(SHOWN)
            .collect::<Vec<_>>()
            .join(", ");
        if more > 0 {
            let _ = write!(shown, " and {more} more");
        }
        notes.push(format!("{message}: {shown}"));
    }
    notes.join("; ")
}

/// The most bytes of source shown with one finding (a long line is cut
/// around it).
const MOST_BYTES: usize = 400;

/// `at`, or the start of the character holding it.
fn floor_boundary(text: &str, mut at: usize) -> usize {
    at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

/// A path as given on the command line, without a leading `./`.
pub fn display_path(path: &Path) -> String {
    let s = path.display().to_string();
    match s.strip_prefix("./") {
        Some(rest) if !rest.is_empty() => rest.to_owned(),
        _ => s,
    }
}

/// GitHub Actions workflow commands, one annotation per diagnostic.
pub fn github(out: &mut impl Write, report: &Report) -> io::Result<()> {
    for (c, d) in all(report) {
        let l = locate(c, d);
        let command = match d.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info | Severity::Hint => "notice",
        };
        writeln!(
            out,
            "::{command} file={},line={},col={},endLine={},endColumn={},title={}::{}",
            escape_property(&display_path(&c.file.path)),
            l.line,
            l.column,
            l.end_line,
            l.end_column,
            escape_property(&format!("{} {}", l.code, l.name)),
            escape_data(&format!("{} [{}]", l.message, l.code)),
        )?;
    }
    for (path, why) in &report.skipped {
        writeln!(
            out,
            "::warning file={},title=rapid check::{}",
            escape_property(&display_path(path)),
            escape_data(why)
        )?;
    }
    Ok(())
}

/// A workflow command's message: `%`, CR and LF escaped.
pub fn escape_data(s: &str) -> String {
    s.replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// A workflow command's property value: also `:` and `,`.
pub fn escape_property(s: &str) -> String {
    escape_data(s).replace(':', "%3A").replace(',', "%2C")
}

fn sarif_level(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info | Severity::Hint => "note",
    }
}

/// The documentation of a rule without the doc comment's leading space.
fn doc_markdown(rule: &Rule) -> String {
    let mut out = String::new();
    for line in rule.doc.lines() {
        out.push_str(line.strip_prefix(' ').unwrap_or(line));
        out.push('\n');
    }
    out
}

/// The "What it checks" part of a rule's documentation, as plain text.
fn what_it_checks(doc: &str) -> String {
    let mut lines = doc
        .lines()
        .map(str::trim)
        .skip_while(|l| *l != "### What it checks")
        .skip(1)
        .take_while(|l| !l.starts_with("###"));
    let mut text = String::new();
    for l in lines.by_ref() {
        if !l.is_empty() {
            if !text.is_empty() {
                text.push(' ');
            }
            text.push_str(l);
        }
    }
    text
}

fn sarif_rule(rule: &Rule) -> Value {
    let full = what_it_checks(rule.doc);
    let mut value = json!({
        "id": rule.code,
        "name": rule.name,
        "shortDescription": {"text": rule.summary},
        "fullDescription": {"text": if full.is_empty() { rule.summary.to_owned() } else { full }},
        "help": {"text": doc_markdown(rule), "markdown": doc_markdown(rule)},
        "defaultConfiguration": {"level": sarif_level(rule.severity)},
        "properties": {"tags": [rule.severity.as_str()]},
    });
    if let Some(uri) = help_uri(rule) {
        value["helpUri"] = json!(uri);
    }
    value
}

/// `path` relative to `root` as a URI reference (percent-encoded, `/`
/// separators), or an absolute `file://` URI when it is not below `root`.
pub fn relative_uri(path: &Path, root: &Path) -> (String, bool) {
    let abs = normalize(&std::path::absolute(path).unwrap_or_else(|_| path.to_owned()));
    match abs.strip_prefix(root) {
        Ok(rel) => (encode_uri_path(&rel.to_string_lossy()), true),
        Err(_) => (
            format!("file://{}", encode_uri_path(&abs.to_string_lossy())),
            false,
        ),
    }
}

fn encode_uri_path(path: &str) -> String {
    let mut out = String::with_capacity(path.len());
    for b in path.replace('\\', "/").bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                out.push(char::from(b));
            }
            _ => {
                let _ = write!(out, "%{b:02X}");
            }
        }
    }
    out
}

/// A cheap, stable fingerprint: FNV-1a of the rule, the file and the
/// trimmed text of the line, so the result survives lines moving (the
/// fingerprint adds how many findings of the rule came before on such a
/// line).
fn line_hash(rule: &str, uri: &str, line_text: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for part in [rule, uri, line_text.trim()] {
        for b in part.bytes().chain([0]) {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

/// SARIF 2.1.0, as GitHub code scanning reads it: every rule with its
/// documentation, results with regions relative to `root`.
pub fn sarif(out: &mut impl Write, report: &Report, root: &Path) -> io::Result<()> {
    let rules: Vec<Value> = RULES.iter().map(|r| sarif_rule(r)).collect();
    let mut results = Vec::new();
    let mut seen: BTreeMap<u64, usize> = BTreeMap::new();
    let mut hashes: HashMap<(*const Checked, &str, usize), u64> = HashMap::new();
    let by_path = checked_by_path(report);
    for (c, d) in all(report) {
        let l = locate(c, d);
        let (uri, relative) = relative_uri(&c.file.path, root);
        let mut artifact = json!({"uri": uri});
        if relative {
            artifact["uriBaseId"] = json!("%SRCROOT%");
        }
        let line = c.file.lines.line_col(d.range.start).line;
        // One hash per rule and line: findings on a long line would each
        // hash it again.
        let hash = *hashes
            .entry((std::ptr::from_ref(c), d.rule.code, line))
            .or_insert_with(|| {
                let line_text = c
                    .file
                    .text
                    .get(c.file.lines.line_range(line, &c.file.text))
                    .unwrap_or_default();
                line_hash(d.rule.code, &uri, line_text)
            });
        let nth = seen.entry(hash).or_default();
        let print = format!("{hash:016x}:{nth}");
        *nth += 1;
        let mut result = json!({
            "ruleId": d.rule.code,
            "level": sarif_level(d.severity),
            "message": {"text": d.message},
            "locations": [{
                "physicalLocation": {
                    "artifactLocation": artifact,
                    "region": {
                        "startLine": l.line,
                        "startColumn": l.column,
                        "endLine": l.end_line,
                        "endColumn": l.end_column,
                    }
                }
            }],
            "partialFingerprints": {"rapidLineHash/v1": print},
        });
        if let Some(index) = RULES.iter().position(|r| r.code == d.rule.code) {
            result["ruleIndex"] = json!(index);
        }
        let related: Vec<Value> = d
            .related
            .iter()
            .enumerate()
            .filter_map(|(id, r)| {
                // Another file is shown only when it was checked too (an
                // extra path's module has no place in the report).
                let target = match &r.file {
                    None => c,
                    Some(path) => *by_path.get(path.as_str())?,
                };
                let (line, column) = target.file.human(r.range.start);
                let (end_line, end_column) = target.file.human(r.range.end);
                let (uri, relative) = relative_uri(&target.file.path, root);
                let mut artifact = json!({"uri": uri});
                if relative {
                    artifact["uriBaseId"] = json!("%SRCROOT%");
                }
                Some(json!({
                    "id": id,
                    "message": {"text": r.message},
                    "physicalLocation": {
                        "artifactLocation": artifact,
                        "region": {
                            "startLine": line,
                            "startColumn": column,
                            "endLine": end_line,
                            "endColumn": end_column,
                        }
                    }
                }))
            })
            .collect();
        if !related.is_empty() {
            result["relatedLocations"] = json!(related);
        }
        results.push(result);
    }
    let notifications: Vec<Value> = report
        .skipped
        .iter()
        .map(|(path, why)| {
            let (uri, relative) = relative_uri(path, root);
            let mut artifact = json!({"uri": uri});
            if relative {
                artifact["uriBaseId"] = json!("%SRCROOT%");
            }
            json!({
                "level": "warning",
                "message": {"text": why},
                "locations": [{"physicalLocation": {"artifactLocation": artifact}}],
            })
        })
        .collect();
    let root_uri = format!(
        "file://{}/",
        encode_uri_path(root.to_string_lossy().trim_end_matches(['/', '\\']))
    );
    let mut driver = json!({
        "name": "rapid",
        "version": env!("CARGO_PKG_VERSION"),
        "rules": rules,
    });
    if !REPOSITORY.is_empty() {
        driver["informationUri"] = json!(REPOSITORY);
    }
    let log = json!({
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": driver},
            "invocations": [{
                "executionSuccessful": true,
                "toolExecutionNotifications": notifications,
            }],
            "originalUriBaseIds": {"%SRCROOT%": {"uri": root_uri}},
            "columnKind": "unicodeCodePoints",
            "results": results,
        }],
    });
    serde_json::to_writer_pretty(&mut *out, &log)?;
    writeln!(out)
}

/// Text for XML attributes and content.
fn xml(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            '\t' => out.push('\t'),
            // Not allowed in XML 1.0 at all.
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

/// JUnit XML: a test suite per file, a test case per diagnostic (failing at
/// error level) or one passing case for a clean file.
pub fn junit(out: &mut impl Write, report: &Report) -> io::Result<()> {
    let tests: usize = report
        .checked
        .iter()
        .map(|c| c.diagnostics.len().max(1))
        .sum::<usize>()
        + report.skipped.len();
    let failures = all(report)
        .filter(|(_, d)| d.severity == Severity::Error)
        .count();
    writeln!(out, r#"<?xml version="1.0" encoding="UTF-8"?>"#)?;
    writeln!(
        out,
        r#"<testsuites name="rapid check" tests="{tests}" failures="{failures}" errors="0">"#
    )?;
    for c in &report.checked {
        let path = xml(&display_path(&c.file.path));
        let failing = c
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .count();
        writeln!(
            out,
            r#"  <testsuite name="{path}" tests="{}" failures="{failing}" errors="0" skipped="0">"#,
            c.diagnostics.len().max(1)
        )?;
        if c.diagnostics.is_empty() {
            writeln!(
                out,
                r#"    <testcase name="{path}" classname="{path}" file="{path}"/>"#
            )?;
        }
        for d in &c.diagnostics {
            let l = locate(c, d);
            let name = xml(&format!("{}:{} {} {}", l.line, l.column, l.code, l.name));
            write!(
                out,
                r#"    <testcase name="{name}" classname="{path}" file="{path}" line="{}">"#,
                l.line
            )?;
            let detail = xml(&format!(
                "{}:{}:{}: {}[{}] {}",
                display_path(&c.file.path),
                l.line,
                l.column,
                l.severity,
                l.code,
                l.message
            ));
            if d.severity == Severity::Error {
                write!(
                    out,
                    r#"<failure message="{}" type="{}">{detail}</failure>"#,
                    xml(l.message),
                    l.code
                )?;
            } else {
                write!(out, "<system-out>{detail}</system-out>")?;
            }
            writeln!(out, "</testcase>")?;
        }
        writeln!(out, "  </testsuite>")?;
    }
    for (path, why) in &report.skipped {
        let path = xml(&display_path(path));
        writeln!(
            out,
            r#"  <testsuite name="{path}" tests="1" failures="0" errors="0" skipped="1">"#
        )?;
        writeln!(
            out,
            r#"    <testcase name="{path}" classname="{path}" file="{path}"><skipped message="{}"/></testcase>"#,
            xml(why)
        )?;
        writeln!(out, "  </testsuite>")?;
    }
    writeln!(out, "</testsuites>")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn workflow_commands_are_escaped() {
        assert_eq!(escape_data("50% a\r\nb: c, d"), "50%25 a%0D%0Ab: c, d");
        assert_eq!(escape_property("a:b,c%\n"), "a%3Ab%2Cc%25%0A");
    }

    #[test]
    fn uris_are_relative_and_encoded() {
        let root = Path::new("/proj");
        assert_eq!(
            relative_uri(Path::new("/proj/src/my mod#1.mod"), root),
            ("src/my%20mod%231.mod".to_owned(), true)
        );
        assert_eq!(
            relative_uri(Path::new("/other/a.mod"), root),
            ("file:///other/a.mod".to_owned(), false)
        );
    }

    #[test]
    fn xml_is_escaped() {
        assert_eq!(
            xml("a<b & \"c\"\n\u{1}"),
            "a&lt;b &amp; &quot;c&quot;&#10;\u{FFFD}"
        );
    }

    #[test]
    fn every_rule_has_a_full_description() {
        for rule in RULES {
            assert!(!what_it_checks(rule.doc).is_empty(), "{}", rule.code);
        }
    }
}
