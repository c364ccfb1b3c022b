//! `rapid diff`: what really changed between two backups, two task
//! folders, two modules, or two git revisions of a path.
//!
//! Each side is read through the project loader (`load`; a git revision
//! through [`git::GitTree`], an [`crate::project::Environment`] over
//! `git ls-tree` and `git cat-file`), reduced to the analyzer's
//! [`Snapshot`] and compared by [`rapid_analyzer::diff::compare`]; this
//! module only chooses the sides and writes the report (`output`: human,
//! JSON, Markdown). Exit codes: 0, or with `--exit-code` 1 when something
//! changed beyond the thresholds; 2 for bad usage or a side that cannot be
//! read.

mod git;
mod load;
mod output;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use std::collections::HashSet;

use rapid_analyzer::diff::{Options, Report, Snapshot, compare};

// Files are named as the paths given name them, not by their real place:
// `git difftool --dir-diff` links the working tree's files into its folder.
use crate::project::DiskAsNamed as Disk;

#[derive(Debug, clap::Args)]
#[command(after_help = "Examples:
  rapid diff backup-2024-01/ backup-2024-06/      two backups (or task folders, or modules)
  rapid diff HEAD~1 HEAD -- cell/                  two commits of a path
  rapid diff HEAD -- cell/                         a commit and the working tree
  rapid diff old/ new/ --format markdown           a pull-request comment
  rapid diff old/ new/ --exit-code --ignore-moves-below 0.1mm --ignore-moves-below 0.05deg")]
pub struct DiffArgs {
    /// The old side: a backup, a task folder or a module; or a git revision
    /// (with `--` and a path, or when it is no file or folder here).
    #[arg(required_unless_present = "git_driver")]
    pub old: Option<String>,
    /// The new side, as OLD; with a revision for OLD and no NEW, the
    /// working tree.
    pub new: Option<String>,
    /// With git revisions: the path to compare (default: the current
    /// folder).
    #[arg(last = true, value_name = "PATH")]
    pub paths: Vec<PathBuf>,
    /// How to print the report.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
    /// Exit with 1 when something changed (beyond the thresholds).
    #[arg(long)]
    pub exit_code: bool,
    /// Leave out positions and frames that moved less than this (`0.1mm`,
    /// or `0.05deg` for orientations and joints; a plain number is mm).
    /// Give it twice for both. Changed configurations and external axes are
    /// always reported.
    #[arg(long, value_name = "AMOUNT", value_parser = parse_threshold)]
    pub ignore_moves_below: Vec<Threshold>,
    /// The seven arguments git passes to an external diff driver (`path
    /// old-file old-hex old-mode new-file new-hex new-mode`): set
    /// `diff.rapid.command` to `rapid diff --git-driver` (see the README).
    #[arg(long, num_args = 7, value_name = "ARG", conflicts_with_all = ["new", "paths"])]
    pub git_driver: Option<Vec<String>>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Grouped by task and module, coloured on a terminal.
    Human,
    /// One JSON document (the report's fields, see docs/diff.md).
    Json,
    /// Markdown for a pull-request comment.
    Markdown,
}

/// A threshold of `--ignore-moves-below`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Threshold {
    Mm(f64),
    Deg(f64),
}

fn parse_threshold(s: &str) -> Result<Threshold, String> {
    let t = s.trim().to_ascii_lowercase();
    let (number, deg) = if let Some(n) = t.strip_suffix("deg").or_else(|| t.strip_suffix('°')) {
        (n, true)
    } else {
        (t.strip_suffix("mm").unwrap_or(&t), false)
    };
    let x: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not an amount like 0.1mm or 0.05deg"))?;
    if !x.is_finite() || x < 0.0 {
        return Err(format!("`{s}` must be a positive amount"));
    }
    Ok(if deg {
        Threshold::Deg(x)
    } else {
        Threshold::Mm(x)
    })
}

pub fn run(args: DiffArgs) -> ExitCode {
    let mut stderr = anstream::stderr();
    let cwd = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    let (mut old, mut new, titles) = match sides(&args, &cwd) {
        Ok(s) => s,
        Err(e) => {
            let _ = writeln!(stderr, "rapid diff: {e}");
            return ExitCode::from(2);
        }
    };
    for p in old.problems.iter().chain(&new.problems) {
        let _ = writeln!(stderr, "rapid diff: {p}");
    }
    let (old_snapshot, new_snapshot) = reduce(&mut old, &mut new);
    let mut options = Options::default();
    for t in &args.ignore_moves_below {
        match *t {
            Threshold::Mm(x) => options.moves_below_mm = x,
            Threshold::Deg(x) => options.rotations_below_deg = x,
        }
    }
    let mut report = compare(&old_snapshot, &new_snapshot, &options);
    new.annotate_reach(&mut report);
    let stdout = std::io::stdout();
    let colours = anstream::AutoStream::choice(&stdout);
    let mut buffered = std::io::BufWriter::new(stdout.lock());
    let written = {
        let mut out = anstream::AutoStream::new(&mut buffered as &mut dyn Write, colours);
        match args.format {
            Format::Human => output::human(&mut out, &report, &titles),
            Format::Markdown => output::markdown(&mut out, &report, &titles),
            Format::Json => output::json(&mut out, &report, &titles),
        }
    };
    if written.and_then(|()| buffered.flush()).is_err() {
        // A closed pipe (`| head`): nothing more to say.
        return ExitCode::SUCCESS;
    }
    if args.exit_code && !report.is_empty() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Both sides reduced, at once. A file with the same path and text on both
/// sides is reduced to its data's values (its routines cannot differ),
/// unless the two backups name different RobotWare versions: then every
/// name the program uses is needed, to list the built-ins that changed.
fn reduce(old: &mut load::Side, new: &mut load::Side) -> (Snapshot, Snapshot) {
    let versions = (old.controller().robotware, new.controller().robotware);
    let same: HashSet<(String, u64)> = match versions {
        (Some(a), Some(b)) if a != b => HashSet::new(),
        _ => old.files().intersection(&new.files()).cloned().collect(),
    };
    rayon::join(|| old.reduce(&same), || new.reduce(&same))
}

/// What the two sides are called in the report.
pub struct Titles {
    pub old: String,
    pub new: String,
}

type Sides = (load::Side, load::Side, Titles);

/// Reads both sides as the arguments say.
fn sides(args: &DiffArgs, cwd: &Path) -> Result<Sides, String> {
    if let Some(g) = &args.git_driver {
        return git_driver(g);
    }
    let old_arg = args.old.as_deref().unwrap_or_default();
    let revisions = !args.paths.is_empty()
        || args.new.is_none()
        || !(exists(cwd, old_arg) && args.new.as_deref().is_some_and(|n| exists(cwd, n)));
    if !revisions {
        let new = args.new.as_deref().unwrap_or_default();
        let titles = Titles {
            old: old_arg.to_owned(),
            new: new.to_owned(),
        };
        let (old, new) = rayon::join(
            || load::side(&Disk, &load::disk_root(cwd, Path::new(old_arg))),
            || load::side(&Disk, &load::disk_root(cwd, Path::new(new))),
        );
        return Ok((old?, new?, titles));
    }
    if args.paths.len() > 1 {
        return Err("give one path after `--`".to_owned());
    }
    for rev in args.old.iter().chain(&args.new) {
        if !git::is_revision(cwd, rev) {
            return Err(if exists(cwd, rev) {
                format!(
                    "`{rev}` is a path here: give two paths, or two git revisions and `-- PATH`"
                )
            } else {
                format!("`{rev}` is neither a file or folder nor a git revision here")
            });
        }
    }
    let path = args
        .paths
        .first()
        .cloned()
        .unwrap_or_else(|| PathBuf::from("."));
    let shown = path.display().to_string();
    let old = revision_side(cwd, old_arg, &path)?;
    let (new, new_title) = match &args.new {
        Some(rev) => (revision_side(cwd, rev, &path)?, format!("{rev}:{shown}")),
        None => (
            load::side(&Disk, &load::disk_root(cwd, &path))?,
            format!("{shown} (working tree)"),
        ),
    };
    let titles = Titles {
        old: format!("{old_arg}:{shown}"),
        new: new_title,
    };
    Ok((old, new, titles))
}

fn exists(cwd: &Path, p: &str) -> bool {
    load::disk_root(cwd, Path::new(p)).exists()
}

fn revision_side(cwd: &Path, rev: &str, path: &Path) -> Result<load::Side, String> {
    let opened = git::open(cwd, rev, std::slice::from_ref(&path.to_path_buf()))?;
    let root = opened
        .roots
        .first()
        .cloned()
        .unwrap_or_else(|| PathBuf::from(format!("{rev}:")));
    load::side(&opened.tree, &root).map_err(|_| format!("`{}` is not in `{rev}`", path.display()))
}

/// `path old-file old-hex old-mode new-file new-hex new-mode`: two files,
/// either `/dev/null` when the file is added or removed.
fn git_driver(a: &[String]) -> Result<Sides, String> {
    let [path, old, _, _, new, _, _] = a else {
        return Err("--git-driver takes the seven arguments git passes".to_owned());
    };
    let one = |f: &str| {
        if f == "/dev/null" {
            Ok(load::nothing())
        } else {
            load::side(&Disk, Path::new(f))
        }
    };
    Ok((
        one(old)?,
        one(new)?,
        Titles {
            old: format!("a/{path}"),
            new: format!("b/{path}"),
        },
    ))
}

/// The JSON report (for the editors, which read it).
pub fn to_json(report: &Report, titles: &Titles) -> serde_json::Value {
    serde_json::json!({
        "old": titles.old,
        "new": titles.new,
        "summary": report.summary(),
        "tasks": report.tasks,
        "config": report.config,
        "builtins": report.builtins,
        "ignored_moves": report.ignored_moves,
    })
}
