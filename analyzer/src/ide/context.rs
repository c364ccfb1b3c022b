//! The context of a cursor in text that may be half written: which call
//! and argument it is in, what precedes it on the statement. Read from the
//! text (comments and strings blanked), not the tree, so it works on code
//! the parser cannot make sense of yet.

/// How far back the scan looks.
const WINDOW: usize = 6000;

/// The text before `offset` with comments and string contents replaced by
/// spaces (so their `;`, `(` and `,` do not count), and where it starts.
/// Also says whether `offset` itself is inside a comment or a string.
pub(crate) struct Before {
    pub start: usize,
    pub text: Vec<u8>,
    pub in_comment: bool,
    pub in_string: bool,
}

pub(crate) fn before(text: &str, offset: usize) -> Before {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    // Start the window at a line start so comments and strings are seen whole.
    let mut start = offset.saturating_sub(WINDOW);
    while start > 0 && text.as_bytes().get(start - 1) != Some(&b'\n') {
        start -= 1;
    }
    let src = text.as_bytes().get(start..offset).unwrap_or_default();
    let mut out = Vec::with_capacity(src.len());
    let (mut in_comment, mut in_string) = (false, false);
    for &b in src {
        if b == b'\n' {
            in_comment = false;
            in_string = false;
            out.push(b);
            continue;
        }
        if in_comment {
            out.push(b' ');
        } else if in_string {
            if b == b'"' {
                in_string = false;
                out.push(b'"');
            } else {
                out.push(b' ');
            }
        } else if b == b'!' {
            in_comment = true;
            out.push(b' ');
        } else if b == b'"' {
            in_string = true;
            out.push(b'"');
        } else {
            out.push(b);
        }
    }
    Before {
        start,
        text: out,
        in_comment,
        in_string,
    }
}

/// Is byte `i` of `b` part of a name (a Latin-1 letter's two bytes count)?
fn is_ident(b: &[u8], i: usize) -> bool {
    crate::names::is_name_byte_at(b, i)
}

/// The length of the name characters at the start of `b`.
fn ident_len(b: &[u8]) -> usize {
    (0..b.len()).take_while(|&i| is_ident(b, i)).count()
}

/// The identifier being typed at the end of `text` (possibly empty).
pub(crate) fn partial(text: &[u8]) -> usize {
    let mut i = text.len();
    while i > 0 && is_ident(text, i - 1) {
        i -= 1;
    }
    text.len() - i
}

/// Keywords after which a new statement starts.
const STATEMENT_OPENERS: &[&str] = &[
    "then", "do", "else", "endif", "endfor", "endwhile", "endtest", "default", "error", "undo",
    "backward",
];

/// The start (index into `b`) of the statement the end of `b` is in: just
/// after the last `;`, statement-opening keyword, label or routine header
/// at bracket depth zero.
pub(crate) fn statement_start(b: &[u8]) -> usize {
    let mut depth: i32 = 0;
    let mut i = b.len();
    while i > 0 {
        let c = b[i - 1];
        match c {
            b')' | b']' | b'}' => depth += 1,
            b'(' | b'[' | b'{' => {
                if depth == 0 {
                    // An unclosed bracket: a routine header `PROC p(` is its own
                    // context; keep scanning for calls.
                }
                depth -= 1;
            }
            b';' if depth <= 0 => return i,
            b':' if depth <= 0 && b.get(i) != Some(&b'=') => {
                // A label `name:` (not `:=`).
                return i;
            }
            _ => {}
        }
        if depth <= 0 && is_ident(b, i - 1) && (i < 2 || !is_ident(b, i - 2)) {
            // The start of a word: is it a statement opener?
            let j = i - 1 + ident_len(&b[i - 1..]);
            let word = String::from_utf8_lossy(&b[i - 1..j]).to_ascii_lowercase();
            if STATEMENT_OPENERS.contains(&word.as_str()) {
                return j;
            }
            if word == "endproc" || word == "endfunc" || word == "endtrap" || word == "endrecord" {
                return j;
            }
        }
        // A routine or module header ends its line.
        if c == b'\n' && depth <= 0 && is_header_line(&b[..i - 1]) {
            return i;
        }
        i -= 1;
    }
    0
}

/// Does the last line of `b` open a module or a routine?
fn is_header_line(b: &[u8]) -> bool {
    let start = b.iter().rposition(|c| *c == b'\n').map_or(0, |i| i + 1);
    let w = words(&b[start..]);
    let first = match w.first().map(String::as_str) {
        Some("local") => w.get(1),
        _ => w.first(),
    };
    first.is_some_and(|f| ["proc", "func", "trap", "module"].contains(&f.as_str()))
}

/// The words of a statement prefix (identifiers and keywords), lowercase.
pub(crate) fn words(b: &[u8]) -> Vec<String> {
    let mut out = Vec::new();
    let mut start = None;
    for i in 0..=b.len() {
        match (start, is_ident(b, i)) {
            (None, true) => start = Some(i),
            (Some(s), false) => {
                out.push(crate::names::fold(&String::from_utf8_lossy(&b[s..i])));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// A call around the cursor.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct CallCx {
    /// The routine's name and its offset in the file.
    pub name: String,
    pub name_start: usize,
    pub is_function: bool,
    /// The arguments before the current one.
    pub done: Vec<ArgCx>,
    /// The argument being written.
    pub current: ArgCx,
}

#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct ArgCx {
    /// `\Name` or `Name:=`: the name given, if any.
    pub name: Option<String>,
    /// Written with a backslash.
    pub optional: bool,
    /// `:=` seen (a value follows).
    pub has_value: bool,
    /// The argument's text (trimmed).
    pub text: String,
}

fn parse_arg(b: &[u8]) -> ArgCx {
    let s = String::from_utf8_lossy(b);
    let t = s.trim();
    let mut arg = ArgCx {
        text: t.to_owned(),
        ..ArgCx::default()
    };
    let rest = match t.strip_prefix('\\') {
        Some(r) => {
            arg.optional = true;
            r.trim_start()
        }
        None => t,
    };
    let name_len = ident_len(rest.as_bytes());
    let after = rest.get(name_len..).unwrap_or_default().trim_start();
    if arg.optional {
        arg.name = Some(rest.get(..name_len).unwrap_or_default().to_owned());
        arg.has_value = after.starts_with(":=");
    } else if name_len > 0 && after.starts_with(":=") {
        arg.name = Some(rest.get(..name_len).unwrap_or_default().to_owned());
        arg.has_value = true;
    }
    arg
}

/// Splits argument text at depth-zero commas and before depth-zero
/// backslashes (optional arguments may follow without a comma).
fn split_args(b: &[u8]) -> Vec<&[u8]> {
    let mut parts = Vec::new();
    let mut depth: i32 = 0;
    let mut start = 0;
    for (i, &c) in b.iter().enumerate() {
        match c {
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b']' | b'}' => depth -= 1,
            b',' if depth == 0 => {
                parts.push(&b[start..i]);
                start = i + 1;
            }
            b'\\' if depth == 0 => {
                if b[start..i].iter().any(|c| !c.is_ascii_whitespace()) {
                    parts.push(&b[start..i]);
                }
                start = i;
            }
            _ => {}
        }
    }
    parts.push(&b[start..]);
    parts
}

/// The innermost call around the end of `before`.
pub(crate) fn call_at(bf: &Before) -> Option<CallCx> {
    let b = &bf.text;
    // An unclosed `(` preceded by a name: a function call.
    let stmt = statement_start(b);
    let mut depth: i32 = 0;
    let mut i = b.len();
    while i > stmt {
        let c = b[i - 1];
        match c {
            b')' | b']' | b'}' => depth += 1,
            b'[' | b'{' => depth -= 1,
            b'(' => {
                if depth == 0 {
                    let mut j = i - 1;
                    while j > stmt && b[j - 1] == b' ' {
                        j -= 1;
                    }
                    let end = j;
                    while j > stmt && is_ident(b, j - 1) {
                        j -= 1;
                    }
                    if j < end && !b[j].is_ascii_digit() {
                        let name = String::from_utf8_lossy(&b[j..end]).into_owned();
                        let lower = name.to_ascii_lowercase();
                        if !["proc", "func", "trap", "if", "while", "elseif"]
                            .contains(&lower.as_str())
                            && !is_routine_header(b.get(stmt..j).unwrap_or_default())
                        {
                            return Some(build(bf, name, j, true, &b[i..]));
                        }
                    }
                    return None;
                }
                depth -= 1;
            }
            _ => {}
        }
        i -= 1;
    }
    // A procedure call: the statement's first word followed by arguments.
    let s = &b[stmt..];
    let lead = s.iter().take_while(|c| c.is_ascii_whitespace()).count();
    let name_len = ident_len(&s[lead..]);
    if name_len == 0 {
        return None;
    }
    let after = &s[lead + name_len..];
    // The name must be followed by white space or a backslash, and the rest
    // must not be an assignment.
    if !after
        .first()
        .is_some_and(|c| c.is_ascii_whitespace() || *c == b'\\')
    {
        return None;
    }
    let name = String::from_utf8_lossy(&s[lead..lead + name_len]).into_owned();
    // A keyword statement, or an assignment `x := ...` (`:=` after the
    // first word rather than after an argument name).
    if is_keyword_statement(&name) || !is_named_args(after) {
        return None;
    }
    Some(build(bf, name, stmt + lead, false, after))
}

/// Does `a := ...` look like named arguments (`Name:=` after a comma or at
/// the start of the arguments) rather than an assignment?
fn is_named_args(after: &[u8]) -> bool {
    let s = String::from_utf8_lossy(after);
    let t = s.trim_start();
    // `x := v` — assignment: the text starts with `:=`.
    !t.starts_with(":=") && !t.starts_with('{') && !t.starts_with('.')
}

fn is_keyword_statement(word: &str) -> bool {
    [
        "if", "for", "while", "test", "case", "return", "raise", "goto", "connect", "var", "pers",
        "const", "local", "task", "proc", "func", "trap", "record", "alias", "module", "exit",
        "retry", "trynext", "elseif", "from",
    ]
    .iter()
    .any(|k| k.eq_ignore_ascii_case(word))
}

fn is_routine_header(b: &[u8]) -> bool {
    let w = words(b);
    w.iter().any(|w| w == "proc" || w == "func" || w == "trap")
}

fn build(bf: &Before, name: String, name_at: usize, is_function: bool, args: &[u8]) -> CallCx {
    let mut parts = split_args(args);
    let current = parts.pop().map(parse_arg).unwrap_or_default();
    CallCx {
        name,
        name_start: bf.start + name_at,
        is_function,
        done: parts.into_iter().map(parse_arg).collect(),
        current,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(src: &str) -> Option<CallCx> {
        call_at(&before(src, src.len()))
    }

    #[test]
    fn procedure_calls_are_found_in_broken_text() {
        let c = call("PROC main()\n  MoveL p10, v1").unwrap_or_else(|| panic!("no call"));
        assert_eq!(c.name, "MoveL");
        assert_eq!(c.done.len(), 1);
        assert_eq!(c.current.text, "v1");
        let c = call("  x := 1;\n  MoveL \\Conc, p10 \\ID").unwrap_or_else(|| panic!("no call"));
        assert_eq!(c.done.len(), 2);
        assert!(c.current.optional);
        assert_eq!(c.current.name.as_deref(), Some("ID"));
        assert_eq!(call("  x := Abs(").map(|c| c.name), Some("Abs".to_owned()));
        assert_eq!(call("  x := y"), None);
        assert_eq!(call("  IF n > "), None);
        assert_eq!(call("  x.a := Abs(y) + "), None);
        assert_eq!(
            call("  MoveL ToPoint:=p10, ").map(|c| c.done[0].name.clone()),
            Some(Some("ToPoint".to_owned()))
        );
        assert_eq!(
            call("  IF a THEN\n    TPWrite \"a;b\", ").map(|c| c.done.len()),
            Some(1)
        );
        assert_eq!(
            call("  ! MoveL p10;\n  Set do1, ").map(|c| c.done.len()),
            Some(1)
        );
    }
}
