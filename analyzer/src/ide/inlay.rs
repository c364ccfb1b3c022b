//! Inlay hints: parameter names of positional arguments, and the values of
//! constants declared with computed initial values.

use std::ops::Range;

use tree_sitter::Node;

use super::tokens::Scopes;
use super::{InlayHint, InlayKind};
use crate::names::same;
use crate::sema::signature::{Arg, Signature, Target, bind_args};
use crate::syntax::{field, kind};
use crate::syntax_util::walk_pruned;
use crate::task::Task;

/// Longest value shown in a hint.
const MAX_VALUE: usize = 48;

/// Which positional arguments get their parameter's name as a hint.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ParameterHints {
    /// None.
    None,
    /// Arguments that do not name themselves: literals, aggregates,
    /// operations and function calls (`MoveL p10, v100, fine, tool0` needs
    /// no hint; `SetDO doGrip, 1` says `Value:` before the `1`).
    #[default]
    Literals,
    /// Every positional argument, names of data too.
    All,
}

impl ParameterHints {
    /// `none`, `literals` or `all` (any case).
    pub fn parse(s: &str) -> Option<ParameterHints> {
        [
            ("none", ParameterHints::None),
            ("literals", ParameterHints::Literals),
            ("all", ParameterHints::All),
        ]
        .into_iter()
        .find(|(name, _)| name.eq_ignore_ascii_case(s))
        .map(|(_, v)| v)
    }
}

/// Parameter names before positional arguments (calls with two or more
/// required parameters; which arguments, `parameters` says) and `= value`
/// after `CONST` initialisers that are not literals, within `range`,
/// sorted by offset.
pub fn inlay_hints(
    task: &Task,
    unit: usize,
    range: Range<usize>,
    parameters: ParameterHints,
) -> Vec<InlayHint> {
    let Some(u) = task.unit(unit) else {
        return Vec::new();
    };
    let text = &u.text;
    let mut scopes = Scopes::new(task, unit);
    let mut out = Vec::new();
    let root = u.tree().root_node();
    let mut calls = Vec::new();
    let mut consts = Vec::new();
    walk_pruned(root, &mut |n: Node<'_>| {
        if n.end_byte() < range.start || n.start_byte() > range.end {
            return false;
        }
        match n.kind() {
            kind::PROCEDURE_CALL | kind::FUNCTION_CALL if parameters != ParameterHints::None => {
                calls.push(n);
            }
            kind::DATA_DECLARATION => consts.push(n),
            _ => {}
        }
        true
    });
    for call in calls {
        let (Some(name), Some(args)) = (
            call.child_by_field_name(field::NAME),
            call.child_by_field_name(field::ARGUMENTS),
        ) else {
            continue;
        };
        let Some(name_text) = text.get(name.byte_range()) else {
            continue;
        };
        let Some(cx) = scopes.at(call.start_byte()) else {
            continue;
        };
        let Some(sym) = cx.resolve_routine(name_text, call.kind() == kind::FUNCTION_CALL) else {
            continue;
        };
        let Some(sig) = Signature::of(&sym, cx.task) else {
            continue;
        };
        let mut cursor = args.walk();
        let args: Vec<Node<'_>> = args
            .children_by_field_name(field::ARGUMENT, &mut cursor)
            .collect();
        if sig.params.iter().filter(|p| p.positional()).count() < 2 {
            continue;
        }
        let given: Vec<Arg<'_>> = args
            .iter()
            .map(|a| {
                match a
                    .child_by_field_name(field::NAME)
                    .and_then(|n| text.get(n.byte_range()))
                {
                    Some(n) => Arg::Named(n),
                    // A lone `\`: no parameter's name.
                    None if is_optional(*a) => Arg::Named(""),
                    None => Arg::Positional,
                }
            })
            .collect();
        let binding = bind_args(&sig, &given);
        for ((a, bound), arg) in args.iter().zip(&binding.args).zip(&given) {
            if *arg != Arg::Positional {
                continue;
            }
            let Target::Param(i) = bound.target else {
                break;
            };
            let Some(p) = sig.params.get(i) else {
                continue;
            };
            let Some(value) = a.child_by_field_name(field::VALUE) else {
                continue;
            };
            let v = text.get(value.byte_range()).unwrap_or_default();
            if same(v.trim(), &p.name)
                || (parameters == ParameterHints::Literals && names_itself(value))
            {
                continue;
            }
            if a.start_byte() >= range.start && a.start_byte() <= range.end {
                out.push(InlayHint {
                    offset: a.start_byte(),
                    label: format!("{}:", p.name),
                    kind: InlayKind::Parameter,
                });
            }
        }
    }
    for decl in consts {
        if decl.child_by_field_name(field::STORAGE).map(|s| s.kind()) != Some("const") {
            continue;
        }
        let Some(value) = decl.child_by_field_name(field::VALUE) else {
            continue;
        };
        if is_literal(value) {
            continue;
        }
        let Some(v) = super::value::value_of_range(task, unit, value.byte_range()) else {
            continue;
        };
        if v.error.is_some() || v.value.is_empty() || v.value.len() > MAX_VALUE {
            continue;
        }
        out.push(InlayHint {
            offset: value.end_byte(),
            label: format!("= {}", v.value),
            kind: InlayKind::Value,
        });
    }
    out.sort_by_key(|h| h.offset);
    out
}

/// A reference to named data (`p10`, `tool.tframe`, `pts{i}`), which says
/// what it is without a hint.
fn names_itself(value: Node<'_>) -> bool {
    match value.kind() {
        kind::IDENTIFIER => true,
        kind::COMPONENT_ACCESS | kind::INDEX_EXPRESSION => value
            .child_by_field_name(field::OBJECT)
            .is_some_and(names_itself),
        kind::PARENTHESIZED_EXPRESSION => value
            .child_by_field_name(field::EXPRESSION)
            .is_some_and(names_itself),
        _ => false,
    }
}

fn is_optional(arg: Node<'_>) -> bool {
    let mut cursor = arg.walk();
    arg.children(&mut cursor).any(|c| c.kind() == "\\")
}

/// A literal, or an aggregate of literals: its value reads as its text.
pub(crate) fn is_literal(n: Node<'_>) -> bool {
    match n.kind() {
        kind::NUMBER | kind::STRING | kind::BOOLEAN => true,
        kind::UNARY_EXPRESSION => n
            .child_by_field_name(field::OPERAND)
            .is_some_and(|o| o.kind() == kind::NUMBER),
        kind::AGGREGATE => {
            let mut cursor = n.walk();
            n.children_by_field_name(field::ELEMENT, &mut cursor)
                .all(is_literal)
        }
        _ => false,
    }
}
