//! The editor features: `ide` results (plain data, byte ranges) converted
//! to protocol types. Every function runs on a [`Snapshot`], off the main
//! loop, and is plain synchronous code.

use std::collections::HashMap;
use std::ops::Range;

use rapid_analyzer::diagnostic::Edit;
use rapid_analyzer::format::FormatOptions;
use rapid_analyzer::ide;
use rapid_analyzer::text::LineIndex;
use serde_json::json;
use tower_lsp_server::ls_types::{
    self as lsp, CodeActionKind, CodeActionOrCommand, CompletionItemKind, DocumentHighlight,
    DocumentHighlightKind, DocumentSymbol, Documentation, FoldingRangeKind, Hover, HoverContents,
    InlayHintKind, InlayHintLabel, InsertTextFormat, MarkupContent, MarkupKind, OneOf,
    ParameterInformation, ParameterLabel, Position, SelectionRange, SemanticToken,
    SignatureInformation, TextEdit, Uri, WorkspaceEdit, WorkspaceSymbol,
};

use super::diagnostics;
use super::position::{LineMap, PosEncoding};
use super::state::Snapshot;

pub fn hover(snap: &Snapshot, pos: Position) -> Option<Hover> {
    let offset = snap.map().offset(pos);
    let h = ide::hover(&snap.task, snap.unit_idx, offset)?;
    Some(Hover {
        contents: HoverContents::Markup(markdown(h.markdown)),
        range: Some(snap.map().range(h.range)),
    })
}

fn markdown(value: String) -> MarkupContent {
    MarkupContent {
        kind: MarkupKind::Markdown,
        value,
    }
}

/// The most items a completion list carries. A statement start in a large
/// module offers thousands (every built-in, every datum of the task); the
/// editor shows a dozen, and what the user types next narrows the list.
/// Longer lists are cut to their best items and marked incomplete, so the
/// editor asks again as the user types, and the server filters by what is
/// typed.
pub const MOST_COMPLETIONS: usize = 400;

/// The completion list at `pos` (asked for by typing `trigger`, if one
/// was typed); with `lazy_detail`, without the items' details (signatures
/// and declarations, most of the list's size), which
/// [`resolve_completion`] adds to the item the user looks at.
pub fn completion(
    snap: &Snapshot,
    pos: Position,
    lazy_detail: bool,
    trigger: Option<char>,
) -> lsp::CompletionList {
    let offset = snap.map().offset(pos);
    let mut found = ide::completions_for(&snap.task, snap.unit_idx, offset, !lazy_detail, trigger);
    let complete = cut_list(&mut found, typed_before(&snap.unit.text, offset));
    let items = found
        .into_iter()
        .map(|c| lsp::CompletionItem {
            kind: Some(completion_kind(c.kind)),
            detail: c.detail.filter(|_| !lazy_detail),
            insert_text_format: c.is_snippet.then_some(InsertTextFormat::SNIPPET),
            // The client sends the item back on resolve: its label is there
            // already, the analyzer's kind goes in `data`.
            data: Some(json!(kind_name(c.kind))),
            insert_text: c.insert_text,
            sort_text: c.sort_text,
            label: c.label,
            ..lsp::CompletionItem::default()
        })
        .collect();
    lsp::CompletionList {
        is_incomplete: !complete,
        items,
    }
}

/// The name being typed before `offset` (possibly empty).
fn typed_before(text: &str, offset: usize) -> &str {
    let before = text.get(..offset).unwrap_or_default();
    let start = before
        .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |i| i + 1);
    &before[start..]
}

/// Cuts a list longer than [`MOST_COMPLETIONS`]: the items whose label holds
/// the letters typed, in order (the editor's own filter keeps fewer), then
/// the best by sort order. Returns whether the list is whole.
fn cut_list(items: &mut Vec<ide::CompletionItem>, typed: &str) -> bool {
    if items.len() <= MOST_COMPLETIONS {
        return true;
    }
    if !typed.is_empty() {
        let typed: Vec<char> = typed.chars().map(|c| c.to_ascii_lowercase()).collect();
        items.retain(|i| {
            let mut want = typed.iter().peekable();
            for c in i.label.chars() {
                if want.peek() == Some(&&c.to_ascii_lowercase()) {
                    want.next();
                }
            }
            want.peek().is_none()
        });
    }
    if items.len() > MOST_COMPLETIONS {
        // The best ones, in no particular order (the editor sorts them).
        items.select_nth_unstable_by(MOST_COMPLETIONS - 1, |a, b| {
            a.sort_text.cmp(&b.sort_text).then(a.label.cmp(&b.label))
        });
        items.truncate(MOST_COMPLETIONS);
    }
    false
}

/// `completionItem/resolve`: documentation, looked up only for the item the
/// user looks at, and the detail of an item sent without it: found in the
/// list asked for at `origin` (the last completion's snapshot and position).
pub fn resolve_completion(
    mut item: lsp::CompletionItem,
    origin: Option<(&Snapshot, Position)>,
) -> lsp::CompletionItem {
    let Some(kind) = item
        .data
        .as_ref()
        .and_then(|d| d.as_str())
        .and_then(kind_from_name)
    else {
        return item;
    };
    if let Some(doc) = ide::completion_documentation(&item.label, kind) {
        item.documentation = Some(Documentation::MarkupContent(markdown(doc)));
    }
    if item.detail.is_none()
        && let Some((snap, pos)) = origin
    {
        item.detail = ide::completions(&snap.task, snap.unit_idx, snap.map().offset(pos))
            .into_iter()
            .find(|c| c.kind == kind && c.label == item.label)
            .and_then(|c| c.detail);
    }
    item
}

const KINDS: &[(ide::CompletionKind, &str, CompletionItemKind)] = &[
    (
        ide::CompletionKind::Keyword,
        "keyword",
        CompletionItemKind::KEYWORD,
    ),
    (
        ide::CompletionKind::Snippet,
        "snippet",
        CompletionItemKind::SNIPPET,
    ),
    (
        ide::CompletionKind::Procedure,
        "procedure",
        CompletionItemKind::METHOD,
    ),
    (
        ide::CompletionKind::Function,
        "function",
        CompletionItemKind::FUNCTION,
    ),
    (ide::CompletionKind::Trap, "trap", CompletionItemKind::EVENT),
    (
        ide::CompletionKind::Variable,
        "variable",
        CompletionItemKind::VARIABLE,
    ),
    (
        ide::CompletionKind::Persistent,
        "persistent",
        CompletionItemKind::VARIABLE,
    ),
    (
        ide::CompletionKind::Constant,
        "constant",
        CompletionItemKind::CONSTANT,
    ),
    (
        ide::CompletionKind::Parameter,
        "parameter",
        CompletionItemKind::VARIABLE,
    ),
    (
        ide::CompletionKind::Type,
        "type",
        CompletionItemKind::STRUCT,
    ),
    (
        ide::CompletionKind::Component,
        "component",
        CompletionItemKind::FIELD,
    ),
    (
        ide::CompletionKind::OptionalArgument,
        "optional-argument",
        CompletionItemKind::PROPERTY,
    ),
    (
        ide::CompletionKind::Module,
        "module",
        CompletionItemKind::MODULE,
    ),
    (
        ide::CompletionKind::Label,
        "label",
        CompletionItemKind::REFERENCE,
    ),
];

fn completion_kind(kind: ide::CompletionKind) -> CompletionItemKind {
    KINDS
        .iter()
        .find(|k| k.0 == kind)
        .map_or(CompletionItemKind::TEXT, |k| k.2)
}

fn kind_name(kind: ide::CompletionKind) -> &'static str {
    KINDS.iter().find(|k| k.0 == kind).map_or("", |k| k.1)
}

fn kind_from_name(name: &str) -> Option<ide::CompletionKind> {
    KINDS.iter().find(|k| k.1 == name).map(|k| k.0)
}

pub fn signature_help(snap: &Snapshot, pos: Position) -> Option<lsp::SignatureHelp> {
    let offset = snap.map().offset(pos);
    let s = ide::signature_help(&snap.task, snap.unit_idx, offset)?;
    let parameters = s
        .parameters
        .iter()
        .map(|(range, doc)| ParameterInformation {
            label: label_offsets(&s.label, range.clone(), snap.encoding),
            documentation: doc
                .clone()
                .map(|d| Documentation::MarkupContent(markdown(d))),
        })
        .collect();
    let active = s.active_parameter.and_then(|a| u32::try_from(a).ok());
    Some(lsp::SignatureHelp {
        signatures: vec![SignatureInformation {
            documentation: s
                .documentation
                .clone()
                .map(|d| Documentation::MarkupContent(markdown(d))),
            parameters: Some(parameters),
            active_parameter: active,
            label: s.label,
        }],
        active_signature: Some(0),
        active_parameter: active,
    })
}

/// A parameter's place in a signature label, in the negotiated units.
fn label_offsets(label: &str, range: Range<usize>, encoding: PosEncoding) -> ParameterLabel {
    let count = |end: usize| -> u32 {
        let mut end = end.min(label.len());
        while !label.is_char_boundary(end) {
            end -= 1;
        }
        let n = match encoding {
            PosEncoding::Utf8 => end,
            PosEncoding::Utf16 => label[..end].encode_utf16().count(),
        };
        u32::try_from(n).unwrap_or(u32::MAX)
    };
    ParameterLabel::LabelOffsets([count(range.start), count(range.end)])
}

pub fn locations(snap: &Snapshot, found: Vec<ide::Location>) -> Vec<lsp::Location> {
    found
        .into_iter()
        .filter_map(|l| snap.location(&l.path, l.range))
        .collect()
}

pub fn document_highlights(snap: &Snapshot, pos: Position) -> Vec<DocumentHighlight> {
    let map = snap.map();
    ide::document_highlights(&snap.task, snap.unit_idx, map.offset(pos))
        .into_iter()
        .map(|(range, write)| DocumentHighlight {
            range: map.range(range),
            kind: Some(if write {
                DocumentHighlightKind::WRITE
            } else {
                DocumentHighlightKind::READ
            }),
        })
        .collect()
}

/// Edits of several files as a workspace edit.
pub fn workspace_edit(snap: &Snapshot, files: Vec<(String, Vec<Edit>)>) -> WorkspaceEdit {
    let mut changes: HashMap<Uri, Vec<TextEdit>> = HashMap::new();
    for (path, edits) in files {
        let Some(uri) = snap.uri_of(&path) else {
            continue;
        };
        let converted = if path == snap.path {
            text_edits(&snap.map(), &edits)
        } else {
            let Some(unit) = snap.unit_of(&path) else {
                continue;
            };
            let index = snap.line_index(&path, unit);
            text_edits(&LineMap::new(&unit.text, &index, snap.encoding), &edits)
        };
        changes.entry(uri).or_default().extend(converted);
    }
    WorkspaceEdit {
        changes: Some(changes),
        ..WorkspaceEdit::default()
    }
}

pub fn text_edits(map: &LineMap<'_>, edits: &[Edit]) -> Vec<TextEdit> {
    edits
        .iter()
        .map(|e| TextEdit::new(map.range(e.range.clone()), e.replacement.clone()))
        .collect()
}

pub fn document_symbols(snap: &Snapshot) -> Vec<DocumentSymbol> {
    let map = snap.map();
    ide::document_symbols(&snap.unit)
        .into_iter()
        .map(|s| document_symbol(&map, s))
        .collect()
}

#[allow(deprecated, reason = "DocumentSymbol::deprecated must still be given")]
fn document_symbol(map: &LineMap<'_>, s: ide::Symbol) -> DocumentSymbol {
    let range = map.range(s.range);
    let mut selection_range = map.range(s.selection_range);
    // The protocol requires the selection inside the range.
    if selection_range.start < range.start || selection_range.end > range.end {
        selection_range = range;
    }
    DocumentSymbol {
        name: if s.name.is_empty() {
            "?".to_owned()
        } else {
            s.name
        },
        detail: s.detail,
        kind: symbol_kind(s.kind),
        tags: None,
        deprecated: None,
        range,
        selection_range,
        children: (!s.children.is_empty()).then(|| {
            s.children
                .into_iter()
                .map(|c| document_symbol(map, c))
                .collect()
        }),
    }
}

fn symbol_kind(kind: ide::SymbolKind) -> lsp::SymbolKind {
    match kind {
        ide::SymbolKind::Module => lsp::SymbolKind::MODULE,
        ide::SymbolKind::Procedure => lsp::SymbolKind::METHOD,
        ide::SymbolKind::Function => lsp::SymbolKind::FUNCTION,
        ide::SymbolKind::Trap => lsp::SymbolKind::EVENT,
        ide::SymbolKind::Variable => lsp::SymbolKind::VARIABLE,
        ide::SymbolKind::Persistent => lsp::SymbolKind::VARIABLE,
        ide::SymbolKind::Constant => lsp::SymbolKind::CONSTANT,
        ide::SymbolKind::Record => lsp::SymbolKind::STRUCT,
        ide::SymbolKind::Alias => lsp::SymbolKind::TYPE_PARAMETER,
        ide::SymbolKind::Component => lsp::SymbolKind::FIELD,
    }
}

/// Workspace symbols, converted with the text of the unit each lives in.
pub fn workspace_symbols(
    tasks: &[std::sync::Arc<rapid_analyzer::task::Task>],
    query: &str,
    encoding: PosEncoding,
    uris: &HashMap<String, Uri>,
) -> Vec<WorkspaceSymbol> {
    let found = ide::workspace_symbols(tasks, query);
    let mut indexes: HashMap<String, LineIndex> = HashMap::new();
    let units: HashMap<&str, &rapid_analyzer::task::Unit> = tasks
        .iter()
        .flat_map(|t| t.units.iter().map(|u| (u.path.as_str(), &**u)))
        .collect();
    found
        .into_iter()
        .take(1000)
        .filter_map(|(path, s)| {
            let unit = units.get(path.as_str())?;
            let uri = super::state::uri_of(uris, &path)?;
            let index = indexes
                .entry(path.clone())
                .or_insert_with(|| LineIndex::new(&unit.text));
            let map = LineMap::new(&unit.text, index, encoding);
            Some(WorkspaceSymbol {
                name: s.name,
                kind: symbol_kind(s.kind),
                tags: None,
                container_name: s.detail,
                location: OneOf::Left(lsp::Location::new(uri, map.range(s.selection_range))),
                data: None,
            })
        })
        .collect()
}

/// Semantic tokens, encoded relative to each other as the protocol wants.
/// A token that spans lines is split at line ends.
pub fn semantic_tokens(snap: &Snapshot, range: Option<Range<usize>>) -> Vec<SemanticToken> {
    let map = snap.map();
    let text = &snap.unit.text;
    let mut out = Vec::new();
    let (mut prev_line, mut prev_start) = (0u32, 0u32);
    let mut tokens = ide::semantic_tokens(&snap.task, snap.unit_idx, range);
    tokens.sort_by_key(|t| t.range.start);
    let mut last_end = 0;
    for t in tokens {
        if t.range.start < last_end || t.range.end <= t.range.start {
            continue; // overlapping or empty: the protocol allows neither
        }
        last_end = t.range.end;
        let mut start = t.range.start;
        while start < t.range.end {
            let p = map.position(start);
            let line_end = snap.index.line_range(p.line as usize, text).end;
            let end = t.range.end.min(line_end.max(start));
            let e = map.position(end);
            if e.character > p.character {
                let delta_line = p.line - prev_line;
                let delta_start = if delta_line == 0 {
                    p.character - prev_start
                } else {
                    p.character
                };
                out.push(SemanticToken {
                    delta_line,
                    delta_start,
                    length: e.character - p.character,
                    token_type: t.token_type,
                    token_modifiers_bitset: t.modifiers,
                });
                prev_line = p.line;
                prev_start = p.character;
            }
            // Continue on the next line, past the line ending.
            let next = snap
                .index
                .line_range(p.line as usize + 1, text)
                .start
                .max(end + 1);
            if next <= start {
                break;
            }
            start = next;
        }
    }
    out
}

/// The smallest edit turning `old` into `new` (flattened token arrays).
pub fn semantic_delta(old: &[u32], new: &[u32]) -> Option<lsp::SemanticTokensEdit> {
    if old == new {
        return None;
    }
    let (prefix, suffix) = rapid_analyzer::text::common_affixes(old, new);
    // Edits are on whole tokens of five numbers, as clients expect.
    let prefix = prefix / 5 * 5;
    let suffix = suffix / 5 * 5;
    let deleted = old.len() - prefix - suffix;
    let inserted = &new[prefix..new.len() - suffix];
    Some(lsp::SemanticTokensEdit {
        start: u32::try_from(prefix).unwrap_or(u32::MAX),
        delete_count: u32::try_from(deleted).unwrap_or(u32::MAX),
        data: Some(flat_to_tokens(inserted)),
    })
}

pub fn tokens_to_flat(tokens: &[SemanticToken]) -> Vec<u32> {
    tokens
        .iter()
        .flat_map(|t| {
            [
                t.delta_line,
                t.delta_start,
                t.length,
                t.token_type,
                t.token_modifiers_bitset,
            ]
        })
        .collect()
}

fn flat_to_tokens(flat: &[u32]) -> Vec<SemanticToken> {
    flat.chunks_exact(5)
        .map(|c| SemanticToken {
            delta_line: c[0],
            delta_start: c[1],
            length: c[2],
            token_type: c[3],
            token_modifiers_bitset: c[4],
        })
        .collect()
}

pub fn folding_ranges(snap: &Snapshot) -> Vec<lsp::FoldingRange> {
    let last = snap.index.line_count().saturating_sub(1);
    ide::folding_ranges(&snap.unit)
        .into_iter()
        .filter(|f| f.start_line < f.end_line && f.end_line <= last)
        .map(|f| lsp::FoldingRange {
            start_line: u32::try_from(f.start_line).unwrap_or(u32::MAX),
            end_line: u32::try_from(f.end_line).unwrap_or(u32::MAX),
            kind: f.kind.map(|k| match k {
                "comment" => FoldingRangeKind::Comment,
                "imports" => FoldingRangeKind::Imports,
                _ => FoldingRangeKind::Region,
            }),
            ..lsp::FoldingRange::default()
        })
        .collect()
}

pub fn selection_ranges(snap: &Snapshot, positions: &[Position]) -> Vec<SelectionRange> {
    let map = snap.map();
    let offsets: Vec<usize> = positions.iter().map(|p| map.offset(*p)).collect();
    let found = ide::selection_ranges(&snap.unit, &offsets);
    offsets
        .iter()
        .enumerate()
        .map(|(i, &offset)| {
            let ranges = found.get(i).cloned().unwrap_or_default();
            // Outermost first, so each range becomes the parent of the next.
            let mut nested: Option<SelectionRange> = None;
            for r in ranges.into_iter().rev() {
                nested = Some(SelectionRange {
                    range: map.range(r),
                    parent: nested.map(Box::new),
                });
            }
            nested.unwrap_or_else(|| SelectionRange {
                range: map.range(offset..offset),
                parent: None,
            })
        })
        .collect()
}

pub fn inlay_hints(snap: &Snapshot, range: lsp::Range) -> Vec<lsp::InlayHint> {
    let map = snap.map();
    ide::inlay_hints(
        &snap.task,
        snap.unit_idx,
        map.offset_range(range),
        snap.settings.parameter_hints,
    )
    .into_iter()
    .map(|h| {
        let parameter = h.kind == ide::InlayKind::Parameter;
        lsp::InlayHint {
            position: map.position(h.offset),
            label: InlayHintLabel::String(h.label),
            kind: parameter.then_some(InlayHintKind::PARAMETER),
            text_edits: None,
            tooltip: None,
            padding_left: Some(!parameter),
            padding_right: Some(parameter),
            data: None,
        }
    })
    .collect()
}

/// Quick fixes: the fixes the analyzer's diagnostics overlapping `range`
/// carry ([`ide::code_actions`]).
pub fn code_actions(snap: &Snapshot, range: lsp::Range) -> Vec<CodeActionOrCommand> {
    let map = snap.map();
    let span = map.offset_range(range);
    let here: Vec<_> = snap
        .reported_diagnostics()
        .into_iter()
        .filter(|d| d.range.start <= span.end && span.start <= d.range.end)
        .collect();
    let converted = |d: &rapid_analyzer::diagnostic::Diagnostic| {
        diagnostics::to_lsp(
            std::slice::from_ref(d),
            &map,
            &snap.uri,
            &snap.settings,
            &|path, range| snap.location(path, range),
        )
    };
    ide::code_actions(&snap.task, snap.unit_idx, span, &here)
        .into_iter()
        .map(|a| {
            let diags = a
                .diagnostic
                .and_then(|i| here.get(i))
                .map(converted)
                .unwrap_or_default();
            CodeActionOrCommand::CodeAction(code_action(
                snap,
                a.title,
                &a.edits,
                diags,
                a.preferred,
            ))
        })
        .collect()
}

fn code_action(
    snap: &Snapshot,
    title: String,
    edits: &[Edit],
    diagnostics: Vec<lsp::Diagnostic>,
    preferred: bool,
) -> lsp::CodeAction {
    let mut changes = HashMap::new();
    changes.insert(snap.uri.clone(), text_edits(&snap.map(), edits));
    lsp::CodeAction {
        title,
        kind: Some(if diagnostics.is_empty() {
            CodeActionKind::REFACTOR
        } else {
            CodeActionKind::QUICKFIX
        }),
        diagnostics: (!diagnostics.is_empty()).then_some(diagnostics),
        edit: Some(WorkspaceEdit {
            changes: Some(changes),
            ..WorkspaceEdit::default()
        }),
        command: None,
        is_preferred: Some(preferred),
        disabled: None,
        data: None,
    }
}

/// Whole-document or range formatting, as the smallest edits.
pub fn format(
    snap: &Snapshot,
    range: Option<lsp::Range>,
    options: &FormatOptions,
) -> Result<Vec<TextEdit>, String> {
    let map = snap.map();
    let text = &snap.unit.text;
    let edits = match range {
        None => rapid_analyzer::format::format_edits(text, options),
        Some(r) => rapid_analyzer::format::format_range(text, map.offset_range(r), options),
    }
    .map_err(|e| e.to_string())?;
    Ok(text_edits(&map, &edits))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tok(v: [u32; 5]) -> SemanticToken {
        flat_to_tokens(&v)[0]
    }

    #[test]
    fn deltas_replace_the_changed_middle() {
        let old = [0, 0, 3, 1, 0, 1, 2, 4, 2, 0, 1, 0, 5, 0, 0];
        let new = [0, 0, 3, 1, 0, 1, 2, 6, 2, 0, 0, 4, 1, 3, 0, 1, 0, 5, 0, 0];
        let edit = semantic_delta(&old, &new).expect("changed");
        assert_eq!(edit.start, 5);
        assert_eq!(edit.delete_count, 5);
        assert_eq!(
            edit.data,
            Some(vec![tok([1, 2, 6, 2, 0]), tok([0, 4, 1, 3, 0])])
        );
        assert_eq!(semantic_delta(&old, &old), None);
        let edit = semantic_delta(&old, &[]).expect("changed");
        assert_eq!((edit.start, edit.delete_count), (0, 15));
        // Applying the edit gives the new array.
        for (a, b) in [
            (&old[..], &new[..]),
            (&new[..], &old[..]),
            (&[][..], &old[..]),
        ] {
            let edit = semantic_delta(a, b).expect("changed");
            let mut applied = a.to_vec();
            let start = edit.start as usize;
            applied.splice(
                start..start + edit.delete_count as usize,
                tokens_to_flat(&edit.data.unwrap_or_default()),
            );
            assert_eq!(applied, b);
        }
    }
}
