//! The checks that look at the whole file's text: unfilled placeholders,
//! strings over the length limit and backslashes that start no escape,
//! wherever they are.

use std::ops::Range;

use tree_sitter::Node;

use super::Cx;
use crate::rules;

/// The longest string RAPID holds (the evaluator's limit too).
use rules::string_too_long::MAX_STRING;

/// Placeholders, string lengths and escapes, anywhere in the file.
pub(super) fn check_file_wide(cx: &mut Cx<'_>) {
    // The walk only enters nodes that overlap a region of the text that may
    // hold a finding, and nodes with syntax errors.
    let regions = file_wide_regions(cx.text);
    if regions.is_empty() {
        return;
    }
    let unit = cx.unit;
    check_file_wide_in(cx, unit.tree().root_node(), &regions);
}

/// [`check_file_wide`] in one tree, entering only nodes that overlap
/// `regions` (or hold a syntax error).
fn check_file_wide_in(cx: &mut Cx<'_>, root: Node<'_>, regions: &[Range<usize>]) {
    let overlaps = |node: Node<'_>| {
        let r = node.byte_range();
        let i = regions.partition_point(|g| g.end <= r.start);
        regions.get(i).is_some_and(|g| g.start < r.end)
    };
    let worth_entering = |node: Node<'_>| overlaps(node) || node.has_error();
    static KINDS: std::sync::OnceLock<(u16, u16)> = std::sync::OnceLock::new();
    let (placeholder, string) = *KINDS.get_or_init(|| {
        let language = crate::syntax::language();
        (
            language.id_for_node_kind("placeholder", true),
            language.id_for_node_kind(crate::syntax::kind::STRING, true),
        )
    });
    crate::syntax_util::walk_pruned(root, &mut |node| {
        let kind = node.kind_id();
        match kind {
            k if k == placeholder && overlaps(node) => {
                rules::incomplete_code::report(cx, node);
            }
            k if k == string && overlaps(node) => {
                rules::string_too_long::check(cx, node);
                rules::invalid_escape::check(cx, node);
            }
            _ => {}
        }
        kind != string && worth_entering(node)
    });
}

/// The regions of the text (sorted, disjoint byte ranges) where a
/// placeholder, a string longer than the limit or a bad escape may be: the
/// placeholder token's pattern, `<[A-Z]{2,4}>` (comparisons such as `a<b`
/// do not match), and the lines with more than the limit, or a backslash,
/// between their first and last quote (a string does not span lines).
fn file_wide_regions(text: &str) -> Vec<Range<usize>> {
    // All need a quote or a `<`: most generated modules have neither, and
    // two searches of the whole text cost less than a look at every line.
    if !text.contains('"') && !text.contains('<') {
        return Vec::new();
    }
    let bytes = text.as_bytes();
    let mut regions: Vec<Range<usize>> = Vec::new();
    let mut add = |r: Range<usize>| match regions.last_mut() {
        Some(last) if last.end >= r.start => last.end = last.end.max(r.end),
        _ => regions.push(r),
    };
    let mut line_start = 0;
    for line in text.split_inclusive('\n') {
        let start = line_start;
        line_start += line.len();
        if let (Some(a), Some(b)) = (line.find('"'), line.rfind('"'))
            && (b - a > MAX_STRING || line.get(a..b).is_some_and(|s| s.contains('\\')))
        {
            add(start..start + line.len());
            continue;
        }
        if !line.contains('<') {
            continue;
        }
        for (i, &b) in line.as_bytes().iter().enumerate() {
            if b != b'<' {
                continue;
            }
            let at = start + i;
            let rest = bytes.get(at + 1..).unwrap_or_default();
            let upper = rest.iter().take_while(|c| c.is_ascii_uppercase()).count();
            if (2..=4).contains(&upper) && rest.get(upper) == Some(&b'>') {
                add(at..at + upper + 2);
            }
        }
    }
    regions
}
