//! A routine as a list of lines that compare by meaning: one line per
//! statement, declaration, comment, label and clause (`ELSE`, `CASE 1:`,
//! `ERROR`), however the source breaks or indents them. A line's key is
//! its tokens, one blank apart, with keywords in upper case, names folded
//! (RAPID ignores their case) and numbers by value (`1.0` is `1`);
//! strings and comments stay as written. A compound statement gives its
//! header line (`IF x THEN`), the lines of its statements one level
//! deeper, and its closing line (`ENDIF`). A routine's data declarations
//! come first, sorted by name, so that reordering them changes nothing.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::ops::Range;

use tree_sitter::Node;

use crate::names::fold;
use crate::syntax::{field, kind};
use crate::syntax_util::{
    field, is_compound_statement, is_simple_statement, kind as kind_of, walk_pruned,
};
use crate::text::LineIndex;

/// One line as compared.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Line {
    /// The tokens as compared (see the module's documentation).
    pub key: String,
    /// As written, each run of blanks and line breaks made one blank.
    pub text: String,
    /// Nesting depth: 0 for a routine's own first and last lines.
    pub depth: u16,
    /// 1-based line of its first token.
    pub line: usize,
}

/// Builds lines from a unit's tree and text.
pub(crate) struct Liner<'a> {
    text: &'a str,
    index: &'a LineIndex,
    /// Every name met, folded.
    pub names: BTreeSet<String>,
}

/// How a token is compared.
#[derive(Clone, Copy)]
enum Key {
    /// A name: folded.
    Folded,
    /// A keyword: upper case.
    Upper,
    /// As written (strings, comments, placeholders, punctuation).
    Raw,
    /// A number, by the bits of its value.
    Number(u64),
}

/// Tokens gathered for one line.
type Tokens = Vec<(Range<usize>, Key)>;

impl<'a> Liner<'a> {
    pub fn new(text: &'a str, index: &'a LineIndex) -> Liner<'a> {
        Liner {
            text,
            index,
            names: BTreeSet::new(),
        }
    }

    /// The lines of a routine declaration (or of any compound node).
    pub fn routine(&mut self, node: Node<'_>) -> Vec<Line> {
        let mut out = Vec::new();
        self.compound(node, 0, &mut out);
        out
    }

    /// A node (a declaration, an expression) as one line, its comments
    /// left out.
    pub fn one_line(&mut self, node: Node<'_>, depth: u16) -> Option<Line> {
        let mut tokens = Vec::new();
        let mut comments = Vec::new();
        self.tokens(node, &mut tokens, &mut comments);
        self.line(&tokens, depth)
    }

    /// Walks a compound node: its own tokens make lines around its
    /// children's.
    fn compound(&mut self, node: Node<'_>, depth: u16, out: &mut Vec<Line>) {
        let is_routine = matches!(
            kind_of(node),
            kind::PROCEDURE_DECLARATION | kind::FUNCTION_DECLARATION | kind::TRAP_DECLARATION
        );
        let mut tokens: Tokens = Vec::new();
        let mut decls: Vec<(String, Line)> = Vec::new();
        let mut header_end = None;
        let mut cursor = node.walk();
        if !cursor.goto_first_child() {
            return;
        }
        loop {
            let child = cursor.node();
            let in_body = cursor.field_name() == Some(field::BODY);
            let k = kind_of(child);
            if is_line_node(k) || (in_body && child.is_named()) {
                self.flush(&mut tokens, depth, out);
                header_end.get_or_insert(out.len());
                let inner = if is_clause(k) { depth } else { depth + 1 };
                if opens_block(k) {
                    self.compound(child, inner, out);
                } else if is_routine && k == kind::DATA_DECLARATION {
                    let name = field(child, field::NAME)
                        .map(|n| fold(&self.text[n.byte_range()]))
                        .unwrap_or_default();
                    let mut lines = Vec::new();
                    self.statement(child, inner, &mut lines);
                    decls.extend(lines.into_iter().map(|l| (name.clone(), l)));
                } else {
                    self.statement(child, inner, out);
                }
            } else {
                // `ENDPROC`, `ENDIF`...: a line of their own, even after an
                // empty body.
                if !child.is_named() && k.starts_with("end") {
                    self.flush(&mut tokens, depth, out);
                }
                let mut comments = Vec::new();
                self.tokens(child, &mut tokens, &mut comments);
                // A comment inside a header goes after the header.
                if !comments.is_empty() {
                    self.flush(&mut tokens, depth, out);
                    self.comments(&comments, depth, out);
                }
            }
            if !cursor.goto_next_sibling() {
                break;
            }
        }
        self.flush(&mut tokens, depth, out);
        if !decls.is_empty() {
            decls.sort_by(|a, b| a.0.cmp(&b.0).then_with(|| a.1.key.cmp(&b.1.key)));
            let at = header_end.unwrap_or(out.len()).min(out.len());
            out.splice(at..at, decls.into_iter().map(|(_, l)| l));
        }
    }

    /// A statement that holds no statement list (a compact `IF` holds one
    /// statement, on its line): one line, then the comments inside it.
    fn statement(&mut self, node: Node<'_>, depth: u16, out: &mut Vec<Line>) {
        let mut tokens = Vec::new();
        let mut comments = Vec::new();
        self.tokens(node, &mut tokens, &mut comments);
        out.extend(self.line(&tokens, depth));
        self.comments(&comments, depth, out);
    }

    fn comments(&mut self, comments: &[Node<'_>], depth: u16, out: &mut Vec<Line>) {
        for c in comments {
            let text = self.text[c.byte_range()].trim_end().to_owned();
            out.push(Line {
                key: text.clone(),
                text,
                depth,
                line: self.index.line_col(c.start_byte()).line + 1,
            });
        }
    }

    fn flush(&mut self, tokens: &mut Tokens, depth: u16, out: &mut Vec<Line>) {
        out.extend(self.line(tokens, depth));
        tokens.clear();
    }

    fn line(&self, tokens: &[(Range<usize>, Key)], depth: u16) -> Option<Line> {
        let first = tokens.first()?;
        let mut key = String::new();
        let mut text = String::new();
        let mut end = first.0.start;
        for (range, k) in tokens {
            let written = &self.text[range.clone()];
            if !key.is_empty() {
                key.push(' ');
            }
            match k {
                Key::Folded => key.extend(written.chars().map(|c| c.to_ascii_lowercase())),
                Key::Upper => key.extend(written.chars().map(|c| c.to_ascii_uppercase())),
                Key::Raw => key.push_str(written),
                Key::Number(bits) => {
                    let _ = write!(key, "#{bits:x}");
                }
            }
            if range.start > end && !text.is_empty() {
                text.push(' ');
            }
            text.push_str(&collapse(written));
            end = range.end;
        }
        Some(Line {
            key,
            text,
            depth,
            line: self.index.line_col(first.0.start).line + 1,
        })
    }

    /// The tokens under `node` in order, comments apart (one cursor for
    /// the whole walk).
    fn tokens<'t>(&mut self, node: Node<'t>, out: &mut Tokens, comments: &mut Vec<Node<'t>>) {
        walk_pruned(node, &mut |n| {
            let k = kind_of(n);
            if k == kind::COMMENT {
                comments.push(n);
                return false;
            }
            if n.is_missing() || n.byte_range().is_empty() {
                return false;
            }
            let leaf = n.child_count() == 0 || k == kind::STRING || k == kind::NUMBER;
            if !leaf {
                return true;
            }
            let written = &self.text[n.byte_range()];
            let key = match k {
                kind::IDENTIFIER | kind::TYPE_IDENTIFIER => {
                    crate::names::with_folded(written, |name| {
                        if !self.names.contains(name) {
                            self.names.insert(name.to_owned());
                        }
                    });
                    Key::Folded
                }
                kind::NUMBER => number_key(written),
                kind::STRING | kind::PLACEHOLDER => Key::Raw,
                _ if !n.is_named() => Key::Upper,
                _ => Key::Raw,
            };
            out.push((n.byte_range(), key));
            false
        });
    }
}

/// Nodes that make lines of their own wherever they are.
fn is_line_node(k: &str) -> bool {
    is_simple_statement(k)
        || is_compound_statement(k)
        || is_clause(k)
        || matches!(k, kind::DATA_DECLARATION | kind::LABEL | kind::COMMENT)
}

/// Parts of a compound statement or routine written at its own depth.
fn is_clause(k: &str) -> bool {
    matches!(
        k,
        kind::ELSEIF_CLAUSE
            | kind::ELSE_CLAUSE
            | kind::TEST_CASE
            | kind::DEFAULT_CASE
            | kind::ERROR_HANDLER
            | kind::BACKWARD_HANDLER
            | kind::UNDO_HANDLER
    )
}

/// Nodes whose statements are lines of their own (a compact `IF` is one
/// line).
fn opens_block(k: &str) -> bool {
    (is_compound_statement(k) && k != kind::COMPACT_IF_STATEMENT) || is_clause(k)
}

/// A number by its value where it reads as a decimal (`1.0`, `1.`, `1E0`
/// are `1`), else as written (`0xFF`, compared in any case: `0XFF`).
fn number_key(text: &str) -> Key {
    match text.parse::<f64>() {
        Ok(x) if x.is_finite() => Key::Number((x + 0.0).to_bits()),
        _ if text.bytes().any(|b| b.is_ascii_uppercase()) => Key::Folded,
        _ => Key::Raw,
    }
}

/// A token's text with each run of blanks and line breaks one blank (a
/// string or comment keeps its inside; only tokens that span lines, which
/// none but broken ones do, are touched).
fn collapse(s: &str) -> std::borrow::Cow<'_, str> {
    if !s.contains(['\n', '\r']) {
        return s.into();
    }
    s.split_whitespace().collect::<Vec<_>>().join(" ").into()
}
