//! The server's settings: `initializationOptions` and
//! `workspace/didChangeConfiguration`.
//!
//! ```json
//! {
//!   "rules": { "W101": "off", "unused-variable": "hint" },
//!   "extraPaths": ["/opt/robot/shared-modules"],
//!   "diagnosticsDelay": 80,
//!   "docsBaseUrl": "https://example.invalid/rapid/blob/main/docs/diagnostics.md"
//! }
//! ```
//!
//! The settings may come bare or wrapped in a `"rapid"` object (as editors
//! send their configuration sections). Unknown keys are ignored and bad
//! values are reported (as log messages) and skipped, so a typo never stops
//! the server.
//!
//! FIXME(issue 6): `rules` and `extraPaths` are the lint keys of
//! `rapid.toml`; when `crate::config` grows its `[lint]` section, map these
//! onto its types here (this is the only place that reads them).

use std::collections::HashMap;
use std::path::PathBuf;
use std::time::Duration;

use rapid_analyzer::diagnostic::Severity;
use rapid_analyzer::rules;
use serde_json::Value;

/// Where diagnostics' `codeDescription` links point by default: the
/// reference page in the repository (`repository` of the workspace's
/// `Cargo.toml`).
pub const DEFAULT_DOCS_URL: &str = "https://example.invalid/rapid/blob/main/docs/diagnostics.md";

/// Default pause after the last keystroke before diagnostics are published.
pub const DEFAULT_DELAY: Duration = Duration::from_millis(75);

#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Severity overrides by rule code; `None` turns the rule off.
    pub rules: HashMap<&'static str, Option<Severity>>,
    /// Further folders whose RAPID files are indexed.
    pub extra_paths: Vec<PathBuf>,
    /// Debounce of diagnostics while typing (0: publish at once).
    pub delay: Duration,
    /// The reference page that diagnostic codes link to.
    pub docs_url: String,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            rules: HashMap::new(),
            extra_paths: Vec::new(),
            delay: DEFAULT_DELAY,
            docs_url: DEFAULT_DOCS_URL.to_owned(),
        }
    }
}

impl Settings {
    /// Reads settings from a JSON value; returns them and the problems met.
    pub fn from_json(value: &Value) -> (Settings, Vec<String>) {
        let mut settings = Settings::default();
        let mut problems = Vec::new();
        let value = value.get("rapid").unwrap_or(value);
        let Some(obj) = value.as_object() else {
            if !value.is_null() {
                problems.push(format!("settings must be an object, not {value}"));
            }
            return (settings, problems);
        };
        if let Some(rules) = obj.get("rules") {
            match rules.as_object() {
                Some(map) => {
                    for (key, level) in map {
                        let Some(rule) = rules::find(key) else {
                            problems.push(format!("rules: unknown rule `{key}`"));
                            continue;
                        };
                        match level.as_str().map(parse_level) {
                            Some(Some(level)) => {
                                settings.rules.insert(rule.code, level);
                            }
                            _ => problems.push(format!(
                                "rules.{key}: expected \"error\", \"warning\", \"info\", \"hint\" or \"off\", found {level}"
                            )),
                        }
                    }
                }
                None => problems.push(format!("rules: expected an object, found {rules}")),
            }
        }
        if let Some(paths) = obj.get("extraPaths") {
            match paths.as_array() {
                Some(list) => {
                    for p in list {
                        match p.as_str() {
                            Some(s) => settings.extra_paths.push(PathBuf::from(s)),
                            None => problems.push(format!("extraPaths: not a path: {p}")),
                        }
                    }
                }
                None => problems.push(format!("extraPaths: expected a list, found {paths}")),
            }
        }
        if let Some(delay) = obj.get("diagnosticsDelay") {
            match delay.as_u64() {
                Some(ms) => settings.delay = Duration::from_millis(ms.min(10_000)),
                None => problems.push(format!(
                    "diagnosticsDelay: expected milliseconds, found {delay}"
                )),
            }
        }
        if let Some(url) = obj.get("docsBaseUrl") {
            match url.as_str() {
                Some(s) => s.clone_into(&mut settings.docs_url),
                None => problems.push(format!("docsBaseUrl: expected a URL, found {url}")),
            }
        }
        (settings, problems)
    }

    /// The severity of a rule's diagnostic after configuration (`None`: off).
    pub fn severity(&self, code: &str, default: Severity) -> Option<Severity> {
        match self.rules.get(code) {
            Some(level) => *level,
            None => Some(default),
        }
    }
}

fn parse_level(s: &str) -> Option<Option<Severity>> {
    if s.eq_ignore_ascii_case("off") || s.eq_ignore_ascii_case("none") {
        Some(None)
    } else {
        Severity::parse(s).map(Some)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn rules_by_code_or_name_and_levels() {
        let (s, problems) = Settings::from_json(&json!({
            "rapid": {
                "rules": {"W101": "off", "syntax-error": "warning", "nope": "error", "E001": 3},
                "extraPaths": ["/x", 1],
                "diagnosticsDelay": 0
            }
        }));
        assert_eq!(s.rules.get("W101"), Some(&None));
        assert_eq!(s.severity("E001", Severity::Error), Some(Severity::Warning));
        assert_eq!(s.severity("E002", Severity::Error), Some(Severity::Error));
        assert_eq!(s.extra_paths, vec![PathBuf::from("/x")]);
        assert_eq!(s.delay, Duration::ZERO);
        assert_eq!(problems.len(), 3, "{problems:?}");
    }

    #[test]
    fn null_and_junk_give_defaults() {
        assert_eq!(
            Settings::from_json(&Value::Null),
            (Settings::default(), vec![])
        );
        let (s, problems) = Settings::from_json(&json!("x"));
        assert_eq!(s, Settings::default());
        assert_eq!(problems.len(), 1);
    }
}
