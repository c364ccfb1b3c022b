//! Modules of one group that cannot be loaded together, and the views of a
//! task that leave them out.
//!
//! A controller loads one module of each name into a task, so two files of
//! one task that declare the same module are two versions of it. In a plain
//! folder, whose grouping is only a guess, modules that declare the same
//! global name (the same entry routine `main`, the same targets) are taken
//! for alternative versions too: real folders hold a program next to its
//! earlier versions. Each such module is checked in a view of the task
//! without the modules it clashes with, so neither version's names are
//! "ambiguous" and each is checked against the rest of the folder.

use std::collections::HashMap;
use std::sync::Arc;

use crate::items::Storage;
use crate::layout::Grouping;
use crate::names::fold;
use crate::task::{Excluded, Unit, module_items};

/// A declaration of a global name: its unit, and for a persistent its type
/// (folded) and rank (one name may declare one persistent in several
/// modules).
type Global = (usize, Option<(String, usize)>);

/// For each unit of a group (by index) that clashes with others, the units
/// it clashes with, in order.
pub(super) fn clashes(units: &[Arc<Unit>], grouping: Grouping) -> HashMap<usize, Vec<usize>> {
    // Folded names to the units that declare them.
    let mut modules: HashMap<String, Vec<usize>> = HashMap::new();
    let mut globals: HashMap<String, Vec<Global>> = HashMap::new();
    for (u, unit) in units.iter().enumerate() {
        for module in &unit.items.modules {
            modules.entry(fold(&module.name)).or_default().push(u);
            if grouping != Grouping::Folder {
                continue;
            }
            for (name, local, item) in module_items(module) {
                if local {
                    continue;
                }
                let pers = match item {
                    crate::task::Item::Data(i) => module
                        .data
                        .get(i)
                        .filter(|d| d.storage == Storage::Pers)
                        .and_then(|d| Some((fold(&d.ty.as_ref()?.name), d.dims.len()))),
                    _ => None,
                };
                globals.entry(fold(name)).or_default().push((u, pers));
            }
        }
    }
    let mut out: HashMap<usize, Vec<usize>> = HashMap::new();
    let mut clash = |a: usize, b: usize| {
        if a != b {
            out.entry(a).or_default().push(b);
            out.entry(b).or_default().push(a);
        }
    };
    for list in modules.values() {
        for (i, &a) in list.iter().enumerate() {
            for &b in &list[i + 1..] {
                clash(a, b);
            }
        }
    }
    for list in globals.values() {
        for (i, (a, pa)) in list.iter().enumerate() {
            for (b, pb) in &list[i + 1..] {
                // One persistent declared in two modules is one object.
                let same_persistent = pa.is_some() && pa == pb;
                if !same_persistent {
                    clash(*a, *b);
                }
            }
        }
    }
    for list in out.values_mut() {
        list.sort_unstable();
        list.dedup();
    }
    out
}

/// The units of a view for unit `owner`: every unit of the group but those
/// it clashes with, the owner's new index among them, and what was left out.
pub(super) fn view_units(
    units: &[Arc<Unit>],
    owner: usize,
    left_out: &[usize],
) -> (Vec<Arc<Unit>>, usize, Vec<Excluded>) {
    let mut kept = Vec::new();
    let mut excluded = Vec::new();
    let mut index = 0;
    for (i, unit) in units.iter().enumerate() {
        if left_out.contains(&i) {
            excluded.push(Excluded {
                path: unit.path.clone(),
                modules: unit
                    .items
                    .modules
                    .iter()
                    .map(|m| (m.name.clone(), m.name_range.clone()))
                    .collect(),
            });
            continue;
        }
        if i == owner {
            index = kept.len();
        }
        kept.push(unit.clone());
    }
    (kept, index, excluded)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(path: &str, text: &str) -> Arc<Unit> {
        Arc::new(Unit::new(path.into(), text.into(), None))
    }

    #[test]
    fn module_names_clash_in_every_grouping() {
        let units = [
            unit(
                "t/a.mod",
                "MODULE Main\n  PROC main()\n  ENDPROC\nENDMODULE\n",
            ),
            unit(
                "t/b.mod",
                "MODULE MAIN\n  PROC other()\n  ENDPROC\nENDMODULE\n",
            ),
            unit("t/c.mod", "MODULE Tools\nENDMODULE\n"),
        ];
        let found = clashes(&units, Grouping::Backup);
        assert_eq!(found.get(&0), Some(&vec![1]));
        assert_eq!(found.get(&1), Some(&vec![0]));
        assert_eq!(found.get(&2), None);
    }

    #[test]
    fn shared_globals_clash_only_in_plain_folders() {
        let units = [
            unit(
                "f/a.mod",
                "MODULE A\n  PERS num n := 1;\n  PROC main()\n  ENDPROC\nENDMODULE\n",
            ),
            unit(
                "f/b.mod",
                "MODULE B\n  PERS num n := 2;\n  PROC main()\n  ENDPROC\nENDMODULE\n",
            ),
            unit("f/c.mod", "MODULE C\n  PERS num n := 3;\nENDMODULE\n"),
        ];
        assert!(clashes(&units, Grouping::Backup).is_empty());
        let found = clashes(&units, Grouping::Folder);
        // `main` twice; the persistent `n` of one type is one object.
        assert_eq!(found.get(&0), Some(&vec![1]));
        assert_eq!(found.get(&2), None);
    }

    #[test]
    fn a_view_leaves_out_the_clashing_units() {
        let units = [
            unit("t/a.mod", "MODULE Main\nENDMODULE\n"),
            unit("t/b.mod", "MODULE Main\nENDMODULE\n"),
            unit("t/c.mod", "MODULE Tools\nENDMODULE\n"),
        ];
        let (kept, owner, excluded) = view_units(&units, 1, &[0]);
        assert_eq!(kept.len(), 2);
        assert_eq!(kept[owner].path, "t/b.mod");
        assert_eq!(excluded.len(), 1);
        assert_eq!(excluded[0].path, "t/a.mod");
        assert_eq!(excluded[0].modules[0].0, "Main");
    }
}
