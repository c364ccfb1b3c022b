//! Helpers shared by the command-line tests (each test file is its own
//! crate and uses what it needs).
#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Output, Stdio};

pub mod editor;
pub mod mcp;
// The binary's in-process server tests use the same file.
mod scratch;
#[allow(unused_imports)]
pub use scratch::*;

/// Writes `files` (`path`, text) below `dir`, making folders as needed.
pub fn write(dir: &Path, files: &[(&str, &str)]) {
    for (path, text) in files {
        let path = dir.join(path);
        std::fs::create_dir_all(path.parent().expect("a parent")).expect("folder");
        std::fs::write(path, text).expect("written");
    }
}

/// `exit CODE`, then stdout and stderr, for snapshots and messages.
pub fn show(out: &Output) -> String {
    format!(
        "exit {}\n--- stdout\n{}--- stderr\n{}",
        out.status.code().unwrap_or(-1),
        text(&out.stdout),
        text(&out.stderr)
    )
}

/// Output bytes as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Runs the built `rapid` binary in `dir` with `args`, outside CI mode and
/// without standard input.
pub fn rapid(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(args)
        .current_dir(dir)
        .env_remove("CI")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .expect("the rapid binary runs")
}

/// (exit code, stdout, stderr) of `rapid ARGS` in `dir`.
pub fn rapid_out(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let out = rapid(dir, args);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}
