//! A project in parts that share nothing: each part holds whole tasks (a
//! controller backup with its every task, `HOME/` and configuration; a
//! `.pgf` program with the modules it lists; a plain folder), so that its
//! workspace is loaded, checked and dropped on its own, and the memory of
//! a run is that of the parts in progress, not of the whole project.
//!
//! A part gets the programs and configuration that apply to its tasks; what
//! a part's workspace says of its files is what a workspace of the whole
//! project says (`tests`: the corpus and layouts of backups, programs and
//! folders checked both ways).

use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};
use std::path::PathBuf;
use std::sync::Arc;

use rapid_analyzer::layout::backup_root;
use rapid_analyzer::task::{Config, Unit, parse_config};
use rapid_analyzer::workspace::{Workspace, config_applies, config_root};

use super::{Discovery, Environment, read_source, size_of};

/// One part of a project.
#[derive(Debug, Default)]
pub struct Part {
    /// The files asked for in this part, with the programs and
    /// configuration that apply to its tasks.
    pub found: Discovery,
    /// The rest of its tasks' files.
    pub context: Discovery,
    /// Where each of `found.files` is in the project's list of files.
    pub positions: Vec<usize>,
    /// The bytes of its module files.
    pub bytes: u64,
}

/// A project split into parts.
#[derive(Debug, Default)]
pub struct Split {
    /// Largest first.
    pub parts: Vec<Part>,
    /// The analyzer's names of the files asked for.
    pub names: HashSet<String>,
    /// The keys of their tasks (by place and programs).
    pub keys: BTreeSet<String>,
}

/// The parts of a project: the files of `found` and `context`, grouped so
/// that every task (and every controller, whose tasks share persistents)
/// is in one part.
pub fn split(env: &dyn Environment, found: &Discovery, context: &Discovery) -> Split {
    // Programs decide which modules form a task outside backups.
    let mut grouping = Workspace::new();
    for pgf in found.programs.iter().chain(&context.programs) {
        if let Ok(bytes) = env.read(pgf) {
            grouping.set_program(&env.name(pgf), &String::from_utf8_lossy(&bytes));
        }
    }
    // Every module with its task's key and its backup's folder, joined.
    let mut parts = Joined::default();
    let modules: Vec<(bool, usize, &PathBuf)> = found
        .files
        .iter()
        .enumerate()
        .map(|(i, p)| (true, i, p))
        .chain(context.files.iter().enumerate().map(|(i, p)| (false, i, p)))
        .collect();
    let mut part_of_module = Vec::with_capacity(modules.len());
    let mut names = HashSet::new();
    let mut asked_keys = BTreeSet::new();
    for (asked, _, path) in &modules {
        let name = env.name(path);
        let key = grouping.task_key(&name);
        if *asked {
            asked_keys.insert(key.clone());
            names.insert(name.clone());
        }
        let id = parts.id(&key);
        // A backup's tasks, `HOME/` and `SYSPAR` are one controller.
        if let Some(root) = backup_root(&key).or_else(|| backup_root(&name)) {
            let root = parts.id(root);
            parts.join(id, root);
        }
        part_of_module.push(id);
    }
    // A program's modules: the program's part.
    let mut program_part = Vec::new();
    for pgf in found.programs.iter().chain(&context.programs) {
        program_part.push(parts.find_key(&env.name(pgf)));
    }
    let mut out: BTreeMap<usize, Part> = BTreeMap::new();
    for ((asked, i, path), id) in modules.iter().zip(&part_of_module) {
        let part = out.entry(parts.find(*id)).or_default();
        part.bytes += size_of(env, path);
        if *asked {
            part.found.files.push((*path).clone());
            part.positions.push(*i);
        } else {
            part.context.files.push((*path).clone());
        }
    }
    let asked_programs = found.programs.len();
    for (k, (pgf, id)) in found
        .programs
        .iter()
        .chain(&context.programs)
        .zip(program_part)
        .enumerate()
    {
        if let Some(part) = id.and_then(|id| out.get_mut(&parts.find(id))) {
            let list = if k < asked_programs {
                &mut part.found.programs
            } else {
                &mut part.context.programs
            };
            list.push(pgf.clone());
        }
    }
    // Configuration goes where it applies (a backup's to its own tasks
    // only), as the workspace decides: among the keys below its folder.
    let keys: BTreeMap<&str, usize> = parts
        .keys
        .iter()
        .map(|(k, &id)| (k.as_str(), parts.find(id)))
        .collect();
    let asked_configs = found.configs.len();
    for (k, cfg) in found.configs.iter().chain(&context.configs).enumerate() {
        let name = env.name(cfg);
        let root = config_root(&name);
        let targets: HashSet<usize> = keys
            .range(root..)
            .take_while(|(key, _)| key.starts_with(root))
            .filter(|(key, _)| config_applies(&name, key))
            .map(|(_, &id)| id)
            .collect();
        for id in targets {
            if let Some(part) = out.get_mut(&id) {
                let list = if k < asked_configs {
                    &mut part.found.configs
                } else {
                    &mut part.context.configs
                };
                list.push(cfg.clone());
            }
        }
    }
    let mut out: Vec<Part> = out.into_values().collect();
    out.sort_by_key(|p| std::cmp::Reverse(p.bytes));
    Split {
        parts: out,
        names,
        keys: asked_keys,
    }
}

/// Sets of keys joined (union-find).
#[derive(Default)]
struct Joined {
    keys: HashMap<String, usize>,
    parent: Vec<usize>,
}

impl Joined {
    fn id(&mut self, key: &str) -> usize {
        if let Some(&id) = self.keys.get(key) {
            return id;
        }
        let id = self.parent.len();
        self.parent.push(id);
        self.keys.insert(key.to_owned(), id);
        id
    }

    fn find_key(&self, key: &str) -> Option<usize> {
        let id = *self.keys.get(key)?;
        Some(self.find(id))
    }

    fn find(&self, mut id: usize) -> usize {
        while self.parent[id] != id {
            id = self.parent[id];
        }
        id
    }

    fn join(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            self.parent[a.max(b)] = a.min(b);
        }
    }
}

/// The modules and configuration of a project's extra paths, read once for
/// every part.
#[derive(Default)]
pub struct Extra {
    pub units: Vec<Arc<Unit>>,
    pub configs: Vec<Config>,
}

/// Reads the extra paths' modules (their trees released: they are read,
/// not checked) and configuration, leaving out the modules named in
/// `asked`.
pub fn read_extra(env: &dyn Environment, extra: &Discovery, asked: &HashSet<String>) -> Extra {
    use rayon::prelude::*;
    let units = extra
        .files
        .par_iter()
        .filter(|p| !asked.contains(&env.name(p)))
        .filter_map(|p| {
            let file = read_source(env, p).ok()?;
            let mut unit = Unit::new(env.name(p), file.text, None);
            unit.release_tree();
            Some(Arc::new(unit))
        })
        .collect();
    let configs = extra
        .configs
        .iter()
        .filter_map(|p| env.read(p).ok())
        .map(|bytes| parse_config(&String::from_utf8_lossy(&bytes)))
        .collect();
    Extra { units, configs }
}

/// Adds the extra paths' modules and configuration to the workspace of a
/// part whose tasks' keys are `part_keys`: a module whose own task is asked
/// for (its key in `asked_keys`, of the whole project) joins that task when
/// it is in this part; any other joins every task; every configuration
/// applies to every task.
pub fn add_extra(
    workspace: &mut Workspace,
    extra: &Extra,
    asked_keys: &BTreeSet<String>,
    part_keys: &BTreeSet<String>,
) {
    for unit in &extra.units {
        let key = workspace.task_key(&unit.path);
        if !asked_keys.contains(&key) {
            workspace.add_extra_unit(unit.clone());
        } else if part_keys.contains(&key) {
            workspace.set_shared_unit(unit.clone());
        }
    }
    for config in &extra.configs {
        workspace.add_parsed_extra_config(config.clone());
    }
}
