//! A git revision as a file system for the project loader: the tree of a
//! commit, listed with `git ls-tree` and read with one `git cat-file
//! --batch`, through the `git` command (no library: the user's git, with
//! its configuration, is what knows the repository).
//!
//! Files are named `REV:/path/from/the/top` (`HEAD~1:/cell/RAPID/TASK1/...`):
//! below the first part, a backup in a commit has the folders it has on
//! disk, so the loader groups it the same way.

use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Component, Path, PathBuf};
use std::process::{Command, Stdio};

use crate::project::{Environment, Excluder, Kind, Walked};

/// The files of one revision that the loader can use.
pub struct GitTree {
    files: BTreeMap<PathBuf, Vec<u8>>,
}

/// A revision opened: its files and the paths asked for, named in it.
pub struct Opened {
    pub tree: GitTree,
    pub roots: Vec<PathBuf>,
}

fn git(cwd: &Path) -> Command {
    let mut c = Command::new("git");
    c.current_dir(cwd);
    c
}

/// The output of a git command, or its error message.
fn output(cmd: &mut Command, what: &str) -> Result<Vec<u8>, String> {
    let out = cmd
        .stdin(Stdio::null())
        .output()
        .map_err(|e| format!("cannot run git ({e}): {what} needs it"))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return Err(format!("{what}: {}", err.trim()));
    }
    Ok(out.stdout)
}

/// Is `rev` a commit of the repository around `cwd`?
pub fn is_revision(cwd: &Path, rev: &str) -> bool {
    git(cwd)
        .args(["rev-parse", "--verify", "--quiet", "--end-of-options"])
        .arg(format!("{rev}^{{commit}}"))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .stdin(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// Is this a file the loader or the comparison reads (a module, a program,
/// a configuration file, a backup's description)?
fn wanted(path: &str) -> bool {
    let name = path.rsplit('/').next().unwrap_or(path);
    rapid_analyzer::text::is_rapid_file_name(name)
        || rapid_analyzer::text::is_program_file_name(name)
        || rapid_analyzer::controller::is_controller_info_name(path)
        || name.to_ascii_lowercase().ends_with(".cfg")
}

/// Opens revision `rev` of the repository around `cwd`, with the files
/// below `paths` (relative to `cwd`; the whole tree below `cwd` when empty).
pub fn open(cwd: &Path, rev: &str, paths: &[PathBuf]) -> Result<Opened, String> {
    if !is_revision(cwd, rev) {
        return Err(format!("`{rev}` is not a commit of a git repository here"));
    }
    let prefix = output(
        git(cwd).args(["rev-parse", "--show-prefix"]),
        "finding the repository",
    )?;
    let prefix = String::from_utf8_lossy(&prefix).trim().to_owned();
    let asked: Vec<PathBuf> = if paths.is_empty() {
        vec![PathBuf::from(".")]
    } else {
        paths.to_vec()
    };
    let listing = output(
        git(cwd)
            .args([
                "ls-tree",
                "-r",
                "-z",
                "-l",
                "--full-name",
                "--end-of-options",
                rev,
                "--",
            ])
            .args(&asked),
        &format!("listing `{rev}`"),
    )?;
    // `<mode> <type> <object> <size>\t<path>`, NUL-terminated.
    let mut blobs: Vec<(String, String)> = Vec::new();
    for entry in listing.split(|b| *b == 0) {
        let entry = String::from_utf8_lossy(entry);
        let Some((meta, path)) = entry.split_once('\t') else {
            continue;
        };
        let mut parts = meta.split_whitespace();
        let (_, kind, object) = (parts.next(), parts.next(), parts.next());
        if kind == Some("blob")
            && wanted(path)
            && let Some(object) = object
        {
            blobs.push((object.to_owned(), path.to_owned()));
        }
    }
    let contents = cat_files(cwd, blobs.iter().map(|(o, _)| o.as_str()))?;
    let files = blobs
        .into_iter()
        .zip(contents)
        .map(|((_, path), bytes)| (named(rev, &path), bytes))
        .collect();
    let roots = asked
        .iter()
        .map(|p| named(rev, &join(&prefix, p)))
        .collect();
    Ok(Opened {
        tree: GitTree { files },
        roots,
    })
}

/// `REV:/path`.
fn named(rev: &str, path: &str) -> PathBuf {
    let path = path.trim_matches('/');
    if path.is_empty() {
        PathBuf::from(format!("{rev}:"))
    } else {
        PathBuf::from(format!("{rev}:/{path}"))
    }
}

/// `prefix` (`sub/`, from the top) and `p` (relative to it), with `.` and
/// `..` resolved.
fn join(prefix: &str, p: &Path) -> String {
    let mut parts: Vec<String> = prefix
        .split('/')
        .filter(|s| !s.is_empty())
        .map(str::to_owned)
        .collect();
    for c in p.components() {
        match c {
            Component::Normal(s) => parts.push(s.to_string_lossy().into_owned()),
            Component::ParentDir => {
                parts.pop();
            }
            _ => {}
        }
    }
    parts.join("/")
}

/// The contents of `objects`, in order, from one `git cat-file --batch`.
fn cat_files<'a>(
    cwd: &Path,
    objects: impl Iterator<Item = &'a str>,
) -> Result<Vec<Vec<u8>>, String> {
    let input: String = objects.map(|o| format!("{o}\n")).collect();
    if input.is_empty() {
        return Ok(Vec::new());
    }
    let mut child = git(cwd)
        .args(["cat-file", "--batch"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("cannot run git ({e})"))?;
    let mut stdin = child.stdin.take().ok_or("git cat-file has no input")?;
    // Written on its own thread: git answers while it reads.
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let stdout = child.stdout.take().ok_or("git cat-file has no output")?;
    let mut reader = BufReader::new(stdout);
    let mut out = Vec::new();
    let mut header = String::new();
    loop {
        header.clear();
        if reader
            .read_line(&mut header)
            .map_err(|e| format!("reading from git: {e}"))?
            == 0
        {
            break;
        }
        // `<object> <type> <size>`, or `<object> missing`.
        let size = header
            .split_whitespace()
            .nth(2)
            .and_then(|s| s.parse::<usize>().ok());
        let Some(size) = size else {
            out.push(Vec::new());
            continue;
        };
        let mut bytes = vec![0; size + 1];
        reader
            .read_exact(&mut bytes)
            .map_err(|e| format!("reading from git: {e}"))?;
        bytes.pop();
        out.push(bytes);
    }
    let _ = writer.join();
    let _ = child.wait();
    Ok(out)
}

impl GitTree {
    fn is_folder(&self, path: &Path) -> bool {
        self.files
            .range(path.to_path_buf()..)
            .next()
            .is_some_and(|(f, _)| f != path && f.starts_with(path))
    }
}

impl Environment for GitTree {
    fn kind(&self, path: &Path) -> std::io::Result<Kind> {
        match self.files.get(path) {
            Some(bytes) => Ok(Kind::File(bytes.len() as u64)),
            None if self.is_folder(path) => Ok(Kind::Folder),
            None => Err(std::io::Error::new(
                std::io::ErrorKind::NotFound,
                "not in this revision",
            )),
        }
    }

    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        self.files.get(path).cloned().ok_or_else(|| {
            std::io::Error::new(std::io::ErrorKind::NotFound, "not in this revision")
        })
    }

    fn read_head(&self, path: &Path, buf: &mut [u8]) -> std::io::Result<usize> {
        let bytes = self.files.get(path).map_or(&[][..], Vec::as_slice);
        let n = bytes.len().min(buf.len());
        buf[..n].copy_from_slice(&bytes[..n]);
        Ok(n)
    }

    fn walk(&self, root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked> {
        let mut out = Vec::new();
        for (path, bytes) in self.files.range(root.to_path_buf()..) {
            let Ok(rest) = path.strip_prefix(root) else {
                break;
            };
            if max_depth.is_some_and(|d| rest.components().count() > d) {
                continue;
            }
            let mut left_out = excluded(path, false);
            let mut above = path.parent();
            while let Some(dir) = above.filter(|d| d.starts_with(root) && *d != root) {
                left_out |= excluded(dir, true);
                above = dir.parent();
            }
            if !left_out {
                out.push(Walked::Entry(path.clone(), Kind::File(bytes.len() as u64)));
            }
        }
        out
    }

    fn name(&self, path: &Path) -> String {
        path.to_string_lossy().into_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_named_from_the_top_of_the_repository() {
        assert_eq!(join("sub/", Path::new(".")), "sub");
        assert_eq!(join("sub/", Path::new("../b/./c")), "b/c");
        assert_eq!(join("", Path::new("x")), "x");
        assert_eq!(named("HEAD", ""), PathBuf::from("HEAD:"));
        assert_eq!(named("HEAD~1", "a/b.mod"), PathBuf::from("HEAD~1:/a/b.mod"));
        assert!(wanted("b/SYSPAR/EIO.cfg") && wanted("x/M.MOD") && !wanted("x/readme.md"));
    }
}
