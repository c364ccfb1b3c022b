//! "Did you mean": the visible name of the same kind nearest to an
//! unresolved one, by edit distance.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

use super::Cx;
use crate::names::fold;
use crate::task::{Item, Task};

impl Cx<'_> {
    /// A visible name of the same kind within a small edit distance of
    /// `name`, with that distance: the first closest of the routine's data
    /// and parameters, then the module's, then the task's globals. A
    /// suggestion of another kind (a data type for a variable) would mislead
    /// more than help.
    pub(crate) fn close_match(&mut self, name: &str, kind: Kind) -> Option<(usize, String)> {
        let key = fold(name);
        let limit = if chars(&key) <= 4 { 1 } else { 2 };
        let mut best = None;
        if kind == Kind::Data {
            best = self.routine.as_ref().and_then(|r| {
                let locals = r.locals.values().map(|d| d.name.as_str());
                closest(
                    &key,
                    limit,
                    locals.chain(r.params.values().map(|p| p.name.as_str())),
                )
            });
        }
        // The module's part does not depend on the routine: remembered per
        // module (a module may declare thousands of data).
        if let Some((mi, m)) = self.module {
            let memo_key = (mi, kind, key.clone());
            let found = match self.module_close_memo.get(&memo_key) {
                Some(found) => found.clone(),
                None => {
                    let found = match kind {
                        Kind::Data => closest(&key, limit, m.data.iter().map(|d| d.name.as_str())),
                        Kind::Routine => {
                            closest(&key, limit, m.routines.iter().map(|r| r.name.as_str()))
                        }
                        Kind::Type => closest(
                            &key,
                            limit,
                            m.records
                                .iter()
                                .map(|r| r.name.as_str())
                                .chain(m.aliases.iter().map(|a| a.name.as_str())),
                        ),
                    };
                    self.module_close_memo.insert(memo_key, found.clone());
                    found
                }
            };
            keep_nearer(&mut best, found);
        }
        keep_nearer(&mut best, close_global(self.task, &key, limit, kind));
        best
    }
}

/// The first of the names nearest to `key` (folded), with its distance:
/// at least one edit and at most `limit`.
fn closest<'n>(
    key: &str,
    limit: usize,
    names: impl IntoIterator<Item = &'n str>,
) -> Option<(usize, String)> {
    let mut best: Option<(usize, &str)> = None;
    for cand in names {
        let d = edit_distance_folded(key, cand);
        if d > 0 && d <= limit && best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, cand));
        }
    }
    best.map(|(d, n)| (d, n.to_owned()))
}

/// Puts `other` in `best` if it is strictly nearer.
fn keep_nearer(best: &mut Option<(usize, String)>, other: Option<(usize, String)>) {
    if let Some((d, n)) = other
        && best.as_ref().is_none_or(|(bd, _)| d < *bd)
    {
        *best = Some((d, n));
    }
}

/// The task's global name of kind `kind` closest to `key` within `limit`
/// edits: the first (in the index's order) of the nearest.
fn close_global(task: &Task, key: &str, limit: usize, kind: Kind) -> Option<(usize, String)> {
    let near = task.close_names.near(task, key, limit);
    let mut best: Option<(usize, String)> = None;
    for (d, folded) in near.iter() {
        if best.as_ref().is_some_and(|(bd, _)| d >= bd) {
            continue;
        }
        let Some(r) = task.globals.refs(folded).find(|r| kind.matches(r.item)) else {
            continue;
        };
        if let Some((n, _)) = task.item_name(r) {
            best = Some((*d, n.to_owned()));
        }
    }
    best
}

/// The global names of a task near others, for "did you mean": built
/// once per group and shared by its views (which leave out what they hide
/// when they pick a name). Asking for a name costs the names of about its
/// length, not every name of the task.
#[derive(Debug, Default)]
pub(crate) struct CloseNames {
    /// The folded global names by length, each with its place in the
    /// index's order.
    by_len: OnceLock<Vec<Vec<(usize, String)>>>,
    /// For each folded name asked, the global names within its limit:
    /// (distance, folded name), in the index's order. The same unresolved
    /// name tends to recur in many places and files.
    near: Mutex<HashMap<String, Near>>,
}

/// Names near an asked one: (distance, folded name).
type Near = Arc<[(usize, String)]>;

impl CloseNames {
    fn near(&self, task: &Task, key: &str, limit: usize) -> Near {
        let mut memo = self.near.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(found) = memo.get(key) {
            return found.clone();
        }
        let by_len = self.by_len.get_or_init(|| {
            let mut by_len: Vec<Vec<(usize, String)>> = Vec::new();
            for (order, name) in task.globals.names().enumerate() {
                let len = chars(name);
                if by_len.len() <= len {
                    by_len.resize_with(len + 1, Vec::new);
                }
                by_len[len].push((order, name.clone()));
            }
            by_len
        });
        let len = chars(key);
        let lo = len.saturating_sub(limit).min(by_len.len());
        let hi = (len + limit + 1).min(by_len.len());
        let mut found: Vec<(usize, usize, &str)> = by_len[lo..hi]
            .iter()
            .flatten()
            .filter_map(|(order, name)| {
                let d = edit_distance(key, name);
                (d > 0 && d <= limit).then_some((*order, d, name.as_str()))
            })
            .collect();
        found.sort_unstable_by_key(|&(order, _, _)| order);
        let found: Arc<[(usize, String)]> = found
            .into_iter()
            .map(|(_, d, n)| (d, n.to_owned()))
            .collect();
        memo.insert(key.to_owned(), found.clone());
        found
    }
}

/// What kind of name a "did you mean" looks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Kind {
    Data,
    Routine,
    Type,
}

impl Kind {
    /// From the word [`Cx::unresolved`] is given: "data", "routine", "data type".
    pub(crate) fn of(what: &str) -> Kind {
        match what {
            "routine" => Kind::Routine,
            "data type" => Kind::Type,
            _ => Kind::Data,
        }
    }

    fn matches(self, item: Item) -> bool {
        matches!(
            (self, item),
            (Kind::Data, Item::Data(_))
                | (Kind::Routine, Item::Routine(_))
                | (Kind::Type, Item::Record(_) | Item::Alias(_))
        )
    }
}

/// The number of characters of a name (its length in bytes when ASCII).
fn chars(name: &str) -> usize {
    if name.is_ascii() {
        name.len()
    } else {
        name.chars().count()
    }
}

/// Levenshtein distance of two short names, in characters (a Latin-1
/// letter is one edit, as the controller counts it).
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    if a.is_ascii() && b.is_ascii() {
        return distance(a.as_bytes(), b.as_bytes(), |x, y| x == y);
    }
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    distance(&a, &b, |x, y| x == y)
}

/// [`edit_distance`] between a folded `key` and `name` as if `name` were
/// folded too (without allocating its folded form when ASCII).
fn edit_distance_folded(key: &str, name: &str) -> usize {
    if key.is_ascii() && name.is_ascii() {
        return distance(key.as_bytes(), name.as_bytes(), |x, y| {
            x == y.to_ascii_lowercase()
        });
    }
    let (a, b): (Vec<char>, Vec<char>) = (key.chars().collect(), name.chars().collect());
    distance(&a, &b, |x, y| x == crate::names::fold_char(y))
}

/// The edit distance of two sequences (a character added, left out or
/// changed, or two neighbours swapped, each one edit: the optimal string
/// alignment distance), or 3 when it is more than 2 (callers only care
/// about distances up to 2).
fn distance<T: Copy>(a: &[T], b: &[T], eq: impl Fn(T, T) -> bool) -> usize {
    if a.len().abs_diff(b.len()) > 2 {
        return 3;
    }
    let width = b.len() + 1;
    // Three rows: the one before the previous, the previous, this one (on
    // the stack for names of usual length).
    const STACK: usize = 3 * 64;
    let mut stack = [0usize; STACK];
    let mut heap;
    let rows: &mut [usize] = if 3 * width <= STACK {
        &mut stack[..3 * width]
    } else {
        heap = vec![0usize; 3 * width];
        &mut heap
    };
    for (j, cell) in rows[width..2 * width].iter_mut().enumerate() {
        *cell = j;
    }
    for (i, &ca) in a.iter().enumerate() {
        let (before, rest) = rows.split_at_mut(width);
        let (prev, cur) = rest.split_at_mut(width);
        cur[0] = i + 1;
        let mut row_min = cur[0];
        for (j, &cb) in b.iter().enumerate() {
            let cost = usize::from(!eq(ca, cb));
            let mut d = (prev[j] + cost).min(prev[j + 1] + 1).min(cur[j] + 1);
            if i > 0 && j > 0 && eq(ca, b[j - 1]) && eq(a[i - 1], cb) {
                d = d.min(before[j - 1] + 1);
            }
            cur[j + 1] = d;
            row_min = row_min.min(d);
        }
        // The distance is at least the smallest value of any row.
        if row_min > 2 {
            return 3;
        }
        rows.rotate_left(width);
    }
    rows[2 * width - 1].min(3)
}

#[cfg(test)]
mod distance_tests {
    #[test]
    fn edit_distances() {
        for (a, b, d) in [
            ("movel", "movel", 0),
            ("movel", "movej", 1),
            ("movel", "mvel", 1),
            ("ptarget", "ptraget", 1),
            ("cuont", "count", 1),
            ("ptarget", "tpraget", 2),
            ("abc", "abcdef", 3),
            ("", "ab", 2),
        ] {
            assert_eq!(super::edit_distance(a, b), d, "{a} {b}");
            assert_eq!(
                super::edit_distance_folded(a, &b.to_uppercase()),
                d,
                "{a} {b}"
            );
        }
        // a Latin-1 letter is one character, folded as the controller does
        assert_eq!(super::edit_distance("sensör", "sensor"), 1);
        assert_eq!(super::edit_distance_folded("varölcüm", "VARÖLCÜM"), 0);
        assert_eq!(super::edit_distance_folded("ñ", "N"), 1);
        let long = "x".repeat(70);
        assert_eq!(super::edit_distance(&long, &format!("{long}y")), 1);
    }
}
