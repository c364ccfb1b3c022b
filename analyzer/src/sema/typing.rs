//! The type of an expression, reporting nothing: the typing rules, which
//! the checker applies too (it reports where a rule says no), and
//! [`type_of`], which composes them for the editor features and constant
//! evaluation.

use rapid_catalogue::operators::{self, Op};
use tree_sitter::Node;

use super::scope::Scope;
use super::signature::Signature;
use crate::syntax::{field, kind};
use crate::syntax_util::{field, kind as kind_of};
use crate::ty::{Ty, Types};

/// The type of expression `node` in `scope`; `expected` is what its
/// context expects (it types aggregates and names taken for signals).
/// Unknown where the checker would report a mistake that leaves no type.
pub(crate) fn type_of(scope: &Scope<'_>, node: Node<'_>, expected: Option<&Ty>) -> Ty {
    let types = &scope.types;
    match kind_of(node) {
        kind::NUMBER => Ty::num(),
        kind::STRING => Ty::string(),
        kind::BOOLEAN => Ty::bool(),
        kind::IDENTIFIER => match scope.resolve_data(scope.node_text(node)) {
            Some(def) => def.ty(scope.task, types),
            None => match expected {
                Some(exp) if is_configured(types, exp) => exp.clone(),
                _ => Ty::Unknown,
            },
        },
        kind::PARENTHESIZED_EXPRESSION => match field(node, field::EXPRESSION) {
            Some(e) => type_of(scope, e, expected),
            None => Ty::Unknown,
        },
        kind::UNARY_EXPRESSION => {
            let Some(operand) = field(node, field::OPERAND) else {
                return Ty::Unknown;
            };
            let ty = type_of(scope, operand, None);
            unary(types, unary_op(node), &ty).unwrap_or(Ty::Unknown)
        }
        kind::BINARY_EXPRESSION => {
            let (Some(l), Some(r), Some(op)) = (
                field(node, field::LEFT),
                field(node, field::RIGHT),
                field(node, field::OPERATOR),
            ) else {
                return Ty::Unknown;
            };
            let op = kind_of(op);
            let comparison = is_comparison(op);
            let operand = |n: Node<'_>, other: Node<'_>| {
                if taken_for_signal(scope, n, other, comparison) {
                    Ty::named("signaldi")
                } else {
                    type_of(scope, n, None)
                }
            };
            let (lt, rt) = match (kind_of(l) == kind::AGGREGATE, kind_of(r) == kind::AGGREGATE) {
                (true, false) => {
                    let rt = operand(r, l);
                    (aggregate_operand(types, &rt).unwrap_or(Ty::Unknown), rt)
                }
                (false, true) => {
                    let lt = operand(l, r);
                    let rt = aggregate_operand(types, &lt).unwrap_or(Ty::Unknown);
                    (lt, rt)
                }
                (true, true) => (Ty::Unknown, Ty::Unknown),
                (false, false) => (operand(l, r), operand(r, l)),
            };
            binary(types, op, &lt, &rt).unwrap_or_else(|fallback| fallback)
        }
        kind::FUNCTION_CALL => {
            if node.has_error() {
                return Ty::Unknown;
            }
            field(node, field::NAME)
                .and_then(|n| scope.resolve_routine(scope.node_text(n), true))
                .and_then(|def| Signature::of(&def, scope.task)?.returns)
                .unwrap_or(Ty::Unknown)
        }
        kind::COMPONENT_ACCESS => {
            let (Some(obj), Some(comp)) =
                (field(node, field::OBJECT), field(node, field::COMPONENT))
            else {
                return Ty::Unknown;
            };
            let obj_ty = type_of(scope, obj, None);
            component(types, &obj_ty, scope.node_text(comp)).unwrap_or(Ty::Unknown)
        }
        kind::INDEX_EXPRESSION => {
            let Some(obj) = field(node, field::OBJECT) else {
                return Ty::Unknown;
            };
            let obj_ty = type_of(scope, obj, None);
            let count = crate::syntax_util::fields(node, field::INDEX).len();
            index(types, &obj_ty, count).0
        }
        kind::AGGREGATE => expected.cloned().unwrap_or(Ty::Unknown),
        _ => Ty::Unknown,
    }
}

/// Is a value of this type configured on the controller rather than
/// declared in RAPID (an I/O signal, a mechanical unit)?
pub(crate) fn is_configured(types: &Types<'_>, ty: &Ty) -> bool {
    types.is_signal(ty) || types.base(ty).is("mecunit")
}

/// The operator of a unary expression (`not`, `-`, `+`).
pub(crate) fn unary_op<'a>(node: Node<'a>) -> &'a str {
    field(node, field::OPERATOR)
        .map(kind_of)
        .unwrap_or_default()
}

/// The type of a unary operation on a value of type `ty`; `Err` when the
/// operator does not apply to it. An unknown operand gives a bool for
/// `NOT`, else an unknown type.
pub(crate) fn unary(types: &Types<'_>, op: &str, ty: &Ty) -> Result<Ty, ()> {
    if !types.is_known(ty) {
        return Ok(if op == "not" { Ty::bool() } else { Ty::Unknown });
    }
    let base = types.base(ty);
    let ok = match op {
        "not" => base.is("bool"),
        _ => types.is_num_like(ty) || base.is("pos"),
    };
    if ok {
        Ok(types.value_type(ty))
    } else {
        Err(())
    }
}

/// Is the binary operator `op` (its node kind) `=` or `<>`?
pub(crate) fn is_comparison(op: &str) -> bool {
    matches!(op, "=" | "<>")
}

/// The type an aggregate operand takes from the other operand: the other's
/// type when that is a known array or a record (as an assignment's target
/// types its value); `None` when it gives the aggregate no type.
pub(crate) fn aggregate_operand(types: &Types<'_>, other: &Ty) -> Option<Ty> {
    let ty = types.value_type(other);
    if other.dims() > 0 && types.is_known(other) {
        Some(other.clone())
    } else if other.dims() == 0 && types.components(&ty).is_some() {
        Some(ty)
    } else {
        None
    }
}

/// Is operand `node` of a comparison taken for a digital input signal: a
/// bare name that nothing declares, compared with a number or a `dionum`
/// constant, while the controller's I/O configuration is not given?
pub(crate) fn taken_for_signal(
    scope: &Scope<'_>,
    node: Node<'_>,
    other: Node<'_>,
    comparison: bool,
) -> bool {
    if !(comparison
        && kind_of(node) == kind::IDENTIFIER
        && matches!(kind_of(other), kind::NUMBER | kind::IDENTIFIER)
        && scope.task.signals.is_none())
    {
        return false;
    }
    let name = scope.node_text(node);
    scope.resolve_data(name).is_none()
        && scope.resolve_routine(name, true).is_none()
        && scope.local_elsewhere(name).is_none()
        && (kind_of(other) == kind::NUMBER
            || scope
                .cat
                .datum(scope.node_text(other))
                .is_some_and(|d| d.ty.eq_ignore_ascii_case("dionum")))
}

/// The type of a binary operation (`op` is the operator's node kind) on
/// values of types `lt` and `rt`: the shared operator table, with unknown
/// types compatible with everything (one mistake, one finding). `Err`
/// when the operator does not apply, with the type the expression is
/// given all the same (a comparison or a logical operator gives a bool).
pub(crate) fn binary(types: &Types<'_>, op: &str, lt: &Ty, rt: &Ty) -> Result<Ty, Ty> {
    let t = types;
    let (lb, rb) = (t.base(lt), t.base(rt));
    let unknown = !t.is_known(lt) || !t.is_known(rt);
    let num = |x: &Ty| t.is_num_like(x);
    let op = Op::parse(op);
    let result = match op {
        // Values of one type compare, arrays too (same element type and
        // number of dimensions: `stReact = ["Ready", "Ready", "Ready"]` for a
        // `string{3}` is loaded by real controllers).
        Some(Op::Eq | Op::Ne) => {
            (unknown || t.assignable(lt, rt) || t.assignable(rt, lt)).then(Ty::bool)
        }
        // With an unknown operand, say what the known one implies.
        Some(Op::Add | Op::Sub) if unknown => {
            Some(t.value_type(if lt.is_unknown() { rt } else { lt }))
        }
        // num * unknown may be num * pos: say nothing about the result.
        Some(Op::Mul) if unknown => Some(if lb.is("pos") || rb.is("pos") {
            Ty::named("pos")
        } else if lb.is("orient") || rb.is("orient") {
            Ty::named("orient")
        } else {
            Ty::Unknown
        }),
        Some(Op::Div) if unknown => Some(
            match operators::binary_by(Op::Div, |l| lb.is(l), |r| r == "num") {
                Some("pos") => Ty::named("pos"),
                _ => Ty::Unknown,
            },
        ),
        // The shared operator table; an operand of an unknown type is
        // taken to be anything numeric or a bool.
        Some(op) => {
            let is = |x: &Ty, b: &Ty, name: &str| match name {
                "num" => num(x) && !b.is("dnum"),
                "dnum" => b.is("dnum"),
                "bool" => t.is_bool(x),
                other => b.is(other),
            };
            operators::binary_by(op, |l| is(lt, &lb, l), |r| is(rt, &rb, r)).map(Ty::named)
        }
        None => None,
    };
    result.ok_or_else(|| {
        let gives_bool = matches!(
            op,
            Some(Op::Eq | Op::Ne | Op::Lt | Op::Gt | Op::Le | Op::Ge | Op::And | Op::Or | Op::Xor)
        );
        if gives_bool { Ty::bool() } else { Ty::Unknown }
    })
}

/// Why a component access has no type.
pub(crate) enum ComponentError {
    /// `.name` on an array.
    OnArray,
    /// The record has no such component; its components, in order.
    NoSuch(Vec<String>),
    /// The value is not a record.
    NotRecord,
}

/// The type of component `name` of a value of type `obj`; unknown when
/// `obj` is.
pub(crate) fn component(types: &Types<'_>, obj: &Ty, name: &str) -> Result<Ty, ComponentError> {
    if !types.is_known(obj) {
        return Ok(Ty::Unknown);
    }
    if obj.dims() > 0 {
        return Err(ComponentError::OnArray);
    }
    let components = types.components(obj).ok_or(ComponentError::NotRecord)?;
    match components.iter().find(|(n, _)| crate::names::same(n, name)) {
        Some((_, t)) => Ok(t.clone()),
        None => Err(ComponentError::NoSuch(
            components.into_iter().map(|(n, _)| n).collect(),
        )),
    }
}

/// Why indexing is wrong.
pub(crate) enum IndexError {
    /// The value is not an array.
    NotArray,
    /// The array has this many dimensions, not as many as indexes.
    Count(usize),
}

/// The element type of a value of type `obj` indexed with `count`
/// indexes, and what is wrong with that. An array indexed with the wrong
/// number of indexes still gives its element type.
pub(crate) fn index(types: &Types<'_>, obj: &Ty, count: usize) -> (Ty, Option<IndexError>) {
    if !types.is_known(obj) {
        return (Ty::Unknown, None);
    }
    let dims = usize::from(obj.dims());
    if dims == 0 {
        return (Ty::Unknown, Some(IndexError::NotArray));
    }
    let error = (dims != count).then_some(IndexError::Count(dims));
    (obj.element().clone(), error)
}

#[cfg(test)]
#[path = "typing_tests.rs"]
mod tests;
