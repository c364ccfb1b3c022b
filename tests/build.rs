//! Whether the corpus of real RAPID code is there (`RAPID_CORPUS`, or
//! `../shared/corpus` next to the repository, as `rapid_tests::corpus_dir`
//! looks for it). Without it the corpus tests are compiled as ignored, with
//! the reason, so that `cargo test` counts them as ignored in its summary
//! (and the build says why) rather than passing them.

use std::path::PathBuf;

pub fn main() {
    println!("cargo::rustc-check-cfg=cfg(no_corpus)");
    println!("cargo::rerun-if-env-changed=RAPID_CORPUS");
    let dir = match std::env::var_os("RAPID_CORPUS") {
        Some(dir) => PathBuf::from(dir),
        None => PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default())
            .join("../../shared/corpus"),
    };
    // A folder that is not there: checked again on every build.
    println!("cargo::rerun-if-changed={}", dir.display());
    if !dir.is_dir() {
        println!("cargo::rustc-cfg=no_corpus");
        println!(
            "cargo::warning=no corpus of real RAPID code at {} (set RAPID_CORPUS): the corpus tests are ignored",
            dir.display()
        );
    }
}
