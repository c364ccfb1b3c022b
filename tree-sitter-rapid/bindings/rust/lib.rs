//! The ABB RAPID grammar for [tree-sitter](https://tree-sitter.github.io/), and its queries.
//!
//! ```
//! let mut parser = tree_sitter::Parser::new();
//! parser
//!     .set_language(&tree_sitter_rapid::LANGUAGE.into())
//!     .expect("the RAPID grammar loads");
//! let tree = parser.parse("MODULE M\nENDMODULE\n", None).expect("a tree");
//! assert!(!tree.root_node().has_error());
//! ```
#![allow(unsafe_code)]

use tree_sitter_language::LanguageFn;

unsafe extern "C" {
    fn tree_sitter_rapid() -> *const ();
}

/// The tree-sitter [`LanguageFn`] of the RAPID grammar.
pub const LANGUAGE: LanguageFn = unsafe { LanguageFn::from_raw(tree_sitter_rapid) };

/// The content of the [`node-types.json`] file of this grammar.
pub const NODE_TYPES: &str = include_str!("../../src/node-types.json");

/// Syntax highlighting query.
pub const HIGHLIGHTS_QUERY: &str = include_str!("../../queries/highlights.scm");
/// Local scopes, definitions and references.
pub const LOCALS_QUERY: &str = include_str!("../../queries/locals.scm");
/// Symbol tagging (code navigation).
pub const TAGS_QUERY: &str = include_str!("../../queries/tags.scm");
/// Folding ranges.
pub const FOLDS_QUERY: &str = include_str!("../../queries/folds.scm");
/// Indentation.
pub const INDENTS_QUERY: &str = include_str!("../../queries/indents.scm");

#[cfg(test)]
mod tests {
    #[test]
    fn the_language_loads() {
        let mut parser = tree_sitter::Parser::new();
        parser
            .set_language(&super::LANGUAGE.into())
            .expect("the RAPID grammar loads");
    }

    #[test]
    fn the_queries_compile() {
        let language = super::LANGUAGE.into();
        for (name, source) in [
            ("highlights", super::HIGHLIGHTS_QUERY),
            ("locals", super::LOCALS_QUERY),
            ("tags", super::TAGS_QUERY),
            ("folds", super::FOLDS_QUERY),
            ("indents", super::INDENTS_QUERY),
        ] {
            if let Err(e) = tree_sitter::Query::new(&language, source) {
                panic!("{name}.scm does not compile: {e}");
            }
        }
    }
}
