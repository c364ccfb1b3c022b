//! Navigation: definition, type definition, references, highlights, rename.

use std::collections::BTreeMap;
use std::ops::Range;
use std::sync::Arc;

use super::resolve::{
    Def, DefKey, NamePath, for_each_name_spelt, name_at, resolve, resolve_at, type_def,
};
use super::{Location, shared};
use crate::diagnostic::Edit;
use crate::names::{fold, same};
use crate::sema::scope::Scope;
use crate::sema::signature::{Arg, Signature, Target, bind_args};
use crate::syntax::{field, kind};
use crate::task::{Item, Task, Unit};

fn location(task: &Task, def: &Def<'_>) -> Option<Location> {
    let (unit, range, full_range) = def.location(task)?;
    Some(Location {
        path: task.unit(unit)?.path.clone(),
        range,
        full_range,
    })
}

fn def_at<'t>(task: &'t Task, unit: usize, offset: usize) -> Option<Def<'t>> {
    let u = task.unit(unit)?;
    let node = name_at(u.tree(), offset)?;
    resolve(task, unit, node)
}

/// Where the name at `offset` is declared (also "go to declaration");
/// empty for built-ins, which have no source.
pub fn definition(task: &Task, unit: usize, offset: usize) -> Vec<Location> {
    def_at(task, unit, offset)
        .and_then(|d| location(task, &d))
        .into_iter()
        .collect()
}

/// Where the type of the name at `offset` is declared (user records and
/// aliases only).
pub fn type_definition(task: &Task, unit: usize, offset: usize) -> Vec<Location> {
    let Some(def) = def_at(task, unit, offset) else {
        return Vec::new();
    };
    let ty = match &def {
        Def::Item(r) => match r.item {
            Item::Data(_) => task
                .data(*r)
                .and_then(|d| d.ty.as_ref())
                .map(|t| t.name.clone()),
            Item::Routine(_) => task
                .routine(*r)
                .and_then(|d| d.returns.as_ref())
                .map(|t| t.name.clone()),
            Item::Alias(_) | Item::Record(_) => {
                return location(task, &def).into_iter().collect();
            }
        },
        Def::Param { decl, .. } => decl.ty.as_ref().map(|t| t.name.clone()),
        Def::Local { decl, .. } => decl.ty.as_ref().map(|t| t.name.clone()),
        Def::Component(r, i) => task
            .record(*r)
            .and_then(|rec| rec.components.get(*i))
            .and_then(|c| c.1.as_ref())
            .map(|t| t.name.clone()),
        Def::BuiltinComponent(t, i) => t.components.get(*i).map(|c| c.ty.clone()),
        Def::BuiltinDatum(d) => Some(d.ty.clone()),
        Def::BuiltinRoutine(r) => r.returns.clone(),
        _ => None,
    };
    let Some(ty) = ty else {
        return Vec::new();
    };
    let (def_unit, at) = def
        .location(task)
        .map_or((unit, offset), |(u, r, _)| (u, r.start));
    let Some(cx) = Scope::at(task, def_unit, at) else {
        return Vec::new();
    };
    type_def(&cx, &ty)
        .and_then(|d| location(task, &d))
        .into_iter()
        .collect()
}

/// Every use of the declaration in the task (or one unit): unit,
/// range, and whether it is a write.
pub(crate) fn uses(
    task: &Task,
    def: &Def<'_>,
    only_unit: Option<usize>,
) -> Vec<(usize, Range<usize>, bool)> {
    let key = def.key(task);
    let name = def.name(task);
    if name.is_empty() {
        return Vec::new();
    }
    // Routine-scope symbols are seen only inside their routine.
    let scope: Option<(usize, Range<usize>)> = match def {
        // Parameters are also named at call sites (`\Opt:=`, `Name:=`).
        Def::Param { .. } => None,
        Def::Local { unit, routine, .. } => Some((*unit, routine.range.clone())),
        Def::ForVar { unit, range, .. } | Def::Label { unit, range, .. } => {
            let u = task.unit(*unit);
            let routine = u.and_then(|u| {
                u.items
                    .modules
                    .iter()
                    .flat_map(|m| &m.routines)
                    .find(|r| r.range.start <= range.start && range.end <= r.range.end)
            });
            routine.map(|r| (*unit, r.range.clone()))
        }
        _ => None,
    };
    let mut out = Vec::new();
    for (ui, u) in task.live_units() {
        if only_unit.is_some_and(|o| o != ui) || scope.as_ref().is_some_and(|(su, _)| *su != ui) {
            continue;
        }
        if u.tree_loaded() {
            uses_in(task, ui, u, &key, &name, scope.as_ref(), &mut out);
        } else {
            // A file whose tree was released is read with a tree parsed for
            // this search only (it stays released).
            let loaded = u.loaded();
            let task = task.with_unit(ui, loaded.clone());
            uses_in(&task, ui, &loaded, &key, &name, scope.as_ref(), &mut out);
        }
    }
    out
}

/// The uses of the declaration `key` (named `name`) in unit `ui` of
/// `task` (in `scope`, a unit and range, if given), added to `out`.
fn uses_in(
    task: &Task,
    ui: usize,
    u: &Unit,
    key: &DefKey,
    name: &str,
    scope: Option<&(usize, Range<usize>)>,
    out: &mut Vec<(usize, Range<usize>, bool)>,
) {
    let root = u.tree().root_node();
    let node = match &scope {
        Some((_, r)) => root.named_descendant_for_byte_range(r.start, r.end),
        None => Some(root),
    };
    let Some(node) = node else { return };
    // The scope of each routine is made once; the FOR variables around
    // a use (which it does not hold) come from the use's path.
    let mut scopes = super::tokens::Scopes::new(task, ui);
    // A label resolves the same in its whole routine: once per routine.
    let mut label: Option<(usize, Option<DefKey>)> = None;
    let mut lists = ArgLists::default();
    for_each_name_spelt(node, &u.text, name, |path| {
        let Some(&[(parent, _), (n, field)]) = path.get(path.len().saturating_sub(2)..) else {
            return;
        };
        let Some(cx) = scopes.at(n.start_byte()) else {
            return;
        };
        let is_label = matches!(
            (parent.kind(), field),
            (kind::LABEL, Some(field::NAME)) | (kind::GOTO_STATEMENT, Some(field::LABEL))
        );
        let routine = cx.routine.as_ref().map(|r| r.decl.range.start);
        let d = match (&label, routine) {
            (Some((at, d)), Some(r)) if is_label && *at == r => d.clone(),
            _ => {
                let for_vars = for_vars_around(path, &u.text);
                let pushed = for_vars.len();
                if let Some(r) = cx.routine.as_mut() {
                    r.for_vars.extend(for_vars);
                }
                let d = resolve_at(cx, n, parent, field).map(|d| d.key(task));
                let write = d.as_ref() == Some(key)
                    && (is_write(path) || passed_by_reference(cx, path, &mut lists));
                if let Some(r) = cx.routine.as_mut() {
                    let keep = r.for_vars.len().saturating_sub(pushed);
                    r.for_vars.truncate(keep);
                }
                if d.as_ref() == Some(key) {
                    out.push((ui, n.byte_range(), write));
                }
                if is_label && let Some(r) = routine {
                    label = Some((r, d));
                }
                return;
            }
        };
        if d.as_ref() == Some(key) {
            out.push((ui, n.byte_range(), false));
        }
    });
}

/// The variables of the FOR loops around the end of `path`, outermost
/// first, as [`Scope::at`] finds them: folded name and range.
fn for_vars_around(path: &NamePath<'_>, text: &str) -> Vec<(String, Range<usize>)> {
    path.iter()
        .filter(|(n, _)| n.kind() == kind::FOR_STATEMENT)
        .filter_map(|(n, _)| n.child_by_field_name(field::VARIABLE))
        .filter_map(|v| Some((fold(text.get(v.byte_range())?), v.byte_range())))
        .collect()
}

/// Is the name at the end of `path` written here: declared, assigned, a
/// FOR variable?
fn is_write(path: &NamePath<'_>) -> bool {
    let Some((&(_, field), up)) = path.split_last() else {
        return false;
    };
    let Some(&(parent, _)) = up.last() else {
        return false;
    };
    if field == Some(field::NAME)
        && matches!(
            parent.kind(),
            kind::DATA_DECLARATION | kind::PARAMETER | kind::RECORD_COMPONENT
        )
    {
        return true;
    }
    if parent.kind() == kind::FOR_STATEMENT && field == Some(field::VARIABLE) {
        return true;
    }
    // The root object of an assignment's left side.
    for i in (1..path.len()).rev() {
        let (Some(&(_, f)), Some(&(p, _))) = (path.get(i), path.get(i - 1)) else {
            return false;
        };
        match (p.kind(), f) {
            (kind::ASSIGNMENT, Some(field::LEFT)) => return true,
            (kind::COMPONENT_ACCESS | kind::INDEX_EXPRESSION, Some(field::OBJECT)) => {}
            _ => return false,
        }
    }
    false
}

/// The arguments of the last argument list seen: their node ids and the
/// names given (`None` for a positional one).
#[derive(Default)]
struct ArgLists {
    list: Option<usize>,
    ids: Vec<usize>,
    names: Vec<Option<String>>,
}

impl ArgLists {
    fn of(&mut self, list: tree_sitter::Node<'_>, text: &str) -> &ArgLists {
        if self.list != Some(list.id()) {
            self.list = Some(list.id());
            self.ids.clear();
            self.names.clear();
            for a in crate::syntax_util::fields(list, field::ARGUMENT) {
                self.ids.push(a.id());
                self.names.push(
                    a.child_by_field_name(field::NAME)
                        .and_then(|n| text.get(n.byte_range()))
                        .map(str::to_owned),
                );
            }
        }
        self
    }

    /// The arguments as the binder takes them.
    fn args(&self) -> Vec<Arg<'_>> {
        self.names
            .iter()
            .map(|n| n.as_deref().map_or(Arg::Positional, Arg::Named))
            .collect()
    }
}

/// Is the name at the end of `path` (or the data it starts) an argument of
/// a VAR, PERS or INOUT parameter, which the routine may change?
fn passed_by_reference(cx: &Scope<'_>, path: &NamePath<'_>, lists: &mut ArgLists) -> bool {
    let mut i = path.len().saturating_sub(1);
    let arg = loop {
        let (Some(&(_, f)), Some(&(p, _))) =
            (path.get(i), i.checked_sub(1).and_then(|j| path.get(j)))
        else {
            return false;
        };
        match (p.kind(), f) {
            (kind::ARGUMENT, Some(field::VALUE)) => break i - 1,
            (kind::COMPONENT_ACCESS | kind::INDEX_EXPRESSION, Some(field::OBJECT)) => i -= 1,
            _ => return false,
        }
    };
    let (Some(&(arg, _)), Some(&(list, _)), Some(&(call, _))) = (
        path.get(arg),
        arg.checked_sub(1).and_then(|j| path.get(j)),
        arg.checked_sub(2).and_then(|j| path.get(j)),
    ) else {
        return false;
    };
    if !matches!(call.kind(), kind::PROCEDURE_CALL | kind::FUNCTION_CALL) {
        return false;
    }
    let Some(sym) = super::resolve::call_routine(cx, call) else {
        return false;
    };
    let Some(sig) = Signature::of(&sym, cx.task) else {
        return false;
    };
    let lists = lists.of(list, cx.text);
    let Some(k) = lists.ids.iter().position(|&id| id == arg.id()) else {
        return false;
    };
    let param = match bind_args(&sig, &lists.args()).args.get(k).map(|a| a.target) {
        Some(Target::Param(i)) => sig.params.get(i),
        _ => None,
    };
    param.is_some_and(|p| p.mode != crate::catalogue::Mode::In)
}

/// Every use of the declaration at `offset` in the task's modules
/// (names compare case-insensitively), and, for a persistent shared by the
/// tasks of a controller, in each task of `peers` that shares it (see
/// [`shared_files`]).
pub fn references(
    task: &Task,
    unit: usize,
    offset: usize,
    include_declaration: bool,
    peers: &[Arc<Task>],
) -> Vec<Location> {
    let Some(def) = def_at(task, unit, offset) else {
        return Vec::new();
    };
    let mut out = references_of(task, &def, include_declaration);
    for (peer, r) in shared::linked(task, &def, peers) {
        out.extend(references_of(peer, &Def::Item(r), include_declaration));
    }
    out
}

/// The files of the other tasks of the controller that declare the
/// persistent at `offset`, when it is a system-global `PERS` (one datum
/// for every task of the controller): the caller hands their tasks to
/// [`references`] and [`rename`] as `peers`. Empty for anything else.
pub fn shared_files(task: &Task, unit: usize, offset: usize) -> Vec<String> {
    def_at(task, unit, offset)
        .map(|def| shared::files(task, &def))
        .unwrap_or_default()
}

fn references_of(task: &Task, def: &Def<'_>, include_declaration: bool) -> Vec<Location> {
    let decl = def.location(task).map(|(u, r, _)| (u, r.start));
    let mut out: Vec<Location> = uses(task, def, None)
        .into_iter()
        .filter(|(u, r, _)| include_declaration || decl != Some((*u, r.start)))
        .filter_map(|(u, range, _)| {
            Some(Location {
                path: task.unit(u)?.path.clone(),
                full_range: range.clone(),
                range,
            })
        })
        .collect();
    if include_declaration
        && let Some(loc) = location(task, def)
        && !out
            .iter()
            .any(|l| l.path == loc.path && l.range == loc.range)
    {
        out.insert(0, loc);
    }
    out
}

/// The uses of the declaration at `offset` in this file: (range, is a
/// write: declared, assigned, a FOR variable, or passed to a VAR, PERS or
/// INOUT parameter).
pub fn document_highlights(task: &Task, unit: usize, offset: usize) -> Vec<(Range<usize>, bool)> {
    let Some(def) = def_at(task, unit, offset) else {
        return Vec::new();
    };
    uses(task, &def, Some(unit))
        .into_iter()
        .map(|(_, r, w)| (r, w))
        .collect()
}

/// Words RAPID reserves, which can never be names.
pub(crate) const RESERVED: &[&str] = &[
    "ALIAS",
    "AND",
    "BACKWARD",
    "CASE",
    "CONNECT",
    "CONST",
    "DEFAULT",
    "DIV",
    "DO",
    "ELSE",
    "ELSEIF",
    "ENDFOR",
    "ENDFUNC",
    "ENDIF",
    "ENDMODULE",
    "ENDPROC",
    "ENDRECORD",
    "ENDTEST",
    "ENDTRAP",
    "ENDWHILE",
    "ERROR",
    "EXIT",
    "FALSE",
    "FOR",
    "FROM",
    "FUNC",
    "GOTO",
    "IF",
    "INOUT",
    "LOCAL",
    "MOD",
    "MODULE",
    "NOSTEPIN",
    "NOT",
    "NOVIEW",
    "OR",
    "PERS",
    "PROC",
    "RAISE",
    "READONLY",
    "RECORD",
    "RETRY",
    "RETURN",
    "STEP",
    "SYSMODULE",
    "TEST",
    "THEN",
    "TO",
    "TRAP",
    "TRUE",
    "TRYNEXT",
    "UNDO",
    "VAR",
    "VIEWONLY",
    "WHILE",
    "WITH",
    "XOR",
];

pub(crate) fn is_reserved(name: &str) -> bool {
    RESERVED.iter().any(|r| same(r, name))
}

/// The range of the name at `offset` if it can be renamed; a message
/// otherwise (reserved words, built-ins, signals, nothing declared).
pub fn prepare_rename(task: &Task, unit: usize, offset: usize) -> Result<Range<usize>, String> {
    let u = task.unit(unit).ok_or("no such file")?;
    let Some(node) = name_at(u.tree(), offset) else {
        return Err("there is no name here to rename".to_owned());
    };
    let text = u.text.get(node.byte_range()).unwrap_or_default();
    if is_reserved(text) {
        return Err(format!("`{text}` is a reserved word"));
    }
    let Some(def) = resolve(task, unit, node) else {
        return Err(format!("`{text}` is not declared in this task"));
    };
    if def.is_builtin() || matches!(def, Def::Signal(..)) {
        return Err(format!(
            "`{text}` is built in (or an I/O signal) and cannot be renamed"
        ));
    }
    Ok(node.byte_range())
}

/// Why `name` is not a valid RAPID identifier, if it is not.
pub(crate) fn invalid_identifier(name: &str) -> Option<String> {
    if name.is_empty() {
        return Some("the new name is empty".to_owned());
    }
    if name.len() > 32 {
        return Some(format!(
            "`{name}` is {} characters long; RAPID names have at most 32",
            name.len()
        ));
    }
    let mut chars = name.chars();
    let first = chars.next().unwrap_or(' ');
    if !first.is_ascii_alphabetic() {
        return Some(format!("`{name}` must start with a letter"));
    }
    if !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Some(format!(
            "`{name}` may only hold letters, digits and underscores"
        ));
    }
    if is_reserved(name) {
        return Some(format!("`{name}` is a reserved word"));
    }
    None
}

/// Edits per file path renaming the declaration at `offset` and all its
/// uses (for a persistent shared by the tasks of a controller, in each
/// task of `peers` that shares it too); refused for invalid identifiers,
/// reserved words, built-in names, names already declared where the
/// symbol is seen, and a shared persistent that a task declares with
/// another type.
pub fn rename(
    task: &Task,
    unit: usize,
    offset: usize,
    new_name: &str,
    peers: &[Arc<Task>],
) -> Result<Vec<(String, Vec<Edit>)>, String> {
    prepare_rename(task, unit, offset)?;
    if let Some(why) = invalid_identifier(new_name) {
        return Err(why);
    }
    let def = def_at(task, unit, offset).ok_or("there is no name here to rename")?;
    if let Some(why) = shared::rename_refusal(task, &def) {
        return Err(why);
    }
    let mut by_path = rename_in(task, &def, new_name)?;
    for (peer, r) in shared::linked(task, &def, peers) {
        for (path, edits) in rename_in(peer, &Def::Item(r), new_name)? {
            let list = by_path.entry(path).or_default();
            for e in edits {
                if !list.iter().any(|x| x.range == e.range) {
                    list.push(e);
                }
            }
        }
    }
    Ok(by_path
        .into_iter()
        .map(|(path, mut edits)| {
            edits.sort_by_key(|e| e.range.start);
            (path, edits)
        })
        .collect())
}

/// The edits, by file path, that rename `def` and its uses in `task`; an
/// error when `new_name` is a built-in's or already denotes something
/// where the symbol is seen.
fn rename_in(
    task: &Task,
    def: &Def<'_>,
    new_name: &str,
) -> Result<BTreeMap<String, Vec<Edit>>, String> {
    let old = def.name(task);
    let cat = task.catalogue;
    if !same(&old, new_name)
        && (cat.routine(new_name).is_some()
            || cat.datatype(new_name).is_some()
            || cat.datum(new_name).is_some())
    {
        return Err(format!("`{new_name}` is the name of a built-in"));
    }
    let uses = uses(task, def, None);
    // A clash: somewhere the symbol is used or declared, the new name
    // already denotes something else.
    if !same(&old, new_name) {
        let mut checked = std::collections::HashSet::new();
        for (u, range, _) in &uses {
            // Each scope once (entering one is not free: thousands of uses
            // in one routine entered it thousands of times).
            let within = |r: &Range<usize>| r.start <= range.start && range.start <= r.end;
            let module = task.unit(*u).and_then(|unit| {
                unit.items
                    .modules
                    .iter()
                    .enumerate()
                    .find(|(_, m)| within(&m.range))
            });
            let routine = module.and_then(|(_, m)| m.routines.iter().find(|r| within(&r.range)));
            let scope = (*u, module.map(|(i, _)| i), routine.map(|r| r.range.start));
            if !checked.insert(scope) {
                continue;
            }
            let Some(cx) = Scope::at(task, *u, range.start) else {
                continue;
            };
            if clashes(&cx, new_name) {
                return Err(format!(
                    "`{new_name}` is already declared where `{old}` is used"
                ));
            }
        }
        if let Some((u, r, _)) = def.location(task)
            && let Some(cx) = Scope::at(task, u, r.start)
            && clashes(&cx, new_name)
        {
            return Err(format!("`{new_name}` is already declared in this scope"));
        }
    }
    let mut by_unit: BTreeMap<usize, Vec<Edit>> = BTreeMap::new();
    for (u, range, _) in uses {
        by_unit.entry(u).or_default().push(Edit {
            range,
            replacement: new_name.to_owned(),
        });
    }
    if let Some((u, r, _)) = def.location(task) {
        let edits = by_unit.entry(u).or_default();
        if !edits.iter().any(|e| e.range == r) {
            edits.push(Edit {
                range: r,
                replacement: new_name.to_owned(),
            });
        }
    }
    Ok(by_unit
        .into_iter()
        .filter_map(|(u, mut edits)| {
            edits.sort_by_key(|e| e.range.start);
            Some((task.unit(u)?.path.clone(), edits))
        })
        .collect())
}

/// Does `name` already denote something in this context (routine data,
/// parameters, the module's or the task's declarations)?
fn clashes(cx: &Scope<'_>, name: &str) -> bool {
    let key = fold(name);
    if let Some(r) = &cx.routine
        && (r.locals.contains_key(&key)
            || r.params.contains_key(&key)
            || r.for_vars.iter().any(|(v, _)| *v == key))
    {
        return true;
    }
    if !cx.lookup_items(name).is_empty() {
        return true;
    }
    // Another module's global that this module's new declaration would clash with.
    cx.task.globals.contains_key(&key)
        || cx.module.is_some_and(|(_, m)| {
            m.data.iter().any(|d| same(&d.name, name))
                || m.routines.iter().any(|d| same(&d.name, name))
                || m.records.iter().any(|d| same(&d.name, name))
                || m.aliases.iter().any(|d| same(&d.name, name))
        })
}
