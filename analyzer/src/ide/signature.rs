//! Signature help for procedure calls (`MoveL p10, |`) and function calls.

use std::ops::Range;

use super::SignatureHelp;
use super::context::{CallCx, before, call_at};
use crate::catalogue::Mode;
use crate::check::{Cx, RoutineSym};
use crate::names::same;
use crate::task::Task;

/// A parameter, of a built-in or a user routine.
#[derive(Clone, Debug)]
pub(crate) struct P {
    pub name: String,
    pub ty: String,
    pub optional: bool,
    pub switch: bool,
    pub alt_group: Option<u32>,
    pub mode: Mode,
}

/// A routine's signature as the editor features need it.
#[derive(Clone, Debug)]
pub(crate) struct Sig {
    pub name: String,
    pub params: Vec<P>,
    pub is_function: bool,
    pub doc: Option<String>,
}

pub(crate) fn sig_of(sym: RoutineSym<'_>) -> Sig {
    match sym {
        RoutineSym::Builtin(r, _) => Sig {
            name: r.name.clone(),
            params: r
                .params
                .iter()
                .map(|p| P {
                    name: p.name.clone(),
                    ty: p.ty.clone(),
                    optional: p.optional,
                    switch: p.switch,
                    alt_group: p.alt_group,
                    mode: p.mode.unwrap_or(Mode::In),
                })
                .collect(),
            is_function: r.returns.is_some(),
            doc: Some(r.summary.clone()).filter(|s| !s.is_empty()),
        },
        RoutineSym::User(d, _) => Sig {
            name: d.name.clone(),
            params: d
                .params
                .iter()
                .map(|p| P {
                    name: p.name.clone(),
                    ty: p.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                    optional: p.optional,
                    switch: p.switch,
                    alt_group: p.alt_group,
                    mode: p.mode,
                })
                .collect(),
            is_function: d.kind == crate::items::RoutineKind::Func,
            doc: None,
        },
    }
}

/// The routine of the call around `offset` and the call's context.
pub(crate) fn call_sig(task: &Task, unit: usize, offset: usize) -> Option<(Sig, CallCx)> {
    let u = task.units.get(unit)?;
    let bf = before(&u.text, offset);
    if bf.in_comment || bf.in_string {
        return None;
    }
    let call = call_at(&bf)?;
    let mut cx = Cx::at(task, unit, offset)?;
    let sym = cx.resolve_routine(&call.name, call.is_function)?;
    Some((sig_of(sym), call))
}

/// Where the next argument of the call goes: the index of the first
/// parameter after those the arguments before it filled (arguments come in
/// the order of the parameters; a positional argument fills the next
/// required parameter, a named one its own).
pub(crate) fn next_position(sig: &Sig, call: &CallCx) -> usize {
    let mut at = 0;
    for arg in &call.done {
        let named = arg
            .name
            .as_ref()
            .and_then(|n| sig.params.iter().position(|p| same(&p.name, n)));
        let filled = match named {
            Some(i) => Some(i),
            None if arg.optional => None,
            None => sig
                .params
                .iter()
                .enumerate()
                .skip(at)
                .find(|(_, p)| !p.optional)
                .map(|(i, _)| i),
        };
        if let Some(i) = filled {
            at = at.max(i + 1);
        }
    }
    at
}

/// The index of the parameter the current argument goes to: a named one's
/// own; after `\`, the first optional parameter from the call's position
/// on whose name starts with what is typed; else the next required one.
pub(crate) fn active(sig: &Sig, call: &CallCx) -> Option<usize> {
    if let Some(name) = &call.current.name
        && (call.current.optional || call.current.has_value)
        && let Some(i) = sig.params.iter().position(|p| same(&p.name, name))
    {
        return Some(i);
    }
    let at = next_position(sig, call);
    if call.current.optional {
        let typed = call.current.name.as_deref().unwrap_or_default();
        let starts = |p: &&P| {
            p.optional
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
    sig.params
        .iter()
        .enumerate()
        .skip(at)
        .find(|(_, p)| !p.optional)
        .map(|(i, _)| i)
}

/// A parameter as the signature shows it: `[\switch Conc]`, `robtarget
/// ToPoint`, `PERS tooldata Tool`, `[\PERS wobjdata WObj]`.
fn param_label(p: &P) -> String {
    let mode = if p.mode == Mode::In {
        String::new()
    } else {
        format!("{} ", p.mode.keyword())
    };
    let ty = if p.switch { "switch" } else { p.ty.as_str() };
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
pub(crate) fn label(sig: &Sig) -> (String, Vec<Range<usize>>) {
    let mut out = sig.name.clone();
    out.push_str(if sig.is_function { "(" } else { " " });
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
    if sig.is_function {
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
                format!("{mode}{}", p.ty)
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
