//! The controller's file system, behind [`FileSystem`]. Paths are the
//! controller's (`HOME:/logs/a.txt`, `TEMP:/x`); an implementation decides
//! where they lead. [`SandboxFs`] (the default) keeps every device in one
//! folder and lets no path leave it; [`MemoryFs`] keeps files in memory
//! (for tests).

use std::collections::BTreeMap;
use std::path::{Component, Path, PathBuf};

/// Why a file operation failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FileError {
    /// There is no such file or folder.
    NotFound(String),
    /// The path may not be used (it leaves the sandbox, say).
    Denied(String),
    /// Files are not available in this simulation.
    Unsupported(String),
    /// Anything else (the operating system's message).
    Other(String),
}

impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FileError::NotFound(m)
            | FileError::Denied(m)
            | FileError::Unsupported(m)
            | FileError::Other(m) => f.write_str(m),
        }
    }
}

/// What a path names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    File,
    Directory,
}

/// The controller's files.
pub trait FileSystem: Send {
    /// The whole content of a file.
    fn read(&mut self, path: &str) -> Result<Vec<u8>, FileError>;
    /// Writes `data` to a file, after what it holds (`append`) or in place
    /// of it; the file is made when it does not exist.
    fn write(&mut self, path: &str, data: &[u8], append: bool) -> Result<(), FileError>;
    fn remove_file(&mut self, path: &str) -> Result<(), FileError>;
    fn make_dir(&mut self, path: &str) -> Result<(), FileError>;
    fn remove_dir(&mut self, path: &str) -> Result<(), FileError>;
    /// Gives a file or folder another path.
    fn rename(&mut self, from: &str, to: &str) -> Result<(), FileError>;
    /// What the path names, if anything.
    fn kind(&mut self, path: &str) -> Option<FileKind>;
    /// The names of the files and folders in the folder `path`, sorted.
    fn list(&mut self, path: &str) -> Result<Vec<String>, FileError>;
}

/// The files in a folder: every device (`HOME:`, `TEMP:`...) is that
/// folder, and no path leaves it. Without a folder, file instructions are
/// not supported.
#[derive(Clone, Debug)]
pub struct SandboxFs {
    root: Option<PathBuf>,
}

impl SandboxFs {
    pub fn new(root: Option<PathBuf>) -> SandboxFs {
        SandboxFs { root }
    }

    /// The folder's path of a controller path.
    fn resolve(&self, name: &str) -> Result<PathBuf, FileError> {
        let Some(root) = &self.root else {
            return Err(FileError::Unsupported(
                "file instructions need a sandbox folder: --sandbox DIR".to_owned(),
            ));
        };
        let mut out = root.clone();
        for part in controller_path(name)? {
            out.push(part);
        }
        Ok(out)
    }
}

/// The parts of a controller path below its device (`HOME:/a/b.txt` is
/// `a`, `b.txt`); a path that climbs out (`..`) is refused.
fn controller_path(name: &str) -> Result<Vec<String>, FileError> {
    let rest = match name.split_once(':') {
        Some((dev, rest)) if !dev.contains(['/', '\\']) => rest,
        _ => name,
    };
    let mut parts = Vec::new();
    for c in Path::new(&rest.replace('\\', "/")).components() {
        match c {
            Component::Normal(p) => parts.push(p.to_string_lossy().into_owned()),
            Component::RootDir | Component::CurDir => {}
            _ => {
                return Err(FileError::Denied(format!(
                    "{name}: the path leaves the sandbox folder"
                )));
            }
        }
    }
    Ok(parts)
}

/// The file a controller path names in the sandbox, as one string
/// (`HOME:/a/b.txt`, `HOME:a/b.txt` and `TEMP:/a/./b.txt` alike): what the
/// run keeps per file (`FileTime`'s stamps).
pub(crate) fn path_key(name: &str) -> String {
    controller_path(name).map_or_else(|_| name.to_owned(), |parts| parts.join("/"))
}

fn os_error(name: &str, e: &std::io::Error) -> FileError {
    if e.kind() == std::io::ErrorKind::NotFound {
        FileError::NotFound(format!("{name}: {e}"))
    } else {
        FileError::Other(format!("{name}: {e}"))
    }
}

impl FileSystem for SandboxFs {
    fn read(&mut self, path: &str) -> Result<Vec<u8>, FileError> {
        std::fs::read(self.resolve(path)?).map_err(|e| os_error(path, &e))
    }

    fn write(&mut self, path: &str, data: &[u8], append: bool) -> Result<(), FileError> {
        use std::io::Write as _;
        let p = self.resolve(path)?;
        std::fs::OpenOptions::new()
            .create(true)
            .write(true)
            .append(append)
            .truncate(!append)
            .open(&p)
            .and_then(|mut f| f.write_all(data))
            .map_err(|e| os_error(path, &e))
    }

    fn remove_file(&mut self, path: &str) -> Result<(), FileError> {
        std::fs::remove_file(self.resolve(path)?).map_err(|e| os_error(path, &e))
    }

    fn make_dir(&mut self, path: &str) -> Result<(), FileError> {
        std::fs::create_dir(self.resolve(path)?).map_err(|e| os_error(path, &e))
    }

    fn rename(&mut self, from: &str, to: &str) -> Result<(), FileError> {
        std::fs::rename(self.resolve(from)?, self.resolve(to)?).map_err(|e| os_error(from, &e))
    }

    fn remove_dir(&mut self, path: &str) -> Result<(), FileError> {
        std::fs::remove_dir(self.resolve(path)?).map_err(|e| os_error(path, &e))
    }

    fn kind(&mut self, path: &str) -> Option<FileKind> {
        let meta = std::fs::metadata(self.resolve(path).ok()?).ok()?;
        Some(if meta.is_dir() {
            FileKind::Directory
        } else {
            FileKind::File
        })
    }

    fn list(&mut self, path: &str) -> Result<Vec<String>, FileError> {
        let entries = std::fs::read_dir(self.resolve(path)?).map_err(|e| os_error(path, &e))?;
        let mut names: Vec<String> = entries
            .filter_map(|e| Some(e.ok()?.file_name().to_string_lossy().into_owned()))
            .collect();
        names.sort();
        Ok(names)
    }
}

/// Files in memory, by their path below the device (folders are made on
/// demand); for tests and for runs that must not touch the disk.
#[derive(Clone, Debug, Default)]
pub struct MemoryFs {
    pub files: BTreeMap<String, Vec<u8>>,
    pub dirs: std::collections::BTreeSet<String>,
}

impl MemoryFs {
    pub fn new() -> MemoryFs {
        MemoryFs::default()
    }

    fn key(path: &str) -> Result<String, FileError> {
        Ok(controller_path(path)?.join("/"))
    }
}

impl FileSystem for MemoryFs {
    fn read(&mut self, path: &str) -> Result<Vec<u8>, FileError> {
        self.files
            .get(&MemoryFs::key(path)?)
            .cloned()
            .ok_or_else(|| FileError::NotFound(format!("{path}: no such file")))
    }

    fn write(&mut self, path: &str, data: &[u8], append: bool) -> Result<(), FileError> {
        let file = self.files.entry(MemoryFs::key(path)?).or_default();
        if !append {
            file.clear();
        }
        file.extend_from_slice(data);
        Ok(())
    }

    fn remove_file(&mut self, path: &str) -> Result<(), FileError> {
        self.files
            .remove(&MemoryFs::key(path)?)
            .map(|_| ())
            .ok_or_else(|| FileError::NotFound(format!("{path}: no such file")))
    }

    fn make_dir(&mut self, path: &str) -> Result<(), FileError> {
        self.dirs.insert(MemoryFs::key(path)?);
        Ok(())
    }

    fn remove_dir(&mut self, path: &str) -> Result<(), FileError> {
        if self.dirs.remove(&MemoryFs::key(path)?) {
            Ok(())
        } else {
            Err(FileError::NotFound(format!("{path}: no such folder")))
        }
    }

    fn rename(&mut self, from: &str, to: &str) -> Result<(), FileError> {
        let (old, new) = (MemoryFs::key(from)?, MemoryFs::key(to)?);
        if let Some(data) = self.files.remove(&old) {
            self.files.insert(new, data);
            Ok(())
        } else if self.dirs.remove(&old) {
            self.dirs.insert(new);
            Ok(())
        } else {
            Err(FileError::NotFound(format!("{from}: no such file")))
        }
    }

    fn kind(&mut self, path: &str) -> Option<FileKind> {
        let key = MemoryFs::key(path).ok()?;
        if self.files.contains_key(&key) {
            Some(FileKind::File)
        } else if self.dirs.contains(&key) {
            Some(FileKind::Directory)
        } else {
            None
        }
    }

    fn list(&mut self, path: &str) -> Result<Vec<String>, FileError> {
        let key = MemoryFs::key(path)?;
        if !key.is_empty() && !self.dirs.contains(&key) {
            return Err(FileError::NotFound(format!("{path}: no such folder")));
        }
        let prefix = if key.is_empty() {
            key
        } else {
            format!("{key}/")
        };
        let mut names: Vec<String> = self
            .files
            .keys()
            .chain(&self.dirs)
            .filter_map(|k| k.strip_prefix(&prefix)?.split('/').next())
            .filter(|n| !n.is_empty())
            .map(str::to_owned)
            .collect();
        names.sort();
        names.dedup();
        Ok(names)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_lists_a_folder_s_files_and_folders_once_each() -> Result<(), FileError> {
        let mut fs = MemoryFs::new();
        fs.make_dir("HOME:/parts")?;
        fs.make_dir("HOME:/parts/old")?;
        fs.write("HOME:/parts/b.txt", b"x", false)?;
        fs.write("HOME:/parts/old/c.txt", b"x", false)?;
        fs.write("HOME:/top.txt", b"x", false)?;
        assert_eq!(fs.list("HOME:/parts")?, ["b.txt", "old"]);
        assert_eq!(fs.list("HOME:")?, ["parts", "top.txt"]);
        assert!(matches!(
            fs.list("HOME:/nowhere"),
            Err(FileError::NotFound(_))
        ));
        Ok(())
    }
}
