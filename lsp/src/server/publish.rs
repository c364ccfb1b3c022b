//! Publishing diagnostics: scheduling per open document (debounced,
//! versioned), the quick carried-over list then the full check, and
//! their conversion to the protocol.

use std::path::Path;
use std::time::Duration;

use tower_lsp_server::ls_types::*;

use super::diagnostics;
use super::state::{Snapshot, State};

use super::backend::*;

impl Backend {
    /// Schedules a publication of diagnostics for each open document in
    /// `paths`, after `delay`. A later schedule for the same document
    /// supersedes this one.
    pub(super) fn schedule(&self, paths: Vec<String>, delay: Option<Duration>) {
        let jobs = self
            .mutate("scheduling diagnostics", |s| {
                let delay = delay.unwrap_or(s.settings.delay);
                let push = !s.caps.pulls();
                paths
                    .into_iter()
                    .filter_map(|p| {
                        let id = s.next_id();
                        let doc = s.docs.get_mut(&p)?;
                        doc.generation = id;
                        push.then_some((p, id, delay))
                    })
                    .collect::<Vec<_>>()
            })
            .unwrap_or_default();
        for (path, generation, delay) in jobs {
            let this = self.clone();
            tokio::spawn(async move { this.publish(path, generation, delay).await });
        }
    }

    /// Every open document, at once.
    pub(super) fn republish_all(&self) {
        let paths = self
            .mutate("listing documents", |s| s.docs.keys().cloned().collect())
            .unwrap_or_default();
        self.schedule(paths, Some(Duration::ZERO));
        self.schedule_workspace_report(Duration::ZERO);
        let caps = self.shared.lock().caps;
        if caps.pulls() {
            let client = self.client.clone();
            tokio::spawn(async move { client.workspace_diagnostic_refresh().await });
        }
    }

    pub(super) async fn publish(&self, path: String, generation: u64, delay: Duration) {
        if !delay.is_zero() {
            tokio::time::sleep(delay).await;
        }
        let current = |s: &State| {
            s.docs
                .get(&path)
                .is_some_and(|d| d.generation == generation)
        };
        let snap = self
            .mutate("publishing diagnostics", |s| {
                if !current(s) {
                    return None;
                }
                let uri = s.docs.get(&path)?.uri.clone();
                s.checkout(&uri)
            })
            .flatten();
        let Some((snap, check)) = snap else {
            return;
        };
        // Two phases, as the text changed: at once, the new syntax
        // diagnostics with the others carried over from the last check;
        // then the full check.
        let Ok((snap, quick)) = self
            .blocking("carrying diagnostics over", move || {
                let quick = snap.carried_over().map(|d| convert_diagnostics(&snap, &d));
                (snap, quick)
            })
            .await
        else {
            return;
        };
        // The check's result always follows a quick publication, even when
        // it is the same list: it tells the client the check is done.
        let quick_sent = quick.is_some();
        if let Some(quick) = quick {
            let _order = self.shared.publish.lock().await;
            let send = self.mutate("publishing diagnostics", |s| {
                current(s) && s.should_publish(&snap.path, snap.version, &quick, true)
            });
            if send == Some(true) {
                self.client
                    .publish_diagnostics(snap.uri.clone(), quick, snap.version)
                    .await;
            }
        }
        let Ok((snap, result, converted)) = self
            .blocking("computing diagnostics", move || {
                let result = check.map(rapid_analyzer::workspace::Check::run);
                let converted = match &result {
                    Some(r) => convert_diagnostics(&snap, &r.diagnostics),
                    None => convert_diagnostics(&snap, &snap.diagnostics()),
                };
                (snap, result, converted)
            })
            .await
        else {
            return;
        };
        let _order = self.shared.publish.lock().await;
        let send = self
            .mutate("publishing diagnostics", |s| {
                if let Some(result) = result {
                    s.finish_check(result);
                }
                current(s) && s.should_publish(&snap.path, snap.version, &converted, quick_sent)
            })
            .unwrap_or(false);
        if send {
            self.client
                .publish_diagnostics(snap.uri.clone(), converted, snap.version)
                .await;
        }
    }
}

pub(super) fn convert_diagnostics(
    snap: &Snapshot,
    raw: &[rapid_analyzer::diagnostic::Diagnostic],
) -> Vec<Diagnostic> {
    let reported = snap.settings.lint.apply(
        Path::new(&snap.path),
        &snap.unit.text,
        &snap.index,
        raw.to_vec(),
    );
    let mut out = diagnostics::to_lsp(
        &reported,
        &snap.map(),
        &snap.uri,
        &snap.settings,
        &|p, r| snap.location(p, r),
    );
    if snap.unit.text.len() > super::state::MAX_ANALYSED_BYTES {
        out.push(Diagnostic {
            range: Range::default(),
            severity: Some(DiagnosticSeverity::INFORMATION),
            source: Some("rapid".to_owned()),
            message: format!(
                "this file is too large to analyse ({} MB; the limit is {} MB)",
                snap.unit.text.len() / (1024 * 1024),
                super::state::MAX_ANALYSED_BYTES / (1024 * 1024)
            ),
            ..Diagnostic::default()
        });
    }
    out
}
