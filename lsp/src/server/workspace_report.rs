//! The diagnostics of every file of the workspace, not only the open ones,
//! as a language server for a project reports them: pushed to clients that
//! are pushed to (after indexing, and again when a change reaches the files
//! that are not open), or answered to `workspace/diagnostic` for clients
//! that pull ([`super::state::ClientCaps::pulls`]).
//!
//! A file that is not open keeps no syntax tree (see
//! [`super::state::closed_unit`]); checking it needs one. So the files of a
//! task are checked on a copy of the task whose closed files are parsed
//! afresh for the check and dropped after it: the workspace keeps its
//! memory. A file's report is kept until its text, what its check reads of
//! its task ([`CheckInputs`]) or the settings change.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;
use std::time::Duration;

use rapid_analyzer::check::StmtCache;
use rapid_analyzer::task::{Task, Unit};
use rapid_analyzer::workspace::{CheckInputs, diagnostics_selected};
use tower_lsp_server::ls_types::{
    Diagnostic, FullDocumentDiagnosticReport, PreviousResultId, UnchangedDocumentDiagnosticReport,
    Uri, WorkspaceDiagnosticParams, WorkspaceDiagnosticReport, WorkspaceDiagnosticReportResult,
    WorkspaceDocumentDiagnosticReport, WorkspaceFullDocumentDiagnosticReport,
    WorkspaceUnchangedDocumentDiagnosticReport,
};

use super::backend::Backend;
use super::publish::convert_diagnostics;
#[cfg(test)]
use super::state::closed_unit;
use super::state::{Shared, Snapshot, State, make_unit, uri_of};

/// The last report of a file that is not open.
pub struct ClosedReport {
    pub uri: Uri,
    unit: Arc<Unit>,
    /// What the check read of the task ([`CheckInputs`]).
    inputs: CheckInputs,
    /// The settings the report was converted with.
    config_generation: u64,
    pub items: Arc<Vec<Diagnostic>>,
    pub result_id: String,
}

/// Files to report: those whose report is stale, with their snapshots.
struct Stale {
    snapshots: Vec<Snapshot>,
    /// Open files (their units keep their trees and are shared as they are).
    open: HashSet<String>,
}

/// How many files' snapshots are taken under one hold of the state's lock
/// (taking them may build their tasks): an edit or a request waits for one
/// batch at most.
const SNAPSHOTS_PER_LOCK: usize = 16;

impl State {
    /// The files that are not open, and the open ones; forgets the reports
    /// of files that are open now or gone (and returns the URIs of the gone
    /// ones).
    fn closed_files(&mut self) -> (Vec<String>, HashSet<String>, Vec<Uri>) {
        let open: HashSet<String> = self.docs.keys().cloned().collect();
        let paths: Vec<String> = self
            .ws
            .paths()
            .filter(|p| !open.contains(*p))
            .map(str::to_owned)
            .collect();
        let known: HashSet<&String> = paths.iter().collect();
        let mut gone = Vec::new();
        let published = &mut self.published;
        self.closed.retain(|path, report| {
            let keep = known.contains(path);
            if !keep && !open.contains(path) {
                gone.push(report.uri.clone());
                published.remove(path);
            }
            keep
        });
        (paths, open, gone)
    }

    /// Snapshots of those of `paths` that are still not open and have no
    /// valid report.
    fn stale_snapshots(&mut self, paths: &[String]) -> Vec<Snapshot> {
        let mut snapshots = Vec::new();
        for path in paths {
            if self.docs.contains_key(path) {
                continue;
            }
            let Some(uri) = uri_of(&HashMap::new(), path) else {
                continue;
            };
            let Some(unit) = self.ws.unit(path).cloned() else {
                continue;
            };
            let task = self.ws.task_of(path);
            let valid = self.closed.get(path).is_some_and(|r| {
                Arc::ptr_eq(&r.unit, &unit)
                    && r.inputs == CheckInputs::of(&task)
                    && r.config_generation == self.config_generation
            });
            if !valid && let Some(snap) = self.snapshot(&uri) {
                snapshots.push(snap);
            }
        }
        snapshots
    }

    /// Keeps fresh reports (those still for the workspace's text, task and
    /// settings).
    fn keep_reports(&mut self, fresh: Vec<(Snapshot, Vec<Diagnostic>)>) {
        for (snap, items) in fresh {
            let current = self
                .ws
                .unit(&snap.path)
                .is_some_and(|u| Arc::ptr_eq(u, &snap.unit))
                && CheckInputs::of(&self.ws.task_of(&snap.path)) == CheckInputs::of(&snap.task);
            if !current
                || self.docs.contains_key(&snap.path)
                || snap.config_generation != self.config_generation
            {
                continue;
            }
            let result_id = super::diagnostics::result_id(&items);
            self.closed.insert(
                snap.path.clone(),
                ClosedReport {
                    uri: snap.uri.clone(),
                    unit: snap.unit.clone(),
                    inputs: CheckInputs::of(&snap.task),
                    config_generation: snap.config_generation,
                    items: Arc::new(items),
                    result_id,
                },
            );
        }
    }
}

/// Checks the stale files, task by task, each on a copy of its task whose
/// closed files are parsed for the check. Stops when `superseded` says a
/// newer run started: gives what it checked so far, and whether that is
/// all.
fn check_stale(
    stale: Stale,
    superseded: &(dyn Fn() -> bool + Sync),
) -> (Vec<(Snapshot, Vec<Diagnostic>)>, bool) {
    let mut by_task: HashMap<*const Task, Vec<Snapshot>> = HashMap::new();
    for snap in stale.snapshots {
        by_task
            .entry(Arc::as_ptr(&snap.task))
            .or_default()
            .push(snap);
    }
    let mut out = Vec::new();
    for (_, snaps) in by_task {
        if superseded() {
            return (out, false);
        }
        let Some(task) = snaps.first().map(|s| s.task.clone()) else {
            continue;
        };
        let checking = with_trees(&task, &stale.open);
        // One file after the other, on one low-priority thread (see
        // `in_background`); a newer run makes this one stop between two
        // files.
        for snap in snaps {
            if superseded() {
                return (out, false);
            }
            let items = match checking.units.get(snap.unit_idx) {
                Some(unit) => {
                    let (found, _) = diagnostics_selected(
                        &checking,
                        unit,
                        StmtCache::default(),
                        &snap.selection,
                    );
                    convert_diagnostics(&snap, &found)
                }
                None => Vec::new(),
            };
            out.push((snap, items));
        }
    }
    (out, true)
}

/// A copy of `task` whose files that are not open are parsed again (their
/// units in the workspace released their trees), to be dropped after use.
fn with_trees(task: &Task, open: &HashSet<String>) -> Task {
    let units: Vec<Arc<Unit>> = task
        .units
        .iter()
        .map(|u| {
            if open.contains(&u.path) {
                u.clone()
            } else {
                Arc::new(make_unit(u.path.clone(), u.text.clone()))
            }
        })
        .collect();
    task.with_units(units)
}

impl Backend {
    /// Brings the reports of the files that are not open up to date.
    /// `generation`: stop (and give `None`) once a newer push run is
    /// scheduled.
    async fn refresh_reports(&self, generation: Option<u64>) -> Option<Vec<Uri>> {
        let (paths, open, gone) = self.mutate("reporting the workspace", State::closed_files)?;
        let mut snapshots = Vec::new();
        for batch in paths.chunks(SNAPSHOTS_PER_LOCK) {
            snapshots.extend(self.mutate("reporting the workspace", |s| s.stale_snapshots(batch))?);
            tokio::task::yield_now().await;
        }
        let stale = Stale { snapshots, open };
        if !stale.snapshots.is_empty() {
            let shared: Arc<Shared> = self.shared.clone();
            let superseded =
                move || generation.is_some_and(|g| shared.lock().closed_generation != g);
            let (fresh, complete) = in_background(move || check_stale(stale, &superseded)).await?;
            // What a superseded run checked is kept (the next run has less
            // to do); the next run publishes.
            self.mutate("reporting the workspace", |s| s.keep_reports(fresh));
            if !complete {
                return None;
            }
        }
        Some(gone)
    }

    /// Schedules a push of the diagnostics of every file that is not open,
    /// after `delay` (clients that pull ask for them instead). A later
    /// schedule supersedes this one.
    pub(super) fn schedule_workspace_report(&self, delay: Duration) {
        let generation = self
            .mutate("scheduling the workspace report", |s| {
                if s.caps.pulls() {
                    return None;
                }
                s.closed_generation += 1;
                Some(s.closed_generation)
            })
            .flatten();
        let Some(generation) = generation else {
            return;
        };
        let this = self.clone();
        tokio::spawn(async move {
            tokio::time::sleep(delay).await;
            this.push_workspace_report(generation).await;
        });
    }

    async fn push_workspace_report(&self, generation: u64) {
        let current = |s: &State| s.closed_generation == generation;
        if self.mutate("reporting the workspace", |s| current(s)) != Some(true) {
            return;
        }
        let Some(gone) = self.refresh_reports(Some(generation)).await else {
            return;
        };
        let _order = self.shared.publish.lock().await;
        let sends = self
            .mutate("reporting the workspace", |s| {
                let mut sends: Vec<(Uri, Vec<Diagnostic>)> =
                    gone.into_iter().map(|uri| (uri, Vec::new())).collect();
                let reports: Vec<(String, Uri, Arc<Vec<Diagnostic>>)> = s
                    .closed
                    .iter()
                    .map(|(p, r)| (p.clone(), r.uri.clone(), r.items.clone()))
                    .collect();
                for (path, uri, items) in reports {
                    // Opened since: the open document's diagnostics count.
                    if s.docs.contains_key(&path) {
                        continue;
                    }
                    if s.should_publish(&path, None, &items, false) {
                        sends.push((uri, items.to_vec()));
                    }
                }
                sends
            })
            .unwrap_or_default();
        for (uri, items) in sends {
            self.client.publish_diagnostics(uri, items, None).await;
        }
    }

    /// `workspace/diagnostic`: the files that are not open (the client
    /// pulls the open ones itself), unchanged when their result is the one
    /// the client has.
    pub(super) async fn workspace_report(
        &self,
        params: WorkspaceDiagnosticParams,
    ) -> WorkspaceDiagnosticReportResult {
        let gone = self.refresh_reports(None).await.unwrap_or_default();
        let previous: HashMap<&str, &str> = params
            .previous_result_ids
            .iter()
            .map(|PreviousResultId { uri, value }| (uri.as_str(), value.as_str()))
            .collect();
        let reports: Vec<(Uri, String, Arc<Vec<Diagnostic>>)> = self
            .mutate("reporting the workspace", |s| {
                s.closed
                    .values()
                    .map(|r| (r.uri.clone(), r.result_id.clone(), r.items.clone()))
                    .collect()
            })
            .unwrap_or_default();
        let mut items: Vec<WorkspaceDocumentDiagnosticReport> = gone
            .into_iter()
            .map(|uri| full(uri, String::new(), Vec::new()))
            .collect();
        for (uri, result_id, diagnostics) in reports {
            if previous.get(uri.as_str()) == Some(&result_id.as_str()) {
                items.push(WorkspaceDocumentDiagnosticReport::Unchanged(
                    WorkspaceUnchangedDocumentDiagnosticReport {
                        uri,
                        version: None,
                        unchanged_document_diagnostic_report: UnchangedDocumentDiagnosticReport {
                            result_id,
                        },
                    },
                ));
            } else {
                items.push(full(uri, result_id, diagnostics.to_vec()));
            }
        }
        WorkspaceDiagnosticReportResult::Report(WorkspaceDiagnosticReport { items })
    }
}

/// Runs `f` on a thread of its own at the lowest scheduling priority, so
/// that the report of the whole workspace (seconds of work on a large
/// one) never delays the editor's requests and the open files'
/// diagnostics; `None` if it panicked or no thread could be started.
async fn in_background<R: Send + 'static>(f: impl FnOnce() -> R + Send + 'static) -> Option<R> {
    let (tx, rx) = tokio::sync::oneshot::channel();
    let spawned = std::thread::Builder::new()
        .name("rapid-workspace-report".to_owned())
        .spawn(move || {
            lowest_priority();
            let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
            if result.is_err() {
                eprintln!("rapid lsp: the workspace report panicked");
            }
            let _ = tx.send(result.ok());
        });
    if spawned.is_err() {
        return None;
    }
    rx.await.ok().flatten()
}

/// Gives the calling thread the lowest priority (nice 19; per thread on
/// Linux). On a machine where every core is busy, the editor's requests
/// then run first.
#[cfg(target_os = "linux")]
#[allow(unsafe_code)]
fn lowest_priority() {
    // SAFETY: setpriority takes plain integers; with PRIO_PROCESS and 0 it
    // changes the nice value of the calling thread only, which affects
    // scheduling and nothing in memory.
    let _ = unsafe { libc::setpriority(libc::PRIO_PROCESS, 0, 19) };
}

#[cfg(not(target_os = "linux"))]
fn lowest_priority() {}

fn full(uri: Uri, result_id: String, items: Vec<Diagnostic>) -> WorkspaceDocumentDiagnosticReport {
    WorkspaceDocumentDiagnosticReport::Full(WorkspaceFullDocumentDiagnosticReport {
        uri,
        version: None,
        full_document_diagnostic_report: FullDocumentDiagnosticReport {
            result_id: (!result_id.is_empty()).then_some(result_id),
            items,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_analyzer::workspace::Workspace;

    /// A file that is not open is checked on a copy of its task with its
    /// tree parsed again: the same diagnostics as in the task itself (a
    /// complete backup task, whose unresolved names are errors, and its
    /// task ids).
    #[test]
    fn closed_files_are_checked_as_in_their_task() {
        let mut ws = Workspace::new();
        let path = "b/RAPID/TASK1/PROGMOD/M.mod";
        ws.set_unit(closed_unit(
            path.into(),
            "MODULE M\n  VAR taskid t;\n  PROC main()\n    t := T_PAINTId;\n    missing;\n  ENDPROC\nENDMODULE\n"
                .into(),
        ));
        ws.set_config(
            "b/SYSPAR/SYS.cfg",
            "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T_PAINT\" -Type \"NORMAL\"\n",
        );
        let task = ws.task_of(path);
        let unit = ws.unit(path).cloned().expect("the file");
        let copy = with_trees(&task, &HashSet::new());
        let in_copy = rapid_analyzer::workspace::diagnostics_of(&copy, &copy.units[0]);
        assert_eq!(
            in_copy,
            rapid_analyzer::workspace::diagnostics_of(&task, &unit)
        );
        assert_eq!(in_copy.len(), 1, "{in_copy:?}");
        assert_eq!(
            in_copy[0].severity,
            rapid_analyzer::diagnostic::Severity::Error
        );
    }
}
