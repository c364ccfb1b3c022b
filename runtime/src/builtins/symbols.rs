//! Searching the task's data by name: `SetDataSearch` starts a search,
//! `GetNextSym` gives its matches one by one, `SetAllDataVal` writes every
//! match at once; `GetDataVal`/`SetDataVal \Block` then reach a match in
//! its module.
//!
//! What a search goes through: the data declared in the task's modules,
//! in module order then declaration order. A search at the task level
//! (the default, `\InTask`) sees the modules' global data, and their
//! `LOCAL` data too when `GetNextSym \Recursive` enters the modules; one
//! in a module (`\InMod`) sees that module's data. `\Object` is a regular
//! expression matched against the name, without regard to case (RAPID
//! names ignore case). The predefined data of the system modules are not
//! searched, and a routine's data (`\InRout`) stops the run as not
//! simulated.

use rapid_analyzer::items::Storage;
use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, Place, R, Root, fault, named_error};
use crate::program::{Home, Symbol};

/// A search session: its matches and how far `GetNextSym` has come.
#[derive(Clone, Debug, Default)]
pub(crate) struct Search {
    /// Each match, and whether it lies below the search's level (a
    /// module's `LOCAL` data in a task-level search).
    matches: Vec<(Symbol, bool)>,
    next: usize,
}

/// The name pattern of `\Object` (every name without it).
fn pattern(cx: &mut Cx<'_>, a: &Args) -> R<Option<regex_lite::Regex>> {
    let Some(text) = cx.opt_string(a, "Object")? else {
        return Ok(None);
    };
    match regex_lite::RegexBuilder::new(&text)
        .case_insensitive(true)
        .build()
    {
        Ok(re) => Ok(Some(re)),
        Err(e) => fault(named_error(
            &cx.m.prog,
            "ERR_ARGVALERR",
            format!(
                "{}: \\Object {text:?} is not a regular expression ({e})",
                a.name
            ),
        )),
    }
}

/// The module data of type `ty` whose names match `re`.
fn of_type(cx: &Cx<'_>, ty: &str, re: Option<&regex_lite::Regex>) -> Vec<Symbol> {
    cx.m.prog
        .module_symbols()
        .into_iter()
        .filter(|s| s.ty.eq_ignore_ascii_case(ty))
        .filter(|s| re.is_none_or(|re| re.is_match(&s.name)))
        .collect()
}

/// `SetDataSearch Type [\TypeMod] [\Object] [\PersSym] | [\VarSym] |
/// [\ConstSym] [\InTask] | [\InMod] [\InRout] [\GlobalSym] | [\LocalSym]`.
pub(crate) fn set_data_search(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    if a.given("InRout") {
        return fault(FaultKind::Unsupported(
            "SetDataSearch \\InRout (a routine's data)".to_owned(),
        ));
    }
    let ty = cx.string(a, "Type")?;
    let re = pattern(cx, a)?;
    let kinds: Vec<Storage> = [
        ("PersSym", Storage::Pers),
        ("VarSym", Storage::Var),
        ("ConstSym", Storage::Const),
    ]
    .into_iter()
    .filter(|(p, _)| a.given(p))
    .map(|(_, k)| k)
    .collect();
    let scope = match (a.given("GlobalSym"), a.given("LocalSym")) {
        (true, _) => Some(true),
        (_, true) => Some(false),
        _ => None,
    };
    let module = match cx.opt_string(a, "InMod")? {
        Some(name) => Some(cx.m.prog.module_named(&name)),
        None => None,
    };
    let matches = of_type(cx, &ty, re.as_ref())
        .into_iter()
        .filter(|s| kinds.is_empty() || kinds.contains(&s.storage))
        .filter(|s| scope.is_none_or(|g| s.global == g))
        .filter_map(|s| match module {
            // A module the task does not have: nothing matches.
            Some(m) => (m == Some(s.module)).then_some((s, false)),
            None => {
                let below = !s.global;
                Some((s, below))
            }
        })
        .collect();
    cx.m.search = Search { matches, next: 0 };
    Ok(Done::Next)
}

/// `GetNextSym(Object, Block [\Recursive])`: the next match's name in
/// `Object` and its module in `Block`, TRUE; FALSE when none is left.
pub(crate) fn get_next_sym(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let recursive = a.given("Recursive");
    let search = &mut cx.m.search;
    let found = loop {
        let Some((symbol, below)) = search.matches.get(search.next) else {
            break None;
        };
        search.next += 1;
        if recursive || !below {
            break Some(symbol.clone());
        }
    };
    let Some(symbol) = found else {
        return Ok(Value::Bool(false));
    };
    let object = cx.place_arg(a, "Object")?;
    cx.store(&object, Value::Str(symbol.name.clone()))?;
    let block = cx.place_arg(a, "Block")?;
    cx.store(&block, block_value(symbol.module))?;
    Ok(Value::Bool(true))
}

/// A `datapos` naming module `module`.
fn block_value(module: usize) -> Value {
    Value::Record {
        ty: "datapos".to_owned(),
        fields: vec![("module".to_owned(), Value::Num((module + 1) as f32))],
    }
}

/// The module a `datapos` names (`None`: no search gave it).
pub(crate) fn block_module(v: &Value) -> Option<usize> {
    let n = v.field("module").and_then(Value::as_f64)?;
    (n >= 1.0).then(|| n as usize - 1)
}

/// `SetAllDataVal Type [\TypeMod] [\Object] [\Hidden] Value`: every
/// variable and persistent of the type whose name matches gets `Value`
/// (constants keep theirs, and arrays, which one value does not fill).
pub(crate) fn set_all_data_val(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let ty = cx.string(a, "Type")?;
    let re = pattern(cx, a)?;
    let value = cx.req(a, "Value")?;
    for s in of_type(cx, &ty, re.as_ref()) {
        if s.storage == Storage::Const || s.array {
            continue;
        }
        let root = match s.home {
            Home::Global(g) => Root::Global(g),
            Home::Pers(k) => match cx.m.pers_map.get(k as usize) {
                Some(&i) => Root::Pers(i),
                None => continue,
            },
        };
        cx.store(&Place::root(root), value.clone())?;
    }
    Ok(Done::Next)
}
