//! The analyzer's part of `rapid diff` on two real backups of one cell (the
//! corpus's `1200-526406` backups of 2025-12-23 and 2026-02-11): reducing
//! both to snapshots (statement lines, evaluated values) and comparing
//! them. Parsing is not measured here (it is `rapid check`'s too); the
//! whole command is measured with hyperfine (BENCHMARKS.md).
//!
//! `cargo bench -p rapid-tests --bench diff`

use divan::Bencher;
use rapid_analyzer::diff::{Options, Snapshot, compare, snapshot};
use rapid_analyzer::workspace::Workspace;

fn main() {
    rapid_tests::alloc::init();
    divan::main();
}

const OLD: &str = "taeyangshim-stack__s25016/RAPID/1200-526406_BACKUP_2025-12-23-1933";
const NEW: &str = "taeyangshim-stack__s25016/RAPID/1200-526406_BACKUP_2026-02-11-1959/1200-526406_BACKUP_2026-02-11-1959";

/// The two backups as workspaces (parsed once).
fn sides() -> Option<(Workspace, Workspace)> {
    let dir = rapid_tests::corpus_dir()?;
    let load = |rel: &str| rapid_tests::workspace_inputs(&dir.join(rel)).workspace();
    Some((load(OLD), load(NEW)))
}

fn snap(ws: &mut Workspace) -> Snapshot {
    Snapshot {
        tasks: snapshot::tasks_of(ws, &|k| k.to_owned(), &|p| p.to_owned()),
        ..Snapshot::default()
    }
}

/// Both backups reduced to snapshots: each module's routines as lines and
/// its data evaluated.
#[divan::bench(sample_count = 20)]
fn snapshots(bencher: Bencher<'_, '_>) {
    let Some((mut old, mut new)) = sides() else {
        eprintln!("diff benchmark skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    bencher.bench_local(|| (snap(&mut old).tasks.len(), snap(&mut new).tasks.len()));
}

/// The comparison of the two snapshots.
#[divan::bench(sample_count = 20)]
fn comparison(bencher: Bencher<'_, '_>) {
    let Some((mut old, mut new)) = sides() else {
        eprintln!("diff benchmark skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    let (a, b) = (snap(&mut old), snap(&mut new));
    bencher.bench(|| compare(&a, &b, &Options::default()).tasks.len());
}
