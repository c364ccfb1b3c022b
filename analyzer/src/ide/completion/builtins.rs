//! The built-ins in completion lists: each catalogue view's names with
//! their signatures and origin notes (made once per view), and their
//! documentation when the client asks for it.

use std::collections::HashMap;

use super::CompletionKind;
use crate::catalogue::Catalogue;
use crate::names::fold;

/// A catalogue view's names (folded) and details (signatures and origin
/// notes), computed once per view.
pub(super) struct Builtins {
    pub(super) instructions: Vec<(String, String)>,
    pub(super) functions: Vec<(String, String)>,
    pub(super) datatypes: Vec<(String, String)>,
    pub(super) data: Vec<(String, String)>,
}

pub(super) fn builtins(cat: &'static Catalogue) -> std::sync::Arc<Builtins> {
    type Cache = std::sync::Mutex<HashMap<usize, std::sync::Arc<Builtins>>>;
    static CACHE: std::sync::OnceLock<Cache> = std::sync::OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    // Views are interned for the life of the process: the address is the key.
    let key = std::ptr::from_ref(cat) as usize;
    if let Ok(map) = cache.lock()
        && let Some(b) = map.get(&key)
    {
        return b.clone();
    }
    let built = std::sync::Arc::new(Builtins {
        instructions: cat
            .instructions
            .iter()
            .map(|r| (fold(&r.name), detail_of(cat, r.signature(), &r.origin)))
            .collect(),
        functions: cat
            .functions
            .iter()
            .map(|r| (fold(&r.name), detail_of(cat, r.signature(), &r.origin)))
            .collect(),
        datatypes: cat
            .datatypes
            .iter()
            .map(|t| (fold(&t.name), detail_of(cat, t.signature(), &t.origin)))
            .collect(),
        data: cat
            .data
            .iter()
            .map(|d| (fold(&d.name), detail_of(cat, d.signature(), &d.origin)))
            .collect(),
    });
    if let Ok(mut map) = cache.lock() {
        map.insert(key, built.clone());
    }
    built
}

/// A built-in's detail: its signature, then where it comes from when that
/// matters (a later RobotWare, an option, what this controller lacks).
fn detail_of(cat: &Catalogue, signature: String, origin: &crate::catalogue::Origin) -> String {
    let notes = crate::ide::hover::origin_notes(cat, origin);
    if notes.is_empty() {
        signature
    } else {
        format!("{signature}  ({})", notes.join("; "))
    }
}

/// Builds what every completion list shares (the built-ins with their
/// signatures) ahead of the first request, which would otherwise pay for
/// it. A server calls this while it indexes.
pub fn prepare_completions() {
    builtins(crate::catalogue::base());
    crate::ide::usage::prepare();
}

/// Documentation of a completion item, looked up when the client asks.
pub fn completion_documentation(label: &str, kind: CompletionKind) -> Option<String> {
    let cat = crate::catalogue::base();
    let doc = |summary: &str, doc: &str| {
        let mut s = summary.to_owned();
        if !doc.is_empty() {
            s.push_str("\n\n");
            s.push_str(doc);
        }
        s
    };
    match kind {
        CompletionKind::Procedure => cat.instruction(label).map(|r| {
            format!(
                "```rapid\n{}\n```\n\n{}",
                r.signature(),
                doc(&r.summary, &r.doc)
            )
        }),
        CompletionKind::Function => cat.function(label).map(|r| {
            format!(
                "```rapid\n{}\n```\n\n{}",
                r.signature(),
                doc(&r.summary, &r.doc)
            )
        }),
        CompletionKind::Type => cat.datatype(label).map(|t| {
            format!(
                "```rapid\n{}\n```\n\n{}",
                t.signature(),
                doc(&t.summary, &t.doc)
            )
        }),
        CompletionKind::Constant | CompletionKind::Variable | CompletionKind::Persistent => cat
            .datum(label)
            .map(|d| format!("```rapid\n{}\n```\n\n{}", d.signature(), d.summary)),
        _ => None,
    }
}
