//! What the name at an offset denotes, through the resolver's scopes
//! ([`Scope::at`]), and the walks over names that references and rename need.

use std::ops::Range;

use tree_sitter::{Node, Tree};

use crate::names::{fold, same};
pub(crate) use crate::sema::def::{Def, DefKey};
use crate::sema::scope::Scope;
use crate::syntax::{field, kind};
use crate::task::{Item, ItemRef, Task};
use crate::ty::{Ty, UserType};

/// Is this node a name (an identifier of any role)?
pub(crate) fn is_name(node: Node<'_>) -> bool {
    matches!(node.kind(), kind::IDENTIFIER | kind::TYPE_IDENTIFIER)
}

/// The name node at `offset`, also when the cursor is just after it.
pub(crate) fn name_at(tree: &Tree, offset: usize) -> Option<Node<'_>> {
    let root = tree.root_node();
    let at = |o: usize| {
        root.descendant_for_byte_range(o, o)
            .filter(|n| is_name(*n) && n.start_byte() <= o && o <= n.end_byte())
    };
    at(offset).or_else(|| offset.checked_sub(1).and_then(at))
}

/// The field under which `node` sits in its parent.
pub(crate) fn field_in_parent<'a>(node: Node<'a>) -> Option<&'a str> {
    let parent = node.parent()?;
    let mut cursor = parent.walk();
    if !cursor.goto_first_child() {
        return None;
    }
    loop {
        if cursor.node().id() == node.id() {
            return cursor.field_name();
        }
        if !cursor.goto_next_sibling() {
            return None;
        }
    }
}

/// The call (`procedure_call` or `function_call`) an argument node belongs to.
pub(crate) fn call_of_argument(arg: Node<'_>) -> Option<Node<'_>> {
    let list = arg.parent()?;
    let call = list.parent()?;
    matches!(call.kind(), kind::PROCEDURE_CALL | kind::FUNCTION_CALL).then_some(call)
}

/// Resolves the routine named by a call node.
pub(crate) fn call_routine<'t>(cx: &Scope<'t>, call: Node<'_>) -> Option<Def<'t>> {
    let name = call.child_by_field_name(field::NAME)?;
    if name.kind() != kind::IDENTIFIER {
        return None;
    }
    let text = cx.text.get(name.byte_range())?;
    cx.resolve_routine(text, call.kind() == kind::FUNCTION_CALL)
}

/// Resolves the name node `node` of unit `unit`.
pub(crate) fn resolve<'t>(task: &'t Task, unit: usize, node: Node<'t>) -> Option<Def<'t>> {
    let cx = Scope::at(task, unit, node.start_byte())?;
    resolve_in(&cx, node)
}

pub(crate) fn resolve_in<'t>(cx: &Scope<'t>, node: Node<'t>) -> Option<Def<'t>> {
    let parent = node.parent()?;
    let field = field_in_parent(node);
    resolve_at(cx, node, parent, field)
}

/// [`resolve_in`] with what a walk down the tree already knows: the name's
/// parent and the field under which it sits (so that nothing walks up
/// parent links, which tree-sitter finds from the root at a cost that
/// grows with the width of the nodes around: thousands of uses in one wide
/// routine made finding them quadratic). The `FOR` variables around the
/// name are the scope's.
pub(crate) fn resolve_at<'t>(
    cx: &Scope<'t>,
    node: Node<'t>,
    parent: Node<'t>,
    field: Option<&str>,
) -> Option<Def<'t>> {
    let task = cx.task;
    let unit = cx.unit_idx;
    let name = cx.text.get(node.byte_range())?.to_owned();
    match (parent.kind(), field) {
        (kind::PROCEDURE_CALL | kind::FUNCTION_CALL, Some(field::NAME)) => {
            return cx.resolve_routine(&name, parent.kind() == kind::FUNCTION_CALL);
        }
        (kind::CONNECT_STATEMENT, Some(field::TRAP)) => {
            return cx.resolve_routine(&name, false);
        }
        (kind::MODULE, Some(field::NAME)) => {
            let module = cx
                .unit
                .items
                .modules
                .iter()
                .position(|m| m.name_range == node.byte_range())?;
            return Some(Def::Module { unit, module });
        }
        (kind::PARAMETER, Some(field::NAME)) => {
            let routine = cx.routine.as_ref()?.decl;
            let decl = routine
                .params
                .iter()
                .find(|p| p.name_range == node.byte_range())?;
            return Some(Def::Param {
                unit,
                decl,
                routine,
            });
        }
        (kind::DATA_DECLARATION, Some(field::NAME)) => {
            if let Some(r) = &cx.routine
                && r.decl.range.start <= parent.start_byte()
                && parent.end_byte() <= r.decl.range.end
            {
                let decl = crate::items::lower_data(parent, cx.text)?;
                return Some(Def::Local {
                    unit,
                    decl,
                    routine: r.decl,
                });
            }
            return item_declared_at(task, unit, &name, node.byte_range()).map(Def::Item);
        }
        (
            kind::PROCEDURE_DECLARATION
            | kind::FUNCTION_DECLARATION
            | kind::TRAP_DECLARATION
            | kind::RECORD_DECLARATION
            | kind::ALIAS_DECLARATION,
            Some(field::NAME),
        ) => return item_declared_at(task, unit, &name, node.byte_range()).map(Def::Item),
        (kind::RECORD_COMPONENT, Some(field::NAME)) => {
            let rec = parent.parent()?;
            let rname = rec.child_by_field_name(field::NAME)?;
            let rname_text = cx.text.get(rname.byte_range())?.to_owned();
            let r = item_declared_at(task, unit, &rname_text, rname.byte_range())?;
            let i = task
                .record(r)?
                .components
                .iter()
                .position(|c| c.2 == node.byte_range())?;
            return Some(Def::Component(r, i));
        }
        (kind::COMPONENT_ACCESS, Some(field::COMPONENT)) => {
            let obj = parent.child_by_field_name(field::OBJECT)?;
            let ty = crate::sema::typing::type_of(cx, obj, None);
            return component_def(cx, &ty, &name);
        }
        (kind::ARGUMENT, Some(field::NAME)) => {
            let call = call_of_argument(parent)?;
            return match call_routine(cx, call)? {
                Def::Item(r) => {
                    let decl = task.routine(r)?;
                    let p = decl.params.iter().find(|p| same(&p.name, &name))?;
                    Some(Def::Param {
                        unit: r.unit,
                        decl: p,
                        routine: decl,
                    })
                }
                Def::BuiltinRoutine(r) => {
                    let i = r.params.iter().position(|p| same(&p.name, &name))?;
                    Some(Def::BuiltinParam(r, i))
                }
                _ => None,
            };
        }
        (kind::LABEL, Some(field::NAME)) | (kind::GOTO_STATEMENT, Some(field::LABEL)) => {
            let routine = cx.routine.as_ref()?.decl;
            let root = cx.unit.tree().root_node();
            let rnode =
                root.named_descendant_for_byte_range(routine.range.start, routine.range.end)?;
            let range = crate::sema::labels::find(cx.text, rnode, None)
                .into_iter()
                .find(|(n, _, _)| same(n, &name))?
                .1;
            return Some(Def::Label { unit, name, range });
        }
        (kind::FOR_STATEMENT, Some(field::VARIABLE)) => {
            return Some(Def::ForVar {
                unit,
                range: node.byte_range(),
            });
        }
        _ => {}
    }
    if node.kind() == kind::TYPE_IDENTIFIER || field == Some(field::TYPE) {
        return type_def(cx, &name);
    }
    cx.resolve_data(&name)
}

/// A type name: a user record or alias visible here, or a built-in type.
pub(crate) fn type_def<'t>(cx: &Scope<'t>, name: &str) -> Option<Def<'t>> {
    for r in cx.lookup_items(name) {
        if matches!(r.item, Item::Record(_) | Item::Alias(_)) {
            return Some(Def::Item(r));
        }
    }
    cx.cat.datatype(name).map(Def::BuiltinType)
}

/// Component `name` of a value of type `ty`.
pub(crate) fn component_def<'t>(cx: &Scope<'t>, ty: &Ty, name: &str) -> Option<Def<'t>> {
    let Ty::Named(base) = cx.types.base(ty) else {
        return None;
    };
    if let Some(UserType::Record(_)) = cx.types.user(&base) {
        let r = cx
            .lookup_items(&base)
            .into_iter()
            .find(|r| matches!(r.item, Item::Record(_)))
            .or_else(|| any_item(cx.task, &base, |i| matches!(i, Item::Record(_))))?;
        let i = cx
            .task
            .record(r)?
            .components
            .iter()
            .position(|c| same(&c.0, name))?;
        return Some(Def::Component(r, i));
    }
    let t = cx.cat.datatype(&base)?;
    let i = t.components.iter().position(|c| same(&c.name, name))?;
    Some(Def::BuiltinComponent(t, i))
}

/// Any declaration of the task under `name` (global or local) of a kind.
pub(crate) fn any_item(task: &Task, name: &str, kind: impl Fn(Item) -> bool) -> Option<ItemRef> {
    let key = fold(name);
    task.globals
        .refs(&key)
        .chain(task.locals.refs(&key))
        .find(|r| kind(r.item))
}

/// The module item of unit `unit` whose name is at `range`.
fn item_declared_at(task: &Task, unit: usize, name: &str, range: Range<usize>) -> Option<ItemRef> {
    let key = fold(name);
    task.globals
        .refs(&key)
        .chain(task.locals.refs(&key))
        .find(|r| r.unit == unit && task.item_name(*r).is_some_and(|(_, n)| n == range))
}

/// The path from a walk's start down to a name: each node with the field
/// under which it sits in the one before it; the name is last.
pub(crate) type NamePath<'a> = [(Node<'a>, Option<&'a str>)];

/// Calls `f` with the path to every name node in `node` spelt `name`
/// (case-insensitive): the text is searched first, then one walk down the
/// tree enters only the nodes around a match, each at most once (linear
/// in the nodes entered, where finding each match from the root and its
/// parents was quadratic in a wide routine).
pub(crate) fn for_each_name_spelt<'a>(
    node: Node<'a>,
    text: &str,
    name: &str,
    mut f: impl FnMut(&NamePath<'a>),
) {
    let spots = spelt_at(node.byte_range(), text, name);
    // Is a match inside `n`? (matches are sorted and disjoint)
    let inside = |n: Node<'a>| {
        let i = spots.partition_point(|s| s.0 < n.start_byte());
        spots.get(i).is_some_and(|s| s.1 <= n.end_byte())
    };
    if !inside(node) {
        return;
    }
    let mut cursor = node.walk();
    let mut path: Vec<(Node<'a>, Option<&'a str>)> = vec![(node, None)];
    loop {
        let n = cursor.node();
        let mut enter = false;
        if inside(n) {
            if is_name(n) && spots.binary_search(&(n.start_byte(), n.end_byte())).is_ok() {
                f(&path);
            }
            enter = true;
        }
        if enter && cursor.goto_first_child() {
            path.push((cursor.node(), cursor.field_name()));
            continue;
        }
        loop {
            if path.len() <= 1 {
                return;
            }
            if cursor.goto_next_sibling() {
                if let Some(last) = path.last_mut() {
                    *last = (cursor.node(), cursor.field_name());
                }
                break;
            }
            if !cursor.goto_parent() {
                return;
            }
            path.pop();
        }
    }
}

/// Where `name` is spelt (case-insensitive, as a whole word) in `range` of
/// `text`: sorted byte ranges.
fn spelt_at(range: Range<usize>, text: &str, name: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let Some(hay) = text.get(range.clone()) else {
        return out;
    };
    if name.is_empty() {
        return out;
    }
    // Folding keeps every character's length: offsets stay.
    let hay_lower = crate::names::fold(hay);
    let needle = crate::names::fold(name);
    let bytes = hay_lower.as_bytes();
    let is_ident = |i: usize| crate::names::is_name_byte_at(bytes, i);
    let mut from = 0;
    while let Some(i) = hay_lower.get(from..).and_then(|h| h.find(&needle)) {
        let start = from + i;
        let end = start + needle.len();
        from = end;
        if start > 0 && is_ident(start - 1) {
            continue;
        }
        if is_ident(end) {
            continue;
        }
        out.push((range.start + start, range.start + end));
    }
    out
}
