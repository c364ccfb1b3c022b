//! Program modules loaded while the program runs: `Load`, `StartLoad` and
//! `WaitLoad`, `CancelLoad`, `UnLoad`, `EraseModule`, `ModExist`.
//!
//! A module is read from the controller's files (the sandbox: a backup's
//! `HOME` is there) and laid out after the program's own
//! ([`crate::program::Program::with_module`]): nothing running moves, and
//! its routines are reached by late binding (`%"part" + n%`), as on the
//! controller, whose programs name a loaded module's routines no other
//! way. Unloading gives the task back the program it had before the load;
//! the modules loaded after it are laid out again, keeping their data's
//! values (the usual load, run, unload of a part program unloads the last
//! one). Unloading a module while a routine of one loaded after it runs,
//! or erasing one of the program's own modules, stops the run as not
//! simulated. `\Dynamic` and `\CheckRef` are
//! taken as the controller takes them: the program is never reset here,
//! and only with `\CheckRef` does a name declared nowhere fail the load.

use std::sync::Arc;

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, Place, R, Root, fault, named_error};
use crate::program::Origin;
use crate::program::{LoadFailure, Program};
use crate::world::FileError;
use rapid_analyzer::items::Storage;

/// A module file `Load` loaded, and the program the task had before.
#[derive(Clone)]
pub(crate) struct LoadedModule {
    /// The path it was loaded from, as the program gave it.
    pub path: String,
    /// Its modules' names.
    pub modules: Vec<String>,
    /// The index of its first module in the program.
    first: usize,
    before: Arc<Program>,
    /// Its text, to lay it out again when a module loaded before it is
    /// unloaded.
    text: Arc<str>,
    /// When it was loaded (simulated seconds).
    at: f64,
}

/// The loads `StartLoad` started and `WaitLoad` has not finished: the
/// session's number and the path.
#[derive(Clone, Debug, Default)]
pub(crate) struct Sessions {
    started: Vec<(u32, String)>,
    next: u32,
}

/// The path parameter `path` gives, with the file parameter `file` after
/// it (`"HOME:"` and `"a.mod"` are `HOME:a.mod`, `"HOME:/parts"` and
/// `"a.mod"` are `HOME:/parts/a.mod`); `None` without `path`.
pub(crate) fn full_path(cx: &mut Cx<'_>, a: &Args, path: &str, file: &str) -> R<Option<String>> {
    let Some(mut path) = cx.opt_string(a, path)? else {
        return Ok(None);
    };
    if let Some(f) = cx.opt_string(a, file)? {
        if !path.ends_with(['/', ':']) {
            path.push('/');
        }
        path.push_str(&f);
    }
    Ok(Some(path))
}

/// The module loaded from `path` (the path as the program wrote it, any
/// case), if one was.
pub(crate) fn loaded_from(cx: &Cx<'_>, path: &str) -> Option<usize> {
    cx.m.loaded
        .iter()
        .rposition(|l| l.path.eq_ignore_ascii_case(path))
}

/// The path a loaded module was loaded from (for `Save` without
/// `\FilePath`).
pub(crate) fn path_of_module(cx: &Cx<'_>, module: &str) -> Option<String> {
    load_of(cx, module).map(|l| l.path.clone())
}

/// The last `Load` that loaded the module named `module` (any case).
fn load_of<'c>(cx: &'c Cx<'_>, module: &str) -> Option<&'c LoadedModule> {
    cx.m.loaded
        .iter()
        .rev()
        .find(|l| l.modules.iter().any(|m| m.eq_ignore_ascii_case(module)))
}

/// Loads the module file at `path` into the task.
fn load(cx: &mut Cx<'_>, name: &str, path: &str, check_refs: bool) -> R<()> {
    let bytes = match cx.sh.files.read(path) {
        Ok(b) => b,
        Err(FileError::Unsupported(why)) => {
            return fault(FaultKind::Unsupported(format!("{name} ({why})")));
        }
        Err(FileError::NotFound(m)) => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_FILNOTFND",
                format!("{name}: {m}"),
            ));
        }
        Err(FileError::Denied(m) | FileError::Other(m)) => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_FILEACC",
                format!("{name}: {m}"),
            ));
        }
    };
    let text = match rapid_analyzer::text::decode(&bytes) {
        rapid_analyzer::text::Decoded::Text { text, .. } => text,
        _ => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_SYNTAX",
                format!("{name}: {path} is not a RAPID module (binary or encrypted)"),
            ));
        }
    };
    let before = cx.m.prog.clone();
    let program = match before.with_module(path, &text, check_refs) {
        Ok(p) => p,
        Err(LoadFailure::Syntax(m)) => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_SYNTAX",
                format!("{name}: {m}"),
            ));
        }
        Err(LoadFailure::Loaded(module)) => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_LOADED",
                format!("{name}: the task has a module {module} already"),
            ));
        }
        Err(LoadFailure::Link(m)) => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_LINKREF",
                format!("{name}: {m}"),
            ));
        }
    };
    let first = before.module_count();
    let modules = program.module_names_from(first);
    cx.trace(&format!("{name}: {} from {path}", modules.join(", ")));
    cx.m.adopt(cx.sh, Arc::new(program));
    cx.m.loaded.push(LoadedModule {
        path: path.to_owned(),
        modules,
        first,
        before,
        text: text.into(),
        at: cx.now(),
    });
    Ok(())
}

/// Unloads the module loaded from `path` (entry `i` of the loads): the
/// task gets back the program it had before that load, then the modules
/// loaded after it again, their data keeping their values.
fn unload(cx: &mut Cx<'_>, name: &str, i: usize) -> R<()> {
    let Some(entry) = cx.m.loaded.get(i).cloned() else {
        return Ok(());
    };
    let later: Vec<LoadedModule> = cx.m.loaded[i + 1..].to_vec();
    let own_end = later.first().map_or(usize::MAX, |l| l.first);
    let running = |from: usize, to: usize| {
        cx.m.frames
            .iter()
            .any(|f| (from..to).contains(&f.code.module))
    };
    if running(entry.first, own_end) {
        return fault(named_error(
            &cx.m.prog,
            "ERR_UNLOAD",
            format!(
                "{name}: a routine of {} is running",
                entry.modules.join(", ")
            ),
        ));
    }
    if running(own_end, usize::MAX) {
        return fault(FaultKind::Unsupported(format!(
            "{name} of a module loaded before one whose routine is running"
        )));
    }
    let kept = later_data(cx, own_end);
    cx.trace(&format!("{name}: {}", entry.modules.join(", ")));
    cx.m.loaded.truncate(i);
    cx.m.adopt(cx.sh, entry.before);
    for l in later {
        let before = cx.m.prog.clone();
        let Ok(program) = before.with_module(&l.path, &l.text, false) else {
            return fault(FaultKind::Unsupported(format!(
                "{name}: {} could not be laid out again",
                l.modules.join(", ")
            )));
        };
        let first = before.module_count();
        cx.m.adopt(cx.sh, Arc::new(program));
        cx.m.loaded.push(LoadedModule { first, before, ..l });
    }
    // The later modules now start where the unloaded one did.
    restore_data(cx, entry.first, kept)
}

/// The data the modules from index `from` on declare, constants left
/// out: each one's module and name (folded), and its place.
fn data_of_modules(cx: &Cx<'_>, from: usize) -> Vec<((String, String), Place)> {
    let prog = &cx.m.prog;
    let key = |m: usize, name: &str| {
        let module = prog.modules.get(m)?.name.to_ascii_lowercase();
        Some((module, name.to_ascii_lowercase()))
    };
    let globals = prog.globals.iter().enumerate().filter_map(|(g, global)| {
        let Origin::Module { module: m, .. } = global.origin else {
            return None;
        };
        (m >= from && global.storage != Storage::Const)
            .then(|| Some((key(m, &global.name)?, Place::root(Root::Global(g as u32)))))?
    });
    let pers = prog.pers.iter().enumerate().filter_map(|(k, p)| {
        let &i = cx.m.pers_map.get(k)?;
        (p.module >= from).then(|| Some((key(p.module, &p.name)?, Place::root(Root::Pers(i)))))?
    });
    globals.chain(pers).collect()
}

/// The values of the data the modules from index `from` on declare, by
/// module and name.
fn later_data(cx: &mut Cx<'_>, from: usize) -> Vec<((String, String), Value)> {
    data_of_modules(cx, from)
        .into_iter()
        .filter_map(|(key, place)| Some((key, cx.m.load(cx.sh, &place).ok()?)))
        .collect()
}

/// Gives the data of the modules from index `from` on the values
/// [`later_data`] kept.
fn restore_data(cx: &mut Cx<'_>, from: usize, kept: Vec<((String, String), Value)>) -> R<()> {
    for (key, place) in data_of_modules(cx, from) {
        if let Some((_, v)) = kept.iter().find(|(k, _)| *k == key) {
            cx.store(&place, v.clone())?;
        }
    }
    Ok(())
}

/// `Load [\Dynamic] FilePath [\File] [\CheckRef]`.
pub(crate) fn load_module(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let path = full_path(cx, a, "FilePath", "File")?.unwrap_or_default();
    load(cx, a.name, &path, a.given("CheckRef"))?;
    Ok(Done::Next)
}

/// `UnLoad [\ErrIfChanged] | [\Save] FilePath [\File]`: the module a
/// `Load` loaded from that path (`ERR_UNLOAD` for one it did not); with
/// `\Save`, written back first. The simulation keeps no record of changes,
/// so `\ErrIfChanged` never fails.
pub(crate) fn unload_module(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let path = full_path(cx, a, "FilePath", "File")?.unwrap_or_default();
    let Some(i) = loaded_from(cx, &path) else {
        return fault(named_error(
            &cx.m.prog,
            "ERR_UNLOAD",
            format!("UnLoad: no module was loaded from {path}"),
        ));
    };
    if a.given("Save")
        && let Some(module) = cx.m.loaded.get(i).and_then(|l| l.modules.first().cloned())
    {
        super::save::write_module(cx, "UnLoad", &module, &path)?;
    }
    unload(cx, a.name, i)?;
    Ok(Done::Next)
}

/// `EraseModule ModuleName`: a module `Load` loaded; the program's own
/// modules stay (not simulated).
pub(crate) fn erase_module(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let name = cx.string(a, "ModuleName")?;
    let found =
        cx.m.loaded
            .iter()
            .rposition(|l| l.modules.iter().any(|m| m.eq_ignore_ascii_case(&name)));
    match found {
        Some(i) => unload(cx, a.name, i)?,
        None if cx.m.prog.module_named(&name).is_some() => {
            return fault(FaultKind::Unsupported(format!(
                "EraseModule of {name}, a module of the program as it was loaded"
            )));
        }
        None => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_MODULE",
                format!("EraseModule: the task has no module {name}"),
            ));
        }
    }
    Ok(Done::Next)
}

/// `ModExist(ModuleName)`: the task has a module of that name.
pub(crate) fn mod_exist(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = cx.string(a, "ModuleName")?;
    Ok(Value::Bool(cx.m.prog.module_named(&name).is_some()))
}

/// `ModTime(Object)`: when the module was loaded, in seconds since 1970
/// (the program's own modules when the run starts, a module `Load`
/// loaded then); `ERR_MODULE` for a module not in the task.
pub(crate) fn mod_time(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = cx.string(a, "Object")?;
    if cx.m.prog.module_named(&name).is_none() {
        return fault(named_error(
            &cx.m.prog,
            "ERR_MODULE",
            format!("ModTime: there is no module {name} in the task"),
        ));
    }
    let at = load_of(cx, &name).map_or(0.0, |l| l.at);
    Ok(super::data::epoch_value(at))
}

fn session_value(id: u32) -> Value {
    Value::Record {
        ty: "loadsession".to_owned(),
        fields: vec![("session".to_owned(), Value::Num(id as f32))],
    }
}

fn session_of(cx: &mut Cx<'_>, a: &Args) -> R<u32> {
    let v = cx.req(a, "LoadNo")?;
    Ok(v.field("session").and_then(Value::as_f64).unwrap_or(0.0) as u32)
}

/// `StartLoad [\Dynamic] FilePath [\File] LoadNo`: the load starts; the
/// file is read when `WaitLoad` waits for it.
pub(crate) fn start_load(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let path = full_path(cx, a, "FilePath", "File")?.unwrap_or_default();
    let sessions = &mut cx.m.load_sessions;
    sessions.next += 1;
    let id = sessions.next;
    sessions.started.push((id, path));
    let p = cx.place_arg(a, "LoadNo")?;
    cx.store(&p, session_value(id))?;
    Ok(Done::Next)
}

/// The started load of session `id`, taken out of the sessions.
fn take_session(cx: &mut Cx<'_>, name: &str, id: u32) -> R<String> {
    let sessions = &mut cx.m.load_sessions;
    match sessions.started.iter().position(|s| s.0 == id) {
        Some(i) => Ok(sessions.started.remove(i).1),
        None => fault(named_error(
            &cx.m.prog,
            "ERR_LOADNO_NOUSE",
            format!("{name}: the load session is not in use"),
        )),
    }
}

/// `WaitLoad [\UnloadPath] [\UnloadFile] LoadNo [\CheckRef]`: unloads
/// the module of `\UnloadPath` first, then finishes the load.
pub(crate) fn wait_load(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    if let Some(path) = full_path(cx, a, "UnloadPath", "UnloadFile")? {
        let Some(i) = loaded_from(cx, &path) else {
            return fault(named_error(
                &cx.m.prog,
                "ERR_UNLOAD",
                format!("WaitLoad: no module was loaded from {path}"),
            ));
        };
        unload(cx, a.name, i)?;
    }
    let id = session_of(cx, a)?;
    let path = take_session(cx, a.name, id)?;
    load(cx, a.name, &path, a.given("CheckRef"))?;
    let p = cx.place_arg(a, "LoadNo")?;
    cx.store(&p, session_value(0))?;
    Ok(Done::Next)
}

/// `CancelLoad LoadNo`: a load `StartLoad` started is dropped.
pub(crate) fn cancel_load(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id = session_of(cx, a)?;
    take_session(cx, a.name, id)?;
    let p = cx.place_arg(a, "LoadNo")?;
    cx.store(&p, session_value(0))?;
    Ok(Done::Next)
}
