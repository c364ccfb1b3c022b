//! Code actions: the fixes the diagnostics carry, and quick fixes computed
//! here from a diagnostic's code and range (declare an unknown variable,
//! `=` for `:=`, remove unused data, add a missing RETURN).

use std::ops::Range;

use tree_sitter::Node;

use super::CodeAction;
use super::signature::{active, call_sig};
use crate::check::Cx;
use crate::diagnostic::{Diagnostic, Edit};
use crate::syntax_util::fields;
use crate::task::{Task, Unit};
use crate::ty::Ty;

/// Quick fixes for the diagnostics (indexes into `diagnostics`) that
/// overlap `range`: the diagnostic's own `fix` when it has one, else an
/// edit computed here for W101 (declare the data), E003/E001 `=` (use
/// `:=`), W201 (remove the declaration) and E404 (add `RETURN`).
pub fn code_actions(
    task: &Task,
    unit: usize,
    range: Range<usize>,
    diagnostics: &[Diagnostic],
) -> Vec<CodeAction> {
    let Some(u) = task.units.get(unit) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (i, d) in diagnostics.iter().enumerate() {
        if d.range.end < range.start || d.range.start > range.end {
            continue;
        }
        if let Some(fix) = &d.fix {
            out.push(CodeAction {
                title: fix.title.clone(),
                edits: fix.edits.clone(),
                diagnostic: Some(i),
                preferred: fix.safe,
            });
            continue;
        }
        let action = match d.rule.code {
            "W101" if d.message.starts_with("no data named") => declare_variable(task, unit, d),
            "E003" => equals_fix(u, d),
            "E001" if u.text.get(d.range.clone()).map(str::trim) == Some("=") => equals_fix(u, d),
            "W201" => remove_declaration(u, d),
            "E404" => add_return(task, unit, d),
            _ => None,
        };
        if let Some(mut a) = action {
            a.diagnostic = Some(i);
            out.push(a);
        }
    }
    out
}

fn equals_fix(u: &Unit, d: &Diagnostic) -> Option<CodeAction> {
    let t = u.text.get(d.range.clone())?;
    let at = d.range.start + t.find('=')?;
    Some(CodeAction {
        title: "Replace `=` with `:=`".to_owned(),
        edits: vec![Edit {
            range: at..at + 1,
            replacement: ":=".to_owned(),
        }],
        diagnostic: None,
        preferred: true,
    })
}

/// The start of the line holding `offset`, and its indentation.
fn line_start(text: &str, offset: usize) -> (usize, &str) {
    let start = text
        .get(..offset)
        .and_then(|b| b.rfind('\n'))
        .map_or(0, |i| i + 1);
    let rest = text.get(start..).unwrap_or_default();
    let indent_len = rest.len() - rest.trim_start_matches([' ', '\t']).len();
    (start, rest.get(..indent_len).unwrap_or_default())
}

fn newline(text: &str) -> &'static str {
    if text.contains("\r\n") { "\r\n" } else { "\n" }
}

/// The routine node around `offset`.
fn routine_node(u: &Unit, offset: usize) -> Option<Node<'_>> {
    let mut at = u
        .tree()
        .root_node()
        .descendant_for_byte_range(offset, offset);
    while let Some(n) = at {
        if matches!(
            n.kind(),
            "procedure_declaration" | "function_declaration" | "trap_declaration"
        ) {
            return Some(n);
        }
        at = n.parent();
    }
    None
}

/// W101 on data: `VAR <type> name;` at the top of the routine.
fn declare_variable(task: &Task, unit: usize, d: &Diagnostic) -> Option<CodeAction> {
    let u = task.units.get(unit)?;
    let name = u.text.get(d.range.clone())?;
    let routine = routine_node(u, d.range.start)?;
    let ty = infer_type(task, unit, d.range.clone()).unwrap_or_else(|| "num".to_owned());
    let body = fields(routine, "body");
    let nl = newline(&u.text);
    let (at, indent) = match body.first() {
        Some(first) => {
            let (s, i) = line_start(&u.text, first.start_byte());
            (s, i.to_owned())
        }
        None => {
            // After the header line.
            let header_end = u
                .text
                .get(routine.start_byte()..)
                .and_then(|t| t.find('\n'))
                .map_or(routine.end_byte(), |i| routine.start_byte() + i + 1);
            let (_, i) = line_start(&u.text, routine.start_byte());
            (header_end, format!("{i}  "))
        }
    };
    Some(CodeAction {
        title: format!("Declare `VAR {ty} {name};` in this routine"),
        edits: vec![Edit {
            range: at..at,
            replacement: format!("{indent}VAR {ty} {name};{nl}"),
        }],
        diagnostic: None,
        preferred: true,
    })
}

/// The type a name at `range` must have: from an assignment's other side,
/// or the parameter it is passed to.
fn infer_type(task: &Task, unit: usize, range: Range<usize>) -> Option<String> {
    let u = task.units.get(unit)?;
    let node = u
        .tree()
        .root_node()
        .named_descendant_for_byte_range(range.start, range.end)?;
    let parent = node.parent()?;
    let field = super::resolve::field_in_parent(node);
    if parent.kind() == "assignment" {
        let other = match field {
            Some("left") => parent.child_by_field_name("right")?,
            _ => parent.child_by_field_name("left")?,
        };
        let mut cx = Cx::at(task, unit, range.start)?;
        let ty = cx.type_of_expr(other);
        return match ty {
            Ty::Named(n) => Some(n),
            _ => None,
        };
    }
    if parent.kind() == "argument" || parent.kind() == "for_statement" {
        if parent.kind() == "for_statement" {
            return Some("num".to_owned());
        }
        let (sig, call) = call_sig(task, unit, range.end)?;
        let p = sig.params.get(active(&sig, &call)?)?;
        if p.ty.eq_ignore_ascii_case(crate::catalogue::ANYTYPE) || p.ty.is_empty() {
            return None;
        }
        return Some(p.ty.clone());
    }
    None
}

/// W201: delete the declaration (its whole line when it stands alone).
fn remove_declaration(u: &Unit, d: &Diagnostic) -> Option<CodeAction> {
    let mut at = u
        .tree()
        .root_node()
        .descendant_for_byte_range(d.range.start, d.range.end);
    while let Some(n) = at {
        if n.kind() == "data_declaration" {
            break;
        }
        at = n.parent();
    }
    let decl = at?;
    let text = &u.text;
    let (line, _) = line_start(text, decl.start_byte());
    let before_alone = text.get(line..decl.start_byte())?.trim().is_empty();
    let line_end = text
        .get(decl.end_byte()..)
        .and_then(|t| t.find('\n'))
        .map_or(text.len(), |i| decl.end_byte() + i + 1);
    let after = text.get(decl.end_byte()..line_end)?.trim();
    let range = if before_alone && (after.is_empty() || after.starts_with('!')) {
        line..line_end
    } else {
        decl.byte_range()
    };
    let name = decl
        .child_by_field_name("name")
        .and_then(|n| text.get(n.byte_range()))
        .unwrap_or("data");
    Some(CodeAction {
        title: format!("Remove the unused `{name}`"),
        edits: vec![Edit {
            range,
            replacement: String::new(),
        }],
        diagnostic: None,
        preferred: false,
    })
}

/// E404: `RETURN <default>;` before ENDFUNC.
fn add_return(task: &Task, unit: usize, d: &Diagnostic) -> Option<CodeAction> {
    let u = task.units.get(unit)?;
    let func = routine_node(u, d.range.start)?;
    if func.kind() != "function_declaration" {
        return None;
    }
    let mut cursor = func.walk();
    let end = func.children(&mut cursor).find(|c| {
        c.kind() == "endfunc"
            || c.kind() == "error_handler"
            || c.kind() == "undo_handler"
            || c.kind() == "backward_handler"
    })?;
    let ty = func
        .child_by_field_name("type")
        .and_then(|t| u.text.get(t.byte_range()))
        .unwrap_or("num");
    let types = task.types();
    let value = default_value(&types, &Ty::named(ty), 0);
    let (at, end_indent) = line_start(&u.text, end.start_byte());
    let body = fields(func, "body");
    let indent = match body.last() {
        Some(last) => line_start(&u.text, last.start_byte()).1.to_owned(),
        None => format!("{end_indent}  "),
    };
    let nl = newline(&u.text);
    Some(CodeAction {
        title: format!("Add `RETURN {value};`"),
        edits: vec![Edit {
            range: at..at,
            replacement: format!("{indent}RETURN {value};{nl}"),
        }],
        diagnostic: None,
        preferred: true,
    })
}

/// A default value of a type: 0, FALSE, "", or an aggregate of defaults.
fn default_value(types: &crate::ty::Types<'_>, ty: &Ty, depth: usize) -> String {
    let base = types.base(ty);
    if base.is("bool") {
        return "FALSE".to_owned();
    }
    if base.is("string") {
        return "\"\"".to_owned();
    }
    if depth < 4
        && let Some(comps) = types.components(&base)
    {
        let parts: Vec<String> = comps
            .iter()
            .map(|(_, t)| default_value(types, t, depth + 1))
            .collect();
        return format!("[{}]", parts.join(", "));
    }
    "0".to_owned()
}
