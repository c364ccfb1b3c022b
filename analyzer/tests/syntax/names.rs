//! Finds the node kinds and field names that Rust source names by string
//! literal, in the common forms:
//!
//! - field names: `field(n, "x")`, `fields(n, "x")`, `child_by_field_name("x")`,
//!   `children_by_field_name("x", …)`, `field_id("x")`, `field_id_for_name("x")`;
//! - kinds: `kind(n) == "x"`, `n.kind() != "x"`, `has_token(n, "x")`,
//!   `id_for_node_kind("x", …)`, `matches!(kind(n), "a" | "b")` (any
//!   `matches!` whose scrutinee calls `kind`), and the arm patterns of a
//!   `match` whose scrutinee calls `kind` (a kind or, in tuple patterns, a
//!   field name).
//!
//! A regex-like pass over the text, not a parser: it misses names held in
//! variables and consts, which is why code should use the generated constants.

/// What a string literal is used as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    Kind,
    Field,
    /// A `match` arm over a tuple such as `(parent.kind(), field)`.
    KindOrField,
}

/// A string literal used as a kind or field name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Use {
    pub line: usize,
    pub role: Role,
    pub name: String,
}

const FIELD_CALLS: &[&str] = &[
    "field",
    "fields",
    "child_by_field_name",
    "children_by_field_name",
    "field_id",
    "field_id_for_name",
    "opt_expr",
    "req_expr",
];
const KIND_CALLS: &[&str] = &["has_token", "id_for_node_kind"];

/// The uses in `text`, in order.
pub fn uses(text: &str) -> Vec<Use> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let line_of = |at: usize| text[..at].matches('\n').count() + 1;
    let mut push = |at: usize, role: Role, name: String| {
        out.push(Use {
            line: line_of(at),
            role,
            name,
        })
    };
    let mut at = 0;
    while at < bytes.len() {
        // Skip comments and string literals outside the forms.
        if bytes[at..].starts_with(b"//") {
            at = bytes[at..]
                .iter()
                .position(|b| *b == b'\n')
                .map_or(bytes.len(), |n| at + n);
            continue;
        }
        if bytes[at] == b'"' {
            at = string_end(bytes, at);
            continue;
        }
        if let Some(after) = raw_string_end(bytes, at) {
            at = after;
            continue;
        }
        if bytes[at] == b'\'' {
            // A char literal ('"', '\\', '\u{c}') or a lifetime.
            at = if bytes[at..].starts_with(b"'\\") {
                bytes[at + 3..]
                    .iter()
                    .position(|b| *b == b'\'')
                    .map_or(bytes.len(), |n| at + 3 + n + 1)
            } else if bytes.get(at + 2) == Some(&b'\'') {
                at + 3
            } else {
                at + 1
            };
            continue;
        }
        let Some((word, end)) = ident(text, at) else {
            at += 1;
            continue;
        };
        if at > 0 && is_ident_byte(bytes[at - 1]) {
            at = end;
            continue;
        }
        let after = skip_blank(bytes, end);
        if word == "match" {
            let open = scrutinee_end(bytes, after);
            if bytes.get(open) == Some(&b'{') && calls_kind(&text[after..open]) {
                let tuple = bytes.get(after) == Some(&b'(');
                let role = if tuple { Role::KindOrField } else { Role::Kind };
                for (s, e) in arm_patterns(bytes, open) {
                    push(s, role, unescape(&text[s + 1..e - 1]));
                }
            }
            at = end;
            continue;
        }
        if bytes.get(after) == Some(&b'(') {
            let close = close_of(bytes, after);
            if FIELD_CALLS.contains(&word) || KIND_CALLS.contains(&word) {
                let role = if FIELD_CALLS.contains(&word) {
                    Role::Field
                } else {
                    Role::Kind
                };
                // The first string literal among the call's arguments.
                if let Some((s, e)) = literals(bytes, after + 1, close).next() {
                    push(s, role, unescape(&text[s + 1..e - 1]));
                }
            }
            if word == "field_name" || word == "field_in_parent" {
                // `cursor.field_name() == Some("x")`.
                if let Some((s, e)) = compared_some(bytes, close + 1) {
                    push(s, Role::Field, unescape(&text[s + 1..e - 1]));
                }
            }
            if word == "kind" || word == "kind_of" {
                // `kind(…) == "x"`, `.kind() != "x"`.
                let next = skip_blank(bytes, close + 1);
                if bytes[next..].starts_with(b"==") || bytes[next..].starts_with(b"!=") {
                    let lit = skip_blank(bytes, next + 2);
                    if bytes.get(lit) == Some(&b'"') {
                        let e = string_end(bytes, lit);
                        push(lit, Role::Kind, unescape(&text[lit + 1..e - 1]));
                    }
                }
            }
            at = after + 1;
            continue;
        }
        if word == "field" {
            // A variable holding a field name: `field == Some("x")`.
            if let Some((s, e)) = compared_some(bytes, end) {
                push(s, Role::Field, unescape(&text[s + 1..e - 1]));
            }
        }
        if word == "matches" && bytes.get(after) == Some(&b'!') {
            let open = skip_blank(bytes, after + 1);
            if bytes.get(open) == Some(&b'(') {
                let close = close_of(bytes, open);
                let comma = top_level_comma(bytes, open + 1, close);
                if calls_kind(&text[open + 1..comma]) {
                    for (s, e) in literals(bytes, comma, close) {
                        push(s, Role::Kind, unescape(&text[s + 1..e - 1]));
                    }
                }
                at = close;
                continue;
            }
        }
        at = end;
    }
    out
}

/// The value of a string literal's body with the simple escapes (`\\`,
/// `\"`) that kind names hold.
fn unescape(body: &str) -> String {
    let mut out = String::with_capacity(body.len());
    let mut chars = body.chars();
    while let Some(c) = chars.next() {
        if c == '\\' {
            out.extend(chars.next());
        } else {
            out.push(c);
        }
    }
    out
}

fn is_ident_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// The identifier at `at`, and where it ends.
fn ident(text: &str, at: usize) -> Option<(&str, usize)> {
    let bytes = text.as_bytes();
    if !bytes
        .get(at)
        .is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_')
    {
        return None;
    }
    let mut end = at;
    while bytes.get(end).is_some_and(|b| is_ident_byte(*b)) {
        end += 1;
    }
    Some((&text[at..end], end))
}

fn skip_blank(bytes: &[u8], mut at: usize) -> usize {
    while bytes.get(at).is_some_and(u8::is_ascii_whitespace) {
        at += 1;
    }
    at
}

/// The end of the raw string literal (`r"…"`, `r#"…"#`, `br"…"`) starting
/// at `at`, if one does.
fn raw_string_end(bytes: &[u8], at: usize) -> Option<usize> {
    if at > 0 && is_ident_byte(bytes[at - 1]) {
        return None;
    }
    let mut i = at + usize::from(bytes.get(at) == Some(&b'b'));
    if bytes.get(i) != Some(&b'r') {
        return None;
    }
    i += 1;
    let hashes = bytes[i..].iter().take_while(|b| **b == b'#').count();
    i += hashes;
    if bytes.get(i) != Some(&b'"') {
        return None;
    }
    let mut close = vec![b'"'];
    close.extend(std::iter::repeat_n(b'#', hashes));
    let body = i + 1;
    Some(
        bytes[body..]
            .windows(close.len())
            .position(|w| w == close.as_slice())
            .map_or(bytes.len(), |n| body + n + close.len()),
    )
}

/// The end (after the closing quote) of the string literal starting at `at`.
fn string_end(bytes: &[u8], at: usize) -> usize {
    let mut i = at + 1;
    while i < bytes.len() {
        match bytes[i] {
            b'\\' => i += 2,
            b'"' => return i + 1,
            _ => i += 1,
        }
    }
    bytes.len()
}

/// The index of the bracket closing the one at `open` (or the end).
fn close_of(bytes: &[u8], open: usize) -> usize {
    let mut depth = 0usize;
    let mut i = open;
    while i < bytes.len() {
        match bytes[i] {
            b'"' => {
                i = string_end(bytes, i);
                continue;
            }
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b']' | b'}' => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return i;
                }
            }
            _ => {}
        }
        i += 1;
    }
    bytes.len()
}

/// The first comma at bracket depth 0 in `from..to` (or `to`).
fn top_level_comma(bytes: &[u8], from: usize, to: usize) -> usize {
    let mut i = from;
    while i < to {
        match bytes[i] {
            b'"' => {
                i = string_end(bytes, i);
                continue;
            }
            b'(' | b'[' | b'{' => {
                i = close_of(bytes, i) + 1;
                continue;
            }
            b',' => return i,
            _ => {}
        }
        i += 1;
    }
    to
}

/// The string literals at bracket depth 0 in `from..to`, as (start, end).
fn literals(bytes: &[u8], from: usize, to: usize) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut i = from;
    std::iter::from_fn(move || {
        while i < to {
            match bytes[i] {
                b'"' => {
                    let start = i;
                    i = string_end(bytes, i);
                    return Some((start, i));
                }
                b'(' | b'[' | b'{' => i = close_of(bytes, i) + 1,
                _ => i += 1,
            }
        }
        None
    })
}

/// The string literal in `== Some("x")` or `!= Some("x")` at `at`.
fn compared_some(bytes: &[u8], at: usize) -> Option<(usize, usize)> {
    let op = skip_blank(bytes, at);
    if !(bytes[op..].starts_with(b"==") || bytes[op..].starts_with(b"!=")) {
        return None;
    }
    let some = skip_blank(bytes, op + 2);
    let lit = some + "Some(".len();
    (bytes[some..].starts_with(b"Some(") && bytes.get(lit) == Some(&b'"'))
        .then(|| (lit, string_end(bytes, lit)))
}

/// Does this expression call `kind` or `kind_of` (`kind(n)`, `n.kind()`,
/// `syntax_util::kind(n)`)?
fn calls_kind(expr: &str) -> bool {
    let bytes = expr.as_bytes();
    expr.match_indices("kind").any(|(i, _)| {
        let before_ok = i == 0 || !is_ident_byte(bytes[i - 1]);
        let mut end = i + 4;
        if bytes[end..].starts_with(b"_of") {
            end += 3;
        }
        let after = skip_blank(bytes, end);
        before_ok && bytes.get(after) == Some(&b'(')
    })
}

/// Where the `{` of a `match` starting at `at` is: the first `{` outside
/// brackets (a scrutinee holds no struct literal in this code).
fn scrutinee_end(bytes: &[u8], mut at: usize) -> usize {
    while at < bytes.len() {
        match bytes[at] {
            b'{' | b';' => return at,
            b'"' => at = string_end(bytes, at),
            b'(' | b'[' => at = close_of(bytes, at) + 1,
            _ => at += 1,
        }
    }
    at
}

/// The string literals in the arm patterns (before each `=>`, guards
/// excluded) of the match block opening at `open`.
fn arm_patterns(bytes: &[u8], open: usize) -> Vec<(usize, usize)> {
    let close = close_of(bytes, open);
    let mut out = Vec::new();
    let mut i = open + 1;
    let mut in_pattern = true;
    let mut pattern_start = i;
    while i < close {
        if bytes[i..].starts_with(b"//") {
            while i < close && bytes[i] != b'\n' {
                i += 1;
            }
            continue;
        }
        if in_pattern {
            if bytes[i..].starts_with(b"=>") {
                collect_pattern(bytes, pattern_start, i, &mut out);
                in_pattern = false;
                i += 2;
                continue;
            }
            match bytes[i] {
                b'"' => i = string_end(bytes, i),
                _ => i += 1,
            }
        } else {
            // The arm's body: a block, or an expression up to a comma at
            // depth 0.
            i = skip_blank(bytes, i);
            if bytes.get(i) == Some(&b'{') {
                i = close_of(bytes, i) + 1;
                let next = skip_blank(bytes, i);
                if bytes.get(next) == Some(&b',') {
                    i = next + 1;
                }
            } else {
                i = top_level_comma(bytes, i, close) + 1;
            }
            in_pattern = true;
            pattern_start = i;
        }
    }
    out
}

/// The literals of one pattern, without its guard.
fn collect_pattern(bytes: &[u8], from: usize, to: usize, out: &mut Vec<(usize, usize)>) {
    let text = std::str::from_utf8(&bytes[from..to]).unwrap_or_default();
    let mut end = to;
    // ` if ` starts a guard (outside strings, which hold no ` if ` here).
    if let Some(g) = text.find(" if ") {
        end = from + g;
    }
    let mut i = from;
    while i < end {
        if bytes[i] == b'"' {
            let e = string_end(bytes, i);
            out.push((i, e));
            i = e;
        } else {
            i += 1;
        }
    }
}
