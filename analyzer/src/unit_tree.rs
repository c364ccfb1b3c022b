//! A unit's syntax tree, which its owner may release to save memory and
//! which is parsed again from the text on its next use.
//!
//! Trees are most of a workspace's memory (about 40 bytes of tree per byte
//! of text: on the corpus, 235 MB of trees for 6 MB of text, against 12 MB
//! for the item trees and everything else). A language server needs the
//! trees of the files the user has open; the other files are needed by
//! their item trees (names, signatures, the task index), and their syntax
//! only now and then (a reference search, a constant defined in another
//! module), so it can release their trees and parse them again on demand.
//!
//! [`crate::task::Unit::tree`] reads the same whether the tree was kept or
//! is parsed again (from the unit's own text); once parsed again, it stays.
//! Readers of other units than the one they work on (a constant declared in
//! another module, references in every file) use
//! [`crate::task::Unit::with_tree`], which parses a released tree for the
//! call only: a released tree stays released.

use std::fmt;
use std::sync::OnceLock;

use tree_sitter::Tree;

/// A unit's tree, kept or released. It holds no text of its own: the unit
/// passes its text when the tree is needed again ([`crate::task::Unit::tree`]).
pub struct UnitTree {
    tree: OnceLock<Tree>,
}

impl UnitTree {
    pub fn new(tree: Tree) -> UnitTree {
        UnitTree {
            tree: OnceLock::from(tree),
        }
    }

    /// Releases the tree; the next [`UnitTree::get`] parses again.
    pub fn release(&mut self) {
        self.tree.take();
    }

    /// The tree, made by `parse` if it was released.
    pub fn get_or_init(&self, parse: impl FnOnce() -> Tree) -> &Tree {
        self.tree.get_or_init(parse)
    }

    /// Whether the tree is in memory (kept, or parsed again since it was
    /// released).
    pub fn is_loaded(&self) -> bool {
        self.tree.get().is_some()
    }

    /// The tree, if it is in memory.
    pub fn loaded(&self) -> Option<&Tree> {
        self.tree.get()
    }

    /// The tree, parsed again from `text` (the unit's text) if it was
    /// released.
    pub fn get(&self, text: &str) -> &Tree {
        self.tree.get_or_init(|| parse(text))
    }
}

/// A tree of `text`, as a unit's tree is parsed again.
pub(crate) fn parse(text: &str) -> Tree {
    let mut parser = crate::syntax::parser();
    match crate::syntax::parse(&mut parser, text, None)
        .or_else(|| crate::syntax::parse(&mut parser, "", None))
    {
        Some(tree) => tree,
        // Only a cancelled parse returns no tree, and we never cancel; an
        // empty text always parses.
        None => unreachable_tree(),
    }
}

fn unreachable_tree() -> Tree {
    panic!("tree-sitter returned no tree for an empty text")
}

impl fmt::Debug for UnitTree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.tree.get() {
            Some(tree) => tree.fmt(f),
            None => f.write_str("Tree(released)"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_released_tree_is_parsed_again_on_use() {
        let text = "MODULE M\n  PROC p()\n    x := ;\n  ENDPROC\nENDMODULE\n";
        let mut parser = crate::syntax::parser();
        let tree = parser.parse(text, None).map(UnitTree::new);
        let Some(mut tree) = tree else {
            panic!("no tree");
        };
        let before = tree.get(text).root_node().to_sexp();
        tree.release();
        assert!(!tree.is_loaded());
        assert_eq!(tree.get(text).root_node().to_sexp(), before);
        assert!(tree.is_loaded());
    }
}
