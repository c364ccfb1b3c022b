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
    /// Reads every RAPID file and `EIO.cfg` under the workspace folders,
    /// reporting progress, and the modules and configuration of the extra
    /// paths, which join every task as they do in `rapid check`.
    pub(super) async fn index_workspace(&self) {
        let (roots, extra_paths, lint) = {
            let s = self.shared.lock();
            (
                s.roots.clone(),
                s.settings.extra_paths(),
                s.settings.lint.clone(),
            )
        };
        if roots.is_empty() {
            return;
        }
        let Ok((found, extras)) = self
            .blocking("finding files", move || {
                let found = crate::project::discover_with(
                    &roots,
                    Arc::new(move |p: &Path, dir: bool| lint.is_excluded(p, dir)),
                );
                let extras = read_extras(&extra_paths, &found);
                (found, extras)
            })
            .await
        else {
            return;
        };
        let problems = self
            .mutate("reading the extra paths", |s| {
                s.ws.clear_extras();
                for unit in extras.units {
                    s.ws.add_extra_unit(Arc::new(unit));
                }
                for text in &extras.configs {
                    s.ws.add_extra_config(text);
                }
                s.config_generation += 1;
                extras.problems
            })
            .unwrap_or_default();
        for problem in problems {
            self.log(MessageType::WARNING, problem).await;
        }
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

/// The CPU priority of the indexing threads: the nice value they add to
/// the server's (Linux counts it per thread). At 10, a thread of the server
/// at 0 gets about nine tenths of a core both want.
const INDEXING_NICENESS: libc::c_int = 10;

/// The threads that read and parse the workspace's files: one per core, at
/// a lower CPU priority than the server's other threads. Indexing ten
/// thousand modules keeps every core busy for seconds; at the same priority
/// a request (hover, completion) got a core only after a turn of the
/// indexer's threads, several milliseconds at each step from the request's
/// arrival to its answer (BENCHMARKS.md, issue 27). Alone, the indexer
/// still uses every core. These threads never take the state's lock
/// ([`read_units`]). `None` when the threads cannot be started (the caller
/// then parses on the shared pool).
fn index_pool() -> Option<&'static rayon::ThreadPool> {
    static POOL: std::sync::OnceLock<Option<rayon::ThreadPool>> = std::sync::OnceLock::new();
    POOL.get_or_init(|| {
        rayon::ThreadPoolBuilder::new()
            .thread_name(|i| format!("rapid-index-{i}"))
            .start_handler(|_| lower_priority(INDEXING_NICENESS))
            .build()
            .ok()
    })
    .as_ref()
}

/// Lowers the calling thread's CPU priority by `niceness` (raising a nice
/// value needs no privilege). Linux only: elsewhere the call would apply to
/// the whole process.
#[cfg(target_os = "linux")]
#[allow(unsafe_code)]
fn lower_priority(niceness: libc::c_int) {
    // SAFETY: gettid has no arguments and cannot fail; setpriority on this
    // thread's id changes its scheduling weight only and touches no memory.
    // A refusal leaves the thread at the server's priority, which is only
    // slower for requests, so its result is not looked at.
    unsafe {
        let tid = libc::gettid();
        let now = libc::getpriority(libc::PRIO_PROCESS, tid as libc::id_t);
        libc::setpriority(libc::PRIO_PROCESS, tid as libc::id_t, now + niceness);
    }
}

#[cfg(not(target_os = "linux"))]
fn lower_priority(_niceness: libc::c_int) {}

/// The most units put into the workspace under one hold of the state's
/// lock (each takes microseconds).
const UNITS_PER_HOLD: usize = 32;

/// Reads and parses `files` in parallel on the indexing threads
/// ([`index_pool`]) and puts the units into the workspace from the calling
/// thread (files open in the editor keep the editor's text), counting them
/// in `done`; returns the files that could not be read, with why. Only the
/// calling thread, at the server's priority, takes the state's lock: an
/// indexing thread preempted while holding it, at its lower priority,
/// kept a request waiting as long as other work had the core (446 ms
/// measured on a busy machine).
pub(super) fn read_units(
    files: &[PathBuf],
    shared: &Shared,
    done: &std::sync::atomic::AtomicUsize,
) -> Vec<String> {
    use rayon::prelude::*;
    let (tx, rx) = std::sync::mpsc::channel();
    // One file per job: with rayon's adaptive splitting, one thread kept
    // the largest quarter of the files (they come first) to itself, and
    // the other, out of work, slept (measured: 18.7 s of CPU against 3.2).
    let parse = move || {
        files.par_iter().with_max_len(1).for_each_with(tx, |tx, p| {
            let read = crate::project::source::SourceFile::read(p)
                .map(|f| closed_unit(p.to_string_lossy().into_owned(), f.text));
            // The receiver lives until every file is sent.
            let _ = tx.send((p, super::state::mtime(p), read));
        });
    };
    let mut problems = Vec::new();
    std::thread::scope(|scope| {
        scope.spawn(|| match index_pool() {
            Some(pool) => pool.install(parse),
            None => parse(),
        });
        while let Ok(first) = rx.recv() {
            let mut s = shared.lock();
            let arrived = std::iter::once(first).chain(rx.try_iter().take(UNITS_PER_HOLD - 1));
            for (p, mtime, read) in arrived {
                match read {
                    Ok(unit) => {
                        if !s.docs.contains_key(&unit.path) {
                            s.disk.insert(p.clone(), mtime);
                            s.ws.set_unit(unit);
                        }
                    }
                    Err(why) => problems.push(format!("{}: {why}", p.display())),
                }
                done.fetch_add(1, Ordering::Relaxed);
            }
        }
    });
    problems
}

/// The modules and configuration of the extra paths, and what could not
/// be read there.
struct Extras {
    units: Vec<rapid_analyzer::task::Unit>,
    configs: Vec<String>,
    problems: Vec<String>,
}

/// Reads the extra paths as `rapid check` does (through the project
/// loader's discovery and reading), leaving out the modules of the
/// workspace folders (`found`), which are the workspace's own.
fn read_extras(paths: &[PathBuf], found: &crate::project::Discovery) -> Extras {
    use crate::project::{Disk, discover, read_source};
    let extra = discover(paths);
    let own: std::collections::HashSet<&PathBuf> = found.files.iter().collect();
    let mut out = Extras {
        units: Vec::new(),
        configs: Vec::new(),
        problems: extra
            .errors
            .iter()
            .map(|(p, why)| format!("{} (extra path): {why}", p.display()))
            .collect(),
    };
    for path in extra.files.iter().filter(|p| !own.contains(p)) {
        match read_source(&Disk, path) {
            Ok(file) => out
                .units
                .push(closed_unit(path.to_string_lossy().into_owned(), file.text)),
            Err(why) => out.problems.push(format!("{}: {why}", path.display())),
        }
    }
    for path in &extra.configs {
        if let Ok(bytes) = crate::project::source::read_regular(path) {
            out.configs
                .push(String::from_utf8_lossy(&bytes).into_owned());
        }
    }
    out
}
