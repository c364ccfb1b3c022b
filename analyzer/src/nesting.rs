//! A bound on the depth of the trees the analyzer works on.
//!
//! Tree-sitter parses without recursion, so a module can nest expressions or
//! statements as deep as its text allows (generated code does: a sum of
//! thousands of terms, thousands of nested `IF`s). Everything after the
//! parse (the checker, type inference, lowering, constant folding, the
//! editor features) walks the tree by recursion, or walks up parent chains
//! (tree-sitter finds a node's parent from the root, so a chain costs the
//! square of its depth); neither survives a tree 100,000 levels deep.
//!
//! So the depth is bounded once, where a unit gets its tree: a tree deeper
//! than [`MAX_DEPTH`] is parsed again from a copy of the text in which each
//! over-deep part (the outermost statement or expression around the
//! deepest point: a routine's statement, a declaration's value) is replaced
//! by a FlexPendant placeholder of the same syntactic kind (`<EXP>` for an
//! expression, `<SMT>` for a statement),
//! padded with blanks so that every byte offset, line and column stays where
//! it was. The unit keeps its real text; its tree is that of the copy, and
//! each replaced part (a [`Cut`]) is reported once as `nesting-too-deep`.
//! Every consumer of the tree sees at most [`MAX_DEPTH`] levels without
//! knowing about the limit. Findings inside a cut are dropped (it is not
//! analysed), and so are the unused-name findings about names written in a
//! cut (their uses there are not seen).

use std::borrow::Cow;
use std::ops::Range;

use tree_sitter::{Node, Tree};

use crate::diagnostic::Diagnostic;
use crate::rules::nesting_too_deep;

/// The deepest tree the analyzer works on, in tree levels from the root.
/// Real programs stay far below it (the deepest of the corpus of 831 real
/// modules is 36 levels); the recursive walks after the parse need about
/// 3 KB of stack per level in a debug build, so 2 MB threads hold it with
/// room to spare.
pub const MAX_DEPTH: usize = 256;

/// How many times a text is parsed again before the last resort (blanking
/// whole declarations): a replacement keeps the parse around it, so one
/// round is enough for well-formed code; broken code may need more.
const MAX_ROUNDS: usize = 4;

/// A part of a unit's text that the analyzer does not read, because it
/// nests deeper than [`MAX_DEPTH`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Cut {
    /// The bytes replaced.
    pub range: Range<usize>,
    /// What replaced them.
    pub kind: CutKind,
    /// Whether the replaced text had a syntax error.
    pub had_error: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CutKind {
    /// An expression, read as `<EXP>`.
    Expression,
    /// A statement, read as `<SMT>`.
    Statement,
    /// Anything else (broken code), read as blanks.
    Blank,
}

impl CutKind {
    fn placeholder(self) -> &'static str {
        match self {
            CutKind::Expression => "<EXP>",
            CutKind::Statement => "<SMT>",
            CutKind::Blank => "",
        }
    }

    fn describe(self) -> &'static str {
        match self {
            CutKind::Expression => "this expression",
            CutKind::Statement => "this statement",
            CutKind::Blank => "this code",
        }
    }
}

/// `tree` (parsed from `text`) if it is at most [`MAX_DEPTH`] deep;
/// otherwise the tree of `text` with its over-deep parts replaced, and those
/// parts.
pub(crate) fn bound(text: &str, tree: Tree) -> (Tree, Vec<Cut>) {
    let found = survey(&tree);
    if found.is_empty() {
        return (tree, Vec::new());
    }
    let mut tree = tree;
    let mut cuts = merge(found);
    for round in 1..=MAX_ROUNDS {
        tree = parse_copy(text, &cuts);
        let more = survey(&tree);
        if more.is_empty() {
            break;
        }
        if round == MAX_ROUNDS {
            // Last resort: blank the top-level items that are still too
            // deep (the copy then has no such item at all).
            cuts.extend(more.iter().filter_map(|c| top_level(&tree, c.range.start)));
            cuts = merge(cuts);
            tree = parse_copy(text, &cuts);
            break;
        }
        cuts.extend(more);
        cuts = merge(cuts);
    }
    (tree, cuts)
}

/// The tree of `text` with `cuts` replaced. It is marked as such (its
/// included range ends at the text's end, where a plain parse's is
/// unbounded), so that it is never the old tree of an incremental parse of
/// the real text ([`is_copy`]): tree-sitter would keep its placeholders
/// where the text has none.
pub(crate) fn parse_copy(text: &str, cuts: &[Cut]) -> Tree {
    let copy = substitute(text, cuts);
    let mut parser = crate::syntax::parser();
    let (rows, line_start) = copy
        .bytes()
        .enumerate()
        .filter(|(_, b)| *b == b'\n')
        .fold((0, 0), |(rows, _), (i, _)| (rows + 1, i + 1));
    let marked = parser.set_included_ranges(&[tree_sitter::Range {
        start_byte: 0,
        end_byte: copy.len(),
        start_point: tree_sitter::Point::new(0, 0),
        end_point: tree_sitter::Point::new(rows, copy.len() - line_start),
    }]);
    match crate::syntax::parse(&mut parser, &copy, None) {
        Some(tree) if marked.is_ok() => tree,
        // Never: the range is valid, and no parse is ever cancelled.
        _ => empty_tree(),
    }
}

fn empty_tree() -> Tree {
    match crate::syntax::parse(&mut crate::syntax::parser(), "", None) {
        Some(tree) => tree,
        None => panic!("tree-sitter returned no tree for an empty text"),
    }
}

/// Was `tree` parsed by [`parse_copy`], from a text with cuts? (A plain
/// parse's one range is unbounded.)
pub(crate) fn is_copy(tree: &Tree) -> bool {
    matches!(tree.included_ranges().as_slice(), [r] if r.start_byte == 0 && r.end_byte < u32::MAX as usize)
}

/// The text the tree of a unit with `cuts` is parsed from.
pub(crate) fn substitute<'a>(text: &'a str, cuts: &[Cut]) -> Cow<'a, str> {
    if cuts.is_empty() {
        return Cow::Borrowed(text);
    }
    let mut bytes = text.as_bytes().to_vec();
    for cut in cuts {
        let Some(span) = bytes.get_mut(cut.range.clone()) else {
            continue;
        };
        // Blanks, keeping line breaks so that lines and columns stay.
        for b in span.iter_mut() {
            if !matches!(*b, b'\n' | b'\r') {
                *b = b' ';
            }
        }
        let word = cut.kind.placeholder();
        if let Some(at) = placeholder_at(text, &cut.range, word.len())
            && let Some(slot) = bytes.get_mut(at..at + word.len())
        {
            slot.copy_from_slice(word.as_bytes());
        }
    }
    // Only whole characters were replaced, by ASCII.
    match String::from_utf8(bytes) {
        Ok(s) => Cow::Owned(s),
        Err(_) => Cow::Borrowed(text),
    }
}

/// Where a placeholder of `len` bytes goes in `range`: the first place
/// where it starts and ends on characters of the real text and crosses no
/// line break (so that the tree's nodes outside it read whole characters).
fn placeholder_at(text: &str, range: &Range<usize>, len: usize) -> Option<usize> {
    if len == 0 {
        return None;
    }
    let end = range.end.checked_sub(len)?;
    (range.start..=end).find(|&at| {
        text.is_char_boundary(at)
            && text.is_char_boundary(at + len)
            && !text.as_bytes()[at..at + len]
                .iter()
                .any(|b| matches!(b, b'\n' | b'\r'))
    })
}

/// The `nesting-too-deep` diagnostics of a unit's cuts: one per cut, on its
/// first line.
pub fn diagnostics(text: &str, cuts: &[Cut]) -> Vec<Diagnostic> {
    cuts.iter()
        .map(|cut| {
            let start = cut.range.start;
            let line_end = text
                .get(start..cut.range.end)
                .and_then(|s| s.find(['\n', '\r']))
                .map_or(cut.range.end, |i| start + i);
            let end = floor_char_boundary(text, line_end.min(start + 80));
            let error = if cut.had_error {
                " (it also has a syntax error)"
            } else {
                ""
            };
            Diagnostic::new(
                &nesting_too_deep::RULE,
                start..end.max(start),
                format!(
                    "{} nests deeper than {MAX_DEPTH} levels and is not analysed{error}",
                    cut.kind.describe()
                ),
            )
        })
        .collect()
}

fn floor_char_boundary(text: &str, mut at: usize) -> usize {
    at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

/// Does a finding of a unit with `cuts` stand? Findings inside a cut are
/// about text the analyzer did not read; an unused-name finding stands
/// only if the name is written in no cut.
pub fn keeps(text: &str, cuts: &[Cut], d: &Diagnostic) -> bool {
    if cuts.is_empty() {
        return true;
    }
    if cuts
        .iter()
        .any(|c| c.range.start <= d.range.start && d.range.end <= c.range.end)
    {
        return false;
    }
    let unused = [
        &crate::rules::unused_data::RULE,
        &crate::rules::unused_parameter::RULE,
        &crate::rules::unused_routine::RULE,
    ];
    if !unused.iter().any(|r| std::ptr::eq(*r, d.rule)) {
        return true;
    }
    let Some(name) = text.get(d.range.clone()).filter(|n| !n.is_empty()) else {
        return true;
    };
    !cuts.iter().any(|c| {
        text.get(c.range.clone())
            .is_some_and(|t| contains_word(t.as_bytes(), name.as_bytes()))
    })
}

/// Does `hay` hold `word` (ASCII case folded) between non-name characters?
fn contains_word(hay: &[u8], word: &[u8]) -> bool {
    let is_name = |b: u8| b.is_ascii_alphanumeric() || b == b'_' || !b.is_ascii();
    hay.windows(word.len()).enumerate().any(|(i, w)| {
        w.eq_ignore_ascii_case(word)
            && (i == 0 || !is_name(hay[i - 1]))
            && hay.get(i + word.len()).is_none_or(|b| !is_name(*b))
    })
}

/// Walks `tree` without recursion: the parts to replace, each the
/// outermost expression or statement above a node at [`MAX_DEPTH`] levels. Only
/// subtrees with enough nodes to reach that depth are entered (a node's
/// count of descendants is stored in it), so a normal module costs a walk
/// over its routines and large statements, not over every node.
fn survey(tree: &Tree) -> Vec<Cut> {
    let kinds = kinds();
    let mut out = Vec::new();
    let mut cursor = tree.walk();
    // Levels below the root.
    let mut depth = 0;
    loop {
        if depth >= MAX_DEPTH {
            // The outermost expression or statement above (its statement
            // in a routine, or a declaration's value); if there is none
            // (broken code), the top-level item, blanked. Not the
            // innermost: each of hundreds of statements around it would
            // still be read whole by the checks of its text.
            let mut up = cursor.clone();
            let mut levels = 0;
            let mut outermost = None;
            while levels + 1 < depth {
                if cut_kind(kinds, up.node()).is_some() {
                    outermost = Some(levels);
                }
                up.goto_parent();
                levels += 1;
            }
            let levels = outermost.unwrap_or(levels);
            let mut up = cursor.clone();
            for _ in 0..levels {
                up.goto_parent();
            }
            let cut = up.node();
            out.push(Cut {
                range: cut.byte_range(),
                kind: cut_kind(kinds, cut).unwrap_or(CutKind::Blank),
                had_error: cut.has_error(),
            });
            // Go on after the cut node.
            for _ in 0..levels {
                cursor.goto_parent();
            }
            depth -= levels;
        } else if depth + cursor.node().descendant_count() > MAX_DEPTH && cursor.goto_first_child()
        {
            depth += 1;
            continue;
        }
        // The next node after the cursor's subtree.
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return out;
            }
            depth -= 1;
        }
    }
}

/// The top-level item (child of the root) at `offset`, blanked.
fn top_level(tree: &Tree, offset: usize) -> Option<Cut> {
    let root = tree.root_node();
    let mut cursor = root.walk();
    let item = root
        .children(&mut cursor)
        .find(|c| c.start_byte() <= offset && offset < c.end_byte().max(c.start_byte() + 1))?;
    // A module: blank the item of its body at `offset`, if there is one.
    let mut inner = item.walk();
    let target = item
        .children(&mut inner)
        .find(|c| c.is_named() && c.start_byte() <= offset && offset < c.end_byte())
        .unwrap_or(item);
    Some(Cut {
        range: target.byte_range(),
        kind: CutKind::Blank,
        had_error: target.has_error(),
    })
}

/// Sorts `cuts` and merges those that overlap (later rounds may replace a
/// part around an earlier one): a merged cut is replaced as its outermost
/// part is.
fn merge(mut cuts: Vec<Cut>) -> Vec<Cut> {
    cuts.sort_by(|a, b| {
        (a.range.start, std::cmp::Reverse(a.range.end))
            .cmp(&(b.range.start, std::cmp::Reverse(b.range.end)))
    });
    let mut out: Vec<Cut> = Vec::with_capacity(cuts.len());
    for cut in cuts {
        match out.last_mut() {
            Some(last) if cut.range.start < last.range.end => {
                last.range.end = last.range.end.max(cut.range.end);
                last.had_error |= cut.had_error;
            }
            _ => out.push(cut),
        }
    }
    out
}

/// Node kind ids the survey compares with.
struct Kinds {
    expressions: Vec<u16>,
    statements: Vec<u16>,
}

fn kinds() -> &'static Kinds {
    use crate::syntax::kind;
    static KINDS: std::sync::OnceLock<Kinds> = std::sync::OnceLock::new();
    KINDS.get_or_init(|| {
        let language = crate::syntax::language();
        let ids = |names: &[&str]| {
            names
                .iter()
                .map(|n| language.id_for_node_kind(n, true))
                .filter(|id| *id != 0)
                .collect()
        };
        Kinds {
            // Expressions with parts: they stand where `<EXP>` may.
            expressions: ids(&[
                kind::BINARY_EXPRESSION,
                kind::UNARY_EXPRESSION,
                kind::PARENTHESIZED_EXPRESSION,
                kind::FUNCTION_CALL,
                kind::AGGREGATE,
                kind::COMPONENT_ACCESS,
                kind::INDEX_EXPRESSION,
            ]),
            statements: ids(&[
                kind::ASSIGNMENT,
                kind::PROCEDURE_CALL,
                kind::IF_STATEMENT,
                kind::COMPACT_IF_STATEMENT,
                kind::FOR_STATEMENT,
                kind::WHILE_STATEMENT,
                kind::TEST_STATEMENT,
                kind::RETURN_STATEMENT,
                kind::RAISE_STATEMENT,
                kind::CONNECT_STATEMENT,
                kind::GOTO_STATEMENT,
            ]),
        }
    })
}

fn cut_kind(kinds: &Kinds, node: Node<'_>) -> Option<CutKind> {
    let id = node.kind_id();
    if node.is_error() || node.is_missing() {
        None
    } else if kinds.expressions.contains(&id) {
        Some(CutKind::Expression)
    } else if kinds.statements.contains(&id) {
        Some(CutKind::Statement)
    } else {
        None
    }
}
