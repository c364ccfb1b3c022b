//! The statement cache: results of single statements, reused by the next
//! check when a statement's text and context are unchanged.

use std::collections::HashMap;
use std::hash::BuildHasherDefault;
use std::ops::Range;

use tree_sitter::Node;

use super::{Cx, StatementContext, Used};
use crate::diagnostic::Diagnostic;

/// Results of single statements, by a key of the statement's text and its
/// context, with diagnostic ranges relative to the statement's start.
#[derive(Debug, Default)]
pub struct StmtCache {
    entries: HashMap<u64, CachedStmt, BuildHasherDefault<KeyHasher>>,
    /// How many statements the check that made this cache took from the
    /// previous one.
    reused: usize,
    /// Checks made with this cache: each entry is stamped with the last one
    /// that met its statement, and the others are dropped after a check.
    generation: u64,
    /// Routines entered by checks made with this cache (never reset), so
    /// that an entry can tell whether its uses were already recorded in the
    /// routine being checked.
    pub(super) routines: u64,
}

impl StmtCache {
    /// How many statement results it holds.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// How many statements the check that made this cache did not redo.
    pub fn reused(&self) -> usize {
        self.reused
    }

    /// Stamps the entries a new check meets with its generation.
    pub(super) fn start_check(&mut self) {
        self.generation += 1;
        self.reused = 0;
    }

    /// Keeps only what the last check met (as if the cache were made
    /// afresh).
    pub(super) fn drop_stale(&mut self) {
        let generation = self.generation;
        self.entries.retain(|_, e| e.generation == generation);
    }
}

/// The cache's keys are hashes already: use them as they are.
#[derive(Default)]
pub(crate) struct KeyHasher(u64);

impl std::hash::Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.0 = self.0.rotate_left(8) ^ u64::from(*b);
        }
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = n;
    }
}

#[derive(Clone, Debug)]
pub(crate) struct CachedStmt {
    diags: Vec<Diagnostic>,
    used: Vec<Used>,
    /// The last check that met this statement.
    generation: u64,
    /// The last routine (a [`StmtCache::routines`] count) whose `used` set
    /// holds this statement's uses.
    routine: u64,
}

impl<'t> Cx<'t> {
    /// Checks a statement through the cache: a statement whose text and
    /// context are unchanged gets its previous findings back.
    pub(crate) fn cached_statement(&mut self, s: Node<'t>, check: impl FnOnce(&mut Cx<'t>)) {
        if !self.cache_enabled || self.recording.is_some() {
            check(self);
            return;
        }
        let Some(key) = self.statement_key(s) else {
            check(self);
            return;
        };
        let start = s.start_byte();
        let generation = self.cache.generation;
        let routine = self.cache.routines;
        if let Some(c) = self.cache.entries.get_mut(&key) {
            c.generation = generation;
            for d in &c.diags {
                // An unconfigured signal is kept once per name, at its first
                // use in source order: a copy that a reused one already
                // precedes (or ties with, being pushed earlier) would be
                // dropped at the end anyway.
                let at = (d.range.start + start, d.range.end + start);
                if std::ptr::eq(d.rule, &crate::rules::unconfigured_signal::RULE) {
                    match self.reused_signals.get_mut(&d.message) {
                        Some(first) if *first <= at => continue,
                        Some(first) => *first = at,
                        None => {
                            self.reused_signals.insert(d.message.clone(), at);
                        }
                    }
                }
                let mut d = d.clone();
                d.range = d.range.start + start..d.range.end + start;
                for r in &mut d.related {
                    if r.file.is_none() {
                        r.range = r.range.start + start..r.range.end + start;
                    }
                }
                if let Some(f) = &mut d.fix {
                    for e in &mut f.edits {
                        e.range = e.range.start + start..e.range.end + start;
                    }
                }
                self.diags.push(d);
            }
            // The same statement met again in this routine: its uses are
            // recorded already.
            if c.routine != routine {
                c.routine = routine;
                for u in &c.used {
                    if !self.used.contains(u) {
                        self.used.insert(u.clone());
                    }
                }
            }
            self.cache.reused += 1;
            return;
        }
        let before = self.diags.len();
        self.recording = Some(Vec::new());
        check(self);
        let used = self.recording.take().unwrap_or_default();
        let range = s.byte_range();
        let inside = |r: &Range<usize>| range.start <= r.start && r.end <= range.end;
        let found = self.diags.get(before..).unwrap_or_default();
        let cacheable = found.iter().all(|d| {
            inside(&d.range)
                && d.related
                    .iter()
                    .all(|r| r.file.is_some() || inside(&r.range))
                && d.fix
                    .as_ref()
                    .is_none_or(|f| f.edits.iter().all(|e| inside(&e.range)))
        });
        if cacheable {
            let rel = |r: &Range<usize>| r.start - start..r.end - start;
            let diags = found
                .iter()
                .map(|d| {
                    let mut d = d.clone();
                    d.range = rel(&d.range);
                    for r in &mut d.related {
                        if r.file.is_none() {
                            r.range = rel(&r.range);
                        }
                    }
                    if let Some(f) = &mut d.fix {
                        for e in &mut f.edits {
                            e.range = rel(&e.range);
                        }
                    }
                    d
                })
                .collect();
            self.cache.entries.insert(
                key,
                CachedStmt {
                    diags,
                    used,
                    generation,
                    routine,
                },
            );
        }
    }

    /// The cache key of a statement: its text and everything around it that
    /// its check reads (routine declarations, handler, FOR variables, module,
    /// the task's interface and constants).
    fn statement_key(&mut self, s: Node<'_>) -> Option<u64> {
        use std::hash::{Hash, Hasher};
        let r = self.routine.as_ref()?;
        let module = self.module_idx();
        // The context changes rarely: hash it once per change.
        let context = match &self.statement_context {
            Some(c)
                if c.fingerprint == self.routine_fingerprint
                    && c.in_error_handler == self.in_error_handler
                    && c.module == module
                    && c.for_vars.iter().eq(r.for_vars.iter().map(|(v, _)| v)) =>
            {
                c.hash
            }
            _ => {
                let mut h = std::hash::DefaultHasher::new();
                self.routine_fingerprint.hash(&mut h);
                self.in_error_handler.hash(&mut h);
                // The names only: where the loops are does not change a
                // statement's findings.
                for (v, _) in &r.for_vars {
                    v.hash(&mut h);
                }
                module.hash(&mut h);
                self.task.interface.hash(&mut h);
                self.task.constants.hash(&mut h);
                self.selection.hash(&mut h);
                let hash = h.finish();
                self.statement_context = Some(StatementContext {
                    fingerprint: self.routine_fingerprint,
                    in_error_handler: self.in_error_handler,
                    for_vars: r.for_vars.iter().map(|(v, _)| v.clone()).collect(),
                    module,
                    hash,
                });
                hash
            }
        };
        let mut h = std::hash::DefaultHasher::new();
        context.hash(&mut h);
        self.node_text(s).hash(&mut h);
        Some(h.finish())
    }
}
