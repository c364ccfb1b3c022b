//! Calls of procedures and functions, checked against the routine's
//! signature: argument count, names, switches, `|` alternatives, modes,
//! arrays and types.

use std::ops::Range;
use std::rc::Rc;

use tree_sitter::Node;

use super::{Cx, Place, exprs};
use crate::catalogue::Mode;
use crate::rules;
use crate::sema::def::Def;
use crate::sema::signature::{Arg, Binding, BoundArg, Param, Signature, Target, bind_args};
use crate::syntax::{field, kind};
use crate::syntax_util::{ArgumentParts, argument_parts, field, fields};
use crate::ty::Ty;

/// The signature of a routine, made once per check context (a MoveL
/// signature is some twenty parameters of names and types).
fn signature(cx: &mut Cx<'_>, def: &Def<'_>) -> Option<Rc<Signature>> {
    let key = match def {
        Def::BuiltinRoutine(r) => (std::ptr::from_ref(*r) as usize, false),
        def => (
            std::ptr::from_ref(def.routine_decl(cx.task)?) as usize,
            true,
        ),
    };
    if let Some(sig) = cx.signatures.get(&key) {
        return Some(Rc::clone(sig));
    }
    let sig = Rc::new(Signature::of(def, cx.task)?);
    cx.signatures.insert(key, Rc::clone(&sig));
    Some(sig)
}

/// A procedure call statement.
pub(super) fn procedure_call<'t>(cx: &mut Cx<'t>, node: Node<'t>) {
    let Some(name_node) = field(node, field::NAME) else {
        return;
    };
    let args = field(node, field::ARGUMENTS);
    if crate::syntax_util::kind(name_node) == kind::LATE_BINDING {
        if let Some(e) = field(name_node, field::EXPRESSION) {
            exprs::check_expected(cx, e, &Ty::string(), "a late-bound procedure name");
        }
        check_args_unknown(cx, args);
        return;
    }
    let name = cx.node_text(name_node);
    if node.has_error() {
        // The parser could not make sense of the call: checking its
        // arguments would only repeat the syntax error in other words.
        let _ = cx.resolve_routine(name, false);
        check_args_unknown(cx, args);
        return;
    }
    match cx.resolve_routine(name, false) {
        Some(sym) => {
            cx.def_used(&sym, name_node.byte_range());
            let Some(sig) = signature(cx, &sym) else {
                check_args_unknown(cx, args);
                return;
            };
            rules::call_kind_mismatch::check_procedure_call(cx, &sig, name_node.byte_range());
            check_args(cx, &sig, args, name_node.byte_range());
        }
        None => {
            rules::not_a_routine::check(cx, name, name_node.byte_range());
            check_args_unknown(cx, args);
        }
    }
}

/// A function call in an expression; returns the result type.
pub(super) fn function_call<'t>(cx: &mut Cx<'t>, node: Node<'t>) -> Ty {
    let Some(name_node) = field(node, field::NAME) else {
        return Ty::Unknown;
    };
    let args = field(node, field::ARGUMENTS);
    let name = cx.node_text(name_node);
    if node.has_error() {
        let _ = cx.resolve_routine(name, true);
        check_args_unknown(cx, args);
        return Ty::Unknown;
    }
    match cx.resolve_routine(name, true) {
        Some(sym) => {
            cx.def_used(&sym, name_node.byte_range());
            let Some(sig) = signature(cx, &sym) else {
                check_args_unknown(cx, args);
                return Ty::Unknown;
            };
            rules::call_kind_mismatch::check_function_call(cx, &sig, name_node.byte_range());
            check_args(cx, &sig, args, name_node.byte_range());
            sig.returns.clone().unwrap_or(Ty::Unknown)
        }
        None => {
            rules::not_a_routine::check(cx, name, name_node.byte_range());
            check_args_unknown(cx, args);
            Ty::Unknown
        }
    }
}

/// Arguments of a call whose signature is unknown: check their expressions.
fn check_args_unknown<'t>(cx: &mut Cx<'t>, args: Option<Node<'t>>) {
    let Some(args) = args else {
        return;
    };
    for arg in fields(args, field::ARGUMENT) {
        let parts = argument_parts(arg);
        if let Some(v) = parts.value
            && crate::syntax_util::kind(v) != kind::STAR
        {
            exprs::place_or_value(cx, v);
        }
        if let Some(c) = parts.conditional {
            rules::conditional_argument::check(cx, c);
        }
    }
}

fn check_args<'t>(cx: &mut Cx<'t>, sig: &Signature, args: Option<Node<'t>>, call: Range<usize>) {
    if !sig.known {
        check_args_unknown(cx, args);
        return;
    }
    let (args, parts, binding) = bind_call(cx, sig, args);
    for ((arg, parts), bound) in args.iter().zip(&parts).zip(&binding.args) {
        report_argument(cx, sig, &args, *arg, parts, bound);
    }
    report_missing(cx, sig, &binding, call);
}

/// A call's arguments (the `arguments` node's), their parts and their
/// binding to `sig`'s parameters.
pub(super) fn bind_call<'t>(
    cx: &Cx<'t>,
    sig: &Signature,
    args: Option<Node<'t>>,
) -> (Vec<Node<'t>>, Vec<ArgumentParts<'t>>, Binding) {
    let args = args.map(|a| fields(a, field::ARGUMENT)).unwrap_or_default();
    let parts: Vec<_> = args.iter().map(|&a| argument_parts(a)).collect();
    let given: Vec<Arg<'_>> = parts
        .iter()
        .map(|p| match p.name {
            Some(n) => Arg::Named(cx.node_text(n)),
            None => Arg::Positional,
        })
        .collect();
    let binding = bind_args(sig, &given);
    (args, parts, binding)
}

/// The findings of one argument: where it goes, and its value.
fn report_argument<'t>(
    cx: &mut Cx<'t>,
    sig: &Signature,
    args: &[Node<'t>],
    arg: Node<'t>,
    parts: &ArgumentParts<'t>,
    bound: &BoundArg,
) {
    let value = parts.value;
    let index = match bound.target {
        Target::Param(i) => i,
        Target::TooMany => {
            rules::argument_count::too_many(cx, sig, arg.byte_range());
            if let Some(v) = value
                && crate::syntax_util::kind(v) != kind::STAR
            {
                exprs::place_or_value(cx, v);
            }
            return;
        }
        Target::UnknownName => {
            let Some(n) = parts.name else {
                return;
            };
            rules::unknown_argument::report(cx, sig, n);
            if let Some(v) = value
                && crate::syntax_util::kind(v) != kind::STAR
            {
                exprs::place_or_value(cx, v);
            }
            if let Some(c) = parts.conditional {
                rules::conditional_argument::check(cx, c);
            }
            return;
        }
    };
    let Some(p) = sig.params.get(index) else {
        return;
    };
    if let Some(prev) = bound.repeats.and_then(|k| args.get(k)) {
        rules::duplicate_argument::report(cx, p, arg.byte_range(), prev.byte_range());
    }
    if let (Some(other), Some(g)) = (bound.excludes, p.alt_group) {
        rules::conflicting_alternatives::report(cx, sig, p, other, g, arg.byte_range());
    }
    if let Some(c) = parts.conditional {
        rules::conditional_argument::check(cx, c);
        return;
    }
    match value {
        Some(v) if p.switch => {
            rules::switch_argument::given_a_value(cx, p, arg.byte_range());
            exprs::place_or_value(cx, v);
        }
        Some(v) => check_value(cx, p, v, searches_signal(sig, p)),
        None if p.switch => {}
        None if parts.backslash => rules::switch_argument::needs_a_value(cx, p, arg.byte_range()),
        None => {}
    }
}

/// The required parameters and `|` groups the call leaves out.
fn report_missing(cx: &mut Cx<'_>, sig: &Signature, binding: &Binding, call: Range<usize>) {
    rules::argument_count::missing(cx, sig, &binding.missing, call.clone());
    for &g in &binding.missing_groups {
        rules::missing_alternative::report(cx, sig, g, call.clone());
    }
}

/// A search's `Signal | PersBool` parameter (`SearchL`...: any type in the
/// catalogue, either a digital input or a `PERS bool`): a name declared
/// nowhere there is taken for the digital input, as a signal parameter
/// takes it.
fn searches_signal(sig: &Signature, p: &Param) -> bool {
    matches!(p.ty, Ty::Any)
        && p.name.eq_ignore_ascii_case("Signal")
        && sig
            .params
            .iter()
            .any(|q| q.name.eq_ignore_ascii_case("SearchPoint"))
}

fn check_value<'t>(cx: &mut Cx<'t>, p: &Param, v: Node<'t>, signal: bool) {
    if crate::syntax_util::kind(v) == kind::STAR {
        return;
    }
    let (actual, place) = match p.mode {
        Mode::In => {
            if crate::syntax_util::kind(v) == kind::AGGREGATE {
                exprs::check_expected(cx, v, &p.ty, &format!("the argument {}", p.name));
                return;
            }
            (exprs::expr(cx, v, Some(&p.ty)), Place::Value)
        }
        _ if signal => exprs::reference(cx, v, &Ty::named("signaldi")),
        _ => exprs::reference(cx, v, &p.ty),
    };
    if !rules::argument_mode::check(cx, p, place, v.byte_range()) {
        return;
    }
    if !cx.types.is_known(&actual) || matches!(p.ty, Ty::Unknown) {
        return;
    }
    if !rules::array_argument::check(cx, p, &actual, v.byte_range()) {
        return;
    }
    let what = format_args!("the argument {}", p.name);
    rules::type_mismatch::check_assignable(cx, v.byte_range(), what, &p.ty, &actual);
}
