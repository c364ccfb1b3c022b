//! Reading RAPID files from disk, as `rapid check`, `rapid fmt` and the
//! language server all need: bytes to text with the analyzer's decoder.

use std::path::{Path, PathBuf};

use rapid_analyzer::text::{Decoded, Encoding, LineIndex, decode};

/// A RAPID file read and decoded.
#[derive(Debug)]
pub struct SourceFile {
    pub path: PathBuf,
    pub text: String,
    #[allow(
        dead_code,
        reason = "read by the formatter, which writes files back in their encoding"
    )]
    pub encoding: Encoding,
    pub lines: LineIndex,
}

/// Why a file was not read as RAPID text.
#[derive(Debug)]
pub enum Unreadable {
    /// The file could not be read (missing, no permission, a broken link...).
    Io(std::io::Error),
    /// An encrypted module: loadable by a controller, readable by nobody.
    Encrypted,
    /// Not a text file.
    Binary,
}

impl std::fmt::Display for Unreadable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unreadable::Io(e) => write!(f, "cannot read it: {e}"),
            Unreadable::Encrypted => {
                f.write_str("skipped: an encrypted module (its content cannot be checked)")
            }
            Unreadable::Binary => f.write_str("skipped: a binary file, not RAPID text"),
        }
    }
}

/// The name the analyzer knows a file by: its real place on disk (absolute,
/// links resolved), so that a file is grouped into the same task and read
/// once whatever path named it and whatever folder the command runs from
/// (`PROGMOD/A.mod` from inside `RAPID/TASK1` and
/// `RAPID/TASK1/PROGMOD/A.mod` from its parent are the same file of the
/// same task). A path that cannot be resolved (a file that is gone) is made
/// absolute without touching the file system.
pub fn analyzer_path(path: &Path) -> String {
    let real = std::fs::canonicalize(path)
        .or_else(|_| std::path::absolute(path).map(|p| crate::check::normalize(&p)))
        .unwrap_or_else(|_| path.to_owned());
    let s = real.to_string_lossy();
    // Windows: `\\?\C:\x` (what canonicalize gives) is `C:\x`.
    match s.strip_prefix(r"\\?\") {
        Some(rest) if rest.as_bytes().get(1) == Some(&b':') => rest.to_owned(),
        _ => s.into_owned(),
    }
}

impl SourceFile {
    pub fn read(path: &Path) -> Result<SourceFile, Unreadable> {
        let bytes = read_regular(path).map_err(Unreadable::Io)?;
        SourceFile::from_bytes(path.to_owned(), &bytes)
    }

    pub fn from_bytes(path: PathBuf, bytes: &[u8]) -> Result<SourceFile, Unreadable> {
        match decode(bytes) {
            Decoded::Text { text, encoding } => Ok(SourceFile {
                lines: LineIndex::new(&text),
                path,
                text,
                encoding,
            }),
            Decoded::Encrypted => Err(Unreadable::Encrypted),
            Decoded::Binary => Err(Unreadable::Binary),
        }
    }

    /// 1-based line and character column of a byte offset.
    pub fn human(&self, offset: usize) -> (usize, usize) {
        self.lines.human(offset, &self.text)
    }
}

/// The bytes of a regular file. Anything else (a FIFO, a device, a folder,
/// something swapped in after discovery) is an error naming what it is,
/// found without blocking: the file is opened non-blocking and checked
/// before it is read.
pub fn read_regular(path: &Path) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let mut file = options.open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(std::io::Error::other(format!(
            "{}, not a file",
            kind_of(&meta.file_type())
        )));
    }
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    file.read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// What a file-system entry that is not a regular file is, in words.
pub fn kind_of(kind: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if kind.is_socket() {
            return "a socket";
        }
        if kind.is_char_device() {
            return "a character device";
        }
        if kind.is_block_device() {
            return "a block device";
        }
    }
    if kind.is_dir() {
        "a folder"
    } else if kind.is_file() {
        "a file"
    } else {
        "not a regular file"
    }
}
