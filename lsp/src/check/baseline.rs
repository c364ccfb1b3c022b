//! `rapid check --baseline FILE`: adopting the linter on a project that has
//! findings already. The first run records them in FILE; later runs report
//! only findings that are not in it.
//!
//! A finding is known by its rule, its file (relative to the baseline's
//! folder, so the file does not depend on where the command runs) and the
//! code it points at: the text of its line and of its range, with runs of
//! blanks made one space. Line numbers are not part of it, so lines added
//! or removed elsewhere in the file, or a new indentation, leave the
//! baseline valid. The same finding on two equal lines is counted: a third
//! copy of the line is new.
//!
//! The file is JSON, sorted, one entry per distinct finding, so that its
//! changes read well in a review. Syntax errors are neither recorded nor
//! left out: a module with one does not load, whatever its age.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use rapid_analyzer::diagnostic::Diagnostic;
use serde::{Deserialize, Serialize};

use super::Checked;
use super::settings::is_syntax_rule;
use crate::project::source::SourceFile;

/// The format's version, written in the file.
const VERSION: u32 = 1;

#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
struct Key {
    file: String,
    code: String,
    /// The finding's first line, blanks collapsed.
    line: String,
    /// The text of the finding's range, blanks collapsed.
    at: String,
}

#[derive(Debug, Serialize, Deserialize)]
struct Entry {
    #[serde(flatten)]
    key: Key,
    /// The rule's name, for whoever reads the file (not matched).
    #[serde(default)]
    name: String,
    count: usize,
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
struct File {
    rapid_baseline: u32,
    findings: Vec<Entry>,
}

/// Findings recorded in a baseline file.
#[derive(Debug)]
pub struct Baseline {
    /// The folder that the files' paths are relative to.
    dir: PathBuf,
    counts: BTreeMap<Key, usize>,
}

/// What filtering a report through a baseline did.
#[derive(Debug, Default, PartialEq, Eq)]
pub struct Filtered {
    /// Findings of the baseline that were found again (not reported).
    pub known: usize,
    /// Findings of the baseline that were not found any more.
    pub gone: usize,
}

impl Baseline {
    /// Reads a baseline file; `Ok(None)` when it does not exist.
    pub fn read(path: &Path) -> Result<Option<Baseline>, String> {
        let text = match std::fs::read_to_string(path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) => return Err(format!("{}: cannot read the baseline: {e}", path.display())),
        };
        let file: File = serde_json::from_str(&text).map_err(|e| {
            format!(
                "{}:{}:{}: not a baseline file of `rapid check`: {e}",
                path.display(),
                e.line(),
                e.column()
            )
        })?;
        if file.rapid_baseline != VERSION {
            return Err(format!(
                "{}: a baseline of format {} (this rapid reads format {VERSION}); record it again",
                path.display(),
                file.rapid_baseline
            ));
        }
        let mut counts = BTreeMap::new();
        for e in file.findings {
            *counts.entry(e.key).or_default() += e.count;
        }
        Ok(Some(Baseline {
            dir: folder_of(path),
            counts,
        }))
    }

    /// Removes from `checked` the findings the baseline holds (as many of
    /// each as it counts).
    pub fn filter(&self, checked: &mut [Checked]) -> Filtered {
        let mut left = self.counts.clone();
        let mut known = 0;
        for c in checked.iter_mut() {
            let file = relative(&self.dir, &c.file.path);
            let source = &c.file;
            c.diagnostics.retain(|d| {
                if is_syntax_rule(d.rule) {
                    return true;
                }
                let key = key_of(&file, source, d);
                match left.get_mut(&key) {
                    Some(n) if *n > 0 => {
                        *n -= 1;
                        known += 1;
                        false
                    }
                    _ => true,
                }
            });
        }
        Filtered {
            known,
            gone: left.values().sum(),
        }
    }
}

/// Writes the findings of `checked` as the baseline `path`; returns how
/// many it holds.
pub fn record(path: &Path, checked: &[Checked]) -> Result<usize, String> {
    let dir = folder_of(path);
    let mut entries: BTreeMap<Key, (String, usize)> = BTreeMap::new();
    let mut total = 0;
    for c in checked {
        let file = relative(&dir, &c.file.path);
        for d in c.diagnostics.iter().filter(|d| !is_syntax_rule(d.rule)) {
            let entry = entries
                .entry(key_of(&file, &c.file, d))
                .or_insert_with(|| (d.rule.name.to_owned(), 0));
            entry.1 += 1;
            total += 1;
        }
    }
    let file = File {
        rapid_baseline: VERSION,
        findings: entries
            .into_iter()
            .map(|(key, (name, count))| Entry { key, name, count })
            .collect(),
    };
    let mut text = serde_json::to_string_pretty(&file).map_err(|e| e.to_string())?;
    text.push('\n');
    std::fs::write(path, text)
        .map_err(|e| format!("{}: cannot write the baseline: {e}", path.display()))?;
    Ok(total)
}

fn key_of(file: &str, source: &SourceFile, d: &Diagnostic) -> Key {
    let text = &source.text;
    let line = source.lines.line_col(d.range.start).line;
    let line_text = text
        .get(source.lines.line_range(line, text))
        .unwrap_or_default();
    Key {
        file: file.to_owned(),
        code: d.rule.code.to_owned(),
        line: collapse(line_text),
        at: collapse(text.get(d.range.clone()).unwrap_or_default()),
    }
}

/// Blanks (and line breaks) as one space, none at the ends.
fn collapse(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The folder a baseline's paths are relative to: its own, as the analyzer
/// names it (absolute, links resolved).
fn folder_of(path: &Path) -> PathBuf {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    PathBuf::from(crate::project::source::analyzer_path(dir))
}

/// A file's path relative to `dir`, with `/` separators (absolute when it
/// is not below `dir`).
fn relative(dir: &Path, file: &Path) -> String {
    let real = PathBuf::from(crate::project::source::analyzer_path(file));
    let rel = real.strip_prefix(dir).unwrap_or(&real);
    rel.to_string_lossy().replace('\\', "/")
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_analyzer::rules::find;

    /// A checked file with a finding of `code` at each `(code, nth
    /// occurrence of the text)`.
    fn checked(path: &str, text: &str, found: &[(&str, &str, usize)]) -> Checked {
        let file = SourceFile::from_bytes(PathBuf::from(path), text.as_bytes()).expect("text");
        let diagnostics = found
            .iter()
            .map(|(code, at, nth)| {
                let (start, _) = text.match_indices(at).nth(*nth).expect("in the text");
                Diagnostic::new(find(code).expect("rule"), start..start + at.len(), "x")
            })
            .collect();
        Checked { file, diagnostics }
    }

    #[test]
    fn findings_are_matched_by_code_and_text_not_by_line() {
        let dir = std::env::temp_dir().join(format!("rapid-baseline-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("folder");
        let base = dir.join("baseline.json");
        let a = dir.join("A.mod").to_string_lossy().into_owned();
        let before = "MODULE A\n  PROC p()\n    Foo;\n    Foo;\n  ENDPROC\nENDMODULE\n";
        let two_foos = [("W101", "Foo", 0), ("W101", "Foo", 1)];
        let recorded = record(&base, &[checked(&a, before, &two_foos)]).expect("written");
        assert_eq!(recorded, 2);
        let written = std::fs::read_to_string(&base).expect("read");
        assert!(
            written.contains("\"file\": \"A.mod\"") && written.contains("\"count\": 2"),
            "{written}"
        );
        let baseline = Baseline::read(&base).expect("valid").expect("there");
        // Lines added above, indentation changed, a third `Foo;` and a new
        // finding: only those two are new.
        let after = "MODULE A\n  VAR num n;\n  PROC p()\n  Foo;\n      Foo;\n    Foo;\n    Bar;\n  ENDPROC\nENDMODULE\n";
        let mut now = vec![checked(
            &a,
            after,
            &[
                ("W101", "Foo", 0),
                ("W101", "Foo", 1),
                ("W101", "Foo", 2),
                ("W101", "Bar", 0),
            ],
        )];
        assert_eq!(baseline.filter(&mut now), Filtered { known: 2, gone: 0 });
        let left: Vec<&str> = now[0]
            .diagnostics
            .iter()
            .map(|d| &after[d.range.clone()])
            .collect();
        assert_eq!(left, ["Foo", "Bar"]);
        // Another rule on the same code is new; a finding fixed since is
        // counted as gone.
        let mut fixed = vec![checked(
            &a,
            before,
            &[("W101", "Foo", 0), ("E201", "Foo", 1)],
        )];
        assert_eq!(baseline.filter(&mut fixed), Filtered { known: 1, gone: 1 });
        assert_eq!(fixed[0].diagnostics.len(), 1);
        // A syntax error is never recorded, so never left out.
        let broken = [("W101", "Foo", 0), ("E002", "Foo", 1)];
        assert_eq!(
            record(&base, &[checked(&a, before, &broken)]).expect("w"),
            1
        );
        let baseline = Baseline::read(&base).expect("valid").expect("there");
        let mut again = vec![checked(&a, before, &broken)];
        assert_eq!(baseline.filter(&mut again), Filtered { known: 1, gone: 0 });
        assert_eq!(again[0].diagnostics[0].rule.code, "E002");
        std::fs::write(&base, "{\"rapid-baseline\": 7, \"findings\": []}").expect("w");
        let err = Baseline::read(&base).expect_err("a future format");
        assert!(err.contains("format 7"), "{err}");
        std::fs::write(&base, "[1,").expect("w");
        let err = Baseline::read(&base).expect_err("broken");
        assert!(err.contains("baseline.json:1:"), "{err}");
        let _ = std::fs::remove_dir_all(&dir);
        assert!(Baseline::read(&base).expect("no file").is_none());
    }
}
