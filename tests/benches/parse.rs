//! Parse throughput over the corpus: raw tree-sitter against our wrapper
//! (decoding, parsing and collecting syntax diagnostics), on the same bytes.
//!
//! `cargo bench -p rapid-tests --bench parse`

use divan::Bencher;
use divan::counter::BytesCount;
use rapid_analyzer::text::{Decoded, decode};

fn main() {
    rapid_tests::alloc::init();
    divan::main();
}

struct Corpus {
    bytes: Vec<Vec<u8>>,
    texts: Vec<String>,
    total: usize,
}

fn corpus() -> Option<&'static Corpus> {
    static CORPUS: std::sync::OnceLock<Option<Corpus>> = std::sync::OnceLock::new();
    CORPUS
        .get_or_init(|| {
            let files = rapid_tests::corpus_files()?;
            let bytes: Vec<Vec<u8>> = files.into_iter().map(|(_, b)| b).collect();
            let texts = bytes
                .iter()
                .filter_map(|b| match decode(b) {
                    Decoded::Text { text, .. } => Some(text),
                    _ => None,
                })
                .collect();
            let total = bytes.iter().map(Vec::len).sum();
            Some(Corpus {
                bytes,
                texts,
                total,
            })
        })
        .as_ref()
}

/// Raw tree-sitter: parse every (already decoded) file.
#[divan::bench(sample_count = 20)]
fn raw_tree_sitter(bencher: Bencher<'_, '_>) {
    let Some(corpus) = corpus() else {
        eprintln!("parse benchmark skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    let mut parser = tree_sitter::Parser::new();
    let language = tree_sitter_rapid::LANGUAGE.into();
    if parser.set_language(&language).is_err() {
        return;
    }
    bencher
        .counter(BytesCount::new(corpus.total))
        .bench_local(|| {
            for text in &corpus.texts {
                divan::black_box(parser.parse(text, None));
            }
        });
}

/// Our wrapper: decode the bytes, parse, and collect syntax diagnostics.
#[divan::bench(sample_count = 20)]
fn rapid_syntax(bencher: Bencher<'_, '_>) {
    let Some(corpus) = corpus() else {
        return;
    };
    let mut parser = rapid_analyzer::syntax::parser();
    bencher
        .counter(BytesCount::new(corpus.total))
        .bench_local(|| {
            for bytes in &corpus.bytes {
                if let Decoded::Text { text, .. } = decode(bytes)
                    && let Some(tree) = rapid_analyzer::syntax::parse(&mut parser, &text, None)
                {
                    divan::black_box(rapid_analyzer::syntax::syntax_diagnostics(&tree, &text));
                }
            }
        });
}
