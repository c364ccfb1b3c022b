//! Completion by context: statement start, arguments (expected type first),
//! optional arguments after `\`, record components after `.`, data types
//! after VAR/PERS/CONST and in parameter lists; nothing in comments and
//! strings. The context comes from the text before the cursor, so
//! half-written code works.

use std::collections::HashSet;

use super::context::{before, call_at, partial, statement_start, words};
use super::usage::{function_rank, instruction_rank};
use super::{CompletionItem, CompletionKind};
use crate::items::{RoutineKind, Storage};
use crate::names::{fold, same};
use crate::sema::def::Def;
use crate::sema::scope::Scope;
use crate::task::{Item, Task};
use crate::ty::Ty;

mod args;
mod builtins;

use builtins::builtins;
pub use builtins::{completion_documentation, prepare_completions};

/// Snippets: label, body.
const STATEMENT_SNIPPETS: &[(&str, &str)] = &[
    ("IF", "IF ${1:condition} THEN\n\t$0\nENDIF"),
    ("IF ELSE", "IF ${1:condition} THEN\n\t$2\nELSE\n\t$0\nENDIF"),
    ("FOR", "FOR ${1:i} FROM ${2:1} TO ${3:10} DO\n\t$0\nENDFOR"),
    ("WHILE", "WHILE ${1:condition} DO\n\t$0\nENDWHILE"),
    (
        "TEST",
        "TEST ${1:value}\nCASE ${2:1}:\n\t$0\nDEFAULT:\n\t\nENDTEST",
    ),
];

const ROUTINE_SNIPPETS: &[(&str, &str)] = &[
    ("PROC", "PROC ${1:name}()\n\t$0\nENDPROC"),
    (
        "FUNC",
        "FUNC ${1:num} ${2:name}()\n\t$0\n\tRETURN ${3:0};\nENDFUNC",
    ),
    ("TRAP", "TRAP ${1:name}\n\t$0\nENDTRAP"),
    (
        "RECORD",
        "RECORD ${1:name}\n\t${2:num} ${3:component};\nENDRECORD",
    ),
];

const STATEMENT_KEYWORDS: &[&str] = &[
    "RETURN", "GOTO", "RAISE", "EXIT", "RETRY", "TRYNEXT", "CONNECT", "VAR", "PERS", "CONST",
    "ELSEIF", "ELSE", "ENDIF", "ENDFOR", "ENDWHILE", "ENDTEST", "CASE", "DEFAULT", "ERROR", "UNDO",
    "BACKWARD", "ENDPROC", "ENDFUNC", "ENDTRAP",
];

const MODULE_KEYWORDS: &[&str] = &[
    "VAR",
    "PERS",
    "CONST",
    "LOCAL",
    "TASK",
    "ALIAS",
    "ENDMODULE",
];

const EXPRESSION_KEYWORDS: &[&str] = &["TRUE", "FALSE", "NOT", "AND", "OR", "XOR", "DIV", "MOD"];

fn item(label: &str, kind: CompletionKind, detail: Option<String>, sort: &str) -> CompletionItem {
    CompletionItem {
        label: label.to_owned(),
        kind,
        detail,
        insert_text: None,
        is_snippet: false,
        sort_text: Some(format!("{sort}{}", fold(label))),
    }
}

/// A snippet line without its placeholders' markup: `FOR ${1:i} FROM`
/// gives `FOR i FROM`.
fn plain(line: &str) -> String {
    let mut out = String::new();
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '$' => {
                if chars.peek() == Some(&'{') {
                    chars.next();
                    while chars.next_if(|c| c.is_ascii_digit()).is_some() {}
                    chars.next_if_eq(&':');
                } else {
                    while chars.next_if(|c| c.is_ascii_digit()).is_some() {}
                }
            }
            '}' => {}
            c => out.push(c),
        }
    }
    out.trim_end().to_owned()
}

fn snippet(label: &str, body: &str) -> CompletionItem {
    CompletionItem {
        label: label.to_owned(),
        kind: CompletionKind::Snippet,
        detail: Some(plain(body.lines().next().unwrap_or_default())),
        insert_text: Some(body.to_owned()),
        is_snippet: true,
        sort_text: Some(format!("3{}", fold(label))),
    }
}

/// Completion candidates at `offset` for the context the text before it
/// shows. All candidates of the context are returned (the client filters);
/// `sort_text` orders the likely ones first.
pub fn completions(task: &Task, unit: usize, offset: usize) -> Vec<CompletionItem> {
    completions_for(task, unit, offset, true, None)
}

/// [`completions`]; without `details`, the routines', data's and built-ins'
/// items have no `detail` (their signatures and declarations, the most of
/// a statement start's list to build: clients that resolve an item's detail
/// when they show it do not need them in the list). `trigger` is the
/// character whose typing asked for the list, if one did: a blank or the
/// `=` of `:=` ask only where a value is due (an argument after a call's
/// name or a comma, a value after `:=`), and get nothing elsewhere.
pub fn completions_for(
    task: &Task,
    unit: usize,
    offset: usize,
    details: bool,
    trigger: Option<char>,
) -> Vec<CompletionItem> {
    let Some(u) = task.unit(unit) else {
        return Vec::new();
    };
    let bf = before(&u.text, offset);
    if bf.in_comment || bf.in_string {
        return Vec::new();
    }
    let offset = bf.start + bf.text.len();
    let Some(cx) = Scope::at(task, unit, offset) else {
        return Vec::new();
    };
    let b = &bf.text;
    let p = partial(b);
    let prefix = &b[..b.len() - p];
    if trigger.is_some_and(|c| c == ' ' || c == '=') {
        return args::values_due(&cx, &bf, prefix, details);
    }
    match prefix.last() {
        Some(b'.') => return components(&cx, &prefix[..prefix.len() - 1]),
        Some(b'\\') => return args::optional_args(&cx, &bf),
        _ => {}
    }
    let stmt = statement_start(prefix);
    let stmt_text = &prefix[stmt..];
    let w = words(stmt_text);
    let in_routine = cx.routine.is_some() || in_routine_text(prefix);

    // Declarations: a type after VAR/PERS/CONST, nothing where the name
    // goes, values of the declared type after `:=`.
    if let Some(i) = w
        .iter()
        .position(|w| w == "var" || w == "pers" || w == "const")
    {
        let in_header = w.iter().any(|w| w == "proc" || w == "func");
        if !in_header {
            if stmt_text.windows(2).any(|p| p == b":=") {
                let ty = w.get(i + 1).cloned();
                return args::typed_values(&cx, ty.as_deref(), details);
            }
            return if w.len() == i + 1 {
                types(&cx)
            } else {
                Vec::new()
            };
        }
    }
    match w.first().map(String::as_str) {
        Some("goto") if w.len() == 1 => return labels(&cx),
        Some("connect") if w.iter().any(|w| w == "with") => {
            let mut out = Vec::new();
            visible_routines(&cx, details, &mut |name, kind, detail| {
                if kind == CompletionKind::Trap {
                    out.push(item(name, kind, detail(), "0"));
                }
            });
            return out;
        }
        _ => {}
    }
    // Routine headers: types in the parameter list and after FUNC.
    if let Some(first) = w
        .iter()
        .position(|w| ["proc", "func", "trap"].contains(&w.as_str()))
    {
        let last = stmt_text
            .iter()
            .rev()
            .find(|c| !c.is_ascii_whitespace())
            .copied();
        let after_mode = w
            .last()
            .is_some_and(|l| ["var", "pers", "inout"].contains(&l.as_str()))
            && matches!(last, Some(c) if c.is_ascii_alphabetic());
        if matches!(last, Some(b'(' | b',' | b'\\' | b'|')) || after_mode {
            return types(&cx);
        }
        if w[first] == "func" && w.len() == first + 1 {
            return types(&cx);
        }
        return Vec::new();
    }
    if stmt_text.iter().all(u8::is_ascii_whitespace) {
        return if in_routine {
            statement_start_items(&cx, details)
        } else {
            module_items(&cx)
        };
    }
    if let Some(call) = call_at(&bf)
        && call.name_start < offset - p
    {
        if call.current.name.is_some() && !call.current.has_value && call.current.optional {
            return args::optional_args(&cx, &bf);
        }
        let expected = args::expected_type(&cx, &call);
        return args::typed_values(&cx, expected.as_deref(), details);
    }
    // After `:=`: the left side's type is expected.
    let expected = assignment_target(&cx, stmt_text);
    args::typed_values(&cx, expected.as_deref(), details)
}

/// The labels of the routine around the cursor.
fn labels(cx: &Scope<'_>) -> Vec<CompletionItem> {
    let Some(r) = &cx.routine else {
        return Vec::new();
    };
    let root = cx.unit.tree().root_node();
    let Some(node) = root.named_descendant_for_byte_range(r.decl.range.start, r.decl.range.end)
    else {
        return Vec::new();
    };
    crate::sema::labels::find(cx.text, node, None)
        .iter()
        .map(|(name, _, _)| item(name, CompletionKind::Label, None, "0"))
        .collect()
}

/// Without an item tree (broken code), is the text inside a routine?
fn in_routine_text(b: &[u8]) -> bool {
    for line in b.split(|c| *c == b'\n').rev() {
        let w = words(line);
        let first = match w.first().map(String::as_str) {
            Some("local") => w.get(1).map(String::as_str),
            other => other,
        };
        match first {
            Some("proc" | "func" | "trap") => return true,
            Some("endproc" | "endfunc" | "endtrap" | "module" | "endmodule") => return false,
            _ => {}
        }
    }
    false
}

/// The declared type of `x` in `x := ` (a plain name only).
fn assignment_target(cx: &Scope<'_>, stmt: &[u8]) -> Option<String> {
    let s = String::from_utf8_lossy(stmt);
    let (left, _) = s.split_once(":=")?;
    let name = left.trim();
    if !name.bytes().all(|c| c.is_ascii_alphanumeric() || c == b'_') || name.is_empty() {
        return None;
    }
    match cx.resolve_data(name)?.ty(cx.task, &cx.types) {
        Ty::Named(n) => Some(n),
        _ => None,
    }
}

fn statement_start_items(cx: &Scope<'_>, details: bool) -> Vec<CompletionItem> {
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    visible_routines(cx, details, &mut |name, kind, detail| {
        if kind == CompletionKind::Procedure && seen.insert(fold(name)) {
            out.push(item(name, kind, detail(), "1"));
        }
    });
    let builtins = builtins(cx.cat);
    for (r, (key, sig)) in cx.cat.instructions.iter().zip(&builtins.instructions) {
        if seen.insert(key.clone()) {
            out.push(item(
                &r.name,
                CompletionKind::Procedure,
                details.then(|| sig.clone()),
                &instruction_rank(key),
            ));
        }
    }
    for k in STATEMENT_KEYWORDS {
        out.push(item(k, CompletionKind::Keyword, None, "4"));
    }
    for (label, body) in STATEMENT_SNIPPETS {
        out.push(snippet(label, body));
    }
    // Assignments start with a name: the data in scope.
    data_items(cx, &Want::default(), details, &mut out);
    out
}

fn module_items(cx: &Scope<'_>) -> Vec<CompletionItem> {
    let _ = cx;
    let mut out = Vec::new();
    for k in MODULE_KEYWORDS {
        out.push(item(k, CompletionKind::Keyword, None, "1"));
    }
    for (label, body) in ROUTINE_SNIPPETS {
        out.push(snippet(label, body));
    }
    out
}

fn types(cx: &Scope<'_>) -> Vec<CompletionItem> {
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    let module = cx.module.map(|(i, _)| i);
    let mut user = |r: crate::task::ItemRef, local: bool| {
        if local && !(r.unit == cx.unit_idx && Some(r.module) == module) {
            return;
        }
        if let Some((name, _)) = cx.task.item_name(r)
            && matches!(r.item, Item::Record(_) | Item::Alias(_))
            && seen.insert(fold(name))
        {
            let detail = match r.item {
                Item::Record(_) => "RECORD",
                _ => "ALIAS",
            };
            out.push(item(
                name,
                CompletionKind::Type,
                Some(detail.to_owned()),
                "0",
            ));
        }
    };
    for refs in cx.task.globals.values() {
        refs.iter().for_each(|r| user(*r, false));
    }
    for refs in cx.task.locals.values() {
        refs.iter().for_each(|r| user(*r, true));
    }
    for (t, (key, sig)) in cx.cat.datatypes.iter().zip(&builtins(cx.cat).datatypes) {
        if seen.insert(key.clone()) {
            out.push(item(&t.name, CompletionKind::Type, Some(sig.clone()), "1"));
        }
    }
    out
}

/// Routines visible here: `f(name, kind, detail)`, where `detail()` gives
/// the routine's header (`None` without `details`).
fn visible_routines(
    cx: &Scope<'_>,
    details: bool,
    f: &mut impl FnMut(&str, CompletionKind, &dyn Fn() -> Option<String>),
) {
    let module = cx.module.map(|(i, _)| i);
    let task = cx.task;
    let mut visit = |r: &crate::task::ItemRef| {
        let (Some(d), Some(u)) = (task.routine(*r), task.unit(r.unit)) else {
            return;
        };
        let kind = match d.kind {
            RoutineKind::Proc => CompletionKind::Procedure,
            RoutineKind::Func => CompletionKind::Function,
            RoutineKind::Trap => CompletionKind::Trap,
        };
        f(&d.name, kind, &|| {
            details.then(|| super::hover::routine_header(&u.text, d))
        });
    };
    for refs in task.globals.values() {
        refs.iter().for_each(&mut visit);
    }
    for refs in task.locals.values() {
        refs.iter()
            .filter(|r| r.unit == cx.unit_idx && Some(r.module) == module)
            .for_each(&mut visit);
    }
}

/// What a list of values is for: the type expected (its data sort first,
/// the most used first), and whether only values of that type are offered.
#[derive(Default)]
pub(super) struct Want<'a> {
    pub expected: Option<&'a str>,
    pub strict: bool,
    /// Uses of each name (folded) where the list is asked for.
    pub uses: Option<&'a std::collections::HashMap<String, usize>>,
}

/// Data in scope; those of type `want.expected` sort first (the most used
/// first), and with `want.strict` only those are offered.
fn data_items(cx: &Scope<'_>, want: &Want<'_>, details: bool, out: &mut Vec<CompletionItem>) {
    let expected = want.expected;
    let types = cx.task.types();
    let expected_base = expected.map(|e| types.base(&Ty::named(e)));
    let matches = |ty: Option<&str>| -> bool {
        match (expected, &expected_base, ty) {
            (Some(e), Some(eb), Some(t)) => same(e, t) || *eb == types.base(&Ty::named(t)),
            _ => false,
        }
    };
    let mut seen = HashSet::new();
    let mut push = |name: &str,
                    kind: CompletionKind,
                    ty: Option<&str>,
                    detail: &dyn Fn() -> String,
                    rank: u8| {
        let fits = matches(ty);
        if want.strict && !fits || !seen.insert(fold(name)) {
            return;
        }
        let sort = if fits {
            let uses = want
                .uses
                .and_then(|u| u.get(&fold(name)))
                .copied()
                .unwrap_or(0);
            format!("0{:05}{rank}", 99_999usize.saturating_sub(uses))
        } else {
            format!("5{rank}")
        };
        out.push(item(name, kind, details.then(detail), &sort));
    };
    let storage_kind = |s: Storage| match s {
        Storage::Var => CompletionKind::Variable,
        Storage::Pers => CompletionKind::Persistent,
        Storage::Const => CompletionKind::Constant,
    };
    if let Some(r) = &cx.routine {
        for (v, _) in &r.for_vars {
            push(
                v,
                CompletionKind::Variable,
                Some("num"),
                &|| "num (FOR)".to_owned(),
                0,
            );
        }
        for p in r.params.values() {
            let ty = p.ty.as_ref().map(|t| t.name.as_str());
            push(
                &p.name,
                CompletionKind::Parameter,
                ty,
                &|| format!("{} {}", ty.unwrap_or("?"), p.name),
                0,
            );
        }
        for d in r.locals.values() {
            let ty = d.ty.as_ref().map(|t| t.name.as_str());
            push(
                &d.name,
                storage_kind(d.storage),
                ty,
                &|| format!("{} {} {}", d.storage.keyword(), ty.unwrap_or("?"), d.name),
                0,
            );
        }
    }
    let module = cx.module.map(|(i, _)| i);
    let mut refs: Vec<crate::task::ItemRef> = Vec::new();
    for rs in cx.task.locals.values() {
        refs.extend(
            rs.iter()
                .filter(|r| r.unit == cx.unit_idx && Some(r.module) == module),
        );
    }
    for rs in cx.task.globals.values() {
        refs.extend(rs.iter());
    }
    refs.sort_by_key(|r| (r.unit != cx.unit_idx, r.unit, r.module));
    for r in refs {
        if let Some(d) = cx.task.data(r) {
            let ty = d.ty.as_ref().map(|t| t.name.as_str());
            let rank = if r.unit == cx.unit_idx { 1 } else { 2 };
            push(
                &d.name,
                storage_kind(d.storage),
                ty,
                &|| format!("{} {} {}", d.storage.keyword(), ty.unwrap_or("?"), d.name),
                rank,
            );
        }
    }
    if let Some(signals) = &cx.task.signals {
        let mut sigs: Vec<_> = signals.iter().collect();
        sigs.sort();
        for (name, ty) in sigs {
            push(
                name,
                CompletionKind::Variable,
                Some(ty),
                &|| format!("{ty} {name}"),
                3,
            );
        }
    }
    for (d, (_, sig)) in cx.cat.data.iter().zip(&builtins(cx.cat).data) {
        let kind = match d.kind {
            crate::catalogue::DatumKind::Const => CompletionKind::Constant,
            crate::catalogue::DatumKind::Pers => CompletionKind::Persistent,
            crate::catalogue::DatumKind::Var => CompletionKind::Variable,
        };
        push(&d.name, kind, Some(&d.ty), &|| sig.clone(), 4);
    }
}

/// Data and functions for an expression (with `want.strict`, only those
/// of the type expected).
fn expression_items(cx: &Scope<'_>, want: &Want<'_>, details: bool) -> Vec<CompletionItem> {
    let expected = want.expected;
    let mut out = Vec::new();
    data_items(cx, want, details, &mut out);
    let types = cx.task.types();
    let expected_base = expected.map(|e| types.base(&Ty::named(e)));
    let returns_expected = |ret: Option<&str>| match (expected, &expected_base, ret) {
        (Some(e), Some(eb), Some(r)) => same(e, r) || *eb == types.base(&Ty::named(r)),
        _ => false,
    };
    let mut seen = HashSet::new();
    let mut user = Vec::new();
    visible_routines(cx, details, &mut |name, kind, detail| {
        if kind == CompletionKind::Function {
            user.push((name.to_owned(), detail()));
        }
    });
    for (name, detail) in user {
        let fits = returns_expected(lookup_return(cx, &name).as_deref());
        if want.strict && !fits || !seen.insert(fold(&name)) {
            continue;
        }
        let first = if fits { "1" } else { "6" };
        out.push(item(
            &name,
            CompletionKind::Function,
            detail,
            &format!("{first}1"),
        ));
    }
    for (r, (key, sig)) in cx.cat.functions.iter().zip(&builtins(cx.cat).functions) {
        let fits = returns_expected(r.returns.as_deref());
        if want.strict && !fits || !seen.insert(key.clone()) {
            continue;
        }
        let first = if fits { "1" } else { "6" };
        out.push(item(
            &r.name,
            CompletionKind::Function,
            details.then(|| sig.clone()),
            &format!("{first}2{}", function_rank(key)),
        ));
    }
    if !want.strict {
        for k in EXPRESSION_KEYWORDS {
            out.push(item(k, CompletionKind::Keyword, None, "7"));
        }
    }
    out
}

fn lookup_return(cx: &Scope<'_>, name: &str) -> Option<String> {
    match cx.resolve_routine(name, true)? {
        Def::BuiltinRoutine(r) => r.returns.clone(),
        def => def
            .routine_decl(cx.task)?
            .returns
            .as_ref()
            .map(|t| t.name.clone()),
    }
}

/// After `.`: the components of the object's type. The object is the
/// chain of names, components and indexes before the dot.
fn components(cx: &Scope<'_>, before_dot: &[u8]) -> Vec<CompletionItem> {
    // Walk back over `name`, `.name` and `{...}` segments.
    let mut i = before_dot.len();
    let mut depth = 0;
    while i > 0 {
        let c = before_dot[i - 1];
        if depth > 0 {
            match c {
                b'}' => depth += 1,
                b'{' => depth -= 1,
                _ => {}
            }
            i -= 1;
            continue;
        }
        match c {
            b'}' => depth += 1,
            b'.' | b'_' => {}
            c if c.is_ascii_alphanumeric() => {}
            _ => break,
        }
        i -= 1;
    }
    let chain = String::from_utf8_lossy(&before_dot[i..]).into_owned();
    let Some(ty) = chain_type(cx, &chain) else {
        return Vec::new();
    };
    if ty.dims() > 0 {
        return Vec::new();
    }
    let Some(comps) = cx.types.components(&ty) else {
        return Vec::new();
    };
    comps
        .into_iter()
        .enumerate()
        .map(|(i, (name, t))| CompletionItem {
            label: name.clone(),
            kind: CompletionKind::Component,
            detail: Some(format!("{t} {name}")),
            insert_text: None,
            is_snippet: false,
            sort_text: Some(format!("{i:03}")),
        })
        .collect()
}

/// The type of `a{i}.b.c`.
fn chain_type(cx: &Scope<'_>, chain: &str) -> Option<Ty> {
    // Split into segments, dropping index contents.
    let mut segs: Vec<(String, usize)> = Vec::new(); // name, index count after it
    let mut cur = String::new();
    let mut depth = 0;
    for c in chain.chars() {
        match c {
            '{' => {
                if depth == 0 {
                    segs.push((std::mem::take(&mut cur), 0));
                }
                depth += 1;
            }
            '}' => {
                depth -= 1;
                if depth == 0
                    && let Some(last) = segs.last_mut()
                {
                    last.1 += 1;
                }
            }
            '.' if depth == 0 && !cur.is_empty() => {
                segs.push((std::mem::take(&mut cur), 0));
            }
            '.' => {}
            c if depth == 0 => cur.push(c),
            _ => {}
        }
    }
    if !cur.is_empty() {
        segs.push((cur, 0));
    }
    let mut segs = segs.into_iter().filter(|(n, _)| !n.is_empty());
    let (first, idx) = segs.next()?;
    let mut ty = cx.resolve_data(&first)?.ty(cx.task, &cx.types);
    if idx > 0 {
        ty = ty.element().clone();
    }
    for (name, idx) in segs {
        ty = cx.types.component(&ty, &name)?;
        if idx > 0 {
            ty = ty.element().clone();
        }
    }
    Some(ty)
}
