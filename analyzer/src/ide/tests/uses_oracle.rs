//! The oracle of the one-walk search for uses (`nav::uses`, behind
//! references, highlights and rename): every name of a fixture resolved
//! on its own, through parent links ([`resolve`]), and grouped by what it
//! denotes, must give exactly the uses that the walk finds, with the same
//! writes (told here the slow way, from parent links). And a routine of
//! 5,000 labels and GOTOs, which made the search quadratic, answers.

use std::collections::BTreeMap;

use super::fixture;
use crate::ide::resolve::{DefKey, is_name, resolve};
use crate::ide::{document_highlights, references, rename};
use crate::syntax::{field, kind};
use crate::syntax_util::walk_pruned;
use crate::task::Task;

const FIXTURE: &str = "==> a.mod
MODULE a
  RECORD part
    num weight;
    num count;
  ENDRECORD
  VAR num count := 0;
  VAR part parts{3};
  PERS num total := 0;
  PROC bump(INOUT num n, \\num by)
    n := n + 1;
    IF Present(by) n := n + by;
  ENDPROC
  PROC main(num count)
    VAR num k;
    FOR i FROM 1 TO 3 DO
      FOR j FROM 1 TO i DO
        parts{i}.count := parts{j}.count + count;
        bump parts{i}.weight \\by:=i;
        bump k;
      ENDFOR
    ENDFOR
    FOR i FROM 1 TO 2 DO
      k := k + i;
    ENDFOR
    l1:
    k := k + 1;
    IF k < 3 GOTO l1;
    total := total + k;
  ENDPROC
  PROC other()
    l1:
    count := count + 1;
    IF count < 3 GOTO l1;
    bump count;
    bump total \\by:=count;
  ENDPROC
ENDMODULE
==> b.mod
MODULE b
  FUNC num twice(num count)
    RETURN count * 2;
  ENDFUNC
  PROC main2()
    VAR part p;
    p.weight := twice(total);
    total := p.weight + count;
    bump p.count;
  ENDPROC
ENDMODULE
";

/// Every name node of the task: (unit, range, what it denotes, written?).
fn resolved_one_by_one(task: &Task) -> Vec<(usize, std::ops::Range<usize>, DefKey, bool)> {
    let mut out = Vec::new();
    for (ui, u) in task.units.iter().enumerate() {
        walk_pruned(u.tree().root_node(), &mut |n| {
            if is_name(n)
                && let Some(d) = resolve(task, ui, n)
            {
                out.push((ui, n.byte_range(), d.key(task), written(n)));
            }
            true
        });
    }
    out
}

/// Declared, assigned (the root object of the left side) or a FOR
/// variable, told through parent links. (Arguments of VAR, PERS and INOUT
/// parameters count as writes too; they are compared separately.)
fn written(node: tree_sitter::Node<'_>) -> bool {
    let field = crate::ide::resolve::field_in_parent(node);
    let Some(parent) = node.parent() else {
        return false;
    };
    if field == Some("name")
        && matches!(
            parent.kind(),
            kind::DATA_DECLARATION | kind::PARAMETER | kind::RECORD_COMPONENT
        )
    {
        return true;
    }
    if parent.kind() == kind::FOR_STATEMENT && field == Some(field::VARIABLE) {
        return true;
    }
    let mut n = node;
    loop {
        let f = crate::ide::resolve::field_in_parent(n);
        let Some(p) = n.parent() else {
            return false;
        };
        match (p.kind(), f) {
            (kind::ASSIGNMENT, Some(field::LEFT)) => return true,
            (kind::COMPONENT_ACCESS | kind::INDEX_EXPRESSION, Some(field::OBJECT)) => n = p,
            _ => return false,
        }
    }
}

#[test]
fn the_walk_finds_what_each_name_resolves_to() {
    let (task, _, _) = fixture(FIXTURE);
    let names = resolved_one_by_one(&task);
    let mut by_def: BTreeMap<String, Vec<(usize, usize)>> = BTreeMap::new();
    for (u, r, key, _) in &names {
        by_def
            .entry(format!("{key:?}"))
            .or_default()
            .push((*u, r.start));
    }
    let mut compared = 0;
    for (u, r, key, write) in &names {
        let Some(want) = by_def.get(&format!("{key:?}")) else {
            continue;
        };
        let mine: Vec<(usize, usize)> = want.iter().filter(|w| w.0 == *u).copied().collect();
        let hl = document_highlights(&task, *u, r.start);
        let got: Vec<(usize, usize)> = hl.iter().map(|(h, _)| (*u, h.start)).collect();
        let text = &task.units[*u].text[r.clone()];
        assert_eq!(got, mine, "highlights of `{text}` at {}", r.start);
        // Writes: at least what the parent links tell, and a write the
        // links do not tell is an argument of a VAR, PERS or INOUT
        // parameter (compared below).
        let here = hl.iter().find(|(h, _)| h.start == r.start).map(|(_, w)| *w);
        if *write {
            assert_eq!(here, Some(true), "`{text}` at {} is written", r.start);
        }
        let refs = references(&task, *u, r.start, true, &[]);
        let mut got: Vec<(usize, usize)> = refs
            .iter()
            .map(|l| {
                (
                    task.units
                        .iter()
                        .position(|x| x.path == l.path)
                        .unwrap_or(9),
                    l.range.start,
                )
            })
            .collect();
        got.sort_unstable();
        let mut want = want.clone();
        want.sort_unstable();
        if matches!(key, DefKey::At(..)) {
            assert_eq!(got, want, "references of `{text}` at {}", r.start);
        }
        compared += 1;
    }
    assert!(compared > 80, "{compared}");
    // The arguments of INOUT parameters are writes, the others reads.
    let (task, unit, offset) = fixture(&FIXTURE.replacen("VAR num k;", "VAR num k$0;", 1));
    let hl: Vec<bool> = document_highlights(&task, unit, offset)
        .into_iter()
        .map(|(_, w)| w)
        .collect();
    // VAR num k; bump k; k := k + i; k := k + 1; k < 3; total + k.
    assert_eq!(hl, vec![true, true, true, false, true, false, false, false]);
    let (task, unit, offset) = fixture(&FIXTURE.replacen("PERS num total", "PERS num tot$0al", 1));
    let hl: Vec<bool> = document_highlights(&task, unit, offset)
        .into_iter()
        .map(|(_, w)| w)
        .collect();
    // Declared; total := total + k; bump total \by:=count (INOUT).
    assert_eq!(hl, vec![true, true, false, true]);
}

#[test]
fn five_thousand_labels_in_one_routine_answer() {
    // Each search used to resolve every use through parent links and walk
    // the routine for each label: minutes. Linear now; the answer is the
    // oracle's, not a time.
    let n = 5_000;
    let mut body = String::new();
    for i in 0..n {
        body.push_str(&format!(
            "    l{i}:\n    GOTO l{};\n    GOTO l0;\n",
            (i + 1) % n
        ));
    }
    let src = format!("MODULE Lab\n  PROC main()\n{body}  ENDPROC\nENDMODULE\n");
    let (task, _, _) = fixture(&src);
    let text = &task.units[0].text;
    let first = text.find("l0:").unwrap_or(0);
    // l0: declared once, used by the last GOTO l{n} and by every GOTO l0.
    let refs = references(&task, 0, first, true, &[]);
    assert_eq!(refs.len(), 1 + 1 + n);
    assert!(refs.iter().all(|l| &text[l.range.clone()] == "l0"));
    let mid = text.find("l2500:").unwrap_or(0);
    assert_eq!(references(&task, 0, mid, true, &[]).len(), 2);
    let edits = rename(&task, 0, first, "start", &[]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(edits.iter().map(|(_, e)| e.len()).sum::<usize>(), 2 + n);
    assert_eq!(document_highlights(&task, 0, first).len(), 2 + n);
}
