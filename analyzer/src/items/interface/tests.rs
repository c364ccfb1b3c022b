use super::*;
use crate::task::Unit;

const BASE: &str = "MODULE Cell(SYSMODULE)
  VAR num count := 1;
  LOCAL PERS num list{3} := [1, 2, 3];
  CONST num limit := 10;
  RECORD pair
    num a;
    bool b;
  ENDRECORD
  ALIAS num length;
  PROC move(VAR num x, \\switch fast | num slow)
    x := x + 1;
  ENDPROC
  FUNC num twice(num x{*})
    RETURN 2;
  ENDFUNC
ENDMODULE
";

fn unit(text: &str) -> Unit {
    Unit::new("t/Cell.sys".into(), text.to_owned(), None)
}

/// `BASE` with `from` replaced by `to` (which must be there once).
fn variant(from: &str, to: &str) -> String {
    assert_eq!(BASE.matches(from).count(), 1, "{from}");
    BASE.replacen(from, to, 1)
}

#[test]
fn moving_text_and_editing_bodies_keep_the_interface() {
    let base = unit(BASE);
    let same = [
        // Positions move.
        format!("\n\n! a comment\n{BASE}"),
        variant("  VAR num count", "\n  ! more\n  VAR   num count"),
        // Bodies and the values of variables are not seen.
        variant("x := x + 1;", "x := x + 2;\n    x := 3;"),
        variant("RETURN 2;", "RETURN 3;"),
        variant("count := 1", "count := 2"),
        // Names are folded.
        variant("PROC move", "PROC MOVE"),
        variant("VAR num count", "VAR NUM Count"),
    ];
    for text in &same {
        let u = unit(text);
        assert_eq!(u.items.interface(), base.items.interface(), "{text}");
        assert_eq!(u.interface, base.interface, "{text}");
        assert_eq!(u.constants, base.constants, "{text}");
    }
    // A constant's value and an array's size are constants, not interface.
    for text in [
        variant("limit := 10", "limit := 11"),
        variant("list{3} := [1, 2, 3]", "list{2} := [1, 2]"),
    ] {
        let u = unit(&text);
        assert_eq!(u.interface, base.interface, "{text}");
        assert_ne!(u.constants, base.constants, "{text}");
    }
}

#[test]
fn every_part_of_the_interface_changes_its_hash() {
    let changes = [
        ("MODULE Cell", "MODULE Cells"),
        ("(SYSMODULE)", "(SYSMODULE, NOVIEW)"),
        ("VAR num count", "VAR num counts"),
        ("VAR num count", "LOCAL VAR num count"),
        ("VAR num count", "PERS num count"),
        ("VAR num count", "VAR bool count"),
        ("list{3}", "list{3, 3}"),
        ("RECORD pair", "RECORD pairs"),
        ("RECORD pair", "LOCAL RECORD pair"),
        ("num a;", "num c;"),
        ("bool b;", "num b;"),
        ("bool b;", "bool b;\n    num c;"),
        ("ALIAS num length", "ALIAS bool length"),
        ("ALIAS num length", "ALIAS num size"),
        ("ALIAS num length", "LOCAL ALIAS num length"),
        ("PROC move", "PROC moves"),
        ("PROC move", "LOCAL PROC move"),
        ("VAR num x", "INOUT num x"),
        ("VAR num x", "VAR bool x"),
        ("VAR num x", "VAR num y"),
        ("VAR num x, \\switch fast", "VAR num x, \\num fast"),
        (
            "\\switch fast | num slow",
            "\\switch fast | num slow | num slower",
        ),
        ("\\switch fast | num slow", "\\switch fast, \\num slow"),
        ("FUNC num twice", "FUNC bool twice"),
        ("num x{*}", "num x{*, *}"),
        ("num x{*})", "num x{*}, num y)"),
        ("  FUNC num twice(num x{*})\n    RETURN 2;\n  ENDFUNC\n", ""),
    ];
    let base = unit(BASE);
    let mut seen = vec![(BASE.to_owned(), base.interface)];
    for (from, to) in changes {
        let text = variant(from, to);
        let u = unit(&text);
        assert!(u.syntax.is_empty(), "{text}: {:?}", u.syntax);
        assert_ne!(u.items.interface(), base.items.interface(), "{text}");
        assert_eq!(u.interface, hash_of(&u.items.interface()));
        for (other, hash) in &seen {
            assert_ne!(u.interface, *hash, "{text}\nhas the hash of\n{other}");
        }
        seen.push((text, u.interface));
    }
}
