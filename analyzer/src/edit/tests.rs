use super::*;

fn unit(text: &str) -> Unit {
    Unit::new("t/A.mod".into(), text.to_owned(), None)
}

/// The edited unit is the unit of the edited text, parsed afresh.
fn assert_same(edited: &Unit, context: &str) {
    let fresh = unit(&edited.text);
    assert_eq!(
        edited.tree().root_node().to_sexp(),
        fresh.tree().root_node().to_sexp(),
        "{context}: {:?}",
        edited.text
    );
    // The same findings at the same places. Their messages may differ: a
    // syntax error's "expected ..." comes from the parse state of its
    // error node, and a node the incremental parse reused keeps the state
    // of the old parse (in about one batch of the random ones in ten).
    let found = |u: &Unit| -> Vec<(&str, Range<usize>)> {
        u.syntax
            .iter()
            .map(|d| (d.rule.code, d.range.clone()))
            .collect()
    };
    assert_eq!(found(edited), found(&fresh), "{context}: {:?}", edited.text);
    assert_eq!(edited.items, fresh.items, "{context}: {:?}", edited.text);
    assert_eq!(edited.interface, fresh.interface, "{context}");
    assert_eq!(edited.constants, fresh.constants, "{context}");
}

fn check(before: &str, edits: &[TextEdit], after: &str) {
    let edited = unit(before).edited(edits);
    assert_eq!(edited.text, after);
    assert_same(&edited, "edit");
    assert_eq!(edited.syntax, unit(after).syntax);
}

#[test]
fn edits_apply_in_order_and_reparse_incrementally() {
    let text = "MODULE M\r\n  PROC p()\r\n    x := 1;\r\n  ENDPROC\r\nENDMODULE\r\n";
    // `1` then `x`: the second range is in the text after the first edit.
    check(
        text,
        &[TextEdit::new(31..32, "42"), TextEdit::new(26..27, "y")],
        "MODULE M\r\n  PROC p()\r\n    y := 42;\r\n  ENDPROC\r\nENDMODULE\r\n",
    );
    // Inserting a line, then deleting across lines.
    check(
        text,
        &[
            TextEdit::new(20..20, "\r\n    ! Größe 𝄞"),
            TextEdit::new(22..42, ""),
        ],
        text,
    );
    // A syntax error comes and goes.
    let text = "MODULE M\n  PROC p()\n  ENDPROC\nENDMODULE\n";
    let broken = unit(text).edited(&[TextEdit::new(11..15, "PRO")]);
    assert_eq!(broken.text, "MODULE M\n  PRO p()\n  ENDPROC\nENDMODULE\n");
    assert!(!broken.syntax.is_empty());
    assert_same(&broken, "broken");
    let mended = broken.edited(&[TextEdit::new(11..14, "PROC")]);
    assert!(mended.syntax.is_empty(), "{:?}", mended.syntax);
    assert_same(&mended, "mended");
}

#[test]
fn replacing_the_whole_text_parses_it_afresh() {
    check(
        "MODULE M\nENDMODULE\n",
        &[
            TextEdit::new(0..19, "MODULE N\nENDMODULE\n"),
            TextEdit::new(7..8, "Q"),
        ],
        "MODULE Q\nENDMODULE\n",
    );
}

#[test]
fn ranges_outside_the_text_or_inside_a_character_are_cut_to_it() {
    // Past the end: an insertion at the end.
    check(
        "MODULE M\nENDMODULE\n",
        &[TextEdit::new(40..50, "\n")],
        "MODULE M\nENDMODULE\n\n",
    );
    // Reversed: empty at its end.
    check(
        "MODULE M\nENDMODULE\n",
        &[TextEdit::new(Range { start: 8, end: 7 }, "N")],
        "MODULE NM\nENDMODULE\n",
    );
    // Inside `é` (bytes 10..12): the whole character.
    check(
        "MODULE M\n!é\nENDMODULE\n",
        &[TextEdit::new(11..11, "e")],
        "MODULE M\n!e\nENDMODULE\n",
    );
}

#[test]
fn points_count_rows_at_line_feeds() {
    assert_eq!(point_at("ab\r\ncd", 5), Point { row: 1, column: 1 });
    assert_eq!(point_at("ab\rcd", 4), Point { row: 0, column: 4 });
    assert_eq!(point_at("ab", 9), Point { row: 0, column: 2 });
}

/// A module with most of what a body holds, to edit at random.
const FIXTURE: &str = "MODULE Cell(SYSMODULE)
  ! Größe: a comment with 𝄞
  CONST num count := 3;
  PERS robtarget home := [[1,2,3],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num list{3} := [1, 2, 3];
  RECORD pair
    num a;
    num b;
  ENDRECORD

  PROC main()
    VAR num i;
    FOR i FROM 1 TO count DO
      IF list{i} > 1 THEN
        TPWrite \"item \" + NumToStr(list{i}, 0);
      ELSEIF i = 2 THEN
        GOTO done;
      ELSE
        list{i} := list{i} * 2;
      ENDIF
    ENDFOR
    done:
    WHILE TRUE DO
      MoveL home, v100, z10, tool0;
    ENDWHILE
  ERROR
    RETRY;
  ENDPROC

  FUNC num twice(num x, \\switch fast)
    RETURN x * 2;
  ENDFUNC

  TRAP stop
    TEST count
    CASE 1, 2:
      Stop;
    DEFAULT:
      EXIT;
    ENDTEST
  ENDTRAP
ENDMODULE
";

/// What the random edits insert: tokens, broken pieces, line breaks.
const PIECES: &[&str] = &[
    "",
    "x",
    " ",
    ";",
    "\n",
    "\r\n",
    "\r",
    ":= 1;",
    "IF",
    "ENDIF",
    "PROC q()\n  ENDPROC\n",
    "ENDPROC",
    "ENDMODULE",
    "\"",
    "!",
    "{",
    "}",
    "(",
    "é",
    "𝄞",
    "<SMT>",
    "VAR num n;",
    "TPWrite \"a\";\n",
    "ENDMODULE\ntrailing text\n",
];

/// xorshift64*: a deterministic sequence, no dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        usize::try_from(self.next() % n.max(1) as u64).unwrap_or(0)
    }
}

/// A random range of `text` on character boundaries, mostly short.
fn random_range(rng: &mut Rng, text: &str) -> Range<usize> {
    let start = floor_boundary(text, rng.below(text.len() + 1));
    let len = match rng.below(4) {
        0 => 0,
        1 | 2 => rng.below(8),
        _ => rng.below(80),
    };
    start..ceil_boundary(text, (start + len).min(text.len()))
}

/// Oracle: over a chain of random batches of edits, each incrementally
/// re-parsed unit equals a fresh parse of its text.
#[test]
fn random_edits_reparse_as_a_fresh_parse_does() {
    let mut rng = Rng(0x0005_EED0_FA11_0F17);
    let mut current = unit(FIXTURE);
    for step in 0..400 {
        let mut text = current.text.clone();
        let mut edits = Vec::new();
        for _ in 0..1 + rng.below(3) {
            let range = random_range(&mut rng, &text);
            let piece = PIECES[rng.below(PIECES.len())];
            text.replace_range(range.clone(), piece);
            edits.push(TextEdit::new(range, piece));
        }
        let edited = current.edited(&edits);
        assert_eq!(edited.text, text, "step {step}");
        assert_same(&edited, &format!("step {step}, {edits:?}"));
        // Start again from the fixture now and then, and before the text
        // grows or shrinks too far from a module.
        current = if step % 50 == 49 || !(200..4000).contains(&text.len()) {
            unit(FIXTURE)
        } else {
            edited
        };
    }
}
