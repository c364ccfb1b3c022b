//! Source text as users have it: decoding controller files, and line positions.
//!
//! Controller files are ISO 8859-1 (Latin-1) without a byte-order mark; newer
//! ones are UTF-8, some with a BOM. Line endings are CRLF, LF or a lone CR, and
//! many files lack a final newline. [`decode`] turns bytes into text without
//! losing a character, and remembers how to write the text back
//! ([`Encoding::encode`]). [`LineIndex`] maps byte offsets to lines for all
//! three line-ending styles.

use std::ops::Range;

/// How a file's bytes were turned into text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Encoding {
    /// UTF-8, with or without a byte-order mark.
    Utf8 { bom: bool },
    /// ISO 8859-1: every byte is one character, U+0000 to U+00FF.
    Latin1,
}

impl Encoding {
    /// A short name for messages: `UTF-8`, `UTF-8 with BOM`, `Latin-1`.
    pub fn name(self) -> &'static str {
        match self {
            Encoding::Utf8 { bom: false } => "UTF-8",
            Encoding::Utf8 { bom: true } => "UTF-8 with BOM",
            Encoding::Latin1 => "Latin-1",
        }
    }

    /// Writes `text` back in this encoding. Fails with the byte offset of the
    /// first character that Latin-1 cannot hold.
    pub fn encode(self, text: &str) -> Result<Vec<u8>, usize> {
        match self {
            Encoding::Utf8 { bom } => {
                let mut out = Vec::with_capacity(text.len() + 3);
                if bom {
                    out.extend_from_slice(UTF8_BOM);
                }
                out.extend_from_slice(text.as_bytes());
                Ok(out)
            }
            Encoding::Latin1 => text
                .char_indices()
                .map(|(at, c)| u8::try_from(u32::from(c)).map_err(|_| at))
                .collect(),
        }
    }
}

const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

/// The result of reading a file's bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Decoded {
    /// Text, and the encoding it came in. The BOM is not part of the text.
    Text { text: String, encoding: Encoding },
    /// An encrypted module (its first byte is 0xFC, 0xFD or 0xFE): the
    /// controller can load it, nobody can read it.
    Encrypted,
    /// Not text at all (it holds NUL bytes).
    Binary,
}

/// Decodes a RAPID file: valid UTF-8 stays UTF-8 (a BOM is noted and
/// dropped), anything else is Latin-1, which maps every byte to a character,
/// so nothing is ever lost.
pub fn decode(bytes: &[u8]) -> Decoded {
    if let Some(rest) = bytes.strip_prefix(UTF8_BOM) {
        return match std::str::from_utf8(rest) {
            Ok(text) => Decoded::Text {
                text: text.to_owned(),
                encoding: Encoding::Utf8 { bom: true },
            },
            Err(_) => latin1(bytes),
        };
    }
    if matches!(bytes.first(), Some(0xFC..=0xFE)) {
        return Decoded::Encrypted;
    }
    if bytes.contains(&0) {
        return Decoded::Binary;
    }
    match std::str::from_utf8(bytes) {
        Ok(text) => Decoded::Text {
            text: text.to_owned(),
            encoding: Encoding::Utf8 { bom: false },
        },
        Err(_) => latin1(bytes),
    }
}

fn latin1(bytes: &[u8]) -> Decoded {
    Decoded::Text {
        text: bytes.iter().map(|&b| char::from(b)).collect(),
        encoding: Encoding::Latin1,
    }
}

/// The line ending a file mostly uses, to write new lines the same way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineEnding {
    Lf,
    CrLf,
    Cr,
}

impl LineEnding {
    /// The most frequent line ending of `text` (LF when there is none).
    pub fn detect(text: &str) -> LineEnding {
        let bytes = text.as_bytes();
        let (mut lf, mut crlf, mut cr) = (0usize, 0usize, 0usize);
        let mut i = 0;
        while i < bytes.len() {
            match bytes[i] {
                b'\r' if bytes.get(i + 1) == Some(&b'\n') => {
                    crlf += 1;
                    i += 1;
                }
                b'\r' => cr += 1,
                b'\n' => lf += 1,
                _ => {}
            }
            i += 1;
        }
        if crlf >= lf && crlf >= cr && crlf > 0 {
            LineEnding::CrLf
        } else if cr > lf {
            LineEnding::Cr
        } else {
            LineEnding::Lf
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            LineEnding::Lf => "\n",
            LineEnding::CrLf => "\r\n",
            LineEnding::Cr => "\r",
        }
    }
}

/// Byte offsets of line starts. A line ends at `\n`, `\r\n` or a lone `\r`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LineIndex {
    starts: Vec<usize>,
    len: usize,
    /// Along lines longer than [`MARK_EVERY`] bytes, a mark at least every
    /// that many bytes: (offset, characters from its line's start to it),
    /// so that [`LineIndex::human`] counts at most that many bytes, however
    /// long the line (generated modules have lines of megabytes, with a
    /// finding every few bytes). With the UTF-16 code units from the line's
    /// start to it, for [`LineIndex::utf16_col`].
    marks: Vec<(usize, usize, usize)>,
}

/// How far apart the character-count marks of long lines are, in bytes.
pub const MARK_EVERY: usize = 1024;

/// A zero-based line and a zero-based byte column within it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct LineCol {
    pub line: usize,
    pub col: usize,
}

impl LineIndex {
    pub fn new(text: &str) -> LineIndex {
        let bytes = text.as_bytes();
        let mut starts = vec![0];
        let mut marks = Vec::new();
        // The last line start or mark, and the characters and UTF-16 units
        // from the line's start to it.
        let mut mark = (0, 0, 0);
        let mut i = 0;
        while i < bytes.len() {
            match bytes[i] {
                b'\r' if bytes.get(i + 1) == Some(&b'\n') => {
                    i += 1;
                    starts.push(i + 1);
                    mark = (i + 1, 0, 0);
                }
                b'\r' | b'\n' => {
                    starts.push(i + 1);
                    mark = (i + 1, 0, 0);
                }
                _ if i - mark.0 >= MARK_EVERY && text.is_char_boundary(i) => {
                    let piece = text.get(mark.0..i).unwrap_or_default();
                    let chars = mark.1 + piece.chars().count();
                    let units = mark.2 + piece.encode_utf16().count();
                    mark = (i, chars, units);
                    marks.push(mark);
                }
                _ => {}
            }
            i += 1;
        }
        LineIndex {
            starts,
            len: text.len(),
            marks,
        }
    }

    /// The number of lines (a text without a final newline still counts its
    /// last line; an empty text has one empty line).
    pub fn line_count(&self) -> usize {
        self.starts.len()
    }

    /// Line and byte column of `offset` (clamped to the end of the text).
    pub fn line_col(&self, offset: usize) -> LineCol {
        let offset = offset.min(self.len);
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        LineCol {
            line,
            col: offset - self.starts[line],
        }
    }

    /// The byte offset of a line and byte column (clamped to the line's
    /// length, without its line ending, and to the text).
    pub fn offset(&self, pos: LineCol, text: &str) -> usize {
        let Some(&start) = self.starts.get(pos.line) else {
            return self.len;
        };
        let end = self.line_range(pos.line, text).end;
        (start + pos.col).min(end)
    }

    /// The bytes of line `line`, without its line ending.
    pub fn line_range(&self, line: usize, text: &str) -> Range<usize> {
        let Some(&start) = self.starts.get(line) else {
            return self.len..self.len;
        };
        let mut end = self.starts.get(line + 1).copied().unwrap_or(self.len);
        let bytes = text.as_bytes();
        while end > start && matches!(bytes.get(end - 1), Some(b'\n' | b'\r')) {
            end -= 1;
        }
        start..end
    }

    /// The 1-based line and 1-based column in characters of `offset`, as
    /// people and most tools count them.
    pub fn human(&self, offset: usize, text: &str) -> (usize, usize) {
        let LineCol { line, col } = self.line_col(offset);
        let (from, (before, _)) = self.mark_before(line, col);
        let chars = text
            .get(from..from.max(offset.min(self.len)))
            .map_or(col, |s| before + s.chars().count());
        (line + 1, chars + 1)
    }

    /// The column of `offset` (a character boundary) in UTF-16 code units,
    /// as the language server protocol counts by default; like
    /// [`LineIndex::human`], it counts at most [`MARK_EVERY`] bytes.
    pub fn utf16_col(&self, offset: usize, text: &str) -> usize {
        let LineCol { line, col } = self.line_col(offset);
        let (from, (_, before)) = self.mark_before(line, col);
        text.get(from..from.max(offset.min(self.len)))
            .map_or(col, |s| before + s.encode_utf16().count())
    }

    /// The nearest mark of `line` at or before byte column `col` (or the
    /// line's start): its offset, and the characters and UTF-16 units
    /// before it on the line.
    fn mark_before(&self, line: usize, col: usize) -> (usize, (usize, usize)) {
        let start = self.starts.get(line).copied().unwrap_or(self.len);
        match self.marks.partition_point(|m| m.0 <= start + col) {
            0 => (start, (0, 0)),
            n => match self.marks.get(n - 1) {
                Some(&(at, chars, units)) if at >= start => (at, (chars, units)),
                _ => (start, (0, 0)),
            },
        }
    }
}

/// The lengths of the longest common prefix of `old` and `new`, and of
/// their longest common suffix in what the prefix leaves (the two never
/// overlap): what an edit between them kept at each end.
pub fn common_affixes<T: PartialEq>(old: &[T], new: &[T]) -> (usize, usize) {
    let prefix = old.iter().zip(new).take_while(|(a, b)| a == b).count();
    let max_suffix = old.len().min(new.len()) - prefix;
    let suffix = old
        .iter()
        .rev()
        .zip(new.iter().rev())
        .take(max_suffix)
        .take_while(|(a, b)| a == b)
        .count();
    (prefix, suffix)
}

/// Is this the name of a RAPID source file? (`.mod .modx .sys .sysx .prg`, in
/// any letter case.) `.pgf` program files are XML lists of modules, not RAPID.
pub fn is_rapid_file_name(name: &str) -> bool {
    let Some((_, ext)) = name.rsplit_once('.') else {
        return false;
    };
    ["mod", "modx", "sys", "sysx", "prg"]
        .iter()
        .any(|e| ext.eq_ignore_ascii_case(e))
}

/// Is this a controller configuration file the analyzer reads (`EIO.cfg`
/// for I/O signals, `MOC.cfg` for mechanical units, `SYS.cfg` for the tasks
/// and the modules they load, `BACKINFO/backinfo.txt` and
/// `BACKINFO/system.xml` for the RobotWare version and options), in any
/// letter case?
pub fn is_controller_config_name(name: &str) -> bool {
    let base = name.rsplit(['/', '\\']).next().unwrap_or(name);
    ["eio.cfg", "moc.cfg", "sys.cfg"]
        .iter()
        .any(|n| base.eq_ignore_ascii_case(n))
        || crate::controller::is_controller_info_name(name)
}

/// Is this a program file (`.pgf`, an XML list of a task's modules)?
pub fn is_program_file_name(name: &str) -> bool {
    name.rsplit_once('.')
        .is_some_and(|(_, ext)| ext.eq_ignore_ascii_case("pgf"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn common_affixes_never_overlap() {
        assert_eq!(common_affixes(b"abcxdef", b"abcdef"), (3, 3));
        assert_eq!(common_affixes(b"aaa", b"aaaa"), (3, 0));
        assert_eq!(common_affixes(b"", b"ab"), (0, 0));
        assert_eq!(common_affixes(b"ab", b"ab"), (2, 0));
        assert_eq!(common_affixes(&[1, 2, 3], &[1, 9, 3]), (1, 1));
    }

    #[test]
    fn utf8_stays_utf8_and_latin1_keeps_every_byte() {
        assert_eq!(
            decode("MODULE Ä".as_bytes()),
            Decoded::Text {
                text: "MODULE Ä".into(),
                encoding: Encoding::Utf8 { bom: false }
            }
        );
        let latin = b"! \xC4\xD6\xDC \xB0C\r\n";
        let Decoded::Text { text, encoding } = decode(latin) else {
            panic!("latin-1 text is text")
        };
        assert_eq!(encoding, Encoding::Latin1);
        assert_eq!(text, "! ÄÖÜ °C\r\n");
        assert_eq!(encoding.encode(&text).as_deref(), Ok(&latin[..]));
    }

    #[test]
    fn bom_is_dropped_and_restored() {
        let bytes = b"\xEF\xBB\xBFMODULE M\nENDMODULE";
        let Decoded::Text { text, encoding } = decode(bytes) else {
            panic!("text")
        };
        assert_eq!(text, "MODULE M\nENDMODULE");
        assert_eq!(encoding, Encoding::Utf8 { bom: true });
        assert_eq!(encoding.encode(&text).as_deref(), Ok(&bytes[..]));
    }

    #[test]
    fn encrypted_and_binary_files_are_recognised() {
        assert_eq!(decode(b"\xFD\x01\x02"), Decoded::Encrypted);
        assert_eq!(decode(b"MODULE\0"), Decoded::Binary);
    }

    #[test]
    fn latin1_cannot_hold_every_character() {
        assert_eq!(Encoding::Latin1.encode("ab€"), Err(2));
    }

    #[test]
    fn lines_end_at_lf_crlf_and_lone_cr() {
        let text = "a\nbb\r\nccc\rd";
        let index = LineIndex::new(text);
        assert_eq!(index.line_count(), 4);
        let got: Vec<_> = (0..4).map(|l| &text[index.line_range(l, text)]).collect();
        assert_eq!(got, ["a", "bb", "ccc", "d"]);
        assert_eq!(index.line_col(7), LineCol { line: 2, col: 1 });
        assert_eq!(index.line_col(99), LineCol { line: 3, col: 1 });
        assert_eq!(index.offset(LineCol { line: 1, col: 10 }, text), 4);
        assert_eq!(index.human(text.len(), text), (4, 2));
    }

    #[test]
    fn human_and_utf16_columns_on_long_lines_count_from_a_nearby_mark() {
        // A line of megabytes with characters of every width: the same
        // columns as counting from the line's start, while each count
        // reads at most MARK_EVERY bytes and a character (the marks are
        // that close).
        let piece = "a;é;€;𝄞;";
        let line = piece.repeat(40_000);
        let text = format!("x\r\n{line}\ny {line}");
        let index = LineIndex::new(&text);
        let mut at = 0;
        let mut checked = 0;
        while at <= text.len() {
            if text.is_char_boundary(at) {
                let start = index.starts[index.line_col(at).line];
                let naive = text[start..at].chars().count() + 1;
                assert_eq!(index.human(at, &text).1, naive, "at {at}");
                let units = text[start..at].encode_utf16().count();
                assert_eq!(index.utf16_col(at, &text), units, "at {at}");
                let mark = index
                    .marks
                    .iter()
                    .rev()
                    .find(|m| m.0 <= at)
                    .map_or(start, |m| m.0.max(start));
                assert!(
                    at - mark < MARK_EVERY + 4,
                    "{at} is {} from a mark",
                    at - mark
                );
                checked += 1;
            }
            at += 97;
        }
        assert!(checked > 3_000);
    }

    #[test]
    fn human_columns_count_characters() {
        let text = "x := \"äö\"; y";
        let index = LineIndex::new(text);
        let y = text.find('y').unwrap_or_default();
        assert_eq!(index.human(y, text), (1, 12));
    }

    #[test]
    fn line_endings_are_detected() {
        assert_eq!(LineEnding::detect("a\r\nb\r\n"), LineEnding::CrLf);
        assert_eq!(LineEnding::detect("a\rb\r"), LineEnding::Cr);
        assert_eq!(LineEnding::detect("a\nb"), LineEnding::Lf);
        assert_eq!(LineEnding::detect("ab"), LineEnding::Lf);
    }

    #[test]
    fn configuration_and_program_file_names() {
        assert!(is_controller_config_name("b/SYSPAR/EIO.cfg"));
        assert!(is_controller_config_name("b/SYSPAR/SYS.cfg"));
        assert!(is_controller_config_name("moc.CFG"));
        assert!(!is_controller_config_name("SIO.cfg"));
        assert!(is_program_file_name("T_ROB1.pgf") && is_program_file_name("a.PGF"));
        assert!(!is_program_file_name("a.mod"));
    }

    #[test]
    fn rapid_file_names() {
        for ok in ["a.mod", "B.MOD", "c.Sysx", "d.prg", "e.modx", "f.sys"] {
            assert!(is_rapid_file_name(ok), "{ok}");
        }
        for no in ["a.pgf", "mod", "a.cfg", "a.mod.bak"] {
            assert!(!is_rapid_file_name(no), "{no}");
        }
    }
}
