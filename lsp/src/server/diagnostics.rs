//! Analyzer diagnostics to LSP diagnostics.

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::str::FromStr;

use rapid_analyzer::diagnostic::{Diagnostic, Severity};
use rapid_analyzer::rules;
use tower_lsp_server::ls_types::{
    CodeDescription, Diagnostic as LspDiagnostic, DiagnosticRelatedInformation, DiagnosticSeverity,
    DiagnosticTag, Location, NumberOrString, Uri,
};

use super::position::LineMap;
use super::settings::Settings;

/// Converts the diagnostics of one file (already filtered by the lint
/// settings). `related_location` turns a related
/// location in another file (its path and byte range) into an LSP location.
pub fn to_lsp(
    diagnostics: &[Diagnostic],
    map: &LineMap<'_>,
    uri: &Uri,
    settings: &Settings,
    related_location: &dyn Fn(&str, std::ops::Range<usize>) -> Option<Location>,
) -> Vec<LspDiagnostic> {
    diagnostics
        .iter()
        .map(|d| {
            let related: Vec<DiagnosticRelatedInformation> = d
                .related
                .iter()
                .filter_map(|r| {
                    let location = match &r.file {
                        None => Location::new(uri.clone(), map.range(r.range.clone())),
                        Some(path) => related_location(path, r.range.clone())?,
                    };
                    Some(DiagnosticRelatedInformation {
                        location,
                        message: r.message.clone(),
                    })
                })
                .collect();
            LspDiagnostic {
                range: map.range(d.range.clone()),
                severity: Some(lsp_severity(d.severity)),
                code: Some(NumberOrString::String(d.rule.code.to_owned())),
                code_description: settings
                    .docs_url
                    .as_deref()
                    .and_then(|base| docs_href(base, d.rule))
                    .map(|href| CodeDescription { href }),
                source: Some("rapid".to_owned()),
                message: d.message.clone(),
                related_information: (!related.is_empty()).then_some(related),
                tags: tags(d),
                data: None,
            }
        })
        .collect()
}

pub fn lsp_severity(severity: Severity) -> DiagnosticSeverity {
    match severity {
        Severity::Error => DiagnosticSeverity::ERROR,
        Severity::Warning => DiagnosticSeverity::WARNING,
        Severity::Info => DiagnosticSeverity::INFORMATION,
        Severity::Hint => DiagnosticSeverity::HINT,
    }
}

fn docs_href(base: &str, rule: &rapid_analyzer::diagnostic::Rule) -> Option<Uri> {
    let base = base.split('#').next().unwrap_or(base);
    Uri::from_str(&format!("{base}#{}", rules::anchor(rule))).ok()
}

/// `Unnecessary` for unused declarations, `Unnecessary` too for unreachable
/// code (the protocol has no separate tag; editors fade both out).
fn tags(d: &Diagnostic) -> Option<Vec<DiagnosticTag>> {
    let name = d.rule.name;
    (name.starts_with("unused-") || name == "unreachable-code")
        .then(|| vec![DiagnosticTag::UNNECESSARY])
}

/// A stable identifier of a list of diagnostics, for pull diagnostics'
/// `resultId`.
pub fn result_id(diagnostics: &[LspDiagnostic]) -> String {
    let mut h = DefaultHasher::new();
    serde_json::to_string(diagnostics)
        .unwrap_or_default()
        .hash(&mut h);
    format!("{:016x}", h.finish())
}
