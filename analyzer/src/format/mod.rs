//! The layout of RAPID code, as `rapid fmt` and the language server's
//! formatting requests produce it. Text in, text (or edits) out. The layout
//! is described, with examples, in `docs/formatting.md`.
//!
//! # The layout
//!
//! - [`Style::AsWritten`] (the default) decides only where lines start:
//!   structure lines by their depth, in the indentation unit the text
//!   already follows (`indent.rs`: columns per level, module body and
//!   `CASE` indented or not, tabs or spaces; per routine when one follows
//!   another unit; 4 spaces when none fits), continuation lines at their
//!   distance from their statement, own-line comments after the code line
//!   they were indented like (`layout.rs`). A line already at its column
//!   keeps its blanks; the content of lines, blank lines and line breaks
//!   between statements are kept.
//! - [`Style::Tight`] and [`Style::Spaced`] also set the blanks between
//!   tokens (`spacing.rs`), keyword case, one statement per line, blank
//!   lines and trailing blanks; continuation lines stay aligned under the
//!   token they were aligned under, else go one level deeper. The blanks of
//!   a `PERS` value (the controller's) are kept by `spaced`.
//! - With a line width, long procedure calls on one line are wrapped
//!   (`wrap.rs`).
//! - The `%%%` header's entries are indented by two spaces; text after
//!   `ENDMODULE` that is not RAPID is kept byte for byte; every line break
//!   is written with the text's most frequent line ending; a gap holding
//!   anything but spaces, tabs and line breaks (a U+FEFF) is kept as it is.
//!
//! # Safety
//!
//! A text with syntax errors is never formatted ([`FormatError::Syntax`]),
//! nor one that nests deeper than 1500 levels
//! ([`FormatError::Unsupported`]). The formatter only rewrites the blanks
//! and line breaks between tokens, and in the styles that normalise the
//! case of keywords and the trailing blanks of comments; two tokens are
//! never made to touch if they could then read as one. [`verify`] checks a
//! result independently, by parsing it again and comparing its tokens with
//! the original's (`rapid fmt --verify` does it for every file; the corpus
//! test makes the same check, with its own code, on every file of the
//! corpus, in every style).

mod collect;
mod edits;
mod indent;
mod layout;
mod spacing;
mod wrap;

use std::cell::RefCell;
use std::ops::Range;

use tree_sitter::{Node, Parser, Tree};

use crate::diagnostic::Edit;
use crate::text::{LineEnding, LineIndex};

pub use edits::line_edits;

/// How the blanks inside a line are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Style {
    /// As the author wrote them: only where lines start and how far they
    /// are indented is the formatter's business (and blank lines, keyword
    /// case and trailing blanks stay as written). A module saved by a
    /// controller is already in this layout, up to lines typed with
    /// another indentation.
    #[default]
    AsWritten,
    /// RobotStudio's form: `reg1:=reg1+1;`,
    /// `MoveL p10,v1000,z50,tool0\WObj:=wobj0;`.
    Tight,
    /// Spaces around `:=` and binary operators, after commas:
    /// `reg1 := reg1 + 1;`, `MoveL p10, v1000, z50, tool0\WObj:=wobj0;`.
    Spaced,
}

impl Style {
    /// The names of `[format] style` in `rapid.toml`.
    pub const NAMES: [(&'static str, Style); 3] = [
        ("as-written", Style::AsWritten),
        ("tight", Style::Tight),
        ("spaced", Style::Spaced),
    ];

    pub fn from_name(name: &str) -> Option<Style> {
        Style::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, s)| s)
    }

    pub fn name(self) -> &'static str {
        Style::NAMES
            .iter()
            .find(|(_, s)| *s == self)
            .map_or("as-written", |(n, _)| n)
    }
}

/// The settings of the formatter (`[format]` in `rapid.toml`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FormatOptions {
    /// The blanks inside lines.
    pub style: Style,
    /// Spaces per indentation level; `None`: the text's own indentation
    /// (the unit most of its lines follow: a tab or some spaces, with the
    /// module body indented or not), 4 spaces when it has none.
    pub indent_width: Option<usize>,
    /// Procedure calls on lines longer than this are wrapped; `None`: lines
    /// are never broken.
    pub line_width: Option<usize>,
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
    run(text, options)
}

/// Formats a whole text, as edits of whole lines that turn `text` into
/// [`format()`]'s result (see [`line_edits`]).
pub fn format_edits(text: &str, options: &FormatOptions) -> Result<Vec<Edit>, FormatError> {
    let formatted = run(text, options)?;
    Ok(line_edits(text, &formatted))
}

/// The edits of [`format_edits`] that touch the lines of `range` (a byte
/// range of `text`, extended to whole lines). The whole text must parse.
pub fn format_range(
    text: &str,
    range: Range<usize>,
    options: &FormatOptions,
) -> Result<Vec<Edit>, FormatError> {
    let formatted = run(text, options)?;
    let index = LineIndex::new(text);
    let first = index.line_col(range.start).line;
    let last = index.line_col(range.end.max(range.start)).line;
    let start = index.line_range(first, text).start;
    // the start of the line after the range
    let end = index.line_range(last + 1, text).start;
    Ok(edits::merge(
        edits::line_changes(text, &formatted)
            .into_iter()
            .filter(|e| e.range.start < end && (e.range.end > start || e.range.start == start))
            .collect(),
    ))
}

/// How a text's lines are indented, as the formatter writes them: columns
/// per level, and tabs or spaces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Indentation {
    pub width: usize,
    pub tabs: bool,
}

/// The indentation the formatter writes in `text` with `options`: the
/// configured width in spaces, else the unit that most of the text's lines
/// follow (tabs if most of the lines that go a tab's width in start with
/// one). Editors set their own indentation from it, so that a line they
/// indent is indented as `rapid fmt` would; a text with syntax errors gets
/// the answer of what parses.
pub fn indentation(text: &str, options: &FormatOptions) -> Indentation {
    let unit = parse(text)
        .and_then(|tree| collect::collect(tree.root_node(), text, false))
        .map_or_else(
            || match options.indent_width {
                Some(width) => indent::Unit::spaces(width),
                None => indent::Unit::spaces(4),
            },
            |toks| layout::unit(&toks, text, options),
        );
    Indentation {
        width: unit.width,
        tabs: unit.tabs,
    }
}

thread_local! {
    static PARSER: RefCell<Parser> = RefCell::new(crate::syntax::parser());
}

fn parse(text: &str) -> Option<Tree> {
    PARSER.with(|p| p.borrow_mut().parse(text, None))
}

fn run(text: &str, options: &FormatOptions) -> Result<String, FormatError> {
    let options = FormatOptions {
        style: options.style,
        indent_width: options.indent_width.map(|w| w.clamp(1, 16)),
        line_width: options.line_width,
    };
    let Some(tree) = parse(text) else {
        return Err(internal("the parser gave no tree"));
    };
    let root = tree.root_node();
    if root.has_error() {
        return Err(syntax_error(&tree, text));
    }
    let normalise = options.style != Style::AsWritten;
    let Some(toks) = collect::collect(root, text, normalise) else {
        return Err(FormatError::Unsupported {
            message: format!(
                "the code nests deeper than {} levels, the file is left as it is",
                collect::MAX_DEPTH
            ),
        });
    };
    if toks.is_empty() {
        return Ok(text.to_owned());
    }
    let gaps = layout::layout(&toks, text, &options);
    let line_ending = LineEnding::detect(text).as_str();

    let mut output = String::with_capacity(text.len() + text.len() / 8);
    let mut prev_end = 0;
    for (tok, gap) in toks.iter().zip(&gaps) {
        layout::render_gap(gap, text, line_ending, &mut output);
        output.push_str(&tok.text);
        prev_end = tok.range.end;
    }
    let tail = text.get(prev_end..).unwrap_or_default();
    let verbatim_end = toks
        .last()
        .is_some_and(|t| t.class == collect::Class::Verbatim);
    if verbatim_end {
        output.push_str(tail);
    } else if !normalise {
        layout::push_kept(tail, line_ending, &mut output);
    } else if tail.contains(['\n', '\r']) {
        output.push_str(line_ending);
    }
    Ok(output)
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
            out.push((
                node.byte_range(),
                keyword,
                node.kind() == crate::syntax::kind::COMMENT,
            ));
        }
        !atomic
    });
}

#[cfg(test)]
mod tests {
    use super::edits::apply;
    use super::*;

    fn fmt(text: &str) -> String {
        format(text, &FormatOptions::default()).expect("formats")
    }

    fn spaced(text: &str) -> String {
        let options = FormatOptions {
            style: Style::Spaced,
            ..FormatOptions::default()
        };
        format(text, &options).expect("formats")
    }

    #[test]
    fn line_endings_are_kept() {
        let crlf = "MODULE M\r\nVAR num a:=1;\r\nENDMODULE\r\n";
        assert_eq!(fmt(crlf), crlf);
        assert_eq!(spaced(crlf), "MODULE M\r\nVAR num a := 1;\r\nENDMODULE\r\n");
        let cr = "MODULE M\rVAR num a:=1;\rENDMODULE\r";
        assert_eq!(spaced(cr), "MODULE M\rVAR num a := 1;\rENDMODULE\r");
        let lf = "MODULE M\nPROC p() x:=1; ENDPROC ENDMODULE";
        assert_eq!(
            spaced(lf),
            "MODULE M\n    PROC p()\n        x := 1;\n    ENDPROC\nENDMODULE"
        );
        // as written: the lines are the author's
        assert_eq!(fmt(lf), "MODULE M\n    PROC p() x:=1; ENDPROC ENDMODULE");
    }

    #[test]
    fn final_line_breaks_collapse_to_one_and_none_stays_none() {
        assert_eq!(spaced("MODULE M\nENDMODULE\n\n\n"), "MODULE M\nENDMODULE\n");
        assert_eq!(spaced("MODULE M\nENDMODULE   "), "MODULE M\nENDMODULE");
        assert_eq!(spaced("\n\n  MODULE M\nENDMODULE"), "MODULE M\nENDMODULE");
        // as written, blank lines and blanks at line ends stay
        for text in ["MODULE M\nENDMODULE\n\n\n", "\n\nMODULE M\nENDMODULE   "] {
            assert_eq!(fmt(text), text);
        }
    }

    #[test]
    fn latin1_text_and_identifier_case_are_untouched() {
        let text = "MODULE m\n! Größe °C\nvar NUM MyVar;\nENDMODULE\n";
        assert_eq!(
            spaced(text),
            "MODULE m\n! Größe °C\nVAR NUM MyVar;\nENDMODULE\n"
        );
        assert_eq!(
            fmt(text),
            "MODULE m\n! Größe °C\nvar NUM MyVar;\nENDMODULE\n"
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
        for options in [
            FormatOptions::default(),
            FormatOptions {
                style: Style::Tight,
                ..FormatOptions::default()
            },
        ] {
            let edits = format_edits(text, &options).expect("formats");
            let formatted = format(text, &options).expect("formats");
            assert_eq!(apply(text, &edits), formatted);
            assert!(edits.windows(2).all(|w| w[0].range.end <= w[1].range.start));
        }
    }

    #[test]
    fn range_formatting_touches_only_the_lines_asked_for() {
        let text = "MODULE M\nPROC p()\nx:=1;\ny:=2;\nENDPROC\nENDMODULE\n";
        let y = text.find("y:=").expect("y");
        for (options, line) in [
            (FormatOptions::default(), "        y:=2;\n"),
            (
                FormatOptions {
                    style: Style::Spaced,
                    ..FormatOptions::default()
                },
                "        y := 2;\n",
            ),
        ] {
            let edits = format_range(text, y..y + 1, &options).expect("formats");
            assert_eq!(
                apply(text, &edits),
                format!("MODULE M\nPROC p()\nx:=1;\n{line}ENDPROC\nENDMODULE\n")
            );
        }
    }

    #[test]
    fn indentation_is_what_the_formatter_writes() {
        let default = FormatOptions::default();
        let spaces = "MODULE m\n    PROC p()\n        x := 1;\n\ty := 2;\n        z := 3;\n    ENDPROC\nENDMODULE\n";
        assert_eq!(
            indentation(spaces, &default),
            Indentation {
                width: 4,
                tabs: false
            }
        );
        // the one line with a tab is the one to change
        assert_eq!(fmt(spaces).matches('\t').count(), 0);
        let tabs = "MODULE m\n\tPROC p()\n\t\tx := 1;\n        y := 2;\n\t\tz := 3;\n\tENDPROC\nENDMODULE\n";
        assert_eq!(
            indentation(tabs, &default),
            Indentation {
                width: 4,
                tabs: true
            }
        );
        let two = "MODULE m\n  PROC p()\n    x := 1;\n  ENDPROC\nENDMODULE\n";
        assert_eq!(indentation(two, &default).width, 2);
        let configured = FormatOptions {
            indent_width: Some(3),
            ..FormatOptions::default()
        };
        assert_eq!(
            indentation(tabs, &configured),
            Indentation {
                width: 3,
                tabs: false
            }
        );
        // half typed: what parses decides
        let broken = "MODULE m\n  PROC p()\n    x := \n  ENDPROC\nENDMODULE\n";
        assert_eq!(indentation(broken, &default).width, 2);
    }

    #[test]
    fn formatting_is_idempotent_on_odd_layouts() {
        for text in [
            "MODULE M PROC p() MoveL p1,v1,z1,t1; ENDPROC ENDMODULE",
            "MODULE M\n\tPROC p()\n\t\tx:=[1,\n2,\n[3,\n4]];\n\tENDPROC\nENDMODULE\n",
            "MODULE M\nPROC p()\n! only a comment\nENDPROC\nENDMODULE",
            "! file comment\n\n\nMODULE M\nENDMODULE\n! end\n",
        ] {
            for style in [Style::AsWritten, Style::Tight, Style::Spaced] {
                let options = FormatOptions {
                    style,
                    ..FormatOptions::default()
                };
                let once = format(text, &options).expect("formats");
                assert_eq!(format(&once, &options), Ok(once.clone()), "{text:?}");
                assert_eq!(verify(text, &once), Ok(()));
            }
        }
    }

    /// A long statement broken inside a call's arguments reaches its fixed
    /// point in one run, whatever the line width (its continuation line
    /// once moved from 4 to 8 columns on the second run).
    #[test]
    fn a_long_call_broken_inside_its_arguments_is_stable() {
        let text = "MODULE M\nPROC p()\nMoveL Offs(pHome, 100, 200, 300), v1000, z50, tGripper\\WObj:=wobjTable, \\TLoad:=load0,\n    \\Corr;\nTPWrite \"a message\" + NumToStr(reg1, 0) + \" and more text that goes on\",\n\\Num:=reg2;\nENDPROC\nENDMODULE\n";
        for style in [Style::AsWritten, Style::Tight, Style::Spaced] {
            for line_width in [None, Some(40), Some(60), Some(120)] {
                let options = FormatOptions {
                    style,
                    indent_width: None,
                    line_width,
                };
                let once = format(text, &options).expect("formats");
                assert_eq!(format(&once, &options), Ok(once.clone()), "{options:?}");
            }
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
        for style in [Style::Tight, Style::Spaced] {
            let options = FormatOptions {
                style,
                ..FormatOptions::default()
            };
            let out = format(
                "MODULE M\nPROC p()\nFoo a\\B;\nx:=a.b{1}-(-1);\nENDPROC\nENDMODULE\n",
                &options,
            )
            .expect("formats");
            assert!(out.contains("Foo a\\B;"), "{out}");
            assert!(out.contains("a.b{1}"), "{out}");
            assert_eq!(
                verify(
                    "MODULE M\nPROC p()\nFoo a\\B;\nx:=a.b{1}-(-1);\nENDPROC\nENDMODULE\n",
                    &out
                ),
                Ok(())
            );
        }
    }
}
