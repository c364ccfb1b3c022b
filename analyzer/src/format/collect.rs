//! From the syntax tree to the formatter's token list: every leaf of the tree
//! (a string literal counts as one leaf) in source order, with what the tree
//! says about its place in the layout.

use std::borrow::Cow;
use std::ops::Range;

use tree_sitter::{Node, TreeCursor};

/// How a token behaves towards its neighbours on a line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Class {
    /// Names, numbers, strings, placeholders, `*` as an argument.
    Word,
    /// A reserved word, written in upper case.
    Keyword,
    Comma,
    Semicolon,
    /// `:` of labels, `CASE ...:`, `DEFAULT:` and header entries: tight.
    Colon,
    Dot,
    /// `(`, `[`, `{`.
    Open,
    /// `)`, `]`, `}`.
    Close,
    /// `\` of an optional argument: tight to the argument before it.
    BackslashArgument,
    /// `\` of an optional parameter.
    BackslashParameter,
    /// `:=` of a named or optional argument: tight.
    AssignTight,
    /// `:=` of an assignment or a declaration: spaced.
    AssignWide,
    /// `?` of a conditional argument: tight.
    Question,
    /// The `%` opening a late-bound procedure name.
    PercentOpen,
    /// The `%` closing it.
    PercentClose,
    /// Unary `+` and `-`: tight to their operand.
    Unary,
    /// Binary operators and anything else: spaced.
    Operator,
    Comment,
    /// Text after `ENDMODULE` that is not RAPID: kept byte for byte, with
    /// the blanks around it.
    Verbatim,
}

/// One token and its layout facts.
#[derive(Debug)]
pub(super) struct Tok<'t> {
    /// Where the token is in the original text.
    pub range: Range<usize>,
    /// What to write: the original text, keywords in upper case, comments
    /// without trailing blanks.
    pub text: Cow<'t, str>,
    pub class: Class,
    /// The structure puts this token first on a line, at this column.
    pub line_start: Option<usize>,
    /// A line-starting token that closes or splits a block (`ENDIF`, `ELSE`,
    /// `ERROR`, `CASE`...): a comment just before it belongs to the block
    /// body and is indented one level deeper.
    pub closer: bool,
    /// A line-starting token that opens a block (`PROC`, `IF`, `ELSE`,
    /// `TEST`, `CASE`, `ERROR`...): the lines after it are one level deeper.
    pub opens: bool,
    /// First token of a routine (or module) that follows another one: the two
    /// are separated by exactly one blank line.
    pub unit_start_after_unit: bool,
    /// The line may be broken before this token when it is too long (an
    /// argument of a procedure call after its comma).
    pub wrap_point: bool,
    /// No blank line before this token (inside the `%%%` header).
    pub no_blank: bool,
    /// The name of a called procedure: spaced from its arguments.
    pub proc_name: bool,
}

/// Node kinds that start a line at their parent's level.
const SAME_LEVEL: &[&str] = &[
    "error_handler",
    "backward_handler",
    "undo_handler",
    "elseif_clause",
    "else_clause",
];

/// Node kinds that start a line one level deeper than their parent.
const DEEPER: &[&str] = &["test_case", "default_case", "record_component"];

/// Node kinds whose first line opens a block of deeper lines.
const BLOCKS: &[&str] = &[
    "module",
    "procedure_declaration",
    "function_declaration",
    "trap_declaration",
    "record_declaration",
    "if_statement",
    "elseif_clause",
    "else_clause",
    "for_statement",
    "while_statement",
    "test_statement",
    "test_case",
    "default_case",
    "error_handler",
    "backward_handler",
    "undo_handler",
];

const ROUTINES: &[&str] = &[
    "procedure_declaration",
    "function_declaration",
    "trap_declaration",
];

#[derive(Clone, Copy, Default)]
struct Pending {
    line_start: Option<usize>,
    closer: bool,
    opens: bool,
    no_blank: bool,
    unit_start_after_unit: bool,
    wrap_point: bool,
}

pub(super) struct Collector<'t> {
    text: &'t str,
    indent_width: usize,
    pub toks: Vec<Tok<'t>>,
    pending: Pending,
    depth: usize,
    too_deep: bool,
}

/// How deep the tree may nest: the walk is recursive, and a formatter
/// thread's stack must hold it (real code nests a few dozen levels; a
/// generated expression of thousands of terms nests as deep as it is long).
pub(super) const MAX_DEPTH: usize = 1500;

/// The tokens of a tree without errors; `None` if it nests deeper than
/// [`MAX_DEPTH`].
pub(super) fn collect<'t>(
    root: Node<'_>,
    text: &'t str,
    indent_width: usize,
) -> Option<Vec<Tok<'t>>> {
    let mut c = Collector {
        text,
        indent_width,
        toks: Vec::new(),
        pending: Pending::default(),
        depth: 0,
        too_deep: false,
    };
    let mut cursor = root.walk();
    let mut previous_module = false;
    for child in root.children(&mut cursor) {
        match child.kind() {
            "module" => {
                c.pending = Pending {
                    line_start: Some(0),
                    opens: true,
                    unit_start_after_unit: previous_module,
                    ..Pending::default()
                };
                c.node(child, root, 0);
                previous_module = true;
            }
            "comment" => c.leaf(child, root),
            _ => {
                // trailing text (kept verbatim), or anything new
                c.pending = Pending::default();
                c.leaf(child, root);
                previous_module = false;
            }
        }
    }
    (!c.too_deep).then_some(c.toks)
}

impl<'t> Collector<'t> {
    /// Emits the tokens of `node`, whose own line (if it starts one) is at
    /// column `indent`.
    fn node(&mut self, node: Node<'_>, parent: Node<'_>, indent: usize) {
        if is_atomic(node) {
            self.leaf(node, parent);
            return;
        }
        if self.depth >= MAX_DEPTH {
            self.too_deep = true;
            return;
        }
        let mut cursor = node.walk();
        if !cursor.goto_first_child() {
            return;
        }
        self.depth += 1;
        let kind = node.kind();
        let mut index = 0;
        let mut previous_routine = false;
        let mut after_comma = false;
        let wrap_args = kind == "argument_list" && parent.kind() == "procedure_call";
        loop {
            let child = cursor.node();
            if child.is_extra() || child.kind() == "comment" {
                self.leaf(child, node);
            } else {
                let child_indent = self.place(&cursor, node, index, indent);
                if kind == "module" && is_field(&cursor, "body") {
                    let routine = ROUTINES.contains(&child.kind());
                    self.pending.unit_start_after_unit = routine && previous_routine;
                    previous_routine = routine;
                }
                if wrap_args && after_comma {
                    self.pending.wrap_point = true;
                }
                after_comma = wrap_args && child.kind() == ",";
                self.node(child, node, child_indent);
            }
            index += 1;
            if !cursor.goto_next_sibling() {
                break;
            }
        }
        self.depth -= 1;
    }

    /// Decides whether the child under `cursor` starts a line (setting the
    /// pending line start), and returns the indentation of its own lines.
    fn place(
        &mut self,
        cursor: &TreeCursor<'_>,
        parent: Node<'_>,
        index: usize,
        indent: usize,
    ) -> usize {
        let child = cursor.node();
        let kind = child.kind();
        let iw = self.indent_width;
        let opens = BLOCKS.contains(&kind);
        let mut start = |column: usize, closer: bool, no_blank: bool| {
            self.pending.line_start = Some(column);
            self.pending.closer = closer;
            self.pending.no_blank = no_blank;
            self.pending.opens = opens;
        };
        match parent.kind() {
            "compact_if_statement" => indent,
            "module_header" => {
                if kind == "%%%" {
                    start(0, false, index != 0);
                } else if kind == "header_entry" {
                    start(2, false, true);
                }
                indent
            }
            "module" if kind == "module" => {
                start(indent, false, false);
                self.pending.opens = true;
                indent
            }
            _ if !child.is_named() && is_end_keyword(kind) => {
                start(indent, true, false);
                indent
            }
            _ if SAME_LEVEL.contains(&kind) => {
                start(indent, true, false);
                indent
            }
            _ if DEEPER.contains(&kind) => {
                let closer = kind != "record_component";
                start(indent + iw, closer, false);
                indent + iw
            }
            _ if child.is_named() && is_field(cursor, "body") => {
                start(indent + iw, false, false);
                indent + iw
            }
            _ => indent,
        }
    }

    /// Emits one token.
    fn leaf(&mut self, node: Node<'_>, parent: Node<'_>) {
        let range = node.byte_range();
        if range.is_empty() {
            return;
        }
        let raw = self.text.get(range.clone()).unwrap_or_default();
        let class = classify(node, parent);
        let text = match class {
            Class::Keyword => Cow::Owned(raw.to_ascii_uppercase()),
            Class::Comment => Cow::Borrowed(raw.trim_end_matches([' ', '\t', '\u{c}'])),
            _ => Cow::Borrowed(raw),
        };
        let pending = if class == Class::Comment {
            Pending::default()
        } else {
            std::mem::take(&mut self.pending)
        };
        let proc_name = parent.kind() == "procedure_call"
            && parent
                .child_by_field_name("name")
                .is_some_and(|n| n.id() == node.id());
        self.toks.push(Tok {
            range,
            text,
            class,
            line_start: pending.line_start,
            closer: pending.closer,
            opens: pending.opens,
            unit_start_after_unit: pending.unit_start_after_unit,
            wrap_point: pending.wrap_point,
            no_blank: pending.no_blank,
            proc_name,
        });
    }
}

fn is_field(cursor: &TreeCursor<'_>, name: &str) -> bool {
    cursor.field_name() == Some(name)
}

/// Leaves, and string literals (whose inside is not the formatter's business).
pub(super) fn is_atomic(node: Node<'_>) -> bool {
    node.child_count() == 0 || node.kind() == "string"
}

fn is_keyword(kind: &str) -> bool {
    !kind.is_empty() && kind.bytes().all(|b| b.is_ascii_alphabetic())
}

fn is_end_keyword(kind: &str) -> bool {
    kind.len() > 3 && kind.starts_with("end") && is_keyword(kind)
}

fn classify(node: Node<'_>, parent: Node<'_>) -> Class {
    let kind = node.kind();
    if node.is_named() {
        return match kind {
            "comment" => Class::Comment,
            "trailing_text" => Class::Verbatim,
            _ => Class::Word,
        };
    }
    match kind {
        "," => Class::Comma,
        ";" => Class::Semicolon,
        ":" => Class::Colon,
        "." => Class::Dot,
        "(" | "[" | "{" => Class::Open,
        ")" | "]" | "}" => Class::Close,
        "\\" if parent.kind() == "optional_parameter" => Class::BackslashParameter,
        "\\" => Class::BackslashArgument,
        ":=" if parent.kind() == "argument" => Class::AssignTight,
        ":=" => Class::AssignWide,
        "?" => Class::Question,
        "%" if parent.child(0).is_some_and(|first| first.id() == node.id()) => Class::PercentOpen,
        "%" => Class::PercentClose,
        "+" | "-" if parent.kind() == "unary_expression" => Class::Unary,
        k if is_keyword(k) => Class::Keyword,
        _ => Class::Operator,
    }
}
