//! Open documents: text, version, line index and the parsed unit, with
//! incremental edits.
//!
//! A batch of changes is applied in order: each range is converted with the
//! line index of the text as it is at that point, spliced into the text and
//! reported to the old tree with `Tree::edit`; after the batch, the text is
//! parsed once, reusing the edited tree. A whole-document change replaces
//! the text and parses from scratch.

use std::sync::Arc;

use rapid_analyzer::task::Unit;
use rapid_analyzer::text::LineIndex;
use tower_lsp_server::ls_types::{TextDocumentContentChangeEvent, Uri};
use tree_sitter::{InputEdit, Point, Tree};

use super::position::{LineMap, PosEncoding};

/// A document the editor has open.
pub struct Document {
    pub uri: Uri,
    pub version: i32,
    pub unit: Arc<Unit>,
    pub index: Arc<LineIndex>,
    /// Bumped on every change; results computed for an older generation
    /// are dropped.
    pub generation: u64,
}

/// Applies `changes` to `unit`'s text and tree; returns the new unit.
/// `index` is the line index of `unit`'s text (the first change's range is
/// converted with it; later ones with an index of the text as it is then).
pub fn apply_changes(
    unit: &Unit,
    index: &LineIndex,
    changes: &[TextDocumentContentChangeEvent],
    encoding: PosEncoding,
) -> Unit {
    let mut text = unit.text.clone();
    let mut tree: Option<Tree> = Some(unit.tree().clone());
    // `None`: `index` still describes `text`.
    let mut fresh: Option<Option<LineIndex>> = None;
    for change in changes {
        match change.range {
            None => {
                text.clone_from(&change.text);
                tree = None;
                fresh = Some(None);
            }
            Some(range) => {
                let idx = match &mut fresh {
                    None => index,
                    Some(fresh) => &*fresh.get_or_insert_with(|| LineIndex::new(&text)),
                };
                let span = LineMap::new(&text, idx, encoding).offset_range(range);
                let start_point = point_at(&text, span.start);
                let old_end_point = point_at(&text, span.end);
                text.replace_range(span.clone(), &change.text);
                let new_end = span.start + change.text.len();
                if let Some(tree) = tree.as_mut() {
                    tree.edit(&InputEdit {
                        start_byte: span.start,
                        old_end_byte: span.end,
                        new_end_byte: new_end,
                        start_position: start_point,
                        old_end_position: old_end_point,
                        new_end_position: point_at(&text, new_end),
                    });
                }
                fresh = Some(None);
            }
        }
    }
    Unit::new(unit.path.clone(), text, tree.as_ref())
}

/// Applies `changes` to a plain text (an I/O configuration open in the
/// editor).
pub fn apply_text_changes(
    text: &mut String,
    changes: &[TextDocumentContentChangeEvent],
    encoding: PosEncoding,
) {
    for change in changes {
        match change.range {
            None => text.clone_from(&change.text),
            Some(range) => {
                let index = LineIndex::new(text);
                let span = LineMap::new(text, &index, encoding).offset_range(range);
                text.replace_range(span, &change.text);
            }
        }
    }
}

/// A byte offset as tree-sitter counts points: rows end at `\n` only,
/// columns are bytes.
fn point_at(text: &str, offset: usize) -> Point {
    let before = &text.as_bytes()[..offset.min(text.len())];
    let row = before.iter().filter(|&&b| b == b'\n').count();
    let column = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(before.len(), |nl| before.len() - nl - 1);
    Point { row, column }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tower_lsp_server::ls_types::{Position, Range};

    fn change(l1: u32, c1: u32, l2: u32, c2: u32, text: &str) -> TextDocumentContentChangeEvent {
        TextDocumentContentChangeEvent {
            range: Some(Range::new(Position::new(l1, c1), Position::new(l2, c2))),
            range_length: None,
            text: text.to_owned(),
        }
    }

    /// Incremental reparse gives the same tree as a fresh parse.
    fn check(before: &str, changes: &[TextDocumentContentChangeEvent], after: &str) {
        let unit = Unit::new("t/A.mod".into(), before.to_owned(), None);
        let index = LineIndex::new(&unit.text);
        let edited = apply_changes(&unit, &index, changes, PosEncoding::Utf16);
        assert_eq!(edited.text, after);
        let fresh = Unit::new("t/A.mod".into(), after.to_owned(), None);
        assert_eq!(
            edited.tree().root_node().to_sexp(),
            fresh.tree().root_node().to_sexp()
        );
        assert_eq!(edited.syntax, fresh.syntax);
    }

    #[test]
    fn edits_apply_in_order_and_reparse_incrementally() {
        let text = "MODULE M\r\n  PROC p()\r\n    x := 1;\r\n  ENDPROC\r\nENDMODULE\r\n";
        check(
            text,
            &[change(2, 9, 2, 10, "42"), change(2, 4, 2, 5, "y")],
            "MODULE M\r\n  PROC p()\r\n    y := 42;\r\n  ENDPROC\r\nENDMODULE\r\n",
        );
        // Inserting a line, then deleting across lines.
        check(
            text,
            &[
                change(1, 10, 1, 10, "\r\n    ! Größe 𝄞"),
                change(2, 0, 3, 0, ""),
            ],
            "MODULE M\r\n  PROC p()\r\n    x := 1;\r\n  ENDPROC\r\nENDMODULE\r\n",
        );
        // Non-ASCII before the edit: UTF-16 columns.
        check(
            "MODULE M\n  ! é𝄞\n  VAR num n := 1;\nENDMODULE\n",
            &[change(1, 7, 1, 7, "!")],
            "MODULE M\n  ! é𝄞!\n  VAR num n := 1;\nENDMODULE\n",
        );
        // A syntax error comes and goes.
        check(
            "MODULE M\n  PROC p()\n  ENDPROC\nENDMODULE\n",
            &[change(1, 2, 1, 6, "PRO")],
            "MODULE M\n  PRO p()\n  ENDPROC\nENDMODULE\n",
        );
    }

    #[test]
    fn whole_document_changes_replace_the_text() {
        let full = TextDocumentContentChangeEvent {
            range: None,
            range_length: None,
            text: "MODULE N\nENDMODULE\n".into(),
        };
        check(
            "MODULE M\nENDMODULE\n",
            &[full, change(0, 7, 0, 8, "Q")],
            "MODULE Q\nENDMODULE\n",
        );
    }

    #[test]
    fn points_count_rows_at_line_feeds() {
        assert_eq!(point_at("ab\r\ncd", 5), Point { row: 1, column: 1 });
        assert_eq!(point_at("ab\rcd", 4), Point { row: 0, column: 4 });
        assert_eq!(point_at("ab", 9), Point { row: 0, column: 2 });
    }
}
