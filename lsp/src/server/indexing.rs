//! Indexing the workspace: finding its files through the project loader
//! and reading them in one parallel pass, with progress.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::Duration;

use rapid_analyzer::ide;
use tower_lsp_server::ls_types::*;

use super::state::{Shared, closed_unit};

use super::backend::*;

impl Backend {
    /// Reads every RAPID file and `EIO.cfg` under the workspace folders and
    /// the extra paths, reporting progress.
    pub(super) async fn index_workspace(&self) {
        let (roots, lint) = {
            let s = self.shared.lock();
            let mut roots = s.roots.clone();
            roots.extend(s.settings.extra_paths());
            (roots, s.settings.lint.clone())
        };
        if roots.is_empty() {
            return;
        }
        let Ok(found) = self
            .blocking("finding files", move || {
                crate::project::discover_with(
                    &roots,
                    Arc::new(move |p: &Path, dir: bool| lint.is_excluded(p, dir)),
                )
            })
            .await
        else {
            return;
        };
        self.index(found).await;
    }

    /// Reads the files found (RAPID files, programs, configuration) into the
    /// workspace, reporting progress, then publishes diagnostics again.
    pub(super) async fn index(&self, found: crate::project::Discovery) {
        let progress_supported = self.shared.lock().caps.work_done_progress;
        let progress = if progress_supported && !found.files.is_empty() {
            let token = NumberOrString::String("rapid/indexing".to_owned());
            match self.client.create_work_done_progress(token.clone()).await {
                Ok(()) => Some(
                    self.client
                        .progress(token, "Indexing RAPID files")
                        .with_message(format!("{} files", found.files.len()))
                        .with_percentage(0)
                        .begin()
                        .await,
                ),
                Err(_) => None,
            }
        } else {
            None
        };
        // One parallel pass over every file, largest first (so that a large
        // file does not start last and leave a core idle); each unit goes
        // into the workspace as soon as it is parsed, and progress is
        // reported from here meanwhile.
        let total = found.files.len().max(1);
        let done = Arc::new(std::sync::atomic::AtomicUsize::new(0));
        let mut files = found.files.clone();
        files
            .sort_by_cached_key(|p| std::cmp::Reverse(std::fs::metadata(p).map_or(0, |m| m.len())));
        let reading = {
            let shared = self.shared.clone();
            let done = done.clone();
            self.blocking("reading files", move || {
                let read = read_units(&files, &shared, &done);
                ide::prepare_completions();
                read
            })
        };
        tokio::pin!(reading);
        let mut problems = loop {
            tokio::select! {
                read = &mut reading => break read.unwrap_or_default(),
                () = tokio::time::sleep(Duration::from_millis(100)) => {
                    if let Some(p) = &progress {
                        let done = done.load(Ordering::Relaxed);
                        let pct = u32::try_from(done * 100 / total).unwrap_or(100);
                        p.report_with_message(format!("{done}/{total} files"), pct)
                            .await;
                    }
                }
            }
        };
        if let Some(p) = &progress {
            let done = done.load(Ordering::Relaxed);
            p.report_with_message(format!("{done}/{total} files"), 100)
                .await;
        }
        self.mutate("indexing", |s| {
            for program in &found.programs {
                if let Ok(bytes) = crate::project::source::read_regular(program) {
                    s.ws.set_program(&program.to_string_lossy(), &String::from_utf8_lossy(&bytes));
                }
            }
            for cfg in &found.configs {
                if let Err(why) = s.load_from_disk(cfg) {
                    problems.push(format!("{}: {why}", cfg.display()));
                }
            }
        });
        if let Some(p) = progress {
            p.finish_with_message(format!("{} files indexed", found.files.len()))
                .await;
        }
        for problem in problems {
            self.log(MessageType::WARNING, problem).await;
        }
        self.log(
            MessageType::INFO,
            format!("indexed {} RAPID files", found.files.len()),
        )
        .await;
        self.republish_all();
    }
}

/// Reads and parses `files` in parallel into the workspace (files open in
/// the editor keep the editor's text), counting them in `done`; returns the
/// files that could not be read, with why.
pub(super) fn read_units(
    files: &[PathBuf],
    shared: &Shared,
    done: &std::sync::atomic::AtomicUsize,
) -> Vec<String> {
    use rayon::prelude::*;
    files
        .par_iter()
        .filter_map(|p| {
            let read = crate::project::source::SourceFile::read(p)
                .map(|f| closed_unit(p.to_string_lossy().into_owned(), f.text));
            let mtime = super::state::mtime(p);
            let problem = {
                let mut s = shared.lock();
                match read {
                    Ok(unit) => {
                        if !s.docs.contains_key(&unit.path) {
                            s.disk.insert(p.clone(), mtime);
                            s.ws.set_unit(unit);
                        }
                        None
                    }
                    Err(why) => Some(format!("{}: {why}", p.display())),
                }
            };
            done.fetch_add(1, Ordering::Relaxed);
            problem
        })
        .collect()
}
