//! `rapid diff` compares meaning, not layout: a module re-indented, with
//! its blanks and line breaks between tokens changed, its keywords and
//! names in another letter case, its data declarations (of the module and
//! of a routine) in another order and its line endings converted compares
//! equal to the original. A property test over random such rewrites of a
//! program written for it, and a check that a real change is still seen.

use proptest::prelude::*;
use rapid_analyzer::diff::{Options, Snapshot, compare, snapshot};
use rapid_analyzer::workspace::Workspace;

/// The program, one line per entry, tokens one blank apart (a string is one
/// token: no blank inside). `=` marks a line that belongs to a group of
/// declarations whose order may change; a line starting with `!` is a
/// comment, kept whole.
const PROGRAM: &[&str] = &[
    "MODULE Cell",
    "= CONST robtarget pHome := [ [ 500 , 0 , 600 ] , [ 0 , 0 , 1 , 0 ] , [ 0 , 0 , 0 , 0 ] , [ 9E9 , 9E9 , 9E9 , 9E9 , 9E9 , 9E9 ] ] ;",
    "= PERS robtarget pPick := [ [ 100.5 , -20 , 30 ] , [ 0.707107 , 0 , 0.707107 , 0 ] , [ -1 , 0 , -1 , 1 ] , [ 9E9 , 9E9 , 9E9 , 9E9 , 9E9 , 9E9 ] ] ;",
    "= PERS num nCount := 12 ;",
    "= VAR speeddata vSlow := [ 100 , 50 , 5000 , 1000 ] ;",
    "= CONST num nMax{3} := [ 1 , 2 , 3 ] ;",
    "= PERS string sName := \"Cell_1\" ;",
    "= LOCAL VAR bool bDone := FALSE ;",
    "! a comment that stays as it is",
    "PROC main ( )",
    "= VAR num i ;",
    "= VAR num k := 2 ;",
    "= VAR robtarget pTmp ;",
    "MoveJ pHome , v1000 , z50 , tool0 ;",
    "FOR i FROM 1 TO nMax{3} DO",
    "IF nCount > 10 AND NOT bDone THEN",
    "MoveL Offs ( pPick , 0 , 0 , 100 ) , vSlow , z10 , tool0 \\WObj:=wobj0 ;",
    "ELSEIF nCount = 0 THEN",
    "nCount := nCount + k * 2 ;",
    "ELSE",
    "bDone := TRUE ;",
    "ENDIF",
    "ENDFOR",
    "TEST nCount",
    "CASE 1 , 2 :",
    "TPWrite \"one_or_two\" ;",
    "DEFAULT :",
    "WHILE nCount > 0 DO",
    "Decr nCount ;",
    "ENDWHILE",
    "ENDTEST",
    "ERROR",
    "RETRY ;",
    "ENDPROC",
    "FUNC num twice ( num x )",
    "RETURN x * 2 ;",
    "ENDFUNC",
    "ENDMODULE",
];

const KEYWORDS: &[&str] = &[
    "MODULE",
    "ENDMODULE",
    "CONST",
    "PERS",
    "VAR",
    "LOCAL",
    "PROC",
    "ENDPROC",
    "FUNC",
    "ENDFUNC",
    "FOR",
    "FROM",
    "TO",
    "DO",
    "ENDFOR",
    "IF",
    "THEN",
    "ELSEIF",
    "ELSE",
    "ENDIF",
    "AND",
    "NOT",
    "TEST",
    "CASE",
    "DEFAULT",
    "ENDTEST",
    "WHILE",
    "ENDWHILE",
    "ERROR",
    "RETRY",
    "RETURN",
    "TRUE",
    "FALSE",
];

/// How to write the program: seeds for each choice.
#[derive(Clone, Debug)]
struct Rewrite {
    /// Line ending: 0 LF, 1 CRLF, 2 CR.
    ending: u8,
    /// Per line: indentation (spaces, or tabs when odd).
    indents: Vec<u8>,
    /// Per token: blanks before it (0 where two words would join), a line
    /// break (4), or another letter case (bit 3).
    gaps: Vec<u8>,
    /// A permutation seed for each group of declarations.
    orders: Vec<u64>,
}

fn is_word(t: &str) -> bool {
    t.chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '"' || c == '\\')
}

/// Letter case changed: lower, upper or alternating (names and keywords
/// only; strings and numbers stay).
fn recase(t: &str, how: u8) -> String {
    if t.starts_with('"') || t.starts_with(|c: char| c.is_ascii_digit()) || t.contains('"') {
        return t.to_owned();
    }
    match how % 3 {
        0 => t.to_ascii_lowercase(),
        1 => t.to_ascii_uppercase(),
        _ => t
            .chars()
            .enumerate()
            .map(|(i, c)| {
                if i % 2 == 0 {
                    c.to_ascii_uppercase()
                } else {
                    c.to_ascii_lowercase()
                }
            })
            .collect(),
    }
}

/// A seeded shuffle (Fisher-Yates with a small LCG).
fn shuffle(group: &mut [&str], seed: u64) {
    let mut s = seed | 1;
    for i in (1..group.len()).rev() {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        group.swap(i, (s >> 33) as usize % (i + 1));
    }
}

fn write(rw: &Rewrite) -> String {
    // Reorder each run of `=` lines.
    let mut lines: Vec<&str> = Vec::new();
    let mut group: Vec<&str> = Vec::new();
    let mut groups = 0;
    for l in PROGRAM.iter().copied() {
        match l.strip_prefix("= ") {
            Some(decl) => group.push(decl),
            None => {
                if !group.is_empty() {
                    shuffle(&mut group, rw.orders.get(groups).copied().unwrap_or(0));
                    groups += 1;
                    lines.append(&mut group);
                }
                lines.push(l);
            }
        }
    }
    let eol = ["\n", "\r\n", "\r"][usize::from(rw.ending % 3)];
    let mut out = String::new();
    let mut k = 0;
    for (i, line) in lines.iter().enumerate() {
        let indent = rw.indents.get(i).copied().unwrap_or(0);
        if indent % 2 == 1 {
            out.push_str(&"\t".repeat(usize::from(indent % 4)));
        } else {
            out.push_str(&" ".repeat(usize::from(indent)));
        }
        if line.starts_with('!') {
            out.push_str(line);
            out.push_str(eol);
            continue;
        }
        let mut prev: Option<&str> = None;
        for tok in line.split(' ') {
            let g = rw.gaps.get(k).copied().unwrap_or(1);
            k += 1;
            if let Some(p) = prev {
                let blanks = usize::from(g % 4);
                // `\WObj:=` and `{3}` stay glued to what they follow.
                let glued = tok.starts_with('{') || p.ends_with(":=");
                if glued {
                } else if g % 8 == 4 {
                    out.push_str(eol);
                    out.push_str("    ");
                } else if blanks == 0 && is_word(p) && is_word(tok) {
                    out.push(' ');
                } else {
                    out.push_str(&" ".repeat(blanks));
                }
            }
            let is_keyword = KEYWORDS.contains(&tok);
            let is_name = tok.starts_with(|c: char| c.is_ascii_alphabetic());
            if (is_keyword || is_name) && g & 8 != 0 {
                out.push_str(&recase(tok, g >> 4));
            } else {
                out.push_str(tok);
            }
            prev = Some(tok);
        }
        out.push_str(eol);
    }
    out
}

fn snap(text: &str) -> Snapshot {
    let mut ws = Workspace::new();
    ws.set_file("t/Cell.mod", text.to_owned());
    Snapshot {
        tasks: snapshot::tasks_of(&mut ws, &|_| "T".to_owned(), &|p| p.to_owned()),
        ..Snapshot::default()
    }
}

fn plain() -> Rewrite {
    Rewrite {
        ending: 0,
        indents: Vec::new(),
        gaps: Vec::new(),
        orders: Vec::new(),
    }
}

fn rewrites() -> impl Strategy<Value = Rewrite> {
    (
        0u8..3,
        prop::collection::vec(0u8..9, PROGRAM.len()),
        prop::collection::vec(any::<u8>(), 400),
        prop::collection::vec(any::<u64>(), 2),
    )
        .prop_map(|(ending, indents, gaps, orders)| Rewrite {
            ending,
            indents,
            gaps,
            orders,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn rewritten_layout_compares_equal(rw in rewrites()) {
        let original = snap(&write(&plain()));
        let text = write(&rw);
        let rewritten = snap(&text);
        let report = compare(&original, &rewritten, &Options::default());
        prop_assert!(report.is_empty(), "{text}\n{report:#?}");
    }
}

#[test]
fn the_program_parses_and_a_real_change_is_seen() {
    let text = write(&plain());
    let mut ws = Workspace::new();
    ws.set_file("t/Cell.mod", text.clone());
    let syntax: Vec<_> = ws
        .unit("t/Cell.mod")
        .map(|u| u.syntax.clone())
        .unwrap_or_default();
    assert!(syntax.is_empty(), "{syntax:#?}");
    let changed = text.replace("nCount + k * 2", "nCount + k * 3");
    let report = compare(&snap(&text), &snap(&changed), &Options::default());
    assert_eq!(report.summary().routines, 1);
    let moved = text.replace("100.5 ", "101.5 ");
    let report = compare(&snap(&text), &snap(&moved), &Options::default());
    assert_eq!(report.summary().moves, 1);
}
