//! The project loader: the one place that finds a project's files (walking
//! folders, ignores, `.pgf` programs, controller configuration, the extra
//! paths of `rapid.toml`), reads and decodes them within the size limit,
//! and builds the analyzer's [`Workspace`] from them, so that `rapid
//! check`, `rapid eval`, `rapid run`/`test`/`dap`, `rapid fmt` (finding
//! files only) and the language server (finding and reading) see the same
//! files and group them into the same tasks.
//!
//! Every file-system access goes through an [`Environment`] ([`Disk`] in
//! the binary), so the loader is tested on a file system in memory.

pub mod context;
mod discover;
mod load;
pub mod parts;
pub mod source;
#[cfg(test)]
mod tests;

use std::path::{Path, PathBuf};

pub use discover::{Discovery, Excluder, discover, discover_in, discover_with, named_program};
pub use load::{Loaded, Sources, assemble, load, load_around, read_and_parse_with};
pub use source::{SourceFile, Unreadable};

/// Files larger than this are not modules a controller would load: `rapid
/// check` skips them with a message, and the language server keeps their
/// text without analysing it.
pub const MAX_FILE_BYTES: u64 = 8 * 1024 * 1024;

/// What a path is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A regular file of this many bytes.
    File(u64),
    Folder,
    /// Anything else (a FIFO, a socket, a device), in words.
    Other(&'static str),
}

/// One entry met walking a folder.
#[derive(Debug)]
pub enum Walked {
    /// A file, folder or other entry (the size of a file is not needed
    /// here and may be 0).
    Entry(PathBuf, Kind),
    /// A path that could not be walked (the root when `None`), with why.
    Error(Option<PathBuf>, String),
    /// Something worth saying that does not stop the walk.
    Warning(PathBuf, String),
}

/// The file system as the loader sees it.
pub trait Environment: Sync {
    /// What `path` is (links followed).
    fn kind(&self, path: &Path) -> std::io::Result<Kind>;
    /// The bytes of a regular file (anything else is an error naming what
    /// it is, found without blocking).
    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>>;
    /// The first bytes of a file, into `buf`; how many were read.
    fn read_head(&self, path: &Path, buf: &mut [u8]) -> std::io::Result<usize>;
    /// The entries below the folder `root`, at most `max_depth` levels
    /// down, leaving out what `excluded` says.
    fn walk(&self, root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked>;
    /// The name the analyzer knows a file by (see
    /// [`source::analyzer_path`]).
    fn name(&self, path: &Path) -> String;
}

/// The real file system.
pub struct Disk;

impl Environment for Disk {
    fn kind(&self, path: &Path) -> std::io::Result<Kind> {
        let meta = std::fs::metadata(path)?;
        Ok(if meta.is_file() {
            Kind::File(meta.len())
        } else if meta.is_dir() {
            Kind::Folder
        } else {
            Kind::Other(source::kind_of(&meta.file_type()))
        })
    }

    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        source::read_regular(path)
    }

    fn read_head(&self, path: &Path, buf: &mut [u8]) -> std::io::Result<usize> {
        use std::io::Read;
        std::fs::File::open(path).and_then(|mut f| f.read(buf))
    }

    fn walk(&self, root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked> {
        discover::walk_disk(root, max_depth, excluded)
    }

    fn name(&self, path: &Path) -> String {
        source::analyzer_path(path)
    }
}

/// An environment that asks `inner` for each path's analyzer name once: a
/// name resolves links on disk ([`source::analyzer_path`]), and the loader
/// asks for the name of each file several times (discovery, parts, parse,
/// tasks). For one run (`rapid check`): a long-lived server must see a
/// link that changes.
pub struct NamedOnce<'e> {
    inner: &'e dyn Environment,
    names: std::sync::Mutex<std::collections::HashMap<PathBuf, String>>,
}

impl<'e> NamedOnce<'e> {
    pub fn new(inner: &'e dyn Environment) -> NamedOnce<'e> {
        NamedOnce {
            inner,
            names: Default::default(),
        }
    }
}

impl Environment for NamedOnce<'_> {
    fn kind(&self, path: &Path) -> std::io::Result<Kind> {
        self.inner.kind(path)
    }

    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        self.inner.read(path)
    }

    fn read_head(&self, path: &Path, buf: &mut [u8]) -> std::io::Result<usize> {
        self.inner.read_head(path, buf)
    }

    fn walk(&self, root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked> {
        self.inner.walk(root, max_depth, excluded)
    }

    fn name(&self, path: &Path) -> String {
        let known = |names: &std::collections::HashMap<PathBuf, String>| names.get(path).cloned();
        if let Some(name) = self.names.lock().ok().and_then(|n| known(&n)) {
            return name;
        }
        // Resolved outside the lock: another thread may resolve it too.
        let name = self.inner.name(path);
        if let Ok(mut names) = self.names.lock() {
            names.insert(path.to_owned(), name.clone());
        }
        name
    }
}

/// Why a file was not loaded.
#[derive(Debug)]
pub enum Skip {
    Unreadable(Unreadable),
    TooLarge(u64),
}

impl Skip {
    /// An IO error fails the run (exit 2); an encrypted or binary file does not.
    pub fn is_error(&self) -> bool {
        matches!(self, Skip::Unreadable(Unreadable::Io(_)))
    }
}

impl std::fmt::Display for Skip {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Skip::Unreadable(why) => why.fmt(f),
            Skip::TooLarge(bytes) => write!(
                f,
                "skipped: {:.1} MB is more than the {} MB a module may have here",
                *bytes as f64 / 1e6,
                MAX_FILE_BYTES / (1024 * 1024)
            ),
        }
    }
}

/// Reads and decodes one RAPID file: a regular file within
/// [`MAX_FILE_BYTES`], as text.
pub fn read_source(env: &dyn Environment, path: &Path) -> Result<SourceFile, Skip> {
    let len = match env.kind(path) {
        Err(e) => return Err(Skip::Unreadable(Unreadable::Io(e))),
        Ok(Kind::File(len)) => len,
        Ok(Kind::Folder) => return Err(not_a_file(path, "a folder")),
        Ok(Kind::Other(what)) => return Err(not_a_file(path, what)),
    };
    if len > MAX_FILE_BYTES {
        return Err(Skip::TooLarge(len));
    }
    let bytes = env
        .read(path)
        .map_err(|e| Skip::Unreadable(Unreadable::Io(e)))?;
    SourceFile::from_bytes(path.to_owned(), &bytes).map_err(Skip::Unreadable)
}

fn not_a_file(_path: &Path, what: &str) -> Skip {
    Skip::Unreadable(Unreadable::Io(std::io::Error::other(format!(
        "{what}, not a file"
    ))))
}

/// The size of a file, 0 when it is not one (to read large files first).
pub fn size_of(env: &dyn Environment, path: &Path) -> u64 {
    match env.kind(path) {
        Ok(Kind::File(len)) => len,
        _ => 0,
    }
}

/// The disk, with files named as the paths given name them rather than
/// by their real place: for `rapid run`, `rapid test` and `rapid dap`,
/// whose reports show the paths the user typed, without their `.`
/// components ([`plain`]).
pub struct DiskAsNamed;

impl Environment for DiskAsNamed {
    fn kind(&self, path: &Path) -> std::io::Result<Kind> {
        Disk.kind(path)
    }

    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        Disk.read(path)
    }

    fn read_head(&self, path: &Path, buf: &mut [u8]) -> std::io::Result<usize> {
        Disk.read_head(path, buf)
    }

    fn walk(&self, root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked> {
        Disk.walk(root, max_depth, excluded)
    }

    fn name(&self, path: &Path) -> String {
        plain(path).to_string_lossy().into_owned()
    }
}

/// `path` without its `.` components: `./Cell.mod`, `Cell.mod` and the
/// `./Cell.mod` that walking `.` finds are one file, and `./MOC.cfg` is
/// beside it (in the folder `""`, the task of `Cell.mod`). `..` stays: it
/// cannot be resolved without the file system. `.` when nothing is left.
pub fn plain(path: &Path) -> PathBuf {
    let out: PathBuf = path
        .components()
        .filter(|c| *c != std::path::Component::CurDir)
        .collect();
    if out.as_os_str().is_empty() {
        PathBuf::from(".")
    } else {
        out
    }
}
