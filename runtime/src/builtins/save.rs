//! `Save`: a program module written to a file, as the controller writes
//! it: the module's text with each persistent's value as it is now.

use rapid_analyzer::items::Storage;
use rapid_analyzer::task::{Item, ItemRef};

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, R, fault, named_error};
use crate::program::Home;
use crate::world::FileError;

/// `Save [\TaskRef] | [\TaskName] ModuleName [\FilePath] [\File]`: the
/// module of this task named `ModuleName` (`ERR_MODULE` when there is
/// none) to `FilePath` (a folder when `\File` names the file), persistents
/// at their current values; a file that cannot be written raises
/// `ERR_FILEOPEN`. Without `\FilePath`, a module `Load` loaded goes back
/// to its file; the simulation saves the task's own modules.
pub(crate) fn save(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    if let Some(task) = cx.named_task(a)?
        && task + 1 != cx.m.number
    {
        let name = cx.sh.names.get(task).cloned().unwrap_or_default();
        return fault(FaultKind::Unsupported(format!(
            "Save of a module of another task ({name})"
        )));
    }
    let name = cx.string(a, "ModuleName")?;
    let path = match super::modules::full_path(cx, a, "FilePath", "File")? {
        Some(path) => path,
        None => match super::modules::path_of_module(cx, &name) {
            Some(path) => path,
            None => {
                return fault(FaultKind::Unsupported(
                    "Save without \\FilePath of a module no Load loaded (the file the controller loaded it from)"
                        .to_owned(),
                ));
            }
        },
    };
    write_module(cx, "Save", &name, &path)?;
    Ok(Done::Next)
}

/// Writes the task's module `name` to `path` (for `what`, an instruction).
pub(crate) fn write_module(cx: &mut Cx<'_>, what: &str, name: &str, path: &str) -> R<()> {
    let Some(text) = module_text(cx, name) else {
        return fault(named_error(
            &cx.m.prog,
            "ERR_MODULE",
            format!("{what}: the task has no module {name}"),
        ));
    };
    match cx.sh.files.write(path, &super::files::latin1(&text), false) {
        Ok(()) => {
            super::files::touch(cx, path, true);
            Ok(())
        }
        Err(FileError::Unsupported(why)) => {
            fault(FaultKind::Unsupported(format!("{what} ({why})")))
        }
        Err(FileError::Denied(m) | FileError::NotFound(m) | FileError::Other(m)) => fault(
            named_error(&cx.m.prog, "ERR_FILEOPEN", format!("{what}: {m}")),
        ),
    }
}

fn module_text(cx: &Cx<'_>, name: &str) -> Option<String> {
    let prog = cx.m.prog.clone();
    let module = prog.modules.get(prog.module_named(name)?)?;
    let unit = prog.task.unit(module.unit)?;
    let decl = unit.items.modules.get(module.index)?;
    let text = unit.text.get(decl.range.clone())?;
    // Edits (range in the unit's text, new text), made from the last.
    let mut edits: Vec<(std::ops::Range<usize>, String)> = Vec::new();
    for (i, d) in decl.data.iter().enumerate() {
        if d.storage != Storage::Pers {
            continue;
        }
        let item = ItemRef {
            unit: module.unit,
            module: module.index,
            item: Item::Data(i),
        };
        let value = match prog.items.get(&item) {
            Some(Home::Pers(k)) => {
                cx.m.pers_map
                    .get(*k as usize)
                    .and_then(|&i| cx.sh.pers.get(i as usize))
            }
            Some(Home::Global(g)) => cx.m.globals.get(*g as usize),
            None => None,
        };
        let Some(value) = value else { continue };
        match &d.init {
            Some(init) => edits.push((init.clone(), value.to_string())),
            None => {
                // `PERS num n;`: the value goes before the `;`.
                let body = unit.text.get(d.range.clone()).unwrap_or_default();
                let at = d.range.start + body.trim_end().trim_end_matches(';').len();
                edits.push((at..at, format!(":={value}")));
            }
        }
    }
    let mut out = text.to_owned();
    edits.sort_by_key(|(r, _)| std::cmp::Reverse(r.start));
    for (range, new) in edits {
        let (Some(start), Some(end)) = (
            range.start.checked_sub(decl.range.start),
            range.end.checked_sub(decl.range.start),
        ) else {
            continue;
        };
        if end <= out.len() && out.is_char_boundary(start) && out.is_char_boundary(end) {
            out.replace_range(start..end, &new);
        }
    }
    if !out.ends_with('\n') {
        out.push('\n');
    }
    Some(out)
}
