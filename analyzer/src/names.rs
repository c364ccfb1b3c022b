//! RAPID names are case-insensitive: compare and look up folded, display as
//! declared.
//!
//! A name is made of the letters of ISO 8859-1 (Latin-1, the controller's
//! character set: `A`-`Z`, `a`-`z`, `À`-`Ö`, `Ø`-`ö`, `ø`-`ÿ`), digits and
//! `_`, and starts with a letter. Folding lowercases every letter that has
//! a lowercase in Latin-1 (`Ö` is `ö`, `Þ` is `þ`; `ß` and `ÿ` stay), so
//! `varÖlcüm` and `VARöLCÜM` are one name.

/// Is `c` a letter of a RAPID name (a Latin-1 letter)?
pub fn is_name_start(c: char) -> bool {
    c.is_ascii_alphabetic() || matches!(c, 'À'..='Ö' | 'Ø'..='ö' | 'ø'..='ÿ')
}

/// Can `c` continue a RAPID name (a Latin-1 letter, a digit or `_`)?
pub fn is_name_char(c: char) -> bool {
    is_name_start(c) || c.is_ascii_digit() || c == '_'
}

/// The length in bytes of the name that starts `text` (0 when it does not
/// start with a letter).
pub fn name_len(text: &str) -> usize {
    match text.chars().next() {
        Some(c) if is_name_start(c) => text
            .char_indices()
            .find(|&(_, c)| !is_name_char(c))
            .map_or(text.len(), |(i, _)| i),
        _ => 0,
    }
}

/// The length in bytes of the name that ends `text` (0 when there is none):
/// the name characters at its end, from the first letter among them.
pub fn name_len_before(text: &str) -> usize {
    let start = text
        .char_indices()
        .rev()
        .take_while(|&(_, c)| is_name_char(c))
        .last()
        .map_or(text.len(), |(i, _)| i);
    // A name starts with a letter: skip leading digits and `_`.
    let name = &text[start..];
    let skip = name
        .char_indices()
        .find(|&(_, c)| is_name_start(c))
        .map_or(name.len(), |(i, _)| i);
    name.len() - skip
}

/// Is byte `i` of the UTF-8 text `b` part of a name character (see
/// [`is_name_char`])? For scanners that work on bytes: a Latin-1 letter is
/// two bytes (`0xC3` and one of `0x80..=0xBF` but `×` and `÷`), and both
/// count; no other byte of a character beyond ASCII does.
pub fn is_name_byte_at(b: &[u8], i: usize) -> bool {
    let letter_tail = |t: u8| (0x80..=0xBF).contains(&t) && t != 0x97 && t != 0xB7;
    match b.get(i) {
        Some(&c) if c.is_ascii() => c.is_ascii_alphanumeric() || c == b'_',
        Some(0xC3) => b.get(i + 1).is_some_and(|&t| letter_tail(t)),
        Some(&t) => i > 0 && b[i - 1] == 0xC3 && letter_tail(t),
        None => false,
    }
}

pub use rapid_catalogue::names::{fold_char, same};

/// The folded form of a name, used as a key (Latin-1 letters lowercase).
pub fn fold(name: &str) -> String {
    if name.is_ascii() {
        name.to_ascii_lowercase()
    } else {
        name.chars().map(fold_char).collect()
    }
}

/// Calls `f` with the folded form of `name` (as [`fold`]) without
/// allocating for names of up to 32 bytes: for map look-ups on a hot path.
pub fn with_folded<R>(name: &str, f: impl FnOnce(&str) -> R) -> R {
    const MAX: usize = 32;
    let bytes = name.as_bytes();
    if bytes.len() <= MAX && name.is_ascii() {
        let mut buf = [0u8; MAX];
        let out = &mut buf[..bytes.len()];
        out.copy_from_slice(bytes);
        out.make_ascii_lowercase();
        // ASCII text lowercased is ASCII, so this always succeeds.
        if let Ok(folded) = std::str::from_utf8(out) {
            return f(folded);
        }
    }
    f(&fold(name))
}

/// A fast, unkeyed hasher for maps of short names with fixed keys (the
/// catalogue): the FxHash mixing step over 8-byte words.
#[derive(Default, Clone, Copy)]
pub struct NameHasher(u64);

impl std::hash::Hasher for NameHasher {
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for chunk in &mut chunks {
            let mut word = [0u8; 8];
            word.copy_from_slice(chunk);
            self.add(u64::from_le_bytes(word));
        }
        let mut word = [0u8; 8];
        let rest = chunks.remainder();
        word[..rest.len()].copy_from_slice(rest);
        self.add(u64::from_le_bytes(word) ^ (rest.len() as u64) << 56);
    }

    fn write_u8(&mut self, i: u8) {
        self.add(u64::from(i));
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

impl NameHasher {
    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// A map keyed by folded names, hashed with [`NameHasher`].
pub type NameMap<V> =
    std::collections::HashMap<String, V, std::hash::BuildHasherDefault<NameHasher>>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_fold_latin1_letters() {
        assert_eq!(fold("MoveL"), "movel");
        assert!(same("EndProc", "ENDPROC"));
        assert!(!same("p10", "p100"));
        assert_eq!(fold("varÖlcüm"), "varölcüm");
        assert_eq!(fold("SENSÖR_Kalibre"), "sensör_kalibre");
        assert!(same("Ñandú", "ñANDÚ"));
        assert!(same("Öl", "öL"));
        assert!(!same("Öl", "Ol"));
        // no capital in Latin-1: they stay; × and ÷ are not letters
        assert_eq!(fold("ßÿ×"), "ßÿ×");
        assert_eq!(fold("ÀÞ"), "àþ");
        for name in ["MoveL", "", "é_Ä", &"AbC".repeat(20), &"Ä".repeat(20)] {
            assert_eq!(with_folded(name, str::to_string), fold(name));
        }
    }

    #[test]
    fn name_characters_are_latin1_letters_digits_and_underscore() {
        for c in ['a', 'Z', 'À', 'Ö', 'Ø', 'ö', 'ø', 'ÿ', 'ß', 'Ñ'] {
            assert!(is_name_start(c), "{c}");
        }
        for c in ['×', '÷', '\u{a0}', '\u{3000}', 'Ā', 'ı', '1', '_', 'µ', 'ª'] {
            assert!(!is_name_start(c), "{c:?}");
        }
        assert!(is_name_char('_') && is_name_char('7'));
        assert_eq!(name_len("Sensör_1 := 2"), "Sensör_1".len());
        assert_eq!(name_len("1abc"), 0);
        assert_eq!(name_len_before("x := varÖlç"), "varÖlç".len());
        assert_eq!(name_len_before("x := 12"), 0);
        assert_eq!(name_len_before("x := 1ab"), 2);
    }

    #[test]
    fn name_bytes_are_those_of_name_characters() {
        let text = "aÖ_1×é\u{a0}\u{3000}€ÿ";
        let bytes = text.as_bytes();
        for (i, c) in text.char_indices() {
            for k in 0..c.len_utf8() {
                assert_eq!(
                    is_name_byte_at(bytes, i + k),
                    is_name_char(c),
                    "{c:?} byte {k}"
                );
            }
        }
        assert!(!is_name_byte_at(bytes, bytes.len()));
    }
}
