//! A file opened outside every workspace folder (Neovim without a project
//! root, VS Code with one file and no folder): the server loads the rest of
//! the file's task from the file's place, as `rapid check` does (a backup's
//! `RAPID/TASKn` folder and its `SYSPAR` configuration, or the modules of
//! the file's own folder), so that its names resolve and its diagnostics
//! are those of its task.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::project::context::{TaskFolders, discover_folders, task_folders};

use super::backend::Backend;
use super::state::State;

impl State {
    /// The folders of the task of `path` when the file lies outside every
    /// workspace folder and they are not loaded yet (they are remembered as
    /// loaded).
    pub fn unloaded_task_of(&mut self, path: &str) -> Option<TaskFolders> {
        let file = Path::new(path);
        if !file.is_absolute() || !file.is_file() || self.roots.iter().any(|r| file.starts_with(r))
        {
            return None;
        }
        let folders = task_folders(path);
        let wanted: Vec<PathBuf> = folders
            .deep
            .iter()
            .chain(&folders.shallow)
            .filter(|f| !self.implicit_roots.contains(f))
            .cloned()
            .collect();
        if wanted.is_empty() {
            return None;
        }
        self.implicit_roots.extend(wanted);
        Some(folders)
    }
}

impl Backend {
    /// Loads the rest of a task whose file was opened outside every
    /// workspace folder.
    pub(super) async fn load_task_of(&self, folders: TaskFolders) {
        let lint = self.shared.lock().settings.lint.clone();
        let found = self
            .blocking("finding the task's files", move || {
                let deep: Vec<PathBuf> = folders.deep.into_iter().collect();
                discover_folders(
                    &deep,
                    &folders.shallow,
                    Arc::new(move |p: &Path, dir: bool| lint.is_excluded(p, dir)),
                )
            })
            .await;
        if let Ok(found) = found {
            self.index(found).await;
        }
    }
}
