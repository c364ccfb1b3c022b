//! Semantic tokens, consistent with `tree-sitter-rapid/queries/highlights.scm`
//! and refined by name resolution: a name used as data is a variable, a
//! persistent (`static`) or a constant (`readonly`); built-ins carry
//! `defaultLibrary`; predefined constants are enum members.

use std::ops::Range;

use tree_sitter::Node;

use super::resolve::is_name;
use super::{
    MOD_DECLARATION, MOD_DEFAULT_LIBRARY, MOD_READONLY, MOD_STATIC, SemanticToken, TokenType,
};
use crate::catalogue::DatumKind;
use crate::items::Storage;
use crate::names::same;
use crate::sema::def::Def;
use crate::sema::scope::Scope;
use crate::syntax::{field, kind};
use crate::task::{Item, Task};

/// A cache of the scope (module, routine) names are resolved in.
pub(crate) struct Scopes<'t> {
    task: &'t Task,
    unit: usize,
    /// Routine ranges of the unit, sorted.
    routines: Vec<Range<usize>>,
    modules: Vec<Range<usize>>,
    current: Option<((usize, usize), Scope<'t>)>,
}

impl<'t> Scopes<'t> {
    pub(crate) fn new(task: &'t Task, unit: usize) -> Scopes<'t> {
        let mut routines = Vec::new();
        let mut modules = Vec::new();
        if let Some(u) = task.unit(unit) {
            for m in &u.items.modules {
                modules.push(m.range.clone());
                routines.extend(m.routines.iter().map(|r| r.range.clone()));
            }
        }
        routines.sort_by_key(|r| r.start);
        Scopes {
            task,
            unit,
            routines,
            modules,
            current: None,
        }
    }

    /// The context for a name at `offset`.
    pub(crate) fn at(&mut self, offset: usize) -> Option<&mut Scope<'t>> {
        let i = self.routines.partition_point(|r| r.start <= offset);
        let routine = i
            .checked_sub(1)
            .and_then(|i| self.routines.get(i))
            .filter(|r| offset <= r.end)
            .map_or(usize::MAX, |r| r.start);
        let module = self
            .modules
            .iter()
            .position(|m| m.start <= offset && offset <= m.end)
            .unwrap_or(usize::MAX);
        let key = (module, routine);
        if self.current.as_ref().is_none_or(|(k, _)| *k != key) {
            let at = if routine == usize::MAX {
                offset
            } else {
                routine
            };
            let cx = Scope::at(self.task, self.unit, at)?;
            self.current = Some((key, cx));
        }
        self.current.as_mut().map(|(_, cx)| cx)
    }
}

fn is_keyword(kind: &str) -> bool {
    kind.bytes().all(|b| b.is_ascii_lowercase()) && !kind.is_empty()
}

const OPERATORS: &[&str] = &[
    ":=", "+", "-", "*", "/", "=", "<>", "<", ">", "<=", ">=", "\\", "?", "%",
];

/// Semantic tokens of the file (or of the nodes overlapping `range`),
/// sorted, one line each; `token_type` indexes [`super::TOKEN_TYPES`] and
/// `modifiers` holds bits of [`super::TOKEN_MODIFIERS`].
pub fn semantic_tokens(
    task: &Task,
    unit: usize,
    range: Option<Range<usize>>,
) -> Vec<SemanticToken> {
    let Some(u) = task.unit(unit) else {
        return Vec::new();
    };
    let text = &u.text;
    let range = range.unwrap_or(0..text.len());
    let mut scopes = Scopes::new(task, unit);
    let mut out: Vec<SemanticToken> = Vec::new();
    let mut emit = |r: Range<usize>, ty: TokenType, modifiers: u32| {
        // One token per line: clients need not support multi-line tokens.
        let mut start = r.start;
        let slice = text.get(r.clone()).unwrap_or_default();
        for (i, _) in slice.match_indices('\n') {
            let end = r.start + i;
            if end > start {
                out.push(SemanticToken {
                    range: start..end,
                    token_type: ty as u32,
                    modifiers,
                });
            }
            start = end + 1;
        }
        if r.end > start {
            out.push(SemanticToken {
                range: start..r.end,
                token_type: ty as u32,
                modifiers,
            });
        }
    };
    let root = u.tree().root_node();
    let mut cursor = root.walk();
    // The ancestors of the cursor's node (`Node::parent` walks down from
    // the root each time; a stack is much cheaper).
    let mut stack: Vec<Node<'_>> = Vec::new();
    'outer: loop {
        let n = cursor.node();
        let overlaps = n.start_byte() < range.end && range.start < n.end_byte();
        let mut descend = overlaps;
        if overlaps {
            let kind = n.kind();
            let leaf_like = match kind {
                kind::COMMENT | kind::TRAILING_TEXT => {
                    emit(n.byte_range(), TokenType::Comment, 0);
                    true
                }
                kind::NUMBER => {
                    emit(n.byte_range(), TokenType::Number, 0);
                    true
                }
                kind::STRING => {
                    emit(n.byte_range(), TokenType::String, 0);
                    true
                }
                kind::BOOLEAN => {
                    emit(
                        n.byte_range(),
                        TokenType::EnumMember,
                        MOD_READONLY | MOD_DEFAULT_LIBRARY,
                    );
                    true
                }
                kind::PLACEHOLDER => {
                    emit(n.byte_range(), TokenType::Macro, 0);
                    true
                }
                kind::MODULE_ATTRIBUTE => {
                    emit(n.byte_range(), TokenType::Keyword, 0);
                    true
                }
                kind::HEADER_VALUE => true,
                _ if is_name(n) => {
                    let field = cursor.field_name();
                    if let Some((ty, m)) = classify(&mut scopes, n, field, &stack, text) {
                        emit(n.byte_range(), ty, m);
                    }
                    true
                }
                _ if !n.is_named() && n.child_count() == 0 => {
                    if is_keyword(kind) {
                        emit(n.byte_range(), TokenType::Keyword, 0);
                    } else if OPERATORS.contains(&kind) {
                        emit(n.byte_range(), TokenType::Operator, 0);
                    }
                    true
                }
                _ => false,
            };
            descend = !leaf_like;
        }
        if descend && cursor.goto_first_child() {
            stack.push(n);
            continue;
        }
        loop {
            if cursor.goto_next_sibling() {
                continue 'outer;
            }
            if !cursor.goto_parent() {
                break 'outer;
            }
            stack.pop();
        }
    }
    out
}

fn data_mods(storage: Storage) -> u32 {
    match storage {
        Storage::Var => 0,
        Storage::Pers => MOD_STATIC,
        Storage::Const => MOD_READONLY,
    }
}

/// The token of a name.
fn classify(
    scopes: &mut Scopes<'_>,
    n: Node<'_>,
    field: Option<&str>,
    ancestors: &[Node<'_>],
    text: &str,
) -> Option<(TokenType, u32)> {
    let name = text.get(n.byte_range())?;
    let parent = *ancestors.last()?;
    let cat = scopes.task.catalogue;
    let decl = MOD_DECLARATION;
    Some(match (parent.kind(), field) {
        (kind::MODULE, Some(field::NAME)) => (TokenType::Namespace, decl),
        (kind::HEADER_ENTRY, _) => (TokenType::Property, 0),
        (kind::PROCEDURE_DECLARATION | kind::TRAP_DECLARATION, Some(field::NAME)) => {
            (TokenType::Method, decl)
        }
        (kind::FUNCTION_DECLARATION, Some(field::NAME)) => (TokenType::Function, decl),
        (kind::RECORD_DECLARATION | kind::ALIAS_DECLARATION, Some(field::NAME)) => {
            (TokenType::Type, decl)
        }
        (kind::RECORD_COMPONENT, Some(field::NAME)) => (TokenType::Property, decl),
        (kind::COMPONENT_ACCESS, Some(field::COMPONENT)) => (TokenType::Property, 0),
        (kind::PARAMETER, Some(field::NAME)) => (TokenType::Parameter, decl),
        (kind::ARGUMENT, Some(field::NAME)) => (TokenType::Parameter, 0),
        (kind::LABEL, Some(field::NAME)) => (TokenType::Label, decl),
        (kind::GOTO_STATEMENT, Some(field::LABEL)) => (TokenType::Label, 0),
        (kind::FOR_STATEMENT, Some(field::VARIABLE)) => (TokenType::Variable, decl),
        (kind::DATA_DECLARATION, Some(field::NAME)) => {
            let m = match field_of_kind(parent) {
                Some("pers") => MOD_STATIC,
                Some("const") => MOD_READONLY,
                _ => 0,
            };
            (TokenType::Variable, decl | m)
        }
        (kind::PROCEDURE_CALL | kind::FUNCTION_CALL, Some(field::NAME))
        | (kind::CONNECT_STATEMENT, Some(field::TRAP)) => {
            let cx = scopes.at(n.start_byte())?;
            match cx.resolve_routine(name, parent.kind() == kind::FUNCTION_CALL) {
                Some(Def::BuiltinRoutine(r)) => {
                    let ty = if r.returns.is_some() {
                        TokenType::Function
                    } else {
                        TokenType::Method
                    };
                    (ty, MOD_DEFAULT_LIBRARY)
                }
                Some(def) => match def.routine_decl(cx.task).map(|d| d.kind) {
                    Some(crate::items::RoutineKind::Func) => (TokenType::Function, 0),
                    _ => (TokenType::Method, 0),
                },
                None if parent.kind() == kind::FUNCTION_CALL => (TokenType::Function, 0),
                None => (TokenType::Method, 0),
            }
        }
        _ if n.kind() == kind::TYPE_IDENTIFIER || field == Some(field::TYPE) => {
            let cx = scopes.at(n.start_byte())?;
            let user = cx
                .lookup_items(name)
                .iter()
                .any(|r| matches!(r.item, Item::Record(_) | Item::Alias(_)));
            if !user && (cat.datatype(name).is_some() || same(name, "switch")) {
                (TokenType::Type, MOD_DEFAULT_LIBRARY)
            } else {
                (TokenType::Type, 0)
            }
        }
        _ => {
            // A name used as data.
            if enclosing_for_var(ancestors, name, text) {
                return Some((TokenType::Variable, 0));
            }
            let cx = scopes.at(n.start_byte())?;
            match cx.resolve_data(name) {
                Some(Def::Param { .. }) => (TokenType::Parameter, 0),
                Some(def @ (Def::Local { .. } | Def::Item(_))) => (
                    TokenType::Variable,
                    def.data_decl(cx.task).map_or(0, |d| data_mods(d.storage)),
                ),
                Some(Def::BuiltinDatum(d)) => match d.kind {
                    DatumKind::Const => (TokenType::EnumMember, MOD_READONLY | MOD_DEFAULT_LIBRARY),
                    DatumKind::Pers => (TokenType::Variable, MOD_STATIC | MOD_DEFAULT_LIBRARY),
                    DatumKind::Var => (TokenType::Variable, MOD_DEFAULT_LIBRARY),
                },
                Some(Def::Signal(..)) => (TokenType::Variable, MOD_DEFAULT_LIBRARY),
                Some(_) => (TokenType::Variable, 0),
                None => {
                    // Perhaps a routine used as a value (a late-binding
                    // name) or nothing known: plain variable.
                    (TokenType::Variable, 0)
                }
            }
        }
    })
}

/// The storage keyword of a data declaration.
fn field_of_kind(decl: Node<'_>) -> Option<&'static str> {
    let s = decl.child_by_field_name(field::STORAGE)?;
    match s.kind() {
        "var" => Some("var"),
        "pers" => Some("pers"),
        "const" => Some("const"),
        _ => None,
    }
}

/// Is `name` the variable of a FOR loop among `ancestors` (innermost last),
/// within the routine?
fn enclosing_for_var(ancestors: &[Node<'_>], name: &str, text: &str) -> bool {
    for p in ancestors.iter().rev() {
        if p.kind() == kind::FOR_STATEMENT
            && let Some(v) = p.child_by_field_name(field::VARIABLE)
            && text.get(v.byte_range()).is_some_and(|t| same(t, name))
        {
            return true;
        }
        if matches!(
            p.kind(),
            kind::PROCEDURE_DECLARATION | kind::FUNCTION_DECLARATION | kind::TRAP_DECLARATION
        ) {
            return false;
        }
    }
    false
}
