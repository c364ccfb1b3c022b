//! Every feature at every offset of broken, odd or half-written code:
//! nothing panics.

use super::fixture;
use crate::ide;

const SOURCES: &[&str] = &[
    "",
    "MODULE",
    "MODULE m\n  PROC",
    "MODULE m\n  PROC p(\\num a | num b, VAR num c{*}\n    MoveL \\Conc, p10, v1000 \\T:=\n  ENDPROC\n",
    "MODULE m\n  VAR num n = 3;\n  FUNC num f()\n    IF n = 1 THEN\n      RETURN n\n  ENDFUNC\nENDMODULE\n",
    "%%%\n  VERSION:1\n%%%\nMODULE m(SYSMODULE)\n  RECORD r\n    num a;\n  ENDRECORD\n  CONST r k := [1];\n  TRAP t\n    x.a.b{1,2}.c := [[1],[2,\"s!;\"]];\n  ENDTRAP\nENDMODULE\ntrailing text",
    "MODULE m\n  PROC main()\n    FOR i FROM 1 TO 10 DO\n      TEST i\n      CASE 1, 2:\n        GOTO l;\n      DEFAULT:\n      ENDTEST\n    ENDFOR\n  l:\n    %\"proc\" + \"x\"%;\n    <SMT>\n  ERROR\n    RETRY;\n  ENDPROC\nENDMODULE",
    "MODULE m\n  PROC main()\n    é := \"ü\"; ! ß\n    Set do1,\n",
];

#[test]
fn no_feature_panics_anywhere() {
    for src in SOURCES {
        let (task, unit, _) = fixture(src);
        let len = src.len();
        let tasks = vec![std::sync::Arc::new(fixture(src).0)];
        for offset in 0..=len + 2 {
            let _ = ide::hover(&task, unit, offset);
            let _ = ide::completions(&task, unit, offset);
            let _ = ide::signature_help(&task, unit, offset);
            let _ = ide::definition(&task, unit, offset);
            let _ = ide::type_definition(&task, unit, offset);
            let _ = ide::references(&task, unit, offset, true, &[]);
            let _ = ide::document_highlights(&task, unit, offset);
            let _ = ide::prepare_rename(&task, unit, offset);
            let _ = ide::rename(&task, unit, offset, "fresh", &[]);
            let _ = ide::inlay_hints(&task, unit, offset..len + 2, ide::ParameterHints::All);
            let _ = ide::semantic_tokens(&task, unit, Some(offset..len + 2));
        }
        let u = &task.units[unit];
        let _ = ide::document_symbols(u);
        let _ = ide::workspace_symbols(&tasks, "m");
        let _ = ide::folding_ranges(u);
        let offsets: Vec<usize> = (0..=len + 2).collect();
        let _ = ide::selection_ranges(u, &offsets);
        let diags = crate::workspace::diagnostics_of(&task, u);
        let mut all = u.syntax.clone();
        all.extend(diags.iter().cloned());
        let _ = ide::code_actions(&task, unit, 0..len + 2, &all);
        // Out of range units.
        assert!(ide::hover(&task, 99, 0).is_none());
        assert!(ide::completions(&task, 99, 0).is_empty());
    }
}
