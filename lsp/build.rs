//! The corpus tests of `rapid diff` (`tests/diff_corpus.rs`) need the corpus
//! as the rapid-tests crate's do: the same check (the same file), so that
//! they are reported as ignored, with the reason, when it is not there.

#[path = "../tests/build.rs"]
mod corpus;

fn main() {
    corpus::main();
}
