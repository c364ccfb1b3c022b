//! A formatted text as edits of whole lines: what an editor applies in one
//! step, instead of one edit per gap between tokens.

use crate::diagnostic::Edit;

/// The lines of `text` with their line breaks, so that they join back into
/// `text`: (byte offset, line).
fn lines(text: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = 0;
    for (_, end) in super::layout::line_breaks(text) {
        out.push((start, &text[start..end]));
        start = end;
    }
    if start < text.len() {
        out.push((start, &text[start..]));
    }
    out
}

/// The edits that turn `old` into `new`, each replacing whole lines (with
/// their line breaks): one per changed line where lines were changed one
/// for one, one per run of lines where they were split, joined, added or
/// removed. In order, not overlapping, on `old`'s byte offsets.
pub(super) fn line_changes(old: &str, new: &str) -> Vec<Edit> {
    let a = lines(old);
    let b = lines(new);
    let a_text: Vec<&str> = a.iter().map(|(_, l)| *l).collect();
    let b_text: Vec<&str> = b.iter().map(|(_, l)| *l).collect();
    let offset_a = |i: usize| a.get(i).map_or(old.len(), |(o, _)| *o);
    let offset_b = |i: usize| b.get(i).map_or(new.len(), |(o, _)| *o);
    let ops = similar::capture_diff_slices(similar::Algorithm::Myers, &a_text, &b_text);
    let mut edits: Vec<Edit> = Vec::new();
    let mut push = |o: std::ops::Range<usize>, n: std::ops::Range<usize>| {
        edits.push(Edit {
            range: offset_a(o.start)..offset_a(o.end),
            replacement: new[offset_b(n.start)..offset_b(n.end)].to_owned(),
        });
    };
    for op in ops {
        if let similar::DiffOp::Equal { .. } = op {
            continue;
        }
        let (o, n) = (op.old_range(), op.new_range());
        if o.len() == n.len() {
            for k in 0..o.len() {
                push(o.start + k..o.start + k + 1, n.start + k..n.start + k + 1);
            }
        } else {
            push(o, n);
        }
    }
    edits
}

/// Neighbouring edits made one.
pub(super) fn merge(edits: Vec<Edit>) -> Vec<Edit> {
    let mut out: Vec<Edit> = Vec::with_capacity(edits.len());
    for e in edits {
        if let Some(last) = out.last_mut()
            && last.range.end == e.range.start
        {
            last.range.end = e.range.end;
            last.replacement.push_str(&e.replacement);
            continue;
        }
        out.push(e);
    }
    out
}

/// The edits that turn `old` into `new`, one per run of changed lines, each
/// replacing whole lines (with their line breaks).
pub(super) fn hunks(old: &str, new: &str) -> Vec<Edit> {
    merge(line_changes(old, new))
}

/// The edits that turn `old` into `new` as whole changed lines, one per
/// run of them, or one edit of the whole text when more than half of its
/// lines change
/// (an editor applies one large edit faster than thousands of small ones).
/// None when the texts are equal.
pub fn line_edits(old: &str, new: &str) -> Vec<Edit> {
    if old == new {
        return Vec::new();
    }
    let edits = hunks(old, new);
    let total = lines(old).len().max(1);
    let changed: usize = edits
        .iter()
        .map(|e| lines(&old[e.range.clone()]).len())
        .sum();
    if changed * 2 > total {
        return vec![Edit {
            range: 0..old.len(),
            replacement: new.to_owned(),
        }];
    }
    edits
}

/// `text` with `edits` (in order, not overlapping) applied.
#[cfg(test)]
pub(super) fn apply(text: &str, edits: &[Edit]) -> String {
    let mut out = text.to_owned();
    for e in edits.iter().rev() {
        out.replace_range(e.range.clone(), &e.replacement);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn changed_lines_become_one_edit_per_run() {
        let old = "a\nb\nc\nd\ne\nf\ng\n";
        let new = "a\n  b\n  c\nd\ne\nf\n  g\n";
        let edits = line_edits(old, new);
        assert_eq!(edits.len(), 2, "{edits:?}");
        assert_eq!(edits[0].range, 2..6);
        assert_eq!(edits[0].replacement, "  b\n  c\n");
        assert_eq!(apply(old, &edits), new);
    }

    #[test]
    fn split_joined_and_unterminated_lines_round_trip() {
        for (old, new) in [
            ("a b\nc", "a\nb\nc"),
            ("a\n\n\nb\r\n", "a\n\nb\r\n"),
            ("x\ny", "x\ny\n"),
            ("p\nq\nr\ns\nt\nu", "p\nQ\nr\ns\nt\nu"),
        ] {
            assert_eq!(apply(old, &line_edits(old, new)), new, "{old:?}");
            assert_eq!(apply(old, &hunks(old, new)), new, "{old:?}");
        }
    }

    #[test]
    fn most_lines_changed_is_one_edit() {
        let edits = line_edits("a\nb\nc\n", "A\nB\nc\n");
        assert_eq!(edits.len(), 1);
        assert_eq!(edits[0].range, 0..6);
        assert!(line_edits("same", "same").is_empty());
    }
}
