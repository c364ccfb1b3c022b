//! Starting and stopping: `initialize` (capabilities, settings),
//! `initialized` (watchers, indexing, polling) and `shutdown`.

use std::sync::atomic::Ordering;

use serde_json::Value;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::*;

use super::position::PosEncoding;

use super::backend::*;
use super::capabilities::{client_caps, server_capabilities, workspace_roots};

impl Backend {
    pub(super) async fn handle_initialize(
        &self,
        params: InitializeParams,
    ) -> Result<InitializeResult> {
        let encoding = PosEncoding::negotiate(
            params
                .capabilities
                .general
                .as_ref()
                .and_then(|g| g.position_encodings.as_deref()),
        );
        let caps = client_caps(&params);
        if let Some(pid) = params.process_id {
            super::exit_with_parent(pid);
        }
        self.mutate("initializing", |s| {
            s.encoding = encoding;
            s.caps = caps;
            s.roots = workspace_roots(&params);
        });
        let options = params.initialization_options.clone().unwrap_or(Value::Null);
        let problems = self.reload_settings(Some(&options));
        for p in problems {
            self.log(MessageType::WARNING, format!("settings: {p}"))
                .await;
        }
        Ok(InitializeResult {
            capabilities: server_capabilities(encoding, caps),
            server_info: Some(ServerInfo {
                name: "rapid".to_owned(),
                version: Some(env!("CARGO_PKG_VERSION").to_owned()),
            }),
            offset_encoding: None,
        })
    }

    pub(super) async fn handle_initialized(&self, _params: InitializedParams) {
        let caps = self.shared.lock().caps;
        // Requests to the client run on their own: an `initialized` that
        // waits for the client's answers would hold up `exit`.
        if caps.watch_files_dynamically {
            let this = self.clone();
            tokio::spawn(async move { this.register_watchers().await });
        }
        let this = self.clone();
        tokio::spawn(async move {
            this.index_workspace().await;
            // Polling starts from the indexed workspace (its first walk
            // would read every file again otherwise).
            if !caps.watch_files_dynamically {
                this.poll_disk().await;
            }
        });
    }

    pub(super) async fn handle_shutdown(&self) -> Result<()> {
        self.shut_down.store(true, Ordering::SeqCst);
        self.mutate("shutting down", |s| s.shutdown = true);
        Ok(())
    }
}
