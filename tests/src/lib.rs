//! Support for the end-to-end, corpus and benchmark suites of rapid.
//!
//! The corpus of real RAPID code is test input only: it is read from the
//! folder named by `RAPID_CORPUS`, or from `../shared/corpus` next to the
//! repository, and never copied into the repository.

use std::path::{Path, PathBuf};

/// The corpus folder, if there is one.
pub fn corpus_dir() -> Option<PathBuf> {
    if let Some(dir) = std::env::var_os("RAPID_CORPUS") {
        let dir = PathBuf::from(dir);
        return dir.is_dir().then_some(dir);
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus");
    dir.is_dir().then_some(dir)
}

/// Every file below `dir` whose extension is a RAPID module's (`.mod
/// .modx .sys .sysx .prg`, any case) or, with `with_pgf`, a `.pgf` program
/// file (some tools write RAPID text into those), sorted.
pub fn rapid_paths(dir: &Path, with_pgf: bool) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(folder) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            let name = path
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            if rapid_analyzer::text::is_rapid_file_name(&name)
                || (with_pgf && rapid_analyzer::text::is_program_file_name(&name))
            {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// Text of a file's bytes: UTF-8 when valid, else Latin-1 (every byte is
/// its code point), as the analyzer decodes modules.
pub fn decode_text(bytes: &[u8]) -> String {
    match std::str::from_utf8(bytes) {
        Ok(text) => text.to_owned(),
        Err(_) => bytes.iter().map(|&b| char::from(b)).collect(),
    }
}

/// Every RAPID file of the corpus (by extension; `.pgf` program files are
/// XML and left out), sorted, with its path relative to the corpus and its
/// bytes. `None` when there is no corpus; callers print one line and skip.
pub fn corpus_files() -> Option<Vec<(PathBuf, Vec<u8>)>> {
    let dir = corpus_dir()?;
    Some(
        rapid_paths(&dir, false)
            .into_iter()
            .filter_map(|path| {
                let bytes = std::fs::read(&path).ok()?;
                let rel = path
                    .strip_prefix(&dir)
                    .map(Path::to_path_buf)
                    .unwrap_or(path);
                Some((rel, bytes))
            })
            .collect(),
    )
}
