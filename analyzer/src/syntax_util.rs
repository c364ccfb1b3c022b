//! Small helpers over tree-sitter nodes, shared by lowering and checking.

use crate::syntax::{field, kind};
use tree_sitter::Node;

/// The source text of a node ("" if the range is not in `text`).
pub fn text_of<'t>(node: Node<'_>, text: &'t str) -> &'t str {
    text.get(node.byte_range()).unwrap_or_default()
}

/// The grammar's field id for a field name, resolved once per name (tree-
/// sitter's own lookup compares the name with every field name per call).
pub fn field_id(name: &str) -> Option<std::num::NonZeroU16> {
    type Ids = std::collections::HashMap<
        String,
        std::num::NonZeroU16,
        std::hash::BuildHasherDefault<crate::names::NameHasher>,
    >;
    static IDS: std::sync::OnceLock<Ids> = std::sync::OnceLock::new();
    IDS.get_or_init(|| {
        let language = crate::syntax::language();
        (1..=language.field_count())
            .filter_map(|i| {
                let id = u16::try_from(i).ok()?;
                Some((
                    language.field_name_for_id(id)?.to_owned(),
                    std::num::NonZeroU16::new(id)?,
                ))
            })
            .collect()
    })
    .get(name)
    .copied()
}

/// The child in field `name`.
pub fn field<'a>(node: Node<'a>, name: &str) -> Option<Node<'a>> {
    node.child_by_field_id(field_id(name)?.get())
}

/// Every child in field `name`, in order.
pub fn fields<'a>(node: Node<'a>, name: &str) -> Vec<Node<'a>> {
    let Some(id) = field_id(name) else {
        return Vec::new();
    };
    let mut cursor = node.walk();
    node.children_by_field_id(id, &mut cursor).collect()
}

/// Does the node have an anonymous child of this kind (a keyword, which the
/// grammar shows in lower case whatever the source case)?
pub fn has_token(node: Node<'_>, kind: &str) -> bool {
    let mut cursor = node.walk();
    node.children(&mut cursor)
        .any(|c| !c.is_named() && c.kind() == kind)
}

/// Is this node a FlexPendant placeholder such as `<SMT>`?
pub fn is_placeholder(node: Node<'_>) -> bool {
    node.kind() == kind::PLACEHOLDER
}

/// A literal aggregate read from the source text: `[...]` nesting number
/// literals (each optionally signed: `-1`, `+ 2.5`), plain strings and
/// booleans, as the robtargets and data tables that fill real programs are
/// written. Checking it from the text spares walking its many tree nodes.
/// Byte ranges are those of the tree's nodes.
#[derive(Debug)]
pub enum Literal {
    /// A number literal or a signed one (a `unary_expression`).
    Number(std::ops::Range<usize>),
    /// A string literal without escape sequences.
    String(std::ops::Range<usize>),
    /// `TRUE` or `FALSE`.
    Boolean(std::ops::Range<usize>),
    /// A nested aggregate.
    Aggregate(std::ops::Range<usize>, Vec<Literal>),
}

/// How deep literal aggregates are read from the text; deeper ones take the
/// tree's way.
const MAX_LITERAL_DEPTH: usize = 16;

/// Reads the aggregate `node` as a [`Literal`] when its text holds nothing
/// but brackets, commas, blanks and literals; `None` otherwise (names,
/// operations, comments, escape sequences, anything unusual), and for nodes
/// with syntax errors.
pub fn literal_aggregate(node: Node<'_>, text: &str) -> Option<Literal> {
    let mut out = Vec::with_capacity(1);
    read_node(node, text, &mut Read::Literals(&mut out)).then(|| out.pop())?
}

/// Is `node` an aggregate made only of literals (see [`literal_aggregate`])?
/// Reads the text without building the [`Literal`].
pub fn is_literal_aggregate(node: Node<'_>, text: &str) -> bool {
    node.kind_id() == kinds().aggregate && read_node(node, text, &mut Read::Check)
}

/// The shape of an aggregate made only of literals: `[` and `]` around
/// each aggregate, `n`, `s` and `b` for numbers, strings and booleans
/// (`[[nnn][nnnn]]`). Whether such an aggregate fits a type depends on its
/// shape only, not on the values.
pub fn literal_shape(node: Node<'_>, text: &str) -> Option<Vec<u8>> {
    let mut shape = Vec::with_capacity(32);
    read_node(node, text, &mut Read::Shape(&mut shape)).then_some(shape)
}

/// Reads the text of `node` as an aggregate of literals into `out`: whether
/// it is one, from its first byte to its last, without syntax errors.
fn read_node(node: Node<'_>, text: &str, out: &mut Read<'_>) -> bool {
    let range = node.byte_range();
    if range.end > text.len() || node.has_error() {
        return false;
    }
    let mut at = range.start;
    read_aggregate(text.as_bytes(), &mut at, 0, out).is_some() && at == range.end
}

/// What reading an aggregate makes.
enum Read<'a> {
    /// Nothing: the text is only checked.
    Check,
    /// The aggregate's [`Literal`], pushed.
    Literals(&'a mut Vec<Literal>),
    /// Its [`literal_shape`], appended.
    Shape(&'a mut Vec<u8>),
}

impl Read<'_> {
    fn leaf(&mut self, literal: Literal, mark: u8) {
        match self {
            Read::Check => {}
            Read::Literals(out) => out.push(literal),
            Read::Shape(shape) => shape.push(mark),
        }
    }
}

fn skip_blanks(bytes: &[u8], at: &mut usize) {
    while bytes
        .get(*at)
        .is_some_and(|b| matches!(b, b' ' | b'\t' | b'\r' | b'\n'))
    {
        *at += 1;
    }
}

/// Reads an aggregate at `at` into `out`.
fn read_aggregate(bytes: &[u8], at: &mut usize, depth: usize, out: &mut Read<'_>) -> Option<()> {
    if depth > MAX_LITERAL_DEPTH || bytes.get(*at) != Some(&b'[') {
        return None;
    }
    let start = *at;
    *at += 1;
    // The elements of this aggregate go to a list of their own.
    let mut elements = Vec::new();
    let mut inner = match out {
        Read::Check => Read::Check,
        Read::Literals(_) => Read::Literals(&mut elements),
        Read::Shape(shape) => {
            shape.push(b'[');
            Read::Shape(shape)
        }
    };
    loop {
        skip_blanks(bytes, at);
        match bytes.get(*at)? {
            b'[' => read_aggregate(bytes, at, depth + 1, &mut inner)?,
            b'"' => inner.leaf(read_string(bytes, at)?, b's'),
            b't' | b'T' | b'f' | b'F' => inner.leaf(read_boolean(bytes, at)?, b'b'),
            _ => inner.leaf(read_number(bytes, at)?, b'n'),
        }
        skip_blanks(bytes, at);
        match bytes.get(*at)? {
            b',' => *at += 1,
            b']' => {
                *at += 1;
                if let Read::Shape(shape) = inner {
                    shape.push(b']');
                }
                if let Read::Literals(out) = out {
                    out.push(Literal::Aggregate(start..*at, elements));
                }
                return Some(());
            }
            _ => return None,
        }
    }
}

/// Does a name character follow (so that a token would run on)?
fn runs_on(bytes: &[u8], at: usize) -> bool {
    bytes
        .get(at)
        .is_some_and(|b| b.is_ascii_alphanumeric() || matches!(b, b'.' | b'_') || !b.is_ascii())
}

/// A number literal as the grammar's decimal form
/// (`(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?`), optionally after one sign.
fn read_number(bytes: &[u8], at: &mut usize) -> Option<Literal> {
    let start = *at;
    if matches!(bytes.get(*at), Some(b'-' | b'+')) {
        *at += 1;
        skip_blanks(bytes, at);
    }
    let digits = |at: &mut usize| {
        let from = *at;
        while bytes.get(*at).is_some_and(u8::is_ascii_digit) {
            *at += 1;
        }
        *at - from
    };
    let int = digits(at);
    let frac = if bytes.get(*at) == Some(&b'.') {
        *at += 1;
        Some(digits(at))
    } else {
        None
    };
    if int == 0 && matches!(frac, None | Some(0)) {
        return None;
    }
    if matches!(bytes.get(*at), Some(b'e' | b'E')) {
        *at += 1;
        if matches!(bytes.get(*at), Some(b'-' | b'+')) {
            *at += 1;
        }
        if digits(at) == 0 {
            return None;
        }
    }
    if runs_on(bytes, *at) {
        return None;
    }
    Some(Literal::Number(start..*at))
}

/// A string literal on one line without escape sequences (`""`, `\\`).
fn read_string(bytes: &[u8], at: &mut usize) -> Option<Literal> {
    let start = *at;
    *at += 1;
    loop {
        match bytes.get(*at)? {
            b'"' => {
                *at += 1;
                if bytes.get(*at) == Some(&b'"') {
                    return None;
                }
                return Some(Literal::String(start..*at));
            }
            b'\\' | b'\r' | b'\n' => return None,
            _ => *at += 1,
        }
    }
}

/// `TRUE` or `FALSE`, in any case.
fn read_boolean(bytes: &[u8], at: &mut usize) -> Option<Literal> {
    let start = *at;
    let word = ["true", "false"].into_iter().find(|w| {
        bytes
            .get(start..start + w.len())
            .is_some_and(|b| b.eq_ignore_ascii_case(w.as_bytes()))
    })?;
    *at += word.len();
    if runs_on(bytes, *at) {
        return None;
    }
    Some(Literal::Boolean(start..*at))
}

/// The node's kind, as [`Node::kind`] gives it, from a table built once
/// (`Node::kind` checks the name's UTF-8 on every call, which shows in walks
/// over long routines).
pub fn kind<'a>(node: Node<'a>) -> &'a str {
    static NAMES: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    let names = NAMES.get_or_init(|| {
        let language = crate::syntax::language();
        (0..language.node_kind_count())
            .map(|i| {
                u16::try_from(i)
                    .ok()
                    .and_then(|id| language.node_kind_for_id(id))
                    .unwrap_or_default()
                    .to_owned()
            })
            .collect()
    });
    match names.get(usize::from(node.kind_id())) {
        Some(name) if !name.is_empty() => name.as_str(),
        // ERROR and the like are outside the table.
        _ => node.kind(),
    }
}

/// Node kind ids the hot paths compare with.
pub struct Kinds {
    pub aggregate: u16,
}

/// The ids of [`Kinds`], resolved once.
pub fn kinds() -> &'static Kinds {
    static KINDS: std::sync::OnceLock<Kinds> = std::sync::OnceLock::new();
    KINDS.get_or_init(|| {
        let language = crate::syntax::language();
        Kinds {
            aggregate: language.id_for_node_kind(kind::AGGREGATE, true),
        }
    })
}

/// The parts of an `argument` node, read in one pass over its children
/// (each [`field`] call walks them again).
#[derive(Clone, Copy, Default)]
pub struct ArgumentParts<'a> {
    pub name: Option<Node<'a>>,
    pub value: Option<Node<'a>>,
    pub conditional: Option<Node<'a>>,
    /// Written in the optional form, `\Name`.
    pub backslash: bool,
}

pub fn argument_parts(arg: Node<'_>) -> ArgumentParts<'_> {
    struct Ids {
        name: Option<std::num::NonZeroU16>,
        value: Option<std::num::NonZeroU16>,
        conditional: Option<std::num::NonZeroU16>,
    }
    static IDS: std::sync::OnceLock<Ids> = std::sync::OnceLock::new();
    let ids = IDS.get_or_init(|| Ids {
        name: field_id(field::NAME),
        value: field_id(field::VALUE),
        conditional: field_id(field::CONDITIONAL),
    });
    let mut parts = ArgumentParts::default();
    let mut cursor = arg.walk();
    if !cursor.goto_first_child() {
        return parts;
    }
    loop {
        let node = cursor.node();
        if let Some(f) = cursor.field_id() {
            let slot = if Some(f) == ids.name {
                &mut parts.name
            } else if Some(f) == ids.value {
                &mut parts.value
            } else if Some(f) == ids.conditional {
                &mut parts.conditional
            } else {
                &mut None
            };
            if slot.is_none() {
                *slot = Some(node);
            }
        }
        if !node.is_named() && kind(node) == "\\" {
            parts.backslash = true;
        }
        if !cursor.goto_next_sibling() {
            return parts;
        }
    }
}

/// Statements that hold no statement list of their own (the grammar's
/// simple statements, which a compact `IF` can hold).
pub fn is_simple_statement(kind: &str) -> bool {
    matches!(
        kind,
        kind::ASSIGNMENT
            | kind::PROCEDURE_CALL
            | kind::GOTO_STATEMENT
            | kind::RETURN_STATEMENT
            | kind::RAISE_STATEMENT
            | kind::EXIT_STATEMENT
            | kind::RETRY_STATEMENT
            | kind::TRYNEXT_STATEMENT
            | kind::CONNECT_STATEMENT
    )
}

/// Statements that hold statements (`IF`, compact `IF`, `FOR`, `WHILE`,
/// `TEST`).
pub fn is_compound_statement(kind: &str) -> bool {
    matches!(
        kind,
        kind::IF_STATEMENT
            | kind::COMPACT_IF_STATEMENT
            | kind::FOR_STATEMENT
            | kind::WHILE_STATEMENT
            | kind::TEST_STATEMENT
    )
}

/// Calls `f` on the nodes under `node` (pre-order); `f` returns whether to
/// visit the node's children.
pub(crate) fn walk_pruned<'a>(node: Node<'a>, f: &mut impl FnMut(Node<'a>) -> bool) {
    let mut cursor = node.walk();
    loop {
        if f(cursor.node()) && cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.node().id() == node.id() {
                return;
            }
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeSet;

    use crate::syntax::generated::{NAMED_KINDS, fields_of};
    use crate::syntax::{field, kind};

    /// The named kinds a field of `owner` holds, without placeholders.
    fn held(owner: &str, name: &str) -> BTreeSet<&'static str> {
        fields_of(owner)
            .iter()
            .find(|f| f.name == name)
            .map(|f| f.kinds)
            .unwrap_or_default()
            .iter()
            .copied()
            .filter(|k| NAMED_KINDS.contains(k) && *k != kind::PLACEHOLDER)
            .collect()
    }

    // The grammar declares no statement or expression supertypes, so the
    // hand-written categories are checked against what node-types.json says
    // the fields hold.

    #[test]
    fn simple_statements_are_what_a_compact_if_holds() {
        let simple = held(kind::COMPACT_IF_STATEMENT, field::BODY);
        let listed: BTreeSet<&str> = NAMED_KINDS
            .iter()
            .copied()
            .filter(|k| super::is_simple_statement(k))
            .collect();
        assert_eq!(listed, simple);
    }

    #[test]
    fn statements_are_simple_or_compound() {
        let mut statements = held(kind::PROCEDURE_DECLARATION, field::BODY);
        statements.remove(kind::DATA_DECLARATION);
        statements.remove(kind::LABEL);
        let listed: BTreeSet<&str> = NAMED_KINDS
            .iter()
            .copied()
            .filter(|k| super::is_simple_statement(k) != super::is_compound_statement(k))
            .collect();
        assert_eq!(listed, statements);
        assert!(
            !NAMED_KINDS
                .iter()
                .any(|k| super::is_simple_statement(k) && super::is_compound_statement(k))
        );
    }

    #[test]
    fn expression_kinds_are_what_an_assignment_assigns() {
        let listed: BTreeSet<&str> = crate::lower::EXPRESSION_KINDS.iter().copied().collect();
        assert_eq!(listed, held(kind::ASSIGNMENT, field::RIGHT));
    }
}
