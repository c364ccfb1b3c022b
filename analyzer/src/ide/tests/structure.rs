use super::fixture;
use crate::ide::{
    SymbolKind, document_symbols, folding_ranges, selection_ranges, workspace_symbols,
};

const SRC: &str = "%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%%\nMODULE m\n  ! first\n  ! second\n  RECORD part\n    num weight;\n  ENDRECORD\n  CONST num k := 2;\n  PERS num p := 1;\n  PROC main()\n    VAR num n;\n    IF n > 0 THEN\n      n := 1;\n    ELSE\n      n := 2;\n    ENDIF\n  ENDPROC\n  FUNC num twice(num x)\n    RETURN 2 * x;\n  ENDFUNC\nENDMODULE\n";

#[test]
fn document_symbols_are_hierarchical() {
    let (task, unit, _) = fixture(SRC);
    let syms = document_symbols(&task.units[unit]);
    let outline: Vec<String> = syms
        .iter()
        .flat_map(|m| {
            std::iter::once(format!("{:?} {}", m.kind, m.name)).chain(m.children.iter().flat_map(
                |c| {
                    std::iter::once(format!(
                        "  {:?} {} {:?}",
                        c.kind,
                        c.name,
                        c.detail.as_deref().unwrap_or("")
                    ))
                    .chain(
                        c.children
                            .iter()
                            .map(|g| format!("    {:?} {}", g.kind, g.name)),
                    )
                },
            ))
        })
        .collect();
    assert_eq!(
        outline,
        vec![
            "Module m",
            "  Record part \"RECORD\"",
            "    Component weight",
            "  Constant k \"CONST num\"",
            "  Persistent p \"PERS num\"",
            "  Procedure main \"PROC main()\"",
            "    Variable n",
            "  Function twice \"FUNC num twice(num x)\"",
        ]
    );
    let main = &syms[0].children[3];
    assert_eq!(&task.units[unit].text[main.selection_range.clone()], "main");
}

#[test]
fn workspace_symbols_match_fuzzily() {
    let (task, _, _) = fixture(SRC);
    let tasks = vec![std::sync::Arc::new(task)];
    let names = |q: &str| -> Vec<String> {
        workspace_symbols(&tasks, q)
            .into_iter()
            .map(|(_, s)| s.name)
            .collect()
    };
    assert_eq!(names("TWI"), vec!["twice"]);
    assert_eq!(names("tce"), vec!["twice"], "letters in order");
    assert!(names("").len() >= 6);
    assert_eq!(
        workspace_symbols(&tasks, "part")[0].1.kind,
        SymbolKind::Record
    );
}

#[test]
fn folding_covers_blocks_comments_and_the_header() {
    let (task, unit, _) = fixture(SRC);
    let folds: Vec<(usize, usize, Option<&str>)> = folding_ranges(&task.units[unit])
        .into_iter()
        .map(|f| (f.start_line, f.end_line, f.kind))
        .collect();
    assert_eq!(
        folds,
        vec![
            (0, 3, Some("region")),
            (4, 22, None),
            (5, 6, Some("comment")),
            (7, 8, None),
            (12, 18, None),
            (14, 17, None),
            (16, 17, None),
            (20, 21, None),
        ]
    );
}

#[test]
fn selection_expands_outwards() {
    let src = "MODULE m\n  PROC main()\n    VAR num n;\n    IF n > 0 THEN\n      n := n + 1$0;\n      n := 0;\n    ENDIF\n  ENDPROC\nENDMODULE\n";
    let (task, unit, offset) = fixture(src);
    let text = &task.units[unit].text;
    let ranges = selection_ranges(&task.units[unit], &[offset]);
    let shown: Vec<&str> = ranges[0]
        .iter()
        .map(|r| text[r.clone()].lines().next().unwrap_or(""))
        .collect();
    assert_eq!(&shown[..4], &["1", "n + 1", "n := n + 1;", "n := n + 1;"]);
    assert!(
        ranges[0]
            .windows(2)
            .all(|w| w[1].start <= w[0].start && w[0].end <= w[1].end && w[0] != w[1])
    );
    assert!(
        shown.contains(&"IF n > 0 THEN")
            && shown.contains(&"PROC main()")
            && shown.contains(&"MODULE m")
    );
}

#[test]
fn a_deep_selection_chain_keeps_its_innermost_and_outermost_ranges() {
    // 100 parentheses: about 200 ranges around the literal, under the
    // nesting limit.
    let src = format!(
        "MODULE m\n  PROC main()\n    VAR num n;\n    n := {}1$0{};\n  ENDPROC\nENDMODULE\n",
        "(".repeat(100),
        ")".repeat(100)
    );
    let (task, unit, offset) = fixture(&src);
    assert!(task.units[unit].syntax.is_empty());
    let text = &task.units[unit].text;
    let ranges = &selection_ranges(&task.units[unit], &[offset])[0];
    assert_eq!(ranges.len(), crate::ide::structure::MAX_SELECTION_CHAIN);
    assert_eq!(&text[ranges[0].clone()], "1");
    assert_eq!(&text[ranges[1].clone()], "(1)");
    assert_eq!(ranges.last(), Some(&(0..text.len())));
    assert!(
        ranges
            .windows(2)
            .all(|w| w[1].start <= w[0].start && w[0].end <= w[1].end && w[0] != w[1])
    );
}
