//! Which modules of a group clash (cannot be loaded together), and the name
//! index as a view of the group sees it.
//!
//! A view of a task for one of its units leaves out the units that clash
//! with it ([`crate::workspace`]'s alternatives). Views share the group's
//! units and name index: a view costs the same whatever the size of its
//! group, and looking a name up filters out what the view leaves out.

use std::borrow::Cow;
use std::collections::HashMap;
use std::sync::Arc;

use super::ItemRef;
use crate::names::NameMap;

/// The units of a group that clash with others, in classes: every two
/// members of one class clash (the files of one module name; in a plain
/// folder, the programs with an entry routine), and so do the pairs of
/// copies of one module. Linear in the units and classes: a class of `k`
/// members is `k` entries, not `k²` pairs.
#[derive(Debug, Default)]
pub struct Clashes {
    /// Each unit's classes, sorted (empty for a unit that clashes with no
    /// class; units past the end are in none).
    classes: Vec<Box<[u32]>>,
    /// The members of each class, sorted; every class has two or more.
    members: Vec<Vec<usize>>,
    /// Pairs of units that are copies of one module: each unit's partners,
    /// sorted.
    copies: HashMap<usize, Vec<usize>>,
}

impl Clashes {
    /// Clashes of `units` units: `classes` are the sets of units that
    /// clash with each other (sets of fewer than two are dropped), `pairs`
    /// further pairs that clash.
    pub fn new(units: usize, classes: Vec<Vec<usize>>, pairs: &[(usize, usize)]) -> Clashes {
        let mut out = Clashes {
            classes: vec![Box::default(); units],
            ..Clashes::default()
        };
        let mut of_unit: Vec<Vec<u32>> = vec![Vec::new(); units];
        for mut members in classes {
            members.sort_unstable();
            members.dedup();
            members.retain(|&u| u < units);
            if members.len() < 2 {
                continue;
            }
            let id = u32::try_from(out.members.len()).unwrap_or(u32::MAX);
            for &u in &members {
                of_unit[u].push(id);
            }
            out.members.push(members);
        }
        for (slot, ids) in out.classes.iter_mut().zip(of_unit) {
            *slot = ids.into_boxed_slice();
        }
        for &(a, b) in pairs {
            if a != b && a < units && b < units {
                out.copies.entry(a).or_default().push(b);
                out.copies.entry(b).or_default().push(a);
            }
        }
        for list in out.copies.values_mut() {
            list.sort_unstable();
            list.dedup();
        }
        out
    }

    /// Do units `a` and `b` clash?
    pub fn clash(&self, a: usize, b: usize) -> bool {
        if a == b {
            return false;
        }
        let (ca, cb) = (self.classes_of(a), self.classes_of(b));
        if !ca.is_empty() && !cb.is_empty() && ca.iter().any(|c| cb.binary_search(c).is_ok()) {
            return true;
        }
        self.copies
            .get(&a)
            .is_some_and(|p| p.binary_search(&b).is_ok())
    }

    /// Does unit `a` clash with any other?
    pub fn any(&self, a: usize) -> bool {
        !self.classes_of(a).is_empty() || self.copies.contains_key(&a)
    }

    /// Does no unit clash with another?
    pub fn is_empty(&self) -> bool {
        self.members.is_empty() && self.copies.is_empty()
    }

    /// The units `a` clashes with, sorted.
    pub fn partners(&self, a: usize) -> Vec<usize> {
        let mut out: Vec<usize> = self
            .classes_of(a)
            .iter()
            .filter_map(|&c| self.members.get(c as usize))
            .flatten()
            .chain(self.copies.get(&a).into_iter().flatten())
            .copied()
            .filter(|&u| u != a)
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    fn classes_of(&self, a: usize) -> &[u32] {
        self.classes.get(a).map_or(&[], |c| c)
    }
}

/// A task's declarations by folded name, as the task (or a view of it)
/// sees them: the group's index, shared by its views, without the units a
/// view leaves out.
#[derive(Clone, Debug, Default)]
pub struct NameIndex {
    map: Arc<NameMap<Vec<ItemRef>>>,
    view: Option<View>,
}

/// What a view leaves out: the units that clash with its owner.
#[derive(Clone, Debug)]
pub(crate) struct View {
    pub owner: usize,
    pub clashes: Arc<Clashes>,
}

impl View {
    /// Does the view leave unit `u` out?
    pub fn hides(&self, u: usize) -> bool {
        self.clashes.clash(self.owner, u)
    }
}

impl NameIndex {
    pub(crate) fn new(map: NameMap<Vec<ItemRef>>) -> NameIndex {
        NameIndex {
            map: Arc::new(map),
            view: None,
        }
    }

    /// The same index, as the view `view` sees it.
    pub(crate) fn seen_by(&self, view: Option<View>) -> NameIndex {
        NameIndex {
            map: self.map.clone(),
            view,
        }
    }

    /// The declarations of the folded name `key` (never empty).
    pub fn get(&self, key: &str) -> Option<Cow<'_, [ItemRef]>> {
        self.visible(self.map.get(key)?)
    }

    /// The declarations of the folded name `key`, one by one.
    pub fn refs(&self, key: &str) -> impl Iterator<Item = ItemRef> + '_ {
        self.map
            .get(key)
            .into_iter()
            .flatten()
            .copied()
            .filter(|r| !self.view.as_ref().is_some_and(|v| v.hides(r.unit)))
    }

    pub fn contains_key(&self, key: &str) -> bool {
        self.refs(key).next().is_some()
    }

    /// Every folded name with its declarations.
    pub fn iter(&self) -> impl Iterator<Item = (&String, Cow<'_, [ItemRef]>)> {
        self.map
            .iter()
            .filter_map(|(k, refs)| Some((k, self.visible(refs)?)))
    }

    /// Every folded name, those a view hides all declarations of included.
    pub fn names(&self) -> impl Iterator<Item = &String> {
        self.map.keys()
    }

    /// Every name's declarations.
    pub fn values(&self) -> impl Iterator<Item = Cow<'_, [ItemRef]>> {
        self.iter().map(|(_, refs)| refs)
    }

    fn visible<'a>(&self, refs: &'a [ItemRef]) -> Option<Cow<'a, [ItemRef]>> {
        let out = match &self.view {
            Some(v) if refs.iter().any(|r| v.hides(r.unit)) => {
                Cow::Owned(refs.iter().copied().filter(|r| !v.hides(r.unit)).collect())
            }
            _ => Cow::Borrowed(refs),
        };
        (!out.is_empty()).then_some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_and_pairs_clash() {
        // 0, 1, 2 one class; 3 and 4 copies; 5 alone
        let c = Clashes::new(6, vec![vec![0, 1, 2], vec![5]], &[(3, 4)]);
        assert!(c.clash(0, 2) && c.clash(2, 1) && c.clash(3, 4) && c.clash(4, 3));
        assert!(!c.clash(0, 0) && !c.clash(0, 3) && !c.clash(5, 0));
        assert!(c.any(1) && c.any(4) && !c.any(5) && !c.any(9));
        assert_eq!(c.partners(1), vec![0, 2]);
        assert_eq!(c.partners(3), vec![4]);
        assert!(c.partners(5).is_empty());
        assert!(Clashes::new(3, vec![vec![1]], &[]).is_empty());
    }
}
