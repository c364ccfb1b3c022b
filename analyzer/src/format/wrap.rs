//! Wrapping long procedure calls at a line width (only when one is set).

use super::collect::{Class, Tok};
use super::indent::{Unit, columns, columns_from};
use super::layout::{Blank, Gap};

fn gap_width(gap: &Gap, text: &str) -> usize {
    match gap {
        Gap::None | Gap::Line { .. } => 0,
        Gap::Space => 1,
        Gap::Keep(range) => columns(text.get(range.clone()).unwrap_or_default()),
    }
}

/// The width of a token with the gap before it.
fn piece(toks: &[Tok<'_>], gaps: &[Gap], text: &str, k: usize) -> usize {
    columns_from(gap_width(&gaps[k], text), &toks[k].text)
}

/// Breaks lines longer than `max` at the wrap points (after the commas of
/// a procedure call's arguments), filling each line as far as it goes,
/// when every resulting line then fits; otherwise the line is left alone.
/// Continuation lines are indented one unit deeper than the statement. A
/// trailing comment does not count towards the width. Only a statement
/// that is on one line is wrapped: one its author already broke keeps the
/// author's breaks.
///
/// Stable: after a run every line with wrap points either fits, has a
/// piece that fits on no line, or belongs to a statement over several
/// lines, so a second run changes nothing.
pub(super) fn wrap(toks: &[Tok<'_>], text: &str, gaps: &mut [Gap], unit: &Unit, max: usize) {
    let mut start = 0;
    while start < toks.len() {
        let mut end = start + 1;
        while end < toks.len() && !starts_line(&gaps[end], text) {
            end += 1;
        }
        let line = start..end;
        start = end;
        if toks[line.start].start.is_none()
            || !toks[line.clone()].iter().skip(1).any(|t| t.wrap_point)
        {
            continue;
        }
        // the statement goes on past this line (its author broke it)
        let next_code = (line.end..toks.len()).find(|&k| toks[k].class != Class::Comment);
        if next_code.is_some_and(|k| toks[k].start.is_none() && toks[k].class != Class::Verbatim) {
            continue;
        }
        let mut code_end = line.end;
        if code_end - line.start > 1 && toks[code_end - 1].class == Class::Comment {
            code_end -= 1;
        }
        let Gap::Line { indent, .. } = &gaps[line.start] else {
            continue;
        };
        let indent = indent.clone();
        let first_col = columns(&indent);
        let total: usize = first_col
            + (line.start..code_end)
                .map(|k| piece(toks, gaps, text, k))
                .sum::<usize>();
        if total <= max {
            continue;
        }
        // the pieces between wrap points: (first token, width with the gap)
        let mut chunks: Vec<(usize, usize)> = Vec::new();
        let mut k = line.start;
        while k < code_end {
            let mut chunk_end = k + 1;
            while chunk_end < code_end && !toks[chunk_end].wrap_point {
                chunk_end += 1;
            }
            let w: usize = (k..chunk_end).map(|k| piece(toks, gaps, text, k)).sum();
            chunks.push((k, w));
            k = chunk_end;
        }
        // wrap only if every line then fits: a piece too long for any line
        // (a call with a long robtarget literal) leaves the line as it is
        let continuation = unit.deeper(&indent);
        let continuation_col = columns(&continuation);
        let first_fits = chunks.first().is_some_and(|&(_, w)| first_col + w <= max);
        if !first_fits
            || chunks
                .iter()
                .skip(1)
                .any(|&(k, w)| continuation_col + w - gap_width(&gaps[k], text) > max)
        {
            continue;
        }
        let mut used = first_col;
        for (n, &(k, w)) in chunks.iter().enumerate() {
            if n > 0 && used + w > max {
                used = continuation_col + w - gap_width(&gaps[k], text);
                gaps[k] = Gap::Line {
                    tail: 0..0,
                    blank: Blank::None,
                    indent: continuation.clone(),
                };
            } else {
                used += w;
            }
        }
    }
}

/// Does a gap put the token after it first on a line?
fn starts_line(gap: &Gap, text: &str) -> bool {
    match gap {
        Gap::Line { .. } => true,
        Gap::Keep(range) => text
            .get(range.clone())
            .is_some_and(|s| s.contains(['\n', '\r'])),
        Gap::None | Gap::Space => false,
    }
}
