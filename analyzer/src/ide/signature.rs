//! Signature help for procedure calls (`MoveL p10, |`) and function calls.

use std::ops::Range;

use super::SignatureHelp;
use super::context::{ArgCx, CallCx, before, call_at};
use crate::catalogue::Mode;
use crate::names::same;
use crate::sema::scope::Scope;
use crate::sema::signature::{Arg, Binding, Param, Signature, Target, bind_args};
use crate::task::Task;

/// The routine of the call around `offset` and the call's context.
pub(crate) fn call_sig(task: &Task, unit: usize, offset: usize) -> Option<(Signature, CallCx)> {
    let u = task.unit(unit)?;
    let bf = before(&u.text, offset);
    if bf.in_comment || bf.in_string {
        return None;
    }
    let call = call_at(&bf)?;
    let cx = Scope::at(task, unit, offset)?;
    let sym = cx.resolve_routine(&call.name, call.is_function)?;
    Some((Signature::of(&sym, cx.task)?, call))
}

/// An argument typed so far, as the binder takes it.
fn arg_of(a: &ArgCx) -> Arg<'_> {
    match (&a.name, a.optional) {
        (Some(n), _) => Arg::Named(n),
        // A lone `\`: no parameter's name.
        (None, true) => Arg::Named(""),
        (None, false) => Arg::Positional,
    }
}

/// The arguments before the current one, bound to the signature.
fn bind_done(sig: &Signature, call: &CallCx) -> Binding {
    let args: Vec<Arg<'_>> = call.done.iter().map(arg_of).collect();
    bind_args(sig, &args)
}

/// Where the next argument of the call goes: the index of the parameter
/// after the last one the arguments before it are bound to.
pub(crate) fn next_position(sig: &Signature, call: &CallCx) -> usize {
    bind_done(sig, call).next_param()
}

/// The index of the parameter the current argument goes to: a named one's
/// own; after `\`, the first optional parameter from the call's position
/// on whose name starts with what is typed; else the parameter the checker
/// binds it to (the next positional one).
pub(crate) fn active(sig: &Signature, call: &CallCx) -> Option<usize> {
    if let Some(name) = &call.current.name
        && (call.current.optional || call.current.has_value)
        && let Some(i) = sig.param(name)
    {
        return Some(i);
    }
    if call.current.optional {
        let at = next_position(sig, call);
        let typed = call.current.name.as_deref().unwrap_or_default();
        let starts = |p: &&Param| {
            !p.positional()
                && p.name
                    .get(..typed.len())
                    .is_some_and(|head| same(head, typed))
        };
        return sig
            .params
            .iter()
            .enumerate()
            .skip(at)
            .find(|(_, p)| starts(p))
            .or_else(|| sig.params.iter().enumerate().find(|(_, p)| starts(p)))
            .map(|(i, _)| i);
    }
    let mut args: Vec<Arg<'_>> = call.done.iter().map(arg_of).collect();
    args.push(Arg::Positional);
    match bind_args(sig, &args).args.last()?.target {
        Target::Param(i) => Some(i),
        Target::UnknownName | Target::TooMany => None,
    }
}

/// A parameter as the signature shows it: `[\switch Conc]`, `robtarget
/// ToPoint`, `PERS tooldata Tool`, `[\PERS wobjdata WObj]`.
fn param_label(p: &Param) -> String {
    let mode = if p.mode == Mode::In {
        String::new()
    } else {
        format!("{} ", p.mode.keyword())
    };
    let ty = if p.switch {
        "switch"
    } else {
        p.type_name.as_str()
    };
    let ty = if ty.is_empty() { "?" } else { ty };
    if p.optional {
        format!("[\\{mode}{ty} {}]", p.name)
    } else {
        format!("{mode}{ty} {}", p.name)
    }
}

/// `MoveL [\switch Conc], robtarget ToPoint, [\identno ID], speeddata
/// Speed, [\num V] | [\num T], ...` (a function's in parentheses) and each
/// parameter's range in it.
pub(crate) fn label(sig: &Signature) -> (String, Vec<Range<usize>>) {
    let mut out = sig.name.clone();
    out.push_str(if sig.is_function() { "(" } else { " " });
    let mut ranges = Vec::new();
    let mut prev_group = None;
    for (i, p) in sig.params.iter().enumerate() {
        if i > 0 {
            if p.alt_group.is_some() && p.alt_group == prev_group {
                out.push_str(" | ");
            } else {
                out.push_str(", ");
            }
        }
        prev_group = p.alt_group;
        let start = out.len();
        out.push_str(&param_label(p));
        ranges.push(start..out.len());
    }
    if sig.is_function() {
        out.push(')');
    }
    (out, ranges)
}

/// The signature of the procedure or function call around `offset`, with
/// the parameter the current argument goes to.
pub fn signature_help(task: &Task, unit: usize, offset: usize) -> Option<SignatureHelp> {
    let (sig, call) = call_sig(task, unit, offset)?;
    let (label, ranges) = label(&sig);
    let parameters = ranges
        .into_iter()
        .zip(&sig.params)
        .map(|(r, p)| {
            let mode = if p.mode == Mode::In {
                String::new()
            } else {
                format!("{} ", p.mode.keyword())
            };
            let doc = if p.switch {
                "switch".to_owned()
            } else {
                format!("{mode}{}", p.type_name)
            };
            (r, Some(doc))
        })
        .collect();
    Some(SignatureHelp {
        label,
        parameters,
        active_parameter: active(&sig, &call),
        documentation: sig.doc.clone(),
    })
}
