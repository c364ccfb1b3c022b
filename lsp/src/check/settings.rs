//! Which rules apply to which file, and how severely: `rapid.toml`'s
//! `[lint]` section and `exclude`, the command-line flags over them, and the
//! inline suppressions in the source.

use std::path::{Component, Path, PathBuf};

use globset::{GlobBuilder, GlobSet, GlobSetBuilder};
use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use rapid_analyzer::rules::RULES;

use super::suppress::Suppressions;
use crate::config::{Config, LintConfig, is_known_selector, selects};

/// Command-line settings that override the configuration file.
#[derive(Clone, Debug, Default)]
pub struct Overrides {
    /// Replaces `[lint] select` when not empty.
    pub select: Vec<String>,
    /// Added to `[lint] ignore`; wins over every selection.
    pub ignore: Vec<String>,
    /// Added to `exclude`.
    pub exclude: Vec<String>,
    /// Findings less severe than this (after the configured severities)
    /// are not reported.
    pub min_severity: Option<Severity>,
}

/// Syntax errors: the controller does not load a module that has one, so
/// no selection, severity or suppression hides them or makes them less
/// than errors.
pub fn is_syntax_rule(rule: &rapid_analyzer::diagnostic::Rule) -> bool {
    use rapid_analyzer::rules::{equals_for_assignment, missing_token, syntax_error};
    [
        &syntax_error::RULE,
        &missing_token::RULE,
        &equals_for_assignment::RULE,
    ]
    .iter()
    .any(|r| r.code == rule.code)
}

/// The rules on, with their severity, for one file.
#[derive(Clone, Debug, PartialEq, Eq)]
struct RuleSet {
    /// Indexed like [`RULES`]: `None` when the rule is off.
    severity: Vec<Option<Severity>>,
    /// Indexed like [`RULES`]: the severity was configured. Otherwise each
    /// diagnostic keeps the severity the analyzer gave it (which may be
    /// lower than the rule's default, e.g. an ambiguous global in a plain
    /// folder, whose grouping into one task is only a guess).
    configured: Vec<bool>,
}

impl RuleSet {
    /// The rules on by default, at their default severity.
    fn all() -> RuleSet {
        RuleSet {
            severity: RULES
                .iter()
                .map(|r| r.default_on.then_some(r.severity))
                .collect(),
            configured: vec![false; RULES.len()],
        }
    }

    fn select(&mut self, selectors: &[String]) {
        if selectors.is_empty() {
            return;
        }
        for (slot, rule) in self.severity.iter_mut().zip(RULES) {
            let on = selectors.iter().any(|s| selects(s, rule));
            *slot = match (on, *slot) {
                (true, Some(sev)) => Some(sev),
                (true, None) => Some(rule.severity),
                (false, _) => None,
            };
        }
    }

    fn ignore(&mut self, selectors: &[String]) {
        for (slot, rule) in self.severity.iter_mut().zip(RULES) {
            if selectors.iter().any(|s| selects(s, rule)) {
                *slot = None;
            }
        }
    }

    fn set_severity<'a>(&mut self, map: impl IntoIterator<Item = (&'a String, &'a String)>) {
        for (selector, sev) in map {
            let Some(sev) = Severity::parse(sev) else {
                continue;
            };
            for ((slot, configured), rule) in self
                .severity
                .iter_mut()
                .zip(&mut self.configured)
                .zip(RULES)
            {
                if let Some(current) = slot
                    && selects(selector, rule)
                {
                    *current = sev;
                    *configured = true;
                }
            }
        }
    }

    /// `None` when the rule is off; else its severity (configured or default).
    #[cfg(test)]
    fn effective(&self, code: &str) -> Option<Severity> {
        let idx = RULES.iter().position(|r| r.code == code)?;
        self.severity.get(idx).copied().flatten()
    }

    /// `None` when the rule is off; else the configured severity, if any.
    fn of(&self, code: &str) -> Option<Option<Severity>> {
        let idx = RULES.iter().position(|r| r.code == code)?;
        let severity = self.severity.get(idx).copied().flatten()?;
        Some(
            self.configured
                .get(idx)
                .copied()
                .unwrap_or(false)
                .then_some(severity),
        )
    }
}

/// Everything that decides what is reported, resolved once per run.
#[derive(Debug)]
pub struct LintSettings {
    /// The folder that relative globs start from: the configuration file's,
    /// or the current folder without one.
    root: PathBuf,
    base: RuleSet,
    overrides: Vec<(GlobSet, LintConfigPart)>,
    /// Ignored on the command line: applied last, whatever the overrides say.
    cli_ignore: Vec<String>,
    exclude: GlobSet,
    min_severity: Option<Severity>,
}

#[derive(Debug)]
struct LintConfigPart {
    select: Vec<String>,
    ignore: Vec<String>,
    severity: Vec<(String, String)>,
}

/// A command-line setting that cannot be used.
#[derive(Debug)]
pub struct SettingsError(pub String);

impl std::fmt::Display for SettingsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl LintSettings {
    /// Resolves the configuration (whose globs are relative to `root`) and
    /// the command-line overrides. The configuration is assumed checked
    /// ([`crate::config::parse`]); the overrides are checked here.
    pub fn new(
        config: &Config,
        root: PathBuf,
        cli: &Overrides,
    ) -> Result<LintSettings, SettingsError> {
        for s in cli.select.iter().chain(&cli.ignore) {
            if !is_known_selector(s) {
                return Err(SettingsError(format!(
                    "no rule has the code or name `{s}` (see `rapid rules`)"
                )));
            }
        }
        let LintConfig {
            select,
            ignore,
            severity,
            overrides,
        } = &config.lint;
        let mut base = RuleSet::all();
        base.select(if cli.select.is_empty() {
            select
        } else {
            &cli.select
        });
        base.ignore(ignore);
        base.set_severity(severity);
        let mut parts = Vec::new();
        for o in overrides {
            parts.push((
                globs(&o.paths).map_err(SettingsError)?,
                LintConfigPart {
                    select: o.select.clone(),
                    ignore: o.ignore.clone(),
                    severity: o
                        .severity
                        .iter()
                        .map(|(k, v)| (k.clone(), v.clone()))
                        .collect(),
                },
            ));
        }
        let exclude: Vec<String> = config.exclude.iter().chain(&cli.exclude).cloned().collect();
        Ok(LintSettings {
            root,
            base,
            overrides: parts,
            cli_ignore: cli.ignore.clone(),
            exclude: globs(&exclude).map_err(SettingsError)?,
            min_severity: cli.min_severity,
        })
    }

    /// The path relative to the root, with `/` separators, as globs see it.
    fn relative(&self, path: &Path) -> String {
        let abs = normalize(&std::path::absolute(path).unwrap_or_else(|_| path.to_owned()));
        let rel = abs.strip_prefix(&self.root).unwrap_or(&abs);
        rel.to_string_lossy().replace('\\', "/")
    }

    /// Is this file or folder excluded?
    pub fn is_excluded(&self, path: &Path, is_dir: bool) -> bool {
        if self.exclude.is_empty() {
            return false;
        }
        let rel = self.relative(path);
        // A folder is excluded when everything in it would be (`old/**`).
        self.exclude.is_match(&rel) || (is_dir && self.exclude.is_match(format!("{rel}/-")))
    }

    fn rules_for(&self, path: &Path) -> std::borrow::Cow<'_, RuleSet> {
        if self.overrides.is_empty() && self.cli_ignore.is_empty() {
            return std::borrow::Cow::Borrowed(&self.base);
        }
        let rel = self.relative(path);
        let mut set = self.base.clone();
        for (glob, part) in &self.overrides {
            if glob.is_match(&rel) {
                set.select(&part.select);
                set.ignore(&part.ignore);
                set.set_severity(part.severity.iter().map(|(k, v)| (k, v)));
            }
        }
        set.ignore(&self.cli_ignore);
        std::borrow::Cow::Owned(set)
    }

    /// The rules the analyzer checks for `path`: those selected, and the
    /// syntax rules, which are always reported.
    pub fn selection_for(&self, path: &Path) -> rapid_analyzer::rules::Selection {
        let rules = self.rules_for(path);
        rapid_analyzer::rules::Selection::of(|r| is_syntax_rule(r) || rules.of(r.code).is_some())
    }

    /// Keeps the diagnostics of `path` that are selected and not
    /// suppressed in its `text`, at their configured severity, and at least
    /// as severe as the floor. Syntax errors are always kept, as errors
    /// ([`is_syntax_rule`]).
    pub fn apply(
        &self,
        path: &Path,
        text: &str,
        lines: &rapid_analyzer::text::LineIndex,
        diagnostics: Vec<Diagnostic>,
    ) -> Vec<Diagnostic> {
        if diagnostics.is_empty() {
            return diagnostics;
        }
        let rules = self.rules_for(path);
        let suppressions = Suppressions::parse(text, lines);
        diagnostics
            .into_iter()
            .filter_map(|mut d| {
                if is_syntax_rule(d.rule) {
                    d.severity = Severity::Error;
                    return Some(d);
                }
                let configured = rules.of(d.rule.code)?;
                if suppressions.suppresses(lines.line_col(d.range.start).line, d.rule) {
                    return None;
                }
                if let Some(severity) = configured {
                    d.severity = severity;
                }
                if self.min_severity.is_some_and(|floor| d.severity < floor) {
                    return None;
                }
                Some(d)
            })
            .collect()
    }
}

/// A glob set where a pattern without `/` matches a name at any depth (as
/// in `.gitignore`), and `*` does not cross folders.
fn globs(patterns: &[String]) -> Result<GlobSet, String> {
    let mut builder = GlobSetBuilder::new();
    for p in patterns {
        let p = p.trim_start_matches("./");
        let p = p.trim_end_matches('/');
        let pattern = if p.contains('/') {
            p.trim_start_matches('/').to_owned()
        } else {
            format!("**/{p}")
        };
        let glob = GlobBuilder::new(&pattern)
            .literal_separator(true)
            .build()
            .map_err(|e| format!("`{p}` is not a valid glob: {}", e.kind()))?;
        builder.add(glob);
    }
    builder.build().map_err(|e| e.to_string())
}

/// `a/./b/../c` as `a/c`, without touching the file system.
pub fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            other => out.push(other),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_analyzer::rules::find;

    fn settings(toml: &str, cli: Overrides) -> LintSettings {
        let config = crate::config::parse(toml, Path::new("rapid.toml")).expect("valid config");
        LintSettings::new(&config, PathBuf::from("/proj"), &cli).expect("valid settings")
    }

    fn severity(s: &LintSettings, path: &str, rule: &str) -> Option<&'static str> {
        let code = find(rule).expect("rule").code;
        s.rules_for(Path::new(path))
            .effective(code)
            .map(Severity::as_str)
    }

    #[test]
    fn rules_off_by_default_are_on_when_selected() {
        let default = settings("", Overrides::default());
        assert_eq!(severity(&default, "/proj/a.mod", "shadowed-name"), None);
        assert_eq!(severity(&default, "/proj/a.mod", "W101"), Some("warning"));
        let chosen = settings("[lint]\nselect = [\"E\", \"W\"]\n", Overrides::default());
        assert_eq!(
            severity(&chosen, "/proj/a.mod", "shadowed-name"),
            Some("warning")
        );
        let cli = settings(
            "",
            Overrides {
                select: vec!["W205".into()],
                ..Overrides::default()
            },
        );
        assert_eq!(severity(&cli, "/proj/a.mod", "W205"), Some("warning"));
        assert_eq!(severity(&cli, "/proj/a.mod", "W101"), None);
    }

    #[test]
    fn select_ignore_and_severity() {
        let s = settings(
            "[lint]\nselect = [\"E\", \"W201\"]\nignore = [\"E001\"]\n[lint.severity]\nunused-data = \"error\"\n",
            Overrides::default(),
        );
        assert_eq!(severity(&s, "/proj/a.mod", "W201"), Some("error"));
        assert_eq!(severity(&s, "/proj/a.mod", "W101"), None);
        assert_eq!(severity(&s, "/proj/a.mod", "E001"), None);
        assert_eq!(severity(&s, "/proj/a.mod", "E002"), Some("error"));
    }

    #[test]
    fn overrides_apply_to_their_paths_and_the_command_line_wins() {
        let s = settings(
            "[lint]\nignore = [\"W101\"]\n[[lint.overrides]]\npaths = [\"legacy/**\"]\nignore = [\"W2\"]\n\
             [lint.overrides.severity]\nW101 = \"error\"\n",
            Overrides {
                select: vec!["W".into()],
                ignore: vec!["unused-routine".into()],
                exclude: vec![],
                min_severity: None,
            },
        );
        assert_eq!(severity(&s, "/proj/a.mod", "W201"), Some("hint"));
        assert_eq!(severity(&s, "/proj/legacy/x/a.mod", "W201"), None);
        assert_eq!(severity(&s, "/proj/a.mod", "W101"), None);
        assert_eq!(severity(&s, "/proj/a.mod", "E001"), None);
        assert_eq!(severity(&s, "/proj/legacy/a.mod", "unused-routine"), None);
        assert_eq!(severity(&s, "/proj/a.mod", "unused-routine"), None);
    }

    /// The codes and severities `apply` keeps of one finding per rule.
    fn kept(s: &LintSettings, codes: &[&str], text: &str) -> Vec<(String, &'static str)> {
        let lines = rapid_analyzer::text::LineIndex::new(text);
        let found = codes
            .iter()
            .map(|c| Diagnostic::new(find(c).expect("rule"), 0..1, "x"))
            .collect();
        s.apply(Path::new("/proj/a.mod"), text, &lines, found)
            .into_iter()
            .map(|d| (d.rule.code.to_owned(), d.severity.as_str()))
            .collect()
    }

    #[test]
    fn syntax_errors_cannot_be_hidden_or_lowered() {
        let s = settings(
            "[lint]\nignore = [\"E002\"]\n[lint.severity]\nE001 = \"hint\"\n",
            Overrides {
                select: vec!["W".into()],
                ignore: vec!["syntax-error".into(), "E003".into()],
                ..Overrides::default()
            },
        );
        let codes = ["E001", "E002", "E003", "E201", "W101"];
        let text = "x ! rapid: ignore\n";
        assert_eq!(
            kept(&s, &codes, text),
            [
                ("E001".to_owned(), "error"),
                ("E002".to_owned(), "error"),
                ("E003".to_owned(), "error"),
            ],
            "W101 is suppressed in the text, E201 not selected"
        );
        assert_eq!(kept(&s, &codes, "x\n").len(), 4);
    }

    #[test]
    fn the_severity_floor_drops_what_is_below_it() {
        let s = settings(
            "[lint.severity]\nunused-data = \"error\"\n",
            Overrides {
                min_severity: Some(Severity::Warning),
                ..Overrides::default()
            },
        );
        let codes = ["W101", "W201", "I102", "E201"];
        assert_eq!(
            kept(&s, &codes, "x\n"),
            [
                ("W101".to_owned(), "warning"),
                ("W201".to_owned(), "error"),
                ("E201".to_owned(), "error"),
            ]
        );
    }

    #[test]
    fn excludes_match_relative_paths_and_names() {
        let s = settings(
            "exclude = [\"backup_old/**\", \"*.bak.mod\", \"./gen/\"]\n",
            Overrides::default(),
        );
        assert!(s.is_excluded(Path::new("/proj/backup_old"), true));
        assert!(s.is_excluded(Path::new("/proj/backup_old/a/b.mod"), false));
        assert!(s.is_excluded(Path::new("/proj/x/y.bak.mod"), false));
        assert!(s.is_excluded(Path::new("/proj/sub/gen"), true));
        assert!(!s.is_excluded(Path::new("/proj/src/backup_old.mod"), false));
        assert!(!s.is_excluded(Path::new("/proj/src/a.mod"), false));
    }

    #[test]
    fn unknown_rules_on_the_command_line_are_errors() {
        let config = Config::default();
        let err = LintSettings::new(
            &config,
            PathBuf::from("/"),
            &Overrides {
                select: vec!["X1".into()],
                ..Overrides::default()
            },
        )
        .expect_err("invalid");
        assert_eq!(
            err.to_string(),
            "no rule has the code or name `X1` (see `rapid rules`)"
        );
    }

    #[test]
    fn paths_are_normalized_lexically() {
        assert_eq!(normalize(Path::new("/a/./b/../c")), PathBuf::from("/a/c"));
    }
}
