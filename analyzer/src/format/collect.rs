//! From the syntax tree to the formatter's token list: every leaf of the tree
//! (a string literal counts as one leaf) in source order, with what the tree
//! says about its place in the layout.

use std::borrow::Cow;
use std::ops::Range;

use std::num::NonZeroU16;
use std::sync::OnceLock;

use tree_sitter::{Node, TreeCursor};

use crate::syntax::{field, kind};

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

/// How deep a line is, in steps of indentation of three kinds: RAPID code
/// is written both ways for two of them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Depth {
    /// The module body: one level in, or at the module's column.
    pub module: usize,
    /// `CASE` and `DEFAULT` inside `TEST`: one level in, or at `TEST`'s
    /// column.
    pub cases: usize,
    /// Every other step: routine and block bodies, record components.
    pub blocks: usize,
}

impl Depth {
    fn module(self) -> Depth {
        Depth {
            module: self.module + 1,
            ..self
        }
    }

    fn case(self) -> Depth {
        Depth {
            cases: self.cases + 1,
            ..self
        }
    }

    fn block(self) -> Depth {
        Depth {
            blocks: self.blocks + 1,
            ..self
        }
    }

    /// A module's own first and last line.
    pub fn is_zero(self) -> bool {
        self == Depth::default()
    }

    /// A line of the module body itself (a declaration or a routine's
    /// first and last lines).
    pub fn is_module_body(self) -> bool {
        self == Depth::default().module()
    }
}

/// Where the structure puts a token that starts a line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Start {
    /// At this depth.
    Level(Depth),
    /// At this column whatever the indentation (`%%%` header lines).
    Column(usize),
}

/// One token and its layout facts.
#[derive(Debug)]
pub(super) struct Tok<'t> {
    /// Where the token is in the original text.
    pub range: Range<usize>,
    /// What to write: the original text, or (in the styles that normalise)
    /// keywords in upper case and comments without trailing blanks.
    pub text: Cow<'t, str>,
    pub class: Class,
    /// The structure puts this token first on a line.
    pub start: Option<Start>,
    /// A line-starting token that closes or splits a block (`ENDIF`, `ELSE`,
    /// `ERROR`, `CASE`...).
    pub closer: bool,
    /// A line-starting token that opens a block (`PROC`, `IF`, `ELSE`,
    /// `TEST`, `CASE`, `ERROR`...): the depth of the lines inside.
    pub opens: Option<Depth>,
    /// First token of a routine (or module) that follows another one: the two
    /// are separated by a blank line in the styles that normalise.
    pub unit_start_after_unit: bool,
    /// The line may be broken before this token when it is too long (an
    /// argument of a procedure call after its comma).
    pub wrap_point: bool,
    /// No blank line before this token (inside the `%%%` header).
    pub no_blank: bool,
    /// The name of a called procedure: spaced from its arguments.
    pub proc_name: bool,
    /// A number literal (a `.` after it could read as its decimal point).
    pub number: bool,
    /// In a `PERS` declaration after the name: the controller writes the
    /// value in its own form (tight, elements of an array on lines of their
    /// own at the declaration's column) whenever it saves the module, so
    /// its continuation lines keep their place in every style, and the
    /// `spaced` style keeps its blanks.
    pub keep_gap: bool,
}

/// Node kinds that start a line at their parent's level.
const SAME_LEVEL_KINDS: &[&str] = &[
    kind::ERROR_HANDLER,
    kind::BACKWARD_HANDLER,
    kind::UNDO_HANDLER,
    kind::ELSEIF_CLAUSE,
    kind::ELSE_CLAUSE,
];

/// Node kinds that start a line one level deeper than their parent.
const DEEPER_KINDS: &[&str] = &[kind::TEST_CASE, kind::DEFAULT_CASE, kind::RECORD_COMPONENT];

/// Node kinds whose first line opens a block of deeper lines.
const BLOCKS: &[&str] = &[
    kind::MODULE,
    kind::PROCEDURE_DECLARATION,
    kind::FUNCTION_DECLARATION,
    kind::TRAP_DECLARATION,
    kind::RECORD_DECLARATION,
    kind::IF_STATEMENT,
    kind::ELSEIF_CLAUSE,
    kind::ELSE_CLAUSE,
    kind::FOR_STATEMENT,
    kind::WHILE_STATEMENT,
    kind::TEST_STATEMENT,
    kind::TEST_CASE,
    kind::DEFAULT_CASE,
    kind::ERROR_HANDLER,
    kind::BACKWARD_HANDLER,
    kind::UNDO_HANDLER,
];

const ROUTINES: &[&str] = &[
    kind::PROCEDURE_DECLARATION,
    kind::FUNCTION_DECLARATION,
    kind::TRAP_DECLARATION,
];

#[derive(Clone, Copy, Default)]
struct Pending {
    start: Option<Start>,
    closer: bool,
    opens: Option<Depth>,
    no_blank: bool,
    unit_start_after_unit: bool,
    wrap_point: bool,
}

/// What the walk knows of a node whose children it is visiting.
struct Frame<'n> {
    node: Node<'n>,
    flags: u32,
    /// The flags of the node's parent.
    parent_flags: u32,
    /// The depth of the node's own lines.
    level: Depth,
    index: usize,
    previous_routine: bool,
    after_comma: bool,
    /// A `PERS` declaration: the gaps after its name are kept.
    pers: bool,
    /// Its name has been seen.
    after_name: bool,
    /// This frame has started keeping gaps (counted in `Collector::keeping`).
    keeping: bool,
}

pub(super) struct Collector<'t> {
    text: &'t str,
    normalise: bool,
    pub toks: Vec<Tok<'t>>,
    pending: Pending,
    /// Frames that keep the gaps of their tokens.
    keeping: usize,
    /// The next leaf is the name of a called procedure.
    next_is_proc_name: bool,
}

/// How deep the tree may nest before the text is left as it is: real code
/// nests a few dozen levels; a generated expression of thousands of terms
/// nests as deep as it is long, and thousands of nested blocks would be
/// indented by megabytes of blanks. (The walk itself has no depth limit of
/// its own: it keeps its frames on the heap.)
pub(super) const MAX_DEPTH: usize = 1500;

/// The tokens of a tree without errors; `None` if it nests deeper than
/// [`MAX_DEPTH`]. `normalise`: keywords in upper case and comments without
/// trailing blanks (otherwise tokens are written as they are).
pub(super) fn collect<'t>(root: Node<'_>, text: &'t str, normalise: bool) -> Option<Vec<Tok<'t>>> {
    let mut c = Collector {
        text,
        normalise,
        toks: Vec::new(),
        pending: Pending::default(),
        keeping: 0,
        next_is_proc_name: false,
    };
    let mut cursor = root.walk();
    let mut previous_module = false;
    for child in root.children(&mut cursor) {
        match child.kind() {
            kind::MODULE => {
                c.pending = Pending {
                    start: Some(Start::Level(Depth::default())),
                    opens: Some(Depth::default().module()),
                    unit_start_after_unit: previous_module,
                    ..Pending::default()
                };
                if !c.walk(child, root) {
                    return None;
                }
                previous_module = true;
            }
            kind::COMMENT => c.leaf(child, root),
            _ => {
                // trailing text (kept verbatim), or anything new
                c.pending = Pending::default();
                c.leaf(child, root);
                previous_module = false;
            }
        }
    }
    Some(c.toks)
}

impl<'t> Collector<'t> {
    /// Emits the tokens of `top` (a module, at level 0), visiting the tree
    /// with a cursor and a stack of frames. False when it nests deeper than
    /// [`MAX_DEPTH`].
    fn walk<'n>(&mut self, top: Node<'n>, parent: Node<'n>) -> bool {
        let k = kinds();
        let top_flags = k.flags(top);
        if is_atomic_with(top, top_flags) {
            self.leaf(top, parent);
            return true;
        }
        let mut cursor = top.walk();
        if !cursor.goto_first_child() {
            return true;
        }
        let mut stack = vec![Frame::new(
            top,
            top_flags,
            k.flags(parent),
            Depth::default(),
        )];
        loop {
            let child = cursor.node();
            let child_flags = k.flags(child);
            let Some(frame) = stack.last_mut() else {
                return true;
            };
            let node = frame.node;
            let mut descend = None;
            if child.is_extra() || child_flags & COMMENT != 0 {
                self.leaf(child, node);
            } else {
                if frame.after_name && !frame.keeping {
                    frame.keeping = true;
                    self.keeping += 1;
                }
                let is_name = cursor.field_id().is_some() && cursor.field_id() == k.name_field;
                frame.after_name |= frame.pers && is_name;
                let (index, level, flags) = (frame.index, frame.level, frame.flags);
                let wrap_args =
                    flags & ARGUMENT_LIST != 0 && frame.parent_flags & PROCEDURE_CALL != 0;
                if flags & MODULE != 0 && k.is_body(&cursor) {
                    let routine = child_flags & ROUTINE != 0;
                    let after_routine = routine && frame.previous_routine;
                    frame.previous_routine = routine;
                    self.pending.unit_start_after_unit = after_routine;
                }
                if wrap_args && frame.after_comma {
                    self.pending.wrap_point = true;
                }
                frame.after_comma = wrap_args && child_flags & COMMA != 0;
                let child_level = self.place(&cursor, flags, child_flags, index, level);
                self.next_is_proc_name =
                    flags & PROCEDURE_CALL != 0 && is_name && child.child_count() == 0;
                if is_atomic_with(child, child_flags) {
                    self.leaf(child, node);
                } else {
                    descend = Some((child_level, flags));
                }
            }
            if let Some((level, flags)) = descend
                && cursor.goto_first_child()
            {
                if stack.len() >= MAX_DEPTH {
                    return false;
                }
                stack.push(Frame::new(child, child_flags, flags, level));
                continue;
            }
            // the next sibling, or back up to the first ancestor that has one
            loop {
                let Some(frame) = stack.last_mut() else {
                    return true;
                };
                frame.index += 1;
                if cursor.goto_next_sibling() {
                    break;
                }
                if let Some(done) = stack.pop()
                    && done.keeping
                {
                    self.keeping -= 1;
                }
                if stack.is_empty() || !cursor.goto_parent() {
                    return true;
                }
            }
        }
    }

    /// Decides whether the child under `cursor` starts a line (setting the
    /// pending line start), and returns the depth of its own lines.
    fn place(
        &mut self,
        cursor: &TreeCursor<'_>,
        parent_flags: u32,
        flags: u32,
        index: usize,
        level: Depth,
    ) -> Depth {
        let opens = |depth: Depth| {
            (flags & BLOCK != 0).then(|| {
                if flags & TEST != 0 {
                    depth.case()
                } else {
                    depth.block()
                }
            })
        };
        let mut start = |start: Start, closer: bool, no_blank: bool, opens: Option<Depth>| {
            self.pending.start = Some(start);
            self.pending.closer = closer;
            self.pending.no_blank = no_blank;
            self.pending.opens = opens;
        };
        if parent_flags & COMPACT_IF != 0 {
            level
        } else if parent_flags & MODULE_HEADER != 0 {
            if flags & HEADER_MARK != 0 {
                start(Start::Column(0), false, index != 0, None);
            } else if flags & HEADER_ENTRY != 0 {
                start(Start::Column(2), false, true, None);
            }
            level
        } else if parent_flags & MODULE != 0 && flags & MODULE_KEYWORD != 0 {
            start(Start::Level(level), false, false, Some(level.module()));
            level
        } else if flags & (END_KEYWORD | SAME_LEVEL) != 0 {
            start(Start::Level(level), true, false, opens(level));
            level
        } else if flags & DEEPER != 0 {
            let deeper = if flags & RECORD_COMPONENT != 0 {
                level.block()
            } else {
                level.case()
            };
            start(
                Start::Level(deeper),
                flags & RECORD_COMPONENT == 0,
                false,
                opens(deeper),
            );
            deeper
        } else if flags & NAMED != 0 && kinds().is_body(cursor) {
            let deeper = if parent_flags & MODULE != 0 {
                level.module()
            } else {
                level.block()
            };
            start(Start::Level(deeper), false, false, opens(deeper));
            deeper
        } else {
            level
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
            Class::Keyword if self.normalise => Cow::Owned(raw.to_ascii_uppercase()),
            Class::Comment if self.normalise => {
                Cow::Borrowed(raw.trim_end_matches([' ', '\t', '\u{c}']))
            }
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
            start: pending.start,
            closer: pending.closer,
            opens: pending.opens,
            unit_start_after_unit: pending.unit_start_after_unit,
            wrap_point: pending.wrap_point,
            no_blank: pending.no_blank,
            proc_name: proc_name && class != Class::Comment,
            number: node.kind() == kind::NUMBER,
            keep_gap: self.keeping > 0 && class != Class::Comment,
        });
    }
}

impl<'n> Frame<'n> {
    fn new(node: Node<'n>, flags: u32, parent_flags: u32, level: Depth) -> Frame<'n> {
        let pers = flags & DATA_DECLARATION != 0
            && node
                .child_by_field_name(field::STORAGE)
                .is_some_and(|s| s.kind() == "pers");
        Frame {
            node,
            flags,
            parent_flags,
            level,
            index: 0,
            previous_routine: false,
            after_comma: false,
            pers,
            after_name: false,
            keeping: false,
        }
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
const DATA_DECLARATION: u32 = 1 << 23;
const TEST: u32 = 1 << 24;

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
            body_field: language.field_id_for_name(field::BODY),
            name_field: language.field_id_for_name(field::NAME),
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
        set(name == kind::COMMENT, COMMENT);
        set(name == kind::TRAILING_TEXT, TRAILING);
        set(name == kind::STRING, STRING);
        set(name == kind::MODULE, MODULE);
        set(name == kind::MODULE_HEADER, MODULE_HEADER);
        set(name == kind::HEADER_ENTRY, HEADER_ENTRY);
        set(name == kind::COMPACT_IF_STATEMENT, COMPACT_IF);
        set(name == kind::ARGUMENT_LIST, ARGUMENT_LIST);
        set(name == kind::PROCEDURE_CALL, PROCEDURE_CALL);
        set(name == kind::ARGUMENT, ARGUMENT);
        set(name == kind::OPTIONAL_PARAMETER, OPTIONAL_PARAMETER);
        set(name == kind::UNARY_EXPRESSION, UNARY_EXPRESSION);
        set(SAME_LEVEL_KINDS.contains(&name), SAME_LEVEL);
        set(DEEPER_KINDS.contains(&name), DEEPER);
        set(BLOCKS.contains(&name), BLOCK);
        set(ROUTINES.contains(&name), ROUTINE);
        set(name == kind::RECORD_COMPONENT, RECORD_COMPONENT);
        set(name == kind::DATA_DECLARATION, DATA_DECLARATION);
        set(name == kind::TEST_STATEMENT, TEST);
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
