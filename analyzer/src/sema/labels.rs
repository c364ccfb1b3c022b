//! The labels of a routine: one walk, for the checker (duplicates, `GOTO`
//! targets), go-to-definition and completion after `GOTO`.

use std::ops::Range;

use tree_sitter::Node;

use crate::syntax::{field, kind};
use crate::syntax_util::{field, kind as kind_of};

/// A label of a routine: its name, the name's range, and the statement list
/// that holds it.
pub(crate) type Label = (String, Range<usize>, BlockKey);

/// The labels of a routine, in source order; `named` are the routine's
/// named children, if the caller has them from a walk of its own.
pub(crate) fn find(source: &str, routine: Node<'_>, named: Option<Vec<Node<'_>>>) -> Vec<Label> {
    // A label is `name:`; a routine without a `:` other than in `:=` or in a
    // comment has none (a cheap look at the text spares the walk of long
    // generated routines).
    let text = source.get(routine.byte_range()).unwrap_or_default();
    let mut from = 0;
    let has_colon = loop {
        match text.get(from..).and_then(|t| t.find(':')) {
            Some(i) => {
                let at = from + i;
                from = at + 1;
                if text.as_bytes().get(at + 1) == Some(&b'=') || in_comment(text, at) {
                    continue;
                }
                break true;
            }
            None => break false,
        }
    };
    if !has_colon {
        return Vec::new();
    }
    let mut stack = vec![(routine, named)];
    let mut found = Vec::new();
    while let Some((node, children)) = stack.pop() {
        let mut cursor = node.walk();
        let children = match children {
            Some(c) => c,
            None => node.named_children(&mut cursor).collect(),
        };
        for child in children {
            let kind = kind_of(child);
            if kind == "label" {
                if let Some(name) = field(child, field::NAME) {
                    found.push((
                        crate::syntax_util::text_of(name, source).to_owned(),
                        name.byte_range(),
                        block_key(node),
                    ));
                }
            } else if !kind.ends_with("expression")
                && kind != kind::ARGUMENT_LIST
                && (child.has_error() || !cannot_hold_label(kind))
            {
                stack.push((child, None));
            }
        }
    }
    found.sort_by_key(|(_, r, _)| r.start);
    found
}

/// What identifies the statement list that holds a label: its node's kind
/// and byte range.
pub(crate) type BlockKey = (u16, usize, usize);

pub(crate) fn block_key(node: Node<'_>) -> BlockKey {
    (node.kind_id(), node.start_byte(), node.end_byte())
}

/// Is byte `at` of `text` certainly inside a comment: after a `!` on its
/// line, with no quote before it on the line (which could open a string that
/// holds the `!`)?
fn in_comment(text: &str, at: usize) -> bool {
    let line = text.get(..at).unwrap_or_default();
    let line = line.rfind(['\n', '\r']).map_or(line, |i| &line[i + 1..]);
    line.contains('!') && !line.contains('"')
}

/// Nodes of these kinds hold no statement list, so (when they parsed
/// without error) no label: the label walk skips them.
fn cannot_hold_label(kind: &str) -> bool {
    crate::syntax_util::is_simple_statement(kind)
        || matches!(
            kind,
            kind::COMMENT | kind::COMPACT_IF_STATEMENT | kind::DATA_DECLARATION
        )
}
