//! Expressions: their types, and the places (data references) that
//! assignments and reference parameters need.

use std::ops::Range;

use tree_sitter::Node;

use super::{Cx, Place, calls};
use crate::rules;
use crate::sema::typing;
use crate::syntax::{field, kind};
use crate::syntax_util::{Literal, field, fields, literal_aggregate};
use crate::ty::Ty;

/// The type of an expression, reporting what is wrong inside it. `expected`
/// gives aggregates their type and lets unknown signal names be recognised.
pub(crate) fn expr<'t>(cx: &mut Cx<'t>, node: Node<'t>, expected: Option<&Ty>) -> Ty {
    match crate::syntax_util::kind(node) {
        kind::NUMBER => Ty::num(),
        kind::STRING => Ty::string(),
        kind::BOOLEAN => Ty::bool(),
        kind::IDENTIFIER => identifier(cx, node, expected),
        kind::PARENTHESIZED_EXPRESSION => match field(node, field::EXPRESSION) {
            Some(e) => expr(cx, e, expected),
            None => Ty::Unknown,
        },
        kind::UNARY_EXPRESSION => unary(cx, node),
        kind::BINARY_EXPRESSION => binary(cx, node),
        kind::FUNCTION_CALL => calls::function_call(cx, node),
        kind::COMPONENT_ACCESS => component(cx, node).0,
        kind::INDEX_EXPRESSION => index(cx, node).0,
        kind::AGGREGATE => {
            let ty = expected.cloned().unwrap_or(Ty::Unknown);
            aggregate(cx, node, &ty, &[]);
            ty
        }
        _ => Ty::Unknown,
    }
}

fn identifier<'t>(cx: &mut Cx<'t>, node: Node<'t>, expected: Option<&Ty>) -> Ty {
    let name = cx.node_text(node);
    match cx.resolve_data(name) {
        Some(sym) => {
            cx.def_used(&sym, node.byte_range());
            sym.ty(cx.task, &cx.types)
        }
        None => {
            if let Some(exp) = expected.filter(|e| is_configured(cx, e)) {
                cx.unknown_signal(node, name, exp);
                return exp.clone();
            }
            cx.unresolved(name, node.byte_range(), "data");
            Ty::Unknown
        }
    }
}

fn is_configured(cx: &Cx<'_>, ty: &Ty) -> bool {
    typing::is_configured(&cx.types, ty)
}

/// Checks an expression against the type its context expects.
pub(crate) fn check_expected<'t>(cx: &mut Cx<'t>, node: Node<'t>, expected: &Ty, what: &str) {
    check_sized(cx, node, expected, &[], what);
}

/// Checks a declaration's initial value; `sizes` are the array's sizes that
/// are written as numbers, for the aggregate arity check.
pub(super) fn check_initial_value<'t>(
    cx: &mut Cx<'t>,
    node: Node<'t>,
    expected: &Ty,
    sizes: &[Option<usize>],
) {
    check_sized(cx, node, expected, sizes, "the initial value");
}

fn check_sized<'t>(
    cx: &mut Cx<'t>,
    node: Node<'t>,
    expected: &Ty,
    sizes: &[Option<usize>],
    what: &str,
) {
    if crate::syntax_util::kind(node) == kind::AGGREGATE {
        aggregate(cx, node, expected, sizes);
        return;
    }
    let actual = expr(cx, node, Some(expected));
    rules::type_mismatch::check_assignable(cx, node.byte_range(), what, expected, &actual);
}

/// "a num", "an orient", "an array num{*}".
pub(crate) fn a_type(ty: &Ty) -> String {
    match ty {
        Ty::Array(..) => format!("an array {ty}"),
        Ty::Named(n) if n.starts_with(['a', 'e', 'i', 'o', 'u', 'A', 'E', 'I', 'O', 'U']) => {
            format!("an {n}")
        }
        _ => format!("a {ty}"),
    }
}

/// An aggregate takes its type from the context: a record fixes its
/// components, an array its elements.
fn aggregate<'t>(cx: &mut Cx<'t>, node: Node<'t>, expected: &Ty, sizes: &[Option<usize>]) {
    // An aggregate of literals fits its type or not by its shape alone:
    // robtargets by the thousand are checked once per shape.
    if let Some(shape) = crate::syntax_util::literal_shape(node, cx.text) {
        let key = (format!("{expected:?}"), sizes.to_vec(), shape);
        if cx.clean_literals.contains(&key) {
            return;
        }
        if let Some(Literal::Aggregate(range, elements)) = literal_aggregate(node, cx.text) {
            let before = cx.diags.len();
            literal_aggregate_check(cx, range, &elements, expected, sizes);
            if cx.diags.len() == before {
                cx.clean_literals.insert(key);
            }
            return;
        }
    }
    let elements = fields(node, field::ELEMENT);
    match expected {
        Ty::Array(elem, dims) => {
            let inner = element_type(elem, *dims);
            rules::aggregate_arity::check_array(cx, node.byte_range(), sizes, elements.len());
            let rest = sizes.get(1..).unwrap_or_default();
            for e in elements {
                check_sized(cx, e, &inner, rest, "an array element");
            }
        }
        Ty::Named(_) if cx.types.is_known(expected) => {
            let Some(components) = cx.types.components(expected) else {
                report_not_aggregate(cx, node.byte_range(), expected);
                for e in elements {
                    expr(cx, e, None);
                }
                return;
            };
            rules::aggregate_arity::check_record(
                cx,
                node.byte_range(),
                expected,
                &components,
                elements.len(),
            );
            for (e, (name, ty)) in elements.into_iter().zip(
                components
                    .iter()
                    .map(|(n, t)| (n.clone(), t.clone()))
                    .chain(std::iter::repeat((String::new(), Ty::Unknown))),
            ) {
                let what = if name.is_empty() {
                    "an element".to_owned()
                } else {
                    format!("component {name}")
                };
                check_sized(cx, e, &ty, &[], &what);
            }
        }
        _ => {
            for e in elements {
                expr(cx, e, None);
            }
        }
    }
}

/// The type of an array aggregate's elements: the array with one dimension
/// less.
fn element_type(elem: &Ty, dims: u8) -> Ty {
    if dims > 1 {
        Ty::Array(Box::new(elem.clone()), dims - 1)
    } else {
        elem.clone()
    }
}

/// An aggregate where the expected type is neither a record nor an array.
fn report_not_aggregate(cx: &mut Cx<'_>, range: Range<usize>, expected: &Ty) {
    rules::type_mismatch::report_not_aggregate(cx, range, expected);
}

/// What an element of a literal aggregate is, for messages (built only when
/// one is reported).
#[derive(Clone, Copy)]
enum What<'a> {
    ArrayElement,
    Component(&'a str),
}

impl std::fmt::Display for What<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            What::ArrayElement => f.write_str("an array element"),
            What::Component("") => f.write_str("an element"),
            What::Component(name) => write!(f, "component {name}"),
        }
    }
}

/// [`aggregate`] for an aggregate of literals read from the text: the same
/// findings, without walking its nodes. A number literal (signed or not) is
/// a `num`, a string a `string`, a boolean a `bool`; an element checked
/// without an expected type reports nothing.
fn literal_aggregate_check(
    cx: &mut Cx<'_>,
    range: std::ops::Range<usize>,
    elements: &[Literal],
    expected: &Ty,
    sizes: &[Option<usize>],
) {
    match expected {
        Ty::Array(elem, dims) => {
            let inner = element_type(elem, *dims);
            rules::aggregate_arity::check_array(cx, range.clone(), sizes, elements.len());
            let rest = sizes.get(1..).unwrap_or_default();
            for e in elements {
                literal_check(cx, e, &inner, rest, What::ArrayElement);
            }
        }
        Ty::Named(_) if cx.types.is_known(expected) => {
            let Some(components) = cx.types.components_shared(expected) else {
                report_not_aggregate(cx, range, expected);
                return;
            };
            rules::aggregate_arity::check_record(cx, range, expected, &components, elements.len());
            for (i, e) in elements.iter().enumerate() {
                match components.get(i) {
                    Some((name, ty)) => literal_check(cx, e, ty, &[], What::Component(name)),
                    None => literal_check(cx, e, &Ty::Unknown, &[], What::Component("")),
                }
            }
        }
        _ => {}
    }
}

/// [`check_sized`] for an element of a literal aggregate.
fn literal_check(
    cx: &mut Cx<'_>,
    literal: &Literal,
    expected: &Ty,
    sizes: &[Option<usize>],
    what: What<'_>,
) {
    match literal {
        Literal::Aggregate(range, elements) => {
            literal_aggregate_check(cx, range.clone(), elements, expected, sizes);
        }
        Literal::Number(range) | Literal::String(range) | Literal::Boolean(range) => {
            let actual = match literal {
                Literal::Number(_) => "num",
                Literal::String(_) => "string",
                _ => "bool",
            };
            if !cx.types.accepts(expected, actual) {
                rules::type_mismatch::report(cx, range.clone(), what, expected, &Ty::named(actual));
            }
        }
    }
}

fn unary<'t>(cx: &mut Cx<'t>, node: Node<'t>) -> Ty {
    let Some(operand) = field(node, field::OPERAND) else {
        return Ty::Unknown;
    };
    let ty = expr(cx, operand, None);
    match typing::unary(&cx.types, typing::unary_op(node), &ty) {
        Ok(ty) => ty,
        Err(()) => {
            let op = field(node, field::OPERATOR).unwrap_or(node);
            rules::invalid_operands::report_unary(cx, node.byte_range(), op, &ty);
            Ty::Unknown
        }
    }
}

fn binary<'t>(cx: &mut Cx<'t>, node: Node<'t>) -> Ty {
    let (Some(l), Some(r), Some(op_node)) = (
        field(node, field::LEFT),
        field(node, field::RIGHT),
        field(node, field::OPERATOR),
    ) else {
        return Ty::Unknown;
    };
    let op = crate::syntax_util::kind(op_node);
    let is_comparison = typing::is_comparison(op);
    // A bare unknown name compared with a number is most likely a signal.
    // An aggregate operand takes its type from the other operand when that
    // is a record (`p + [0, 0, 10]`), and is left unknown otherwise.
    let (lt, rt) = match (
        crate::syntax_util::kind(l) == kind::AGGREGATE,
        crate::syntax_util::kind(r) == kind::AGGREGATE,
    ) {
        (true, false) => {
            let rt = operand(cx, r, l, is_comparison);
            (aggregate_operand(cx, l, &rt), rt)
        }
        (false, true) => {
            let lt = operand(cx, l, r, is_comparison);
            let rt = aggregate_operand(cx, r, &lt);
            (lt, rt)
        }
        (true, true) => (
            aggregate_operand(cx, l, &Ty::Unknown),
            aggregate_operand(cx, r, &Ty::Unknown),
        ),
        (false, false) => (
            operand(cx, l, r, is_comparison),
            operand(cx, r, l, is_comparison),
        ),
    };
    let result = typing::binary(&cx.types, op, &lt, &rt);
    match result {
        Ok(ty) => {
            if is_comparison {
                rules::float_equality::check(cx, node, op_node, (l, &lt), (r, &rt));
            }
            ty
        }
        Err(fallback) => {
            rules::invalid_operands::report_binary(cx, op_node, &lt, &rt);
            fallback
        }
    }
}

/// An aggregate operand, typed as the other operand when that is a record
/// or an array (as an assignment's target types its value).
fn aggregate_operand<'t>(cx: &mut Cx<'t>, node: Node<'t>, other: &Ty) -> Ty {
    match typing::aggregate_operand(&cx.types, other) {
        Some(ty) => {
            aggregate(cx, node, &ty, &[]);
            ty
        }
        None => {
            for e in fields(node, field::ELEMENT) {
                expr(cx, e, None);
            }
            Ty::Unknown
        }
    }
}

/// The type of one operand; an unknown bare name compared with a number is
/// taken for a signal.
fn operand<'t>(cx: &mut Cx<'t>, node: Node<'t>, other: Node<'t>, comparison: bool) -> Ty {
    if typing::taken_for_signal(cx, node, other, comparison) {
        let name = cx.node_text(node);
        cx.unknown_signal(node, name, &Ty::named("signaldi"));
        return Ty::named("signaldi");
    }
    expr(cx, node, None)
}

/// The signal a `TEST` of an unknown bare name is taken for, when every
/// `CASE` value is a number (as a comparison with a number takes it):
/// a `signaldi` when they are all 0 or 1, else a `signalgi`.
pub(super) fn tested_signal<'t>(cx: &Cx<'t>, value: Node<'t>, cases: &[Node<'t>]) -> Option<Ty> {
    let taken = !cases.is_empty()
        && cases
            .iter()
            .all(|c| typing::taken_for_signal(cx, value, *c, true));
    let bit =
        |c: &Node<'t>| c.kind() != kind::NUMBER || matches!(cx.node_text(*c).trim(), "0" | "1");
    taken.then(|| {
        Ty::named(if cases.iter().all(bit) {
            "signaldi"
        } else {
            "signalgi"
        })
    })
}

/// `a.b`: the component's type.
fn component<'t>(cx: &mut Cx<'t>, node: Node<'t>) -> (Ty, Place) {
    let (Some(obj), Some(comp)) = (field(node, field::OBJECT), field(node, field::COMPONENT))
    else {
        return (Ty::Unknown, Place::Unknown);
    };
    let (obj_ty, place) = place_or_value(cx, obj);
    (
        rules::unknown_component::component_type(cx, &obj_ty, comp),
        place,
    )
}

/// `a{i, j}`: the element type.
fn index<'t>(cx: &mut Cx<'t>, node: Node<'t>) -> (Ty, Place) {
    let Some(obj) = field(node, field::OBJECT) else {
        return (Ty::Unknown, Place::Unknown);
    };
    let (obj_ty, place) = place_or_value(cx, obj);
    let indexes = fields(node, field::INDEX);
    for i in &indexes {
        let ty = expr(cx, *i, Some(&Ty::num()));
        rules::non_numeric_index::check(cx, i.byte_range(), &ty);
    }
    let (ty, error) = typing::index(&cx.types, &obj_ty, indexes.len());
    if let Some(error) = error {
        rules::index_count::report(cx, node.byte_range(), &obj_ty, &error, indexes.len());
    }
    (ty, place)
}

/// The type and place of a data reference (a name, a component, an
/// element); other expressions are values.
pub(crate) fn place_or_value<'t>(cx: &mut Cx<'t>, node: Node<'t>) -> (Ty, Place) {
    match crate::syntax_util::kind(node) {
        kind::IDENTIFIER => {
            let name = cx.node_text(node);
            match cx.resolve_data(name) {
                Some(sym) => (sym.ty(cx.task, &cx.types), Place::of(&sym, cx.task)),
                None => {
                    cx.unresolved(name, node.byte_range(), "data");
                    (Ty::Unknown, Place::Unknown)
                }
            }
        }
        kind::COMPONENT_ACCESS => component(cx, node),
        kind::INDEX_EXPRESSION => index(cx, node),
        kind::PLACEHOLDER => (Ty::Unknown, Place::Unknown),
        _ => (expr(cx, node, None), Place::Value),
    }
}

/// A place that an argument passes by reference; an unknown name where a
/// signal is expected is taken for the signal.
pub(super) fn reference<'t>(cx: &mut Cx<'t>, node: Node<'t>, expected: &Ty) -> (Ty, Place) {
    if crate::syntax_util::kind(node) == kind::IDENTIFIER && is_configured(cx, expected) {
        let name = cx.node_text(node);
        if cx.resolve_data(name).is_none() {
            cx.unknown_signal(node, name, expected);
            return (expected.clone(), Place::Unknown);
        }
    }
    place_or_value(cx, node)
}
