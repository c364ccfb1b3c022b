//! The blanks between two tokens on one line, in the styles that set them
//! (`tight` and `spaced`; `as-written` keeps the author's).

use super::Style;
use super::collect::{Class, Tok};

/// Is there a space between two tokens on one line?
pub(super) fn spaced(prev: &Tok<'_>, next: &Tok<'_>, style: Style) -> bool {
    use Class::*;
    // `|` between the alternatives of an optional parameter
    if prev.text == "|" || next.text == "|" {
        return true;
    }
    if matches!(
        next.class,
        Comma | Semicolon | Colon | Dot | Close | PercentClose | Question | AssignTight
    ) {
        return false;
    }
    if matches!(
        prev.class,
        Dot | Open
            | PercentOpen
            | Unary
            | Question
            | AssignTight
            | Colon
            | BackslashArgument
            | BackslashParameter
    ) {
        return false;
    }
    if style == Style::Tight {
        return tight(prev, next);
    }
    match next.class {
        BackslashArgument => prev.class == Comma || prev.proc_name,
        Open => prev.proc_name || !matches!(prev.class, Word | Close),
        _ => true,
    }
}

/// RobotStudio's form: `reg1:=reg1+1;`, `MoveL p10,v1000,z50,tool0\WObj:=wobj0;`,
/// `StopMove\Quick;`. Keywords stand apart (`IF a=b THEN`, `NOT (a)`)
/// except after a comma, `:=` or an operator (`(num a,INOUT num b)`,
/// `ok:=NOT done`), as do two words and a procedure name from its first
/// argument.
fn tight(prev: &Tok<'_>, next: &Tok<'_>) -> bool {
    use Class::*;
    if prev.proc_name || prev.class == PercentClose {
        return next.class != BackslashArgument;
    }
    let boolean = |t: &Tok<'_>| {
        t.class == Keyword
            && (t.text.eq_ignore_ascii_case("TRUE") || t.text.eq_ignore_ascii_case("FALSE"))
    };
    let keyword = |t: &Tok<'_>| t.class == Keyword && !boolean(t);
    let word = |t: &Tok<'_>| t.class == Word || boolean(t);
    keyword(prev)
        || keyword(next) && !matches!(prev.class, Comma | AssignWide | Operator)
        || (word(prev) || prev.class == Close) && word(next)
}

/// Can two tokens touch without becoming one token (or a different one)?
/// A safety net under [`spaced`]: names and numbers never touch, nor do
/// characters that would form `:=`, `<>`, `<=`, `>=`, `%%%`, a comment, a
/// longer number (a number and a `.` after it), or two signs in a row.
pub(super) fn joinable(a: &Tok<'_>, b: &Tok<'_>) -> bool {
    let (Some(x), Some(y)) = (a.text.chars().next_back(), b.text.chars().next()) else {
        return true;
    };
    let word = |c: char| c.is_alphanumeric() || c == '_';
    !(word(x) && word(y)
        || y == '!'
        || (a.number && y == '.')
        || matches!(
            (x, y),
            ('<', '>' | '=')
                | ('>', '=')
                | (':', '=')
                | ('%', '%')
                | ('"', '"')
                | ('.', '0'..='9')
                | ('\\', '\\')
                | ('+' | '-', '+' | '-')
        ))
}
