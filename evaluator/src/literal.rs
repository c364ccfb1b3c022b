//! Decoding of RAPID literals from their source text.

use crate::error::{ErrorCode, EvalError, err};

/// The longest string RAPID holds, in characters.
pub const MAX_STRING_LEN: usize = 80;

/// Decodes a RAPID string literal, given with its surrounding quotes.
///
/// `""` stands for one quote, `\\` for one backslash and `\hh` (two hex
/// digits) for the character with that ISO 8859-1 code. Every character must
/// be in ISO 8859-1 and the result at most 80 characters long
/// ([`ErrorCode::StrTooLong`]); anything else malformed is
/// [`ErrorCode::BadLiteral`].
///
/// ```
/// assert_eq!(rapid_evaluator::parse_string_literal(r#""a""b\41\\""#).unwrap(), "a\"bA\\");
/// ```
pub fn parse_string_literal(src: &str) -> Result<String, EvalError> {
    let inner = src
        .strip_prefix('"')
        .and_then(|s| s.strip_suffix('"'))
        .filter(|_| src.len() >= 2);
    let Some(inner) = inner else {
        return err(
            ErrorCode::BadLiteral,
            "a string literal must be enclosed in double quotes",
        );
    };
    let mut out = String::with_capacity(inner.len());
    let mut count = 0usize;
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        let decoded = match c {
            '"' => match chars.next() {
                Some('"') => '"',
                _ => {
                    return err(
                        ErrorCode::BadLiteral,
                        "a double quote inside a string must be written twice",
                    );
                }
            },
            '\\' => match chars.next() {
                Some('\\') => '\\',
                Some(h1) => {
                    let h2 = chars.next();
                    match (h1.to_digit(16), h2.and_then(|h| h.to_digit(16))) {
                        (Some(a), Some(b)) => char::from((a * 16 + b) as u8),
                        _ => {
                            return err(
                                ErrorCode::BadLiteral,
                                "a backslash in a string must be followed by a backslash or two hex digits",
                            );
                        }
                    }
                }
                None => {
                    return err(
                        ErrorCode::BadLiteral,
                        "a backslash in a string must be followed by a backslash or two hex digits",
                    );
                }
            },
            c if (c as u32) > 0xff => {
                return err(
                    ErrorCode::BadLiteral,
                    format!("character '{c}' is not in ISO 8859-1"),
                );
            }
            c => c,
        };
        count += 1;
        if count > MAX_STRING_LEN {
            return err(
                ErrorCode::StrTooLong,
                format!("string literal longer than {MAX_STRING_LEN} characters"),
            );
        }
        out.push(decoded);
    }
    Ok(out)
}

/// Decodes a RAPID numeric literal (without sign): decimal `3`, `1.`, `.5`,
/// `2.5E-2`, hexadecimal `0xFF`, octal `0o17`, binary `0b101`.
///
/// ```
/// assert_eq!(rapid_evaluator::parse_num_literal("2E3").unwrap(), 2000.0);
/// assert_eq!(rapid_evaluator::parse_num_literal("0xFF").unwrap(), 255.0);
/// ```
pub fn parse_num_literal(src: &str) -> Result<f64, EvalError> {
    let s = src.trim();
    let bad = || {
        EvalError::new(
            ErrorCode::BadLiteral,
            format!("`{src}` is not a numeric literal"),
        )
    };
    let radix = match s.get(..2) {
        Some("0x" | "0X") => Some(16),
        Some("0o" | "0O") => Some(8),
        Some("0b" | "0B") => Some(2),
        _ => None,
    };
    if let Some(radix) = radix {
        let digits = s.get(2..).unwrap_or("");
        if digits.is_empty() || digits.len() > 64 {
            return Err(bad());
        }
        return u64::from_str_radix(digits, radix)
            .map(|v| v as f64)
            .map_err(|_| bad());
    }
    // decimal: digits [. [digits]] [E [+|-] digits]  or  . digits [E ...]
    let bytes = s.as_bytes();
    let mut i = 0;
    let int_start = i;
    while i < bytes.len() && bytes[i].is_ascii_digit() {
        i += 1;
    }
    let int_digits = i - int_start;
    let mut frac_digits = 0;
    if i < bytes.len() && bytes[i] == b'.' {
        i += 1;
        let f = i;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            i += 1;
        }
        frac_digits = i - f;
    }
    if int_digits + frac_digits == 0 {
        return Err(bad());
    }
    if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
        i += 1;
        if i < bytes.len() && (bytes[i] == b'+' || bytes[i] == b'-') {
            i += 1;
        }
        let e = i;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            i += 1;
        }
        if i == e {
            return Err(bad());
        }
    }
    if i != bytes.len() {
        return Err(bad());
    }
    // Rust's parser accepts "1." and ".5" and exponents; normalise "1.E3"
    // (only when it is there: this runs for every number of every table).
    if !s.contains(".e") && !s.contains(".E") {
        return s.parse::<f64>().map_err(|_| bad());
    }
    let text = s.replace(".e", ".0e").replace(".E", ".0E");
    text.parse::<f64>().map_err(|_| bad())
}
