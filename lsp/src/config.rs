//! `rapid.toml`, the project's configuration file.
//!
//! Found by walking up from the first path given on the command line (or
//! named with `--config FILE`). Every section and key is optional; an
//! unknown key is an error naming the file, the line and the key, so a typo
//! never silently does nothing.
//!
//! ```toml
//! [format]
//! indent-width = 4   # spaces per indentation level
//! line-width = 120   # procedure-call arguments are wrapped past this width
//! ```

use std::path::{Path, PathBuf};

use rapid_analyzer::format::FormatOptions;
use serde::Deserialize;

/// The name of the configuration file.
pub const FILE_NAME: &str = "rapid.toml";

/// The whole configuration: one field per section.
#[derive(Clone, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "kebab-case")]
pub struct Config {
    /// `[format]`: the layout `rapid fmt` produces.
    pub format: FormatConfig,
}

/// `[format]`.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(default, deny_unknown_fields, rename_all = "kebab-case")]
pub struct FormatConfig {
    /// Spaces per indentation level (1 to 16; default 4).
    pub indent_width: usize,
    /// The width past which procedure-call arguments are wrapped (at least
    /// 20; default 120).
    pub line_width: usize,
}

impl Default for FormatConfig {
    fn default() -> FormatConfig {
        let options = FormatOptions::default();
        FormatConfig {
            indent_width: options.indent_width,
            line_width: options.line_width,
        }
    }
}

impl FormatConfig {
    pub fn options(&self) -> FormatOptions {
        FormatOptions {
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

/// Reads and checks a configuration file.
pub fn load(path: &Path) -> Result<Config, ConfigError> {
    let text = std::fs::read_to_string(path).map_err(|e| ConfigError {
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
    if !(1..=16).contains(&config.format.indent_width) {
        return Err(invalid("indent-width", "must be between 1 and 16"));
    }
    if config.format.line_width < 20 {
        return Err(invalid("line-width", "must be at least 20"));
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

/// The nearest `rapid.toml` in `start`'s folder (or `start` itself if it is
/// a folder) and its parents.
pub fn find(start: &Path) -> Option<PathBuf> {
    let start = std::path::absolute(start).ok()?;
    let mut dir = if start.is_dir() {
        Some(start.as_path())
    } else {
        start.parent()
    };
    while let Some(d) = dir {
        let candidate = d.join(FILE_NAME);
        if candidate.is_file() {
            return Some(candidate);
        }
        dir = d.parent();
    }
    None
}

/// The configuration for a run: the file named explicitly, else the one
/// found from `first_path`, else the defaults.
pub fn resolve(explicit: Option<&Path>, first_path: &Path) -> Result<Config, ConfigError> {
    match explicit.map(Path::to_owned).or_else(|| find(first_path)) {
        Some(path) => load(&path),
        None => Ok(Config::default()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(text: &str) -> Result<Config, String> {
        parse(text, Path::new("rapid.toml")).map_err(|e| e.to_string())
    }

    #[test]
    fn an_empty_file_is_the_defaults() {
        assert_eq!(check(""), Ok(Config::default()));
        assert_eq!(check("[format]\n"), Ok(Config::default()));
    }

    #[test]
    fn format_settings_are_read() {
        let config = check("[format]\nindent-width = 2\nline-width = 80\n").expect("valid");
        assert_eq!(
            config.format.options(),
            FormatOptions {
                indent_width: 2,
                line_width: 80
            }
        );
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
    fn bad_values_are_errors() {
        let err = check("[format]\n\nindent-width = 0\n").expect_err("invalid");
        assert_eq!(err, "rapid.toml:3: `indent-width` must be between 1 and 16");
        let err = check("[format]\nline-width = \"wide\"\n").expect_err("invalid");
        assert!(err.starts_with("rapid.toml:2: invalid type"), "{err}");
    }
}
