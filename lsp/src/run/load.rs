//! Loading the task(s) a path holds for `rapid run`, `rapid test` and
//! `rapid dap`: the files are found and grouped as `rapid check` finds and
//! groups them (a backup's `RAPID/TASKn`, the modules a `.pgf` lists, else
//! a folder), through the analyzer's `Workspace`; a backup's `SYS.cfg`
//! says what each task is called, when it starts and where.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use rapid_analyzer::layout::controller_of;
use rapid_analyzer::task::{Task, TaskKind, TaskSettings, Unit};
use rapid_runtime::world::{SysInfo, System};
use rapid_runtime::{Program, SignalChange, SignalKind};

use crate::project::Environment;

/// The tasks found under `paths` (each named file's task whole: the other
/// modules of its folder or backup task are loaded with it), each with
/// what `SYS.cfg` says of it. Files that cannot be read are reported in
/// `skipped`.
pub struct Found {
    pub tasks: Vec<Arc<Task>>,
    /// By task: its `SYS.cfg` entry, when its controller has one.
    pub settings: Vec<Option<TaskSettings>>,
    /// By task: its controller's configuration and identity.
    pub systems: Vec<System>,
    pub skipped: Vec<(PathBuf, String)>,
}

pub fn tasks(paths: &[PathBuf]) -> Result<Found, String> {
    tasks_in(&crate::project::DiskAsNamed, paths)
}

/// [`tasks`] in `env`.
pub fn tasks_in(env: &dyn Environment, paths: &[PathBuf]) -> Result<Found, String> {
    let around = crate::project::load_around(env, paths)
        .map_err(|(p, e)| format!("{}: {e}", p.display()))?;
    let mut workspace = around.loaded.workspace;
    let skipped = around
        .loaded
        .read
        .iter()
        .zip(&around.files)
        .filter_map(|(r, file)| r.as_ref().err().map(|why| (file.clone(), why.to_string())))
        .collect();
    let mut tasks = if around.named.is_empty() {
        workspace.tasks()
    } else {
        let mut t: Vec<Arc<Task>> = around
            .named
            .iter()
            .map(|n| workspace.task_of(&env.name(n)))
            .collect();
        t.dedup_by(|a, b| a.key == b.key);
        t
    };
    tasks.retain(|t| !t.units.is_empty());
    let settings = tasks
        .iter()
        .map(|t| workspace.task_settings(&t.key))
        .collect();
    let systems = tasks
        .iter()
        .map(|t| system_of(&workspace, &t.key, &around.controller))
        .collect();
    Ok(Found {
        tasks,
        settings,
        systems,
        skipped,
    })
}

/// The controller's `HOME:` folder for the task `key`: a backup's `HOME`
/// folder, else the `HOME` folder that holds the task, else one the task's
/// folder holds (a project keeps its controller's HOME so; never a Unix
/// system's `/home`). File instructions see a copy of it
/// ([`super::Sandbox::seeded`]).
pub fn home_of(key: &str) -> Option<PathBuf> {
    let is_home = |p: &Path| {
        p.file_name()
            .is_some_and(|n| rapid_analyzer::layout::is_home_folder(&n.to_string_lossy()))
            && p.is_dir()
    };
    let home_in = |dir: &Path| {
        std::fs::read_dir(dir)
            .ok()?
            .filter_map(Result::ok)
            .map(|e| e.path())
            .find(|p| is_home(p))
    };
    if let Some(root) = rapid_analyzer::layout::backup_root(key)
        && let Some(found) = home_in(Path::new(root))
    {
        return Some(found);
    }
    // The task's folder (the current one for an empty key).
    let dir = Path::new(if key.is_empty() { "." } else { key });
    dir.ancestors()
        .find(|p| is_home(p))
        .map(Path::to_path_buf)
        // A project's folder that keeps its controller's HOME inside.
        .or_else(|| home_in(dir))
}

/// [`home_of`], when it lies inside one of `roots` (`None`: anywhere), as
/// a server that may read only inside its roots asks.
pub fn home_within(key: &str, roots: Option<&[PathBuf]>) -> Option<PathBuf> {
    let home = home_of(key)?;
    let Some(roots) = roots else {
        return Some(home);
    };
    let real = std::fs::canonicalize(&home).ok()?;
    roots
        .iter()
        .filter_map(|r| std::fs::canonicalize(r).ok())
        .any(|r| real.starts_with(r))
        .then_some(home)
}

/// The controller of the task `key` for `ReadCfgData` and `GetSysInfo`:
/// the configuration files that apply to it (a backup's `SYSPAR`), read by
/// the analyzer's one reader, and what `BACKINFO` says (the system's name,
/// the RobotWare version as written there, else the version `rapid.toml`
/// sets); `rapid.toml`'s `[controller]` identity keys (`system-name`,
/// `serial-number`, `lan-ip`, `controller-id`, `language`) win.
pub fn system_of(
    workspace: &rapid_analyzer::workspace::Workspace,
    key: &str,
    config: &crate::config::ControllerConfig,
) -> System {
    let domains = workspace
        .config_files_of_task(key)
        .into_iter()
        .map(|(path, file)| (System::domain_of(&path, &file), (*file).clone()))
        .collect();
    let info = workspace.controller_of_task(key);
    let version = info
        .robotware_text
        .clone()
        .or_else(|| info.robotware.map(|v| v.to_string()));
    System {
        domains,
        info: SysInfo {
            sw_version_name: version.as_ref().map(|v| format!("RobotWare {v}")),
            sw_version: version,
            system_name: config.system_name.clone().or(info.system_name),
            serial_no: config.serial_number.clone(),
            lan_ip: config.lan_ip.clone(),
            ctrl_id: config.controller_id.clone(),
            ctrl_lang: config.language.clone(),
            ..SysInfo::default()
        },
    }
}

pub(crate) fn folder_name(key: &str) -> &str {
    let key = key.trim_end_matches(['/', '\\']);
    key.rsplit(['/', '\\']).next().unwrap_or(key)
}

/// A task of a controller to run.
pub struct TaskToRun {
    /// The task's name on the controller (`T_ROB1`).
    pub name: String,
    pub task: Arc<Task>,
    pub kind: TaskKind,
    /// The routine it starts in.
    pub entry: String,
    /// It moves a robot.
    pub motion: bool,
    /// What the loader found in `task` (when known: [`TaskToRun::load_check`]).
    pub checked: Option<(Arc<Task>, rapid_runtime::LoadCheck)>,
}

impl TaskToRun {
    /// What the controller's loader finds in the task
    /// ([`rapid_runtime::load_check`]), found once.
    pub fn load_check(&self) -> rapid_runtime::LoadCheck {
        match &self.checked {
            Some((task, check)) if Arc::ptr_eq(task, &self.task) => check.clone(),
            _ => rapid_runtime::load_check(&self.task),
        }
    }
}

/// The controller a path holds: its tasks, its configuration and
/// identity.
#[derive(Default)]
pub struct Loaded {
    pub tasks: Vec<TaskToRun>,
    pub system: System,
    /// The controller's `HOME:` folder ([`home_of`]).
    pub home: Option<PathBuf>,
    /// What loading says of the tasks: the modules taken from the
    /// repository around them ([`super::missing`]).
    pub notes: Vec<String>,
}

/// The controller `path` holds, to run: every task of a backup (or of a
/// folder of task folders) together, else the one task of `path` (the
/// one that declares `entry` when a folder holds unrelated ones); `only`
/// keeps the task of that name. A task starts in its `SYS.cfg` entry
/// routine, else in `entry` (`main` when `None`); `entry` given wins for
/// the one task `only` names.
pub fn controller(path: &Path, only: Option<&str>, entry: Option<&str>) -> Result<Loaded, String> {
    controller_in(&crate::project::DiskAsNamed, path, only, entry)
}

/// [`controller`], its files read through `env` (`rapid mcp` reads only
/// inside its roots).
pub fn controller_in(
    env: &dyn Environment,
    path: &Path,
    only: Option<&str>,
    entry: Option<&str>,
) -> Result<Loaded, String> {
    let found = tasks_in(env, std::slice::from_ref(&path.to_path_buf()))?;
    if found.tasks.is_empty() {
        return Err(format!("{}: no RAPID modules found", path.display()));
    }
    let near = found.tasks.clone();
    let mut loaded = chosen(found, path, only, entry)?;
    // The modules the tasks lack: from what was loaded with them, else
    // from the whole repository (the folder with `.git` or `rapid.toml`
    // around the path).
    let mut repository = None;
    for t in &mut loaded.tasks {
        let mut done = super::missing::complete(&t.task, &near, &t.entry);
        if done.lacking {
            let pool = repository.get_or_insert_with(|| {
                repository_of(env, path)
                    .and_then(|root| tasks_in(env, &[root]).ok())
                    .map(|f| f.tasks)
                    .unwrap_or_default()
            });
            let more = super::missing::complete(&done.task, pool, &t.entry);
            done.task = more.task;
            done.check = more.check;
            done.notes.extend(more.notes);
        }
        t.checked = Some((done.task.clone(), done.check));
        t.task = done.task;
        loaded.notes.extend(done.notes);
    }
    Ok(loaded)
}

/// The repository `path` is in: the nearest folder around it with a
/// `.git` or a `rapid.toml` (not the home folder), named as `path` is
/// (relative to the working folder when `path` is relative).
fn repository_of(env: &dyn Environment, path: &Path) -> Option<PathBuf> {
    let full = std::fs::canonicalize(path).ok()?;
    // Asked of `env`: `rapid mcp` looks nowhere outside its roots.
    let marks = |a: &Path| {
        [".git", "rapid.toml"]
            .iter()
            .any(|m| env.kind(&a.join(m)).is_ok())
    };
    let root = full.ancestors().find(|a| marks(a))?;
    // A home folder kept in git is no repository of RAPID programs.
    let home = std::env::var_os("HOME").and_then(|h| std::fs::canonicalize(h).ok());
    if home.as_deref() == Some(root) {
        return None;
    }
    if path.is_absolute() {
        return Some(root.to_path_buf());
    }
    let here = std::fs::canonicalize(".").ok()?;
    match root.strip_prefix(&here) {
        Ok(rel) if rel.as_os_str().is_empty() => Some(PathBuf::from(".")),
        Ok(rel) => Some(rel.to_path_buf()),
        Err(_) => Some(root.to_path_buf()),
    }
}

/// The task(s) of `found` to run ([`controller`]).
fn chosen(
    mut found: Found,
    path: &Path,
    only: Option<&str>,
    entry: Option<&str>,
) -> Result<Loaded, String> {
    let given = entry;
    let entry = entry.unwrap_or("main");
    without_home_files(&mut found, path);
    let mut together =
        found.tasks.len() > 1 && (one_backup(&found.tasks) || folder_of_tasks(path, &found.tasks));
    let lone = found.tasks.len() == 1;
    let system = found.systems.first().cloned().unwrap_or_default();
    let home = found.tasks.first().and_then(|t| home_of(&t.key));
    let per_task = match found.tasks.as_slice() {
        [one] if !one.is_backup() => super::multimove::per_task(one, entry),
        _ => None,
    };
    let mut out: Vec<TaskToRun> = match per_task {
        Some(tasks) => {
            together = true;
            tasks
        }
        None => found
            .tasks
            .iter()
            .zip(&found.settings)
            .map(|(t, s)| to_run(t, s.as_ref(), lone, entry))
            .collect(),
    };
    let notes = super::task_names::name_from_use(&mut out);
    if let Some(name) = only {
        let Some(i) = out.iter().position(|t| t.name.eq_ignore_ascii_case(name)) else {
            let names: Vec<&str> = out.iter().map(|t| t.name.as_str()).collect();
            return Err(format!(
                "{}: no task {name} (the tasks: {})",
                path.display(),
                names.join(", ")
            ));
        };
        let mut t = out.swap_remove(i);
        if let Some(e) = given {
            e.clone_into(&mut t.entry);
        }
        t.motion = true;
        return Ok(Loaded {
            tasks: vec![t],
            system,
            home,
            notes,
        });
    }
    if let Some(programs) = out
        .iter()
        .map(|t| alternatives(&t.task, &t.entry))
        .find(|p| !p.is_empty())
    {
        return Err(name_one_of(path, &programs));
    }
    if lone || together {
        return Ok(Loaded {
            tasks: out,
            system,
            home,
            notes,
        });
    }
    let with_entry: Vec<usize> = (0..out.len())
        .filter(|&i| declares(&out[i].task, entry))
        .collect();
    let chosen = match with_entry.as_slice() {
        [i] => Some(*i),
        // Several do: the folder's own modules are the task the folder
        // names (the others are named by their own folders or files).
        _ => {
            let given = path.to_string_lossy();
            let given = match given.trim_end_matches(['/', '\\']) {
                "." => "",
                g => g,
            };
            with_entry
                .iter()
                .copied()
                .find(|&i| out[i].task.key.trim_end_matches(['/', '\\']) == given)
        }
    };
    match chosen {
        Some(i) => {
            let mut t = out.swap_remove(i);
            t.name = "T_ROB1".to_owned();
            Ok(Loaded {
                tasks: vec![t],
                system,
                home,
                notes,
            })
        }
        None => {
            let keys: Vec<&str> = out.iter().map(|t| t.task.key.as_str()).collect();
            let why = several_backups(&keys).unwrap_or_else(|| several_tasks(&keys));
            Err(format!("{}: {why}", path.display()))
        }
    }
}

/// A task to run, as `SYS.cfg` says (`settings`): its name (`T_ROB1` for
/// the lone task outside a backup, else the folder's), kind, entry
/// routine (`entry` when `SYS.cfg` names none) and whether it moves a
/// robot.
pub fn to_run(
    t: &Arc<Task>,
    settings: Option<&TaskSettings>,
    lone: bool,
    entry: &str,
) -> TaskToRun {
    let name = match settings {
        Some(s) => s.name.clone(),
        None if lone && !t.is_backup() => "T_ROB1".to_owned(),
        None => folder_name(&t.key).to_owned(),
    };
    let entry = settings
        .and_then(|s| s.entry.clone())
        .unwrap_or_else(|| entry.to_owned());
    TaskToRun {
        name,
        task: at_start(t, &entry),
        kind: settings.map_or(TaskKind::Normal, |s| s.kind),
        entry,
        motion: settings.is_none_or(|s| s.motion),
        checked: None,
    }
}

/// The task as the controller has it when the program starts: without the
/// `HOME` modules its program loads while it runs (`Load`), which the
/// checker checks with it ([`Task::run_time_loads`]), unless the run
/// starts in one of them, or the rest of the program names what they
/// declare (then the controller has them from the start, as `SYS.cfg`
/// loads modules: the task without them would have more load errors).
pub fn at_start(t: &Arc<Task>, entry: &str) -> Arc<Task> {
    let later: Vec<usize> = t
        .run_time_loads()
        .into_iter()
        .filter(|&i| t.unit(i).is_none_or(|u| !unit_declares(u, entry)))
        .collect();
    if later.is_empty() {
        return t.clone();
    }
    let without = Arc::new(t.without_units(&later));
    let errors = |t: &Task| rapid_runtime::load_check(t).errors.len();
    if errors(&without) > errors(t) {
        return t.clone();
    }
    without
}

/// A backup's tasks without the modules of its `HOME` folder, which are
/// files on the controller's disk (the run's `HOME:`, from which a
/// program loads them), not tasks; a path in `HOME` (a program kept
/// there) keeps only what it holds.
fn without_home_files(found: &mut Found, path: &Path) {
    let first = |t: &Task| t.units.first().map(|u| u.path.clone());
    let in_home = |t: &Task| first(t).is_some_and(|p| rapid_analyzer::layout::in_home(&p));
    // A module given stands for its folder's program.
    let Ok(given) = std::fs::canonicalize(path) else {
        return;
    };
    let root = match given.parent() {
        Some(parent) if given.is_file() => parent.to_path_buf(),
        _ => given,
    };
    let keep: Vec<bool> = if rapid_analyzer::layout::in_home(&root.join("x.mod").to_string_lossy())
    {
        let under = |t: &Task| {
            first(t)
                .and_then(|p| std::fs::canonicalize(p).ok())
                .is_some_and(|p| p.starts_with(&root))
        };
        found.tasks.iter().map(|t| under(t)).collect()
    } else if found.tasks.iter().any(|t| t.is_backup()) {
        found.tasks.iter().map(|t| !in_home(t)).collect()
    } else {
        return;
    };
    if !keep.contains(&true) {
        return;
    }
    fn kept<T>(v: &mut Vec<T>, keep: &[bool]) {
        *v = std::mem::take(v)
            .into_iter()
            .zip(keep)
            .filter_map(|(x, k)| k.then_some(x))
            .collect();
    }
    kept(&mut found.tasks, &keep);
    kept(&mut found.settings, &keep);
    kept(&mut found.systems, &keep);
}

/// Are these the tasks of one controller's backup?
fn one_backup(tasks: &[Arc<Task>]) -> bool {
    let first = controller_of(&tasks[0].key);
    first.is_some() && tasks.iter().all(|t| controller_of(&t.key) == first)
}

/// Is `path` a folder whose subfolders are the tasks (`cell/T_ROB1`,
/// `cell/T_ROB2`)?
fn folder_of_tasks(path: &Path, tasks: &[Arc<Task>]) -> bool {
    let Ok(dir) = std::fs::canonicalize(path) else {
        return false;
    };
    tasks.iter().all(|t| {
        Path::new(&t.key)
            .parent()
            .and_then(|p| std::fs::canonicalize(p).ok())
            .is_some_and(|p| p == dir)
    })
}

/// Does `task` declare a routine named `routine`?
pub fn declares(task: &Task, routine: &str) -> bool {
    task.units.iter().any(|u| unit_declares(u, routine))
}

fn unit_declares(u: &Unit, routine: &str) -> bool {
    u.items.modules.iter().any(|m| {
        m.routines
            .iter()
            .any(|r| r.name.eq_ignore_ascii_case(routine))
    })
}

/// The alternative programs of a folder's task, as `rapid check` tells
/// them apart: each module that declares `entry` and cannot be loaded with
/// another of the folder's modules (two versions of one module, or two
/// programs with a `main`), as the view of the task that leaves out what
/// it clashes with. Empty when the task is one program (or a view already).
pub fn alternatives(task: &Arc<Task>, entry: &str) -> Vec<Arc<Task>> {
    let programs = views(task, |u| unit_declares(u, entry));
    if programs.len() < 2 {
        return Vec::new();
    }
    programs.into_iter().map(|(_, v)| v).collect()
}

/// The views of a folder's task for each of its modules that clash with
/// another (and that `keep` keeps), with the module's unit: what `rapid
/// check` checks apart. Empty when the task is one program (or a view).
pub fn views(task: &Arc<Task>, keep: impl Fn(&Unit) -> bool) -> Vec<(Arc<Unit>, Arc<Task>)> {
    if task.owner.is_some() || task.clashes.is_empty() {
        return Vec::new();
    }
    (0..task.units.len())
        .filter(|&i| task.clashes.any(i))
        .filter_map(|i| {
            let unit = task.unit(i).filter(|u| keep(u))?.clone();
            Some((unit, Arc::new(task.view(i))))
        })
        .collect()
}

/// The error for a folder whose tasks belong to several backups (a
/// repository of dated backups): a backup runs its tasks together, so the
/// run names one backup. `None` for tasks of one backup or of none.
fn several_backups(keys: &[&str]) -> Option<String> {
    let mut backups: Vec<&str> = keys
        .iter()
        .filter(|k| rapid_analyzer::layout::controller_of(k).is_some())
        .filter_map(|k| rapid_analyzer::layout::backup_root(k))
        .collect();
    backups.sort_unstable();
    backups.dedup();
    (backups.len() > 1).then(|| {
        let shown: Vec<&str> = backups.iter().take(5).copied().collect();
        format!(
            "the folder holds {} controller backups ({} tasks); name the backup to run (e.g. {})",
            backups.len(),
            keys.len(),
            shown.join(", ")
        )
    })
}

/// "the folder holds N tasks; name one of them (e.g. ...)": the first
/// tasks' keys, which are the paths to give (the folder or program file as
/// the command line names it; empty for the current folder, shown `.`).
pub(crate) fn several_tasks(keys: &[&str]) -> String {
    let shown: Vec<&str> = keys
        .iter()
        .take(5)
        .map(|k| if k.is_empty() { "." } else { k })
        .collect();
    format!(
        "the folder holds {} tasks; name one of them (e.g. {})",
        keys.len(),
        shown.join(", ")
    )
}

/// The error for a folder of alternative programs run without naming one.
fn name_one_of(path: &Path, programs: &[Arc<Task>]) -> String {
    let paths: Vec<String> = programs
        .iter()
        .filter_map(|v| Some(v.unit(v.owner?)?.path.clone()))
        .collect();
    format!(
        "{}: the folder holds {} alternative programs (modules that cannot be loaded together); name the module to run: {}",
        path.display(),
        paths.len(),
        paths.join(", ")
    )
}

/// `task` with more modules (given as path and text), unless it declares
/// a routine of theirs already: the same controller's task (configuration,
/// catalogue view, controller names), as `rapid check` checks it, with the
/// modules added ([`Task::with_extra_units`]).
pub fn with_modules(task: &Arc<Task>, modules: &[(&str, &str)]) -> Arc<Task> {
    let mut extra = Vec::new();
    for (path, text) in modules {
        let unit = Unit::new((*path).to_owned(), (*text).to_owned(), None);
        let clash = unit
            .items
            .modules
            .iter()
            .flat_map(|m| m.routines.iter())
            .any(|r| declares(task, &r.name));
        if !clash {
            extra.push(Arc::new(unit));
        }
    }
    if extra.is_empty() {
        return task.clone();
    }
    Arc::new(task.with_extra_units(extra))
}

/// A `--set NAME=VALUE[@SECONDS]` option.
pub fn parse_set(text: &str) -> Result<SignalChange, String> {
    let (name, rest) = text
        .split_once('=')
        .ok_or_else(|| format!("--set {text}: expected NAME=VALUE or NAME=VALUE@SECONDS"))?;
    let (value, at) = rest.split_once('@').unwrap_or((rest, "0"));
    let value: f64 = value
        .trim()
        .parse()
        .map_err(|_| format!("--set {text}: {value:?} is not a number"))?;
    let at: f64 = at
        .trim()
        .parse()
        .ok()
        .filter(|t: &f64| *t >= 0.0 && t.is_finite())
        .ok_or_else(|| format!("--set {text}: {at:?} is not a time in seconds"))?;
    let name = name.trim();
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(format!("--set {text}: {name:?} is not a signal name"));
    }
    Ok(SignalChange {
        name: name.to_owned(),
        value,
        at,
    })
}

/// The program of `task`, with the signals and mechanical units taken
/// from their use (`check`, [`rapid_runtime::load_check`]) and the signals `--set` names
/// that neither its configuration declares nor its use shows (their kind
/// guessed from the name's first letters: `di`, `do`, `ai`, `ao`, `gi`,
/// `go`; a digital input otherwise).
pub fn program(
    task: Arc<Task>,
    sets: &[SignalChange],
    check: &rapid_runtime::LoadCheck,
) -> Arc<Program> {
    let task = check.with_units(task);
    let taken = check.extra_signals();
    let configured = |n: &str| {
        task.signals
            .as_ref()
            .is_some_and(|s| s.contains_key(&n.to_ascii_lowercase()))
    };
    let mut extra: Vec<(String, SignalKind)> = taken;
    for s in sets {
        if !configured(&s.name) && !extra.iter().any(|(n, _)| n.eq_ignore_ascii_case(&s.name)) {
            extra.push((s.name.clone(), SignalKind::guess(&s.name)));
        }
    }
    Arc::new(Program::new(task, &extra))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_controller_s_home_is_the_backup_s_or_the_one_around_never_slash_home() {
        let dir = std::env::temp_dir().join(format!("rapid-home-of-{}", std::process::id()));
        for d in [
            "Cell/RAPID/TASK1",
            "Cell/HOME",
            "proj/HOME/parts",
            "home/user/prog",
        ] {
            std::fs::create_dir_all(dir.join(d)).expect("a folder");
        }
        let key = |p: &str| dir.join(p).to_string_lossy().into_owned();
        assert_eq!(
            home_of(&key("Cell/RAPID/TASK1")),
            Some(dir.join("Cell/HOME"))
        );
        assert_eq!(
            home_of(&key("proj/HOME/parts")),
            Some(dir.join("proj/HOME"))
        );
        // A Unix system's `/home` is no controller's.
        assert_eq!(home_of(&key("home/user/prog")), None);
        // A server confined to a folder inside the HOME gets none.
        let inner = [dir.join("proj/HOME/parts")];
        assert_eq!(home_within(&key("proj/HOME/parts"), Some(&inner)), None);
        let outer = [dir.join("proj")];
        assert_eq!(
            home_within(&key("proj/HOME/parts"), Some(&outer)),
            Some(dir.join("proj/HOME"))
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn set_options_parse_or_say_what_is_wrong() {
        let s = parse_set("di1=1@2.5").expect("valid");
        assert_eq!((s.name.as_str(), s.value, s.at), ("di1", 1.0, 2.5));
        assert_eq!(parse_set("go_code=12").expect("valid").at, 0.0);
        assert!(
            parse_set("di1")
                .expect_err("invalid")
                .contains("NAME=VALUE")
        );
        assert!(
            parse_set("di1=x")
                .expect_err("invalid")
                .contains("not a number")
        );
        assert!(
            parse_set("di1=1@-2")
                .expect_err("invalid")
                .contains("seconds")
        );
        assert!(
            parse_set("a b=1")
                .expect_err("invalid")
                .contains("signal name")
        );
    }
}
