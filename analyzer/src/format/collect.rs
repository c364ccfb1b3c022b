//! From the syntax tree to the formatter's token list: every leaf of the tree
//! (a string literal counts as one leaf) in source order, with what the tree
//! says about its place in the layout.

use std::borrow::Cow;
use std::ops::Range;

use std::num::NonZeroU16;
use std::sync::OnceLock;

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
const SAME_LEVEL_KINDS: &[&str] = &[
    "error_handler",
    "backward_handler",
    "undo_handler",
    "elseif_clause",
    "else_clause",
];

/// Node kinds that start a line one level deeper than their parent.
const DEEPER_KINDS: &[&str] = &["test_case", "default_case", "record_component"];

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
    /// The next leaf is the name of a called procedure.
    next_is_proc_name: bool,
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
        next_is_proc_name: false,
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
        let k = kinds();
        let flags = k.flags(node);
        if is_atomic_with(node, flags) {
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
        let mut index = 0;
        let mut previous_routine = false;
        let mut after_comma = false;
        let wrap_args = flags & ARGUMENT_LIST != 0 && k.flags(parent) & PROCEDURE_CALL != 0;
        let is_call = flags & PROCEDURE_CALL != 0;
        loop {
            let child = cursor.node();
            let child_flags = k.flags(child);
            if child.is_extra() || child_flags & COMMENT != 0 {
                self.leaf(child, node);
            } else {
                let child_indent = self.place(&cursor, flags, child_flags, index, indent);
                if flags & MODULE != 0 && k.is_body(&cursor) {
                    let routine = child_flags & ROUTINE != 0;
                    self.pending.unit_start_after_unit = routine && previous_routine;
                    previous_routine = routine;
                }
                if wrap_args && after_comma {
                    self.pending.wrap_point = true;
                }
                after_comma = wrap_args && child_flags & COMMA != 0;
                self.next_is_proc_name = is_call
                    && cursor.field_id().is_some()
                    && cursor.field_id() == k.name_field
                    && child.child_count() == 0;
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
        parent_flags: u32,
        flags: u32,
        index: usize,
        indent: usize,
    ) -> usize {
        let iw = self.indent_width;
        let opens = flags & BLOCK != 0;
        let mut start = |column: usize, closer: bool, no_blank: bool| {
            self.pending.line_start = Some(column);
            self.pending.closer = closer;
            self.pending.no_blank = no_blank;
            self.pending.opens = opens;
        };
        if parent_flags & COMPACT_IF != 0 {
            indent
        } else if parent_flags & MODULE_HEADER != 0 {
            if flags & HEADER_MARK != 0 {
                start(0, false, index != 0);
            } else if flags & HEADER_ENTRY != 0 {
                start(2, false, true);
            }
            indent
        } else if parent_flags & MODULE != 0 && flags & MODULE_KEYWORD != 0 {
            start(indent, false, false);
            self.pending.opens = true;
            indent
        } else if flags & (END_KEYWORD | SAME_LEVEL) != 0 {
            start(indent, true, false);
            indent
        } else if flags & DEEPER != 0 {
            start(indent + iw, flags & RECORD_COMPONENT == 0, false);
            indent + iw
        } else if flags & NAMED != 0 && kinds().is_body(cursor) {
            start(indent + iw, false, false);
            indent + iw
        } else {
            indent
        }
    }

    /// Emits one token.
    fn leaf(&mut self, node: Node<'_>, parent: Node<'_>) {
        let range = node.byte_range();
        let proc_name = std::mem::take(&mut self.next_is_proc_name);
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
            proc_name: proc_name && class != Class::Comment,
        });
    }
}

/// Leaves, and string literals (whose inside is not the formatter's business).
pub(super) fn is_atomic(node: Node<'_>) -> bool {
    is_atomic_with(node, kinds().flags(node))
}

fn is_atomic_with(node: Node<'_>, flags: u32) -> bool {
    flags & STRING != 0 || node.child_count() == 0
}

// What the formatter needs to know of a node kind, as bits, looked up by
// kind id (comparing kind names for every node would cost more than the
// layout itself).
const NAMED: u32 = 1;
const COMMENT: u32 = 1 << 1;
const TRAILING: u32 = 1 << 2;
const STRING: u32 = 1 << 3;
const MODULE: u32 = 1 << 4;
const MODULE_KEYWORD: u32 = 1 << 5;
const MODULE_HEADER: u32 = 1 << 6;
const HEADER_MARK: u32 = 1 << 7;
const HEADER_ENTRY: u32 = 1 << 8;
const COMPACT_IF: u32 = 1 << 9;
const ARGUMENT_LIST: u32 = 1 << 10;
const PROCEDURE_CALL: u32 = 1 << 11;
const ARGUMENT: u32 = 1 << 12;
const OPTIONAL_PARAMETER: u32 = 1 << 13;
const UNARY_EXPRESSION: u32 = 1 << 14;
const END_KEYWORD: u32 = 1 << 15;
const KEYWORD: u32 = 1 << 16;
const SAME_LEVEL: u32 = 1 << 17;
const DEEPER: u32 = 1 << 18;
const BLOCK: u32 = 1 << 19;
const ROUTINE: u32 = 1 << 20;
const RECORD_COMPONENT: u32 = 1 << 21;
const COMMA: u32 = 1 << 22;

struct Kinds {
    flags: Vec<u32>,
    body_field: Option<NonZeroU16>,
    name_field: Option<NonZeroU16>,
}

impl Kinds {
    fn new() -> Kinds {
        let language = crate::syntax::language();
        let count = language.node_kind_count();
        let mut flags = vec![0; count];
        for (id, f) in flags.iter_mut().enumerate() {
            let Ok(id) = u16::try_from(id) else { break };
            let Some(name) = language.node_kind_for_id(id) else {
                continue;
            };
            *f = kind_flags(name, language.node_kind_is_named(id));
        }
        Kinds {
            flags,
            body_field: language.field_id_for_name("body"),
            name_field: language.field_id_for_name("name"),
        }
    }

    fn flags(&self, node: Node<'_>) -> u32 {
        self.flags
            .get(usize::from(node.kind_id()))
            .copied()
            .unwrap_or(0)
    }

    fn is_body(&self, cursor: &TreeCursor<'_>) -> bool {
        cursor.field_id().is_some() && cursor.field_id() == self.body_field
    }
}

fn kinds() -> &'static Kinds {
    static KINDS: OnceLock<Kinds> = OnceLock::new();
    KINDS.get_or_init(Kinds::new)
}

fn kind_flags(name: &str, named: bool) -> u32 {
    let mut f = 0;
    let mut set = |cond: bool, bit: u32| {
        if cond {
            f |= bit;
        }
    };
    if named {
        set(true, NAMED);
        set(name == "comment", COMMENT);
        set(name == "trailing_text", TRAILING);
        set(name == "string", STRING);
        set(name == "module", MODULE);
        set(name == "module_header", MODULE_HEADER);
        set(name == "header_entry", HEADER_ENTRY);
        set(name == "compact_if_statement", COMPACT_IF);
        set(name == "argument_list", ARGUMENT_LIST);
        set(name == "procedure_call", PROCEDURE_CALL);
        set(name == "argument", ARGUMENT);
        set(name == "optional_parameter", OPTIONAL_PARAMETER);
        set(name == "unary_expression", UNARY_EXPRESSION);
        set(SAME_LEVEL_KINDS.contains(&name), SAME_LEVEL);
        set(DEEPER_KINDS.contains(&name), DEEPER);
        set(BLOCKS.contains(&name), BLOCK);
        set(ROUTINES.contains(&name), ROUTINE);
        set(name == "record_component", RECORD_COMPONENT);
    } else {
        let keyword = !name.is_empty() && name.bytes().all(|b| b.is_ascii_alphabetic());
        set(keyword, KEYWORD);
        set(
            keyword && name.len() > 3 && name.starts_with("end"),
            END_KEYWORD,
        );
        set(name == "module", MODULE_KEYWORD);
        set(name == "%%%", HEADER_MARK);
        set(name == ",", COMMA);
    }
    f
}

fn classify(node: Node<'_>, parent: Node<'_>) -> Class {
    let k = kinds();
    let flags = k.flags(node);
    if flags & NAMED != 0 {
        return if flags & COMMENT != 0 {
            Class::Comment
        } else if flags & TRAILING != 0 {
            Class::Verbatim
        } else {
            Class::Word
        };
    }
    if flags & KEYWORD != 0 {
        return Class::Keyword;
    }
    let parent_flags = k.flags(parent);
    match node.kind() {
        "," => Class::Comma,
        ";" => Class::Semicolon,
        ":" => Class::Colon,
        "." => Class::Dot,
        "(" | "[" | "{" => Class::Open,
        ")" | "]" | "}" => Class::Close,
        "\\" if parent_flags & OPTIONAL_PARAMETER != 0 => Class::BackslashParameter,
        "\\" => Class::BackslashArgument,
        ":=" if parent_flags & ARGUMENT != 0 => Class::AssignTight,
        ":=" => Class::AssignWide,
        "?" => Class::Question,
        "%" if parent.child(0).is_some_and(|first| first.id() == node.id()) => Class::PercentOpen,
        "%" => Class::PercentClose,
        "+" | "-" if parent_flags & UNARY_EXPRESSION != 0 => Class::Unary,
        _ => Class::Operator,
    }
}
