//! A light reading of RAPID text without the grammar, for what needs only
//! strings and comments: string literals never span lines, `""` is a quote
//! inside one, and `!` outside a string starts a comment to the end of the
//! line.

use std::ops::Range;

/// The string literals of `text` outside comments: the range of each
/// literal's content (between its quotes) and that content as written
/// (with `""` still doubled). An unterminated string ends its line.
pub fn string_literals(text: &str) -> Vec<(Range<usize>, &str)> {
    let mut out = Vec::new();
    let bytes = text.as_bytes();
    let mut i = 0;
    let mut start: Option<usize> = None;
    while i < bytes.len() {
        let b = bytes[i];
        match (start, b) {
            (None, b'"') => start = Some(i + 1),
            (None, b'!') => {
                // A comment: skip to the end of the line.
                while i < bytes.len() && bytes[i] != b'\n' && bytes[i] != b'\r' {
                    i += 1;
                }
                continue;
            }
            (Some(s), b'"') => {
                if bytes.get(i + 1) == Some(&b'"') {
                    i += 2;
                    continue;
                }
                out.push((s..i, text.get(s..i).unwrap_or_default()));
                start = None;
            }
            (Some(s), b'\n' | b'\r') => {
                out.push((s..i, text.get(s..i).unwrap_or_default()));
                start = None;
            }
            _ => {}
        }
        i += 1;
    }
    if let Some(s) = start {
        out.push((s..text.len(), text.get(s..).unwrap_or_default()));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contents(text: &str) -> Vec<&str> {
        string_literals(text).into_iter().map(|(_, s)| s).collect()
    }

    #[test]
    fn strings_outside_comments() {
        assert_eq!(
            contents("TPWrite \"a!b\"; ! \"not\"\n%\"path_\" + s%;"),
            ["a!b", "path_"]
        );
        assert_eq!(contents("s := \"say \"\"hi\"\"\";"), ["say \"\"hi\"\""]);
        assert_eq!(contents("s := \"open\nt := \"x\";"), ["open", "x"]);
        assert_eq!(contents("\"tail"), ["tail"]);
        assert_eq!(contents("! only \"a comment\""), Vec::<&str>::new());
    }

    #[test]
    fn ranges_point_at_the_content() {
        let text = "x := \"héllo\";";
        let (range, s) = string_literals(text).remove(0);
        assert_eq!(&text[range], s);
        assert_eq!(s, "héllo");
    }
}
