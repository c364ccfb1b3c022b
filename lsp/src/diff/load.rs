//! One side of a comparison read through the project loader: a backup, a
//! task folder or a module, on the disk or in a git revision.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use rapid_analyzer::controller::ControllerOverride;
use rapid_analyzer::diff::{Snapshot, snapshot};
use rapid_analyzer::text::{Decoded, decode};
use rayon::prelude::*;

use crate::project::{self, Discovery, Environment, Kind, Sources, Walked};

/// A side read and parsed, not yet reduced ([`Side::reduce`]).
pub struct Side {
    workspace: rapid_analyzer::workspace::Workspace,
    /// The analyzer's name of the side's folder: files and tasks are named
    /// by their path below it.
    base: String,
    configs: Vec<(String, rapid_analyzer::cfg::CfgFile)>,
    /// Files that could not be read, with why (a module skipped makes the
    /// comparison incomplete: said, never silent).
    pub problems: Vec<String>,
}

/// Reads the side at `root` in `env`: a folder (a backup, a task, a folder
/// of modules) with its configuration, or one module file alone. Tasks are
/// named by their folder below `root` (`RAPID/TASK1`; `.` for `root`
/// itself), files by their path below `root`.
pub fn side(env: &dyn Environment, root: &Path) -> Result<Side, String> {
    let kind = env
        .kind(root)
        .map_err(|e| format!("{}: {e}", root.display()))?;
    let found = match kind {
        Kind::File(_) => Discovery {
            files: vec![root.to_owned()],
            ..Discovery::default()
        },
        Kind::Folder => project::discover_in(env, &[root.to_owned()], Arc::new(|_, _| false), None),
        Kind::Other(what) => return Err(format!("{}: {what}, not a file", root.display())),
    };
    let mut problems: Vec<String> = found
        .errors
        .iter()
        .map(|(p, why)| format!("{}: {why}", p.display()))
        .collect();
    let sources = Sources {
        found: Some(&found),
        ..Sources::default()
    };
    let loaded = project::load(env, &sources, &ControllerOverride::default());
    for (r, path) in loaded.read.iter().zip(&found.files) {
        if let Err(why) = r {
            problems.push(format!("{}: {why}", path.display()));
        }
    }
    let base = match kind {
        Kind::File(_) => env.name(root.parent().unwrap_or(Path::new(""))),
        _ => env.name(root),
    };
    let mut side = Side {
        workspace: loaded.workspace,
        base,
        configs: Vec::new(),
        problems,
    };
    if kind == Kind::Folder {
        side.configs = configs(env, root, &|name| side.relative(name));
    }
    Ok(side)
}

/// A side with nothing (a file git says did not exist: `/dev/null`).
pub fn nothing() -> Side {
    Side {
        workspace: rapid_analyzer::workspace::Workspace::new(),
        base: String::new(),
        configs: Vec::new(),
        problems: Vec::new(),
    }
}

impl Side {
    /// A name below the side's folder (`.` for the folder itself).
    fn relative(&self, name: &str) -> String {
        let rest = name
            .strip_prefix(self.base.as_str())
            .map(|r| r.trim_start_matches(['/', '\\']))
            .unwrap_or(name);
        if rest.is_empty() {
            ".".to_owned()
        } else {
            rest.replace('\\', "/")
        }
    }

    /// The RobotWare version and options the side's backup names.
    pub fn controller(&mut self) -> rapid_analyzer::controller::ControllerInfo {
        let first = self.workspace.tasks().first().map(|t| t.key.clone());
        first
            .map(|k| self.workspace.controller_of_task(&k))
            .unwrap_or_default()
    }

    /// Each module file by its path below the side, with its text's digest.
    pub fn files(&self) -> HashSet<(String, u64)> {
        self.workspace
            .paths()
            .filter_map(|p| self.workspace.unit(p))
            .map(|u| (self.relative(&u.path), snapshot::text_digest(&u.text)))
            .collect()
    }

    /// The side reduced to what is compared, each file on the thread pool;
    /// a file in `same` (its path and digest) is the same on the other side
    /// and is reduced to its data's values only.
    pub fn reduce(&mut self, same: &HashSet<(String, u64)>) -> Snapshot {
        let controller = self.controller();
        let checks = self.workspace.checks();
        let per_file = checks
            .par_iter()
            .map(|(task, unit)| {
                let file = self.relative(&unit.path);
                let depth = if same.contains(&(file.clone(), snapshot::text_digest(&unit.text))) {
                    snapshot::Depth::SameText
                } else {
                    snapshot::Depth::Full
                };
                let modules = snapshot::unit_modules(task, unit, &file, depth);
                (self.relative(&task.key), modules)
            })
            .collect();
        Snapshot {
            tasks: snapshot::group(per_file),
            configs: std::mem::take(&mut self.configs),
            robotware: controller.robotware,
            options: controller.options,
        }
    }
}

impl Side {
    /// Says of each moved target of `report` whether this side's task
    /// robot still reaches it, and in which configuration (the analyzer's
    /// [`rapid_analyzer::diff::Report::annotate_reach`]).
    pub fn annotate_reach(&mut self, report: &mut rapid_analyzer::diff::Report) {
        for task in self.workspace.tasks() {
            report.annotate_reach(&self.relative(&task.key), &task);
        }
    }
}

/// Every `.cfg` file below `root`, read and named by its path below it.
fn configs(
    env: &dyn Environment,
    root: &Path,
    relative: &dyn Fn(&str) -> String,
) -> Vec<(String, rapid_analyzer::cfg::CfgFile)> {
    let mut out = Vec::new();
    for w in env.walk(
        root,
        None,
        &(Arc::new(|_: &Path, _| false) as project::Excluder),
    ) {
        let Walked::Entry(path, Kind::File(_)) = w else {
            continue;
        };
        let is_cfg = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("cfg"));
        if !is_cfg {
            continue;
        }
        let Ok(bytes) = env.read(&path) else {
            continue;
        };
        if let Decoded::Text { text, .. } = decode(&bytes) {
            out.push((
                relative(&env.name(&path)),
                rapid_analyzer::cfg::parse(&text),
            ));
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// The working tree's paths, for a side read from the disk.
pub fn disk_root(cwd: &Path, p: &Path) -> PathBuf {
    if p.is_absolute() {
        p.to_owned()
    } else {
        cwd.join(p)
    }
}
