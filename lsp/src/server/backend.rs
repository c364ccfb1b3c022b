//! The server's handle: the state shared by every handler and background
//! job, and how handlers run (state mutations and blocking work guarded so
//! a panic becomes an error answer). The handlers live by concern in
//! `lifecycle`, `sync`, `handlers`, `publish`, `indexing`, `watch`,
//! `configure` and `capabilities`.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::Duration;

use rapid_analyzer::ide;
use tower_lsp_server::Client;
use tower_lsp_server::jsonrpc::{Error, ErrorCode, Result};
use tower_lsp_server::ls_types::*;

use super::requests;
use super::state::{Shared, Snapshot, State};

/// How long after an edit that changed a module's interface the files that
/// are not open are checked again (each is a whole check: not on every
/// keystroke).
pub(super) const CLOSED_FILES_DELAY: Duration = Duration::from_millis(600);

/// The handle every handler and background job shares.
#[derive(Clone)]
pub struct Backend {
    pub(super) client: Client,
    pub(super) shared: Arc<Shared>,
    pub(super) shut_down: Arc<AtomicBool>,
}

/// A panic's message.
pub(super) fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_owned())
}

pub(super) fn internal_error(what: &str) -> Error {
    Error {
        code: ErrorCode::InternalError,
        message: format!("rapid: {what} failed (internal error; see the server log)").into(),
        data: None,
    }
}

pub(super) fn request_failed(message: String) -> Error {
    Error {
        // RequestFailed in LSP 3.17.
        code: ErrorCode::ServerError(-32803),
        message: message.into(),
        data: None,
    }
}

impl Backend {
    pub fn new(client: Client, shut_down: Arc<AtomicBool>) -> Backend {
        Backend {
            client,
            shared: Arc::new(Shared::default()),
            shut_down,
        }
    }

    pub(super) async fn log(&self, typ: MessageType, message: String) {
        self.client.log_message(typ, message).await;
    }

    /// Runs a mutation of the state, catching panics (the state is left as
    /// it was at the panic, which is always consistent enough to go on).
    pub(super) fn mutate<R>(&self, what: &str, f: impl FnOnce(&mut State) -> R) -> Option<R> {
        let mut state = self.shared.lock();
        match catch_unwind(AssertUnwindSafe(|| f(&mut state))) {
            Ok(r) => Some(r),
            Err(payload) => {
                eprintln!("rapid lsp: {what} panicked: {}", panic_message(&*payload));
                None
            }
        }
    }

    /// Runs `f` on a snapshot of `uri`'s file on the blocking pool. A file
    /// the server does not know gives `Ok(None)`; a panic gives an error.
    pub(super) async fn on_snapshot<R: Send + 'static>(
        &self,
        uri: &Uri,
        what: &'static str,
        f: impl FnOnce(&Snapshot) -> R + Send + 'static,
    ) -> Result<Option<R>> {
        let snap = self.mutate(what, |s| s.snapshot(uri)).flatten();
        let Some(snap) = snap else {
            return Ok(None);
        };
        self.blocking(what, move || f(&snap)).await.map(Some)
    }

    /// [`Backend::on_snapshot`] with the snapshot's peers: the tasks that
    /// share the persistent at `pos` ([`State::add_peers`]).
    pub(super) async fn on_snapshot_with_peers<R: Send + 'static>(
        &self,
        uri: &Uri,
        pos: Position,
        what: &'static str,
        f: impl FnOnce(&Snapshot) -> R + Send + 'static,
    ) -> Result<Option<R>> {
        let snap = self
            .mutate(what, |s| {
                let mut snap = s.snapshot(uri)?;
                s.add_peers(&mut snap, pos);
                Some(snap)
            })
            .flatten();
        let Some(snap) = snap else {
            return Ok(None);
        };
        self.blocking(what, move || f(&snap)).await.map(Some)
    }

    /// Runs `f` on a snapshot of `uri`'s file and its diagnostics on the
    /// blocking pool: the cached ones, or a check run there (reusing the
    /// statement results of the file's last check) whose result the
    /// workspace keeps.
    pub(super) async fn on_checked<R: Send + 'static>(
        &self,
        uri: &Uri,
        what: &'static str,
        f: impl FnOnce(&Snapshot, &[rapid_analyzer::diagnostic::Diagnostic]) -> R + Send + 'static,
    ) -> Result<Option<R>> {
        let Some((snap, check)) = self.mutate(what, |s| s.checkout(uri)).flatten() else {
            return Ok(None);
        };
        let (out, result) = self
            .blocking(what, move || match check {
                Some(check) => {
                    let result = check.run();
                    (f(&snap, &result.diagnostics), Some(result))
                }
                None => (f(&snap, &snap.diagnostics()), None),
            })
            .await?;
        if let Some(result) = result {
            self.mutate(what, |s| s.finish_check(result));
        }
        Ok(Some(out))
    }

    /// Definition, declaration and type definition: the locations `find`
    /// gives for the position.
    pub(super) async fn goto(
        &self,
        p: TextDocumentPositionParams,
        what: &'static str,
        find: fn(&rapid_analyzer::task::Task, usize, usize) -> Vec<ide::Location>,
    ) -> Result<Option<GotoDefinitionResponse>> {
        let pos = p.position;
        Ok(self
            .on_snapshot(&p.text_document.uri, what, move |s| {
                let found = find(&s.task, s.unit_idx, s.map().offset(pos));
                requests::locations(s, found)
            })
            .await?
            .map(GotoDefinitionResponse::Array))
    }

    pub(super) async fn blocking<R: Send + 'static>(
        &self,
        what: &'static str,
        f: impl FnOnce() -> R + Send + 'static,
    ) -> Result<R> {
        match tokio::task::spawn_blocking(f).await {
            Ok(r) => Ok(r),
            Err(e) => {
                let message = if e.is_panic() {
                    panic_message(&*e.into_panic())
                } else {
                    "cancelled".to_owned()
                };
                self.log(MessageType::ERROR, format!("{what} failed: {message}"))
                    .await;
                Err(internal_error(what))
            }
        }
    }
}
