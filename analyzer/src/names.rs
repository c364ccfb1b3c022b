//! RAPID names are case-insensitive: compare and look up folded, display as
//! declared.

/// The folded form of a name, used as a key (ASCII lowercase: RAPID names are
/// ASCII).
pub fn fold(name: &str) -> String {
    name.to_ascii_lowercase()
}

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
    }
}
