//! Open documents: text, version, line index and the parsed unit, with
//! incremental edits.
//!
//! A batch of changes is applied in order: each range is converted to
//! bytes with the line index of the text as it is at that point; the
//! analyzer applies the edits and parses again, reusing the old tree
//! (`Unit::edited`).

use std::sync::Arc;

use rapid_analyzer::edit::TextEdit;
use rapid_analyzer::task::Unit;
use rapid_analyzer::text::LineIndex;
use tower_lsp_server::ls_types::{TextDocumentContentChangeEvent, Uri};

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
    unit.edited(&to_edits(&unit.text, index, changes, encoding))
}

/// `changes` as byte ranges, each in the text as the changes before it
/// left it (a whole-document change replaces the whole text).
fn to_edits(
    text: &str,
    index: &LineIndex,
    changes: &[TextDocumentContentChangeEvent],
    encoding: PosEncoding,
) -> Vec<TextEdit> {
    let mut edits = Vec::with_capacity(changes.len());
    // The text after the edits so far and its index, once there are any.
    let mut now: Option<(String, LineIndex)> = None;
    for (i, change) in changes.iter().enumerate() {
        let (text, index) = match &now {
            None => (text, index),
            Some((text, index)) => (text.as_str(), index),
        };
        let range = match change.range {
            None => 0..text.len(),
            Some(range) => LineMap::new(text, index, encoding).offset_range(range),
        };
        if i + 1 < changes.len() {
            let mut next = text.to_owned();
            next.replace_range(range.clone(), &change.text);
            let index = LineIndex::new(&next);
            now = Some((next, index));
        }
        edits.push(TextEdit::new(range, change.text.clone()));
    }
    edits
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
}
