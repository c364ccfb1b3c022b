//! Finding the RAPID files, programs and configuration under some paths.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use rapid_analyzer::text::{is_controller_config_name, is_program_file_name, is_rapid_file_name};

use super::{Disk, Environment, Kind, Walked};

/// The files found, and the problems met on the way.
#[derive(Debug, Default)]
pub struct Discovery {
    /// RAPID files, sorted, without duplicates.
    pub files: Vec<PathBuf>,
    /// Controller configuration files (`EIO.cfg` signals, `MOC.cfg`
    /// mechanical units), sorted.
    pub configs: Vec<PathBuf>,
    /// Program files (`.pgf`: the modules of one task), sorted.
    pub programs: Vec<PathBuf>,
    /// Paths that could not be walked, with the reason.
    pub errors: Vec<(PathBuf, String)>,
    /// Things worth saying that do not stop the run (a folder reached twice
    /// through a link, a FIFO or a device named like a module), with the
    /// path.
    pub warnings: Vec<(PathBuf, String)>,
}

impl Discovery {
    /// Adds what `other` found (files, configuration, programs; errors and
    /// warnings), keeping each list sorted and without duplicates.
    pub fn extend(&mut self, other: Discovery) {
        self.files.extend(other.files);
        self.configs.extend(other.configs);
        self.programs.extend(other.programs);
        self.errors.extend(other.errors);
        self.warnings.extend(other.warnings);
        for list in [&mut self.files, &mut self.configs, &mut self.programs] {
            list.sort();
            list.dedup();
        }
    }
}

/// Says whether a path (a folder when the flag is set) is left out.
pub type Excluder = Arc<dyn Fn(&Path, bool) -> bool + Send + Sync>;

/// [`discover_with`] without excluding anything.
pub fn discover(paths: &[PathBuf]) -> Discovery {
    discover_with(paths, Arc::new(|_, _| false))
}

/// Walks `paths` on the disk: [`discover_in`] of [`Disk`].
pub fn discover_with(paths: &[PathBuf], excluded: Excluder) -> Discovery {
    discover_in(&Disk, paths, excluded, None)
}

/// Walks `paths` in `env` (folders recursively, honouring `.gitignore`,
/// `.ignore` and git's global excludes on the disk; hidden folders are
/// walked too, since controller backups have none worth skipping) and
/// collects RAPID files, configuration and programs. A file named
/// explicitly is taken whatever its extension. `excluded(path, is_folder)`
/// says what to leave out, named explicitly or not (so a pre-commit hook,
/// which names files, honours the exclude list too).
pub fn discover_in(
    env: &dyn Environment,
    paths: &[PathBuf],
    excluded: Excluder,
    max_depth: Option<usize>,
) -> Discovery {
    let mut out = Discovery::default();
    for root in paths {
        match env.kind(root) {
            Err(e) => {
                out.errors.push((root.clone(), e.to_string()));
                continue;
            }
            Ok(Kind::File(_)) => {
                if !excluded(root, false) {
                    let name = root.file_name().unwrap_or_default().to_string_lossy();
                    if is_controller_config_name(&name) {
                        out.configs.push(root.clone());
                    } else if let Some(modules) = named_program(env, root) {
                        // Naming a program names the modules it lists.
                        if modules.is_empty() {
                            out.warnings.push((
                                root.clone(),
                                "the program lists no module that exists".into(),
                            ));
                        }
                        out.programs.push(root.clone());
                        out.files.extend(modules);
                    } else {
                        out.files.push(root.clone());
                    }
                }
                continue;
            }
            Ok(Kind::Other(what)) => {
                if !excluded(root, false) {
                    out.warnings.push((root.clone(), not_a_file(what)));
                }
                continue;
            }
            Ok(Kind::Folder) => {}
        }
        if excluded(root, true) {
            continue;
        }
        for walked in env.walk(root, max_depth, &excluded) {
            match walked {
                Walked::Entry(path, kind) => {
                    let name = path.file_name().unwrap_or_default().to_string_lossy();
                    let is_file = matches!(kind, Kind::File(_));
                    if is_file && is_rapid_file_name(&name) {
                        out.files.push(path);
                    } else if is_file && is_controller_config_name(&name) {
                        out.configs.push(path);
                    } else if let Kind::Other(what) = kind
                        && (is_rapid_file_name(&name) || is_controller_config_name(&name))
                    {
                        // A FIFO, a socket or a device (or a link to one)
                        // named like a module: never read (a FIFO would
                        // block), and said.
                        out.warnings.push((path, not_a_file(what)));
                    } else if is_file && is_program_file_name(&name) {
                        // Some tools write RAPID text into `.pgf` files.
                        if is_xml(env, &path) {
                            out.programs.push(path);
                        } else {
                            out.files.push(path);
                        }
                    }
                }
                Walked::Error(path, why) => {
                    out.errors.push((path.unwrap_or_else(|| root.clone()), why));
                }
                Walked::Warning(path, why) => out.warnings.push((path, why)),
            }
        }
    }
    out.files.sort();
    out.files.dedup();
    out.configs.sort();
    out.configs.dedup();
    out.programs.sort();
    out.programs.dedup();
    out
}

/// The entries below `root` on the disk, walked with `ignore`.
pub(super) fn walk_disk(root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked> {
    let excluded = excluded.clone();
    let walker = ignore::WalkBuilder::new(root)
        .hidden(false)
        .follow_links(true)
        .require_git(false)
        .max_depth(max_depth)
        .filter_entry(move |entry| {
            entry.file_name() != ".git"
                && !excluded(entry.path(), entry.file_type().is_some_and(|t| t.is_dir()))
        })
        .build();
    let mut out = Vec::new();
    for entry in walker {
        match entry {
            Ok(entry) => {
                let kind = match entry.file_type() {
                    Some(t) if t.is_file() => Kind::File(0),
                    Some(t) if t.is_dir() => Kind::Folder,
                    Some(t) => Kind::Other(super::source::kind_of(&t)),
                    None => continue,
                };
                out.push(Walked::Entry(entry.into_path(), kind));
            }
            Err(e) => {
                let path = error_path(&e).map(Path::to_owned);
                if is_loop(&e) {
                    out.push(Walked::Warning(
                        path.unwrap_or_else(|| root.to_owned()),
                        "a link leads back to a folder above it; the folder is checked once"
                            .to_owned(),
                    ));
                } else if is_broken_link(path.as_deref().unwrap_or(root)) {
                    // A dangling link matters only if it was meant to be a module.
                    let path = path.unwrap_or_else(|| root.to_owned());
                    let name = path.file_name().unwrap_or_default().to_string_lossy();
                    if is_rapid_file_name(&name) {
                        out.push(Walked::Error(
                            Some(path),
                            "a broken symbolic link (its target is missing)".to_owned(),
                        ));
                    }
                } else {
                    out.push(Walked::Error(path, io_message(&e)));
                }
            }
        }
    }
    out
}

/// Why an entry named like a RAPID file is skipped.
fn not_a_file(what: &str) -> String {
    format!("skipped: {what}, not a file that can be read")
}

/// The modules that the file `path` lists when it is a program (an XML
/// `.pgf`), those that exist; `None` for any other file (RAPID text written
/// into a `.pgf` is a module).
pub fn named_program(env: &dyn Environment, path: &Path) -> Option<Vec<PathBuf>> {
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    (is_program_file_name(&name) && is_xml(env, path))
        .then(|| super::context::program_members(env, std::iter::once(&path.to_path_buf())))
}

/// Does the file start like XML (after a byte-order mark and blanks)? A
/// `.pgf` program file does; RAPID text written into a `.pgf` does not.
fn is_xml(env: &dyn Environment, path: &Path) -> bool {
    let mut head = [0u8; 64];
    let n = env.read_head(path, &mut head).unwrap_or(0);
    let head = head.get(..n).unwrap_or_default();
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    head.iter()
        .find(|b| !b.is_ascii_whitespace())
        .is_some_and(|&b| b == b'<')
}

fn is_loop(e: &ignore::Error) -> bool {
    match e {
        ignore::Error::Loop { .. } => true,
        ignore::Error::WithPath { err, .. }
        | ignore::Error::WithDepth { err, .. }
        | ignore::Error::WithLineNumber { err, .. } => is_loop(err),
        _ => false,
    }
}

fn is_broken_link(path: &Path) -> bool {
    path.symlink_metadata()
        .is_ok_and(|m| m.file_type().is_symlink())
        && path.metadata().is_err()
}

/// The walker's message without the path it repeats.
fn io_message(e: &ignore::Error) -> String {
    match e {
        ignore::Error::WithPath { err, .. } | ignore::Error::WithDepth { err, .. } => {
            io_message(err)
        }
        other => other.to_string(),
    }
}

fn error_path(e: &ignore::Error) -> Option<&Path> {
    match e {
        ignore::Error::WithPath { path, .. } => Some(path),
        ignore::Error::WithDepth { err, .. } | ignore::Error::WithLineNumber { err, .. } => {
            error_path(err)
        }
        ignore::Error::Loop { child, .. } => Some(child),
        _ => None,
    }
}
