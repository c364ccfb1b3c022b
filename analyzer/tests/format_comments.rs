//! A property of the formatter: comments on their own lines, at any
//! column, in any place of a routine (the first, only or last line of a
//! body; before `ENDPROC`, `ELSE`, `CASE`, `DEFAULT`, `ENDIF`), in a
//! module whose lines are indented at random, format to a fixed point:
//! formatting the result again changes nothing, in every style, with
//! the file's own indentation or a configured width.

use proptest::prelude::*;
use rapid_analyzer::format::{FormatOptions, Style, format};

/// A line of the generated module: its text and whether it is one of the
/// optional comments.
#[derive(Clone, Copy)]
enum Line {
    Code(&'static str),
    /// Present when its switch is on.
    Comment(usize),
}

/// The skeleton: every place a comment may go, numbered.
const SKELETON: &[Line] = &[
    Line::Code("MODULE m"),
    Line::Comment(0),
    Line::Code("VAR num x;"),
    Line::Code("PROC main()"),
    Line::Comment(1), // the first line of the body (or the only one)
    Line::Comment(2),
    Line::Code("<first>"),
    Line::Code("IF x > 0 THEN"),
    Line::Comment(3), // the only line of a block
    Line::Code("<then>"),
    Line::Comment(4), // the last line of a block, before ELSE
    Line::Comment(5),
    Line::Code("ELSE"),
    Line::Comment(6),
    Line::Code("ENDIF"),
    Line::Code("WHILE x < 3 DO"),
    Line::Comment(7),
    Line::Code("ENDWHILE"),
    Line::Code("TEST x"),
    Line::Comment(8), // before CASE
    Line::Code("CASE 1:"),
    Line::Code("<case>"),
    Line::Comment(9), // before DEFAULT
    Line::Code("DEFAULT:"),
    Line::Comment(10),
    Line::Code("ENDTEST"),
    Line::Comment(11), // the last line of the body, before ENDPROC
    Line::Comment(12),
    Line::Code("ERROR"),
    Line::Comment(13),
    Line::Code("ENDPROC"),
    Line::Comment(14),
    Line::Code("PROC other()"),
    Line::Comment(15),
    Line::Code("ENDPROC"),
    Line::Comment(16),
    Line::Code("ENDMODULE"),
];

const COMMENTS: usize = 17;

/// Indentations a line may have: none, spaces, tabs, RobotStudio's tab and
/// four spaces.
const INDENTS: &[&str] = &[
    "",
    "",
    " ",
    "  ",
    "    ",
    "      ",
    "        ",
    "            ",
    "\t",
    "\t\t",
    "\t    ",
];

fn module(comments: &[bool], statements: &[bool], indents: &[usize]) -> String {
    let mut out = String::new();
    for (i, line) in SKELETON.iter().enumerate() {
        let text = match *line {
            Line::Code("<first>") if statements[0] => "x := 1;",
            Line::Code("<then>") if statements[1] => "x := 2;",
            Line::Code("<case>") if statements[2] => "x := 3;",
            Line::Code(t) if t.starts_with('<') => continue,
            Line::Code(t) => t,
            Line::Comment(k) if comments[k] => "!SMT",
            Line::Comment(_) => continue,
        };
        out.push_str(INDENTS[indents[i] % INDENTS.len()]);
        out.push_str(text);
        out.push('\n');
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn comments_format_to_a_fixed_point(
        comments in proptest::collection::vec(any::<bool>(), COMMENTS),
        statements in proptest::collection::vec(any::<bool>(), 3),
        indents in proptest::collection::vec(0..INDENTS.len(), SKELETON.len()),
        style in prop_oneof![Just(Style::AsWritten), Just(Style::Tight), Just(Style::Spaced)],
        indent_width in prop_oneof![Just(None), Just(Some(2)), Just(Some(4))],
    ) {
        let input = module(&comments, &statements, &indents);
        let options = FormatOptions { style, indent_width, ..FormatOptions::default() };
        let once = format(&input, &options).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let twice = format(&once, &options).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(&twice, &once, "input:\n{}", input);
    }
}

/// The case of the issue that found it: a routine whose body is only a
/// comment at column 0, in a module indented by two.
#[test]
fn a_body_of_one_comment_at_column_zero_is_stable() {
    let input =
        "MODULE m\n  PROC a()\n    x:=1;\n  ENDPROC\n  PROC main()\n!SMT\nENDPROC\nENDMODULE\n";
    let options = FormatOptions::default();
    let once = format(input, &options).expect("formats");
    assert_eq!(format(&once, &options).expect("formats"), once);
}
