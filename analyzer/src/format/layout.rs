//! The whitespace between tokens: line breaks and indentation from the
//! structure, spaces from the token classes, then long argument lists
//! wrapped.

use std::ops::Range;

use super::FormatOptions;
use super::collect::{Class, Tok};

/// What goes between a token and the one before it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Gap {
    /// Nothing: the tokens touch.
    None,
    /// One space.
    Space,
    /// The original blanks, kept as they were (before a trailing comment).
    Keep(Range<usize>),
    /// A line break, maybe a blank line, then `indent` spaces.
    Line { blank: bool, indent: usize },
}

/// The number of line breaks in `s` (CRLF counts once).
fn newlines(s: &str) -> usize {
    let bytes = s.as_bytes();
    let mut n = 0;
    for (i, &b) in bytes.iter().enumerate() {
        match b {
            b'\n' => n += 1,
            b'\r' if bytes.get(i + 1) != Some(&b'\n') => n += 1,
            _ => {}
        }
    }
    n
}

/// The gap before every token (the first one's is always [`Gap::None`]).
pub(super) fn layout(toks: &[Tok<'_>], text: &str, options: &FormatOptions) -> Vec<Gap> {
    let iw = options.indent_width;
    let n = toks.len();
    let breaks: Vec<usize> = (0..n)
        .map(|i| {
            let start = if i == 0 { 0 } else { toks[i - 1].range.end };
            newlines(text.get(start..toks[i].range.start).unwrap_or_default())
        })
        .collect();
    let force_blank = forced_blank_lines(toks, &breaks);
    // the next token that is not a comment, for each position
    let mut next_code = vec![None; n];
    let mut next = None;
    for i in (0..n).rev() {
        next_code[i] = next;
        if toks[i].class != Class::Comment {
            next = Some(i);
        }
    }

    let mut gaps = Vec::with_capacity(n);
    let mut statement_indent = vec![0; n];
    let mut stmt = 0;
    let mut line_indent = 0;
    // where a statement would go after the last line-starting token
    let mut body_level = 0;
    // for each open bracket, the indentation of lines inside it
    let mut stack: Vec<usize> = Vec::new();
    let continuation = |stack: &[usize], stmt: usize, tok: &Tok<'_>| match stack.last() {
        Some(&inner) if tok.class == Class::Close => inner.saturating_sub(iw),
        Some(&inner) => inner,
        None => stmt + iw,
    };
    for (i, tok) in toks.iter().enumerate() {
        let blank = breaks[i] >= 2 || force_blank[i];
        let gap = if i == 0 {
            Gap::None
        } else if tok.class == Class::Verbatim || toks[i - 1].class == Class::Verbatim {
            Gap::Keep(toks[i - 1].range.end..tok.range.start)
        } else if tok.class == Class::Comment && breaks[i] == 0 {
            let before = toks[i - 1].range.end..tok.range.start;
            if before.is_empty() {
                Gap::Space
            } else {
                Gap::Keep(before)
            }
        } else if tok.class == Class::Comment {
            let indent = match next_code[i].map(|j| &toks[j]) {
                None => 0,
                Some(next) => match next.line_start {
                    Some(_) if next.closer => body_level,
                    Some(column) => column,
                    None => continuation(&stack, stmt, next),
                },
            };
            Gap::Line {
                blank: blank && !tok.no_blank,
                indent,
            }
        } else if let Some(column) = tok.line_start {
            Gap::Line {
                blank: blank && !tok.no_blank,
                indent: column,
            }
        } else if breaks[i] > 0 {
            Gap::Line {
                blank,
                indent: continuation(&stack, stmt, tok),
            }
        } else if spaced(&toks[i - 1], tok) || !joinable(&toks[i - 1].text, &tok.text) {
            Gap::Space
        } else {
            Gap::None
        };
        if let Some(column) = tok.line_start {
            stmt = column;
            body_level = if tok.opens { column + iw } else { column };
            stack.clear();
        }
        if let Gap::Line { indent, .. } = gap {
            line_indent = indent;
        }
        match tok.class {
            Class::Open => stack.push(line_indent + iw),
            Class::Close => {
                stack.pop();
            }
            _ => {}
        }
        statement_indent[i] = stmt;
        gaps.push(gap);
    }
    wrap(toks, text, &mut gaps, &statement_indent, options);
    gaps
}

/// Where a blank line must be added so that routines (and modules) are
/// separated by one: right after the end of the one before, unless there is
/// already a blank line between them (comments may sit in between).
fn forced_blank_lines(toks: &[Tok<'_>], breaks: &[usize]) -> Vec<bool> {
    let mut force = vec![false; toks.len()];
    for i in 0..toks.len() {
        if !toks[i].unit_start_after_unit {
            continue;
        }
        let mut first = i;
        while first > 0 && toks[first - 1].class == Class::Comment {
            first -= 1;
        }
        if (first..=i).any(|k| breaks[k] >= 2) {
            continue;
        }
        let at = (first..=i).find(|&k| breaks[k] >= 1).unwrap_or(i);
        force[at] = true;
    }
    force
}

/// Is there a space between two tokens on one line?
fn spaced(prev: &Tok<'_>, next: &Tok<'_>) -> bool {
    use Class::*;
    if matches!(
        next.class,
        Comma | Semicolon | Colon | Dot | Close | PercentClose | Question | AssignTight
    ) {
        return false;
    }
    if matches!(
        prev.class,
        Dot | Open
            | PercentOpen
            | Unary
            | Question
            | AssignTight
            | Colon
            | BackslashArgument
            | BackslashParameter
    ) {
        return false;
    }
    match next.class {
        BackslashArgument => prev.class == Comma || prev.proc_name,
        Open => prev.proc_name || !matches!(prev.class, Word | Close),
        _ => true,
    }
}

/// Can two tokens touch without becoming one token (or a different one)?
/// A safety net under [`spaced`]: names and numbers never touch, nor do
/// characters that would form `:=`, `<>`, `<=`, `>=`, `%%%`, a comment or a
/// longer number.
fn joinable(a: &str, b: &str) -> bool {
    let (Some(x), Some(y)) = (a.chars().next_back(), b.chars().next()) else {
        return true;
    };
    let word = |c: char| c.is_alphanumeric() || c == '_';
    !(word(x) && word(y)
        || y == '!'
        || matches!(
            (x, y),
            ('<', '>' | '=')
                | ('>', '=')
                | (':', '=')
                | ('%', '%')
                | ('"', '"')
                | ('.', '0'..='9')
                | ('0'..='9', '.')
                | ('\\', '\\')
        ))
}

fn width(s: &str) -> usize {
    s.chars().count()
}

fn gap_width(gap: &Gap, text: &str) -> usize {
    match gap {
        Gap::None | Gap::Line { .. } => 0,
        Gap::Space => 1,
        Gap::Keep(range) => width(text.get(range.clone()).unwrap_or_default()),
    }
}

/// Breaks lines longer than the line width at the wrap points (after the
/// commas of a procedure call's arguments), filling each line as far as it
/// goes, when every resulting line then fits; otherwise the line is left
/// alone. Continuation lines are indented one level deeper than the
/// statement. A trailing comment does not count towards the width.
///
/// Stable: after a run every line with wrap points either fits or has a
/// piece that fits on no line, so a second run changes nothing.
fn wrap(
    toks: &[Tok<'_>],
    text: &str,
    gaps: &mut [Gap],
    statement_indent: &[usize],
    options: &FormatOptions,
) {
    let max = options.line_width;
    let mut start = 0;
    while start < toks.len() {
        let mut end = start + 1;
        while end < toks.len() && !matches!(gaps[end], Gap::Line { .. }) {
            end += 1;
        }
        let line = start..end;
        start = end;
        if !toks[line.clone()].iter().skip(1).any(|t| t.wrap_point) {
            continue;
        }
        let mut code_end = line.end;
        if code_end - line.start > 1 && toks[code_end - 1].class == Class::Comment {
            code_end -= 1;
        }
        let indent = match gaps[line.start] {
            Gap::Line { indent, .. } => indent,
            _ => 0,
        };
        let total: usize = indent
            + (line.start..code_end)
                .map(|k| piece(toks, gaps, text, k))
                .sum::<usize>()
            - gap_width(&gaps[line.start], text);
        if total <= max {
            continue;
        }
        // the pieces between wrap points: (first token, width with the gap)
        let mut chunks: Vec<(usize, usize)> = Vec::new();
        let mut k = line.start;
        while k < code_end {
            let mut chunk_end = k + 1;
            while chunk_end < code_end
                && !(toks[chunk_end].wrap_point && gaps[chunk_end] == Gap::Space)
            {
                chunk_end += 1;
            }
            let w: usize = (k..chunk_end).map(|k| piece(toks, gaps, text, k)).sum();
            chunks.push((k, w));
            k = chunk_end;
        }
        // wrap only if every line then fits: a piece too long for any line
        // (a call with a long robtarget literal) leaves the line as it is
        let continuation = |k: usize| statement_indent[k] + options.indent_width;
        let first_fits = chunks
            .first()
            .is_some_and(|&(k, w)| indent + w - gap_width(&gaps[k], text) <= max);
        if !first_fits
            || chunks
                .iter()
                .skip(1)
                .any(|&(k, w)| continuation(k) + w - 1 > max)
        {
            continue;
        }
        let mut used = indent;
        for (n, &(k, w)) in chunks.iter().enumerate() {
            if n == 0 {
                used += w - gap_width(&gaps[k], text);
            } else if used + w > max {
                let indent = continuation(k);
                gaps[k] = Gap::Line {
                    blank: false,
                    indent,
                };
                used = indent + w - 1;
            } else {
                used += w;
            }
        }
    }
}

/// The width of a token with the gap before it.
fn piece(toks: &[Tok<'_>], gaps: &[Gap], text: &str, k: usize) -> usize {
    gap_width(&gaps[k], text) + width(&toks[k].text)
}

/// The text of a gap.
pub(super) fn render(gap: &Gap, text: &str, line_ending: &str, out: &mut String) {
    match gap {
        Gap::None => {}
        Gap::Space => out.push(' '),
        Gap::Keep(range) => out.push_str(text.get(range.clone()).unwrap_or_default()),
        Gap::Line { blank, indent } => {
            out.push_str(line_ending);
            if *blank {
                out.push_str(line_ending);
            }
            out.extend(std::iter::repeat_n(' ', *indent));
        }
    }
}
