//! The whitespace between tokens: line breaks and indentation from the
//! structure, continuation lines and comments placed after the code around
//! them, blanks inside lines from the style, then (with a line width) long
//! argument lists wrapped.

use std::ops::Range;

use super::collect::{Class, Depth, Start, Tok};
use super::indent::{self, Unit, columns, columns_from};
use super::{FormatOptions, Style, spacing, wrap};

/// What goes between a token and the one before it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Gap {
    /// Nothing: the tokens touch.
    None,
    /// One space.
    Space,
    /// The original text, kept as it was (line breaks written with the
    /// text's line ending).
    Keep(Range<usize>),
    /// A line break: first `tail` (blanks the line ended with, kept), then
    /// blank lines, then the indentation of the new line.
    Line {
        tail: Range<usize>,
        blank: Blank,
        indent: String,
    },
}

/// The blank lines of a [`Gap::Line`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Blank {
    None,
    One,
    /// The original blank lines: the text between the gap's first and last
    /// line breaks (each line with the blanks it had).
    Kept(Range<usize>),
}

/// Every line break in `s`: (start, end) byte offsets, CRLF counting once.
pub(super) fn line_breaks(s: &str) -> impl Iterator<Item = (usize, usize)> + '_ {
    let bytes = s.as_bytes();
    bytes.iter().enumerate().filter_map(move |(i, &b)| match b {
        b'\n' if i > 0 && bytes[i - 1] == b'\r' => None,
        b'\n' => Some((i, i + 1)),
        b'\r' if bytes.get(i + 1) == Some(&b'\n') => Some((i, i + 2)),
        b'\r' => Some((i, i + 1)),
        _ => None,
    })
}

/// Only spaces, tabs and line breaks: the blanks the formatter may rewrite.
/// Anything else between tokens (a U+FEFF, a form feed, another Unicode
/// space) makes the gap one it keeps as it is.
fn plain(s: &str) -> bool {
    s.bytes().all(|b| matches!(b, b' ' | b'\t' | b'\n' | b'\r'))
}

/// What the layout knows of each token of the original text.
struct Original<'t> {
    text: &'t str,
    /// The gap before each token.
    gap: Vec<Range<usize>>,
    /// Line breaks in that gap.
    breaks: Vec<usize>,
    /// The column of each token (tabs counted as in [`columns`]).
    col: Vec<usize>,
    /// The indentation of the token's line, if the token starts it.
    indent: Vec<Option<&'t str>>,
    /// The first token of the token's line.
    line_first: Vec<usize>,
}

impl<'t> Original<'t> {
    fn new(toks: &[Tok<'_>], text: &'t str) -> Original<'t> {
        let n = toks.len();
        let mut o = Original {
            text,
            gap: Vec::with_capacity(n),
            breaks: Vec::with_capacity(n),
            col: Vec::with_capacity(n),
            indent: Vec::with_capacity(n),
            line_first: Vec::with_capacity(n),
        };
        let mut first = 0;
        let mut prev_end = 0;
        // the column after the previous token
        let mut end_col = 0;
        for (i, tok) in toks.iter().enumerate() {
            let gap = prev_end..tok.range.start;
            let gap_text = text.get(gap.clone()).unwrap_or_default();
            let breaks = line_breaks(gap_text).count();
            let last_break = line_breaks(gap_text).last().map(|(_, end)| end);
            let (col, indent) = match last_break {
                Some(end) => {
                    let before = &gap_text[end..];
                    let blank = before.bytes().all(|b| b == b' ' || b == b'\t');
                    (columns(before), blank.then_some(before))
                }
                None if i == 0 => {
                    let blank = gap_text.bytes().all(|b| b == b' ' || b == b'\t');
                    (columns(gap_text), blank.then_some(gap_text))
                }
                None => (columns_from(end_col, gap_text), None),
            };
            if i == 0 || breaks > 0 || indent.is_some() {
                first = i;
            }
            o.col.push(col);
            o.indent.push(indent);
            o.line_first.push(first);
            o.breaks.push(breaks);
            o.gap.push(gap);
            // a token holding line breaks (text after ENDMODULE)
            let raw = text.get(tok.range.clone()).unwrap_or_default();
            end_col = match line_breaks(raw).last() {
                Some((_, end)) => columns(&raw[end..]),
                None => columns_from(col, raw),
            };
            prev_end = tok.range.end;
        }
        o
    }

    fn gap_text(&self, i: usize) -> &'t str {
        self.text.get(self.gap[i].clone()).unwrap_or_default()
    }

    /// The blanks before the gap's first line break, and its blank lines.
    fn line_parts(&self, i: usize) -> (Range<usize>, Option<Range<usize>>) {
        let gap = &self.gap[i];
        let s = self.gap_text(i);
        let mut breaks = line_breaks(s);
        let Some((first_start, first_end)) = breaks.next() else {
            return (gap.end..gap.end, None);
        };
        let tail = gap.start..gap.start + first_start;
        let blank = breaks
            .last()
            .map(|(last_start, _)| gap.start + first_end..gap.start + last_start);
        (tail, blank)
    }
}

/// The layout under construction.
struct Layout<'a, 't> {
    toks: &'a [Tok<'t>],
    orig: Original<'a>,
    style: Style,
    /// The file's unit (for wrapped lines).
    unit: Unit,
    /// The unit of each top-level item, and each token's item.
    units: Vec<Unit>,
    item: Vec<usize>,
    /// The indentation written before each token that starts a line.
    indent: Vec<Option<String>>,
    /// The column of each token in the result.
    col: Vec<usize>,
    /// The first token of each token's line in the result.
    line_first: Vec<usize>,
    /// The statement (the last token the structure starts a line with) of
    /// each token.
    stmt: Vec<Option<usize>>,
    /// The tokens of the current statement that a continuation line can be
    /// aligned under, by their column as written (the first of each).
    anchors: std::collections::HashMap<usize, usize>,
}

/// Each token's top-level item of the module (a routine, a run of
/// declarations), the number of items, and the lines of the text that the
/// structure starts: their item, depth and indentation as written.
type Structure<'t> = (Vec<usize>, usize, Vec<(usize, Depth, &'t str)>);

fn structure<'t>(toks: &[Tok<'_>], orig: &Original<'t>) -> Structure<'t> {
    let n = toks.len();
    let mut item = vec![0; n];
    let mut lines = Vec::new();
    let mut items = 0;
    // a run of data declarations is one item; a routine (or record) is one
    let mut in_declarations = false;
    for (i, t) in toks.iter().enumerate() {
        if let Some(Start::Level(depth)) = t.start {
            let top = depth.is_module_body() && !t.closer;
            if depth.is_zero() || top && (t.opens.is_some() || !in_declarations) {
                items += 1;
            }
            if depth.is_zero() || top {
                in_declarations = top && t.opens.is_none();
            }
            if let Some(indent) = orig.indent[i]
                && (i == 0 || orig.breaks[i] > 0)
            {
                lines.push((items, depth, indent));
            }
        }
        item[i] = items;
    }
    (item, items, lines)
}

/// The text's indentation unit: configured, or the one most of its
/// structure lines follow ([`indent::detect`]).
fn file_unit(toks: &[Tok<'_>], lines: &[(usize, Depth, &str)], options: &FormatOptions) -> Unit {
    // declarations only: nothing opens a block deeper than the module body
    let declarations_only = !toks
        .iter()
        .any(|t| t.opens.is_some_and(|d| !d.is_zero() && !d.is_module_body()));
    match options.indent_width {
        Some(width) => Unit::spaces(width),
        None => indent::detect(lines.iter().map(|&(_, d, s)| (d, s)), declarations_only),
    }
}

/// The unit [`layout`] indents the text of `toks` with.
pub(super) fn unit(toks: &[Tok<'_>], text: &str, options: &FormatOptions) -> Unit {
    let orig = Original::new(toks, text);
    file_unit(toks, &structure(toks, &orig).2, options)
}

/// The gap before every token.
pub(super) fn layout(toks: &[Tok<'_>], text: &str, options: &FormatOptions) -> Vec<Gap> {
    let orig = Original::new(toks, text);
    let n = toks.len();
    let (item, items, lines) = structure(toks, &orig);
    let file = file_unit(toks, &lines, options);
    let mut units = vec![file.clone(); items + 1];
    if options.indent_width.is_none() {
        // each item that consistently follows another unit keeps it
        let mut from = 0;
        while from < lines.len() {
            let it = lines[from].0;
            let to = from + lines[from..].iter().take_while(|l| l.0 == it).count();
            units[it] = indent::refine(&file, lines[from..to].iter().map(|&(_, d, s)| (d, s)));
            from = to;
        }
    }
    let mut l = Layout {
        toks,
        orig,
        style: options.style,
        unit: file,
        units,
        item,
        indent: vec![None; n],
        col: vec![0; n],
        line_first: vec![0; n],
        stmt: vec![None; n],
        anchors: std::collections::HashMap::new(),
    };
    let mut gaps = l.code_gaps();
    l.comment_gaps(&mut gaps);
    if let Some(width) = options.line_width {
        wrap::wrap(toks, text, &mut gaps, &l.unit, width);
    }
    if options.style == Style::AsWritten && options.indent_width.is_none() {
        // a line that is at the right column keeps the blanks that took it
        // there (tabs, spaces or both)
        for (i, gap) in gaps.iter_mut().enumerate() {
            if let Gap::Line { indent, .. } = gap
                && let Some(old) = l.orig.indent[i]
                && l.orig.breaks[i] > 0
                && columns(old) == columns(indent)
                && old != indent
            {
                old.clone_into(indent);
            }
        }
    }
    gaps
}

impl Layout<'_, '_> {
    fn normalise(&self) -> bool {
        self.style != Style::AsWritten
    }

    /// The gaps of every token, those before own-line comments without
    /// their indentation (the code after them decides it).
    fn code_gaps(&mut self) -> Vec<Gap> {
        let toks = self.toks;
        let force_blank = forced_blank_lines(toks, &self.orig.breaks);
        let mut gaps = Vec::with_capacity(toks.len());
        let mut stmt = None;
        let mut end_col = 0;
        for (i, tok) in toks.iter().enumerate() {
            let breaks = self.orig.breaks[i];
            let gap_range = self.orig.gap[i].clone();
            let gap = if i == 0 {
                self.first_gap()
            } else if tok.class == Class::Verbatim
                || toks[i - 1].class == Class::Verbatim
                || !plain(self.orig.gap_text(i))
            {
                Gap::Keep(gap_range.clone())
            } else if tok.class == Class::Comment && breaks == 0 {
                if gap_range.is_empty() && self.normalise() {
                    Gap::Space
                } else {
                    Gap::Keep(gap_range.clone())
                }
            } else if breaks > 0 || tok.start.is_some() && self.normalise() {
                let blank = if self.normalise() {
                    let wanted = (breaks >= 2 || force_blank[i]) && !tok.no_blank;
                    if wanted { Blank::One } else { Blank::None }
                } else {
                    match self.orig.line_parts(i).1 {
                        Some(range) => Blank::Kept(range),
                        None => Blank::None,
                    }
                };
                let tail = if self.normalise() || breaks == 0 {
                    gap_range.start..gap_range.start
                } else {
                    self.orig.line_parts(i).0
                };
                let indent = match tok.start {
                    _ if tok.class == Class::Comment => String::new(),
                    Some(Start::Level(level)) => self.units[self.item[i]].indent(level),
                    Some(Start::Column(column)) => " ".repeat(column),
                    None => self.continuation(i, stmt),
                };
                Gap::Line {
                    tail,
                    blank,
                    indent,
                }
            } else if !self.normalise() || tok.keep_gap && self.style == Style::Spaced {
                Gap::Keep(gap_range.clone())
            } else if spacing::spaced(&toks[i - 1], tok, self.style)
                || !spacing::joinable(&toks[i - 1], tok)
            {
                Gap::Space
            } else {
                Gap::None
            };
            // where the token lands
            let kept_break = match &gap {
                Gap::Keep(r) => self
                    .orig
                    .text
                    .get(r.clone())
                    .and_then(|s| line_breaks(s).last().map(|(_, e)| r.start + e)),
                _ => None,
            };
            let (col, starts) = match &gap {
                Gap::Line { indent, .. } => (columns(indent), true),
                Gap::None => (end_col, false),
                Gap::Space => (end_col + 1, false),
                Gap::Keep(r) => match kept_break {
                    Some(after) => (
                        columns(self.orig.text.get(after..r.end).unwrap_or("")),
                        true,
                    ),
                    None => (
                        columns_from(end_col, self.orig.text.get(r.clone()).unwrap_or("")),
                        i == 0,
                    ),
                },
            };
            if let Gap::Line { indent, .. } = &gap {
                self.indent[i] = Some(indent.clone());
            } else if starts {
                let indent = match kept_break {
                    Some(after) => self.orig.text.get(after..gap_range.end).unwrap_or(""),
                    None => "",
                };
                self.indent[i] = Some(indent.to_owned());
            } else if i == 0 {
                // the first token starts the first line, at the column it
                // is given
                self.indent[i] = Some(" ".repeat(col));
            }
            self.col[i] = col;
            self.line_first[i] = if starts || i == 0 {
                i
            } else {
                self.line_first[i - 1]
            };
            end_col = columns_from(col, &tok.text);
            if tok.start.is_some() {
                stmt = Some(i);
                self.anchors.clear();
            } else if let Some(s) = stmt
                && self.is_anchor(i, s)
            {
                self.anchors.entry(self.orig.col[i]).or_insert(i);
            }
            self.stmt[i] = stmt;
            gaps.push(gap);
        }
        gaps
    }

    /// Before the first token: nothing in the styles that normalise; the
    /// original lines before it, as written, otherwise.
    fn first_gap(&self) -> Gap {
        let gap = self.orig.gap[0].clone();
        if self.normalise() {
            return Gap::None;
        }
        let s = self.orig.gap_text(0);
        match line_breaks(s).last() {
            Some((_, end)) if self.toks[0].class != Class::Comment => {
                Gap::Keep(gap.start..gap.start + end)
            }
            Some(_) => Gap::Keep(gap),
            None if self.toks[0].class == Class::Comment => Gap::Keep(gap),
            None => Gap::None,
        }
    }

    /// The indentation that reaches `col`: in a text indented with tabs,
    /// tabs and spaces for the rest; else `base` (an indentation) and
    /// spaces after it, or spaces alone when `col` is left of `base`'s end.
    fn render(&self, col: usize, base: &str) -> String {
        let width = columns(base);
        if self.unit.tabs {
            self.unit.render(col)
        } else if col >= width {
            format!("{base}{}", " ".repeat(col - width))
        } else {
            " ".repeat(col)
        }
    }

    /// Can a continuation line of statement `s` be aligned under token `t`?
    /// The first argument of a call or the first element of a bracket
    /// (after the procedure name or an opening bracket), or the first token
    /// of a line of the statement; right of the statement's start.
    fn is_anchor(&self, t: usize, s: usize) -> bool {
        let tok = &self.toks[t];
        let before = &self.toks[t - 1];
        tok.class != Class::Comment
            && self.orig.col[t] > self.orig.col[s]
            && (before.proc_name || before.class == Class::Open || self.orig.indent[t].is_some())
    }

    /// The indentation of a line that continues the statement `stmt`
    /// (starting with token `i`).
    ///
    /// As written, and in the value of a `PERS` declaration (which the
    /// controller writes in its own form): as far from the statement's
    /// first token as it was (its blanks kept when the statement kept its
    /// own), or under the token it was aligned under if the line before
    /// changed. In the styles that normalise: under the token of the
    /// statement's earlier lines it was aligned under (arguments aligned
    /// under the first one), else one level deeper than the statement; a
    /// line that starts with a closing bracket at the statement's level.
    fn continuation(&self, i: usize, stmt: Option<usize>) -> String {
        let here = self.orig.indent[i].unwrap_or("");
        let Some(s) = stmt else {
            return here.to_owned();
        };
        let base = self.indent[s].as_deref().unwrap_or("");
        // the statement kept its line: the continuation keeps its distance
        let same_distance = || {
            let old = self.orig.indent[s]?;
            let rest = here.strip_prefix(old)?;
            Some(format!("{base}{rest}"))
        };
        let aligned = || {
            self.anchors
                .get(&self.orig.col[i])
                .map(|&t| self.render(self.col[t], base))
        };
        if !self.normalise() || self.toks[i].keep_gap {
            return same_distance().or_else(aligned).unwrap_or_else(|| {
                let distance = self.orig.col[i].saturating_sub(self.orig.col[s]);
                self.render(self.col[s] + distance, base)
            });
        }
        aligned().unwrap_or_else(|| {
            if self.toks[i].class == Class::Close {
                base.to_owned()
            } else {
                self.unit.deeper(base)
            }
        })
    }

    /// The indentation of comments on their own lines, from where the
    /// comment was against the code lines around it (compared in columns):
    ///
    /// - like the next code line: that line's indentation, unless that line
    ///   closes a block (`ENDIF`, `ELSE`, `CASE`...) and the comment was
    ///   also like the line before: then it belongs to the block before,
    ///   and goes where that block's statements go;
    /// - like the code line before: that line's indentation (where the
    ///   statements of its block go if that line opens a block the next
    ///   line closes);
    /// - at column 0: stays there;
    /// - deeper than a next line that closes a block (commented-out code at
    ///   the end of a body): where the statements of that body go;
    /// - deeper than a line before that opens a block, followed by the
    ///   block's first line, which moved: with that line;
    /// - else as far from the next code line as it was;
    /// - but alone in a block, never at the column of the line that opens
    ///   it (formatted again, it would be like that line): inside it.
    fn comment_gaps(&self, gaps: &mut [Gap]) {
        let toks = self.toks;
        let n = toks.len();
        let mut next_code = vec![None; n];
        let mut next = None;
        for i in (0..n).rev() {
            next_code[i] = next;
            if toks[i].class != Class::Comment {
                next = Some(i);
            }
        }
        let mut prev = None;
        for i in 0..n {
            if toks[i].class != Class::Comment {
                prev = Some(i);
                continue;
            }
            let Gap::Line { indent, .. } = &mut gaps[i] else {
                continue;
            };
            let here = self.orig.indent[i].unwrap_or("");
            let next = next_code[i].filter(|&j| toks[j].class != Class::Verbatim);
            let next_indent = next.and_then(|j| self.orig.indent[j]);
            // the first line of the statement before (of its last line if
            // it started after another statement on a line)
            let prev_line = prev.map(|p| match self.stmt[p] {
                Some(s) if self.orig.indent[s].is_some() => s,
                _ => self.orig.line_first[p],
            });
            let same = |other: Option<&str>| other.is_some_and(|o| columns(o) == columns(here));
            let like_prev = prev_line.is_some_and(|p| same(self.orig.indent[p]));
            let prev_indent = || prev_line.and_then(|p| self.indent[p].clone());
            // where the statements of the block the previous line is in go
            let in_block_before = || {
                let s = prev.and_then(|p| self.stmt[p]);
                match s.and_then(|s| toks[s].opens.map(|inside| (s, inside))) {
                    Some((s, inside)) => Some(self.units[self.item[s]].indent(inside)),
                    None => prev_indent(),
                }
            };
            let closes = next.is_some_and(|j| toks[j].closer);
            let opens_before = prev
                .and_then(|p| self.stmt[p])
                .is_some_and(|s| toks[s].opens.is_some());
            let prev_line_indent = prev_line.and_then(|p| self.orig.indent[p]);
            let moved = |j: usize| {
                let old = self.orig.indent[j].map(columns);
                old != self.indent[j].as_deref().map(columns)
            };
            let new = if same(next_indent) && closes && like_prev {
                in_block_before()
            } else if let Some(j) = next
                && same(next_indent)
            {
                self.indent[j].clone()
            } else if like_prev && closes && opens_before {
                // alone in a block that the next line closes
                in_block_before()
            } else if like_prev {
                prev_indent()
            } else if here.is_empty() {
                Some(String::new())
            } else if closes && next_indent.is_some_and(|o| columns(here) > columns(o)) {
                in_block_before()
            } else if let Some(j) = next
                && opens_before
                && moved(j)
                && prev_line_indent.is_some_and(|o| {
                    columns(here) > columns(o)
                        && next_indent.is_some_and(|n| columns(n) > columns(o))
                })
            {
                // inside the block the line before opens, whose first line
                // was re-indented
                self.indent[j].clone()
            } else if let (Some(j), Some(old)) = (next, next_indent) {
                let new_next = self.indent[j].as_deref().unwrap_or("");
                let col = (columns(new_next) + columns(here)).saturating_sub(columns(old));
                Some(self.render(col, new_next))
            } else {
                None
            };
            // Alone in a block, at the column where the line that opens
            // it goes: formatted again, the comment would read as like
            // that line, which puts it inside the block. So it goes there
            // now (formatting twice gives what formatting once gave).
            let new = match new {
                Some(s)
                    if closes
                        && opens_before
                        && prev_line.and_then(|p| self.indent[p].as_deref().map(columns))
                            == Some(columns(&s)) =>
                {
                    in_block_before()
                }
                new => new,
            };
            *indent = new.unwrap_or_else(|| here.to_owned());
        }
    }
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

/// The text of a gap; every line break is written as `line_ending`.
pub(super) fn render_gap(gap: &Gap, text: &str, line_ending: &str, out: &mut String) {
    match gap {
        Gap::None => {}
        Gap::Space => out.push(' '),
        Gap::Keep(range) => push_kept(
            text.get(range.clone()).unwrap_or_default(),
            line_ending,
            out,
        ),
        Gap::Line {
            tail,
            blank,
            indent,
        } => {
            out.push_str(text.get(tail.clone()).unwrap_or_default());
            out.push_str(line_ending);
            match blank {
                Blank::None => {}
                Blank::One => out.push_str(line_ending),
                Blank::Kept(range) => {
                    push_kept(
                        text.get(range.clone()).unwrap_or_default(),
                        line_ending,
                        out,
                    );
                    out.push_str(line_ending);
                }
            }
            out.push_str(indent);
        }
    }
}

/// `s` with every line break written as `line_ending`.
pub(super) fn push_kept(s: &str, line_ending: &str, out: &mut String) {
    let mut from = 0;
    for (start, end) in line_breaks(s) {
        out.push_str(&s[from..start]);
        out.push_str(line_ending);
        from = end;
    }
    out.push_str(&s[from..]);
}
