//! Analysis cost over the corpus: parsing alone against parsing and checking
//! every task, and the re-check after a one-character edit inside a routine
//! of the largest file (incremental parse, then only that file's check).
//!
//! `cargo bench -p rapid-tests --bench analyze`

use divan::Bencher;
use rapid_analyzer::task::Unit;
use rapid_analyzer::text::{Decoded, decode};
use rapid_analyzer::workspace::{Workspace, diagnostics_of};

fn main() {
    rapid_tests::alloc::init();
    divan::main();
}

struct Corpus {
    /// (path relative to the corpus, text)
    files: Vec<(String, String)>,
    /// (path, text) of `.pgf` program files and `.cfg` configuration files.
    programs: Vec<(String, String)>,
    configs: Vec<(String, String)>,
}

fn corpus() -> Option<&'static Corpus> {
    static CORPUS: std::sync::OnceLock<Option<Corpus>> = std::sync::OnceLock::new();
    CORPUS
        .get_or_init(|| {
            let files = rapid_tests::corpus_files()?
                .into_iter()
                .filter_map(|(p, b)| match decode(&b) {
                    Decoded::Text { text, .. } => {
                        Some((p.to_string_lossy().replace('\\', "/"), text))
                    }
                    _ => None,
                })
                .collect();
            let dir = rapid_tests::corpus_dir()?;
            let inputs = rapid_tests::workspace_inputs(&dir);
            let programs = inputs.programs;
            let configs = inputs
                .configs
                .into_iter()
                .filter(|(p, _)| rapid_analyzer::text::is_controller_config_name(p))
                .collect();
            Some(Corpus {
                files,
                programs,
                configs,
            })
        })
        .as_ref()
}

fn workspace(corpus: &Corpus) -> Workspace {
    let mut ws = Workspace::new();
    for (p, t) in &corpus.configs {
        ws.set_config(p, t);
    }
    for (p, t) in &corpus.programs {
        ws.set_program(p, t);
    }
    for (p, t) in &corpus.files {
        ws.set_file(p, t.clone());
    }
    ws
}

/// Parsing every file (what analysis is measured against).
#[divan::bench(sample_count = 10)]
fn parse_only(bencher: Bencher<'_, '_>) {
    let Some(corpus) = corpus() else {
        eprintln!("analyze benchmark skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    bencher.bench(|| {
        corpus
            .files
            .iter()
            .map(|(p, t)| Unit::new(p.clone(), t.clone(), None).syntax.len())
            .sum::<usize>()
    });
}

/// Parsing every file, grouping tasks and checking every file.
#[divan::bench(sample_count = 10)]
fn parse_and_analyze(bencher: Bencher<'_, '_>) {
    let Some(corpus) = corpus() else {
        return;
    };
    bencher.bench(|| {
        let mut ws = workspace(corpus);
        ws.checks()
            .iter()
            .map(|(t, u)| diagnostics_of(t, u).len())
            .sum::<usize>()
    });
}

/// Checking only (the tasks built and parsed beforehand).
#[divan::bench(sample_count = 10)]
fn analyze_only(bencher: Bencher<'_, '_>) {
    let Some(corpus) = corpus() else {
        return;
    };
    let mut ws = workspace(corpus);
    let checks = ws.checks();
    bencher.bench(|| {
        checks
            .iter()
            .map(|(t, u)| diagnostics_of(t, u).len())
            .sum::<usize>()
    });
}

/// A one-character edit inside a routine of the largest file: incremental
/// reparse, and the workspace re-checks that file only.
#[divan::bench(sample_count = 50)]
fn edit_recheck_largest(bencher: Bencher<'_, '_>) {
    let Some(corpus) = corpus() else {
        return;
    };
    let Some((path, text)) = corpus.files.iter().max_by_key(|(_, t)| t.len()) else {
        return;
    };
    let mut ws = workspace(corpus);
    for (p, _) in &corpus.files {
        ws.diagnostics(p);
    }
    let edit = rapid_tests::SpaceEdit::new(text);
    let mut flip = 0usize;
    bencher.bench_local(|| {
        flip ^= 1;
        let Some(unit) = ws.unit(path) else {
            return 0;
        };
        let mut tree = unit.tree().clone();
        tree.edit(&edit.input_edit(flip));
        let new = edit.versions[flip].clone();
        ws.set_unit(Unit::new(path.clone(), new, Some(&tree)));
        ws.diagnostics(path).len()
    });
}

/// The incremental reparse alone of the same one-character edit as
/// [`edit_recheck_largest`] (what the re-check cannot avoid).
#[divan::bench(sample_count = 50)]
fn edit_reparse_only_largest(bencher: Bencher<'_, '_>) {
    let Some(corpus) = corpus() else {
        return;
    };
    let Some((path, text)) = corpus.files.iter().max_by_key(|(_, t)| t.len()) else {
        return;
    };
    let edit = rapid_tests::SpaceEdit::new(text);
    let unit = Unit::new(path.clone(), text.clone(), None);
    let (input, edited) = (edit.input_edit(1), &edit.versions[1]);
    let mut parser = tree_sitter::Parser::new();
    let _ = parser.set_language(&tree_sitter_rapid::LANGUAGE.into());
    bencher.bench_local(|| {
        let mut tree = unit.tree().clone();
        tree.edit(&input);
        parser
            .parse(edited, Some(&tree))
            .map(|t| t.root_node().child_count())
    });
}
