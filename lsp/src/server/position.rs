//! Byte offsets (the analyzer's) to LSP positions and back.
//!
//! The analyzer speaks byte offsets into the decoded text; LSP speaks lines
//! and columns, the columns counted in UTF-16 code units unless the client
//! and server agreed on UTF-8. Lines end at `\n`, `\r\n` or a lone `\r`, as
//! both the protocol and [`LineIndex`] say. Positions past the end of a line
//! are clamped to the line's end, lines past the end of the text to the end
//! of the text, and a column inside a character to the character's start:
//! clients send such positions and must get an answer, not an error.

use std::ops::Range;

use rapid_analyzer::text::{LineCol, LineIndex};
use tower_lsp_server::ls_types::{Position, PositionEncodingKind, Range as LspRange};

/// How columns are counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PosEncoding {
    /// UTF-16 code units: the protocol's default.
    #[default]
    Utf16,
    /// Bytes of UTF-8, when the client offers it.
    Utf8,
}

impl PosEncoding {
    /// The encoding to use given the client's offer (`general.positionEncodings`):
    /// UTF-8 when offered (no conversion at all), else UTF-16.
    pub fn negotiate(offered: Option<&[PositionEncodingKind]>) -> PosEncoding {
        match offered {
            Some(kinds) if kinds.contains(&PositionEncodingKind::UTF8) => PosEncoding::Utf8,
            _ => PosEncoding::Utf16,
        }
    }

    pub fn kind(self) -> PositionEncodingKind {
        match self {
            PosEncoding::Utf16 => PositionEncodingKind::UTF16,
            PosEncoding::Utf8 => PositionEncodingKind::UTF8,
        }
    }
}

/// A text with its line index and the column encoding: everything needed to
/// convert positions of one file.
#[derive(Clone, Copy)]
pub struct LineMap<'a> {
    pub text: &'a str,
    pub index: &'a LineIndex,
    pub encoding: PosEncoding,
}

impl<'a> LineMap<'a> {
    pub fn new(text: &'a str, index: &'a LineIndex, encoding: PosEncoding) -> LineMap<'a> {
        LineMap {
            text,
            index,
            encoding,
        }
    }

    /// The LSP position of a byte offset (clamped to the text, and to a
    /// character boundary).
    pub fn position(&self, offset: usize) -> Position {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let LineCol { line, col } = self.index.line_col(offset);
        let character = match self.encoding {
            PosEncoding::Utf8 => col,
            // From the nearest mark: positions along a line of megabytes
            // (generated code) cost at most a kilobyte each, not the line.
            PosEncoding::Utf16 => self.index.utf16_col(offset, self.text),
        };
        Position::new(to_u32(line), to_u32(character))
    }

    pub fn range(&self, range: Range<usize>) -> LspRange {
        let start = self.position(range.start);
        let end = self.position(range.end.max(range.start));
        LspRange::new(start, end)
    }

    /// The byte offset of an LSP position, clamped: past the end of its
    /// line is the line's end, past the last line is the end of the text.
    pub fn offset(&self, pos: Position) -> usize {
        let line = pos.line as usize;
        if line >= self.index.line_count() {
            return self.text.len();
        }
        let span = self.index.line_range(line, self.text);
        let Some(line_text) = self.text.get(span.clone()) else {
            return span.start;
        };
        let want = pos.character as usize;
        let col = match self.encoding {
            PosEncoding::Utf8 => {
                let mut col = want.min(line_text.len());
                while !line_text.is_char_boundary(col) {
                    col -= 1;
                }
                col
            }
            PosEncoding::Utf16 => {
                let mut units = 0;
                let mut col = line_text.len();
                for (at, c) in line_text.char_indices() {
                    if units + c.len_utf16() > want {
                        col = at;
                        break;
                    }
                    units += c.len_utf16();
                }
                col
            }
        };
        span.start + col
    }

    pub fn offset_range(&self, range: LspRange) -> Range<usize> {
        let start = self.offset(range.start);
        let end = self.offset(range.end);
        start.min(end)..end.max(start)
    }
}

fn to_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roundtrip(text: &str, encoding: PosEncoding) {
        let index = LineIndex::new(text);
        let map = LineMap::new(text, &index, encoding);
        for (at, _) in text.char_indices().chain([(text.len(), ' ')]) {
            let pos = map.position(at);
            // A line ending's bytes all map to the line's end position.
            let back = map.offset(pos);
            let expected = if text[..at].ends_with('\r') && text[at..].starts_with('\n') {
                at - 1
            } else {
                at
            };
            assert_eq!(back, expected, "{text:?} at {at}: {pos:?}");
        }
    }

    #[test]
    fn offsets_round_trip_in_both_encodings() {
        for text in [
            "",
            "MODULE M\nENDMODULE",
            "a\r\nb\rc\n",
            "! Größe 𝄞 x\r\n  s := \"ä\";\n",
            "\u{1F600}\u{1F600}\n",
        ] {
            roundtrip(text, PosEncoding::Utf16);
            roundtrip(text, PosEncoding::Utf8);
        }
    }

    #[test]
    fn columns_count_utf16_units_or_bytes() {
        let text = "x𝄞é=1\n";
        let index = LineIndex::new(text);
        let at = text.find('=').expect("=");
        let utf16 = LineMap::new(text, &index, PosEncoding::Utf16);
        assert_eq!(utf16.position(at), Position::new(0, 4));
        let utf8 = LineMap::new(text, &index, PosEncoding::Utf8);
        assert_eq!(utf8.position(at), Position::new(0, 7));
    }

    #[test]
    fn positions_out_of_range_are_clamped() {
        let text = "ab\r\ncd";
        let index = LineIndex::new(text);
        let map = LineMap::new(text, &index, PosEncoding::Utf16);
        assert_eq!(map.offset(Position::new(0, 99)), 2);
        assert_eq!(map.offset(Position::new(7, 0)), text.len());
        assert_eq!(map.offset(Position::new(1, 99)), text.len());
        // Inside a surrogate pair: the character's start.
        let text = "𝄞x";
        let index = LineIndex::new(text);
        let map = LineMap::new(text, &index, PosEncoding::Utf16);
        assert_eq!(map.offset(Position::new(0, 1)), 0);
        assert_eq!(map.offset(Position::new(0, 2)), 4);
        let map = LineMap::new(text, &index, PosEncoding::Utf8);
        assert_eq!(map.offset(Position::new(0, 2)), 0);
        assert_eq!(map.position(99), Position::new(0, 5));
    }
}
