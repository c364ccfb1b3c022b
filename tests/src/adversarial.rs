//! A bounded generator of deep and adversarial RAPID inputs, shared by the
//! adversarial suite (`tests/adversarial.rs`), the server's survival and
//! oracle tests and the fuzz targets' seed corpus.
//!
//! Everything is generated from a seed with a small deterministic generator
//! (no corpus text): deep nesting of every kind, long chains of constants,
//! aliases and records, cycles, many duplicates, non-ASCII names and text,
//! and random damage (bytes cut, repeated, swapped, inserted) to all of it.

/// A named input.
pub struct Input {
    pub name: String,
    pub text: String,
}

/// xorshift64*: deterministic, fast, good enough to pick mutations.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A number below `n` (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next_u64() % n as u64) as usize
        }
    }
}

fn module(decls: &str, body: &str) -> String {
    format!("MODULE Deep\n{decls}  PROC main()\n{body}\n  ENDPROC\nENDMODULE\n")
}

/// Inputs nested `depth` levels deep, one per kind of nesting.
pub fn deep(depth: usize) -> Vec<Input> {
    let d = depth;
    let var = "  VAR num x;\n  VAR bool b;\n  VAR num a{10};\n";
    let nest = |open: &str, inner: &str, close: &str| {
        format!("{}{inner}{}", open.repeat(d), close.repeat(d))
    };
    let cases: Vec<(&str, String)> = vec![
        (
            "calls",
            module(var, &format!("    x := {};", nest("Abs(", "1", ")"))),
        ),
        (
            "sum",
            module(var, &format!("    x := {}1;", "1+".repeat(d))),
        ),
        (
            "product",
            module(var, &format!("    x := 2{};", "*2".repeat(d))),
        ),
        (
            "parens",
            module(var, &format!("    x := {};", nest("(", "1", ")"))),
        ),
        (
            "signs",
            module(var, &format!("    x := {}1;", "-".repeat(d))),
        ),
        (
            "not",
            module(var, &format!("    b := {}TRUE;", "NOT ".repeat(d))),
        ),
        (
            "indexes",
            module(var, &format!("    x := {};", nest("a{", "1", "}"))),
        ),
        (
            "aggregates",
            module(var, &format!("    x := {};", nest("[", "1", "]"))),
        ),
        (
            "components",
            module(var, &format!("    x := a{}.c;", ".c".repeat(d))),
        ),
        (
            "ifs",
            module(var, &nest("IF b THEN\n", "x := 1;\n", "ENDIF\n")),
        ),
        (
            "compact-ifs",
            module(var, &format!("    {}x := 1;", "IF b ".repeat(d))),
        ),
        (
            "whiles",
            module(var, &nest("WHILE b DO\n", "x := 1;\n", "ENDWHILE\n")),
        ),
        (
            "fors",
            module(
                var,
                &nest("FOR i FROM 1 TO 2 DO\n", "x := i;\n", "ENDFOR\n"),
            ),
        ),
        (
            "tests",
            module(var, &nest("TEST x\nCASE 1:\n", "x := 1;\n", "ENDTEST\n")),
        ),
        (
            "const-sum",
            format!(
                "MODULE Deep\n  CONST num c := {}1;\nENDMODULE\n",
                "1+".repeat(d)
            ),
        ),
        (
            "const-aggregate",
            format!(
                "MODULE Deep\n  CONST num c{{2}} := {};\nENDMODULE\n",
                nest("[", "1", ",1]")
            ),
        ),
        (
            "routine-call-args",
            module(
                var,
                &format!(
                    "    MoveL {}, v100, z10, tool0;",
                    nest("Offs(", "p", ",0,0,0)")
                ),
            ),
        ),
        // Unclosed: the parser recovers around errors at every level.
        (
            "unclosed-parens",
            module(var, &format!("    x := {}1;", "(".repeat(d))),
        ),
        ("unclosed-ifs", module(var, &"IF b THEN\n".repeat(d))),
        (
            "stray-closers",
            module(var, &format!("    x := 1{};", ")]}".repeat(d))),
        ),
    ];
    cases
        .into_iter()
        .map(|(name, text)| Input {
            name: format!("deep-{name}-{depth}"),
            text,
        })
        .collect()
}

/// Long chains and cycles of names, many duplicates, odd text.
pub fn chains(n: usize) -> Vec<Input> {
    let mut consts = String::from("MODULE Chain\n  CONST num c0 := 1;\n");
    let mut aliases = String::from("MODULE Alias\n  ALIAS num t0;\n");
    let mut records = String::from("MODULE Rec\n  RECORD r0\n    num v;\n  ENDRECORD\n");
    for i in 1..n {
        consts.push_str(&format!("  CONST num c{i} := c{} + 1;\n", i - 1));
        aliases.push_str(&format!("  ALIAS t{} t{i};\n", i - 1));
        records.push_str(&format!("  RECORD r{i}\n    r{} v;\n  ENDRECORD\n", i - 1));
    }
    let last = n - 1;
    consts.push_str(&format!(
        "  PROC main()\n    TPWrite \"\" \\Num:=c{last};\n  ENDPROC\nENDMODULE\n"
    ));
    aliases.push_str(&format!("  VAR t{last} x := 1;\nENDMODULE\n"));
    records.push_str(&format!(
        "  VAR r{last} x;\n  PROC main()\n    x{} := 1;\n  ENDPROC\nENDMODULE\n",
        ".v".repeat(n)
    ));
    let cycle = "MODULE Cycle\n  CONST num a := b + 1;\n  CONST num b := a + 1;\n  ALIAS t2 t1;\n  ALIAS t1 t2;\n  RECORD r1\n    r2 v;\n  ENDRECORD\n  RECORD r2\n    r1 v;\n  ENDRECORD\n  VAR r1 x;\n  VAR t1 y;\n  PROC main()\n    x.v.v.v := a;\n  ENDPROC\nENDMODULE\n".to_owned();
    let duplicates = format!("MODULE Dup\n{}\nENDMODULE\n", "VAR num a;".repeat(n));
    let labels = format!(
        "MODULE Lab\n  PROC main()\n{}  ENDPROC\nENDMODULE\n",
        "  l:\n    GOTO l;\n".repeat(n)
    );
    let odd = "\u{feff}MODULE Ödd\n  VAR string s := \"é\u{feff}机器人\";\n  PROC main()\n    s := s\u{feff}+ \"\\\\\";\n    TPWrite s;\r\n  ENDPROC\rENDMODULE\0tail";
    vec![
        Input {
            name: format!("const-chain-{n}"),
            text: consts,
        },
        Input {
            name: format!("alias-chain-{n}"),
            text: aliases,
        },
        Input {
            name: format!("record-chain-{n}"),
            text: records,
        },
        Input {
            name: "cycles".to_owned(),
            text: cycle,
        },
        Input {
            name: format!("duplicates-{n}"),
            text: duplicates,
        },
        Input {
            name: format!("labels-{n}"),
            text: labels,
        },
        Input {
            name: "odd-text".to_owned(),
            text: odd.to_owned(),
        },
    ]
}

/// `text` with a few random pieces of damage.
pub fn mutate(text: &str, rng: &mut Rng) -> String {
    let mut bytes = text.as_bytes().to_vec();
    const TOKENS: &[&str] = &[
        "(",
        ")",
        "[",
        "]",
        "{",
        "}",
        ";",
        ":=",
        "IF ",
        "ENDIF",
        "PROC ",
        "ENDPROC",
        "MODULE ",
        "ENDMODULE",
        "\"",
        "!",
        "\\",
        "<EXP>",
        "é",
        "\u{feff}",
        "\r",
        "\n",
        "%",
        "GOTO ",
        "\0",
    ];
    for _ in 0..1 + rng.below(4) {
        let at = rng.below(bytes.len() + 1);
        match rng.below(5) {
            0 => {
                let end = (at + rng.below(64)).min(bytes.len());
                bytes.drain(at..end);
            }
            1 => {
                let end = (at + rng.below(64)).min(bytes.len());
                let piece = bytes[at..end].to_vec();
                for _ in 0..1 + rng.below(8) {
                    bytes.splice(at..at, piece.iter().copied());
                }
            }
            2 => {
                let token = TOKENS[rng.below(TOKENS.len())];
                bytes.splice(at..at, token.bytes());
            }
            3 => {
                let other = rng.below(bytes.len() + 1);
                let (a, b) = (at.min(other), at.max(other));
                if b < bytes.len() {
                    bytes.swap(a, b);
                }
            }
            _ => {
                if let Some(b) = bytes.get_mut(at) {
                    *b = (rng.next_u64() & 0xFF) as u8;
                }
            }
        }
    }
    String::from_utf8_lossy(&bytes).into_owned()
}
