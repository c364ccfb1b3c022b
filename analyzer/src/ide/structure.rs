//! Folding ranges and selection ranges, from the tree.

use std::ops::Range;

use tree_sitter::Node;

use super::FoldingRange;
use crate::syntax::{field, kind};
use crate::syntax_util::walk_pruned;
use crate::task::Unit;
use crate::text::LineIndex;

const FOLDED: &[&str] = &[
    kind::MODULE,
    kind::MODULE_HEADER,
    kind::RECORD_DECLARATION,
    kind::PROCEDURE_DECLARATION,
    kind::FUNCTION_DECLARATION,
    kind::TRAP_DECLARATION,
    kind::BACKWARD_HANDLER,
    kind::ERROR_HANDLER,
    kind::UNDO_HANDLER,
    kind::IF_STATEMENT,
    kind::ELSEIF_CLAUSE,
    kind::ELSE_CLAUSE,
    kind::FOR_STATEMENT,
    kind::WHILE_STATEMENT,
    kind::TEST_STATEMENT,
    kind::TEST_CASE,
    kind::DEFAULT_CASE,
];

/// Nodes that hold nothing foldable (but may hold comments only at their
/// ends, which a statement-level walk sees anyway).
const LEAVES: &[&str] = &[
    kind::DATA_DECLARATION,
    kind::PROCEDURE_CALL,
    kind::ASSIGNMENT,
    kind::RETURN_STATEMENT,
    kind::RAISE_STATEMENT,
    kind::GOTO_STATEMENT,
    kind::CONNECT_STATEMENT,
    kind::LABEL,
    kind::BINARY_EXPRESSION,
    kind::FUNCTION_CALL,
    kind::ARGUMENT_LIST,
    kind::NUMBER,
    kind::STRING,
    kind::IDENTIFIER,
    kind::TYPE_IDENTIFIER,
];

/// Foldable line ranges: modules, the `%%%` header (`region`), routines,
/// records, handlers, compound statements and their clauses, and runs of
/// two or more whole-line comments (`comment`). A block's closing line
/// (`ENDPROC`, `ENDIF`, ...) stays visible.
pub fn folding_ranges(unit: &Unit) -> Vec<FoldingRange> {
    let text = &unit.text;
    let lines = LineIndex::new(text);
    let line_of = |o: usize| lines.line_col(o).line;
    let mut out = Vec::new();
    let mut comments: Option<(usize, usize)> = None;
    let root = unit.tree().root_node();
    let flush = |c: &mut Option<(usize, usize)>, out: &mut Vec<FoldingRange>| {
        if let Some((s, e)) = c.take()
            && e > s
        {
            out.push(FoldingRange {
                start_line: s,
                end_line: e,
                kind: Some("comment"),
            });
        }
    };
    walk_pruned(root, &mut |n: Node<'_>| {
        let kind = n.kind();
        if LEAVES.contains(&kind) {
            return false;
        }
        if kind == kind::COMMENT {
            let line = line_of(n.start_byte());
            // Only comments that start their line form a block.
            let starts_line = text
                .get(..n.start_byte())
                .map(|b| b.rsplit('\n').next().unwrap_or_default().trim().is_empty())
                .unwrap_or(false);
            match &mut comments {
                Some((_, e)) if starts_line && *e + 1 == line => *e = line,
                _ => {
                    flush(&mut comments, &mut out);
                    if starts_line {
                        comments = Some((line, line));
                    }
                }
            }
            return false;
        }
        if FOLDED.contains(&kind) {
            // A module folds from its MODULE line (its `%%%` header folds alone).
            let from = match kind {
                kind::MODULE => n
                    .child_by_field_name(field::NAME)
                    .map_or(n.start_byte(), |m| m.start_byte()),
                _ => n.start_byte(),
            };
            let start = line_of(from);
            let mut end = line_of(n.end_byte().saturating_sub(1).max(n.start_byte()));
            // Keep the closing line (ENDPROC, ENDIF, ...) visible, except for
            // clauses and the `%%%` header, which have none of their own.
            let has_end_line = !matches!(
                kind,
                kind::MODULE_HEADER
                    | kind::ELSEIF_CLAUSE
                    | kind::ELSE_CLAUSE
                    | kind::TEST_CASE
                    | kind::DEFAULT_CASE
                    | kind::BACKWARD_HANDLER
                    | kind::ERROR_HANDLER
                    | kind::UNDO_HANDLER
            );
            if has_end_line && end > start {
                end -= 1;
            }
            if end > start {
                out.push(FoldingRange {
                    start_line: start,
                    end_line: end,
                    kind: (kind == kind::MODULE_HEADER).then_some("region"),
                });
            }
        }
        true
    });
    flush(&mut comments, &mut out);
    out.sort_by_key(|f| (f.start_line, std::cmp::Reverse(f.end_line)));
    out.dedup_by_key(|f| (f.start_line, f.end_line));
    out
}

/// For each offset, the ranges around it, innermost first: token,
/// expression, statement, block, routine, module, file.
pub fn selection_ranges(unit: &Unit, offsets: &[usize]) -> Vec<Vec<Range<usize>>> {
    let root = unit.tree().root_node();
    offsets
        .iter()
        .map(|&offset| {
            let offset = offset.min(unit.text.len());
            let mut out: Vec<Range<usize>> = Vec::new();
            let push = |r: Range<usize>, out: &mut Vec<Range<usize>>| {
                if out
                    .last()
                    .is_none_or(|l| l != &r && l.start >= r.start && l.end <= r.end)
                {
                    out.push(r);
                }
            };
            let mut at = root.descendant_for_byte_range(offset, offset);
            // Just after a token (where editors put the cursor): that token.
            if at.is_some_and(|n| !n.is_named() || n.start_byte() == offset)
                && offset > 0
                && let Some(left) = root.descendant_for_byte_range(offset - 1, offset - 1)
                && left.end_byte() == offset
                && left.is_named()
            {
                at = Some(left);
            }
            while let Some(n) = at {
                push(n.byte_range(), &mut out);
                // A statement in a block: the block's statements together.
                if let Some(p) = n.parent()
                    && super::resolve::field_in_parent(n) == Some(field::BODY)
                {
                    let body = crate::syntax_util::fields(p, field::BODY);
                    if let (Some(f), Some(l)) = (body.first(), body.last())
                        && body.len() > 1
                    {
                        push(f.start_byte()..l.end_byte(), &mut out);
                    }
                }
                at = n.parent();
            }
            // In deeply nested code, the innermost and the outermost
            // ranges only: a chain is sent as nested JSON objects, which
            // clients parse by recursion (serde_json stops at 128 levels).
            if out.len() > MAX_SELECTION_CHAIN {
                out.drain(MAX_SELECTION_CHAIN / 2..out.len() - MAX_SELECTION_CHAIN / 2);
            }
            out
        })
        .collect()
}

/// The most ranges [`selection_ranges`] gives around one offset.
pub const MAX_SELECTION_CHAIN: usize = 64;
