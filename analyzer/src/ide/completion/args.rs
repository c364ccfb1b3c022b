//! Completion of a call's arguments and of values: after `\`, the optional
//! arguments that may come next; where a value of a type is due (an
//! argument, the value after `:=`), the data of that type, the most used
//! first, and the functions that return it.

use std::collections::{HashMap, HashSet};

use super::super::context::{Before, CallCx, call_at, statement_start};
use super::super::signature::active;
use super::super::{CompletionItem, CompletionKind};
use super::{Want, assignment_target, expression_items};
use crate::names::{fold, is_name_byte_at, name_len, same};
use crate::sema::scope::Scope;
use crate::sema::signature::Signature;
use crate::ty::Ty;

/// The type of the parameter the argument being written goes to.
pub(super) fn expected_type(cx: &Scope<'_>, call: &CallCx) -> Option<String> {
    let sym = cx.resolve_routine(&call.name, call.is_function)?;
    let sig = Signature::of(&sym, cx.task)?;
    let i = active(&sig, call)?;
    Some(sig.params.get(i)?.type_name.clone())
}

/// Values for a place where a value of type `expected` is due. For a type
/// other than the basic ones (`num`, `dnum`, `bool`, `string`): only the
/// data of that type and the functions that return it (every `wobjdata`
/// in scope after `\WObj:=`), when there are any. The data of the type come
/// first, the most used in the file first.
pub(super) fn typed_values(
    cx: &Scope<'_>,
    expected: Option<&str>,
    details: bool,
) -> Vec<CompletionItem> {
    let uses = use_counts(cx.text);
    let mut want = Want {
        expected,
        strict: expected.is_some_and(|e| only_its_own(cx, e)),
        uses: Some(&uses),
    };
    if want.strict {
        let items = expression_items(cx, &want, details);
        if !items.is_empty() {
            return items;
        }
        want.strict = false;
    }
    expression_items(cx, &want, details)
}

/// Is a value of type `ty` only ever data or a function result of that
/// type (not a computed number, truth value or text)?
fn only_its_own(cx: &Scope<'_>, ty: &str) -> bool {
    let base = cx.task.types().base(&Ty::named(ty));
    match &base {
        Ty::Named(name) => !["num", "dnum", "bool", "string"]
            .iter()
            .any(|b| same(b, name)),
        _ => false,
    }
}

/// The list asked for by typing a blank or the `=` of `:=`: the values of
/// the argument or assignment whose value starts here (`MoveL `, `MoveL
/// p10, `, `\WObj:=`, `x :=`); nothing anywhere else (the blank between
/// any two words asks too).
pub(super) fn values_due(
    cx: &Scope<'_>,
    bf: &Before,
    prefix: &[u8],
    details: bool,
) -> Vec<CompletionItem> {
    let text = String::from_utf8_lossy(prefix);
    let trimmed = text.trim_end();
    let after_assign = trimmed.ends_with(":=");
    if let Some(call) = call_at(bf) {
        let starting = call.current.text.is_empty()
            || (after_assign && call.current.has_value && call.current.text.ends_with(":="));
        if !starting || call.current.optional && !call.current.has_value {
            return Vec::new();
        }
        // a routine with a parameter there (not `count ` before `:=`)
        return match expected_type(cx, &call) {
            Some(expected) => typed_values(cx, Some(&expected), details),
            None => Vec::new(),
        };
    }
    if after_assign {
        let stmt = &prefix[statement_start(prefix)..];
        if let Some(expected) = assignment_target(cx, stmt) {
            return typed_values(cx, Some(&expected), details);
        }
    }
    Vec::new()
}

/// After `\`: the optional parameters of the call not yet given (nor an
/// alternative of one given) that may come here: between the last
/// argument given and the next required parameter, in order. Those whose
/// place is past or after a required parameter still to give cannot.
pub(super) fn optional_args(cx: &Scope<'_>, bf: &Before) -> Vec<CompletionItem> {
    let Some(call) = call_at(bf) else {
        return Vec::new();
    };
    let Some(sym) = cx.resolve_routine(&call.name, call.is_function) else {
        return Vec::new();
    };
    let Some(sig) = Signature::of(&sym, cx.task) else {
        return Vec::new();
    };
    let given: Vec<&str> = call.done.iter().filter_map(|a| a.name.as_deref()).collect();
    let given_groups: HashSet<u32> = sig
        .params
        .iter()
        .filter(|p| given.iter().any(|g| same(g, &p.name)))
        .filter_map(|p| p.alt_group)
        .collect();
    let at = super::super::signature::next_position(&sig, &call);
    let next_required = sig
        .params
        .iter()
        .enumerate()
        .skip(at)
        .find(|(_, p)| !p.optional)
        .map_or(sig.params.len(), |(i, _)| i);
    let mut out = Vec::new();
    for (i, p) in sig.params.iter().enumerate().take(next_required).skip(at) {
        if !p.optional
            || given.iter().any(|g| same(g, &p.name))
            || p.alt_group.is_some_and(|g| given_groups.contains(&g))
        {
            continue;
        }
        let detail = if p.switch {
            format!("\\{} (switch)", p.name)
        } else {
            format!("\\{} {}", p.type_name, p.name)
        };
        out.push(CompletionItem {
            label: p.name.clone(),
            kind: CompletionKind::OptionalArgument,
            detail: Some(detail),
            insert_text: (!p.switch).then(|| format!("{}:=", p.name)),
            is_snippet: false,
            sort_text: Some(format!("0{i:03}")),
        });
    }
    out
}

/// How often each name (folded) is written in `text`, outside comments
/// and strings.
fn use_counts(text: &str) -> HashMap<String, usize> {
    let mut out: HashMap<String, usize> = HashMap::new();
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'!' => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
            }
            b'"' => {
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' && bytes[i] != b'\n' {
                    i += 1;
                }
                i += 1;
            }
            c if c.is_ascii_digit() => {
                while is_name_byte_at(bytes, i) {
                    i += 1;
                }
            }
            _ => match text.get(i..).map(name_len) {
                Some(n) if n > 0 => {
                    *out.entry(fold(&text[i..i + n])).or_default() += 1;
                    i += n;
                }
                _ => i += 1,
            },
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::use_counts;

    #[test]
    fn names_with_latin1_letters_are_counted_whole() {
        let uses = use_counts("MoveL pÖlç, v100;\n! pÖlç\nx := \"pÖlç\" + PÖLÇ + 2pÖlç;");
        assert_eq!(uses.get("pölç"), Some(&2));
        assert_eq!(uses.get("p"), None);
        assert_eq!(uses.get("movel"), Some(&1));
    }
}
