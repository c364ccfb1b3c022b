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

/// The index of the parameter the current argument goes to.
pub(crate) fn active(sig: &Sig, call: &CallCx) -> Option<usize> {
    if let Some(name) = &call.current.name
        && (call.current.optional || call.current.has_value)
    {
        if let Some(i) = sig.params.iter().position(|p| same(&p.name, name)) {
            return Some(i);
        }
        if call.current.optional {
            return None;
        }
    }
    if call.current.optional {
        // `\` with a name still being typed: the first optional left.
        return None;
    }
    // Positional: count the required arguments already given.
    let given = call.done.iter().filter(|a| !a.optional).count();
    sig.params
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.optional)
        .nth(given)
        .map(|(i, _)| i)
}

/// `MoveL [\Conc] ToPoint [\ID] Speed [\V] | [\T] Zone ...` and each
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
                out.push(' ');
            }
        }
        prev_group = p.alt_group;
        let start = out.len();
        if p.optional {
            out.push_str("[\\");
            out.push_str(&p.name);
            out.push(']');
        } else {
            out.push_str(&p.name);
        }
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
