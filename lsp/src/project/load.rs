//! Reading the files found and building the analyzer's [`Workspace`].

use std::collections::{BTreeSet, HashSet};
use std::path::PathBuf;
use std::sync::Arc;

use rapid_analyzer::controller::ControllerOverride;
use rapid_analyzer::task::Unit;
use rapid_analyzer::workspace::Workspace;
use rayon::prelude::*;

use super::{Discovery, Environment, Skip, SourceFile, read_source, size_of};

/// What a project is made of.
#[derive(Default)]
pub struct Sources<'a> {
    /// The files asked for (checked, evaluated, run), with the programs and
    /// configuration found with them.
    pub found: Option<&'a Discovery>,
    /// The rest of those files' tasks ([`super::context::task_context`]):
    /// loaded, not asked for.
    pub context: Option<&'a Discovery>,
    /// The modules and configuration of the extra paths: a module whose own
    /// task is asked for joins it; any other, and every configuration,
    /// joins every task asked for.
    pub extra: Option<&'a Discovery>,
}

/// A project loaded.
pub struct Loaded {
    pub workspace: Workspace,
    /// What became of each file of `found.files`, in its order.
    pub read: Vec<Result<SourceFile, Skip>>,
    /// The analyzer's name of each of them that was read.
    pub names: Vec<Option<String>>,
    /// The analyzer's names of the files asked for that were read.
    pub asked: HashSet<String>,
    /// The keys of their tasks.
    pub keys: BTreeSet<String>,
}

/// Reads, decodes and parses `files` in one parallel pass, largest files
/// first so that no big module is left to one thread at the end; `done` is
/// told of each file.
/// Returns each file's outcome and unit, in the order of `files`.
pub fn read_and_parse(
    env: &dyn Environment,
    files: &[PathBuf],
    done: &(dyn Fn() + Sync),
) -> (Vec<Result<SourceFile, Skip>>, Vec<Option<Unit>>) {
    read_and_parse_with(env, files, done, false)
}

/// [`read_and_parse`], releasing each unit's tree once its items are
/// lowered when `release` (it is parsed again where it is needed).
pub fn read_and_parse_with(
    env: &dyn Environment,
    files: &[PathBuf],
    done: &(dyn Fn() + Sync),
    release: bool,
) -> (Vec<Result<SourceFile, Skip>>, Vec<Option<Unit>>) {
    let mut order: Vec<(u64, usize)> = files
        .iter()
        .enumerate()
        .map(|(i, p)| (size_of(env, p), i))
        .collect();
    order.sort_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut parsed: Vec<(usize, Result<SourceFile, Skip>, Option<Unit>)> = order
        .par_iter()
        .map(|&(_, i)| {
            let read = read_source(env, &files[i]);
            let unit = read.as_ref().ok().map(|f| {
                let mut unit = Unit::new(env.name(&f.path), f.text.clone(), None);
                if release {
                    unit.release_tree();
                }
                unit
            });
            done();
            (i, read, unit)
        })
        .collect();
    parsed.sort_by_key(|(i, _, _)| *i);
    parsed.into_iter().map(|(_, r, u)| (r, u)).unzip()
}

/// Builds the workspace of `sources` from the files of `sources.found`
/// read by [`read_and_parse`] (`read` and `units`).
pub fn assemble(
    env: &dyn Environment,
    sources: &Sources<'_>,
    controller: &ControllerOverride,
    read: Vec<Result<SourceFile, Skip>>,
    units: Vec<Option<Unit>>,
) -> Loaded {
    let empty = Discovery::default();
    let found = sources.found.unwrap_or(&empty);
    let context = sources.context.unwrap_or(&empty);
    let names: Vec<Option<String>> = units
        .iter()
        .map(|u| u.as_ref().map(|u| u.path.clone()))
        .collect();
    let mut workspace = Workspace::new();
    workspace.set_controller(controller.clone());
    for path in found.programs.iter().chain(&context.programs) {
        if let Ok(bytes) = env.read(path) {
            workspace.set_program(&env.name(path), &String::from_utf8_lossy(&bytes));
        }
    }
    for path in found.configs.iter().chain(&context.configs) {
        if let Ok(bytes) = env.read(path) {
            workspace.set_config(&env.name(path), &String::from_utf8_lossy(&bytes));
        }
    }
    // A module that could not be read (encrypted, binary, too large)
    // leaves its task incomplete.
    for (r, path) in read.iter().zip(&found.files) {
        if r.is_err() {
            workspace.set_unreadable(&env.name(path));
        }
    }
    let asked: HashSet<String> = units.iter().flatten().map(|u| u.path.clone()).collect();
    let keys: BTreeSet<String> = asked.iter().map(|p| workspace.task_key(p)).collect();
    add_context(env, &mut workspace, context, &asked, &keys);
    if let Some(extra) = sources.extra {
        add_extra(env, &mut workspace, extra, &asked, &keys);
    }
    workspace.set_units(units.into_iter().flatten());
    Loaded {
        workspace,
        read,
        names,
        asked,
        keys,
    }
}

/// [`read_and_parse`] and [`assemble`].
pub fn load(
    env: &dyn Environment,
    sources: &Sources<'_>,
    controller: &ControllerOverride,
) -> Loaded {
    let files = sources.found.map_or(&[][..], |f| &f.files[..]);
    let (read, units) = read_and_parse(env, files, &|| {});
    assemble(env, sources, controller, read, units)
}

/// Adds the modules of the asked files' tasks that were not asked for
/// themselves (their programs and configuration are in already).
fn add_context(
    env: &dyn Environment,
    workspace: &mut Workspace,
    context: &Discovery,
    asked: &HashSet<String>,
    keys: &BTreeSet<String>,
) {
    // A backup's files all count: its tasks share persistents and load
    // modules of its HOME/.
    let backups: HashSet<&str> = asked
        .iter()
        .filter_map(|p| super::context::backup_of_file(p))
        .collect();
    let read: Vec<(String, Option<Unit>)> = context
        .files
        .par_iter()
        .filter_map(|p| {
            let path = env.name(p);
            let wanted = keys.contains(&workspace.task_key(&path))
                || rapid_analyzer::layout::owner_backup(&path).is_some_and(|b| backups.contains(b));
            if asked.contains(&path) || !wanted {
                return None;
            }
            // Read for its declarations, not checked: its tree is parsed
            // again where a check reads it.
            let unit = read_source(env, p).ok().map(|file| {
                let mut unit = Unit::new(path.clone(), file.text, None);
                unit.release_tree();
                unit
            });
            Some((path, unit))
        })
        .collect();
    for (path, unit) in read {
        match unit {
            Some(unit) => {
                workspace.set_unit(unit);
            }
            // A module of the task that cannot be read leaves it incomplete,
            // as when it is checked itself.
            None => workspace.set_unreadable(&path),
        }
    }
}

/// Adds the modules and configuration of the extra paths. A module whose
/// own task is asked for joins it; any other joins every task (all of them
/// are tasks asked for), under its own name (its diagnostics are not
/// computed), and so does every configuration.
fn add_extra(
    env: &dyn Environment,
    workspace: &mut Workspace,
    extra: &Discovery,
    asked: &HashSet<String>,
    keys: &BTreeSet<String>,
) {
    let units: Vec<Unit> = extra
        .files
        .par_iter()
        .map(|p| env.name(p))
        .zip(&extra.files)
        .filter(|(name, _)| !asked.contains(name))
        .filter_map(|(name, p)| {
            let file = read_source(env, p).ok()?;
            Some(Unit::new(name, file.text, None))
        })
        .collect();
    for unit in units {
        if keys.contains(&workspace.task_key(&unit.path)) {
            workspace.set_unit(unit);
            continue;
        }
        workspace.add_extra_unit(Arc::new(unit));
    }
    for path in &extra.configs {
        if let Ok(bytes) = env.read(path) {
            workspace.add_extra_config(&String::from_utf8_lossy(&bytes));
        }
    }
}

/// The tasks some paths hold, loaded whole: a file named brings the other
/// modules, programs and configuration of its task's folder (a backup's
/// `RAPID/TASKn`, else its own folder); a folder brings what is under it.
/// For `rapid eval --file`, `rapid run`, `rapid test` and `rapid dap`.
pub struct Around {
    pub loaded: Loaded,
    /// The files named (not folders), in the order given.
    pub named: Vec<PathBuf>,
    /// Every module file found, named ones included (the order of
    /// `loaded.read`).
    pub files: Vec<PathBuf>,
    /// `rapid.toml`'s `[controller]`, found from the first path.
    pub controller: crate::config::ControllerConfig,
}

/// Loads the tasks of `paths` ([`Around`]). A path that does not exist is
/// an error, with the path.
pub fn load_around(
    env: &dyn Environment,
    paths: &[PathBuf],
) -> Result<Around, (PathBuf, std::io::Error)> {
    let mut roots = Vec::new();
    let mut named = Vec::new();
    for p in paths {
        match env.kind(p) {
            Err(e) => return Err((p.clone(), e)),
            Ok(super::Kind::File(_)) => {
                let key = rapid_analyzer::task::task_key(&env.name(p));
                roots.push(if key.is_empty() {
                    PathBuf::from(".")
                } else {
                    PathBuf::from(key)
                });
                // A program (`.pgf`) names the modules it lists.
                match super::named_program(env, p) {
                    Some(modules) if modules.is_empty() => {
                        return Err((
                            p.clone(),
                            std::io::Error::new(
                                std::io::ErrorKind::NotFound,
                                "the program lists no module that exists",
                            ),
                        ));
                    }
                    Some(modules) => named.extend(modules),
                    None => named.push(p.clone()),
                }
            }
            Ok(_) => {
                // A backup's task folder (or a folder in it) is loaded with
                // the rest of its task: its modules and the backup's
                // configuration.
                let inside = env.name(&p.join("x.mod"));
                let folders = super::context::task_folders_in(env, &inside);
                match folders.deep {
                    Some(deep) => {
                        roots.extend(folders.shallow);
                        roots.push(deep);
                    }
                    None => roots.push(p.clone()),
                }
            }
        }
    }
    let mut seen = std::collections::HashSet::new();
    roots.retain(|r| seen.insert(r.clone()));
    let mut found = super::discover_in(env, &roots, Arc::new(|_, _| false), None);
    let listed = super::context::program_members(env, found.programs.iter());
    // A file named is found again walking its folder, perhaps spelt
    // otherwise (`Cell.mod` is `./Cell.mod` walking `.`): one file.
    let mut have: std::collections::HashSet<String> =
        found.files.iter().map(|f| env.name(f)).collect();
    for n in named.iter().chain(&listed) {
        if have.insert(env.name(n)) {
            found.files.push(n.clone());
        }
    }
    let sources = Sources {
        found: Some(&found),
        ..Sources::default()
    };
    // The controller `rapid check` would take: rapid.toml's `[controller]`
    // (RobotWare, options, robot), found from the first path.
    let (controller, config_controller) = match paths.first() {
        Some(first) => {
            let (config, file) = crate::config::resolve_in(env, None, first).map_err(|e| {
                (
                    first.clone(),
                    std::io::Error::new(std::io::ErrorKind::InvalidData, e.to_string()),
                )
            })?;
            let resolved = config.controller.resolve().map_err(|(key, why)| {
                (
                    file.unwrap_or_else(|| first.clone()),
                    std::io::Error::new(
                        std::io::ErrorKind::InvalidData,
                        format!("[controller] {key}: {why}"),
                    ),
                )
            })?;
            (resolved, config.controller)
        }
        None => Default::default(),
    };
    let loaded = load(env, &sources, &controller);
    Ok(Around {
        loaded,
        named,
        files: found.files,
        controller: config_controller,
    })
}
