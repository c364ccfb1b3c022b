//! The server's settings: `rapid.toml` (found from the first workspace
//! folder) with `initializationOptions` and `workspace/didChangeConfiguration`
//! over it.
//!
//! The client's settings use the keys of `rapid.toml` (see
//! [`crate::config`]), as JSON, bare or wrapped in a `"rapid"` object (as
//! editors send their configuration sections); a key the client gives
//! replaces the file's (objects are merged key by key). Besides them:
//!
//! ```json
//! {
//!   "lint": { "ignore": ["W2"], "severity": { "unused-data": "hint" } },
//!   "extra-paths": ["/opt/robot/shared-modules"],
//!   "rules": { "W101": "off", "unused-data": "hint" },
//!   "diagnosticsDelay": 80,
//!   "docsBaseUrl": "https://docs.example.com/rapid/diagnostics.html",
//!   "inlayHints": { "parameterNames": "literals" }
//! }
//! ```
//!
//! `rules` (rule code or name to `error`, `warning`, `info`, `hint` or
//! `off`) is a shorthand mapped onto `lint.severity` and `lint.ignore`;
//! `extraPaths` is accepted for `extra-paths`. `diagnosticsDelay` (ms, 0
//! for none), `docsBaseUrl` (where diagnostic codes link to, `#code-name`
//! appended; no link without it) and `inlayHints.parameterNames` (`none`,
//! `literals`, `all`: which arguments show their parameter's name) are the
//! server's own; `server` and `trace` (the VS Code extension's settings) are
//! ignored. Bad values are reported (as log messages) and skipped, so a typo
//! never stops the server.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use serde_json::{Map, Value};

use rapid_analyzer::ide::ParameterHints;

use crate::check::{LintSettings, Overrides};
use crate::config::Config;

/// Default pause after the last keystroke before diagnostics are published.
pub const DEFAULT_DELAY: Duration = Duration::from_millis(75);

#[derive(Clone, Debug)]
pub struct Settings {
    /// The effective configuration.
    pub config: Config,
    /// The folder relative paths and globs start from (`rapid.toml`'s, else
    /// the first workspace folder).
    pub root: PathBuf,
    /// Which rules apply, how severely, and which files are excluded.
    pub lint: Arc<LintSettings>,
    /// Debounce of diagnostics while typing (0: publish at once).
    pub delay: Duration,
    /// The reference page that diagnostic codes link to (`None`: no link;
    /// the rule's documentation is in the hover of the diagnostic, in
    /// `rapid rules CODE` and in docs/diagnostics.md).
    pub docs_url: Option<String>,
    /// Which positional arguments show their parameter's name.
    pub parameter_hints: ParameterHints,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings::resolve(&Value::Null, None, Path::new("/")).0
    }
}

impl Settings {
    /// The settings from the client's JSON over the configuration file
    /// (`(path, text)`), relative to `root`; and the problems met.
    pub fn resolve(
        client: &Value,
        file: Option<(&Path, &str)>,
        root: &Path,
    ) -> (Settings, Vec<String>) {
        let mut problems = Vec::new();
        let mut delay = DEFAULT_DELAY;
        let mut docs_url = None;
        let mut parameter_hints = ParameterHints::default();
        let mut root = root.to_owned();
        let mut merged = Value::Object(Map::new());
        if let Some((path, text)) = file {
            if let Some(dir) = path.parent() {
                dir.clone_into(&mut root);
            }
            match crate::config::parse(text, path) {
                Ok(_) => match toml::from_str::<toml::Value>(text) {
                    Ok(v) => merged = serde_json::to_value(v).unwrap_or(merged),
                    Err(e) => problems.push(format!("{}: {e}", path.display())),
                },
                Err(e) => problems.push(e.to_string()),
            }
        }
        let client = client.get("rapid").unwrap_or(client);
        match client {
            Value::Null => {}
            Value::Object(obj) => {
                let mut obj = obj.clone();
                if let Some(v) = obj.remove("diagnosticsDelay") {
                    match v.as_u64() {
                        Some(ms) => delay = Duration::from_millis(ms.min(10_000)),
                        None => problems.push(format!(
                            "diagnosticsDelay: expected milliseconds, found {v}"
                        )),
                    }
                }
                if let Some(v) = obj.remove("docsBaseUrl") {
                    match v.as_str() {
                        Some("") => docs_url = None,
                        Some(s) => docs_url = Some(s.to_owned()),
                        None => problems.push(format!("docsBaseUrl: expected a URL, found {v}")),
                    }
                }
                if let Some(v) = obj.remove("inlayHints") {
                    match v.get("parameterNames").map(|p| (p, p.as_str())) {
                        None => {}
                        Some((_, Some(name))) if ParameterHints::parse(name).is_some() => {
                            parameter_hints = ParameterHints::parse(name).unwrap_or_default();
                        }
                        Some((p, _)) => problems.push(format!(
                            "inlayHints.parameterNames: expected \"none\", \"literals\" or \"all\", found {p}"
                        )),
                    }
                }
                // The VS Code extension's own settings, sent with the rest.
                obj.remove("server");
                obj.remove("trace");
                obj.remove("debug");
                if let Some(v) = obj.remove("extraPaths") {
                    obj.insert("extra-paths".to_owned(), v);
                }
                if let Some(rules) = obj.remove("rules") {
                    map_rules(&rules, &mut obj, &mut problems);
                }
                merge(&mut merged, Value::Object(obj));
            }
            other => problems.push(format!("settings must be an object, not {other}")),
        }
        let config = match serde_json::from_value::<Config>(merged) {
            Ok(c) => c,
            Err(e) => {
                problems.push(format!("{e}"));
                Config::default()
            }
        };
        for (key, why) in config.lint.problems() {
            problems.push(format!("{key}: {why}"));
        }
        let lint = match LintSettings::new(&config, root.clone(), &Overrides::default()) {
            Ok(l) => l,
            Err(e) => {
                problems.push(e.to_string());
                LintSettings::new(&Config::default(), root.clone(), &Overrides::default())
                    .unwrap_or_else(|_| unreachable_default())
            }
        };
        (
            Settings {
                config,
                root,
                lint: Arc::new(lint),
                delay,
                docs_url,
                parameter_hints,
            },
            problems,
        )
    }

    /// Extra folders to index, absolute.
    pub fn extra_paths(&self) -> Vec<PathBuf> {
        self.config
            .extra_paths
            .iter()
            .map(|p| self.root.join(p))
            .collect()
    }
}

/// The default settings cannot fail: they have no glob and no selector.
fn unreachable_default() -> LintSettings {
    panic!("the default lint settings are valid")
}

/// `rules: {code-or-name: level}` onto `lint.severity` and `lint.ignore`.
fn map_rules(rules: &Value, obj: &mut Map<String, Value>, problems: &mut Vec<String>) {
    let Some(map) = rules.as_object() else {
        problems.push(format!("rules: expected an object, found {rules}"));
        return;
    };
    let lint = obj
        .entry("lint")
        .or_insert_with(|| Value::Object(Map::new()));
    let Some(lint) = lint.as_object_mut() else {
        problems.push("lint: expected an object".to_owned());
        return;
    };
    for (key, level) in map {
        if rapid_analyzer::rules::find(key).is_none() && !crate::config::is_known_selector(key) {
            problems.push(format!("rules: unknown rule `{key}`"));
            continue;
        }
        match level.as_str() {
            Some(l) if l.eq_ignore_ascii_case("off") => {
                let ignore = lint
                    .entry("ignore")
                    .or_insert_with(|| Value::Array(Vec::new()));
                if let Some(list) = ignore.as_array_mut() {
                    list.push(Value::String(key.clone()));
                }
            }
            Some(l) if rapid_analyzer::diagnostic::Severity::parse(l).is_some() => {
                let severity = lint
                    .entry("severity")
                    .or_insert_with(|| Value::Object(Map::new()));
                if let Some(m) = severity.as_object_mut() {
                    m.insert(key.clone(), Value::String(l.to_ascii_lowercase()));
                }
            }
            _ => problems.push(format!(
                "rules.{key}: expected \"error\", \"warning\", \"info\", \"hint\" or \"off\", found {level}"
            )),
        }
    }
}

/// Merges `over` into `base`: objects key by key, anything else replaced.
fn merge(base: &mut Value, over: Value) {
    match (base, over) {
        (Value::Object(b), Value::Object(o)) => {
            for (k, v) in o {
                match b.get_mut(&k) {
                    Some(existing) => merge(existing, v),
                    None => {
                        b.insert(k, v);
                    }
                }
            }
        }
        (b, o) => *b = o,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_analyzer::diagnostic::{Diagnostic, Severity};
    use rapid_analyzer::rules;
    use rapid_analyzer::text::LineIndex;
    use serde_json::json;

    /// The severity each rule code gets for a file, after the settings.
    fn severities(settings: &Settings, codes: &[&str]) -> Vec<Option<Severity>> {
        codes
            .iter()
            .map(|code| {
                let rule = rules::find(code).expect("rule");
                let d = Diagnostic::new(rule, 0..1, "x");
                let text = "x\n";
                settings
                    .lint
                    .apply(
                        &settings.root.join("A.mod"),
                        text,
                        &LineIndex::new(text),
                        vec![d],
                    )
                    .first()
                    .map(|d| d.severity)
            })
            .collect()
    }

    #[test]
    fn client_keys_go_over_the_file() {
        let file = "[lint]\nignore = [\"W201\"]\n[lint.severity]\nW101 = \"error\"\n";
        let (s, problems) = Settings::resolve(
            &json!({"rapid": {
                "lint": {"severity": {"W202": "hint"}},
                "rules": {"W101": "off", "syntax-error": "warning", "nope": "error", "E001": 3},
                "extraPaths": ["shared"],
                "diagnosticsDelay": 0
            }}),
            Some((Path::new("/p/rapid.toml"), file)),
            Path::new("/w"),
        );
        assert_eq!(problems.len(), 2, "{problems:?}");
        // The client's `lint.ignore` (from `rules`) replaces the file's list;
        // a syntax error stays an error whatever the settings say.
        assert_eq!(
            severities(&s, &["W201", "W101", "W202", "E001", "E002"]),
            [
                Some(Severity::Hint),
                None,
                Some(Severity::Hint),
                Some(Severity::Error),
                Some(Severity::Error)
            ]
        );
        assert_eq!(s.extra_paths(), vec![PathBuf::from("/p/shared")]);
        assert_eq!(s.delay, Duration::ZERO);
    }

    #[test]
    fn the_servers_own_keys_and_the_editors_keys_are_not_lint_settings() {
        let (s, problems) = Settings::resolve(
            &json!({"rapid": {
                "inlayHints": {"parameterNames": "all"},
                "docsBaseUrl": "https://docs.example.com/rules.html",
                "server": {"path": "/opt/rapid", "extraArgs": []},
                "trace": {"server": "off"},
                "debug": {"showPath": false}
            }}),
            None,
            Path::new("/w"),
        );
        assert!(problems.is_empty(), "{problems:?}");
        assert_eq!(s.parameter_hints, ParameterHints::All);
        assert_eq!(
            s.docs_url.as_deref(),
            Some("https://docs.example.com/rules.html")
        );
        let (s, problems) = Settings::resolve(
            &json!({"inlayHints": {"parameterNames": "some"}}),
            None,
            Path::new("/w"),
        );
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert_eq!(s.parameter_hints, ParameterHints::Literals);
        assert_eq!(s.docs_url, None, "no link by default");
    }

    #[test]
    fn bad_settings_are_reported_and_skipped() {
        let (s, problems) = Settings::resolve(&json!("x"), None, Path::new("/w"));
        assert_eq!(problems.len(), 1);
        assert_eq!(s.delay, DEFAULT_DELAY);
        let (_, problems) =
            Settings::resolve(&json!({"lint": {"bogus": 1}}), None, Path::new("/w"));
        assert_eq!(problems.len(), 1, "{problems:?}");
        let (_, problems) = Settings::resolve(
            &Value::Null,
            Some((Path::new("/p/rapid.toml"), "[lint\n")),
            Path::new("/w"),
        );
        assert_eq!(problems.len(), 1, "{problems:?}");
    }
}
