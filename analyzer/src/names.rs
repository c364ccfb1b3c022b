//! RAPID names are case-insensitive: compare and look up folded, display as
//! declared.

/// The folded form of a name, used as a key (ASCII lowercase: RAPID names are
/// ASCII).
pub fn fold(name: &str) -> String {
    name.to_ascii_lowercase()
}

/// Calls `f` with the folded form of `name` (as [`fold`]) without
/// allocating for names of up to 32 bytes: for map look-ups on a hot path.
pub fn with_folded<R>(name: &str, f: impl FnOnce(&str) -> R) -> R {
    const MAX: usize = 32;
    let bytes = name.as_bytes();
    if bytes.len() <= MAX {
        let mut buf = [0u8; MAX];
        let out = &mut buf[..bytes.len()];
        out.copy_from_slice(bytes);
        out.make_ascii_lowercase();
        // ASCII lowercasing keeps UTF-8 valid, so this always succeeds.
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

/// Do two names denote the same thing?
pub fn same(a: &str, b: &str) -> bool {
    a.eq_ignore_ascii_case(b)
}

#[cfg(test)]
mod tests {
    #[test]
    fn names_fold_ascii_only() {
        assert_eq!(super::fold("MoveL"), "movel");
        assert!(super::same("EndProc", "ENDPROC"));
        assert!(!super::same("p10", "p100"));
        for name in ["MoveL", "", "é_Ä", &"AbC".repeat(20)] {
            assert_eq!(super::with_folded(name, str::to_string), super::fold(name));
        }
    }
}
