//! Edits to a unit's text, and the incremental re-parse after them.
//!
//! A batch of edits is applied in order, each range in the text as the
//! edits before it left it. Each edit is spliced into the text and reported
//! to the old tree (`Tree::edit`); after the batch, the text is parsed once,
//! reusing the edited tree. An edit replacing the whole text drops the tree:
//! the text is parsed from scratch.

use std::ops::Range;

use tree_sitter::{InputEdit, Point, Tree};

use crate::task::Unit;

/// One edit: the bytes of `range` (in the text as the edits before it left
/// it) replaced by `text`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextEdit {
    pub range: Range<usize>,
    pub text: String,
}

impl TextEdit {
    pub fn new(range: Range<usize>, text: impl Into<String>) -> TextEdit {
        TextEdit {
            range,
            text: text.into(),
        }
    }
}

impl Unit {
    /// The unit after `edits` (applied in order), parsed again reusing this
    /// unit's tree. A range past the end of the text is cut to it, and one
    /// that splits a character is widened to the whole character.
    pub fn edited(&self, edits: &[TextEdit]) -> Unit {
        let mut text = self.text.clone();
        let mut tree: Option<Tree> = Some(self.tree().clone());
        for edit in edits {
            let span = clamp(&text, &edit.range);
            if span.start == 0 && span.end == text.len() {
                text.clone_from(&edit.text);
                tree = None;
                continue;
            }
            let start_position = point_at(&text, span.start);
            let old_end_position = point_at(&text, span.end);
            text.replace_range(span.clone(), &edit.text);
            let new_end = span.start + edit.text.len();
            if let Some(tree) = tree.as_mut() {
                tree.edit(&InputEdit {
                    start_byte: span.start,
                    old_end_byte: span.end,
                    new_end_byte: new_end,
                    start_position,
                    old_end_position,
                    new_end_position: point_at(&text, new_end),
                });
            }
        }
        Unit::new(self.path.clone(), text, tree.as_ref())
    }
}

/// `range` within `text`, on character boundaries (widened outwards).
fn clamp(text: &str, range: &Range<usize>) -> Range<usize> {
    let end = range.end.min(text.len());
    let start = range.start.min(end);
    floor_boundary(text, start)..ceil_boundary(text, end)
}

/// The last character boundary at or before `at` (`at <= text.len()`).
pub(crate) fn floor_boundary(text: &str, at: usize) -> usize {
    (0..=at)
        .rev()
        .find(|&i| text.is_char_boundary(i))
        .unwrap_or(0)
}

/// The first character boundary at or after `at` (`at <= text.len()`).
pub(crate) fn ceil_boundary(text: &str, at: usize) -> usize {
    (at..text.len())
        .find(|&i| text.is_char_boundary(i))
        .unwrap_or(text.len())
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
mod tests;
