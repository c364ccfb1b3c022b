//! RAPID names compare without letter case over the ISO 8859-1 letters
//! (the kernel's character set): `Größe` and `GRÖßE` are one name. The
//! catalogue binds named arguments with it, and the analyzer re-exports it
//! for every other comparison, so there is one rule.

/// A character of a name folded: Latin-1 capitals to their lowercase.
pub fn fold_char(c: char) -> char {
    match c {
        'A'..='Z' | 'À'..='Ö' | 'Ø'..='Þ' => char::from_u32(c as u32 + 32).unwrap_or(c),
        _ => c,
    }
}

/// Do two names denote the same thing (equal once folded)?
pub fn same(a: &str, b: &str) -> bool {
    if a.is_ascii() || b.is_ascii() {
        // A Latin-1 letter never folds to ASCII: an ASCII name equals only
        // an ASCII name.
        return a.eq_ignore_ascii_case(b);
    }
    a.len() == b.len() && a.chars().map(fold_char).eq(b.chars().map(fold_char))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin1_capitals_fold_and_others_stay() {
        assert!(same("Größe", "GRÖßE"));
        assert!(same("varÖlcüm", "VARöLCÜM"));
        assert!(!same("Größe", "Grosse"));
        assert!(!same("ÿ", "Ÿ"));
        assert_eq!(fold_char('×'), '×');
        assert_eq!(fold_char('Þ'), 'þ');
    }
}
