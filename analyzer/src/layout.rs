//! Where a module file sits, and what that says about the task it belongs
//! to: a controller backup's task folders, `.pgf` programs (in the
//! workspace), or a plain folder.
//!
//! A backup (or a program saved from RobotStudio) keeps each task under
//! `RAPID/`: `RAPID/TASK1/PROGMOD/Main.mod` (RobotWare 5 and 6),
//! `RAPID/T_ROB1/...` (task names, with any folders below them), or, for a
//! system with one task, `RAPID/PROGMOD/...`. Anywhere else the modules of
//! one folder are taken to form one task, which is only a guess.

/// How the modules of a task were grouped: this decides how sure the
/// checker may be that they are loaded together.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Grouping {
    /// A task folder of a controller backup's `RAPID/` folder: its modules
    /// were loaded together by a real controller.
    Backup,
    /// The modules a `.pgf` program file lists.
    Program,
    /// The modules of one plain folder: maybe one program, maybe several
    /// versions of one, maybe unrelated.
    Folder,
}

/// The task a file belongs to by its place: the key (a folder path, `/`
/// separated) and how it was found.
pub fn locate(path: &str) -> (String, Grouping) {
    let normal = path.replace('\\', "/");
    let parts: Vec<&str> = normal.split('/').collect();
    // Folders only (the last part is the file), innermost first.
    let folders = parts.len().saturating_sub(1);
    for i in (1..folders).rev() {
        if !parts[i - 1].eq_ignore_ascii_case("rapid") {
            continue;
        }
        let dir = parts[i];
        if is_module_folder(dir) {
            // `RAPID/PROGMOD/...`: the system's only task.
            return (parts[..i].join("/"), Grouping::Backup);
        }
        let child_is_module_folder = i + 1 < folders && is_module_folder(parts[i + 1]);
        if is_task_name(dir) || child_is_module_folder {
            return (parts[..=i].join("/"), Grouping::Backup);
        }
    }
    let key = match normal.rsplit_once('/') {
        Some((dir, _)) => dir.to_owned(),
        None => String::new(),
    };
    (key, Grouping::Folder)
}

/// The key of the task a file belongs to by its place ([`locate`]).
pub fn task_key(path: &str) -> String {
    locate(path).0
}

/// `PROGMOD` or `SYSMOD`, the folders a backup keeps a task's modules in.
fn is_module_folder(name: &str) -> bool {
    name.eq_ignore_ascii_case("progmod") || name.eq_ignore_ascii_case("sysmod")
}

/// A task folder's name as controllers write them: `TASK1` (RobotWare 5 and
/// 6 number them) or a task name in the `T_ROB1` style.
fn is_task_name(name: &str) -> bool {
    let numbered = name
        .get(..4)
        .zip(name.get(4..))
        .is_some_and(|(head, digits)| {
            head.eq_ignore_ascii_case("task")
                && !digits.is_empty()
                && digits.bytes().all(|b| b.is_ascii_digit())
        });
    let named = name
        .get(..2)
        .is_some_and(|head| head.eq_ignore_ascii_case("t_") && name.len() > 2);
    numbered || named
}

/// The number of a backup's numbered task folder (`TASK7`: 7), which
/// names no task: `SYS.cfg` says which task it holds.
pub fn task_folder_number(name: &str) -> Option<u32> {
    let digits = name
        .get(..4)?
        .eq_ignore_ascii_case("task")
        .then(|| &name[4..])?;
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

/// The controller a task of a backup belongs to: for a key that
/// [`locate`] gives a task folder under `RAPID/`, the key up to and
/// including `RAPID/`; `None` for any other key.
pub fn controller_of(key: &str) -> Option<&str> {
    let (parent, last) = key.rsplit_once('/')?;
    let rapid = parent.rsplit('/').next()?;
    (rapid.eq_ignore_ascii_case("rapid") && !is_module_folder(last)).then(|| &key[..=parent.len()])
}

/// The backup folder (the one holding `RAPID/`, `HOME/`, `SYSPAR/`) of a
/// task key of a backup, or of a path inside a backup's `HOME/`: the path
/// before its innermost `RAPID` or `HOME` folder.
pub fn backup_root(path: &str) -> Option<&str> {
    let normal = path.replace('\\', "/");
    let parts: Vec<&str> = normal.split('/').collect();
    let at = (0..parts.len())
        .rev()
        .find(|&i| parts[i].eq_ignore_ascii_case("rapid") || is_controller_home(&parts, i))?;
    // `\` and `/` are one byte each: offsets in `normal` are offsets in `path`.
    let end = parts[..at].iter().map(|p| p.len() + 1).sum::<usize>();
    path.get(..end.saturating_sub(1))
}

/// Is this file inside a backup's `HOME/` folder (the controller's file
/// area, from which programs load modules at run time)? A backup kept
/// inside another's `HOME/` is a backup of its own: its `RAPID/` is not in
/// that `HOME/` ([`home_root`]).
pub fn in_home(path: &str) -> bool {
    home_root(path).is_some()
}

/// The backup folder whose `HOME/` holds this file: when the innermost
/// `RAPID` or `HOME` folder around the file is a controller's `HOME`.
pub fn home_root(path: &str) -> Option<&str> {
    let normal = path.replace('\\', "/");
    let mut parts: Vec<&str> = normal.split('/').collect();
    parts.pop();
    let at = (0..parts.len())
        .rev()
        .find(|&i| parts[i].eq_ignore_ascii_case("rapid") || is_controller_home(&parts, i))?;
    if parts[at].eq_ignore_ascii_case("rapid") {
        return None;
    }
    let end = parts[..at].iter().map(|p| p.len() + 1).sum::<usize>();
    path.get(..end.saturating_sub(1))
}

/// Is `path` (a file or a folder, either separator) below the folder
/// `folder`, or that folder itself? Folder names are whole: `b1` does not
/// hold `b10/x.mod`.
pub fn is_within(path: &str, folder: &str) -> bool {
    if folder.is_empty() {
        return true;
    }
    let sep = |b: u8| b == b'/' || b == b'\\';
    let (p, f) = (path.as_bytes(), folder.as_bytes());
    p.len() >= f.len()
        && p.iter().zip(f).all(|(&a, &b)| a == b || (sep(a) && sep(b)))
        && (p.len() == f.len() || sep(p[f.len()]) || f.last().copied().is_some_and(sep))
}

/// Is folder `i` of a path's `parts` a controller's `HOME` folder? A
/// folder of that name in any case but all lowercase: controllers write
/// `HOME`, and `home` is where Unix systems keep their users' folders
/// (`/home/NAME/...`, where projects and backups are kept).
fn is_controller_home(parts: &[&str], i: usize) -> bool {
    is_home_folder(parts[i])
}

/// Is a folder of this name a controller's `HOME` (any case but all
/// lower case, which is a Unix system's `/home`)?
pub fn is_home_folder(name: &str) -> bool {
    name.eq_ignore_ascii_case("home") && name != "home"
}

/// The backup folder of a configuration file in its `SYSPAR/` folder.
pub fn syspar_root(path: &str) -> Option<&str> {
    root_of_folder(path, "syspar")
}

/// The folder holding the folder `name` (any case) that holds the file
/// `path`.
fn root_of_folder<'p>(path: &'p str, name: &str) -> Option<&'p str> {
    let normal = path.replace('\\', "/");
    let (dir, _) = normal.rsplit_once('/')?;
    let (parent, last) = dir.rsplit_once('/').unwrap_or(("", dir));
    if !last.eq_ignore_ascii_case(name) {
        return None;
    }
    path.get(..parent.len())
}

/// The backup a file belongs to: the folder around its innermost `RAPID/`,
/// `HOME/`, `SYSPAR/` or `BACKINFO/` folder (see
/// [`backup_root`]).
pub fn owner_backup(path: &str) -> Option<&str> {
    let config = syspar_root(path).or_else(|| backinfo_root(path));
    match (backup_root(path), config) {
        (Some(a), Some(b)) => Some(if a.len() >= b.len() { a } else { b }),
        (a, b) => a.or(b),
    }
}

/// The backup folder of a file in its `BACKINFO/` folder.
pub fn backinfo_root(path: &str) -> Option<&str> {
    root_of_folder(path, "backinfo")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tasks_follow_the_backup_layout() {
        let key = |p| locate(p);
        assert_eq!(
            key("b/RAPID/TASK1/PROGMOD/Main.mod"),
            ("b/RAPID/TASK1".into(), Grouping::Backup)
        );
        assert_eq!(task_key("b/RAPID/TASK2/SYSMOD/user.sys"), "b/RAPID/TASK2");
        assert_eq!(
            key("b/RAPID/T_ROB1/TCSupport/TcDefine.sys"),
            ("b/RAPID/T_ROB1".into(), Grouping::Backup)
        );
        assert_eq!(task_key("b/RAPID/T_ROB1/Main.mod"), "b/RAPID/T_ROB1");
        assert_eq!(
            task_key("b/RAPID/Robot1/PROGMOD/Main.mod"),
            "b/RAPID/Robot1"
        );
        assert_eq!(
            key("b/RAPID/PROGMOD/Main.mod"),
            ("b/RAPID".into(), Grouping::Backup)
        );
        assert_eq!(
            key("repo/RAPID/backup/RAPID/TASK3/PROGMOD/a.mod"),
            ("repo/RAPID/backup/RAPID/TASK3".into(), Grouping::Backup)
        );
        assert_eq!(
            key("proj/src/Main.mod"),
            ("proj/src".into(), Grouping::Folder)
        );
        assert_eq!(
            key("proj/RAPID/Main.mod"),
            ("proj/RAPID".into(), Grouping::Folder)
        );
        assert_eq!(
            key("b/HOME/T_ROB1/x.mod"),
            ("b/HOME/T_ROB1".into(), Grouping::Folder)
        );
        assert_eq!(task_key("Main.mod"), "");
        assert_eq!(
            task_key(r"c:\b\RAPID\TASK1\PROGMOD\a.mod"),
            "c:/b/RAPID/TASK1"
        );
    }

    #[test]
    fn a_backup_inside_a_home_folder_is_its_own() {
        let inner = "b/HOME/Backups/b2/RAPID/TASK1/PROGMOD/m.mod";
        assert!(!in_home(inner));
        assert_eq!(backup_root(inner), Some("b/HOME/Backups/b2"));
        assert_eq!(
            home_root("b/HOME/Backups/b2/HOME/x.mod"),
            Some("b/HOME/Backups/b2")
        );
        assert_eq!(home_root("b/HOME/Backups/x.mod"), Some("b"));
        assert_eq!(home_root("b/RAPID/TASK1/x.mod"), None);
        assert!(is_within("b1/RAPID/TASK1", "b1"));
        assert!(is_within("b1", "b1"));
        assert!(!is_within("b10/RAPID/TASK1", "b1"));
        assert!(is_within(r"c:\w\b1\x.mod", "c:/w/b1"));
        assert!(is_within("x.mod", ""));
        assert!(is_within("/b/x.mod", "/"));
    }

    #[test]
    fn a_unix_home_folder_is_not_a_controller_home() {
        assert!(!in_home("/home/runner/proj/Main.mod"));
        assert!(!in_home("/home/runner/b/RAPID/TASK1/PROGMOD/Main.mod"));
        assert!(in_home("/home/runner/b/HOME/Part1.mod"));
        assert!(in_home("b/HOME/Lib/Part1.mod"));
        assert!(in_home("b/Home/Part1.mod"));
        assert!(!in_home("home/josé/robot/Main.mod"));
        assert!(in_home(r"C:\Backups\b\HOME\Part1.mod"));
        assert_eq!(backup_root("/home/runner/proj/Main.mod"), None);
        assert_eq!(
            backup_root("/home/runner/b/HOME/P.mod"),
            Some("/home/runner/b")
        );
        assert_eq!(
            backup_root("/home/runner/b/RAPID/TASK1"),
            Some("/home/runner/b")
        );
        // the innermost marker: a backup kept in a folder named `rapid`
        assert_eq!(backup_root("/w/rapid/b/HOME/P.mod"), Some("/w/rapid/b"));
        assert_eq!(backup_root(r"C:\w\b\RAPID\TASK1"), Some(r"C:\w\b"));
        // run inside the backup folder
        assert_eq!(backup_root("RAPID/TASK1"), Some(""));
        assert_eq!(backup_root("HOME/P.mod"), Some(""));
    }

    #[test]
    fn folder_names_in_any_script_are_safe() {
        assert_eq!(task_key("/home/josé/robot/Main.mod"), "/home/josé/robot");
        assert_eq!(
            task_key("/srv/ロボット/RAPID/タスク/Main.mod"),
            "/srv/ロボット/RAPID/タスク"
        );
        assert_eq!(
            task_key("/srv/é/RAPID/TASKé/PROGMOD/a.mod"),
            "/srv/é/RAPID/TASKé"
        );
        assert_eq!(
            controller_of("/srv/ロボット/RAPID/TASK1"),
            Some("/srv/ロボット/RAPID/")
        );
        assert!(!is_task_name("tâsk1"));
        assert!(!is_task_name("T_"));
    }

    #[test]
    fn controllers_are_the_rapid_folder() {
        assert_eq!(controller_of("b/RAPID/TASK1"), Some("b/RAPID/"));
        assert_eq!(controller_of("b/RAPID/T_ROB2"), Some("b/RAPID/"));
        assert_eq!(controller_of("proj/src"), None);
        assert_eq!(controller_of("b/RAPID"), None);
        assert_eq!(backup_root("b/RAPID/TASK1"), Some("b"));
        assert_eq!(backup_root("b/HOME/Parts/p.mod"), Some("b"));
        assert_eq!(backup_root("b/RAPID"), Some("b"));
        assert_eq!(backup_root("proj/src"), None);
    }
}
