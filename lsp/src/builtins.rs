//! `rapid builtins`: prints the built-in catalogue (functions, instructions, data types,
//! predefined data), as a whole or one entry, for people (`human`) or tools (`json`).

use std::io::Write as _;
use std::process::ExitCode;

use rapid_analyzer::catalogue::{Catalogue, DataType, Datum, Origin, Routine, Selection, Version};

/// Show the built-in routines, data types and predefined data of RAPID.
#[derive(Debug, clap::Args)]
pub struct BuiltinsArgs {
    /// A routine, data type or predefined datum to describe (case-insensitive);
    /// the whole catalogue when omitted.
    pub name: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value = "human")]
    pub format: Format,
    /// Show the catalogue of one RobotWare version (e.g. 6.15): entries it
    /// lacks are left out and signatures are that version's.
    #[arg(long, value_name = "VERSION")]
    pub robotware: Option<String>,
    /// With --robotware: also list the entries of these option packages
    /// (comma-separated ids, e.g. arc,egm); without it, every package.
    #[arg(long, value_name = "IDS", value_delimiter = ',')]
    pub options: Option<Vec<String>>,
}

/// Output format of `rapid builtins`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Signatures and documentation, for reading.
    Human,
    /// One JSON object, for tools.
    Json,
}

/// The catalogue `args` ask for: the whole one, or one version's with its
/// options (entries it lacks are left out).
fn catalogue_for(args: &BuiltinsArgs) -> Result<Catalogue, String> {
    catalogue_of(args.robotware.as_deref(), args.options.as_deref())
        .map_err(|e| format!("rapid builtins: {e}"))
}

/// The whole catalogue, or the catalogue of the RobotWare version `robotware`
/// with the option packages `options` (every one when `None`).
pub fn catalogue_of(
    robotware: Option<&str>,
    options: Option<&[String]>,
) -> Result<Catalogue, String> {
    let base = rapid_analyzer::catalogue::base();
    let Some(text) = robotware else {
        if options.is_some() {
            return Err("--options needs --robotware".into());
        }
        return Ok(base.select(&Selection::default()));
    };
    let version = Version::parse(text).map_err(|e| e.to_string())?;
    let options = match options {
        Some(o) => o.to_vec(),
        None => base.packages.iter().map(|p| p.id.clone()).collect(),
    };
    for o in &options {
        if base.package(o).is_none() {
            return Err(format!("no option package `{o}`"));
        }
    }
    Ok(base.only_available(&Selection::new(Some(version), options)))
}

/// Runs `rapid builtins`.
pub fn run(args: BuiltinsArgs) -> ExitCode {
    let cat = match catalogue_for(&args) {
        Ok(c) => c,
        Err(message) => {
            let _ = writeln!(std::io::stderr().lock(), "{message}");
            return ExitCode::FAILURE;
        }
    };
    let cat = &cat;
    let result = match &args.name {
        None => match args.format {
            Format::Human => Ok(list_human(cat)),
            Format::Json => whole_json(cat),
        },
        Some(name) => match args.format {
            Format::Human => describe(cat, name),
            Format::Json => entry_json(cat, name),
        },
    };
    match result {
        Ok(text) => {
            let mut out = std::io::stdout().lock();
            if out.write_all(text.as_bytes()).is_err() {
                return ExitCode::FAILURE;
            }
            ExitCode::SUCCESS
        }
        Err(message) => {
            let _ = writeln!(std::io::stderr().lock(), "{message}");
            ExitCode::FAILURE
        }
    }
}

/// One entry found by name.
pub enum Entry<'a> {
    Routine(&'a Routine),
    DataType(&'a DataType),
    Datum(&'a Datum),
}

pub fn find<'a>(cat: &'a Catalogue, name: &str) -> Result<Entry<'a>, String> {
    if let Some(r) = cat.routine(name) {
        return Ok(Entry::Routine(r));
    }
    if let Some(t) = cat.datatype(name) {
        return Ok(Entry::DataType(t));
    }
    if let Some(d) = cat.datum(name) {
        return Ok(Entry::Datum(d));
    }
    let mut message =
        format!("rapid builtins: no built-in routine, data type or datum named `{name}`");
    let near = suggestions(cat, name);
    if !near.is_empty() {
        message.push_str("\n  did you mean: ");
        message.push_str(&near.join(", "));
    }
    Err(message)
}

/// Describes one entry for a person: its signature, then its documentation.
pub fn describe(cat: &Catalogue, name: &str) -> Result<String, String> {
    let mut out = String::new();
    match find(cat, name)? {
        Entry::Routine(r) => {
            let kind = if r.is_function() {
                "function"
            } else {
                "instruction"
            };
            out.push_str(&r.signature());
            out.push_str("\n\n");
            out.push_str(&r.summary);
            out.push('\n');
            push_para(&mut out, &r.doc);
            let mut facts = vec![kind.to_string()];
            if r.pure {
                facts.push("pure".into());
            }
            for g in r.alt_groups.iter().filter(|g| g.required) {
                let members: Vec<String> = r
                    .params
                    .iter()
                    .filter(|p| p.alt_group == Some(g.id))
                    .map(|p| format!("\\{}", p.name))
                    .collect();
                facts.push(format!("one of {} is required", members.join(", ")));
            }
            if !r.signature_known && r.params.is_empty() {
                facts.push("arguments not documented publicly, not checked".into());
            } else if !r.signature_known {
                facts.push("parameters as loaded code calls it, calls not checked".into());
            }
            push_facts(cat, &mut out, &facts, &r.origin);
        }
        Entry::DataType(t) => {
            out.push_str(&t.signature());
            out.push_str("\n\n");
            out.push_str(&t.summary);
            out.push('\n');
            push_para(&mut out, &t.doc);
            let mut facts = vec!["data type".to_string()];
            if let Some(vc) = t.value_class {
                facts.push(
                    match vc {
                        rapid_analyzer::catalogue::ValueClass::Value => "value type",
                        rapid_analyzer::catalogue::ValueClass::SemiValue => "semi-value type",
                        rapid_analyzer::catalogue::ValueClass::NonValue => "non-value type",
                    }
                    .into(),
                );
            }
            push_facts(cat, &mut out, &facts, &t.origin);
        }
        Entry::Datum(d) => {
            out.push_str(&d.signature());
            out.push_str("\n\n");
            out.push_str(&d.summary);
            out.push('\n');
            push_facts(cat, &mut out, &["predefined data".into()], &d.origin);
        }
    }
    Ok(out)
}

fn push_para(out: &mut String, text: &str) {
    if !text.is_empty() {
        out.push('\n');
        out.push_str(text);
        out.push('\n');
    }
}

fn push_facts(cat: &Catalogue, out: &mut String, facts: &[String], origin: &Origin) {
    out.push('\n');
    out.push_str(&facts.join("; "));
    out.push('\n');
    out.push_str(&format!("RobotWare {}", origin.versions()));
    match origin.package.as_deref() {
        Some(id) => {
            let name = cat.package(id).map_or(id, |p| p.name.as_str());
            out.push_str(&format!("; option {name} (`{id}`)"));
        }
        None => out.push_str("; base language"),
    }
    out.push('\n');
    out.push_str("From ");
    out.push_str(origin.source.describe());
    if let Some(section) = &origin.section {
        out.push_str(&format!(", section {section}"));
    }
    out.push('\n');
    if let Some(note) = &origin.note {
        out.push_str("Note: ");
        out.push_str(note);
        out.push('\n');
    }
}

/// The whole catalogue for a person: one line per entry.
pub fn list_human(cat: &Catalogue) -> String {
    let mut out = String::new();
    out.push_str(&format!("Functions ({})\n", cat.functions.len()));
    for r in &cat.functions {
        out.push_str(&format!("  {}\n", r.signature()));
    }
    out.push_str(&format!("\nInstructions ({})\n", cat.instructions.len()));
    for r in &cat.instructions {
        out.push_str(&format!("  {}\n", r.signature()));
    }
    out.push_str(&format!("\nData types ({})\n", cat.datatypes.len()));
    for t in &cat.datatypes {
        out.push_str(&format!("  {}\n", t.signature()));
    }
    out.push_str(&format!("\nPredefined data ({})\n", cat.data.len()));
    for d in &cat.data {
        out.push_str(&format!("  {}\n", d.signature()));
    }
    out
}

fn whole_json(cat: &Catalogue) -> Result<String, String> {
    serde_json::to_string_pretty(cat)
        .map(|s| s + "\n")
        .map_err(|e| format!("rapid builtins: cannot write JSON: {e}"))
}

fn entry_json(cat: &Catalogue, name: &str) -> Result<String, String> {
    let value = match find(cat, name)? {
        Entry::Routine(r) => serde_json::to_string_pretty(r),
        Entry::DataType(t) => serde_json::to_string_pretty(t),
        Entry::Datum(d) => serde_json::to_string_pretty(d),
    };
    value
        .map(|s| s + "\n")
        .map_err(|e| format!("rapid builtins: cannot write JSON: {e}"))
}

/// Names close to `name` (edit distance, or a shared prefix), best first, at most five.
fn suggestions(cat: &Catalogue, name: &str) -> Vec<String> {
    let wanted = name.to_lowercase();
    let limit = (wanted.chars().count() / 3).max(2);
    let names = cat
        .functions
        .iter()
        .chain(&cat.instructions)
        .map(|r| &r.name)
        .chain(cat.datatypes.iter().map(|t| &t.name))
        .chain(cat.data.iter().map(|d| &d.name));
    let mut scored: Vec<(usize, &String)> = names
        .filter_map(|n| {
            let lower = n.to_lowercase();
            let d = edit_distance(&wanted, &lower);
            if d <= limit {
                Some((d, n))
            } else if wanted.len() >= 3 && lower.starts_with(&wanted) {
                Some((limit + 1, n))
            } else {
                None
            }
        })
        .collect();
    scored.sort_by(|a, b| a.0.cmp(&b.0).then_with(|| a.1.cmp(b.1)));
    scored.into_iter().take(5).map(|(_, n)| n.clone()).collect()
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != *cb);
            cur[j + 1] = (prev[j] + cost).min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn base_view() -> Catalogue {
        rapid_analyzer::catalogue::base().select(&Selection::default())
    }

    #[test]
    fn describe_function() {
        insta::assert_snapshot!(describe(&base_view(), "round").unwrap_or_else(|e| e));
    }

    #[test]
    fn describe_instruction_with_alternatives() {
        insta::assert_snapshot!(describe(&base_view(), "MoveL").unwrap_or_else(|e| e));
    }

    #[test]
    fn describe_required_alternatives_and_note() {
        insta::assert_snapshot!(describe(&base_view(), "EulerZYX").unwrap_or_else(|e| e));
    }

    #[test]
    fn describe_type_and_datum() {
        let text = [
            describe(&base_view(), "robtarget"),
            describe(&base_view(), "v100"),
        ]
        .into_iter()
        .map(|r| r.unwrap_or_else(|e| e))
        .collect::<Vec<_>>()
        .join("\n----\n");
        insta::assert_snapshot!(text);
    }

    #[test]
    fn unknown_name_suggests_close_matches() {
        let err = describe(&base_view(), "MoveLL").err().unwrap_or_default();
        insta::assert_snapshot!(err);
    }

    #[test]
    fn json_has_the_documented_shape() {
        let text = whole_json(&base_view()).unwrap_or_default();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap_or_default();
        for key in ["functions", "instructions", "datatypes", "data"] {
            assert!(v[key].is_array(), "{key}");
        }
        let round = v["functions"]
            .as_array()
            .and_then(|a| a.iter().find(|f| f["name"] == "Round"))
            .cloned()
            .unwrap_or_default();
        insta::assert_json_snapshot!(round);
        let movel = v["instructions"]
            .as_array()
            .and_then(|a| a.iter().find(|f| f["name"] == "MoveL"))
            .cloned()
            .unwrap_or_default();
        assert!(movel.get("returns").is_none());
        assert_eq!(movel["params"][0]["mode"], serde_json::Value::Null);
        assert_eq!(movel["params"][0]["switch"], true);
        let datum = v["data"]
            .as_array()
            .and_then(|a| a.iter().find(|d| d["name"] == "v100"))
            .cloned()
            .unwrap_or_default();
        assert_eq!(datum["kind"], "CONST");
        assert_eq!(datum["type"], "speeddata");
        assert_eq!(datum["value"], "[100,500,5000,1000]");
    }
}
