//! A large module parsed as two parts at once.
//!
//! Tree-sitter parses a file on one thread; on a 9,000-line module that is
//! more than half of `rapid check`'s time. A module's declarations, and a
//! routine's statements, are parsed the same wherever they stand, so the
//! later ones can be parsed by a second parser while the first parses the
//! rest: each parser reads only its byte ranges of the text (tree-sitter's
//! included ranges), and the nodes of both trees keep their offsets in the
//! whole text.
//!
//! - The main tree holds everything but [`SplitPlan::chunk`].
//! - The part tree holds the module's header line, the chunk and
//!   `ENDMODULE`; the chunk is either the module's later declarations (data
//!   and routines, [`PartKind::Declarations`]) or the later statements of
//!   one long routine, read with that routine's first and last lines
//!   ([`PartKind::Statements`]).
//!
//! The plan is made from the text's lines alone, before any parse: a
//! routine starts on a line whose first word is `PROC`, `FUNC` or `TRAP`
//! (after `LOCAL`) and ends on the line whose first word closes it; a
//! declaration or a statement starts on a line after one that ended the
//! previous one (with `;`), blocks counted by their opening and closing
//! words. That holds for any module without syntax errors (those words are
//! reserved, strings end with their line and comments are lines); where the
//! counting loses track, that routine is not split. A module with syntax
//! errors, or trees that do not fit together as planned, is parsed again as
//! a whole ([`crate::task::Unit::from_split`] does so), so that syntax
//! errors are reported as a whole parse finds them.

use std::ops::Range;

use tree_sitter::{Node, Point, Tree};

/// How to parse a text as two parts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SplitPlan {
    /// The byte ranges the main parser reads: everything but `chunk`.
    pub main: Vec<Range<usize>>,
    /// The byte ranges the second parser reads: the module's header, the
    /// chunk (with, for statements, their routine's first and last lines),
    /// and `ENDMODULE` to the end of the text.
    pub part: Vec<Range<usize>>,
    /// The text the second parser reads that the main one does not (whole
    /// lines).
    pub chunk: Range<usize>,
    /// What the chunk holds.
    pub kind: PartKind,
}

/// What the second parser of a [`SplitPlan`] reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PartKind {
    /// The module's later declarations (data and routines), to its end.
    Declarations,
    /// The later statements of one routine (a long generated routine): the
    /// second tree holds that routine again, with only those statements.
    Statements,
}

/// A routine of the module, from its lines.
struct RoutineLines {
    /// The start of its first line.
    start: usize,
    /// The end of its first line (the header: name and parameters).
    header_end: usize,
    /// The start of the line that ends its statements (its error, backward
    /// or undo handler, or its closing line).
    body_end: Option<usize>,
    /// The closing line (`ENDPROC`, ...).
    end_line: Option<Range<usize>>,
    /// Lines where a statement of its body (not of a nested block) starts.
    statements: Vec<usize>,
    /// The nesting of compound statements lost track: no statement split.
    unsure: bool,
}

/// Splits `text` so that the main parser reads about `main_share` (0 to 1)
/// of its bytes: at a declaration of the module, or at a statement of a
/// long routine, whichever comes nearer. `None` when the text is not one
/// module whose routines can be found line by line, or when either parser
/// would get less than an eighth of the text.
pub fn plan(text: &str, main_share: f64) -> Option<SplitPlan> {
    let mut header_end = None;
    let mut endmodule = None;
    let mut routines: Vec<RoutineLines> = Vec::new();
    // Inside a routine: the nesting of compound statements, and whether
    // the last line of code ended a statement.
    let mut depth = 0usize;
    let mut after_statement = false;
    // Outside routines: where a module data declaration starts a line after
    // the end of the previous declaration.
    let mut data_starts: Vec<usize> = Vec::new();
    let mut after_declaration = false;
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let start = offset;
        offset += line.len();
        let (first, rest) = first_word(line);
        let (word, rest) =
            if first.eq_ignore_ascii_case("LOCAL") || first.eq_ignore_ascii_case("TASK") {
                first_word(rest)
            } else {
                (first, rest)
            };
        let is = |w: &str| word.eq_ignore_ascii_case(w);
        let open = routines.last_mut().filter(|r| r.end_line.is_none());
        if let Some(r) = open {
            if is("ENDPROC") || is("ENDFUNC") || is("ENDTRAP") {
                r.body_end.get_or_insert(start);
                r.end_line = Some(start..offset);
                after_declaration = true;
                continue;
            }
            if r.body_end.is_some() || r.unsure {
                continue;
            }
            let code = code_of(line);
            if code.is_empty() {
                continue;
            }
            if depth == 0 && (is("ERROR") || is("BACKWARD") || is("UNDO")) {
                r.body_end = Some(start);
                continue;
            }
            let declaration = ["VAR", "PERS", "CONST", "TASK"].iter().any(|w| is(w));
            if depth == 0 && after_statement && !declaration && !word.is_empty() {
                r.statements.push(start);
            }
            if is("FOR") || is("WHILE") || is("TEST") || (is("IF") && ends_with_word(code, "THEN"))
            {
                depth += 1;
            } else if is("ENDIF") || is("ENDFOR") || is("ENDWHILE") || is("ENDTEST") {
                match depth.checked_sub(1) {
                    Some(d) => depth = d,
                    None => r.unsure = true,
                }
            }
            after_statement = code.ends_with(';')
                || code.ends_with(':')
                || ["ENDIF", "ENDFOR", "ENDWHILE", "ENDTEST"]
                    .iter()
                    .any(|w| is(w));
            continue;
        }
        let code = code_of(line);
        if is("MODULE") {
            if header_end.is_some() || !is_bare_header(rest) {
                return None;
            }
            header_end = Some(offset);
            after_declaration = true;
        } else if is("ENDMODULE") {
            if endmodule.is_some() {
                return None;
            }
            endmodule = Some(start);
        } else if is("PROC") || is("FUNC") || is("TRAP") {
            if endmodule.is_some() || header_end.is_none() {
                return None;
            }
            // A header that does not end its line (parameters over several
            // lines): no split between its statements.
            let complete = code.ends_with(')') || is("TRAP");
            routines.push(RoutineLines {
                start,
                header_end: offset,
                body_end: None,
                end_line: None,
                statements: Vec::new(),
                unsure: !complete,
            });
            depth = 0;
            after_statement = true;
        } else if is("ENDPROC") || is("ENDFUNC") || is("ENDTRAP") {
            return None;
        } else if is("VAR") || is("PERS") || is("CONST") {
            if after_declaration && header_end.is_some() && endmodule.is_none() {
                data_starts.push(start);
            }
            after_declaration = code.ends_with(';');
        } else if !code.is_empty() {
            after_declaration = code.ends_with(';') || is("ENDRECORD");
        }
    }
    let (header_end, endmodule) = (header_end?, endmodule?);
    if routines.iter().any(|r| r.end_line.is_none()) {
        return None;
    }
    // The second parser's share of the bytes, and the split that comes
    // nearest to it: at a module declaration (data or routine: the chunk
    // runs to `ENDMODULE`) or at a statement of a long routine (to that
    // routine's last statement).
    let want = (text.len() as f64 * (1.0 - main_share.clamp(0.0, 1.0))) as usize;
    let declaration_splits = routines
        .iter()
        .map(|r| r.start)
        .chain(data_starts)
        .filter(|&at| at > header_end)
        .map(|at| (at..endmodule, None));
    let statement_splits = routines
        .iter()
        .filter(|r| !r.unsure)
        .filter_map(|r| Some((r, r.body_end?)))
        .flat_map(|(r, end)| {
            r.statements
                .iter()
                .skip(1)
                .filter(move |&&at| at < end)
                .map(move |&at| (at..end, Some(r)))
        });
    let (chunk, routine) = declaration_splits
        .chain(statement_splits)
        .min_by_key(|(chunk, _)| chunk.len().abs_diff(want))?;
    let (part, kind) = match routine {
        Some(r) => (
            vec![
                0..header_end,
                r.start..r.header_end,
                chunk.clone(),
                r.end_line.clone()?,
                endmodule..text.len(),
            ],
            PartKind::Statements,
        ),
        None => (
            vec![0..header_end, chunk.clone(), endmodule..text.len()],
            PartKind::Declarations,
        ),
    };
    // Both parsers must have a good share of the work.
    let least = text.len() / 8;
    if chunk.len() < least || text.len() - chunk.len() < least {
        return None;
    }
    Some(SplitPlan {
        main: vec![0..chunk.start, chunk.end..text.len()],
        part,
        chunk,
        kind,
    })
}

/// A line without its comment and surrounding blanks (a `!` inside a string
/// cuts the line short: the line is then taken for one that does not end a
/// statement, which only loses a place to split).
fn code_of(line: &str) -> &str {
    line.split('!').next().unwrap_or_default().trim()
}

/// Does `code` end with the keyword `word` (case-insensitive)?
fn ends_with_word(code: &str, word: &str) -> bool {
    code.len() >= word.len()
        && code.is_char_boundary(code.len() - word.len())
        && code[code.len() - word.len()..].eq_ignore_ascii_case(word)
        && !code[..code.len() - word.len()]
            .ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_')
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
    // Adjacent ranges as one.
    let mut merged: Vec<Range<usize>> = Vec::with_capacity(ranges.len());
    for r in ranges {
        match merged.last_mut() {
            Some(last) if last.end == r.start => last.end = r.end,
            _ => merged.push(r.clone()),
        }
    }
    let ranges: Vec<tree_sitter::Range> = merged
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
/// Rows count `\n` only, as tree-sitter's lexer does (`text::LineIndex`
/// also breaks lines at a lone `\r`).
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

/// The module of a tree when it is the tree's only top-level node besides
/// comments and the tree has no syntax error.
pub(crate) fn sole_module(tree: &Tree) -> Option<Node<'_>> {
    let root = tree.root_node();
    if root.has_error() {
        return None;
    }
    let mut cursor = root.walk();
    let mut top = root
        .named_children(&mut cursor)
        .filter(|n| n.kind() != "comment");
    let module = top.next().filter(|m| m.kind() == "module")?;
    top.next().is_none().then_some(module)
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
    fn comments_around_the_module_do_not_count() {
        let text = format!("! written by a tool\n{}! the end\n", module(6));
        let plan = plan(&text, 0.5).expect("a plan");
        let main = parse_ranges(&text, &plan.main).expect("main");
        let part = parse_ranges(&text, &plan.part).expect("part");
        assert!(sole_module(&main).is_some() && sole_module(&part).is_some());
    }

    /// The range and the tree of each child of `node` in field `body`.
    fn body_of(node: Node<'_>) -> Vec<(Range<usize>, String)> {
        crate::syntax_util::fields(node, "body")
            .into_iter()
            .map(|n| (n.byte_range(), n.to_sexp()))
            .collect()
    }

    /// The whole parse of `text`, and the two trees of its plan.
    fn three_parses(text: &str, main_share: f64) -> [Tree; 3] {
        let plan = plan(text, main_share).expect("a plan");
        let whole = crate::syntax::parse(&mut crate::syntax::parser(), text, None).expect("tree");
        let main = parse_ranges(text, &plan.main).expect("main");
        let part = parse_ranges(text, &plan.part).expect("part");
        [whole, main, part]
    }

    #[test]
    fn the_later_routines_go_to_the_second_parser() {
        let text = module(6);
        let plan = plan(&text, 0.5).expect("a plan");
        assert_eq!(plan.kind, PartKind::Declarations);
        let chunk = &text[plan.chunk.clone()];
        // From the routine nearest the middle to the last one.
        assert!(
            chunk.starts_with("  PROC p3()") || chunk.starts_with("  LOCAL PROC p2()"),
            "{chunk}"
        );
        assert!(
            chunk.ends_with("ENDPROC\n") && chunk.contains("PROC p5()"),
            "{chunk}"
        );
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
        let [whole, main, part] = three_parses(&text, 0.4);
        let body = |t: &Tree| body_of(sole_module(t).expect("one module without errors"));
        let mut split = body(&main);
        split.extend(body(&part));
        split.sort_by_key(|(r, _)| r.start);
        assert_eq!(split, body(&whole));
    }

    #[test]
    fn a_data_module_splits_between_its_declarations() {
        let mut text = String::from("MODULE Points\n");
        for i in 0..40 {
            text.push_str(&format!(
                "  CONST robtarget p{i} := [[{i},0,0],[1,0,0,0],[0,0,0,0],\n    [9E9,9E9,9E9,9E9,9E9,9E9]];\n"
            ));
        }
        text.push_str("ENDMODULE\n");
        let plan = plan(&text, 0.5).expect("a plan");
        assert_eq!(plan.kind, PartKind::Declarations);
        assert!(text[plan.chunk.clone()].starts_with("  CONST robtarget p20 :="));
        let whole = crate::syntax::parse(&mut crate::syntax::parser(), &text, None).expect("tree");
        let main = parse_ranges(&text, &plan.main).expect("main");
        let part = parse_ranges(&text, &plan.part).expect("part");
        let body =
            |t: &Tree| crate::syntax_util::fields(sole_module(t).expect("module"), "body").len();
        assert_eq!((body(&main), body(&part), body(&whole)), (20, 20, 40));
    }

    /// One long routine with nested blocks, labels and an error handler.
    fn long_routine(statements: usize) -> String {
        let mut text = String::from("MODULE Gen\n  VAR num n;\n  PROC main()\n    VAR num i;\n");
        for i in 0..statements {
            text.push_str(&match i % 4 {
                0 => format!("    n := n + {i};\n"),
                1 => format!("    IF n > {i} THEN\n      n := 0;\n    ELSE\n      n := 1;\n    ENDIF\n"),
                2 => format!("    l{i}:\n    FOR j FROM 1 TO 3 DO\n      n := n * j; ! step;\n    ENDFOR\n"),
                _ => format!("    IF n = 0 n := {i};\n    MoveL Offs(p,\n      0, 0, {i}), v100, fine, tool0;\n"),
            });
        }
        text.push_str("  ERROR\n    RETURN;\n  ENDPROC\nENDMODULE\n");
        text
    }

    #[test]
    fn a_long_routine_splits_between_its_statements() {
        let text = long_routine(40);
        let plan = plan(&text, 0.5).expect("a plan");
        assert_eq!(plan.kind, PartKind::Statements);
        let chunk = &text[plan.chunk.clone()];
        assert!(chunk.ends_with(";\n"), "{chunk}");
        assert!(!chunk.contains("ERROR"), "{chunk}");
        // It starts where the statement before it ended.
        let before = text[..plan.chunk.start].trim_end();
        assert!(
            [";", ":", "ENDIF", "ENDFOR"]
                .iter()
                .any(|e| before.ends_with(e)),
            "{before}"
        );
        let first = chunk.split_whitespace().next().unwrap_or_default();
        assert!(
            !["ELSE", "ENDIF", "ENDFOR", "ERROR"].contains(&first),
            "{chunk}"
        );
        assert_eq!(&text[plan.part[1].clone()], "  PROC main()\n");
        assert_eq!(&text[plan.part[3].clone()], "  ENDPROC\n");
    }

    #[test]
    fn both_trees_hold_the_statements_of_a_whole_parse() {
        let text = long_routine(40);
        let [whole, main, part] = three_parses(&text, 0.5);
        let statements = |t: &Tree| {
            let m = sole_module(t).expect("one module without errors");
            let routine = crate::syntax_util::fields(m, "body")
                .into_iter()
                .find(|n| n.kind() == "procedure_declaration")
                .expect("the routine");
            body_of(routine)
        };
        let mut split = statements(&main);
        split.extend(statements(&part));
        assert_eq!(split, statements(&whole));
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
            // no declaration
            "MODULE m\n  ! nothing yet\nENDMODULE\n".to_owned(),
            // an IF whose condition goes over two lines, then ENDIF: the
            // nesting is lost, and the routine is the whole module
            long_routine(40).replace(
                "    IF n > 5 THEN\n",
                "    IF n > 5 AND\n      n < 9 THEN\n",
            ),
            // parameters over two lines
            long_routine(40).replace("PROC main()", "PROC main(\n    num a)"),
        ];
        for text in &cases {
            assert_eq!(plan(text, 0.5), None, "{text}");
        }
    }
}
