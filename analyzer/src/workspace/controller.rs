//! What the configuration says of each task: the controller's version and
//! options, its `SYSPAR` files and `SYS.cfg` tasks, the robot, signals and
//! mechanical units, and what the tasks of one controller share.

use std::collections::{BTreeMap, HashSet};
use std::sync::Arc;

use super::{Workspace, home, under};
use crate::controller::ControllerInfo;
use crate::task::{SharedMap, Signals, Unit, controller_of, shared_persistents};

impl Workspace {
    /// What the backups and the project configuration say about the
    /// controller of the task `key`.
    pub fn controller_of_task(&self, key: &str) -> ControllerInfo {
        let mut info = ControllerInfo::default();
        for (path, system) in &self.systems {
            if config_applies(path, key) {
                info.merge(system);
            }
        }
        let sel = info.selection(&self.controller);
        ControllerInfo {
            robotware: sel.robotware,
            options: sel.options().to_vec(),
            system_name: info.system_name,
            robotware_text: info
                .robotware_text
                .filter(|_| self.controller.robotware.is_none()),
            tasks: info.tasks,
        }
    }

    /// The task names of backup `root` by task number (`RAPID/TASKn` is
    /// the *n*-th), one list per file that names them: each `SYS.cfg`'s
    /// `CAB_TASKS`, else what `BACKINFO` names (a backup kept without its
    /// `SYSPAR`), else the project configuration's `tasks`.
    pub(super) fn task_lists(&self, root: &str) -> Vec<Vec<Option<String>>> {
        let configured: Vec<Vec<Option<String>>> = self
            .configs
            .iter()
            .filter(|(p, c)| home::syspar_root(p) == Some(root) && !c.tasks.is_empty())
            .map(|(_, c)| c.tasks.iter().cloned().map(Some).collect())
            .collect();
        if !configured.is_empty() {
            return configured;
        }
        let mut out: Vec<Option<String>> = Vec::new();
        for (path, system) in &self.systems {
            if home::backinfo_root(path) != Some(root) {
                continue;
            }
            for (n, name) in &system.tasks {
                if out.len() < *n {
                    out.resize(*n, None);
                }
                if let Some(slot) = out.get_mut(n - 1) {
                    slot.get_or_insert_with(|| name.clone());
                }
            }
        }
        if !out.is_empty() {
            return vec![out];
        }
        match &self.controller.tasks {
            Some(names) if !names.is_empty() => vec![names.iter().cloned().map(Some).collect()],
            _ => Vec::new(),
        }
    }

    /// [`Workspace::task_lists`] one after the other.
    pub(super) fn task_list(&self, root: &str) -> Vec<Option<String>> {
        self.task_lists(root).concat()
    }

    /// What the tasks of `controller` (a backup's `RAPID/` folder) share:
    /// their persistents and their synchronisation points. Only this
    /// controller's tasks: not a backup kept in one of its folders.
    pub(super) fn controller_data(&self, controller: &str) -> Controller {
        let mut by_task: BTreeMap<String, Vec<&Arc<Unit>>> = BTreeMap::new();
        for u in self.units.values().filter(|u| under(&u.path, controller)) {
            let key = crate::layout::task_key(&u.path);
            if controller_of(&key) == Some(controller) {
                by_task.entry(key).or_default().push(u);
            }
        }
        let (map, shared_hash) =
            shared_persistents(by_task.values().flatten().copied().chain(&self.extras));
        let names = crate::layout::backup_root(controller)
            .map(|root| self.task_names_of(root))
            .unwrap_or_default();
        let mut syncs = crate::sema::sync::ControllerSyncs::default();
        for (key, units) in &by_task {
            let mut own: Vec<String> = names
                .iter()
                .filter(|(_, k)| *k == key)
                .map(|(n, _)| n.clone())
                .collect();
            own.sort();
            let mut task = crate::sema::sync::task_syncs(units.iter().copied());
            task.complete = self.is_complete(key);
            syncs.tasks.push((key.clone(), own, task));
        }
        let syncs_hash = crate::items::hash_of(&syncs);
        Controller {
            shared: Arc::new(map),
            shared_hash,
            syncs: Arc::new(syncs),
            syncs_hash,
        }
    }

    /// The configuration files that apply to the task `key` (its backup's
    /// `SYSPAR/*.cfg`, or those above it), each with its path, in path
    /// order.
    pub fn config_files_of_task(&self, key: &str) -> Vec<(String, Arc<crate::cfg::CfgFile>)> {
        self.cfg_files
            .iter()
            .filter(|(p, _)| config_applies(p, key))
            .map(|(p, f)| (p.clone(), f.clone()))
            .collect()
    }

    /// How the controller of the backup task `key` runs its tasks: the
    /// `CAB_TASKS` of the backup's `SYS.cfg`, in order (task *n* is kept
    /// in `RAPID/TASKn`). Empty outside a backup or without a `SYS.cfg`.
    pub fn controller_tasks(&self, key: &str) -> Vec<crate::task::TaskSettings> {
        if crate::layout::controller_of(key).is_none() {
            return Vec::new();
        }
        let Some(root) = crate::layout::backup_root(key) else {
            return Vec::new();
        };
        let configured: Vec<crate::task::TaskSettings> = self
            .configs
            .iter()
            .filter(|(p, _)| home::syspar_root(p) == Some(root))
            .flat_map(|(_, c)| c.task_settings.iter().cloned())
            .collect();
        if !configured.is_empty() {
            return configured;
        }
        // Named by BACKINFO only: how each task runs is not known (a
        // NORMAL motion task, as without any configuration).
        let named = self.task_list(root);
        if named.iter().all(Option::is_none) {
            return Vec::new();
        }
        named
            .into_iter()
            .enumerate()
            .map(|(i, name)| crate::task::TaskSettings {
                name: name.unwrap_or_else(|| format!("TASK{}", i + 1)),
                kind: crate::task::TaskKind::Normal,
                entry: None,
                motion: true,
                unit_group: None,
            })
            .collect()
    }

    /// The `taskid` data of the controller a backup task `key` belongs to
    /// (folded `<task name>id`): its `SYS.cfg` tasks, and its task folders
    /// named after a task (`T_ROB1`; `TASKn` folders are numbered, not
    /// named). Empty for a task outside a backup.
    pub(super) fn task_ids_for(&self, key: &str) -> HashSet<String> {
        let mut ids = HashSet::new();
        if crate::layout::controller_of(key).is_none() {
            return ids;
        }
        let Some(root) = crate::layout::backup_root(key) else {
            return ids;
        };
        let mut names: Vec<String> = self.task_list(root).into_iter().flatten().collect();
        names.extend(self.backup_task_keys(root).iter().filter_map(|k| {
            let last = k.rsplit('/').next()?;
            let numbered = crate::layout::task_folder_number(last).is_some();
            (!numbered).then(|| last.to_owned())
        }));
        for name in names {
            ids.insert(crate::names::fold(&format!("{name}Id")));
        }
        ids
    }

    /// The robot of a task: the `MOC.cfg` robots that apply to it (its
    /// backup's or the extra paths'), else the project's setting.
    pub(super) fn robot_for(
        &self,
        key: &str,
    ) -> Result<Option<Arc<crate::robot::TaskRobot>>, String> {
        let by_place = self
            .configs
            .iter()
            .filter(|(path, _)| config_applies(path, key))
            .map(|(_, config)| config);
        let mocs: Vec<&crate::robot::MocRobot> = self
            .extra_configs
            .iter()
            .chain(by_place)
            .flat_map(|c| &c.robots)
            .collect();
        let settings = self.task_settings(key);
        let task = crate::robot::RobotOf {
            key,
            name: settings.as_ref().map(|s| s.name.as_str()),
            group: settings.as_ref().and_then(|s| s.unit_group.as_deref()),
        };
        crate::robot::resolve(task, &mocs, self.controller.robot.as_ref())
    }

    /// The `SYS.cfg` entry of the backup task kept in folder `key`
    /// ([`settings_by_folder`] of [`Workspace::controller_tasks`]).
    pub fn task_settings(&self, key: &str) -> Option<crate::task::TaskSettings> {
        settings_by_folder(key, &self.controller_tasks(key))
    }

    /// The configuration that applies to a task: its signals (`None` when
    /// no configuration declares signals) and its mechanical units.
    pub(super) fn config_for(&self, key: &str) -> (Option<Signals>, HashSet<String>) {
        let mut signals: Option<Signals> = None;
        let mut mecunits = HashSet::new();
        let by_place = self
            .configs
            .iter()
            .filter(|(path, _)| config_applies(path, key))
            .map(|(_, config)| config);
        for config in self.extra_configs.iter().chain(by_place) {
            if let Some(s) = &config.signals {
                signals
                    .get_or_insert_with(Signals::new)
                    .extend(s.iter().map(|(k, v)| (k.clone(), *v)));
            }
            mecunits.extend(config.mecunits.iter().cloned());
        }
        (signals, mecunits)
    }
}

/// The `SYS.cfg` entry of the task kept in folder `key`: task *n* for
/// `RAPID/TASKn`, else the entry named as the folder.
pub fn settings_by_folder(
    key: &str,
    all: &[crate::task::TaskSettings],
) -> Option<crate::task::TaskSettings> {
    let folder = key.rsplit(['/', '\\']).next().unwrap_or(key);
    let numbered = folder
        .get(..4)
        .filter(|h| h.eq_ignore_ascii_case("task"))
        .and_then(|_| folder.get(4..)?.parse::<usize>().ok());
    match numbered {
        Some(n) => all.get(n.checked_sub(1)?).cloned(),
        None => all
            .iter()
            .find(|t| t.name.eq_ignore_ascii_case(folder))
            .cloned(),
    }
}

/// What the tasks of one controller share ([`Workspace::controller_data`]).
#[derive(Clone)]
pub(super) struct Controller {
    pub(super) shared: Arc<SharedMap>,
    pub(super) shared_hash: u64,
    pub(super) syncs: Arc<crate::sema::sync::ControllerSyncs>,
    pub(super) syncs_hash: u64,
}

/// Does the configuration file `path` (`SYSPAR/*.cfg`, `BACKINFO/...`, or
/// one elsewhere) apply to the task `key`? A backup's configuration applies
/// to its own tasks (the `HOME/` modules' too), never to another backup's,
/// not even one kept inside it; a configuration elsewhere applies to the
/// tasks below its folder, but not to a backup below it, which a controller
/// configured with its own. A `SYSPAR/` (or `BACKINFO/`) folder beside
/// modules outside a backup is their controller's: it applies to the
/// modules of its folder.
pub fn config_applies(path: &str, key: &str) -> bool {
    let backup = crate::layout::backup_root(key);
    if let Some(root) = home::syspar_root(path).or_else(|| home::backinfo_root(path)) {
        return match backup {
            Some(b) => b == root,
            None => crate::layout::is_within(key, root) && crate::layout::is_within(root, key),
        };
    }
    let root = config_root(path);
    crate::layout::is_within(key, root)
        && backup.is_none_or(|b| !crate::layout::is_within(b, root) || b.len() <= root.len())
}

/// The folder an I/O configuration applies below: a backup's root for
/// `.../SYSPAR/EIO.cfg`, else the file's own folder ([`config_applies`]
/// decides which tasks below it).
pub fn config_root(path: &str) -> &str {
    let dir = path.rsplit_once(['/', '\\']).map_or("", |(d, _)| d);
    match dir.rsplit_once(['/', '\\']) {
        Some((parent, last))
            if last.eq_ignore_ascii_case("syspar") || last.eq_ignore_ascii_case("backinfo") =>
        {
            parent
        }
        None if dir.eq_ignore_ascii_case("syspar") || dir.eq_ignore_ascii_case("backinfo") => "",
        _ => dir,
    }
}
