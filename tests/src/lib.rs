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

/// Every RAPID file of the corpus (by extension; `.pgf` program files are
/// XML and left out), sorted, with its bytes. `None` when there is no corpus;
/// callers print one line and skip.
pub fn corpus_files() -> Option<Vec<(PathBuf, Vec<u8>)>> {
    let dir = corpus_dir()?;
    let mut out = Vec::new();
    let mut stack = vec![dir.clone()];
    while let Some(folder) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else if path
                .file_name()
                .is_some_and(|n| rapid_analyzer::text::is_rapid_file_name(&n.to_string_lossy()))
                && let Ok(bytes) = std::fs::read(&path)
            {
                let rel = path
                    .strip_prefix(&dir)
                    .map(Path::to_path_buf)
                    .unwrap_or(path);
                out.push((rel, bytes));
            }
        }
    }
    out.sort();
    Some(out)
}
