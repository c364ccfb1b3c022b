//! Support for the end-to-end, corpus and benchmark suites of rapid.
//!
//! The corpus of real RAPID code is test input only: it is read from the
//! folder named by `RAPID_CORPUS`, or from `../shared/corpus` next to the
//! repository, and never copied into the repository.

use std::path::{Path, PathBuf};

use rapid_analyzer::text::{Decoded, decode};

/// The `rapid` binary's allocator (mimalloc, for Rust and for
/// tree-sitter), the same file compiled here: every test, bench and example
/// of this crate allocates as the binary does, so their figures agree with
/// it. Benches and examples call [`alloc::init`] first thing in `main`.
#[path = "../../lsp/src/alloc.rs"]
pub mod alloc;

pub mod adversarial;
pub mod layout;

/// The corpus folder, if there is one.
pub fn corpus_dir() -> Option<PathBuf> {
    if let Some(dir) = std::env::var_os("RAPID_CORPUS") {
        return std::fs::canonicalize(dir).ok().filter(|d| d.is_dir());
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus");
    std::fs::canonicalize(dir).ok().filter(|d| d.is_dir())
}

/// Every file below `dir` (recursively, links followed as the file system
/// reports them), sorted.
pub fn all_files(dir: &Path) -> Vec<PathBuf> {
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
            } else {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Every file below `dir` whose extension is a RAPID module's (`.mod
/// .modx .sys .sysx .prg`, any case) or, with `with_pgf`, a `.pgf` program
/// file (some tools write RAPID text into those), sorted.
pub fn rapid_paths(dir: &Path, with_pgf: bool) -> Vec<PathBuf> {
    all_files(dir)
        .into_iter()
        .filter(|path| {
            let name = file_name(path);
            rapid_analyzer::text::is_rapid_file_name(&name)
                || (with_pgf && rapid_analyzer::text::is_program_file_name(&name))
        })
        .collect()
}

/// What a workspace needs from a folder, as (path relative to `dir` with
/// `/` separators, text), each list sorted: RAPID modules that decode as
/// text, `.pgf` program files, and `.cfg` configuration files (all of them;
/// callers keep the ones they want).
#[derive(Debug, Default)]
pub struct Inputs {
    pub modules: Vec<(String, String)>,
    pub programs: Vec<(String, String)>,
    pub configs: Vec<(String, String)>,
}

impl Inputs {
    /// A workspace holding every input (configuration, programs, modules).
    pub fn workspace(&self) -> rapid_analyzer::workspace::Workspace {
        let mut ws = rapid_analyzer::workspace::Workspace::new();
        for (p, t) in &self.configs {
            ws.set_config(p, t);
        }
        for (p, t) in &self.programs {
            ws.set_program(p, t);
        }
        for (p, t) in &self.modules {
            ws.set_file(p, t.clone());
        }
        ws
    }
}

/// Reads the [`Inputs`] below `dir`.
pub fn workspace_inputs(dir: &Path) -> Inputs {
    let mut inputs = Inputs::default();
    for path in all_files(dir) {
        let rel = path
            .strip_prefix(dir)
            .map(|p| p.to_string_lossy().replace('\\', "/"))
            .unwrap_or_default();
        let name = file_name(&path);
        let lower = name.to_ascii_lowercase();
        let Ok(bytes) = std::fs::read(&path) else {
            continue;
        };
        if rapid_analyzer::text::is_rapid_file_name(&name) {
            if let Decoded::Text { text, .. } = decode(&bytes) {
                inputs.modules.push((rel, text));
            }
        } else if lower.ends_with(".pgf") {
            inputs
                .programs
                .push((rel, String::from_utf8_lossy(&bytes).into_owned()));
        } else if lower.ends_with(".cfg") {
            inputs
                .configs
                .push((rel, String::from_utf8_lossy(&bytes).into_owned()));
        }
    }
    inputs
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

/// The one-character edit of the edit benchmarks: a space inserted at the
/// start of the first line inside the first routine of a text, then removed
/// again, alternately.
pub struct SpaceEdit {
    /// Where the space goes.
    pub at: usize,
    /// The text without the space (`0`) and with it (`1`).
    pub versions: [String; 2],
}

impl SpaceEdit {
    pub fn new(text: &str) -> SpaceEdit {
        let at = ["PROC ", "FUNC ", "TRAP "]
            .iter()
            .filter_map(|k| text.find(k))
            .min()
            .and_then(|i| text[i..].find('\n').map(|j| i + j + 1))
            .unwrap_or(0);
        let mut edited = text.to_owned();
        edited.insert(at, ' ');
        SpaceEdit {
            at,
            versions: [text.to_owned(), edited],
        }
    }

    /// The edit from `versions[1 - to]` to `versions[to]`, as tree-sitter
    /// takes it.
    pub fn input_edit(&self, to: usize) -> tree_sitter::InputEdit {
        let (old, new) = (&self.versions[1 - to], &self.versions[to]);
        let at = self.at;
        let point = |s: &str| tree_sitter::Point {
            row: s.matches('\n').count(),
            column: s.len() - s.rfind('\n').map_or(0, |i| i + 1),
        };
        let (old_end, new_end) = if new.len() > old.len() {
            (at, at + 1)
        } else {
            (at + 1, at)
        };
        tree_sitter::InputEdit {
            start_byte: at,
            old_end_byte: old_end,
            new_end_byte: new_end,
            start_position: point(&old[..at]),
            old_end_position: point(&old[..old_end]),
            new_end_position: point(&new[..new_end]),
        }
    }
}
