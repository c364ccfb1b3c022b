//! A large module parsed as two parts at once.
//!
//! Tree-sitter parses a file on one thread; on a 9,000-line module that is
//! more than half of `rapid check`'s time. A module's routines are parsed
//! the same wherever they stand in it, so the later routines can be parsed
//! by a second parser while the first parses the rest: each parser reads
//! only its byte ranges of the text (tree-sitter's included ranges), and
//! the nodes of both trees keep their offsets in the whole text.
//!
//! - The main tree holds everything but [`SplitPlan::chunk`]: the header,
//!   the module data, the first routines, `ENDMODULE`.
//! - The part tree holds the module's header line, the chunk (whole
//!   routines, with whatever lies between them) and `ENDMODULE`.
//!
//! The plan is made from the text's lines alone, before any parse: a
//! routine starts on a line whose first word is `PROC`, `FUNC` or `TRAP`
//! (after `LOCAL`) and ends on the line whose first word closes it. That
//! holds for any module without syntax errors (those words are reserved,
//! strings end with their line and comments are lines). A module with syntax
//! errors, or trees that do not fit together as planned, is parsed again as
//! a whole by the caller ([`crate::task::Unit::from_split`] says so), so
//! that syntax errors are reported as a whole parse finds them.

use std::ops::Range;

use tree_sitter::{Node, Point, Tree};

/// How to parse a text as two parts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SplitPlan {
    /// The byte ranges the main parser reads: everything but `chunk`.
    pub main: Vec<Range<usize>>,
    /// The byte ranges the second parser reads: the module's header, the
    /// chunk, and `ENDMODULE` to the end of the text.
    pub part: Vec<Range<usize>>,
    /// The later routines (whole lines, from the first routine's start to
    /// the last one's end).
    pub chunk: Range<usize>,
}

/// Splits `text` so that the main parser reads about `main_share` (0 to 1)
/// of its bytes. `None` when the text is not one module whose routines can
/// be found line by line, or when fewer than two routines would go to the
/// second parser.
pub fn plan(text: &str, main_share: f64) -> Option<SplitPlan> {
    let mut header_end = None;
    let mut endmodule = None;
    // (start, end) of each routine's lines, in order.
    let mut routines: Vec<(usize, Option<usize>)> = Vec::new();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let start = offset;
        offset += line.len();
        let (first, rest) = first_word(line);
        let (word, rest) = if first.eq_ignore_ascii_case("LOCAL") {
            first_word(rest)
        } else {
            (first, rest)
        };
        let is = |w: &str| word.eq_ignore_ascii_case(w);
        if is("MODULE") {
            if header_end.is_some() || !is_bare_header(rest) {
                return None;
            }
            header_end = Some(offset);
        } else if is("ENDMODULE") {
            if endmodule.is_some() {
                return None;
            }
            endmodule = Some(start);
        } else if is("PROC") || is("FUNC") || is("TRAP") {
            if endmodule.is_some() || routines.last().is_some_and(|r| r.1.is_none()) {
                return None;
            }
            routines.push((start, None));
        } else if is("ENDPROC") || is("ENDFUNC") || is("ENDTRAP") {
            match routines.last_mut() {
                Some(r) if r.1.is_none() => r.1 = Some(offset),
                _ => return None,
            }
        }
    }
    let (header_end, endmodule) = (header_end?, endmodule?);
    let last_end = routines.last()?.1?;
    let target = (text.len() as f64 * main_share.clamp(0.0, 1.0)) as usize;
    let first = routines
        .iter()
        .position(|r| r.0 >= target && r.0 >= header_end)?;
    if routines.len() - first < 2 || last_end > endmodule {
        return None;
    }
    let chunk = routines[first].0..last_end;
    Some(SplitPlan {
        main: vec![0..chunk.start, chunk.end..text.len()],
        part: vec![0..header_end, chunk.clone(), endmodule..text.len()],
        chunk,
    })
}

/// The first word of a line (letters, digits, `_`) and what follows it.
fn first_word(line: &str) -> (&str, &str) {
    let line = line.trim_start();
    let end = line
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(line.len());
    line.split_at(end)
}

/// Is the rest of a `MODULE` line only a name and attributes (so that the
/// second parser, which reads the whole line, reads no declaration)?
fn is_bare_header(rest: &str) -> bool {
    let code = rest.split('!').next().unwrap_or_default();
    let (name, after) = first_word(code);
    let after = after.trim();
    !name.is_empty()
        && (after.is_empty()
            || (after.starts_with('(')
                && after.ends_with(')')
                && after[1..after.len() - 1]
                    .chars()
                    .all(|c| c.is_ascii_alphabetic() || c == ',' || c.is_whitespace())))
}

/// Parses only the byte ranges `ranges` of `text` (sorted, not
/// overlapping); nodes keep their offsets in the whole text.
pub fn parse_ranges(text: &str, ranges: &[Range<usize>]) -> Option<Tree> {
    let mut points = Points::new(text);
    let ranges: Vec<tree_sitter::Range> = ranges
        .iter()
        .map(|r| tree_sitter::Range {
            start_byte: r.start,
            end_byte: r.end,
            start_point: points.at(r.start),
            end_point: points.at(r.end),
        })
        .collect();
    let mut parser = crate::syntax::parser();
    parser.set_included_ranges(&ranges).ok()?;
    crate::syntax::parse(&mut parser, text, None)
}

/// Rows and columns of increasing offsets, from one pass over the text.
struct Points<'a> {
    text: &'a str,
    offset: usize,
    row: usize,
    line_start: usize,
}

impl<'a> Points<'a> {
    fn new(text: &'a str) -> Self {
        Points {
            text,
            offset: 0,
            row: 0,
            line_start: 0,
        }
    }

    fn at(&mut self, offset: usize) -> Point {
        let offset = offset.min(self.text.len());
        if offset > self.offset {
            let bytes = &self.text.as_bytes()[self.offset..offset];
            for (i, b) in bytes.iter().enumerate() {
                if *b == b'\n' {
                    self.row += 1;
                    self.line_start = self.offset + i + 1;
                }
            }
            self.offset = offset;
        }
        Point::new(self.row, offset.saturating_sub(self.line_start))
    }
}

/// The module of a tree when it is the tree's only top-level node and has
/// no syntax error.
pub(crate) fn sole_module(tree: &Tree) -> Option<Node<'_>> {
    let root = tree.root_node();
    if root.has_error() || root.named_child_count() != 1 {
        return None;
    }
    root.named_child(0).filter(|m| m.kind() == "module")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module(routines: usize) -> String {
        let mut text = String::from("%%%\n  VERSION:1\n%%%\nMODULE Big(SYSMODULE)\n  VAR num n;\n");
        for i in 0..routines {
            text.push_str(&format!(
                "  ! routine {i}\n  {}PROC p{i}()\n    n := n + {i};\n  ENDPROC\n",
                if i % 2 == 0 { "LOCAL " } else { "" }
            ));
        }
        text.push_str("ENDMODULE\n");
        text
    }

    #[test]
    fn the_later_routines_go_to_the_second_parser() {
        let text = module(6);
        let plan = plan(&text, 0.5).expect("a plan");
        let chunk = &text[plan.chunk.clone()];
        assert!(chunk.trim_start().starts_with("PROC p3()") || chunk.contains("PROC p3()"));
        assert!(chunk.trim_end().ends_with("ENDPROC"), "{chunk}");
        assert!(!chunk.contains("p2()"), "{chunk}");
        assert_eq!(
            plan.main,
            vec![0..plan.chunk.start, plan.chunk.end..text.len()]
        );
        let header = &text[plan.part[0].clone()];
        assert!(header.ends_with("MODULE Big(SYSMODULE)\n"), "{header}");
        assert_eq!(&text[plan.part[2].clone()], "ENDMODULE\n");
    }

    #[test]
    fn both_trees_hold_the_nodes_of_a_whole_parse() {
        let text = module(9);
        let plan = plan(&text, 0.4).expect("a plan");
        let whole = crate::syntax::parse(&mut crate::syntax::parser(), &text, None).expect("tree");
        let main = parse_ranges(&text, &plan.main).expect("main");
        let part = parse_ranges(&text, &plan.part).expect("part");
        let body = |t: &Tree| {
            let m = sole_module(t).expect("one module without errors");
            crate::syntax_util::fields(m, "body")
                .into_iter()
                .map(|n| (n.byte_range(), n.to_sexp()))
                .collect::<Vec<_>>()
        };
        let mut split = body(&main);
        split.extend(body(&part));
        split.sort_by_key(|(r, _)| r.start);
        assert_eq!(split, body(&whole));
    }

    #[test]
    fn texts_that_cannot_be_split_by_lines() {
        let cases = [
            // a routine without its end, and one inside another
            "MODULE m\n  PROC a()\n  PROC b()\n  ENDPROC\n  ENDPROC\nENDMODULE\n".to_owned(),
            // two modules
            format!("{}{}", module(4), module(4)),
            // a declaration on the MODULE line
            module(6).replace("MODULE Big(SYSMODULE)", "MODULE Big VAR num k;"),
            // no ENDMODULE
            module(6).replace("ENDMODULE", ""),
            // too few routines to share
            module(2),
        ];
        for text in &cases {
            assert_eq!(plan(text, 0.5), None, "{text}");
        }
    }
}
