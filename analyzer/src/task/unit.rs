//! A parsed module file ([`Unit`]): its text, syntax tree (released and
//! parsed again on use), item tree and the hashes the caches compare.

use std::sync::{Arc, OnceLock};

use tree_sitter::Tree;

use crate::diagnostic::Diagnostic;
use crate::items::{FileItems, RoutineDecl, hash_of};
use crate::unit_tree::UnitTree;

/// One parsed file with its item tree. Immutable once built: an edit makes
/// a new unit (reusing the old tree for an incremental parse).
#[derive(Debug)]
pub struct Unit {
    /// The file's path as the caller names it (used for task grouping and
    /// in related locations).
    pub path: String,
    pub text: String,
    /// The syntax tree ([`Unit::tree`]); it may have been released
    /// ([`Unit::release_tree`]) and is then parsed again on use.
    tree: UnitTree,
    pub items: FileItems,
    pub interface: u64,
    /// A hash of the values of the unit's module data and the sizes of its
    /// arrays (which constant evaluation reads; the interface leaves them out).
    pub constants: u64,
    pub syntax: Vec<Diagnostic>,
    /// The module files it loads at run time ([`crate::loads`]).
    pub loads: crate::loads::Loads,
    /// The parts of the text nested too deep to analyse: the tree is that
    /// of a copy of the text with these replaced ([`crate::nesting`]).
    cuts: Vec<crate::nesting::Cut>,
    /// The lowered bodies of the routines that mention synchronisation
    /// ([`Unit::sync_bodies`]), lowered on first use.
    sync_bodies: OnceLock<Arc<[crate::body::Body]>>,
}

impl Unit {
    /// Parses and lowers `text`; `old` is the previous tree, already edited.
    pub fn new(path: String, text: String, old: Option<&Tree>) -> Unit {
        let mut parser = crate::syntax::parser();
        // The tree of a unit with parts nested too deep is not that of its
        // text ([`crate::nesting`]): never reuse it.
        let old = old.filter(|t| !crate::nesting::is_copy(t));
        let tree = crate::syntax::parse(&mut parser, &text, old)
            .or_else(|| crate::syntax::parse(&mut parser, "", None));
        Unit::from_tree(path, text, tree)
    }

    /// Builds a unit from a tree parsed by the caller.
    pub fn from_tree(path: String, text: String, tree: Option<Tree>) -> Unit {
        if tree.as_ref().is_some_and(crate::nesting::is_copy) {
            return Unit::new(path, text, None);
        }
        let Some(tree) = tree else {
            // Only a cancelled parse returns no tree; we never cancel. Keep
            // the file, empty, rather than fail.
            let mut parser = crate::syntax::parser();
            let tree = parser.parse("", None);
            return Unit::empty(path, text, tree);
        };
        let (tree, cuts) = crate::nesting::bound(&text, tree);
        let items = FileItems::lower(&tree, &text);
        let loads = crate::loads::of(&tree, &text, &items);
        let mut syntax = crate::syntax::syntax_diagnostics(&tree, &text);
        if !cuts.is_empty() {
            syntax.extend(crate::nesting::diagnostics(&text, &cuts));
            syntax.sort_by_key(|d| d.range.start);
        }
        Unit {
            interface: items.interface_hash(),
            constants: hash_of(&items.constants(&text)),
            path,
            text,
            tree: UnitTree::new(tree),
            items,
            syntax,
            loads,
            cuts,
            sync_bodies: OnceLock::new(),
        }
    }

    /// Releases the syntax tree to save memory (most of a unit's memory is
    /// its tree); the next use of [`Unit::tree`] parses the text again.
    /// Everything else (items, interface, syntax diagnostics) stays.
    pub fn release_tree(&mut self) {
        self.tree.release();
    }

    /// The syntax tree, parsed again from the text if it was released.
    pub fn tree(&self) -> &Tree {
        if self.cuts.is_empty() {
            self.tree.get(&self.text)
        } else {
            self.tree
                .get_or_init(|| crate::nesting::parse_copy(&self.text, &self.cuts))
        }
    }

    /// Calls `f` with the syntax tree: the unit's own when it is in memory,
    /// else one parsed again for this call only and dropped after it (a
    /// released tree stays released). For readers of other units than the
    /// one they work on.
    pub fn with_tree<R>(&self, f: impl FnOnce(&Tree) -> R) -> R {
        if let Some(tree) = self.tree.loaded() {
            return f(tree);
        }
        f(&self.parse_again())
    }

    /// Is the syntax tree in memory (kept, or parsed again by
    /// [`Unit::tree`] since it was released)?
    pub fn tree_loaded(&self) -> bool {
        self.tree.is_loaded()
    }

    /// This unit with its syntax tree in memory: itself if it is, else a
    /// copy (the same text, items and findings) with the tree parsed again,
    /// to check it and drop it ([`Task::with_unit`]).
    pub fn loaded(self: &Arc<Unit>) -> Arc<Unit> {
        if self.tree.is_loaded() {
            return self.clone();
        }
        Arc::new(Unit {
            path: self.path.clone(),
            text: self.text.clone(),
            tree: UnitTree::new(self.parse_again()),
            items: self.items.clone(),
            interface: self.interface,
            constants: self.constants,
            syntax: self.syntax.clone(),
            cuts: self.cuts.clone(),
            loads: self.loads.clone(),
            sync_bodies: self.sync_bodies.clone(),
        })
    }

    /// The lowered bodies of the unit's routines whose text names a
    /// synchronisation instruction ([`crate::sema::sync::mentions_sync`]),
    /// in source order: lowered once for both readers, the controller's
    /// synchronisation index and the MultiMove checks of the routine.
    pub(crate) fn sync_bodies(&self) -> &[crate::body::Body] {
        self.sync_bodies.get_or_init(|| {
            self.items
                .modules
                .iter()
                .flat_map(|m| &m.routines)
                .filter(|r| {
                    let text = self.text.get(r.range.clone()).unwrap_or_default();
                    crate::sema::sync::mentions_sync(text)
                })
                .filter_map(|r| crate::body::lower_routine(self, r))
                .collect()
        })
    }

    /// The lowered body of `routine` if it names a synchronisation
    /// instruction ([`Unit::sync_bodies`]).
    pub(crate) fn sync_body(&self, routine: &RoutineDecl) -> Option<&crate::body::Body> {
        self.sync_bodies().iter().find(|b| b.range == routine.range)
    }

    pub(crate) fn parse_again(&self) -> Tree {
        if self.cuts.is_empty() {
            crate::unit_tree::parse(&self.text)
        } else {
            crate::nesting::parse_copy(&self.text, &self.cuts)
        }
    }

    /// The parts of the text nested too deep to analyse (the tree has a
    /// placeholder or blanks there); empty for almost every file.
    pub fn cuts(&self) -> &[crate::nesting::Cut] {
        &self.cuts
    }

    /// Is this a module of the RobotWare installation that a repository
    /// happens to hold: RobotWare's own system modules (`BASE.sys`,
    /// `base_shared.sys`, `basefun.sys`, system modules that RobotWare marks
    /// `NOSTEPIN`), or a `user.sys` as RobotWare installs it (the registers
    /// `reg1` to `reg5` and `clock1`, nothing of the user's)? Its
    /// declarations count; its code is RobotWare's, not the user's, so only
    /// its syntax errors are reported.
    pub fn is_robotware(&self) -> bool {
        const SYSTEM: [&str; 3] = ["base.sys", "base_shared.sys", "basefun.sys"];
        const USER_DEFAULTS: [&str; 6] = ["reg1", "reg2", "reg3", "reg4", "reg5", "clock1"];
        let file = self
            .path
            .rsplit(['/', '\\'])
            .next()
            .unwrap_or_default()
            .to_ascii_lowercase();
        let modules = &self.items.modules;
        if modules.is_empty() || !modules.iter().all(|m| m.attributes.sysmodule) {
            return false;
        }
        if SYSTEM.contains(&file.as_str()) {
            return modules.iter().all(|m| m.attributes.nostepin);
        }
        file == "user.sys"
            && modules.iter().all(|m| {
                m.routines.is_empty()
                    && m.records.is_empty()
                    && m.aliases.is_empty()
                    && m.data
                        .iter()
                        .all(|d| USER_DEFAULTS.iter().any(|n| crate::names::same(n, &d.name)))
            })
    }

    fn empty(path: String, text: String, tree: Option<Tree>) -> Unit {
        match tree {
            Some(tree) => Unit {
                path,
                text,
                tree: UnitTree::new(tree),
                items: FileItems::default(),
                interface: 0,
                constants: 0,
                syntax: Vec::new(),
                loads: Default::default(),
                cuts: Vec::new(),
                sync_bodies: OnceLock::new(),
            },
            // No tree even for empty text means the grammar could not be
            // loaded at all, which the grammar's own tests rule out.
            None => unreachable_tree(path, text),
        }
    }
}

fn unreachable_tree(path: String, _text: String) -> Unit {
    panic!("tree-sitter returned no tree for an empty text ({path})")
}
