//! Finding the RAPID files under the paths given on the command line.

use std::path::{Path, PathBuf};

use rapid_analyzer::text::is_rapid_file_name;

/// The files found, and the problems met on the way.
#[derive(Debug, Default)]
pub struct Discovery {
    /// RAPID files, sorted, without duplicates.
    pub files: Vec<PathBuf>,
    /// I/O configuration files (`EIO.cfg`), sorted.
    pub configs: Vec<PathBuf>,
    /// Paths that could not be walked, with the reason.
    pub errors: Vec<(PathBuf, String)>,
}

/// Walks `paths` (folders recursively, honouring `.gitignore`, `.ignore`
/// and git's global excludes; hidden folders are walked too, since controller
/// backups have none worth skipping) and collects RAPID files. A file named
/// explicitly is taken whatever its extension.
pub fn discover(paths: &[PathBuf]) -> Discovery {
    let mut out = Discovery::default();
    for root in paths {
        match std::fs::metadata(root) {
            Err(e) => {
                out.errors.push((root.clone(), e.to_string()));
                continue;
            }
            Ok(meta) if meta.is_file() => {
                out.files.push(root.clone());
                continue;
            }
            Ok(_) => {}
        }
        let walker = ignore::WalkBuilder::new(root)
            .hidden(false)
            .follow_links(true)
            .require_git(false)
            .filter_entry(|entry| entry.file_name() != ".git")
            .build();
        for entry in walker {
            match entry {
                Ok(entry) => {
                    let is_file = entry.file_type().is_some_and(|t| t.is_file());
                    let name = entry.file_name().to_string_lossy();
                    if is_file && is_rapid_file_name(&name) {
                        out.files.push(entry.into_path());
                    } else if is_file && name.eq_ignore_ascii_case("eio.cfg") {
                        out.configs.push(entry.into_path());
                    }
                }
                Err(e) => out
                    .errors
                    .push((error_path(&e).unwrap_or(root).to_owned(), e.to_string())),
            }
        }
    }
    out.files.sort();
    out.files.dedup();
    out.configs.sort();
    out.configs.dedup();
    out
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
