//! The canonical layout of RAPID code, as `rapid fmt` and the language
//! server's formatting requests produce it. Text in, text (or edits) out.
//!
//! # The layout
//!
//! - Indentation by levels of [`FormatOptions::indent_width`] spaces: the
//!   module body one level; routine bodies one more; the bodies of `IF`,
//!   `FOR`, `WHILE` one more; `CASE` and `DEFAULT` one level inside `TEST`
//!   and their statements one more; `ERROR`, `UNDO` and `BACKWARD` at the
//!   level of their routine with their statements one deeper; record
//!   components one level inside `RECORD`.
//! - Keywords in upper case; names keep their spelling.
//! - One statement per line: a line break before every statement,
//!   declaration, clause and end keyword. Line breaks that the user wrote
//!   inside a statement or declaration (a long aggregate over several lines,
//!   arguments one per line) are kept, as continuation lines indented one
//!   level deeper than the statement, or one level deeper than the line that
//!   opened the innermost bracket still open; a closing bracket that starts a
//!   line goes back to the level of the line that opened it.
//! - Spaces around binary operators and `:=`, after commas, none inside
//!   brackets; `Name:=value`, `\Opt:=value`, `\Switch` and `\Opt?var` in
//!   arguments are tight, as RAPID writes them (`MoveL p10, v100, fine,
//!   tool0\WObj:=wobj0;`), except that a `\` right after the procedure name or
//!   after a comma is preceded by a space (`StopMove \Quick;`). In parameter
//!   lists `\` follows a space and `|` is spaced (`(num a, \switch On |
//!   switch Off)`).
//! - Wrapping: only the arguments of a procedure call are wrapped. When such
//!   a line is longer than [`FormatOptions::line_width`] characters (a
//!   trailing comment not counted), it is broken after the commas that
//!   separate the arguments, filling each line as far as it goes, with
//!   continuation lines one level deeper; but only if every resulting line
//!   then fits: a call whose first argument alone is too long (a `MoveL`
//!   with a `robtarget` literal) stays on its line. Aggregates, declarations
//!   and expressions are never wrapped: long `robtarget` literals stay on
//!   the line the user put them on.
//! - Blank lines: exactly one between two routines, and between two modules
//!   of a file (a blank line is added after the first one's end keyword if
//!   there is none, comments between them stay with the second); elsewhere
//!   runs of blank lines collapse to one, and a single blank line is kept
//!   where the user put one. Blank lines before the first token go.
//! - Comments stay where they are: a trailing comment stays at the end of its
//!   line with the blanks before it kept; a comment on its own line keeps its
//!   line, indented like the statement after it or, when the next line
//!   closes or splits a block (`ENDIF`, `ELSE`, `CASE`, `ERROR`...), like a
//!   statement of the block body before it (so commented-out code at the end
//!   of a body stays in the body). Trailing blanks in comments are removed.
//! - The `%%%` header: `%%%` lines at column 0, each entry on its own line
//!   indented by two spaces (`  VERSION:1`), as RobotStudio writes it.
//! - Text after an `ENDMODULE` that is not RAPID (trailing junk, which the
//!   grammar calls `trailing_text`) is kept byte for byte, with the blanks
//!   and line breaks around it.
//! - Line endings: the text's most frequent line ending is used for every
//!   line break. A file that ends with a line break ends with exactly one; a
//!   file without a final line break (as controllers write them) keeps
//!   having none. Encoding is the caller's business: the text is returned as
//!   text, with no character added but spaces and line breaks.
//!
//! # Safety
//!
//! A text with syntax errors is never formatted ([`FormatError::Syntax`]).
//! The formatter only rewrites the blanks between tokens and the case of
//! keywords (and drops trailing blanks of comments); two tokens are never
//! made to touch if they could then read as one. [`verify`] checks a result
//! independently, by parsing it again and comparing its tokens with the
//! original's (`rapid fmt --verify` does it for every file; the corpus test
//! makes the same check, with its own code, on every file of the corpus).

mod collect;
mod layout;

use std::cell::RefCell;
use std::ops::Range;

use tree_sitter::{Node, Parser, Tree};

use crate::diagnostic::Edit;
use crate::text::{LineEnding, LineIndex};

/// The settings of the formatter (`[format]` in `rapid.toml`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FormatOptions {
    /// Spaces per indentation level.
    pub indent_width: usize,
    /// The longest line before procedure-call arguments are wrapped.
    pub line_width: usize,
}

impl Default for FormatOptions {
    fn default() -> FormatOptions {
        FormatOptions {
            indent_width: 4,
            line_width: 120,
        }
    }
}

/// Why a text was left as it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FormatError {
    /// The text does not parse; nothing is formatted. The position is the
    /// first syntax error: 1-based line and 1-based column in characters.
    Syntax {
        range: Range<usize>,
        line: usize,
        column: usize,
        message: String,
    },
    /// The formatter would have changed more than whitespace and keyword
    /// case (a bug in the formatter): nothing is formatted.
    Internal { message: String },
    /// The text is valid but beyond what the formatter handles (nesting
    /// deeper than 1500 levels): nothing is formatted.
    Unsupported { message: String },
}

impl std::fmt::Display for FormatError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FormatError::Syntax {
                line,
                column,
                message,
                ..
            } => write!(f, "{line}:{column}: syntax error, not formatted: {message}"),
            FormatError::Internal { message } => {
                write!(
                    f,
                    "not formatted, the formatter would change the program: {message}"
                )
            }
            FormatError::Unsupported { message } => write!(f, "not formatted: {message}"),
        }
    }
}

impl std::error::Error for FormatError {}

/// Formats a whole text.
pub fn format(text: &str, options: &FormatOptions) -> Result<String, FormatError> {
    Ok(run(text, options, false)?.output)
}

/// Formats a whole text, as the smallest edits that turn `text` into
/// [`format()`]'s result: non-overlapping, in order, on the original byte
/// offsets.
pub fn format_edits(text: &str, options: &FormatOptions) -> Result<Vec<Edit>, FormatError> {
    Ok(run(text, options, true)?.edits)
}

/// The edits of [`format_edits`] for the lines of `range` (a byte range of
/// `text`, extended to whole lines): those that end on these lines, so the
/// line break and indentation before a line belong to it. The whole text
/// must parse.
pub fn format_range(
    text: &str,
    range: Range<usize>,
    options: &FormatOptions,
) -> Result<Vec<Edit>, FormatError> {
    let edits = run(text, options, true)?.edits;
    let index = LineIndex::new(text);
    let first = index.line_col(range.start).line;
    let last = index.line_col(range.end.max(range.start)).line;
    let start = index.line_range(first, text).start;
    let end = index.line_range(last, text).end;
    Ok(edits
        .into_iter()
        .filter(|e| e.range.end >= start && e.range.end <= end)
        .collect())
}

struct Formatted {
    output: String,
    edits: Vec<Edit>,
}

thread_local! {
    static PARSER: RefCell<Parser> = RefCell::new(crate::syntax::parser());
}

fn parse(text: &str) -> Option<Tree> {
    PARSER.with(|p| p.borrow_mut().parse(text, None))
}

fn run(text: &str, options: &FormatOptions, want_edits: bool) -> Result<Formatted, FormatError> {
    let options = FormatOptions {
        indent_width: options.indent_width.min(16),
        line_width: options.line_width,
    };
    let Some(tree) = parse(text) else {
        return Err(internal("the parser gave no tree"));
    };
    let root = tree.root_node();
    if root.has_error() {
        return Err(syntax_error(&tree, text));
    }
    let Some(toks) = collect::collect(root, text, options.indent_width) else {
        return Err(FormatError::Unsupported {
            message: format!("the code nests deeper than {} levels", collect::MAX_DEPTH),
        });
    };
    if toks.is_empty() {
        return Ok(Formatted {
            output: text.to_owned(),
            edits: Vec::new(),
        });
    }
    let gaps = layout::layout(&toks, text, &options);
    let line_ending = LineEnding::detect(text).as_str();

    let mut output = String::with_capacity(text.len() + text.len() / 8);
    // no capacity: no edits wanted (see `push_edit`)
    let mut edits = if want_edits {
        Vec::with_capacity(toks.len() / 2 + 1)
    } else {
        Vec::new()
    };
    let mut rendered = String::new();
    let mut prev_end = 0;
    for (tok, gap) in toks.iter().zip(&gaps) {
        rendered.clear();
        layout::render(gap, text, line_ending, &mut rendered);
        let before = prev_end..tok.range.start;
        push_edit(&mut edits, text, before, &rendered);
        output.push_str(&rendered);
        push_edit(&mut edits, text, tok.range.clone(), &tok.text);
        output.push_str(&tok.text);
        prev_end = tok.range.end;
    }
    let tail = text.get(prev_end..).unwrap_or_default();
    let end = if toks
        .last()
        .is_some_and(|t| t.class == collect::Class::Verbatim)
    {
        tail
    } else if tail.contains(['\n', '\r']) {
        line_ending
    } else {
        ""
    };
    push_edit(&mut edits, text, prev_end..text.len(), end);
    output.push_str(end);
    Ok(Formatted { output, edits })
}

fn push_edit(edits: &mut Vec<Edit>, text: &str, range: Range<usize>, new: &str) {
    if edits.capacity() > 0 && text.get(range.clone()) != Some(new) {
        edits.push(Edit {
            range,
            replacement: new.to_owned(),
        });
    }
}

fn internal(message: impl Into<String>) -> FormatError {
    FormatError::Internal {
        message: message.into(),
    }
}

fn syntax_error(tree: &Tree, text: &str) -> FormatError {
    let diagnostics = crate::syntax::syntax_diagnostics(tree, text);
    let (range, message) = match diagnostics.into_iter().next() {
        Some(d) => (d.range, d.message),
        None => (0..0, "the text does not parse".to_owned()),
    };
    let (line, column) = LineIndex::new(text).human(range.start, text);
    FormatError::Syntax {
        range,
        line,
        column,
        message,
    }
}

/// Checks that `formatted` is a faithful formatting of `original`: it parses
/// without errors and holds the same tokens (keywords compared in upper
/// case, comments without trailing blanks).
pub fn verify(original: &str, formatted: &str) -> Result<(), FormatError> {
    let tokens = |text: &str| -> Result<Vec<String>, FormatError> {
        let Some(tree) = parse(text) else {
            return Err(internal("the parser gave no tree"));
        };
        let root = tree.root_node();
        if root.has_error() {
            return Err(syntax_error(&tree, text));
        }
        let mut leaves = Vec::new();
        collect_leaves(root, &mut leaves);
        Ok(leaves
            .into_iter()
            .map(|(range, keyword, comment)| {
                let t = text.get(range).unwrap_or_default();
                if keyword {
                    t.to_ascii_uppercase()
                } else if comment {
                    t.trim_end().to_owned()
                } else {
                    t.to_owned()
                }
            })
            .collect())
    };
    let before = tokens(original)?;
    let after = tokens(formatted).map_err(|e| match e {
        FormatError::Syntax {
            line,
            column,
            message,
            ..
        } => internal(format!(
            "the result does not parse ({line}:{column}: {message})"
        )),
        other => other,
    })?;
    if let Some((a, b)) = before.iter().zip(&after).find(|(a, b)| a != b) {
        return Err(internal(format!("`{a}` became `{b}`")));
    }
    if before.len() != after.len() {
        return Err(internal(format!(
            "{} tokens became {}",
            before.len(),
            after.len()
        )));
    }
    Ok(())
}

/// Leaves in order: range, is it a keyword, is it a comment. (Iterative:
/// any depth.)
fn collect_leaves(root: Node<'_>, out: &mut Vec<(Range<usize>, bool, bool)>) {
    crate::syntax_util::walk_pruned(root, &mut |node| {
        let atomic = collect::is_atomic(node);
        if atomic && !node.byte_range().is_empty() {
            let keyword = !node.is_named() && node.kind().bytes().all(|b| b.is_ascii_alphabetic());
            out.push((node.byte_range(), keyword, node.kind() == "comment"));
        }
        !atomic
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fmt(text: &str) -> String {
        format(text, &FormatOptions::default()).expect("formats")
    }

    fn apply(text: &str, edits: &[Edit]) -> String {
        let mut out = text.to_owned();
        for e in edits.iter().rev() {
            out.replace_range(e.range.clone(), &e.replacement);
        }
        out
    }

    #[test]
    fn line_endings_are_kept() {
        let crlf = "MODULE M\r\nVAR num a:=1;\r\nENDMODULE\r\n";
        assert_eq!(
            fmt(crlf),
            "MODULE M\r\n    VAR num a := 1;\r\nENDMODULE\r\n"
        );
        let cr = "MODULE M\rVAR num a:=1;\rENDMODULE\r";
        assert_eq!(fmt(cr), "MODULE M\r    VAR num a := 1;\rENDMODULE\r");
        let lf = "MODULE M\nPROC p() x:=1; ENDPROC ENDMODULE";
        assert_eq!(
            fmt(lf),
            "MODULE M\n    PROC p()\n        x := 1;\n    ENDPROC\nENDMODULE"
        );
    }

    #[test]
    fn final_line_breaks_collapse_to_one_and_none_stays_none() {
        assert_eq!(fmt("MODULE M\nENDMODULE\n\n\n"), "MODULE M\nENDMODULE\n");
        assert_eq!(fmt("MODULE M\nENDMODULE   "), "MODULE M\nENDMODULE");
        assert_eq!(fmt("\n\n  MODULE M\nENDMODULE"), "MODULE M\nENDMODULE");
    }

    #[test]
    fn latin1_text_and_identifier_case_are_untouched() {
        let text = "MODULE m\n! Größe °C\nvar NUM MyVar;\nENDMODULE\n";
        assert_eq!(
            fmt(text),
            "MODULE m\n    ! Größe °C\n    VAR NUM MyVar;\nENDMODULE\n"
        );
    }

    #[test]
    fn syntax_errors_give_the_first_position() {
        let err = format(
            "MODULE M\n  PROC p()\n    x := ;\n  ENDPROC\nENDMODULE\n",
            &FormatOptions::default(),
        );
        let Err(FormatError::Syntax { line, column, .. }) = err else {
            panic!("a syntax error: {err:?}")
        };
        assert_eq!(line, 3);
        assert!(column > 5, "{column}");
    }

    #[test]
    fn edits_rebuild_the_formatted_text() {
        let text = "MODULE M\nPROC p()\nif a then b:=1; endif\nENDPROC\nENDMODULE\n";
        let edits = format_edits(text, &FormatOptions::default()).expect("formats");
        assert_eq!(apply(text, &edits), fmt(text));
        assert!(edits.windows(2).all(|w| w[0].range.end <= w[1].range.start));
    }

    #[test]
    fn range_formatting_touches_only_the_lines_asked_for() {
        let text = "MODULE M\nPROC p()\nx:=1;\ny:=2;\nENDPROC\nENDMODULE\n";
        let y = text.find("y:=").expect("y");
        let edits = format_range(text, y..y + 1, &FormatOptions::default()).expect("formats");
        assert_eq!(
            apply(text, &edits),
            "MODULE M\nPROC p()\nx:=1;\n        y := 2;\nENDPROC\nENDMODULE\n"
        );
    }

    #[test]
    fn formatting_is_idempotent_on_odd_layouts() {
        for text in [
            "MODULE M PROC p() MoveL p1,v1,z1,t1; ENDPROC ENDMODULE",
            "MODULE M\n\tPROC p()\n\t\tx:=[1,\n2,\n[3,\n4]];\n\tENDPROC\nENDMODULE\n",
            "MODULE M\nPROC p()\n! only a comment\nENDPROC\nENDMODULE",
            "! file comment\n\n\nMODULE M\nENDMODULE\n! end\n",
        ] {
            let once = fmt(text);
            assert_eq!(fmt(&once), once, "{text:?}");
            assert_eq!(verify(text, &once), Ok(()));
        }
    }

    #[test]
    fn verify_notices_a_changed_token() {
        let err = verify("MODULE M\nENDMODULE\n", "MODULE N\nENDMODULE\n");
        assert!(matches!(err, Err(FormatError::Internal { .. })), "{err:?}");
    }

    #[test]
    fn very_deep_nesting_is_refused_not_a_crash() {
        let depth = 3000;
        let text = format!(
            "MODULE M\nPROC p()\nx := {}1{};\nENDPROC\nENDMODULE\n",
            "(".repeat(depth),
            ")".repeat(depth)
        );
        let err = format(&text, &FormatOptions::default());
        assert!(
            matches!(err, Err(FormatError::Unsupported { .. })),
            "{err:?}"
        );
        assert_eq!(verify(&text, &text), Ok(()));
    }

    #[test]
    fn tokens_never_merge() {
        // names stay apart even where the spacing rules would join them
        let out = fmt("MODULE M\nPROC p()\nFoo a\\B;\nx:=a.b{1};\nENDPROC\nENDMODULE\n");
        assert!(out.contains("Foo a\\B;"), "{out}");
        assert!(out.contains("x := a.b{1};"), "{out}");
    }
}
