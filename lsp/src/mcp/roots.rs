//! What `rapid mcp` may read: the folders it is given (`--root`, and the
//! client's roots when it shares them), and the project loader's
//! [`Environment`] confined to them, with the unsaved texts of a request
//! laid over the disk.
//!
//! Every path a tool names is resolved here first (relative paths start at
//! the first root; links and `..` are resolved before the comparison) and
//! refused when it is outside every root. The loader then reads through
//! [`Confined`], so the rest of a task (`SYSPAR`, sibling modules, the
//! `rapid.toml` above a file, `extra-paths`) is read only where it lies
//! inside the roots too.

use std::collections::HashMap;
use std::path::{Component, Path, PathBuf};
use std::sync::Mutex;

use crate::project::{Disk, Environment, Excluder, Kind, Walked};

/// The folders the server may read.
pub struct Roots {
    /// `--root` folders, resolved.
    given: Vec<PathBuf>,
    /// The current folder, the root when nothing else is given.
    default: PathBuf,
    /// The client's roots, once asked for (`None`: not known yet, or the
    /// client has none).
    client: Mutex<ClientRoots>,
}

#[derive(Default)]
struct ClientRoots {
    known: Option<Vec<PathBuf>>,
    /// The client said its roots changed since they were asked for.
    stale: bool,
}

impl Roots {
    /// The roots of `--root` (each must be a folder), else the current
    /// folder until the client names its own.
    pub fn new(given: &[PathBuf]) -> Result<Roots, String> {
        let mut resolved = Vec::new();
        for root in given {
            let real = std::fs::canonicalize(root)
                .map_err(|e| format!("--root {}: {e}", root.display()))?;
            if !real.is_dir() {
                return Err(format!("--root {}: not a folder", root.display()));
            }
            resolved.push(real);
        }
        let default = std::env::current_dir()
            .and_then(std::fs::canonicalize)
            .map_err(|e| format!("the current folder: {e}"))?;
        Ok(Roots {
            given: resolved,
            default,
            client: Mutex::default(),
        })
    }

    /// The roots in force: `--root` and the client's; the current folder
    /// when there are neither.
    pub fn current(&self) -> Vec<PathBuf> {
        let mut roots = self.given.clone();
        if let Ok(client) = self.client.lock()
            && let Some(known) = &client.known
        {
            roots.extend(known.iter().cloned());
        }
        if roots.is_empty() {
            roots.push(self.default.clone());
        }
        roots.dedup();
        roots
    }

    /// Whether the client's roots should be asked for (again).
    pub fn wants_client_roots(&self) -> bool {
        self.client
            .lock()
            .is_ok_and(|c| c.known.is_none() || c.stale)
    }

    /// The client's roots (`file:` URIs), as it listed them; folders that
    /// do not exist are left out.
    pub fn set_client<'a>(&self, uris: impl Iterator<Item = &'a str>) {
        let folders: Vec<PathBuf> = uris
            .filter_map(path_of_uri)
            .filter_map(|p| std::fs::canonicalize(p).ok())
            .filter(|p| p.is_dir())
            .collect();
        if let Ok(mut client) = self.client.lock() {
            client.known = Some(folders);
            client.stale = false;
        }
    }

    /// The client said its roots changed.
    pub fn client_changed(&self) {
        if let Ok(mut client) = self.client.lock() {
            client.stale = true;
        }
    }
}

/// The path of a `file:` URI.
fn path_of_uri(uri: &str) -> Option<PathBuf> {
    use std::str::FromStr;
    let uri = tower_lsp_server::ls_types::Uri::from_str(uri).ok()?;
    uri.to_file_path().map(|p| p.into_owned())
}

/// Where `path` really is: the path with links and `..` resolved, or for a
/// file that does not exist (an unsaved module), its resolved folder and
/// its name. `None` when neither exists.
pub fn real_path(path: &Path) -> Option<PathBuf> {
    if let Ok(real) = std::fs::canonicalize(path) {
        return Some(real);
    }
    let name = match path.components().next_back()? {
        Component::Normal(name) => name,
        _ => return None,
    };
    let parent = path.parent().filter(|p| !p.as_os_str().is_empty())?;
    Some(std::fs::canonicalize(parent).ok()?.join(name))
}

/// `path` (relative: to the first root), a file or folder that exists,
/// resolved and checked to be inside `roots`, or why not.
pub fn resolve(roots: &[PathBuf], path: &str) -> Result<PathBuf, String> {
    let real = resolve_unsaved(roots, path)?;
    if !real.exists() {
        return Err(format!("{path}: no such file or folder"));
    }
    Ok(real)
}

/// [`resolve`] for the file of an unsaved text, which need not exist (its
/// folder must).
pub fn resolve_unsaved(roots: &[PathBuf], path: &str) -> Result<PathBuf, String> {
    let given = Path::new(path.trim());
    if given.as_os_str().is_empty() {
        return Err("the path is empty".to_owned());
    }
    let joined = match roots.first() {
        Some(first) if given.is_relative() => first.join(given),
        _ => given.to_owned(),
    };
    let Some(real) = real_path(&joined) else {
        return Err(format!(
            "{path}: no such file or folder (relative paths start at {})",
            roots
                .first()
                .map_or_else(|| ".".to_owned(), |r| r.display().to_string())
        ));
    };
    if !inside(roots, &real) {
        return Err(outside(path, roots));
    }
    Ok(real)
}

/// The message for a path outside the roots.
pub fn outside(path: &str, roots: &[PathBuf]) -> String {
    let list: Vec<String> = roots.iter().map(|r| r.display().to_string()).collect();
    format!(
        "{path}: outside the folders this server may read ({}); start it with `--root FOLDER` \
         or open the folder in the client",
        list.join(", ")
    )
}

fn inside(roots: &[PathBuf], real: &Path) -> bool {
    roots.iter().any(|r| real.starts_with(r))
}

/// The disk as far as the roots reach, with unsaved texts over it.
pub struct Confined {
    roots: Vec<PathBuf>,
    /// Unsaved texts by their real path: they hide the file there, or
    /// stand for one that does not exist.
    overlay: HashMap<PathBuf, String>,
}

impl Confined {
    pub fn new(roots: Vec<PathBuf>) -> Confined {
        Confined {
            roots,
            overlay: HashMap::new(),
        }
    }

    /// Lays `text` over the file at `path` (a real path, see
    /// [`real_path`], or an absolute path in no folder for a text that
    /// belongs to no task).
    pub fn lay(&mut self, path: PathBuf, text: String) {
        self.overlay.insert(path, text);
    }

    fn unsaved(&self, path: &Path) -> Option<(&PathBuf, &String)> {
        if self.overlay.is_empty() {
            return None;
        }
        let absolute = std::path::absolute(path).ok()?;
        if let Some(found) = self
            .overlay
            .get_key_value(&crate::check::normalize(&absolute))
        {
            return Some(found);
        }
        self.overlay.get_key_value(&real_path(&absolute)?)
    }

    fn allowed(&self, path: &Path) -> std::io::Result<()> {
        let real = std::path::absolute(path).ok().and_then(|p| real_path(&p));
        match real {
            Some(real) if inside(&self.roots, &real) => Ok(()),
            Some(_) => Err(std::io::Error::new(
                std::io::ErrorKind::PermissionDenied,
                "outside the folders this server may read",
            )),
            None => Err(std::io::Error::new(
                std::io::ErrorKind::NotFound,
                "no such file or folder",
            )),
        }
    }
}

impl Environment for Confined {
    fn kind(&self, path: &Path) -> std::io::Result<Kind> {
        if let Some((_, text)) = self.unsaved(path) {
            return Ok(Kind::File(text.len() as u64));
        }
        self.allowed(path)?;
        Disk.kind(path)
    }

    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        if let Some((_, text)) = self.unsaved(path) {
            return Ok(text.as_bytes().to_vec());
        }
        self.allowed(path)?;
        Disk.read(path)
    }

    fn read_head(&self, path: &Path, buf: &mut [u8]) -> std::io::Result<usize> {
        if let Some((_, text)) = self.unsaved(path) {
            let n = text.len().min(buf.len());
            buf[..n].copy_from_slice(&text.as_bytes()[..n]);
            return Ok(n);
        }
        self.allowed(path)?;
        Disk.read_head(path, buf)
    }

    fn walk(&self, root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked> {
        let mut out: Vec<Walked> = match self.allowed(root) {
            Ok(()) => Disk
                .walk(root, max_depth, excluded)
                .into_iter()
                .filter(|w| match w {
                    // A link inside a root may point out of it.
                    Walked::Entry(p, _) | Walked::Warning(p, _) => self.allowed(p).is_ok(),
                    Walked::Error(p, _) => p.as_deref().is_none_or(|p| self.allowed(p).is_ok()),
                })
                .collect(),
            Err(e) => vec![Walked::Error(None, e.to_string())],
        };
        // Unsaved texts of files that do not exist yet.
        let real_root = std::path::absolute(root).ok().and_then(|p| real_path(&p));
        for (path, text) in &self.overlay {
            let Some(rest) = real_root.as_ref().and_then(|r| path.strip_prefix(r).ok()) else {
                continue;
            };
            let depth = rest.components().count();
            if max_depth.is_some_and(|d| depth > d) || path.exists() || excluded(path, false) {
                continue;
            }
            let shown = root.join(rest);
            out.push(Walked::Entry(shown, Kind::File(text.len() as u64)));
        }
        out
    }

    fn name(&self, path: &Path) -> String {
        match self.unsaved(path) {
            Some((real, _)) => real.to_string_lossy().into_owned(),
            None => Disk.name(path),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nothing_excluded() -> Excluder {
        std::sync::Arc::new(|_, _| false)
    }

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("rapid-mcp-roots-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("inner")).expect("a scratch folder");
        std::fs::canonicalize(dir).expect("a real path")
    }

    #[test]
    fn paths_outside_the_roots_are_refused() {
        let dir = scratch("refuse");
        std::fs::write(dir.join("inner/a.mod"), "MODULE a\nENDMODULE\n").expect("write");
        std::fs::write(dir.join("b.mod"), "MODULE b\nENDMODULE\n").expect("write");
        let roots = vec![dir.join("inner")];
        assert_eq!(
            resolve(&roots, "a.mod").expect("inside"),
            dir.join("inner/a.mod")
        );
        // An unsaved module that does not exist yet, inside.
        assert!(resolve_unsaved(&roots, "new.mod").is_ok());
        assert!(resolve(&roots, "new.mod").is_err());
        for outside in [
            "../b.mod",
            "..",
            dir.join("b.mod").to_str().unwrap_or_default(),
        ] {
            let err = resolve(&roots, outside).expect_err("outside");
            assert!(err.contains("outside the folders"), "{err}");
        }
        let env = Confined::new(roots);
        assert!(env.read(&dir.join("b.mod")).is_err());
        assert!(env.read(&dir.join("inner/../b.mod")).is_err());
        assert!(env.read(&dir.join("inner/a.mod")).is_ok());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[cfg(unix)]
    #[test]
    fn a_link_out_of_a_root_is_not_followed() {
        let dir = scratch("link");
        std::fs::write(dir.join("secret.mod"), "MODULE s\nENDMODULE\n").expect("write");
        std::os::unix::fs::symlink(dir.join("secret.mod"), dir.join("inner/link.mod"))
            .expect("a link");
        let roots = vec![dir.join("inner")];
        assert!(resolve(&roots, "link.mod").is_err());
        let env = Confined::new(roots);
        let walked = env.walk(&dir.join("inner"), None, &nothing_excluded());
        assert!(
            !walked
                .iter()
                .any(|w| matches!(w, Walked::Entry(p, _) if p.ends_with("link.mod"))),
            "{walked:?}"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn unsaved_texts_lie_over_the_disk() {
        let dir = scratch("overlay");
        std::fs::write(dir.join("inner/a.mod"), "MODULE a\nENDMODULE\n").expect("write");
        let mut env = Confined::new(vec![dir.clone()]);
        env.lay(
            dir.join("inner/a.mod"),
            "MODULE changed\nENDMODULE\n".into(),
        );
        env.lay(dir.join("inner/new.mod"), "MODULE new\nENDMODULE\n".into());
        let read = env.read(&dir.join("inner/a.mod")).expect("read");
        assert!(String::from_utf8_lossy(&read).contains("changed"));
        let walked = env.walk(&dir, None, &nothing_excluded());
        let files: Vec<_> = walked
            .iter()
            .filter_map(|w| match w {
                Walked::Entry(p, Kind::File(_)) => p.file_name(),
                _ => None,
            })
            .collect();
        assert!(
            files.contains(&std::ffi::OsStr::new("new.mod")),
            "{files:?}"
        );
        assert!(files.contains(&std::ffi::OsStr::new("a.mod")), "{files:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
