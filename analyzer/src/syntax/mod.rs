//! Parsing, and the syntax diagnostics of a tree.
//!
//! Parsing never fails: tree-sitter always returns a tree, with `ERROR` nodes
//! around text it could not fit and zero-width `MISSING` nodes where it
//! assumed a token. [`syntax_diagnostics`] turns those into diagnostics that
//! say what was expected and what was found.

use std::ops::Range;

use tree_sitter::{Language, Node, Parser, Tree};

use crate::diagnostic::Diagnostic;
use crate::rules::{equals_for_assignment, missing_token, syntax_error};

// Generated (tests/syntax.rs checks it is current); its layout is the
// generator's.
#[rustfmt::skip]
pub mod generated;
mod characters;
mod typos;

pub use generated::{field, kind};

/// The RAPID language of the tree-sitter grammar.
pub fn language() -> Language {
    tree_sitter_rapid::LANGUAGE.into()
}

/// A parser for RAPID.
pub fn parser() -> Parser {
    let mut parser = Parser::new();
    // The grammar is compiled into this crate against the same tree-sitter
    // ABI, so this cannot fail; a tree-less parser would return no tree, which
    // `parse` below reports as an empty tree anyway.
    let _ = parser.set_language(&language());
    parser
}

/// Parses `text`, reusing `old` (already edited with `Tree::edit`) when given.
///
/// Returns `None` only if tree-sitter was cancelled, which we never ask it to.
pub fn parse(parser: &mut Parser, text: &str, old: Option<&Tree>) -> Option<Tree> {
    parser.parse(text, old)
}

/// The syntax diagnostics of `tree`, in source order: one per `ERROR` node
/// (not looking inside it) and one per `MISSING` node.
pub fn syntax_diagnostics(tree: &Tree, text: &str) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let root = tree.root_node();
    if let Some(d) = no_module(root, text) {
        out.push(d);
        return out;
    }
    if !root.has_error() {
        return out;
    }
    let language = tree.language();
    // Strings left open first: the errors around them are theirs.
    let mut errors = Vec::new();
    crate::syntax_util::walk_pruned(root, &mut |node| {
        if node.is_error() || node.is_missing() {
            errors.push(node.byte_range());
            false
        } else {
            node.has_error()
        }
    });
    out.extend(typos::unterminated_strings(text, &errors));
    let quotes: Vec<usize> = out.iter().map(|d| d.range.start).collect();
    // Characters RAPID does not know: one error per line.
    let mut stray = Vec::new();
    // Only nodes with an error below them are entered.
    crate::syntax_util::walk_pruned(root, &mut |node| {
        if node.is_error() {
            if quotes
                .iter()
                .any(|&q| node.start_byte() <= q && q < node.end_byte())
            {
                return false;
            }
            if let Some(chars) = characters::stray(node, text) {
                stray.push(chars);
                return false;
            }
            let equals = equals_for_assignment(node, text);
            if !equals.is_empty() {
                out.extend(equals);
            } else if let Some(typo) = typos::explain(node, text, &language) {
                out.push(typo);
            } else {
                out.push(error_diagnostic(node, text, &language));
            }
            false
        } else if node.is_missing() {
            // the `;` after a string that the end of its line closed: the
            // string's finding says it
            let after_open_string = out
                .iter()
                .take(quotes.len())
                .any(|d| d.range.end == node.start_byte());
            if !after_open_string {
                out.push(
                    typos::broken_off(node, text)
                        .unwrap_or_else(|| missing_diagnostic(node, &language)),
                );
            }
            false
        } else {
            node.has_error()
        }
    });
    out.extend(characters::once_per_line(text, stray));
    out.sort_by_key(|d| (d.range.start, d.range.end));
    out
}

/// A file without a module: empty, only comments, or declarations and
/// routines written without `MODULE name` around them. A controller loads
/// none of these; everything else wrong in such a file follows from it, so
/// this is the only diagnostic.
fn no_module(root: Node<'_>, text: &str) -> Option<Diagnostic> {
    let mut cursor = root.walk();
    if root.children(&mut cursor).any(|c| c.kind() == kind::MODULE) {
        return None;
    }
    // A `MODULE` the parser could not make a module of: its errors say why.
    let mut keyword = false;
    crate::syntax_util::walk_pruned(root, &mut |n| {
        keyword |= n.kind() == "module";
        !keyword
    });
    if keyword {
        return None;
    }
    const MODULE: &str = "a module starts with `MODULE name` and ends with `ENDMODULE`";
    if text.trim_start_matches('\u{feff}').trim().is_empty() {
        return Some(Diagnostic::new(
            &syntax_error::RULE,
            0..0,
            format!("the file is empty: {MODULE}"),
        ));
    }
    let mut first = None;
    crate::syntax_util::walk_pruned(root, &mut |n| {
        if first.is_some() {
            return false;
        }
        if n.kind() == kind::COMMENT {
            return false;
        }
        if n.child_count() == 0 && n.end_byte() > n.start_byte() {
            first = Some(n);
            return false;
        }
        true
    });
    Some(match first {
        None => Diagnostic::new(
            &syntax_error::RULE,
            0..0,
            format!("the file holds no module: {MODULE}"),
        ),
        Some(token) => Diagnostic::new(
            &syntax_error::RULE,
            token.byte_range(),
            format!(
                "expected `MODULE name` before `{}`: declarations and routines go inside a module",
                snippet(text, token.byte_range())
            ),
        ),
    })
}

/// `=` written for `:=` in an error: either the error starts with `=` right
/// after a declaration's or a statement's name (`VAR num n = 0;`,
/// `n = n + 1;`), or it holds a data reference that starts its line followed
/// by `=` (`a.b = 1;`, `a{1} = 2;`).
fn equals_for_assignment(error: Node<'_>, text: &str) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let mut cursor = error.walk();
    let children: Vec<Node<'_>> = error.children(&mut cursor).collect();
    let is_equals = |n: &Node<'_>| !n.is_named() && n.kind() == "=";
    if let Some(first) = children.first().filter(|n| is_equals(n))
        && let Some(prev) = previous_leaf(error)
        && prev.kind() == kind::IDENTIFIER
        && let Some(parent) = prev.parent()
        && (parent.kind() == kind::DATA_DECLARATION
            || (parent.kind() == kind::PROCEDURE_CALL && starts_line(prev, text)))
    {
        out.push(equals_for_assignment::diagnostic(first.byte_range()));
        return out;
    }
    for pair in children.windows(2) {
        let [place, eq] = pair else { continue };
        if is_equals(eq)
            && matches!(
                place.kind(),
                kind::IDENTIFIER | kind::COMPONENT_ACCESS | kind::INDEX_EXPRESSION
            )
            && starts_line(*place, text)
        {
            out.push(equals_for_assignment::diagnostic(eq.byte_range()));
        }
    }
    out
}

/// Is this node the first thing on its line?
fn starts_line(node: Node<'_>, text: &str) -> bool {
    let before = text.get(..node.start_byte()).unwrap_or_default();
    let line_start = before.rfind(['\n', '\r']).map_or(0, |i| i + 1);
    before[line_start..].trim().is_empty()
}

fn missing_diagnostic(node: Node<'_>, language: &Language) -> Diagnostic {
    let what = describe_symbol(language, node.kind_id(), node.kind());
    missing_token::diagnostic(node.start_byte(), &what)
}

fn error_diagnostic(node: Node<'_>, text: &str, language: &Language) -> Diagnostic {
    let found_leaf = first_leaf(node);
    let found = match found_leaf {
        Some(leaf) if leaf.end_byte() > leaf.start_byte() => {
            format!("`{}`", snippet(text, leaf.byte_range()))
        }
        _ => "the end of the file".to_owned(),
    };
    let range = if node.start_position().row == node.end_position().row {
        node.byte_range()
    } else {
        found_leaf.map_or(node.start_byte()..node.start_byte(), |l| l.byte_range())
    };
    let message = match expected_before(node, language) {
        Some(expected) => format!("expected {expected}, found {found}"),
        None => format!("unexpected {found}"),
    };
    let fix = syntax_error::fix(text, &range);
    let d = Diagnostic::new(&syntax_error::RULE, range, message);
    match fix {
        Some(fix) => d.with_fix(fix),
        None => d,
    }
}

/// What the grammar would have accepted where `error` starts, from the parse
/// state after the token before it.
fn expected_before(error: Node<'_>, language: &Language) -> Option<String> {
    let prev = previous_leaf(error)?;
    let state = prev.next_parse_state();
    let mut names: Vec<String> = language
        .lookahead_iterator(state)?
        .filter(|&id| language.node_kind_is_visible(id) && id != 0)
        .filter_map(|id| {
            let kind = language.node_kind_for_id(id)?;
            (kind != "ERROR" && kind != kind::COMMENT).then(|| describe_symbol(language, id, kind))
        })
        .collect();
    names.sort();
    names.dedup();
    if names.is_empty() {
        return None;
    }
    if let Some(semi) = names.iter().find(|n| *n == "`;`") {
        return Some(semi.clone());
    }
    const MOST: usize = 6;
    Some(match names.len() {
        1 => names.remove(0),
        n if n <= MOST => {
            let last = names.pop().unwrap_or_default();
            format!("{} or {last}", names.join(", "))
        }
        n => format!(
            "{} or one of {} other tokens",
            names[..MOST].join(", "),
            n - MOST
        ),
    })
}

/// A person's name for a grammar symbol: keywords and punctuation quoted as
/// written in RAPID, named tokens described.
fn describe_symbol(language: &Language, id: u16, kind: &str) -> String {
    if !language.node_kind_is_named(id) {
        if kind.bytes().all(|b| b.is_ascii_alphabetic()) {
            return format!("`{}`", kind.to_ascii_uppercase());
        }
        return format!("`{kind}`");
    }
    match kind {
        "identifier" => "a name".to_owned(),
        k if k.contains("num") && k.contains("literal") => "a number".to_owned(),
        k if k.contains("string") => "a string".to_owned(),
        k if k.contains("placeholder") => "a placeholder".to_owned(),
        k => format!("`{}`", k.replace('_', " ")),
    }
}

fn first_leaf(node: Node<'_>) -> Option<Node<'_>> {
    let mut node = node.child(0)?;
    while let Some(child) = node.child(0) {
        node = child;
    }
    Some(node)
}

fn previous_leaf(node: Node<'_>) -> Option<Node<'_>> {
    let mut at = node;
    let prev = loop {
        if let Some(prev) = at.prev_sibling() {
            break prev;
        }
        at = at.parent()?;
    };
    Some(last_leaf(prev))
}

/// The last token of `node` (the node itself when it has no children).
fn last_leaf(node: Node<'_>) -> Node<'_> {
    let mut leaf = node;
    while let Some(last) = leaf
        .child_count()
        .checked_sub(1)
        .and_then(|i| leaf.child(i))
    {
        leaf = last;
    }
    leaf
}

/// At most 40 characters of `range`, on one line.
fn snippet(text: &str, range: Range<usize>) -> String {
    let s = text.get(range).unwrap_or_default();
    let line = s.lines().next().unwrap_or_default();
    let mut out: String = line.chars().take(40).collect();
    if out.len() < s.len() {
        out.push('…');
    }
    out
}
