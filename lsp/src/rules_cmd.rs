//! `rapid rules`: every rule `rapid check` and the language server apply,
//! or one with its documentation.

use std::io::Write as _;
use std::process::ExitCode;

use rapid_analyzer::diagnostic::Rule;
use rapid_analyzer::rules::{RULES, anchor, find};
use serde_json::{Value, json};

/// List the diagnostics' rules, or describe one.
#[derive(Debug, clap::Args)]
pub struct RulesArgs {
    /// A rule's code or name (any case); every rule when omitted.
    pub rule: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value = "human")]
    pub format: Format,
}

/// Output format of `rapid rules`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A table, or one rule's documentation, for reading.
    Human,
    /// JSON, for tools.
    Json,
}

pub fn run(args: RulesArgs) -> ExitCode {
    let text = match (&args.rule, args.format) {
        (None, Format::Human) => Ok(table()),
        (None, Format::Json) => Ok(pretty(&Value::Array(
            RULES.iter().map(|r| rule_json(r)).collect(),
        ))),
        (Some(name), format) => match find(name) {
            Some(rule) if format == Format::Json => Ok(pretty(&rule_json(rule))),
            Some(rule) => Ok(describe(rule)),
            None => Err(format!(
                "rapid: no rule has the code or name `{name}` (`rapid rules` lists them)"
            )),
        },
    };
    match text {
        Ok(text) => {
            let mut out = std::io::stdout().lock();
            match out.write_all(text.as_bytes()) {
                Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => ExitCode::from(2),
                _ => ExitCode::SUCCESS,
            }
        }
        Err(message) => {
            let _ = writeln!(std::io::stderr().lock(), "{message}");
            ExitCode::from(2)
        }
    }
}

/// One line per rule: code, name, default severity, summary.
pub fn table() -> String {
    let width = RULES.iter().map(|r| r.name.len()).max().unwrap_or(0);
    let mut out = String::new();
    for r in RULES {
        out.push_str(&format!(
            "{}  {:width$}  {:7}  {}\n",
            r.code,
            r.name,
            r.severity.as_str(),
            r.summary
        ));
    }
    out
}

/// A rule's documentation (the doc comment without its leading space).
pub fn doc(rule: &Rule) -> String {
    let mut out = String::new();
    for line in rule.doc.lines() {
        out.push_str(line.strip_prefix(' ').unwrap_or(line));
        out.push('\n');
    }
    out.trim_end().to_owned()
}

pub fn describe(rule: &Rule) -> String {
    format!(
        "{} {} (default severity: {})\n\n{}\n",
        rule.code,
        rule.name,
        rule.severity.as_str(),
        doc(rule)
    )
}

pub fn rule_json(rule: &Rule) -> Value {
    json!({
        "code": rule.code,
        "name": rule.name,
        "severity": rule.severity.as_str(),
        "summary": rule.summary,
        "doc": doc(rule),
        "anchor": anchor(rule),
    })
}

fn pretty(value: &Value) -> String {
    let mut s = serde_json::to_string_pretty(value).unwrap_or_default();
    s.push('\n');
    s
}
