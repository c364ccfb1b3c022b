//! The server's state: the analysis host, the open documents, settings and
//! caches, behind one short synchronous lock; and snapshots handed to
//! requests that run off the main loop.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

use rapid_analyzer::carry::carry_over;
use rapid_analyzer::check::StmtCache;
use rapid_analyzer::diagnostic::Diagnostic;
use rapid_analyzer::rules::Selection;
use rapid_analyzer::task::{Task, Unit};
use rapid_analyzer::text::LineIndex;
use rapid_analyzer::workspace::{Check, CheckResult, Workspace, diagnostics_selected};
use tower_lsp_server::ls_types::{Location, Position, Uri};

use super::document::Document;
use super::position::{LineMap, PosEncoding};
use super::settings::Settings;
use crate::project::source::{SourceFile, Unreadable};

/// Files larger than the project's limit ([`crate::project::MAX_FILE_BYTES`])
/// are kept as text but not analysed: parsing tens of megabytes would stall
/// every request behind it, and no RAPID module is that large.
pub const MAX_ANALYSED_BYTES: usize = crate::project::MAX_FILE_BYTES as usize;

/// What the client can do, as far as the server cares.
#[derive(Clone, Copy, Debug, Default)]
pub struct ClientCaps {
    pub work_done_progress: bool,
    pub watch_files_dynamically: bool,
    pub pull_diagnostics: bool,
    pub diagnostic_refresh: bool,
    pub semantic_tokens_refresh: bool,
    /// The client resolves a completion item's `detail` when it shows the
    /// item (`completionItem.resolveSupport`): lists are sent without it.
    pub resolve_completion_detail: bool,
}

impl ClientCaps {
    /// Whether the client is served pull diagnostics: it pulls them and can
    /// be told to pull again when another file's edit changes them (VS
    /// Code). A client that pulls but cannot be told (Neovim 0.11) would
    /// show stale diagnostics for every file but the one being edited: it
    /// gets them pushed, as a client that does not pull at all.
    pub fn pulls(&self) -> bool {
        self.pull_diagnostics && self.diagnostic_refresh
    }
}

#[derive(Default)]
pub struct State {
    pub ws: Workspace,
    /// Open documents by path (the analyzer's name of the file).
    pub docs: HashMap<String, Document>,
    /// I/O configurations (`EIO.cfg`) open in the editor, with their text.
    pub open_configs: HashMap<String, String>,
    pub encoding: PosEncoding,
    pub settings: Settings,
    /// The client's settings as it sent them, to resolve again when
    /// `rapid.toml` changes.
    pub client_settings: serde_json::Value,
    pub caps: ClientCaps,
    /// Where the last completion list was asked for, so that resolving one
    /// of its items can find the item's detail.
    pub last_completion: Option<(Uri, Position)>,
    /// Workspace folders.
    pub roots: Vec<PathBuf>,
    /// Every change to the settings or the I/O configuration bumps this, so
    /// the reports of the files that are not open, converted with the
    /// settings, are made again (the analyzer's own results are keyed by
    /// what they read: [`Workspace::cached`]).
    pub config_generation: u64,
    /// The diagnostics last published per open document, with the version
    /// they were for: an unchanged list for the same version is not sent
    /// again (another file's edit re-checks this one, mostly to the same
    /// result).
    pub published: HashMap<String, (Option<i32>, Vec<tower_lsp_server::ls_types::Diagnostic>)>,
    /// The last semantic tokens sent per document, for deltas.
    pub semantic: HashMap<String, (String, Arc<Vec<u32>>)>,
    pub next_id: u64,
    /// RAPID files on disk that are not open, with their modification time,
    /// for polling when the client cannot watch files.
    pub disk: HashMap<PathBuf, Option<std::time::SystemTime>>,
    pub shutdown: bool,
    /// The diagnostics of the files that are not open, as last reported
    /// (see [`super::workspace_report`]).
    pub closed: HashMap<String, super::workspace_report::ClosedReport>,
    /// Bumped when a report of the files that are not open is scheduled: a
    /// run for an older one stops.
    pub closed_generation: u64,
    /// Folders indexed because a file outside every workspace folder was
    /// opened (the rest of its task).
    pub implicit_roots: Vec<PathBuf>,
}

/// The state, shared between the handlers.
#[derive(Default)]
pub struct Shared {
    state: Mutex<State>,
    /// Held while a publication is checked for staleness and sent, so a
    /// stale result can never overtake a newer one.
    pub publish: tokio::sync::Mutex<()>,
}

impl Shared {
    /// Locks the state. A panic while it was held poisons nothing that
    /// matters: the state stays consistent between statements.
    pub fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// An immutable view of one file and its task, for requests.
pub struct Snapshot {
    pub path: String,
    pub uri: Uri,
    pub version: Option<i32>,
    pub task: Arc<Task>,
    /// Index of the file in `task.units`.
    pub unit_idx: usize,
    pub unit: Arc<Unit>,
    pub index: Arc<LineIndex>,
    pub encoding: PosEncoding,
    pub settings: Arc<Settings>,
    /// URIs of open documents (which may not be `file:` URIs).
    pub uris: Arc<HashMap<String, Uri>>,
    /// The workspace's last diagnostics of the file, when they are for this
    /// text and task ([`Workspace::cached`]).
    pub cached: Option<Arc<Vec<Diagnostic>>>,
    /// The last diagnostics computed for an older text of the file, with
    /// that unit: carried over while the new ones are computed
    /// ([`Workspace::previous`]).
    pub previous: Option<(Arc<Unit>, Arc<Vec<Diagnostic>>)>,
    /// The rules the analyzer checks in this file (the lint settings'
    /// selection; severities and suppressions are applied after).
    pub selection: Selection,
    pub config_generation: u64,
    /// Line indexes of the task's other files, built on demand.
    pub other_indexes: Mutex<HashMap<String, Arc<LineIndex>>>,
    /// The other tasks of the controller that declare the persistent at
    /// the request's position, when it is a shared one
    /// ([`State::add_peers`]); empty otherwise.
    pub peers: Vec<Arc<Task>>,
}

impl Snapshot {
    pub fn map(&self) -> LineMap<'_> {
        LineMap::new(&self.unit.text, &self.index, self.encoding)
    }

    /// The URI of a file of the workspace.
    pub fn uri_of(&self, path: &str) -> Option<Uri> {
        uri_of(&self.uris, path)
    }

    /// An LSP location for a byte range of any unit of the task (or, failing
    /// that, of a file on disk).
    pub fn location(&self, path: &str, range: std::ops::Range<usize>) -> Option<Location> {
        let uri = self.uri_of(path)?;
        if path == self.path {
            return Some(Location::new(uri, self.map().range(range)));
        }
        let unit = self.unit_of(path)?;
        let index = self.line_index(path, unit);
        Some(Location::new(
            uri,
            LineMap::new(&unit.text, &index, self.encoding).range(range),
        ))
    }

    /// A unit of the task, or of one of its [`Snapshot::peers`].
    pub fn unit_of(&self, path: &str) -> Option<&Arc<Unit>> {
        std::iter::once(&self.task)
            .chain(&self.peers)
            .find_map(|t| t.units.iter().find(|u| u.path == path))
    }

    /// The line index of another unit of the task, built once per snapshot.
    pub fn line_index(&self, path: &str, unit: &Unit) -> Arc<LineIndex> {
        let mut cache = self
            .other_indexes
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        cache
            .entry(path.to_owned())
            .or_insert_with(|| Arc::new(LineIndex::new(&unit.text)))
            .clone()
    }

    /// The diagnostics to report: the analyzer's, with the lint settings
    /// (selection, severities, inline suppressions) applied.
    pub fn reported_diagnostics(&self) -> Vec<Diagnostic> {
        self.settings.lint.apply(
            Path::new(&self.path),
            &self.unit.text,
            &self.index,
            self.diagnostics().to_vec(),
        )
    }

    /// Diagnostics at once, without checking: the new text's syntax
    /// diagnostics and the previous text's other diagnostics moved past the
    /// edit (those inside the edited span are dropped). `None` when there is
    /// no previous result, or a fresh one is cached.
    pub fn carried_over(&self) -> Option<Vec<Diagnostic>> {
        if self.cached.is_some() {
            return None;
        }
        let (old_unit, old) = self.previous.as_ref()?;
        Some(carry_over(old_unit, old, &self.unit))
    }

    /// The analyzer's diagnostics of the file (cached when possible).
    pub fn diagnostics(&self) -> Arc<Vec<Diagnostic>> {
        match &self.cached {
            Some(d) => d.clone(),
            None => Arc::new(
                diagnostics_selected(
                    &self.task,
                    &self.unit,
                    StmtCache::default(),
                    &self.selection,
                )
                .0,
            ),
        }
    }
}

pub fn uri_of(uris: &HashMap<String, Uri>, path: &str) -> Option<Uri> {
    uris.get(path)
        .cloned()
        .or_else(|| Uri::from_file_path(path))
}

/// The analyzer's name for a document: its file path, or the URI itself
/// for documents that are not files (`untitled:`).
pub fn path_of(uri: &Uri) -> String {
    match uri.to_file_path() {
        Some(p) => p.to_string_lossy().into_owned(),
        None => uri.as_str().to_owned(),
    }
}

/// A controller configuration file the analyzer reads (`EIO.cfg` signals,
/// `MOC.cfg` mechanical units).
pub fn is_eio_cfg(path: &str) -> bool {
    rapid_analyzer::text::is_controller_config_name(path)
}

/// Parses a text into a unit, unless it is too large to analyse.
pub fn make_unit(path: String, text: String) -> Unit {
    if text.len() > MAX_ANALYSED_BYTES {
        Unit::from_tree(path, text, None)
    } else {
        Unit::new(path, text, None)
    }
}

/// A unit of a file that is not open in the editor: parsed for its items
/// and syntax diagnostics, then its tree released (trees are most of the
/// memory of a workspace; a feature that needs the syntax of a closed file
/// parses it again).
pub fn closed_unit(path: String, text: String) -> Unit {
    let mut unit = make_unit(path, text);
    unit.release_tree();
    unit
}

impl State {
    pub fn next_id(&mut self) -> u64 {
        self.next_id += 1;
        self.next_id
    }

    pub fn open_uris(&self) -> HashMap<String, Uri> {
        self.docs
            .iter()
            .map(|(p, d)| (p.clone(), d.uri.clone()))
            .collect()
    }

    /// A snapshot of a file: open, or known from disk.
    /// Sets the snapshot's [`Snapshot::peers`]: the tasks of the files that
    /// declare the shared persistent at `pos` in other tasks.
    pub fn add_peers(&mut self, snap: &mut Snapshot, pos: tower_lsp_server::ls_types::Position) {
        let offset = snap.map().offset(pos);
        snap.peers = rapid_analyzer::ide::shared_files(&snap.task, snap.unit_idx, offset)
            .iter()
            .map(|path| self.ws.task_of(path))
            .collect();
    }

    pub fn snapshot(&mut self, uri: &Uri) -> Option<Snapshot> {
        let path = path_of(uri);
        let (unit, index, version) = match self.docs.get(&path) {
            Some(doc) => (doc.unit.clone(), doc.index.clone(), Some(doc.version)),
            None => {
                let unit = self.ws.unit(&path)?.clone();
                let index = Arc::new(LineIndex::new(&unit.text));
                (unit, index, None)
            }
        };
        let task = self.ws.task_of(&path);
        let unit_idx = task.units.iter().position(|u| Arc::ptr_eq(u, &unit))?;
        let selection = self.settings.lint.selection_for(Path::new(&path));
        let cached = self.ws.cached(&path, &unit, &task, &selection);
        let previous = self.ws.previous(&path, &unit);
        Some(Snapshot {
            uri: uri.clone(),
            path,
            version,
            task,
            unit_idx,
            unit,
            index,
            encoding: self.encoding,
            settings: Arc::new(self.settings.clone()),
            uris: Arc::new(self.open_uris()),
            cached,
            previous,
            selection,
            config_generation: self.config_generation,
            other_indexes: Mutex::default(),
            peers: Vec::new(),
        })
    }

    /// A snapshot of a file, with a check of it to run off the lock unless
    /// its diagnostics are cached ([`Workspace::check`]: the check takes
    /// the statement results of the file's last check; give its result
    /// back with [`State::finish_check`]).
    pub fn checkout(&mut self, uri: &Uri) -> Option<(Snapshot, Option<Check>)> {
        let snap = self.snapshot(uri)?;
        let check = snap.cached.is_none().then(|| {
            self.ws.check(
                &snap.path,
                snap.unit.clone(),
                snap.task.clone(),
                snap.selection.clone(),
            )
        });
        Some((snap, check))
    }

    /// Keeps the result of a check as the file's last one (its statement
    /// results only while the file is open: they serve the next edit).
    pub fn finish_check(&mut self, result: CheckResult) {
        let open = self.docs.contains_key(&result.path);
        self.ws.finish(result, open);
    }

    /// Whether `diagnostics` for `version` of `path` are to be published:
    /// `always`, or when they differ from what was last published for it.
    /// Remembers them as published if so.
    pub fn should_publish(
        &mut self,
        path: &str,
        version: Option<i32>,
        diagnostics: &[tower_lsp_server::ls_types::Diagnostic],
        always: bool,
    ) -> bool {
        if !always
            && let Some((v, d)) = self.published.get(path)
            && *v == version
            && d.as_slice() == diagnostics
        {
            return false;
        }
        self.published
            .insert(path.to_owned(), (version, diagnostics.to_vec()));
        true
    }

    /// Open documents of the task of `path`, other than `path`, grouped as
    /// the workspace groups them (a `.pgf` program's modules may be in
    /// several folders).
    pub fn open_in_task(&self, path: &str) -> Vec<String> {
        let key = self.ws.task_key(path);
        self.docs
            .keys()
            .filter(|p| *p != path && self.ws.task_key(p) == key)
            .cloned()
            .collect()
    }

    /// Reads a file from disk into the workspace (unless it is open: the
    /// editor's text wins). Returns whether what the other files' checks
    /// read of it changed ([`Workspace::set_unit`]).
    pub fn load_from_disk(&mut self, path: &Path) -> Result<bool, Unreadable> {
        let name = path.to_string_lossy().into_owned();
        if is_eio_cfg(&name) {
            let bytes = crate::project::source::read_regular(path).map_err(Unreadable::Io)?;
            self.ws.set_config(&name, &String::from_utf8_lossy(&bytes));
            self.config_generation += 1;
            return Ok(true);
        }
        self.disk.insert(path.to_owned(), mtime(path));
        if self.docs.contains_key(&name) {
            return Ok(false);
        }
        match SourceFile::read(path) {
            Ok(file) => Ok(self.ws.set_unit(closed_unit(name.clone(), file.text))),
            Err(why) => {
                self.ws.remove_file(&name);
                Err(why)
            }
        }
    }

    /// Forgets a file deleted from disk (unless it is open).
    pub fn remove_from_disk(&mut self, path: &Path) {
        let name = path.to_string_lossy().into_owned();
        self.disk.remove(path);
        if is_eio_cfg(&name) {
            self.ws.remove_config(&name);
            self.config_generation += 1;
        } else if !self.docs.contains_key(&name) {
            self.ws.remove_file(&name);
        }
    }
}

pub fn mtime(path: &Path) -> Option<std::time::SystemTime> {
    std::fs::metadata(path).and_then(|m| m.modified()).ok()
}
