//! Hover: what a name denotes (declaration, type, documentation), and the
//! decoded contents of robtarget literals.

use std::fmt::Write as _;

use tree_sitter::Node;

use super::HoverResult;
use super::resolve::{Def, name_at, resolve};
use crate::catalogue::{Availability, Catalogue, Origin, Version};
use crate::items::RoutineKind;
use crate::syntax::{field, kind};
use crate::task::{Item, Task};

/// Longest declaration text shown before it is shortened.
const MAX_DECL: usize = 160;

/// Markdown for the name, constant expression or robtarget literal at
/// `offset`, with the range it describes.
pub fn hover(task: &Task, unit: usize, offset: usize) -> Option<HoverResult> {
    let u = task.unit(unit)?;
    if let Some(node) = name_at(u.tree(), offset) {
        let def = resolve(task, unit, node);
        if let Some(def) = def {
            let mut markdown = describe(task, &def)?;
            let data = matches!(
                def,
                Def::Item(crate::task::ItemRef {
                    item: Item::Data(_),
                    ..
                }) | Def::Local { .. }
                    | Def::BuiltinDatum(_)
                    | Def::BuiltinComponent(..)
                    | Def::Component(..)
            );
            if data
                && !literal_initialiser(task, &def)
                && let Some(v) = super::value::value_at(task, unit, offset)
                    .filter(|v| {
                        v.range.start <= node.start_byte() && node.end_byte() <= v.range.end
                    })
                    .or_else(|| declared_value(task, unit, node.byte_range(), &def))
            {
                markdown.push_str("\n\n---\n\n");
                markdown.push_str(&value_markdown(&v));
            }
            if let Some(extra) = robtarget_of_def(task, &def) {
                markdown.push_str("\n\n---\n\n");
                markdown.push_str(&extra);
            }
            // The task's robot: the joint angles of a robtarget's value.
            if let Some(joints) = crate::robot::joints_of_def(task, &def) {
                markdown.push_str("\n\n");
                markdown.push_str(&joints);
            }
            return Some(HoverResult {
                range: node.byte_range(),
                markdown,
            });
        }
        return None;
    }
    // A robtarget literal under the cursor.
    let root = u.tree().root_node();
    let mut at = root.descendant_for_byte_range(offset, offset);
    let mut outermost = None;
    while let Some(n) = at {
        if n.kind() == kind::AGGREGATE {
            outermost = Some(n);
        }
        at = n.parent();
    }
    if let Some(agg) = outermost
        && let Some(markdown) = decode_robtarget(agg, &u.text)
    {
        return Some(HoverResult {
            range: agg.byte_range(),
            markdown,
        });
    }
    let v = super::value::value_at(task, unit, offset)?;
    Some(HoverResult {
        markdown: value_markdown(&v),
        range: v.range,
    })
}

fn code(s: &str) -> String {
    format!("```rapid\n{s}\n```")
}

/// The markdown for a declaration.
pub(crate) fn describe(task: &Task, def: &Def<'_>) -> Option<String> {
    let mut out = String::new();
    match def {
        Def::BuiltinRoutine(r) => {
            out.push_str(&code(&r.signature()));
            push_doc(&mut out, &r.summary, &r.doc);
            push_origin(&mut out, task.catalogue, &r.origin);
        }
        Def::BuiltinParam(r, i) => {
            let p = r.params.get(*i)?;
            let mode = p
                .mode
                .map(|m| format!("{} ", m.keyword()))
                .unwrap_or_default();
            let opt = if p.optional { "\\" } else { "" };
            out.push_str(&code(&format!("{opt}{mode}{} {}", p.ty, p.name)));
            let _ = write!(out, "\n\nparameter of `{}`", r.name);
            push_added(&mut out, p.since);
        }
        Def::BuiltinDatum(d) => {
            out.push_str(&code(&d.signature()));
            push_doc(&mut out, &d.summary, "");
            push_origin(&mut out, task.catalogue, &d.origin);
        }
        Def::BuiltinType(t) => {
            out.push_str(&code(&t.signature()));
            push_doc(&mut out, &t.summary, &t.doc);
            push_origin(&mut out, task.catalogue, &t.origin);
        }
        Def::BuiltinComponent(t, i) => {
            let c = t.components.get(*i)?;
            out.push_str(&code(&format!("{} {}", c.ty, c.name)));
            let _ = write!(out, "\n\ncomponent of `{}`", t.name);
            push_added(&mut out, c.since);
        }
        Def::Signal(name, ty) => {
            out.push_str(&code(&format!("{ty} {name}")));
            out.push_str("\n\nI/O signal from the configuration (EIO.cfg)");
        }
        Def::Module { unit, module } => {
            let u = task.unit(*unit)?;
            let m = u.items.modules.get(*module)?;
            let line = first_line_from(&u.text, m.name_range.start);
            out.push_str(&code(&format!("MODULE {line}")));
            push_comments(&mut out, &u.text, m.range.start);
        }
        Def::ForVar { .. } => {
            out.push_str(&code(&format!("num {}", def.name(task))));
            out.push_str("\n\n`FOR` loop variable");
        }
        Def::Label { name, .. } => {
            out.push_str(&code(&format!("{name}:")));
            out.push_str("\n\nlabel");
        }
        Def::Param {
            unit,
            decl,
            routine,
        } => {
            let _ = unit;
            out.push_str(&code(&param_text(decl)));
            let _ = write!(out, "\n\nparameter of `{}`", routine.name);
        }
        Def::Local {
            unit,
            decl,
            routine,
        } => {
            let u = task.unit(*unit)?;
            out.push_str(&code(&shorten(u.text.get(decl.range.clone())?)));
            let _ = write!(out, "\n\nroutine data of `{}`", routine.name);
            push_comments(&mut out, &u.text, decl.range.start);
        }
        Def::Component(r, i) => {
            let rec = task.record(*r)?;
            let (name, ty, _) = rec.components.get(*i)?;
            let ty = ty.as_ref().map_or("?", |t| t.name.as_str());
            out.push_str(&code(&format!("{ty} {name}")));
            let _ = write!(out, "\n\ncomponent of `{}`", rec.name);
        }
        Def::Item(r) => {
            let u = task.unit(r.unit)?;
            let m = task.module(*r)?;
            let (start, shown) = match r.item {
                Item::Data(i) => {
                    let d = m.data.get(i)?;
                    (d.range.start, shorten(u.text.get(d.range.clone())?))
                }
                Item::Routine(i) => {
                    let d = m.routines.get(i)?;
                    (d.range.start, routine_header(&u.text, d))
                }
                Item::Record(i) => {
                    let d = m.records.get(i)?;
                    let text = u.text.get(d.range.clone())?;
                    let lines: Vec<&str> = text.lines().take(12).collect();
                    (d.range.start, lines.join("\n"))
                }
                Item::Alias(i) => {
                    let d = m.aliases.get(i)?;
                    (d.range.start, shorten(u.text.get(d.range.clone())?))
                }
            };
            out.push_str(&code(&shown));
            let _ = write!(out, "\n\nin module `{}`", m.name);
            push_comments(&mut out, &u.text, start);
        }
    }
    Some(out)
}

/// Where a built-in comes from, for people: its RobotWare versions when it is
/// not in every version, the option package that brings it, and what the
/// task's controller (`[controller]` in `rapid.toml`, or a backup's
/// `BACKINFO`) lacks of it. Empty for a base built-in of every version.
pub(crate) fn origin_notes(cat: &Catalogue, origin: &Origin) -> Vec<String> {
    let mut notes = Vec::new();
    if origin.since > BASELINE {
        notes.push(format!("RobotWare {} and later", origin.since));
    }
    if let Some(until) = origin.until {
        notes.push(format!("removed in RobotWare {until}"));
    }
    let availability = cat.availability(origin);
    if let Some(id) = &origin.package {
        let name = cat.package(id).map_or(id.as_str(), |p| p.name.as_str());
        if matches!(availability, Availability::NeedsOption(_)) {
            notes.push(format!("option {name}, not enabled here"));
        } else {
            notes.push(format!("option {name}"));
        }
    }
    match availability {
        Availability::Newer { since, selected } => {
            notes.push(format!("not in RobotWare {selected}: added in {since}"));
        }
        Availability::Removed { until, selected } => {
            notes.push(format!("not in RobotWare {selected}: removed in {until}"));
        }
        Availability::Yes | Availability::NeedsOption(_) => {}
    }
    notes
}

/// The first version of the catalogue's entries whose first RobotWare is not
/// established (`since = "5.0"`): not worth saying.
const BASELINE: Version = Version::new(5, 0);

fn push_origin(out: &mut String, cat: &Catalogue, origin: &Origin) {
    let notes = origin_notes(cat, origin);
    if !notes.is_empty() {
        out.push_str("\n\n*");
        out.push_str(&notes.join("; "));
        out.push('*');
    }
}

/// A parameter or component that a later RobotWare added. (A view of an
/// older controller has no such parameter or component.)
fn push_added(out: &mut String, since: Option<Version>) {
    if let Some(since) = since {
        let _ = write!(out, "\n\n*added in RobotWare {since}*");
    }
}

fn push_doc(out: &mut String, summary: &str, doc: &str) {
    if !summary.is_empty() {
        out.push_str("\n\n");
        out.push_str(summary);
    }
    if !doc.is_empty() {
        out.push_str("\n\n");
        out.push_str(doc);
    }
}

/// Appends the doc comment of the declaration starting at `start`.
fn push_comments(out: &mut String, text: &str, start: usize) {
    let doc = doc_comment(text, start);
    if !doc.is_empty() {
        out.push_str("\n\n");
        out.push_str(&doc);
    }
}

/// The `!` comment lines directly above the declaration at `start`, and a
/// comment at the end of its first line.
pub(crate) fn doc_comment(text: &str, start: usize) -> String {
    let Some(before) = text.get(..start) else {
        return String::new();
    };
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let mut lines: Vec<&str> = Vec::new();
    let mut rest = text.get(..line_start).unwrap_or_default();
    loop {
        let trimmed_rest = rest.strip_suffix('\n').unwrap_or(rest);
        let trimmed_rest = trimmed_rest.strip_suffix('\r').unwrap_or(trimmed_rest);
        if trimmed_rest.len() == rest.len() {
            break;
        }
        let ls = trimmed_rest.rfind('\n').map_or(0, |i| i + 1);
        let line = trimmed_rest.get(ls..).unwrap_or_default().trim();
        let Some(comment) = line.strip_prefix('!') else {
            break;
        };
        lines.push(comment.trim());
        rest = trimmed_rest.get(..ls).unwrap_or_default();
        if ls == 0 {
            break;
        }
    }
    lines.reverse();
    // Separator lines (`!*****`) say nothing.
    lines.retain(|l| !l.is_empty() && l.chars().any(|c| c.is_alphanumeric()));
    // A trailing comment on the declaration's line.
    let line_end = text
        .get(start..)
        .and_then(|s| s.find('\n'))
        .map_or(text.len(), |i| start + i);
    if let Some(line) = text.get(start..line_end)
        && let Some(i) = trailing_comment(line)
    {
        let c = line.get(i + 1..).unwrap_or_default().trim();
        if !c.is_empty() {
            lines.push(c);
        }
    }
    lines.join("  \n")
}

/// Where a `!` comment starts in a line, outside strings.
fn trailing_comment(line: &str) -> Option<usize> {
    let mut in_string = false;
    for (i, c) in line.char_indices() {
        match c {
            '"' => in_string = !in_string,
            '!' if !in_string => return Some(i),
            _ => {}
        }
    }
    None
}

/// A declaration's text on one line, shortened if long.
pub(crate) fn shorten(decl: &str) -> String {
    let one: String = decl.split_whitespace().collect::<Vec<_>>().join(" ");
    if one.len() <= MAX_DECL {
        return one;
    }
    let mut cut = MAX_DECL;
    while !one.is_char_boundary(cut) {
        cut -= 1;
    }
    format!("{} ...", one.get(..cut).unwrap_or_default())
}

fn first_line_from(text: &str, start: usize) -> &str {
    let rest = text.get(start..).unwrap_or_default();
    rest.lines().next().unwrap_or_default().trim_end()
}

/// `PROC name(params)` as written, on one line.
pub(crate) fn routine_header(text: &str, d: &crate::items::RoutineDecl) -> String {
    let body = text.get(d.range.clone()).unwrap_or_default();
    let end = match d.kind {
        RoutineKind::Trap => body.find('\n').unwrap_or(body.len()),
        _ => body
            .find(')')
            .map_or_else(|| body.find('\n').unwrap_or(body.len()), |i| i + 1),
    };
    let header = body.get(..end).unwrap_or_default();
    let header = match header.find('!') {
        Some(i) if d.kind == RoutineKind::Trap => header.get(..i).unwrap_or(header),
        _ => header,
    };
    header.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn param_text(p: &crate::items::ParamDecl) -> String {
    let mode = if p.mode == crate::catalogue::Mode::In {
        String::new()
    } else {
        format!("{} ", p.mode.keyword())
    };
    let opt = if p.optional { "\\" } else { "" };
    let ty = p.ty.as_ref().map_or("?", |t| t.name.as_str());
    let dims = if p.dims > 0 {
        format!("{{{}}}", vec!["*"; usize::from(p.dims)].join(","))
    } else {
        String::new()
    };
    format!("{opt}{mode}{ty} {}{dims}", p.name)
}

/// For robtarget data with a literal initial value, the decoded value.
fn robtarget_of_def(task: &Task, def: &Def<'_>) -> Option<String> {
    let (unit, init) = match def {
        Def::Item(r) => (r.unit, task.data(*r)?.init.clone()?),
        Def::Local { unit, decl, .. } => (*unit, decl.init.clone()?),
        _ => return None,
    };
    let u = task.unit(unit)?;
    u.with_tree(|tree| {
        let node = tree
            .root_node()
            .named_descendant_for_byte_range(init.start, init.end)?;
        (node.kind() == kind::AGGREGATE).then_some(())?;
        decode_robtarget(node, &u.text)
    })
}

/// The numbers of an aggregate's elements (each a number, maybe negated).
fn numbers(node: Node<'_>, text: &str) -> Option<Vec<f64>> {
    let mut cursor = node.walk();
    node.children_by_field_name(field::ELEMENT, &mut cursor)
        .map(|e| {
            let t: String = text.get(e.byte_range())?.split_whitespace().collect();
            let t = t.replace("+", "");
            t.parse::<f64>().ok().or_else(|| {
                rapid_evaluator::parse_num_literal(t.trim_start_matches('-'))
                    .ok()
                    .map(|v| if t.starts_with('-') { -v } else { v })
            })
        })
        .collect()
}

/// `[[x,y,z],[q1..q4],[cf1,cf4,cf6,cfx],[eax_a..eax_f]]`, decoded.
pub(crate) fn decode_robtarget(node: Node<'_>, text: &str) -> Option<String> {
    let mut cursor = node.walk();
    let parts: Vec<Node<'_>> = node
        .children_by_field_name(field::ELEMENT, &mut cursor)
        .collect();
    if parts.len() != 4 || parts.iter().any(|p| p.kind() != kind::AGGREGATE) {
        return None;
    }
    let trans = numbers(parts[0], text)?;
    let rot = numbers(parts[1], text)?;
    let conf = numbers(parts[2], text)?;
    let ext = numbers(parts[3], text)?;
    if trans.len() != 3 || rot.len() != 4 || conf.len() != 4 || ext.len() != 6 {
        return None;
    }
    let [z, y, x] = rapid_evaluator::euler_zyx_deg([rot[0], rot[1], rot[2], rot[3]]);
    let mut out = String::from("**robtarget**\n\n");
    let _ = writeln!(
        out,
        "- position: x = {}, y = {}, z = {} mm",
        num(trans[0]),
        num(trans[1]),
        num(trans[2])
    );
    let _ = writeln!(
        out,
        "- orientation (Euler ZYX): rz = {}°, ry = {}°, rx = {}°",
        num(z),
        num(y),
        num(x)
    );
    let _ = writeln!(
        out,
        "- configuration: cf1 = {}, cf4 = {}, cf6 = {}, cfx = {}",
        num(conf[0]),
        num(conf[1]),
        num(conf[2]),
        num(conf[3])
    );
    let axes: Vec<String> = ["a", "b", "c", "d", "e", "f"]
        .iter()
        .zip(&ext)
        .map(|(n, v)| {
            if *v >= 8.9e9 {
                format!("{n} = not used")
            } else {
                format!("{n} = {}", num(*v))
            }
        })
        .collect();
    let _ = write!(out, "- external axes: {}", axes.join(", "));
    Some(out)
}

/// A number rounded for display.
fn num(v: f64) -> String {
    let r = (v * 1000.0).round() / 1000.0;
    let r = if r == 0.0 { 0.0 } else { r };
    format!("{r}")
}

/// `= value` of a constant expression, with Euler angles for orientations.
fn value_markdown(v: &super::value::ConstValue) -> String {
    let mut out = String::new();
    if let Some((code, message)) = &v.error {
        let _ = write!(out, "always fails: `{code}` ({message})");
        return out;
    }
    let _ = write!(out, "`= {}` ({})", shorten(&v.value), v.ty);
    if v.initial_value_only {
        out.push_str(" — initial value");
    }
    if let Some([z, y, x]) = v.euler_zyx {
        let _ = write!(
            out,
            "\n\nEuler ZYX: rz = {}°, ry = {}°, rx = {}°",
            num(z),
            num(y),
            num(x)
        );
    }
    out
}

/// On the name of a constant's declaration, the value of its initialiser
/// (on a use, [`super::value::value_at`] evaluates the name itself).
fn declared_value(
    task: &Task,
    unit: usize,
    name: std::ops::Range<usize>,
    def: &Def<'_>,
) -> Option<super::value::ConstValue> {
    let (at, decl) = match def {
        Def::Item(r) => (r.unit, task.data(*r)?),
        Def::Local { unit, decl, .. } => (*unit, decl),
        _ => return None,
    };
    if at != unit || decl.name_range != name || decl.storage != crate::items::Storage::Const {
        return None;
    }
    super::value::value_of_range(task, unit, decl.init.clone()?)
}

/// Is the data's initial value a literal (so its value is in the
/// declaration shown already)?
fn literal_initialiser(task: &Task, def: &Def<'_>) -> bool {
    let (unit, init) = match def {
        Def::Item(r) => match task.data(*r).and_then(|d| d.init.clone()) {
            Some(i) => (r.unit, i),
            None => return false,
        },
        Def::Local { unit, decl, .. } => match decl.init.clone() {
            Some(i) => (*unit, i),
            None => return false,
        },
        _ => return false,
    };
    task.unit(unit).is_some_and(|u| {
        u.with_tree(|tree| {
            tree.root_node()
                .named_descendant_for_byte_range(init.start, init.end)
                .is_some_and(super::inlay::is_literal)
        })
    })
}
