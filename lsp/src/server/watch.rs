//! Following the disk: file watchers for clients that have them, a poll
//! of module times and a walk of the folders for the others.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use tower_lsp_server::ls_types::*;

use super::state::is_eio_cfg;

use super::backend::*;

/// The extensions of RAPID files, in the letter cases seen in practice, for
/// file watchers (LSP glob patterns are case-sensitive).
const WATCH_GLOBS: &[&str] = &[
    "**/*.{mod,modx,sys,sysx,prg}",
    "**/*.{MOD,MODX,SYS,SYSX,PRG}",
    "**/*.{Mod,Modx,Sys,Sysx,Prg}",
    "**/{EIO,eio,Eio}.{cfg,CFG}",
    "**/rapid.toml",
];

impl Backend {
    pub(super) async fn register_watchers(&self) {
        let watchers = WATCH_GLOBS
            .iter()
            .map(|g| FileSystemWatcher {
                glob_pattern: GlobPattern::String((*g).to_owned()),
                kind: None,
            })
            .collect();
        let options = DidChangeWatchedFilesRegistrationOptions { watchers };
        let Ok(options) = serde_json::to_value(options) else {
            return;
        };
        let registration = Registration {
            id: "rapid/watch".to_owned(),
            method: "workspace/didChangeWatchedFiles".to_owned(),
            register_options: Some(options),
        };
        if let Err(e) = self.client.register_capability(vec![registration]).await {
            self.log(
                MessageType::WARNING,
                format!("cannot watch files: {}", e.message),
            )
            .await;
        }
    }

    /// For clients that cannot watch files: every two seconds, looks for
    /// modules changed or gone on disk (their times), and walks the
    /// workspace folders again for new, renamed and re-created modules and
    /// for changed `EIO.cfg` and `rapid.toml` files. A walk that takes long
    /// is made less often (at most a twentieth of the time goes to walks),
    /// so a huge folder costs a bounded share of a core.
    pub(super) async fn poll_disk(&self) {
        // The configuration files seen at the last walk, with their times.
        let mut configs: HashMap<PathBuf, Option<std::time::SystemTime>> = HashMap::new();
        let mut next_walk = std::time::Instant::now();
        let mut first = true;
        loop {
            if !first {
                tokio::time::sleep(Duration::from_secs(2)).await;
            }
            let (known, roots, lint) = {
                let s = self.shared.lock();
                if s.shutdown {
                    return;
                }
                let known: Vec<(PathBuf, Option<std::time::SystemTime>)> =
                    s.disk.iter().map(|(p, t)| (p.clone(), *t)).collect();
                (known, s.roots.clone(), s.settings.lint.clone())
            };
            let walk = std::time::Instant::now() >= next_walk;
            let Ok((changed, found)) = self
                .blocking("polling files", move || {
                    let changed: Vec<PathBuf> = known
                        .iter()
                        .filter(|(p, t)| super::state::mtime(p) != *t)
                        .map(|(p, _)| p.clone())
                        .collect();
                    let found = walk.then(|| {
                        let started = std::time::Instant::now();
                        let mut found = crate::project::discover_with(
                            &roots,
                            Arc::new(move |p: &Path, dir: bool| lint.is_excluded(p, dir)),
                        );
                        let known: HashSet<&PathBuf> = known.iter().map(|(p, _)| p).collect();
                        found.files.retain(|p| !known.contains(p));
                        let mut watched: HashMap<PathBuf, Option<std::time::SystemTime>> = found
                            .configs
                            .iter()
                            .map(|p| (p.clone(), super::state::mtime(p)))
                            .collect();
                        if let Some(toml) = roots.first().and_then(|r| crate::config::find(r)) {
                            let time = super::state::mtime(&toml);
                            watched.insert(toml, time);
                        }
                        (found.files, watched, started.elapsed())
                    });
                    (changed, found)
                })
                .await
            else {
                continue;
            };
            let mut new_files = Vec::new();
            let mut new_configs = Vec::new();
            let mut settings_changed = false;
            if let Some((files, watched, took)) = found {
                next_walk = std::time::Instant::now() + took * 20;
                new_files = files;
                if !first {
                    for (path, time) in &watched {
                        if configs.get(path) != Some(time) {
                            if is_eio_cfg(&path.to_string_lossy()) {
                                new_configs.push(path.clone());
                            } else {
                                settings_changed = true;
                            }
                        }
                    }
                    // A `rapid.toml` that went away changes the settings too.
                    settings_changed |= configs
                        .keys()
                        .any(|p| !watched.contains_key(p) && !is_eio_cfg(&p.to_string_lossy()));
                }
                configs = watched;
            }
            first = false;
            if settings_changed {
                for p in self.reload_settings(None) {
                    self.log(MessageType::WARNING, format!("settings: {p}"))
                        .await;
                }
            }
            if changed.is_empty()
                && new_files.is_empty()
                && new_configs.is_empty()
                && !settings_changed
            {
                continue;
            }
            self.mutate("reloading files", |s| {
                for p in changed.iter().chain(&new_files).chain(&new_configs) {
                    if p.exists() {
                        let _ = s.load_from_disk(p);
                    } else {
                        s.remove_from_disk(p);
                    }
                }
            });
            self.republish_all();
        }
    }
}
