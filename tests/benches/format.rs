//! Formatting throughput over the corpus: `rapid_analyzer::format::format`
//! on every file that parses without errors (parsing included, as the
//! formatter parses), one thread.
//!
//! `cargo bench -p rapid-tests --bench format`

use divan::Bencher;
use divan::counter::BytesCount;
use rapid_analyzer::format::{FormatOptions, format};
use rapid_analyzer::text::{Decoded, decode};

fn main() {
    rapid_tests::alloc::init();
    divan::main();
}

/// The decoded texts of the corpus files that parse without errors.
fn corpus() -> Option<&'static (Vec<String>, usize)> {
    static CORPUS: std::sync::OnceLock<Option<(Vec<String>, usize)>> = std::sync::OnceLock::new();
    CORPUS
        .get_or_init(|| {
            let files = rapid_tests::corpus_files()?;
            let options = FormatOptions::default();
            let texts: Vec<String> = files
                .into_iter()
                .filter_map(|(_, bytes)| match decode(&bytes) {
                    Decoded::Text { text, .. } => Some(text),
                    _ => None,
                })
                .filter(|text| format(text, &options).is_ok())
                .collect();
            let total = texts.iter().map(String::len).sum();
            Some((texts, total))
        })
        .as_ref()
}

/// Format every file of the corpus.
#[divan::bench(sample_count = 10)]
fn format_corpus(bencher: Bencher<'_, '_>) {
    let Some((texts, total)) = corpus() else {
        eprintln!("format benchmark skipped: no corpus (set RAPID_CORPUS)");
        return;
    };
    let options = FormatOptions::default();
    bencher.counter(BytesCount::new(*total)).bench_local(|| {
        for text in texts {
            divan::black_box(format(text, &options).is_ok());
        }
    });
}

/// The parse alone over the same files: the part of formatting that is
/// tree-sitter's.
#[divan::bench(sample_count = 10)]
fn parse_only(bencher: Bencher<'_, '_>) {
    let Some((texts, total)) = corpus() else {
        return;
    };
    let mut parser = rapid_analyzer::syntax::parser();
    bencher.counter(BytesCount::new(*total)).bench_local(|| {
        for text in texts {
            divan::black_box(rapid_analyzer::syntax::parse(&mut parser, text, None));
        }
    });
}
