//! Text positions the rules' fix builders share: lines, indentation and
//! the file's line break.

/// The start of the line holding `offset` (after a `\n` or a lone `\r`).
pub(crate) fn line_start(text: &str, offset: usize) -> usize {
    text.get(..offset)
        .and_then(|b| b.rfind(['\n', '\r']))
        .map_or(0, |i| i + 1)
}

/// The end of the line holding `offset`, after its line break (or the end
/// of the text).
pub(crate) fn line_end(text: &str, offset: usize) -> usize {
    text.get(offset..)
        .and_then(|t| t.find('\n'))
        .map_or(text.len(), |i| offset + i + 1)
}

/// The indentation (spaces and tabs) that starts the line holding `offset`.
pub(crate) fn indent_at(text: &str, offset: usize) -> &str {
    let rest = text.get(line_start(text, offset)..).unwrap_or_default();
    let len = rest.len() - rest.trim_start_matches([' ', '\t']).len();
    rest.get(..len).unwrap_or_default()
}

/// Is only white space between the start of its line and `offset`?
pub(crate) fn starts_line(text: &str, offset: usize) -> bool {
    text.get(line_start(text, offset)..offset)
        .is_some_and(|b| b.trim().is_empty())
}

/// The file's line break: `\r\n` when it uses it anywhere, else `\n`.
pub(crate) fn line_break(text: &str) -> &'static str {
    if text.contains("\r\n") { "\r\n" } else { "\n" }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_indentation() {
        let text = "a\r\n  \tb c\nd";
        let b = text.find('b').unwrap_or(0);
        assert_eq!(line_start(text, b), 3);
        assert_eq!(indent_at(text, b), "  \t");
        assert_eq!(line_end(text, b), text.find('d').unwrap_or(0));
        assert!(starts_line(text, b));
        assert!(!starts_line(text, b + 2));
        assert_eq!(line_break(text), "\r\n");
        assert_eq!(line_end(text, text.len() - 1), text.len());
    }
}
