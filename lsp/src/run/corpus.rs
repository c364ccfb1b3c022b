//! How `rapid run` fares on the corpus of real programs
//! (`../shared/corpus`, or `RAPID_CORPUS`): every controller backup runs
//! with all its tasks together (as `rapid run BACKUP`), every other task
//! alone from its `main` (as `rapid run FOLDER`; each of a folder's
//! alternative programs alone, as `rapid run MODULE`), with no operator
//! answers, the simulated network and the corpus test's budgets; each
//! task's end is classified. The figures, the classes, the instructions
//! that stop runs and every call a run would stop at (reached or not) are
//! generated into `docs/corpus-runs.md`, which the test checks
//! (`RAPID_BLESS=1` rewrites it).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use rapid_analyzer::layout::controller_of;
use rapid_analyzer::task::Task;
use rapid_runtime::{Limits, Outcome, Status};

use super::load::{self, Loaded};
use super::{NotRun, RunOptions, execute, multimove};

/// How a task's run ended, in the words of the classification.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Class {
    /// Its end, `EXIT`, `Stop`.
    Ended,
    /// Waiting for an input nothing changes, or for the operator.
    Idle,
    /// The step or time budget ran out (an endless main loop).
    Budget,
    /// An instruction the simulation does not have.
    Unsupported,
    /// A RAPID error no handler took.
    Error,
    /// The program cannot run as written.
    Invalid,
    /// The controller would not load it (its errors), or would not link
    /// it: it uses a name declared nowhere (a module missing from the
    /// repository).
    Refused,
    /// No entry routine: nothing to run.
    NoEntry,
}

impl Class {
    fn of(o: &Outcome) -> Class {
        match o.status {
            Status::Finished | Status::Exited | Status::Stopped | Status::Halted => Class::Ended,
            Status::Deadlock | Status::Operator => Class::Idle,
            Status::Budget => Class::Budget,
            Status::Unsupported => Class::Unsupported,
            Status::Error => Class::Error,
            Status::Invalid if o.message.contains(rapid_runtime::DECLARED_NOWHERE) => {
                Class::Refused
            }
            Status::Invalid => Class::Invalid,
        }
    }

    fn describe(self) -> &'static str {
        match self {
            Class::Ended => "ended (its end, EXIT, Stop)",
            Class::Idle => "waits idle (an input nothing changes, the operator)",
            Class::Budget => "loops until the budget",
            Class::Unsupported => "stopped on an unsupported instruction",
            Class::Error => "an unhandled RAPID error",
            Class::Invalid => "cannot run as written",
            Class::Refused => "refused: load errors, or a name declared nowhere",
            Class::NoEntry => "no entry routine (not counted)",
        }
    }

    fn good(self) -> bool {
        matches!(self, Class::Ended | Class::Idle | Class::Budget)
    }
}

/// One task's run.
pub struct TaskRun {
    pub key: String,
    pub backup: bool,
    pub class: Class,
    /// The unsupported instruction, the error, the message.
    pub detail: String,
    /// The calls of the task the simulation does not support (where a
    /// run would stop, as `rapid run --list-unsupported` lists them): the
    /// name and its place (`path:line:column`).
    pub unsupported: Vec<(String, String)>,
}

/// A task of a run, before it runs: its name, its key on the page,
/// whether it is a backup's, and its unsupported calls.
type Member = (String, String, bool, Vec<(String, String)>);

fn options() -> RunOptions {
    RunOptions {
        sets: Vec::new(),
        limits: Limits {
            max_steps: 100_000,
            max_time: 300.0,
            max_depth: 200,
            ..Limits::default()
        },
        sandbox: None,
        trace: false,
        operator: super::operator::OperatorOptions::default(),
        socket_map: None,
        robot: None,
    }
}

/// Runs every task of the corpus at `dir`.
pub fn sweep(dir: &Path) -> Result<Vec<TaskRun>, String> {
    let found = load::tasks(&[dir.to_path_buf()])?;
    // Each run: its tasks (an index into `found`, the task itself and the
    // name a folder of per-task programs gives it: a folder of alternative
    // programs runs each program alone, one of per-task programs runs them
    // together).
    type Program = (usize, Arc<Task>, Option<String>);
    let mut groups: BTreeMap<String, Vec<Program>> = BTreeMap::new();
    for (i, t) in found.tasks.iter().enumerate() {
        if let Some(programs) = multimove::programs(t, "main") {
            let group = groups.entry(t.key.clone()).or_default();
            group.extend(
                programs
                    .into_iter()
                    .map(|(view, name)| (i, view, Some(name))),
            );
            continue;
        }
        let programs = load::alternatives(t, "main");
        if programs.is_empty() {
            let group = controller_of(&t.key).map_or_else(|| t.key.clone(), |c| c.to_string());
            groups.entry(group).or_default().push((i, t.clone(), None));
        }
        for view in programs {
            let key = view
                .owner
                .and_then(|o| view.unit(o))
                .map_or_else(|| t.key.clone(), |u| u.path.clone());
            groups.entry(key).or_default().push((i, view, None));
        }
    }
    let mut opts = options();
    let mut out = Vec::new();
    for members in groups.values() {
        let lone = members.len() == 1;
        let mut notes = Vec::new();
        let mut tasks: Vec<_> = members
            .iter()
            .map(|(i, t, name)| {
                let mut run = load::to_run(t, found.settings[*i].as_ref(), lone, "main");
                if let Some(name) = name {
                    name.clone_into(&mut run.name);
                }
                // The modules it lacks, from its repository (the corpus's
                // top folders).
                let repository = repository_of(&t.key, dir);
                let pool: Vec<Arc<Task>> = found
                    .tasks
                    .iter()
                    .filter(|o| repository_of(&o.key, dir) == repository)
                    .cloned()
                    .collect();
                let done = super::missing::complete(&run.task, &pool, &run.entry);
                run.checked = Some((done.task.clone(), done.check));
                run.task = done.task;
                notes.extend(done.notes);
                run
            })
            .collect();
        notes.extend(super::task_names::name_from_use(&mut tasks));
        let names: Vec<Member> = tasks
            .iter()
            .map(|t| {
                let key = match t.task.owner.and_then(|o| t.task.unit(o)) {
                    Some(unit) => &unit.path,
                    None => &t.task.key,
                };
                let check = t.load_check();
                let calls = load::program(t.task.clone(), &[], &check)
                    .unsupported()
                    .into_iter()
                    .map(|(name, at)| (name, format!("{}:{}:{}", at.path, at.line, at.column)))
                    .collect();
                (t.name.clone(), key.clone(), t.task.is_backup(), calls)
            })
            .collect();
        let system = found.systems[members[0].0].clone();
        let home = load::home_of(&found.tasks[members[0].0].key);
        let sandbox = super::Sandbox::seeded(None, home.as_deref())?;
        opts.sandbox = Some(sandbox.path.clone());
        let loaded = Loaded {
            tasks,
            system,
            home,
            notes,
        };
        let result = execute(&loaded, &opts, Box::new(|_, _: &str| {}));
        for (name, key, backup, unsupported) in names {
            let (class, detail) = match &result {
                Err(NotRun::LoadErrors(e)) => {
                    (Class::Refused, e.first().cloned().unwrap_or_default())
                }
                Err(NotRun::Other(m)) => (Class::NoEntry, m.clone()),
                Ok(report) => match report.tasks.iter().find(|(n, _)| *n == name) {
                    Some((_, o)) => (Class::of(o), o.message.clone()),
                    None => (Class::NoEntry, String::new()),
                },
            };
            out.push(TaskRun {
                key,
                backup,
                class,
                detail,
                unsupported,
            });
        }
    }
    Ok(out)
}

/// The repository of the corpus at `dir` that the task `key` is in: the
/// corpus's first folder on its path (`owner__repo`).
fn repository_of<'k>(key: &'k str, dir: &Path) -> &'k str {
    let dir = dir.to_string_lossy();
    let rest = key.strip_prefix(dir.as_ref()).unwrap_or(key);
    rest.trim_start_matches(['/', '\\'])
        .split(['/', '\\'])
        .next()
        .unwrap_or_default()
}

/// The generated page.
pub fn page(runs: &[TaskRun]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Corpus runs\n");
    let _ = writeln!(
        s,
        "<!-- Generated by `RAPID_BLESS=1 cargo test -p rapid-lsp --bin rapid corpus_runs`. Do not edit. -->\n"
    );
    let _ = writeln!(
        s,
        "`rapid run` over `../shared/corpus` (real RAPID programs from public repositories, test input only): every controller backup with all its tasks together, every other task (grouped as `rapid check` groups them) alone from its `main`; a folder of alternative programs (modules that cannot be loaded together, each with a `main`) runs each program alone, as `rapid run MODULE` runs it, and a folder of per-task programs (`Grey_T_ROB1.mod`, `Grey_T_ROB2.mod`, naming each other's tasks) runs them together, as `rapid run FOLDER` does. No operator answers (a question stops the task waiting for the operator), a network where nobody answers, at most 100,000 statements and 300 simulated seconds a run. As `rapid run` does, a task that uses a name none of its modules declares takes the nearest module of its repository (here the corpus's `owner__repo` folder) that declares it, and a backup kept without `SYS.cfg` and `BACKINFO` names its numbered tasks for the names its program uses (`T_ROBn` is `TASKn`); each is a note of the run. A task without an entry routine (a library of modules) has nothing to run and is not counted.\n"
    );
    // The controller backups' tasks, the other tasks, all.
    let groups: [fn(&TaskRun) -> bool; 3] = [|r| r.backup, |r| !r.backup, |_| true];
    let _ = writeln!(
        s,
        "| class | controller backups' tasks | other tasks | all tasks |\n| --- | ---: | ---: | ---: |"
    );
    let classes = [
        Class::Ended,
        Class::Idle,
        Class::Budget,
        Class::Unsupported,
        Class::Error,
        Class::Invalid,
        Class::Refused,
        Class::NoEntry,
    ];
    for c in classes {
        let counts: Vec<String> = groups
            .iter()
            .map(|f| {
                runs.iter()
                    .filter(|r| f(r) && r.class == c)
                    .count()
                    .to_string()
            })
            .collect();
        let _ = writeln!(s, "| {} | {} |", c.describe(), counts.join(" | "));
    }
    let shares: Vec<String> = groups
        .iter()
        .map(|f| {
            let counted: Vec<&TaskRun> = runs
                .iter()
                .filter(|r| f(r) && r.class != Class::NoEntry)
                .collect();
            let good = counted.iter().filter(|r| r.class.good()).count();
            format!(
                "{good} of {} ({}%)",
                counted.len(),
                percent(good, counted.len())
            )
        })
        .collect();
    let _ = writeln!(
        s,
        "| **ended, idle or budget** | **{}** |\n",
        shares.join("** | **")
    );
    let _ = writeln!(
        s,
        "The targets: four in five among the controller backups' tasks, two in three overall.\n"
    );
    let mut stops: BTreeMap<String, usize> = BTreeMap::new();
    for r in runs.iter().filter(|r| r.class == Class::Unsupported) {
        let name = r
            .detail
            .trim_start_matches("not supported in simulation: ")
            .split([' ', '('])
            .next()
            .unwrap_or_default()
            .to_owned();
        *stops.entry(name).or_default() += 1;
    }
    let mut stops: Vec<_> = stops.into_iter().collect();
    stops.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    let _ = writeln!(
        s,
        "## Instructions that stop runs\n\n| instruction or function | tasks |\n| --- | ---: |"
    );
    for (name, n) in stops {
        let _ = writeln!(s, "| `{name}` | {n} |");
    }
    unsupported_calls(&mut s, runs);
    let _ = writeln!(s, "\n## Every task\n");
    let _ = writeln!(
        s,
        "| task | backup | class | detail |\n| --- | --- | --- | --- |"
    );
    for r in runs {
        let detail = r
            .detail
            .lines()
            .next()
            .unwrap_or_default()
            .replace('|', "\\|");
        let backup = if r.backup { "yes" } else { "" };
        let _ = writeln!(s, "| `{}` | {backup} | {:?} | {detail} |", r.key, r.class);
    }
    s
}

/// Every call the simulation does not support, in any task (reached or
/// not): by name, its call sites (each counted once, though several
/// tasks or programs share its module) and the tasks that hold one.
fn unsupported_calls(s: &mut String, runs: &[TaskRun]) {
    let mut by_name: BTreeMap<&str, (std::collections::BTreeSet<&str>, usize)> = BTreeMap::new();
    for r in runs {
        let mut names: Vec<&str> = Vec::new();
        for (name, at) in &r.unsupported {
            by_name.entry(name).or_default().0.insert(at);
            if !names.contains(&name.as_str()) {
                names.push(name);
            }
        }
        for name in names {
            by_name.entry(name).or_default().1 += 1;
        }
    }
    let mut rows: Vec<(&str, usize, usize)> = by_name
        .into_iter()
        .map(|(name, (sites, tasks))| (name, sites.len(), tasks))
        .collect();
    rows.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(b.0)));
    let sites: usize = rows.iter().map(|r| r.1).sum();
    let _ = writeln!(
        s,
        "\n## Calls the simulation does not support\n\nEvery call a run would stop at, reached or not (`rapid run --list-unsupported`): {sites} call sites of {} instructions and functions.\n\n| instruction or function | call sites | tasks |\n| --- | ---: | ---: |",
        rows.len()
    );
    for (name, n, tasks) in rows {
        let _ = writeln!(s, "| `{name}` | {n} | {tasks} |");
    }
}

fn percent(a: usize, b: usize) -> usize {
    (a * 100).checked_div(b).unwrap_or(0)
}

/// The corpus folder: `RAPID_CORPUS`, else `../shared/corpus` beside the
/// repository.
pub fn corpus_dir() -> Option<PathBuf> {
    if let Some(dir) = std::env::var_os("RAPID_CORPUS") {
        return std::fs::canonicalize(dir).ok().filter(|d| d.is_dir());
    }
    // Resolved: the runs' paths are the loader's (no `..`), and the page
    // shows them relative to this folder.
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus");
    std::fs::canonicalize(dir).ok().filter(|d| d.is_dir())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corpus_runs_are_classified_as_docs_corpus_runs_says() {
        let Some(dir) = corpus_dir() else {
            return;
        };
        let runs = sweep(&dir).expect("the corpus loads");
        let relative: Vec<TaskRun> = runs
            .into_iter()
            .map(|r| TaskRun {
                key: Path::new(&r.key)
                    .strip_prefix(&dir)
                    .map_or(r.key.clone(), |p| p.to_string_lossy().into_owned()),
                detail: r.detail.replace(&*dir.to_string_lossy(), ""),
                unsupported: r
                    .unsupported
                    .iter()
                    .map(|(n, at)| (n.clone(), at.replace(&*dir.to_string_lossy(), "")))
                    .collect(),
                ..r
            })
            .collect();
        let text = page(&relative);
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/corpus-runs.md");
        if std::env::var_os("RAPID_BLESS").is_some() {
            std::fs::write(&path, &text).expect("written");
            return;
        }
        let old = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            old == text,
            "docs/corpus-runs.md is stale: RAPID_BLESS=1 cargo test -p rapid-lsp --bin rapid corpus_runs"
        );
    }
}
