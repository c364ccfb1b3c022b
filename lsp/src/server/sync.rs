//! What the client tells: documents opened, changed and closed, files
//! changed on disk, workspace folders and settings.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use rapid_analyzer::text::{LineIndex, is_rapid_file_name};
use tower_lsp_server::ls_types::*;

use super::document::{Document, apply_changes, apply_text_changes};
use super::state::{is_eio_cfg, make_unit, path_of};

use super::backend::*;

impl Backend {
    pub(super) async fn handle_did_open(&self, params: DidOpenTextDocumentParams) {
        let doc = params.text_document;
        let path = path_of(&doc.uri);
        if is_eio_cfg(&path) {
            self.mutate("opening", |s| {
                s.ws.set_config(&path, &doc.text);
                s.open_configs.insert(path.clone(), doc.text);
                s.config_generation += 1;
            });
            self.republish_all();
            return;
        }
        let others = self
            .mutate("opening", |s| {
                let changed = s.ws.set_unit(make_unit(path.clone(), doc.text));
                let unit = s.ws.unit(&path)?.clone();
                s.docs.insert(
                    path.clone(),
                    Document {
                        uri: doc.uri.clone(),
                        version: doc.version,
                        index: Arc::new(LineIndex::new(&unit.text)),
                        unit,
                        generation: 0,
                    },
                );
                s.semantic.remove(&path);
                Some(if changed {
                    s.open_in_task(&path)
                } else {
                    Vec::new()
                })
            })
            .flatten();
        self.schedule(vec![path.clone()], Some(Duration::ZERO));
        if let Some(others) = others {
            self.schedule(others, None);
        }
        // Outside every workspace folder: the rest of its task, from its place.
        if let Some(folders) = self
            .mutate("opening", |s| s.unloaded_task_of(&path))
            .flatten()
        {
            let this = self.clone();
            tokio::spawn(async move { this.load_task_of(folders).await });
        }
    }

    pub(super) async fn handle_did_change(&self, params: DidChangeTextDocumentParams) {
        let path = path_of(&params.text_document.uri);
        let version = params.text_document.version;
        if is_eio_cfg(&path) {
            let applied = self.mutate("applying a change", |s| {
                let encoding = s.encoding;
                let text = s.open_configs.get_mut(&path)?;
                apply_text_changes(text, &params.content_changes, encoding);
                let text = text.clone();
                s.ws.set_config(&path, &text);
                s.config_generation += 1;
                Some(())
            });
            if applied.flatten().is_some() {
                self.republish_all();
            }
            return;
        }
        let outcome = self.mutate("applying a change", |s| {
            let encoding = s.encoding;
            let doc = s.docs.get(&path)?;
            let unit = apply_changes(&doc.unit, &doc.index, &params.content_changes, encoding);
            let changed = s.ws.set_unit(unit);
            let unit = s.ws.unit(&path)?.clone();
            let doc = s.docs.get_mut(&path)?;
            doc.index = Arc::new(LineIndex::new(&unit.text));
            doc.unit = unit;
            doc.version = version;
            Some(if changed {
                (true, s.open_in_task(&path))
            } else {
                (false, Vec::new())
            })
        });
        match outcome {
            Some(Some((interface_changed, others))) => {
                self.schedule(vec![path], None);
                let caps = self.shared.lock().caps;
                if !others.is_empty() && caps.pulls() {
                    // Pulling clients ask again for the other files.
                    let client = self.client.clone();
                    tokio::spawn(async move { client.workspace_diagnostic_refresh().await });
                }
                if interface_changed {
                    self.schedule_workspace_report(CLOSED_FILES_DELAY);
                }
                self.schedule(others, None);
            }
            Some(None) => {
                self.log(
                    MessageType::WARNING,
                    format!("didChange for a document that is not open: {path}"),
                )
                .await;
            }
            None => {
                self.log(
                    MessageType::ERROR,
                    format!("applying a change to {path} failed; the document is out of step"),
                )
                .await;
            }
        }
    }

    pub(super) async fn handle_did_close(&self, params: DidCloseTextDocumentParams) {
        let uri = params.text_document.uri;
        let path = path_of(&uri);
        if is_eio_cfg(&path) {
            self.mutate("closing", |s| {
                if s.open_configs.remove(&path).is_some() {
                    let p = PathBuf::from(&path);
                    if !p.is_file() || s.load_from_disk(&p).is_err() {
                        s.ws.remove_config(&path);
                        s.config_generation += 1;
                    }
                }
            });
            self.republish_all();
            return;
        }
        let others = self
            .mutate("closing", |s| {
                s.docs.remove(&path)?;
                s.semantic.remove(&path);
                s.ws.forget_check(&path);
                s.published.remove(&path);
                // The file goes back to its state on disk.
                let p = PathBuf::from(&path);
                let changed = if p.is_file() {
                    s.load_from_disk(&p).unwrap_or(true)
                } else {
                    s.ws.remove_file(&path);
                    true
                };
                Some(if changed {
                    s.open_in_task(&path)
                } else {
                    Vec::new()
                })
            })
            .flatten();
        let (push, on_disk) = {
            let s = self.shared.lock();
            (!s.caps.pulls(), s.ws.unit(&path).is_some())
        };
        if push && !on_disk {
            self.client.publish_diagnostics(uri, Vec::new(), None).await;
        }
        // The file as it is on disk is reported with the other files that
        // are not open (and they may see another interface now).
        self.schedule_workspace_report(Duration::ZERO);
        if let Some(others) = others {
            self.schedule(others, None);
        }
    }

    pub(super) async fn handle_did_change_watched_files(
        &self,
        params: DidChangeWatchedFilesParams,
    ) {
        let config_changed = params.changes.iter().any(|c| {
            c.uri
                .to_file_path()
                .and_then(|p| p.file_name().map(|n| n == crate::config::FILE_NAME))
                .unwrap_or(false)
        });
        if config_changed {
            for p in self.reload_settings(None) {
                self.log(MessageType::WARNING, format!("settings: {p}"))
                    .await;
            }
        }
        let problems = self
            .mutate("reloading files", |s| {
                let mut problems = Vec::new();
                for change in &params.changes {
                    let Some(path) = change.uri.to_file_path() else {
                        continue;
                    };
                    let name = path.to_string_lossy();
                    if !is_rapid_file_name(&name) && !is_eio_cfg(&name) {
                        continue;
                    }
                    if change.typ == FileChangeType::DELETED {
                        s.remove_from_disk(&path);
                    } else if let Err(why) = s.load_from_disk(&path) {
                        problems.push(format!("{}: {why}", path.display()));
                    }
                }
                problems
            })
            .unwrap_or_default();
        for p in problems {
            self.log(MessageType::WARNING, p).await;
        }
        self.republish_all();
    }

    pub(super) async fn handle_did_change_workspace_folders(
        &self,
        params: DidChangeWorkspaceFoldersParams,
    ) {
        self.mutate("changing workspace folders", |s| {
            let removed: Vec<PathBuf> = params
                .event
                .removed
                .iter()
                .filter_map(|f| f.uri.to_file_path().map(|p| p.into_owned()))
                .collect();
            s.roots.retain(|r| !removed.contains(r));
            for f in &params.event.added {
                if let Some(p) = f.uri.to_file_path() {
                    s.roots.push(p.into_owned());
                }
            }
            // Files of removed folders are forgotten (unless open).
            let gone: Vec<PathBuf> = s
                .disk
                .keys()
                .filter(|p| removed.iter().any(|r| p.starts_with(r)))
                .cloned()
                .collect();
            for p in gone {
                s.remove_from_disk(&p);
            }
        });
        let this = self.clone();
        tokio::spawn(async move { this.index_workspace().await });
    }

    pub(super) async fn handle_did_change_configuration(
        &self,
        params: DidChangeConfigurationParams,
    ) {
        let old_extra = self.shared.lock().settings.extra_paths();
        let problems = self.reload_settings(Some(&params.settings));
        for p in problems {
            self.log(MessageType::WARNING, format!("settings: {p}"))
                .await;
        }
        if self.shared.lock().settings.extra_paths() != old_extra {
            let this = self.clone();
            tokio::spawn(async move { this.index_workspace().await });
        } else {
            self.republish_all();
        }
        if self.shared.lock().caps.semantic_tokens_refresh {
            let client = self.client.clone();
            tokio::spawn(async move { client.semantic_tokens_refresh().await });
        }
    }
}
