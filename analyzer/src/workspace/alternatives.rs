//! Modules of one group that cannot be loaded together, and the views of a
//! task that leave them out.
//!
//! A controller loads one module of each name into a task, so two files of
//! one task that declare the same module are two versions of it. In a plain
//! folder, whose grouping is only a guess, modules that declare the same
//! entry routine (`main`) are taken for alternative programs too: real
//! folders hold a program next to its earlier versions, or several
//! exercises side by side. Modules of a plain folder that declare largely
//! the same globals (at least [`COPY_SHARED`] of them, and at least half of
//! the globals of the one with fewer) are copies of one module for
//! different tasks or cells (a left and a right arm's driver): no task can
//! load both, as every shared name would be ambiguous. Each such module is
//! checked in a view of the task without the modules it clashes with, so neither version's names are
//! "ambiguous" and each is checked against the rest of the folder (the
//! shared modules a program is meant to run with). Other names declared
//! twice are still reported, as warnings in a plain folder.

use std::collections::HashMap;
use std::sync::Arc;

use crate::layout::Grouping;
use crate::names::fold;
use crate::task::{Clashes, Unit};

/// The entry routine a program starts from unless configured otherwise.
const ENTRY: &str = "main";

/// The fewest shared globals that make two modules of a plain folder copies
/// of one module (one or two shared names are more likely a real clash).
const COPY_SHARED: usize = 3;

/// The folded names of a module's global declarations.
fn globals(module: &crate::items::Module) -> std::collections::HashSet<String> {
    module.global_names().map(fold).collect()
}

/// Pairs of units of a plain folder that are copies of one module
/// ([`COPY_SHARED`]). Counted through the names (each unit pair that shares
/// one), not by comparing every pair of units; a name more than
/// [`MOST_SHARING`] units declare is left out of the count.
fn copies(units: &[Arc<Unit>]) -> Vec<(usize, usize)> {
    let sets: Vec<std::collections::HashSet<String>> = units
        .iter()
        .map(|u| u.items.modules.iter().flat_map(globals).collect())
        .collect();
    let mut declaring: HashMap<&str, Vec<usize>> = HashMap::new();
    for (u, set) in sets.iter().enumerate() {
        for name in set {
            declaring.entry(name).or_default().push(u);
        }
    }
    let mut shared: HashMap<(usize, usize), usize> = HashMap::new();
    for list in declaring.values().filter(|l| l.len() <= MOST_SHARING) {
        for (i, &a) in list.iter().enumerate() {
            for &b in &list[i + 1..] {
                *shared.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
    }
    let mut out: Vec<(usize, usize)> = shared
        .into_iter()
        .filter(|&((a, b), n)| n >= COPY_SHARED && 2 * n >= sets[a].len().min(sets[b].len()))
        .map(|(pair, _)| pair)
        .collect();
    out.sort_unstable();
    out
}

/// The most units a name may be declared in and still count towards
/// [`copies`] (bounds the pairs counted in a folder of thousands of files).
const MOST_SHARING: usize = 256;

/// The units of a group that clash with others: units that declare the
/// same module, and in a plain folder units that both declare the entry
/// routine or are copies of one module.
pub(super) fn clashes(units: &[Arc<Unit>], grouping: Grouping) -> Clashes {
    // Folded module names to the units that declare them.
    let mut modules: HashMap<String, Vec<usize>> = HashMap::new();
    let mut entries: Vec<usize> = Vec::new();
    for (u, unit) in units.iter().enumerate() {
        for module in &unit.items.modules {
            modules.entry(fold(&module.name)).or_default().push(u);
            let entry = module
                .routines
                .iter()
                .any(|r| !r.local && r.name.eq_ignore_ascii_case(ENTRY));
            if grouping == Grouping::Folder && entry {
                entries.push(u);
            }
        }
    }
    let mut classes: Vec<Vec<usize>> = modules.into_values().filter(|l| l.len() > 1).collect();
    classes.push(entries);
    let pairs = match grouping {
        Grouping::Folder => copies(units),
        _ => Vec::new(),
    };
    Clashes::new(units.len(), classes, &pairs)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(path: &str, text: &str) -> Arc<Unit> {
        Arc::new(Unit::new(path.into(), text.into(), None))
    }

    #[test]
    fn copies_of_one_module_in_a_plain_folder_clash() {
        let left = "MODULE HandL\n  VAR num a;\n  VAR num b;\n  PROC c()\n  ENDPROC\n  PROC d()\n  ENDPROC\nENDMODULE\n";
        let right = left.replace("HandL", "HandR");
        // shares one global of its two: a real clash, not a copy
        let other = "MODULE Other\n  VAR num a;\n  VAR num e;\nENDMODULE\n";
        let units = [
            unit("f/l.sys", left),
            unit("f/r.sys", &right),
            unit("f/o.mod", other),
        ];
        let found = clashes(&units, Grouping::Folder);
        assert_eq!(found.partners(0), vec![1]);
        assert_eq!(found.partners(1), vec![0]);
        assert!(!found.any(2));
        // a backup's task loads what it has: never guessed
        assert!(clashes(&units, Grouping::Backup).is_empty());
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
        assert_eq!(found.partners(0), vec![1]);
        assert_eq!(found.partners(1), vec![0]);
        assert!(!found.any(2));
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
        assert_eq!(found.partners(0), vec![1]);
        assert!(!found.any(2));
    }

    #[test]
    fn a_view_leaves_out_the_clashing_units() {
        let units = vec![
            unit("t/a.mod", "MODULE Main\n  PROC p()\n  ENDPROC\nENDMODULE\n"),
            unit("t/b.mod", "MODULE Main\n  PROC p()\n  ENDPROC\nENDMODULE\n"),
            unit("t/c.mod", "MODULE Tools\nENDMODULE\n"),
        ];
        let mut group = crate::task::Task::new("t".into(), units.clone(), None);
        group.clashes = Arc::new(clashes(&units, Grouping::Backup));
        assert!(!group.owns(1) && group.owns(2));
        assert_eq!(group.globals.get("p").map(|r| r.len()), Some(2));
        let view = group.view(1);
        let live: Vec<&str> = view.live_units().map(|(_, u)| u.path.as_str()).collect();
        assert_eq!(live, ["t/b.mod", "t/c.mod"]);
        let left: Vec<&str> = view.left_out().map(|u| u.path.as_str()).collect();
        assert_eq!(left, ["t/a.mod"]);
        let p = view
            .globals
            .get("p")
            .map(|r| r.to_vec())
            .unwrap_or_default();
        assert_eq!(p.len(), 1);
        assert_eq!(p[0].unit, 1);
        // the view shares the group's units
        assert!(Arc::ptr_eq(&view.units, &group.units));
    }
}
