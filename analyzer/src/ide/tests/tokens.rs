use super::fixture;
use crate::ide::{TOKEN_MODIFIERS, TOKEN_TYPES, semantic_tokens};

/// Each token as `text:type[+modifier...]`.
fn tokens(src: &str, range: Option<std::ops::Range<usize>>) -> Vec<String> {
    let (task, unit, _) = fixture(src);
    let text = &task.units[unit].text;
    semantic_tokens(&task, unit, range)
        .into_iter()
        .map(|t| {
            let mut s = format!(
                "{}:{}",
                &text[t.range.clone()],
                TOKEN_TYPES[t.token_type as usize]
            );
            for (i, m) in TOKEN_MODIFIERS.iter().enumerate() {
                if t.modifiers & (1 << i) != 0 {
                    s.push('+');
                    s.push_str(m);
                }
            }
            s
        })
        .collect()
}

const SRC: &str = "MODULE m\n  CONST num k := 2;\n  PERS tooldata tg := tool0.tframe;\n  PROC main(num x)\n    VAR num n;\n    n := k + x;\n    MoveL p, v100, fine, tg;\n    Grab;\n  again:\n    GOTO again;\n  ENDPROC\n  PROC Grab()\n    n2 := Abs(pi);\n  ENDPROC\nENDMODULE\n";

#[test]
fn names_are_classified_by_resolution() {
    let t = tokens(SRC, None);
    let has = |s: &str| assert!(t.iter().any(|x| x == s), "{s} not in {t:#?}");
    has("m:namespace+declaration");
    has("k:variable+declaration+readonly");
    has("tg:variable+declaration+static");
    has("tooldata:type+defaultLibrary");
    has("tool0:variable+defaultLibrary+static");
    has("tframe:property");
    has("main:method+declaration");
    has("x:parameter+declaration");
    has("x:parameter");
    has("k:variable+readonly");
    has("MoveL:method+defaultLibrary");
    has("Grab:method");
    has("v100:enumMember+readonly+defaultLibrary");
    has("tg:variable+static");
    has("again:label+declaration");
    has("again:label");
    has("Abs:function+defaultLibrary");
    has("pi:enumMember+readonly+defaultLibrary");
    has("PROC:keyword");
    has(":=:operator");
    has("2:number");
}

#[test]
fn tokens_are_sorted_and_a_range_restricts_them() {
    let (task, unit, _) = fixture(SRC);
    let all = semantic_tokens(&task, unit, None);
    assert!(all.windows(2).all(|w| w[0].range.end <= w[1].range.start));
    let line = SRC.find("    MoveL").unwrap_or(0);
    let some = tokens(SRC, Some(line..line + 28));
    assert_eq!(
        some.first().map(String::as_str),
        Some("MoveL:method+defaultLibrary")
    );
    assert_eq!(some.len(), 5, "{some:?}");
    assert_eq!(some.last().map(String::as_str), Some("tg:variable+static"));
}
