//! One side of a comparison read through the project loader: a backup, a
//! task folder or a module, on the disk or in a git revision.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use rapid_analyzer::controller::ControllerOverride;
use rapid_analyzer::diff::{Snapshot, snapshot};
use rapid_analyzer::text::{Decoded, decode};
use rayon::prelude::*;

use crate::project::{self, Discovery, Environment, Kind, Sources, Walked};

/// What a side is.
pub struct Side {
    pub snapshot: Snapshot,
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
    let mut loaded = project::load(env, &sources, &ControllerOverride::default());
    for (r, path) in loaded.read.iter().zip(&found.files) {
        if let Err(why) = r {
            problems.push(format!("{}: {why}", path.display()));
        }
    }
    let base = match kind {
        Kind::File(_) => env.name(root.parent().unwrap_or(Path::new(""))),
        _ => env.name(root),
    };
    let relative = |name: &str| -> String {
        let rest = name
            .strip_prefix(base.as_str())
            .map(|r| r.trim_start_matches(['/', '\\']))
            .unwrap_or(name);
        if rest.is_empty() {
            ".".to_owned()
        } else {
            rest.replace('\\', "/")
        }
    };
    // Each file reduced on the thread pool.
    let per_file = loaded
        .workspace
        .checks()
        .par_iter()
        .map(|(task, unit)| {
            let modules = snapshot::unit_modules(task, unit, &relative(&unit.path));
            (relative(&task.key), modules)
        })
        .collect();
    let tasks = snapshot::group(per_file);
    let controller = loaded
        .workspace
        .tasks()
        .first()
        .map(|t| loaded.workspace.controller_of_task(&t.key))
        .unwrap_or_default();
    let configs = match kind {
        Kind::Folder => configs(env, root, &relative),
        _ => Vec::new(),
    };
    Ok(Side {
        snapshot: Snapshot {
            tasks,
            configs,
            robotware: controller.robotware,
            options: controller.options,
        },
        problems,
    })
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

/// An empty side (a file git says did not exist: `/dev/null`).
pub fn nothing() -> Side {
    Side {
        snapshot: Snapshot::default(),
        problems: Vec::new(),
    }
}

/// The working tree's paths, for a side read from the disk.
pub fn disk_root(cwd: &Path, p: &Path) -> PathBuf {
    if p.is_absolute() {
        p.to_owned()
    } else {
        cwd.join(p)
    }
}
