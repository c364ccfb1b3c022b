//! The typos people make most, told where they are: a missing `,` between
//! two arguments, a `FOR` or `WHILE` line without `DO`, an `IF` or
//! `ELSEIF` line without `THEN`, a string without its closing `"`, a
//! missing `;` at the end of a line. The parser's error recovery puts the
//! error elsewhere (on the next line, on the `ENDIF` that no longer fits,
//! around a whole routine); these read the error with its surroundings and
//! say what is wrong where it is wrong. Anything else keeps the generic
//! message of [`super::error_diagnostic`].

use std::ops::Range;

use tree_sitter::{Language, Node};

use crate::diagnostic::Diagnostic;
use crate::rules::{missing_token, syntax_error};
use crate::syntax::{field, kind};

/// Strings that a line opens and does not close (RAPID strings end on the
/// line they start): the opening quote and the end of its line, for lines
/// that hold a syntax error (so text the parser accepted is never blamed).
pub(super) fn unterminated_strings(text: &str, errors: &[Range<usize>]) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let mut line_start = 0;
    for line in text.split_inclusive('\n') {
        let body = line.trim_end_matches(['\n', '\r']);
        let mut open = None;
        let bytes = body.as_bytes();
        let mut i = 0;
        while i < bytes.len() {
            match (bytes[i], open) {
                (b'!', None) => break,
                (b'"', None) => open = Some(i),
                // `""` inside a string is a quote.
                (b'"', Some(_)) if bytes.get(i + 1) == Some(&b'"') => i += 1,
                (b'"', Some(_)) => open = None,
                _ => {}
            }
            i += 1;
        }
        if let Some(quote) = open {
            let at = line_start + quote;
            let end = line_start + body.len();
            if errors
                .iter()
                .any(|e| e.start <= end && at < e.end.max(e.start + 1))
            {
                out.push(Diagnostic::new(
                    &syntax_error::RULE,
                    at..end,
                    "this string has no closing `\"`: a string ends on the line it starts",
                ));
            }
        }
        line_start += line.len();
    }
    out
}

/// A message for a common typo that explains the error node `error`, if
/// one does.
pub(super) fn explain(error: Node<'_>, text: &str, language: &Language) -> Option<Diagnostic> {
    missing_keyword(error, text)
        .or_else(|| missing_then_before(error, text))
        .or_else(|| missing_comma(error, text))
        .or_else(|| missing_semicolon(error, language))
}

/// The end of a line's code: before a trailing comment and blanks.
fn code_end(text: &str, at: usize) -> usize {
    let start = text[..at.min(text.len())].rfind('\n').map_or(0, |i| i + 1);
    let end = text[start..]
        .find(['\n', '\r'])
        .map_or(text.len(), |i| start + i);
    let line = &text[start..end];
    let mut in_string = false;
    let mut code = line.len();
    for (i, c) in line.char_indices() {
        match c {
            '"' => in_string = !in_string,
            '!' if !in_string => {
                code = i;
                break;
            }
            _ => {}
        }
    }
    start + line[..code].trim_end().len()
}

/// The words of the line around `at`, lowercase, outside comments.
fn line_words(text: &str, at: usize) -> Vec<String> {
    let start = text[..at.min(text.len())].rfind('\n').map_or(0, |i| i + 1);
    let end = code_end(text, at);
    text.get(start..end)
        .unwrap_or_default()
        .split(|c: char| !crate::names::is_name_char(c))
        .filter(|w| !w.is_empty())
        .map(crate::names::fold)
        .collect()
}

fn first_leaf(node: Node<'_>) -> Option<Node<'_>> {
    let mut node = node.child(0)?;
    while let Some(child) = node.child(0) {
        node = child;
    }
    Some(node)
}

fn missing(at: usize, message: String) -> Diagnostic {
    Diagnostic::new(&missing_token::RULE, at..at, message)
}

/// `FOR i FROM 1 TO 10` or `WHILE cond` without `DO`, `ELSEIF cond` without
/// `THEN`: the error starts with the keyword and its line lacks the other.
fn missing_keyword(error: Node<'_>, text: &str) -> Option<Diagnostic> {
    let lead = first_leaf(error)?;
    let (opener, wanted) = match lead.kind() {
        "for" => ("FOR", "do"),
        "while" => ("WHILE", "do"),
        "elseif" => ("ELSEIF", "then"),
        _ => return None,
    };
    let words = line_words(text, lead.start_byte());
    if words.iter().any(|w| w == wanted) {
        return None;
    }
    let at = code_end(text, lead.start_byte());
    Some(missing(
        at,
        format!(
            "missing `{}` at the end of the `{opener}` line",
            wanted.to_ascii_uppercase()
        ),
    ))
}

/// An `IF cond` line without `THEN`: the parser reads `IF cond` and the
/// next line as a one-line `IF`, and fails at the `ELSE`, `ELSEIF` or
/// `ENDIF` that follows.
fn missing_then_before(error: Node<'_>, text: &str) -> Option<Diagnostic> {
    let lead = first_leaf(error)?;
    if !matches!(lead.kind(), "endif" | "else" | "elseif") {
        return None;
    }
    let mut at = error.prev_named_sibling();
    while let Some(n) = at {
        if n.kind() != kind::COMMENT {
            break;
        }
        at = n.prev_named_sibling();
    }
    let compact = at.filter(|n| n.kind() == kind::COMPACT_IF_STATEMENT)?;
    let condition = compact.child_by_field_name(field::CONDITION)?;
    let body = compact.child_by_field_name(field::BODY)?;
    if body.start_position().row <= condition.end_position().row {
        return None;
    }
    Some(missing(
        code_end(text, condition.end_byte().saturating_sub(1)),
        "missing `THEN` at the end of the `IF` line".to_owned(),
    ))
}

/// Is `leaf` part of a statement or declaration that ends with `;`?
fn in_statement(leaf: Node<'_>) -> bool {
    let mut at = leaf.parent();
    while let Some(n) = at {
        match n.kind() {
            kind::DATA_DECLARATION
            | kind::RECORD_COMPONENT
            | kind::ALIAS_DECLARATION
            | kind::ASSIGNMENT
            | kind::PROCEDURE_CALL
            | kind::GOTO_STATEMENT
            | kind::RETURN_STATEMENT
            | kind::RAISE_STATEMENT
            | kind::CONNECT_STATEMENT => return true,
            kind::MODULE
            | kind::PROCEDURE_DECLARATION
            | kind::FUNCTION_DECLARATION
            | kind::TRAP_DECLARATION
            | kind::SOURCE_FILE => return false,
            _ => at = n.parent(),
        }
    }
    false
}

/// Can a token of this kind end a statement (before its `;`)?
fn ends_statement(node: Node<'_>) -> bool {
    ends_argument(node) || node.kind() == "%"
}

/// Can a token of this kind end an argument?
fn ends_argument(node: Node<'_>) -> bool {
    matches!(
        node.kind(),
        kind::IDENTIFIER | kind::NUMBER | kind::STRING | "\"" | ")" | "]" | "}" | "true" | "false"
    )
}

/// Two arguments side by side: `MoveL p10 v100, ...`, `Max(1 2)`. The
/// error holds one argument, written right after the previous one or right
/// before the next, on the same line, with only blanks between.
fn missing_comma(error: Node<'_>, text: &str) -> Option<Diagnostic> {
    let parent = error.parent()?;
    if !matches!(
        parent.kind(),
        kind::PROCEDURE_CALL | kind::FUNCTION_CALL | kind::ARGUMENT_LIST | kind::ARGUMENT
    ) || error.named_child_count() != 1
    {
        return None;
    }
    let word = |r: Range<usize>| -> String {
        let s = text.get(r).unwrap_or_default();
        let s: String = s.chars().take(30).collect();
        s.split_whitespace().collect::<Vec<_>>().join(" ")
    };
    let blank = |r: Range<usize>| {
        r.start < r.end
            && text
                .get(r)
                .is_some_and(|s| s.chars().all(|c| c == ' ' || c == '\t'))
    };
    // After the previous argument (not the routine's name, nor a token that
    // starts a line without a `,` at the end of the line before: that is a
    // statement of its own after a missing `;`).
    if let Some(prev) = super::previous_leaf(error)
        && ends_argument(prev)
        && !is_routine_name(prev)
        && !starts_statement_line(prev)
        && blank(prev.end_byte()..error.start_byte())
    {
        return Some(comma(
            prev.end_byte()..error.start_byte(),
            &word(argument_around(prev).byte_range()),
            &word(error.byte_range()),
        ));
    }
    // Before the next argument (the error not first on a line of its own).
    let next = error.next_sibling()?;
    if matches!(next.kind(), kind::ARGUMENT_LIST | kind::ARGUMENT)
        && !first_leaf(error).is_some_and(starts_statement_line)
        && ends_argument(super::last_leaf(error))
        && blank(error.end_byte()..next.start_byte())
    {
        let first = next.named_child(0).unwrap_or(next);
        let first = if first.kind() == kind::ARGUMENT {
            first.named_child(0).unwrap_or(first)
        } else {
            first
        };
        return Some(comma(
            error.end_byte()..next.start_byte(),
            &word(error.byte_range()),
            &word(first.byte_range()),
        ));
    }
    None
}

/// Does `leaf` start its line, after a line that does not end with `,`
/// (the line before ends a statement, or should)?
fn starts_statement_line(leaf: Node<'_>) -> bool {
    super::previous_leaf(leaf).is_some_and(|before| {
        before.end_position().row < leaf.start_position().row && before.kind() != ","
    })
}

fn comma(gap: Range<usize>, before: &str, after: &str) -> Diagnostic {
    Diagnostic::new(
        &missing_token::RULE,
        gap,
        format!("missing `,` between the arguments `{before}` and `{after}`"),
    )
}

fn is_routine_name(leaf: Node<'_>) -> bool {
    leaf.parent().is_some_and(|p| {
        matches!(p.kind(), kind::PROCEDURE_CALL | kind::FUNCTION_CALL)
            && p.child_by_field_name(field::NAME)
                .is_some_and(|n| n.id() == leaf.id())
    })
}

/// The argument a leaf belongs to (the leaf itself outside one).
fn argument_around(leaf: Node<'_>) -> Node<'_> {
    let mut at = leaf;
    while let Some(p) = at.parent() {
        if p.kind() == kind::ARGUMENT {
            return p;
        }
        if matches!(
            p.kind(),
            kind::ARGUMENT_LIST | kind::PROCEDURE_CALL | kind::FUNCTION_CALL
        ) {
            break;
        }
        at = p;
    }
    at
}

/// A statement whose `;` is missing at the end of its line: the parser
/// goes on into the next line and fails there, at its start or after
/// taking its first words as more arguments. Told at the end of the line
/// where the `;` belongs.
fn missing_semicolon(error: Node<'_>, language: &Language) -> Option<Diagnostic> {
    let mut prev = super::previous_leaf(error)?;
    if error.start_position().row == prev.end_position().row {
        // The error is not first on its line: the line's first token, if
        // the statement of the line before swallowed it.
        let mut first = prev;
        while let Some(before) = super::previous_leaf(first)
            && before.end_position().row == error.start_position().row
        {
            first = before;
        }
        if first.start_position().row != error.start_position().row {
            return None;
        }
        prev = super::previous_leaf(first)?;
        if !starts_statement_line(first) {
            return None;
        }
    }
    if error.start_position().row <= prev.end_position().row
        || !ends_statement(prev)
        || !in_statement(prev)
    {
        return None;
    }
    let state = prev.next_parse_state();
    let semicolon = language
        .lookahead_iterator(state)?
        .any(|id| language.node_kind_for_id(id) == Some(";"));
    if !semicolon {
        return None;
    }
    Some(missing(
        prev.end_byte(),
        "missing `;` at the end of the line".to_owned(),
    ))
}

/// A statement broken off at the end of its line before a line that no
/// statement continues (`MoveL p10, v100, z10, tool0\` and `ENDPROC`
/// after it): the grammar closes what is open there and only the `;` is
/// missing (see `_incomplete` in the grammar). Told at what was left
/// open: an optional argument's `\`, a `:=`, a `,`, an aggregate's `[`.
/// `None` for a plain missing `;` (and for a string left open, which
/// [`unterminated_strings`] tells).
pub(super) fn broken_off(missing: Node<'_>, text: &str) -> Option<Diagnostic> {
    if missing.kind() != ";" {
        return None;
    }
    let before = text.get(..missing.start_byte())?.trim_end();
    let end = before.len();
    let said = |at: usize, len: usize, message: &str| {
        Some(Diagnostic::new(
            &syntax_error::RULE,
            at..at + len,
            format!("{message}; the statement is not finished (its `;` is missing too)"),
        ))
    };
    if before.ends_with('\\') {
        return said(
            end - 1,
            1,
            "the name of an optional argument is missing after `\\`",
        );
    }
    if before.ends_with(":=") {
        return said(end - 2, 2, "a value is missing after `:=`");
    }
    if before.ends_with(',') {
        // an argument, or an aggregate's element: the innermost bracket says
        let prev = super::previous_leaf(missing)?;
        let in_aggregate = std::iter::successors(Some(prev), |n| n.parent())
            .take_while(|n| !crate::syntax_util::is_simple_statement(n.kind()))
            .any(|n| n.kind() == kind::AGGREGATE);
        if !in_aggregate {
            return said(end - 1, 1, "an argument is missing after `,`");
        }
    }
    // an aggregate that the end of the line closed
    let prev = super::previous_leaf(missing)?;
    let open = std::iter::successors(Some(prev), |n| n.parent())
        .take_while(|n| !crate::syntax_util::is_simple_statement(n.kind()))
        .filter(|n| n.kind() == kind::AGGREGATE)
        .find(|n| text.get(n.byte_range()).is_some_and(|t| !t.ends_with(']')))?;
    said(open.start_byte(), 1, "this aggregate has no closing `]`")
}

#[cfg(test)]
mod tests {
    use crate::syntax::{parse, parser, syntax_diagnostics};

    /// (line:column, code, message) of the syntax diagnostics of `body` in
    /// a routine (lines count from the routine's first statement, 1).
    fn told(body: &str) -> Vec<(String, &'static str, String)> {
        let head = "MODULE M\n  VAR num n;\n  PROC main()\n";
        let text = format!("{head}{body}\n  ENDPROC\nENDMODULE\n");
        let tree = parse(&mut parser(), &text, None).expect("a tree");
        let index = crate::text::LineIndex::new(&text);
        syntax_diagnostics(&tree, &text)
            .into_iter()
            .map(|d| {
                let at = index.line_col(d.range.start);
                (
                    format!("{}:{}", at.line - 2, at.col + 1),
                    d.rule.code,
                    d.message,
                )
            })
            .collect()
    }

    fn one(body: &str) -> (String, &'static str, String) {
        let all = told(body);
        assert_eq!(all.len(), 1, "{body}: {all:?}");
        all.into_iter().next().expect("one")
    }

    #[test]
    fn common_typos_are_told_where_they_are() {
        let cases = [
            (
                "    MoveL p10 v100, z10, tool0;",
                "1:14",
                "E002",
                "missing `,` between the arguments `p10` and `v100`",
            ),
            (
                "    MoveL p10, v100 z10, tool0;",
                "1:20",
                "E002",
                "missing `,` between the arguments `v100` and `z10`",
            ),
            (
                "    n := Max(1 2);",
                "1:15",
                "E002",
                "missing `,` between the arguments `1` and `2`",
            ),
            (
                "    FOR i FROM 1 TO 10 ! count\n      n := i;\n    ENDFOR",
                "1:23",
                "E002",
                "missing `DO` at the end of the `FOR` line",
            ),
            (
                "    WHILE n > 1\n      n := n - 1;\n    ENDWHILE",
                "1:16",
                "E002",
                "missing `DO` at the end of the `WHILE` line",
            ),
            (
                "    IF n > 1\n      n := 2;\n    ENDIF",
                "1:13",
                "E002",
                "missing `THEN` at the end of the `IF` line",
            ),
            (
                "    IF n > 1 THEN\n      n := 2;\n    ELSEIF n > 3\n      n := 1;\n    ENDIF",
                "3:17",
                "E002",
                "missing `THEN` at the end of the `ELSEIF` line",
            ),
            (
                "    TPWrite \"hello;\n    n := 1;",
                "1:13",
                "E001",
                "this string has no closing `\"`: a string ends on the line it starts",
            ),
            (
                "    TPWrite \"a \"\"quoted\"\" word, \\Num:=n;",
                "1:13",
                "E001",
                "this string has no closing `\"`: a string ends on the line it starts",
            ),
            (
                "    MoveL p10, v100, z10, tool0\n    n := 2;",
                "1:32",
                "E002",
                "missing `;` at the end of the line",
            ),
            (
                "    %Tablet%\n    Set do1;",
                "1:13",
                "E002",
                "missing `;` at the end of the line",
            ),
            (
                "    MoveL p10,\n      v100 z10, tool0;",
                "2:11",
                "E002",
                "missing `,` between the arguments `v100` and `z10`",
            ),
            ("    n := 1\n    n := 2;", "1:11", "E002", "missing `;`"),
            (
                "    n = n + 1;",
                "1:7",
                "E003",
                "expected `:=` to assign a value, found `=` (the comparison operator)",
            ),
        ];
        for (body, at, code, message) in cases {
            assert_eq!(
                one(body),
                (at.to_owned(), code, message.to_owned()),
                "{body}"
            );
        }
    }

    /// A statement broken off before `ENDPROC` (the routine's end follows
    /// each body): told at what was left open, and nothing else.
    #[test]
    fn half_typed_statements_are_told_at_what_they_left_open() {
        let cases = [
            (
                "    MoveL p10, v100, z10, tool0\\",
                "1:32",
                "the name of an optional argument is missing after `\\`",
            ),
            (
                "    MoveL p10, v100, z10, tool0\\WObj:=",
                "1:37",
                "a value is missing after `:=`",
            ),
            (
                "    MoveL p10, v100,",
                "1:20",
                "an argument is missing after `,`",
            ),
            (
                "    n := [1, 2, ",
                "1:10",
                "this aggregate has no closing `]`",
            ),
            ("    n :=", "1:7", "a value is missing after `:=`"),
        ];
        for (body, at, message) in cases {
            let message =
                format!("{message}; the statement is not finished (its `;` is missing too)");
            assert_eq!(one(body), (at.to_owned(), "E001", message), "{body}");
        }
        // the string's finding says it all
        assert_eq!(one("    TPWrite \"hello;").0, "1:13");
    }

    #[test]
    fn what_is_right_is_left_alone() {
        for body in [
            "    MoveL p10, v100, z10, tool0 \\WObj:=wobj0;",
            "    IF n > 1\n      n := 2;\n    n := 3;",
            "    TPWrite \"a \"\"quoted\"\" ! word\";",
            "    TPWrite \"x\"; ! a \"comment",
            "    FOR i FROM 1 TO 10 DO\n      n := i;\n    ENDFOR",
            "    n := Max(1,\n      2);",
        ] {
            assert_eq!(told(body), [], "{body}");
        }
    }
}
