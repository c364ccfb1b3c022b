//! Diagnostics and the rules that produce them.
//!
//! Every diagnostic belongs to a [`Rule`]: a stable code (`E001`, never
//! reused), a kebab-case name, a default severity and documentation in three
//! parts (what it checks, why it matters, an example). Rules are declared with
//! [`declare_rule!`], one per file under `rules/`, and listed once in
//! [`crate::rules::RULES`]; `docs/diagnostics.md` is generated from that list.

use std::ops::Range;

/// How bad a finding is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// A hint that something could be written better.
    Hint,
    /// Worth knowing, not a defect (e.g. an unconfigured signal).
    Info,
    /// Probably a mistake, but the controller accepts it.
    Warning,
    /// The controller would reject the module, or the code cannot work.
    Error,
}

impl Severity {
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Hint => "hint",
            Severity::Info => "info",
            Severity::Warning => "warning",
            Severity::Error => "error",
        }
    }

    /// Parses `error`, `warning`, `info` or `hint` (any case).
    pub fn parse(s: &str) -> Option<Severity> {
        [
            Severity::Error,
            Severity::Warning,
            Severity::Info,
            Severity::Hint,
        ]
        .into_iter()
        .find(|sev| sev.as_str().eq_ignore_ascii_case(s))
    }
}

/// What a rule is: its identity and its documentation.
#[derive(Debug)]
pub struct Rule {
    /// Stable code, such as `E001`. Codes are never reused.
    pub code: &'static str,
    /// Stable kebab-case name, such as `syntax-error`.
    pub name: &'static str,
    /// The severity unless configuration says otherwise.
    pub severity: Severity,
    /// Whether the rule is on unless configuration says otherwise. Rules
    /// off by default report style choices that real, working code often
    /// makes; a project selects them explicitly.
    pub default_on: bool,
    /// One line: what the rule reports.
    pub summary: &'static str,
    /// Markdown: what it checks, why it matters, an example.
    pub doc: &'static str,
}

impl PartialEq for Rule {
    fn eq(&self, other: &Rule) -> bool {
        self.code == other.code
    }
}

impl Eq for Rule {}

/// Declares a rule as a `static` [`Rule`] whose documentation is its doc
/// comment, so the code and the reference page cannot drift apart.
#[macro_export]
macro_rules! declare_rule {
    (
        $(#[doc = $doc:literal])+
        $vis:vis static $ident:ident = ($code:literal, $name:literal, $severity:ident);
    ) => {
        $crate::declare_rule! {
            $(#[doc = $doc])+
            $vis static $ident = ($code, $name, $severity, on);
        }
    };
    (
        $(#[doc = $doc:literal])+
        $vis:vis static $ident:ident = ($code:literal, $name:literal, $severity:ident, $default:ident);
    ) => {
        $(#[doc = $doc])+
        $vis static $ident: $crate::diagnostic::Rule = $crate::diagnostic::Rule {
            code: $code,
            name: $name,
            severity: $crate::diagnostic::Severity::$severity,
            default_on: $crate::declare_rule!(@on $default),
            summary: $crate::diagnostic::first_line(concat!($($doc, "\n"),+)),
            doc: concat!($($doc, "\n"),+),
        };
    };
    (@on on) => { true };
    (@on off) => { false };
}

/// The first non-empty line of a doc comment, trimmed (usable in consts).
pub const fn first_line(doc: &'static str) -> &'static str {
    let bytes = doc.as_bytes();
    let mut start = 0;
    while start < bytes.len() && (bytes[start] == b' ' || bytes[start] == b'\n') {
        start += 1;
    }
    let mut end = start;
    while end < bytes.len() && bytes[end] != b'\n' {
        end += 1;
    }
    match doc.split_at_checked(end) {
        Some((head, _)) => match head.split_at_checked(start) {
            Some((_, line)) => line,
            None => "",
        },
        None => "",
    }
}

/// Another place that explains a diagnostic (e.g. the declaration it clashes
/// with), in the same file or another.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Related {
    /// The file, as the caller named it to the analyzer; `None` for the same
    /// file as the diagnostic.
    pub file: Option<String>,
    pub range: Range<usize>,
    pub message: String,
}

/// A text edit that fixes a diagnostic.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Edit {
    pub range: Range<usize>,
    pub replacement: String,
}

/// Whether a fix may be applied without review.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Applicability {
    /// Keeps the program's meaning: `rapid check --fix` applies it.
    Safe,
    /// A likely repair whose details are the author's call (a guessed type
    /// or value, a deletion): offered in the editor only.
    Unsafe,
}

/// A fix: a title for menus and the edits, all in the diagnostic's file.
/// Every quick fix is one of these, built by its rule (`rules/<rule>.rs`)
/// and attached to the diagnostic it repairs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fix {
    pub title: String,
    /// The edits, against the text the diagnostic was found in. A fix whose
    /// edits depend on more than the statement reported (the top of its
    /// routine) is attached with none while the unit is checked, and its
    /// rule completes it once the unit's findings are known
    /// ([`crate::rules::complete_fixes`]); statement results stay cacheable.
    pub edits: Vec<Edit>,
    pub applicability: Applicability,
    /// The fix an editor applies by its "auto fix" key (LSP `isPreferred`):
    /// the obvious repair when there is one.
    pub preferred: bool,
}

impl Fix {
    /// Safe fixes keep the program's meaning and may be applied without
    /// review (`rapid check --fix`).
    pub fn is_safe(&self) -> bool {
        self.applicability == Applicability::Safe
    }

    /// A fix of one edit.
    pub fn edit(
        title: impl Into<String>,
        range: Range<usize>,
        replacement: impl Into<String>,
        applicability: Applicability,
        preferred: bool,
    ) -> Fix {
        Fix {
            title: title.into(),
            edits: vec![Edit {
                range,
                replacement: replacement.into(),
            }],
            applicability,
            preferred,
        }
    }

    /// The fix with each edit's range mapped by `map` (to another version
    /// of the text), or `None` when `map` has no place for one of them.
    pub fn shifted(&self, map: impl Fn(&Range<usize>) -> Option<Range<usize>>) -> Option<Fix> {
        let mut fix = self.clone();
        for e in &mut fix.edits {
            e.range = map(&e.range)?;
        }
        Some(fix)
    }
}

/// One finding in one file. Ranges are byte offsets into the decoded text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    pub rule: &'static Rule,
    pub severity: Severity,
    pub range: Range<usize>,
    pub message: String,
    pub related: Vec<Related>,
    pub fix: Option<Fix>,
}

impl Diagnostic {
    /// A diagnostic of `rule` at its default severity.
    pub fn new(rule: &'static Rule, range: Range<usize>, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            rule,
            severity: rule.severity,
            range,
            message: message.into(),
            related: Vec::new(),
            fix: None,
        }
    }

    pub fn with_related(mut self, related: Related) -> Diagnostic {
        self.related.push(related);
        self
    }

    pub fn with_fix(mut self, fix: Fix) -> Diagnostic {
        self.fix = Some(fix);
        self
    }
}
