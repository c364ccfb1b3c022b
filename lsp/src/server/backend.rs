//! The protocol handlers.

use std::collections::{HashMap, HashSet};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use rapid_analyzer::format::FormatOptions;
use rapid_analyzer::ide;
use rapid_analyzer::text::{LineIndex, is_rapid_file_name};
use serde_json::Value;
use tower_lsp_server::jsonrpc::{Error, ErrorCode, Result};
use tower_lsp_server::ls_types::request::{
    GotoDeclarationParams, GotoDeclarationResponse, GotoTypeDefinitionParams,
    GotoTypeDefinitionResponse,
};
use tower_lsp_server::ls_types::*;
use tower_lsp_server::{Client, LanguageServer};

use super::diagnostics;
use super::document::{Document, apply_changes, apply_text_changes};
use super::position::PosEncoding;
use super::requests;
use super::settings::Settings;
use super::state::{
    ClientCaps, Shared, Snapshot, State, closed_unit, is_eio_cfg, make_unit, path_of,
};

/// How long after an edit that changed a module's interface the files that
/// are not open are checked again (each is a whole check: not on every
/// keystroke).
const CLOSED_FILES_DELAY: Duration = Duration::from_millis(600);

/// The extensions of RAPID files, in the letter cases seen in practice, for
/// file watchers (LSP glob patterns are case-sensitive).
const WATCH_GLOBS: &[&str] = &[
    "**/*.{mod,modx,sys,sysx,prg}",
    "**/*.{MOD,MODX,SYS,SYSX,PRG}",
    "**/*.{Mod,Modx,Sys,Sysx,Prg}",
    "**/{EIO,eio,Eio}.{cfg,CFG}",
    "**/rapid.toml",
];

/// The handle every handler and background job shares.
#[derive(Clone)]
pub struct Backend {
    pub(super) client: Client,
    pub(super) shared: Arc<Shared>,
    shut_down: Arc<AtomicBool>,
}

/// A panic's message.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_owned())
}

fn internal_error(what: &str) -> Error {
    Error {
        code: ErrorCode::InternalError,
        message: format!("rapid: {what} failed (internal error; see the server log)").into(),
        data: None,
    }
}

fn request_failed(message: String) -> Error {
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

    async fn log(&self, typ: MessageType, message: String) {
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
    async fn on_snapshot<R: Send + 'static>(
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

    /// Definition, declaration and type definition: the locations `find`
    /// gives for the position.
    async fn goto(
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

    // ---- diagnostics ---------------------------------------------------

    /// Schedules a publication of diagnostics for each open document in
    /// `paths`, after `delay`. A later schedule for the same document
    /// supersedes this one.
    fn schedule(&self, paths: Vec<String>, delay: Option<Duration>) {
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
    fn republish_all(&self) {
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

    async fn publish(&self, path: String, generation: u64, delay: Duration) {
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
                let snap = s.snapshot(&uri)?;
                // Taken, not shared: a check still running for an older
                // text finds none and starts afresh.
                let statements = s.statements.remove(&path).unwrap_or_default();
                Some((snap, statements))
            })
            .flatten();
        let Some((snap, statements)) = snap else {
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
        let Ok((snap, raw, statements, converted)) = self
            .blocking("computing diagnostics", move || {
                let (raw, statements) = snap.diagnostics_reusing(statements);
                let converted = convert_diagnostics(&snap, &raw);
                (snap, raw, statements, converted)
            })
            .await
        else {
            return;
        };
        let _order = self.shared.publish.lock().await;
        let send = self
            .mutate("publishing diagnostics", |s| {
                s.cache_diagnostics(&snap, raw);
                if s.docs.contains_key(&snap.path) {
                    s.statements.insert(snap.path.clone(), statements);
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

    // ---- workspace -----------------------------------------------------

    /// Reads every RAPID file and `EIO.cfg` under the workspace folders and
    /// the extra paths, reporting progress.
    async fn index_workspace(&self) {
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

    async fn register_watchers(&self) {
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
    async fn poll_disk(&self) {
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

    /// Resolves the settings again: `rapid.toml` from the first workspace
    /// folder, the client's settings over it (`client`, or the last ones).
    fn reload_settings(&self, client: Option<&Value>) -> Vec<String> {
        let (roots, client) = {
            let mut s = self.shared.lock();
            if let Some(c) = client {
                s.client_settings = c.clone();
            }
            (s.roots.clone(), s.client_settings.clone())
        };
        let root = roots.first().cloned().unwrap_or_default();
        let mut problems = Vec::new();
        let file =
            crate::config::find(&root).and_then(|path| match crate::config::read_text(&path) {
                Ok(text) => Some((path, text)),
                Err(e) => {
                    problems.push(format!("{}: {e}", path.display()));
                    None
                }
            });
        let (settings, more) = Settings::resolve(
            &client,
            file.as_ref().map(|(p, t)| (p.as_path(), t.as_str())),
            &root,
        );
        problems.extend(more);
        self.mutate("applying settings", |s| {
            s.ws.set_controller(settings.config.controller.resolve().unwrap_or_default());
            s.settings = settings;
            s.config_generation += 1;
        });
        problems
    }

    fn format_options(&self) -> FormatOptions {
        self.shared.lock().settings.config.format.options()
    }
}

/// Reads and parses `files` in parallel into the workspace (files open in
/// the editor keep the editor's text), counting them in `done`; returns the
/// files that could not be read, with why.
fn read_units(
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

fn client_caps(params: &InitializeParams) -> ClientCaps {
    let caps = &params.capabilities;
    let window = caps.window.as_ref();
    let workspace = caps.workspace.as_ref();
    ClientCaps {
        work_done_progress: window.and_then(|w| w.work_done_progress) == Some(true),
        watch_files_dynamically: workspace
            .and_then(|w| w.did_change_watched_files.as_ref())
            .and_then(|d| d.dynamic_registration)
            == Some(true),
        pull_diagnostics: caps
            .text_document
            .as_ref()
            .is_some_and(|t| t.diagnostic.is_some()),
        diagnostic_refresh: workspace
            .and_then(|w| w.diagnostics.as_ref())
            .and_then(|d| d.refresh_support)
            == Some(true),
        semantic_tokens_refresh: workspace
            .and_then(|w| w.semantic_tokens.as_ref())
            .and_then(|d| d.refresh_support)
            == Some(true),
        resolve_completion_detail: caps
            .text_document
            .as_ref()
            .and_then(|t| t.completion.as_ref())
            .and_then(|c| c.completion_item.as_ref())
            .and_then(|i| i.resolve_support.as_ref())
            .is_some_and(|r| r.properties.iter().any(|p| p == "detail")),
    }
}

#[allow(
    deprecated,
    reason = "root_uri and root_path are still sent by older clients"
)]
fn workspace_roots(params: &InitializeParams) -> Vec<PathBuf> {
    let mut roots: Vec<PathBuf> = params
        .workspace_folders
        .iter()
        .flatten()
        .filter_map(|f| f.uri.to_file_path().map(|p| p.into_owned()))
        .collect();
    if roots.is_empty() {
        if let Some(p) = params.root_uri.as_ref().and_then(|u| u.to_file_path()) {
            roots.push(p.into_owned());
        } else if let Some(p) = &params.root_path {
            roots.push(PathBuf::from(p));
        }
    }
    roots
}

fn server_capabilities(encoding: PosEncoding, caps: ClientCaps) -> ServerCapabilities {
    let token_types = ide::TOKEN_TYPES
        .iter()
        .map(|t| SemanticTokenType::new(t))
        .collect();
    let token_modifiers = ide::TOKEN_MODIFIERS
        .iter()
        .map(|t| SemanticTokenModifier::new(t))
        .collect();
    ServerCapabilities {
        position_encoding: Some(encoding.kind()),
        text_document_sync: Some(TextDocumentSyncCapability::Options(
            TextDocumentSyncOptions {
                open_close: Some(true),
                change: Some(TextDocumentSyncKind::INCREMENTAL),
                save: Some(TextDocumentSyncSaveOptions::Supported(true)),
                ..TextDocumentSyncOptions::default()
            },
        )),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        completion_provider: Some(CompletionOptions {
            resolve_provider: Some(true),
            trigger_characters: Some(vec!["\\".to_owned(), ".".to_owned(), ":".to_owned()]),
            ..CompletionOptions::default()
        }),
        signature_help_provider: Some(SignatureHelpOptions {
            trigger_characters: Some(vec![
                "\\".to_owned(),
                ",".to_owned(),
                "(".to_owned(),
                " ".to_owned(),
            ]),
            retrigger_characters: None,
            work_done_progress_options: WorkDoneProgressOptions::default(),
        }),
        definition_provider: Some(OneOf::Left(true)),
        declaration_provider: Some(DeclarationCapability::Simple(true)),
        type_definition_provider: Some(TypeDefinitionProviderCapability::Simple(true)),
        references_provider: Some(OneOf::Left(true)),
        document_highlight_provider: Some(OneOf::Left(true)),
        rename_provider: Some(OneOf::Right(RenameOptions {
            prepare_provider: Some(true),
            work_done_progress_options: WorkDoneProgressOptions::default(),
        })),
        document_symbol_provider: Some(OneOf::Left(true)),
        workspace_symbol_provider: Some(OneOf::Left(true)),
        semantic_tokens_provider: Some(SemanticTokensServerCapabilities::SemanticTokensOptions(
            SemanticTokensOptions {
                legend: SemanticTokensLegend {
                    token_types,
                    token_modifiers,
                },
                range: Some(true),
                full: Some(SemanticTokensFullOptions::Delta { delta: Some(true) }),
                work_done_progress_options: WorkDoneProgressOptions::default(),
            },
        )),
        folding_range_provider: Some(FoldingRangeProviderCapability::Simple(true)),
        selection_range_provider: Some(SelectionRangeProviderCapability::Simple(true)),
        inlay_hint_provider: Some(OneOf::Left(true)),
        code_action_provider: Some(CodeActionProviderCapability::Options(CodeActionOptions {
            code_action_kinds: Some(vec![CodeActionKind::QUICKFIX, CodeActionKind::REFACTOR]),
            ..CodeActionOptions::default()
        })),
        document_formatting_provider: Some(OneOf::Left(true)),
        document_range_formatting_provider: Some(OneOf::Left(true)),
        workspace: Some(WorkspaceServerCapabilities {
            workspace_folders: Some(WorkspaceFoldersServerCapabilities {
                supported: Some(true),
                change_notifications: Some(OneOf::Left(true)),
            }),
            file_operations: None,
        }),
        // Pull diagnostics only for clients that can be told to pull again
        // (see ClientCaps::pulls); the others get them pushed.
        diagnostic_provider: caps.pulls().then(|| {
            DiagnosticServerCapabilities::Options(DiagnosticOptions {
                identifier: Some("rapid".to_owned()),
                inter_file_dependencies: true,
                workspace_diagnostics: true,
                work_done_progress_options: WorkDoneProgressOptions::default(),
            })
        }),
        ..ServerCapabilities::default()
    }
}

impl LanguageServer for Backend {
    async fn initialize(&self, params: InitializeParams) -> Result<InitializeResult> {
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

    async fn initialized(&self, _: InitializedParams) {
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

    async fn shutdown(&self) -> Result<()> {
        self.shut_down.store(true, Ordering::SeqCst);
        self.mutate("shutting down", |s| s.shutdown = true);
        Ok(())
    }

    async fn did_open(&self, params: DidOpenTextDocumentParams) {
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
                let before = s.ws.unit(&path).map(|u| u.interface);
                s.ws.set_unit(make_unit(path.clone(), doc.text, None));
                let unit = s.ws.unit(&path)?.clone();
                let changed = before != Some(unit.interface);
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

    async fn did_change(&self, params: DidChangeTextDocumentParams) {
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
            let old_interface = doc.unit.interface;
            let unit = apply_changes(&doc.unit, &doc.index, &params.content_changes, encoding);
            let changed = unit.interface != old_interface;
            s.ws.set_unit(unit);
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

    async fn did_save(&self, _: DidSaveTextDocumentParams) {}

    async fn did_close(&self, params: DidCloseTextDocumentParams) {
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
                let doc = s.docs.remove(&path)?;
                s.semantic.remove(&path);
                s.diagnostics.remove(&path);
                s.statements.remove(&path);
                s.published.remove(&path);
                let before = doc.unit.interface;
                // The file goes back to its state on disk.
                let p = PathBuf::from(&path);
                let changed = if p.is_file() {
                    match s.load_from_disk(&p) {
                        Ok(_) => s.ws.unit(&path).map(|u| u.interface) != Some(before),
                        Err(_) => true,
                    }
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

    async fn did_change_watched_files(&self, params: DidChangeWatchedFilesParams) {
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

    async fn did_change_workspace_folders(&self, params: DidChangeWorkspaceFoldersParams) {
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

    async fn did_change_configuration(&self, params: DidChangeConfigurationParams) {
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

    async fn diagnostic(
        &self,
        params: DocumentDiagnosticParams,
    ) -> Result<DocumentDiagnosticReportResult> {
        let previous = params.previous_result_id;
        let computed = self
            .on_snapshot(&params.text_document.uri, "diagnostics", |snap| {
                convert_diagnostics(snap, &snap.diagnostics())
            })
            .await?;
        let items = computed.unwrap_or_default();
        let result_id = diagnostics::result_id(&items);
        let report = if previous.as_deref() == Some(result_id.as_str()) {
            DocumentDiagnosticReport::Unchanged(RelatedUnchangedDocumentDiagnosticReport {
                related_documents: None,
                unchanged_document_diagnostic_report: UnchangedDocumentDiagnosticReport {
                    result_id,
                },
            })
        } else {
            DocumentDiagnosticReport::Full(RelatedFullDocumentDiagnosticReport {
                related_documents: None,
                full_document_diagnostic_report: FullDocumentDiagnosticReport {
                    result_id: Some(result_id),
                    items,
                },
            })
        };
        Ok(DocumentDiagnosticReportResult::Report(report))
    }

    async fn workspace_diagnostic(
        &self,
        params: WorkspaceDiagnosticParams,
    ) -> Result<WorkspaceDiagnosticReportResult> {
        Ok(self.workspace_report(params).await)
    }

    async fn hover(&self, params: HoverParams) -> Result<Option<Hover>> {
        let p = params.text_document_position_params;
        let pos = p.position;
        Ok(self
            .on_snapshot(&p.text_document.uri, "hover", move |s| {
                requests::hover(s, pos)
            })
            .await?
            .flatten())
    }

    async fn completion(&self, params: CompletionParams) -> Result<Option<CompletionResponse>> {
        let p = params.text_document_position;
        let pos = p.position;
        let uri = p.text_document.uri;
        let lazy = self
            .mutate("completion", |s| {
                s.last_completion = Some((uri.clone(), pos));
                s.caps.resolve_completion_detail
            })
            .unwrap_or(false);
        Ok(self
            .on_snapshot(&uri, "completion", move |s| {
                requests::completion(s, pos, lazy)
            })
            .await?
            .map(CompletionResponse::List))
    }

    async fn completion_resolve(&self, item: CompletionItem) -> Result<CompletionItem> {
        // An item sent without its detail finds it again in the list it
        // came from.
        let origin = self
            .mutate("completion resolve", |s| {
                let (uri, pos) = s.last_completion.clone()?;
                Some((s.snapshot(&uri)?, pos))
            })
            .flatten();
        self.blocking("completion resolve", move || {
            requests::resolve_completion(item, origin.as_ref().map(|(s, p)| (s, *p)))
        })
        .await
    }

    async fn signature_help(&self, params: SignatureHelpParams) -> Result<Option<SignatureHelp>> {
        let p = params.text_document_position_params;
        let pos = p.position;
        Ok(self
            .on_snapshot(&p.text_document.uri, "signature help", move |s| {
                requests::signature_help(s, pos)
            })
            .await?
            .flatten())
    }

    async fn goto_definition(
        &self,
        params: GotoDefinitionParams,
    ) -> Result<Option<GotoDefinitionResponse>> {
        self.goto(
            params.text_document_position_params,
            "definition",
            ide::definition,
        )
        .await
    }

    async fn goto_declaration(
        &self,
        params: GotoDeclarationParams,
    ) -> Result<Option<GotoDeclarationResponse>> {
        self.goto(
            params.text_document_position_params,
            "declaration",
            ide::definition,
        )
        .await
    }

    async fn goto_type_definition(
        &self,
        params: GotoTypeDefinitionParams,
    ) -> Result<Option<GotoTypeDefinitionResponse>> {
        self.goto(
            params.text_document_position_params,
            "type definition",
            ide::type_definition,
        )
        .await
    }

    async fn references(&self, params: ReferenceParams) -> Result<Option<Vec<Location>>> {
        let p = params.text_document_position;
        let pos = p.position;
        let decl = params.context.include_declaration;
        self.on_snapshot(&p.text_document.uri, "references", move |s| {
            let found = ide::references(&s.task, s.unit_idx, s.map().offset(pos), decl);
            requests::locations(s, found)
        })
        .await
    }

    async fn document_highlight(
        &self,
        params: DocumentHighlightParams,
    ) -> Result<Option<Vec<DocumentHighlight>>> {
        let p = params.text_document_position_params;
        let pos = p.position;
        self.on_snapshot(&p.text_document.uri, "document highlight", move |s| {
            requests::document_highlights(s, pos)
        })
        .await
    }

    async fn prepare_rename(
        &self,
        params: TextDocumentPositionParams,
    ) -> Result<Option<PrepareRenameResponse>> {
        let pos = params.position;
        let answer = self
            .on_snapshot(&params.text_document.uri, "prepare rename", move |s| {
                ide::prepare_rename(&s.task, s.unit_idx, s.map().offset(pos))
                    .map(|r| PrepareRenameResponse::Range(s.map().range(r)))
            })
            .await?;
        match answer {
            None => Ok(None),
            Some(Ok(r)) => Ok(Some(r)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }

    async fn rename(&self, params: RenameParams) -> Result<Option<WorkspaceEdit>> {
        let p = params.text_document_position;
        let pos = p.position;
        let new_name = params.new_name;
        let answer = self
            .on_snapshot(&p.text_document.uri, "rename", move |s| {
                ide::rename(&s.task, s.unit_idx, s.map().offset(pos), &new_name)
                    .map(|files| requests::workspace_edit(s, files))
            })
            .await?;
        match answer {
            None => Ok(None),
            Some(Ok(edit)) => Ok(Some(edit)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }

    async fn document_symbol(
        &self,
        params: DocumentSymbolParams,
    ) -> Result<Option<DocumentSymbolResponse>> {
        Ok(self
            .on_snapshot(&params.text_document.uri, "document symbols", |s| {
                requests::document_symbols(s)
            })
            .await?
            .map(DocumentSymbolResponse::Nested))
    }

    async fn symbol(
        &self,
        params: WorkspaceSymbolParams,
    ) -> Result<Option<WorkspaceSymbolResponse>> {
        let (tasks, encoding, uris) = self
            .mutate("workspace symbols", |s| {
                (s.ws.tasks(), s.encoding, s.open_uris())
            })
            .ok_or_else(|| internal_error("workspace symbols"))?;
        let query = params.query;
        let found = self
            .blocking("workspace symbols", move || {
                requests::workspace_symbols(&tasks, &query, encoding, &uris)
            })
            .await?;
        Ok(Some(WorkspaceSymbolResponse::Nested(found)))
    }

    async fn semantic_tokens_full(
        &self,
        params: SemanticTokensParams,
    ) -> Result<Option<SemanticTokensResult>> {
        let uri = params.text_document.uri;
        let Some(data) = self
            .on_snapshot(&uri, "semantic tokens", |s| {
                requests::semantic_tokens(s, None)
            })
            .await?
        else {
            return Ok(None);
        };
        let result_id = self.remember_tokens(&uri, &data);
        Ok(Some(SemanticTokensResult::Tokens(SemanticTokens {
            result_id: Some(result_id),
            data,
        })))
    }

    async fn semantic_tokens_full_delta(
        &self,
        params: SemanticTokensDeltaParams,
    ) -> Result<Option<SemanticTokensFullDeltaResult>> {
        let uri = params.text_document.uri;
        let previous = self
            .shared
            .lock()
            .semantic
            .get(&path_of(&uri))
            .filter(|(id, _)| *id == params.previous_result_id)
            .map(|(_, data)| data.clone());
        let Some(data) = self
            .on_snapshot(&uri, "semantic tokens", |s| {
                requests::semantic_tokens(s, None)
            })
            .await?
        else {
            return Ok(None);
        };
        let flat = requests::tokens_to_flat(&data);
        let result_id = self.remember_tokens(&uri, &data);
        Ok(Some(match previous {
            Some(old) => SemanticTokensFullDeltaResult::TokensDelta(SemanticTokensDelta {
                result_id: Some(result_id),
                edits: requests::semantic_delta(&old, &flat).into_iter().collect(),
            }),
            None => SemanticTokensFullDeltaResult::Tokens(SemanticTokens {
                result_id: Some(result_id),
                data,
            }),
        }))
    }

    async fn semantic_tokens_range(
        &self,
        params: SemanticTokensRangeParams,
    ) -> Result<Option<SemanticTokensRangeResult>> {
        let range = params.range;
        Ok(self
            .on_snapshot(&params.text_document.uri, "semantic tokens", move |s| {
                let span = s.map().offset_range(range);
                requests::semantic_tokens(s, Some(span))
            })
            .await?
            .map(|data| {
                SemanticTokensRangeResult::Tokens(SemanticTokens {
                    result_id: None,
                    data,
                })
            }))
    }

    async fn folding_range(&self, params: FoldingRangeParams) -> Result<Option<Vec<FoldingRange>>> {
        self.on_snapshot(&params.text_document.uri, "folding ranges", |s| {
            requests::folding_ranges(s)
        })
        .await
    }

    async fn selection_range(
        &self,
        params: SelectionRangeParams,
    ) -> Result<Option<Vec<SelectionRange>>> {
        let positions = params.positions;
        self.on_snapshot(&params.text_document.uri, "selection ranges", move |s| {
            requests::selection_ranges(s, &positions)
        })
        .await
    }

    async fn inlay_hint(&self, params: InlayHintParams) -> Result<Option<Vec<InlayHint>>> {
        let range = params.range;
        self.on_snapshot(&params.text_document.uri, "inlay hints", move |s| {
            requests::inlay_hints(s, range)
        })
        .await
    }

    async fn code_action(&self, params: CodeActionParams) -> Result<Option<CodeActionResponse>> {
        let range = params.range;
        self.on_snapshot(&params.text_document.uri, "code actions", move |s| {
            requests::code_actions(s, range)
        })
        .await
    }

    async fn formatting(&self, params: DocumentFormattingParams) -> Result<Option<Vec<TextEdit>>> {
        let uri = params.text_document.uri;
        let options = self.format_options();
        match self
            .on_snapshot(&uri, "formatting", move |s| {
                requests::format(s, None, &options)
            })
            .await?
        {
            None => Ok(None),
            Some(Ok(edits)) => Ok(Some(edits)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }

    async fn range_formatting(
        &self,
        params: DocumentRangeFormattingParams,
    ) -> Result<Option<Vec<TextEdit>>> {
        let uri = params.text_document.uri;
        let range = params.range;
        let options = self.format_options();
        match self
            .on_snapshot(&uri, "formatting", move |s| {
                requests::format(s, Some(range), &options)
            })
            .await?
        {
            None => Ok(None),
            Some(Ok(edits)) => Ok(Some(edits)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }
}

impl Backend {
    /// Keeps the tokens sent for a document, for the next delta request.
    fn remember_tokens(&self, uri: &Uri, data: &[SemanticToken]) -> String {
        let flat = Arc::new(requests::tokens_to_flat(data));
        self.mutate("semantic tokens", |s| {
            let id = s.next_id().to_string();
            s.semantic.insert(path_of(uri), (id.clone(), flat));
            id
        })
        .unwrap_or_default()
    }
}

#[cfg(test)]
impl Backend {
    pub async fn test_panic(&self) -> Result<Value> {
        self.blocking("the test method", || -> Value {
            panic!("deliberate test panic")
        })
        .await
    }
}
