//! `rapid.toml`, the project's configuration file.
//!
//! Found by walking up from the first path given on the command line (or
//! named with `--config FILE`). Every section and key is optional; an
//! unknown key is an error naming the file, the line and the key, so a typo
//! never silently does nothing.
//!
//! ```toml
//! exclude = ["backup_old/**"]     # never checked (globs, relative to this file)
//! extra-paths = ["../controller"] # modules and EIO.cfg the program uses, not reported
//!
//! [format]
//! style = "spaced"   # blanks inside lines: "as-written" (default), "tight", "spaced"
//! indent-width = 4   # spaces per level (default: each file's own indentation)
//! line-width = 100   # procedure calls wrapped past this width (default: never)
//!
//! [lint]
//! select = ["E", "W101"]      # rules by code, code prefix or name (default: all)
//! ignore = ["unused-data"]    # taken away from the selection
//!
//! [lint.severity]
//! unused-data = "error"       # error, warning, info or hint
//!
//! [[lint.overrides]]          # for some files only (globs, relative to this file)
//! paths = ["legacy/**"]
//! ignore = ["W"]
//! ```
//!
//! The same structure deserialises from JSON (the language server's
//! `initializationOptions`), with the same keys.

use std::path::{Path, PathBuf};

use std::collections::BTreeMap;

use crate::project::{Environment, Kind};
use rapid_analyzer::diagnostic::{Rule, Severity};
use rapid_analyzer::format::{FormatOptions, Style};
use rapid_analyzer::rules::RULES;
use serde::Deserialize;

/// The name of the configuration file.
pub const FILE_NAME: &str = "rapid.toml";

/// The whole configuration: one field per section.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "kebab-case")]
pub struct Config {
    /// Globs of files and folders never checked, relative to the
    /// configuration file's folder.
    pub exclude: Vec<String>,
    /// Folders (or files) holding more modules of the program or the
    /// controller's `EIO.cfg`: they are analysed with the checked files but
    /// their own diagnostics are not reported. Relative to the configuration
    /// file's folder.
    pub extra_paths: Vec<PathBuf>,
    /// `[format]`: the layout `rapid fmt` produces.
    pub format: FormatConfig,
    /// `[lint]`: which rules `rapid check` reports, and how severely.
    pub lint: LintConfig,
    /// `[controller]`: the RobotWare version and options the code runs on.
    pub controller: ControllerConfig,
}

/// `[controller]`: what a backup's `BACKINFO` would say; each key set here
/// wins over the backup's.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "kebab-case")]
pub struct ControllerConfig {
    /// The RobotWare version, e.g. "6.15": calls are checked against its
    /// signatures and newer built-ins are reported. Unset: every version's
    /// built-ins and signatures are accepted.
    pub robotware: Option<String>,
    /// The enabled option packages by id ("arc", "egm"...; `rapid builtins`
    /// lists them). Unset: the backup's, else none.
    pub options: Option<Vec<String>>,
    /// The robot ("IRB 120-3/0.58", or MOC.cfg's "ROB1_120_0.58_3") for
    /// tasks whose MOC.cfg does not name one: moves are checked against its
    /// reach and joint limits. Unset: not checked.
    pub robot: Option<String>,
    /// The robot's working range of each axis, degrees (`[[-165, 165],
    /// ...]`, six pairs). Unset: the model's data sheet.
    pub joint_limits: Option<Vec<[f64; 2]>>,
    /// What `GetSysInfo` answers in `rapid run` (`\SystemName`,
    /// `\SerialNo`, `\LanIp`, `\CtrlId`, `\CtrlLang`). Unset: the
    /// backup's `BACKINFO` and `MOC.cfg`, else a virtual controller's.
    pub system_name: Option<String>,
    pub serial_number: Option<String>,
    pub lan_ip: Option<String>,
    pub controller_id: Option<String>,
    pub language: Option<String>,
    /// The task names by task number (`["T_ROB1", "T_ROB2"]` names the
    /// folders `RAPID/TASK1` and `RAPID/TASK2`), for backups kept without
    /// `SYSPAR/SYS.cfg` and `BACKINFO`. Unset: the folders' names.
    pub tasks: Option<Vec<String>>,
}

impl ControllerConfig {
    /// The analyzer's form; the first problem (key, why) when a value is
    /// not a RobotWare version or not a known option.
    pub fn resolve(
        &self,
    ) -> Result<rapid_analyzer::controller::ControllerOverride, (String, String)> {
        let robotware = match &self.robotware {
            Some(v) => Some(
                rapid_analyzer::catalogue::Version::parse(v)
                    .map_err(|e| ("robotware".to_string(), e))?,
            ),
            None => None,
        };
        // The catalogue only when there are options to look up: loading it
        // takes tens of milliseconds, which `rapid check` spends on a
        // thread that parsing leaves idle.
        if let Some(options) = &self.options {
            let cat = rapid_analyzer::catalogue::base();
            for o in options {
                if cat.package(o).is_none() {
                    let ids: Vec<&str> = cat.packages.iter().map(|p| p.id.as_str()).collect();
                    return Err((
                        o.clone(),
                        format!("`{o}` is not an option package; known: {}", ids.join(", ")),
                    ));
                }
            }
        }
        let robot = match &self.robot {
            Some(name) => {
                rapid_robot::find_model(name).map_err(|why| ("robot".to_owned(), why))?;
                let limits = match &self.joint_limits {
                    Some(l) => match <[[f64; 2]; 6]>::try_from(l.as_slice()) {
                        Ok(l) if l.iter().all(|[lo, hi]| lo < hi) => Some(l),
                        _ => {
                            return Err((
                                "joint-limits".into(),
                                "six [lower, upper] pairs in degrees, lower below upper".into(),
                            ));
                        }
                    },
                    None => None,
                };
                Some(rapid_analyzer::robot::RobotSetting {
                    name: name.clone(),
                    limits,
                })
            }
            None if self.joint_limits.is_some() => {
                return Err((
                    "joint-limits".into(),
                    "joint limits need `robot` (the model they belong to)".into(),
                ));
            }
            None => None,
        };
        if let Some(bad) = self.tasks.iter().flatten().find(|t| !is_task_name(t)) {
            return Err((
                "tasks".into(),
                format!(
                    "`{bad}` is not a task name (a RAPID name: a letter, then letters, digits or `_`)"
                ),
            ));
        }
        Ok(rapid_analyzer::controller::ControllerOverride {
            robotware,
            options: self.options.clone(),
            robot,
            tasks: self.tasks.clone(),
        })
    }
}

/// A controller task's name: a RAPID name (the language's rule, Latin-1
/// letters included).
fn is_task_name(name: &str) -> bool {
    !name.is_empty() && rapid_analyzer::names::name_len(name) == name.len()
}

/// `[lint]`.
#[derive(Clone, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "kebab-case")]
pub struct LintConfig {
    /// Rules to report, by code, code prefix (`"E"`, `"W1"`) or name; empty
    /// means every rule.
    pub select: Vec<String>,
    /// Rules not to report (same forms), taken from the selection.
    pub ignore: Vec<String>,
    /// Severity by rule code or name: `"error"`, `"warning"`, `"info"` or
    /// `"hint"`.
    pub severity: BTreeMap<String, String>,
    /// Settings for some files only, applied in order after the ones above.
    pub overrides: Vec<LintOverride>,
}

/// `[[lint.overrides]]`: `select`, `ignore` and `severity` for the files
/// matching `paths`.
#[derive(Clone, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "kebab-case")]
pub struct LintOverride {
    /// Globs relative to the configuration file's folder.
    pub paths: Vec<String>,
    /// Replaces the selection for these files when not empty.
    pub select: Vec<String>,
    /// Added to the ignored rules for these files.
    pub ignore: Vec<String>,
    /// Added to (and overriding) the severities for these files.
    pub severity: BTreeMap<String, String>,
}

/// Does `selector` (a code, a code prefix or a name, any case) pick `rule`?
pub fn selects(selector: &str, rule: &Rule) -> bool {
    rule.name.eq_ignore_ascii_case(selector)
        || rule
            .code
            .get(..selector.len())
            .is_some_and(|prefix| prefix.eq_ignore_ascii_case(selector))
}

/// Is `selector` a code, code prefix or name of at least one rule?
pub fn is_known_selector(selector: &str) -> bool {
    !selector.is_empty() && RULES.iter().any(|r| selects(selector, r))
}

impl LintConfig {
    /// Every rule selector and severity of the section (and its overrides)
    /// that names no rule, or a severity that is not one, with a message.
    pub fn problems(&self) -> Vec<(String, String)> {
        let mut out = Vec::new();
        let check_list = |list: &[String], key: &str, out: &mut Vec<(String, String)>| {
            for s in list {
                if !is_known_selector(s) {
                    out.push((
                        s.clone(),
                        format!("`{key}`: no rule has the code or name `{s}`"),
                    ));
                }
            }
        };
        let check_severity = |map: &BTreeMap<String, String>, out: &mut Vec<(String, String)>| {
            for (rule, sev) in map {
                if !is_known_selector(rule) {
                    out.push((
                        rule.clone(),
                        format!("`severity`: no rule has the code or name `{rule}`"),
                    ));
                }
                if Severity::parse(sev).is_none() {
                    out.push((
                        sev.clone(),
                        format!(
                            "`severity.{rule}`: `{sev}` is not one of error, warning, info, hint"
                        ),
                    ));
                }
            }
        };
        check_list(&self.select, "select", &mut out);
        check_list(&self.ignore, "ignore", &mut out);
        check_severity(&self.severity, &mut out);
        for o in &self.overrides {
            if o.paths.is_empty() {
                out.push((
                    "[[lint.overrides]]".into(),
                    "`[[lint.overrides]]` needs `paths`".into(),
                ));
            }
            for glob in &o.paths {
                if let Err(e) = globset::Glob::new(glob) {
                    out.push((
                        glob.clone(),
                        format!("`paths`: `{glob}` is not a valid glob: {}", e.kind()),
                    ));
                }
            }
            check_list(&o.select, "select", &mut out);
            check_list(&o.ignore, "ignore", &mut out);
            check_severity(&o.severity, &mut out);
        }
        out
    }
}

/// `[format]`.
#[derive(Clone, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "kebab-case")]
pub struct FormatConfig {
    /// How the blanks inside lines are written.
    pub style: StyleName,
    /// Spaces per indentation level (1 to 16); unset: each file's own.
    pub indent_width: Option<usize>,
    /// The width past which procedure calls are wrapped (at least 20);
    /// unset: lines are never broken.
    pub line_width: Option<usize>,
}

/// The values of `[format] style`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum StyleName {
    #[default]
    AsWritten,
    Tight,
    Spaced,
}

impl FormatConfig {
    pub fn options(&self) -> FormatOptions {
        FormatOptions {
            style: match self.style {
                StyleName::AsWritten => Style::AsWritten,
                StyleName::Tight => Style::Tight,
                StyleName::Spaced => Style::Spaced,
            },
            indent_width: self.indent_width,
            line_width: self.line_width,
        }
    }
}

/// A configuration file that cannot be used.
#[derive(Debug, PartialEq, Eq)]
pub struct ConfigError {
    pub path: PathBuf,
    /// 1-based line of the problem, when known.
    pub line: Option<usize>,
    pub message: String,
}

impl std::fmt::Display for ConfigError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{line}: {}", self.path.display(), self.message),
            None => write!(f, "{}: {}", self.path.display(), self.message),
        }
    }
}

/// The text of a configuration file (a regular file in UTF-8; a FIFO or a
/// device is refused without blocking).
pub fn read_text(path: &Path) -> std::io::Result<String> {
    let bytes = crate::project::source::read_regular(path)?;
    String::from_utf8(bytes)
        .map_err(|_| std::io::Error::new(std::io::ErrorKind::InvalidData, "not UTF-8 text"))
}

/// Reads and checks a configuration file in `env`.
pub fn load_in(env: &dyn Environment, path: &Path) -> Result<Config, ConfigError> {
    let text = env
        .read(path)
        .and_then(|bytes| {
            String::from_utf8(bytes)
                .map_err(|_| std::io::Error::new(std::io::ErrorKind::InvalidData, "not UTF-8 text"))
        })
        .map_err(|e| ConfigError {
            path: path.to_owned(),
            line: None,
            message: format!("cannot read the configuration: {e}"),
        })?;
    parse(&text, path)
}

/// Parses and checks the text of a configuration file (`path` is for
/// messages).
pub fn parse(text: &str, path: &Path) -> Result<Config, ConfigError> {
    let config: Config = toml::from_str(text).map_err(|e| {
        let line = e
            .span()
            .map(|span| text[..span.start.min(text.len())].matches('\n').count() + 1);
        ConfigError {
            path: path.to_owned(),
            line,
            message: e.message().trim_end().replace('\n', " "),
        }
    })?;
    let invalid = |key: &str, why: &str| ConfigError {
        path: path.to_owned(),
        line: key_line(text, key),
        message: format!("`{key}` {why}"),
    };
    if config
        .format
        .indent_width
        .is_some_and(|w| !(1..=16).contains(&w))
    {
        return Err(invalid("indent-width", "must be between 1 and 16"));
    }
    if config.format.line_width.is_some_and(|w| w < 20) {
        return Err(invalid("line-width", "must be at least 20"));
    }
    for glob in &config.exclude {
        if let Err(e) = globset::Glob::new(glob) {
            return Err(ConfigError {
                path: path.to_owned(),
                line: value_line(text, glob),
                message: format!("`exclude`: `{glob}` is not a valid glob: {}", e.kind()),
            });
        }
    }
    if let Err((key, why)) = config.controller.resolve() {
        return Err(ConfigError {
            path: path.to_owned(),
            line: key_line(text, &key).or_else(|| value_line(text, &key)),
            message: format!("[controller]: {why}"),
        });
    }
    if let Some((value, message)) = config.lint.problems().into_iter().next() {
        return Err(ConfigError {
            path: path.to_owned(),
            line: value_line(text, &value),
            message,
        });
    }
    Ok(config)
}

/// The line where `key` is set, for messages about its value.
fn key_line(text: &str, key: &str) -> Option<usize> {
    text.lines()
        .position(|l| {
            l.trim_start()
                .strip_prefix(key)
                .is_some_and(|rest| rest.trim_start().starts_with('='))
        })
        .map(|i| i + 1)
}

/// The first line where `value` appears (quoted, or as a bare key), for
/// messages about a value inside a list or table.
fn value_line(text: &str, value: &str) -> Option<usize> {
    let quoted = [format!("\"{value}\""), format!("'{value}'")];
    text.lines()
        .position(|l| {
            quoted.iter().any(|q| l.contains(q.as_str()))
                || l.trim_start()
                    .strip_prefix(value)
                    .is_some_and(|rest| rest.trim_start().starts_with('='))
                || l.trim() == value
        })
        .map(|i| i + 1)
}

/// The nearest `rapid.toml` in `start`'s folder (or `start` itself if it is
/// a folder) and its parents.
pub fn find(start: &Path) -> Option<PathBuf> {
    find_in(&crate::project::Disk, start)
}

/// [`find`] in `env` (a folder it refuses ends the search).
pub fn find_in(env: &dyn Environment, start: &Path) -> Option<PathBuf> {
    let start = std::path::absolute(start).ok()?;
    let mut dir = if env.kind(&start).is_ok_and(|k| k == Kind::Folder) {
        Some(start.as_path())
    } else {
        start.parent()
    };
    while let Some(d) = dir {
        let candidate = d.join(FILE_NAME);
        if matches!(env.kind(&candidate), Ok(Kind::File(_))) {
            return Some(candidate);
        }
        dir = d.parent();
    }
    None
}

/// The configuration for a run: the file named explicitly, else the one
/// found from `first_path`, else the defaults; with the file it came from
/// (its folder is the root that relative globs and paths start from).
pub fn resolve_with_path(
    explicit: Option<&Path>,
    first_path: &Path,
) -> Result<(Config, Option<PathBuf>), ConfigError> {
    resolve_in(&crate::project::Disk, explicit, first_path)
}

/// [`resolve_with_path`] in `env`.
pub fn resolve_in(
    env: &dyn Environment,
    explicit: Option<&Path>,
    first_path: &Path,
) -> Result<(Config, Option<PathBuf>), ConfigError> {
    match explicit
        .map(Path::to_owned)
        .or_else(|| find_in(env, first_path))
    {
        Some(path) => load_in(env, &path).map(|config| (config, Some(path))),
        None => Ok((Config::default(), None)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(text: &str) -> Result<Config, String> {
        parse(text, Path::new("rapid.toml")).map_err(|e| e.to_string())
    }

    #[test]
    fn controller_section_is_checked() {
        let ok = check("[controller]\nrobotware = \"6.15\"\noptions = [\"arc\", \"egm\"]\n");
        let sel = ok.map(|c| c.controller.resolve());
        assert!(
            matches!(sel, Ok(Ok(ref o)) if o.robotware.map(|v| v.to_string()).as_deref() == Some("6.15"))
        );
        let bad = check("[controller]\nrobotware = \"six\"\n")
            .err()
            .unwrap_or_default();
        assert!(
            bad.contains(":2: [controller]") && bad.contains("not a RobotWare version"),
            "{bad}"
        );
        let bad = check("[controller]\noptions = [\"arcc\"]\n")
            .err()
            .unwrap_or_default();
        assert!(
            bad.contains(":2: [controller]: `arcc` is not an option package"),
            "{bad}"
        );
        let robot = check("[controller]\nrobot = \"ROB1_120_0.58_3\"\njoint-limits = [[-90, 90], [-110, 110], [-110, 70], [-160, 160], [-120, 120], [-400, 400]]\n").map(|c| c.controller.resolve());
        assert!(
            matches!(robot, Ok(Ok(ref o)) if o.robot.as_ref().is_some_and(|r| r.limits.is_some_and(|l| l[0] == [-90.0, 90.0]))),
            "{robot:?}"
        );
        let bad = check("[controller]\nrobot = \"IRB 9999\"\n")
            .err()
            .unwrap_or_default();
        assert!(
            bad.contains("is not a modelled robot; known: IRB 120-3/0.58"),
            "{bad}"
        );
        let bad = check("[controller]\nrobot = \"IRB 14000\"\n")
            .err()
            .unwrap_or_default();
        assert!(
            bad.contains("not modelled: IRB 14000: a seven-axis dual arm"),
            "{bad}"
        );
        let bad = check("[controller]\nrobot = \"IRB 120\"\njoint-limits = [[1, 0]]\n")
            .err()
            .unwrap_or_default();
        assert!(bad.contains("six [lower, upper] pairs"), "{bad}");
    }

    #[test]
    fn an_empty_file_is_the_defaults() {
        assert_eq!(check(""), Ok(Config::default()));
        assert_eq!(check("[format]\n"), Ok(Config::default()));
    }

    #[test]
    fn format_settings_are_read() {
        let config = check("[format]\nstyle = \"tight\"\nindent-width = 2\nline-width = 80\n")
            .expect("valid");
        assert_eq!(
            config.format.options(),
            FormatOptions {
                style: Style::Tight,
                indent_width: Some(2),
                line_width: Some(80)
            }
        );
        let defaults = check("[format]\n").expect("valid").format.options();
        assert_eq!(defaults, FormatOptions::default());
        assert_eq!(defaults.style, Style::AsWritten);
    }

    #[test]
    fn unknown_keys_name_the_file_line_and_key() {
        let err = check("[format]\nindent-width = 2\nindent_size = 3\n").expect_err("invalid");
        assert!(
            err.starts_with("rapid.toml:3: unknown field `indent_size`"),
            "{err}"
        );
        let err = check("[formatting]\n").expect_err("invalid");
        assert!(
            err.starts_with("rapid.toml:1: unknown field `formatting`"),
            "{err}"
        );
    }

    #[test]
    fn lint_settings_are_read() {
        let config = check(
            "exclude = [\"old/**\"]\nextra-paths = [\"../ctrl\"]\n[lint]\nselect = [\"E\", \"W101\"]\nignore = [\"unused-data\"]\n\
             [lint.severity]\nunused-data = \"error\"\n[[lint.overrides]]\npaths = [\"legacy/**\"]\nignore = [\"W\"]\n",
        )
        .expect("valid");
        assert_eq!(config.exclude, ["old/**"]);
        assert_eq!(config.extra_paths, [PathBuf::from("../ctrl")]);
        assert_eq!(config.lint.select, ["E", "W101"]);
        assert_eq!(config.lint.ignore, ["unused-data"]);
        assert_eq!(config.lint.severity["unused-data"], "error");
        assert_eq!(config.lint.overrides[0].paths, ["legacy/**"]);
        assert_eq!(config.lint.overrides[0].ignore, ["W"]);
    }

    #[test]
    fn the_same_keys_deserialise_from_json() {
        let json = r#"{"exclude": ["a/**"], "lint": {"ignore": ["W2"], "severity": {"W201": "error"}}, "format": {"line-width": 100}}"#;
        let config: Config = serde_json::from_str(json).expect("valid");
        assert_eq!(config.exclude, ["a/**"]);
        assert_eq!(config.lint.ignore, ["W2"]);
        assert_eq!(config.format.line_width, Some(100));
        assert!(serde_json::from_str::<Config>(r#"{"lint": {"slect": []}}"#).is_err());
    }

    #[test]
    fn unknown_rules_severities_and_globs_are_errors_with_their_line() {
        let err = check("[lint]\nselect = [\"E\",\n  \"W999\"]\n").expect_err("invalid");
        assert_eq!(
            err,
            "rapid.toml:3: `select`: no rule has the code or name `W999`"
        );
        let err = check("[lint]\nignore = [\"unused-dta\"]\n").expect_err("invalid");
        assert_eq!(
            err,
            "rapid.toml:2: `ignore`: no rule has the code or name `unused-dta`"
        );
        let err = check("[lint.severity]\nunused-data = \"fatal\"\n").expect_err("invalid");
        assert_eq!(
            err,
            "rapid.toml:2: `severity.unused-data`: `fatal` is not one of error, warning, info, hint"
        );
        let err = check("[lint.severity]\nno-such-rule = \"error\"\n").expect_err("invalid");
        assert_eq!(
            err,
            "rapid.toml:2: `severity`: no rule has the code or name `no-such-rule`"
        );
        let err = check("exclude = [\"a/[b\"]\n").expect_err("invalid");
        assert!(
            err.starts_with("rapid.toml:1: `exclude`: `a/[b` is not a valid glob"),
            "{err}"
        );
        let err =
            check("[[lint.overrides]]\npaths = [\"x\"]\nignor = [\"W\"]\n").expect_err("invalid");
        assert!(
            err.starts_with("rapid.toml:3: unknown field `ignor`"),
            "{err}"
        );
    }

    #[test]
    fn selectors_match_codes_prefixes_and_names() {
        let rule = rapid_analyzer::rules::find("unused-data").expect("a rule");
        assert!(selects("W201", rule));
        assert!(selects("w2", rule));
        assert!(selects("W", rule));
        assert!(selects("UNUSED-DATA", rule));
        assert!(!selects("E", rule));
        assert!(!selects("unused", rule));
        assert!(!selects("W2011", rule));
    }

    #[test]
    fn bad_values_are_errors() {
        let err = check("[format]\n\nindent-width = 0\n").expect_err("invalid");
        assert_eq!(err, "rapid.toml:3: `indent-width` must be between 1 and 16");
        let err = check("[format]\nline-width = \"wide\"\n").expect_err("invalid");
        assert!(err.starts_with("rapid.toml:2: invalid type"), "{err}");
        let err = check("[format]\nline-width = 10\n").expect_err("invalid");
        assert_eq!(err, "rapid.toml:2: `line-width` must be at least 20");
        let err = check("[format]\n\nstyle = \"loose\"\n").expect_err("invalid");
        assert!(
            err.starts_with("rapid.toml:3: unknown variant `loose`, expected one of `as-written`, `tight`, `spaced`"),
            "{err}"
        );
    }
}
