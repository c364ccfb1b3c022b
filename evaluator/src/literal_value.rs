//! Reading literal data from text: numbers (with an optional sign),
//! strings, `TRUE`/`FALSE`, aggregates of those and, where allowed, names.

use crate::expr::{Expr, UnOp};

const MAX_NESTING: u32 = 32;

/// Parses the whole of `text` as literal data (no names), the format
/// `StrToVal` accepts; `None` if it is not.
pub(crate) fn parse(text: &str) -> Option<Expr> {
    parse_with(text, false)
}

/// Reads a data value written as RAPID literal data, such as the value of
/// predefined data in a catalogue: `[100,500,5000,1000]`, `"HOME:"`,
/// `-1`, `[inpos,TRUE,[20,20,0,20],0,0,"",0,0]`. Numbers may carry a sign;
/// names (other than `TRUE`/`FALSE`) become [`Expr::Name`]. `None` if the
/// text is anything else (operators, calls, unbalanced brackets).
///
/// ```
/// use rapid_evaluator::{EmptyEnv, Type, eval_as, parse_data_literal};
/// let e = parse_data_literal("[100, 500, 5000, 1000]").unwrap();
/// let v = eval_as(&e, Some(&Type::named("speeddata")), &EmptyEnv).unwrap();
/// assert_eq!(v.to_string(), "[100,500,5000,1000]");
/// ```
pub fn parse_data_literal(text: &str) -> Option<Expr> {
    parse_with(text, true)
}

fn parse_with(text: &str, names: bool) -> Option<Expr> {
    let mut p = Parser {
        s: text.as_bytes(),
        text,
        i: 0,
        names,
    };
    let e = p.value(0)?;
    p.ws();
    (p.i == p.s.len()).then_some(e)
}

struct Parser<'a> {
    s: &'a [u8],
    text: &'a str,
    i: usize,
    names: bool,
}

impl Parser<'_> {
    fn ws(&mut self) {
        while self.s.get(self.i).is_some_and(|c| c.is_ascii_whitespace()) {
            self.i += 1;
        }
    }

    fn value(&mut self, depth: u32) -> Option<Expr> {
        if depth > MAX_NESTING {
            return None;
        }
        self.ws();
        match *self.s.get(self.i)? {
            b'[' => {
                self.i += 1;
                let mut items = Vec::new();
                self.ws();
                if self.s.get(self.i) == Some(&b']') {
                    return None;
                }
                loop {
                    items.push(self.value(depth + 1)?);
                    self.ws();
                    match *self.s.get(self.i)? {
                        b',' => self.i += 1,
                        b']' => {
                            self.i += 1;
                            return Some(Expr::Aggregate(items));
                        }
                        _ => return None,
                    }
                }
            }
            b'"' => {
                let start = self.i;
                self.i += 1;
                loop {
                    match *self.s.get(self.i)? {
                        b'"' if self.s.get(self.i + 1) == Some(&b'"') => self.i += 2,
                        b'"' => {
                            self.i += 1;
                            break;
                        }
                        _ => self.i += 1,
                    }
                }
                Some(Expr::Str(self.text.get(start..self.i)?.to_string()))
            }
            b'-' | b'+' => {
                let neg = self.s[self.i] == b'-';
                self.i += 1;
                self.ws();
                let n = self.number()?;
                Some(if neg {
                    Expr::Unary(UnOp::Neg, Box::new(n))
                } else {
                    n
                })
            }
            c if c.is_ascii_digit() || c == b'.' => self.number(),
            c if c.is_ascii_alphabetic() => {
                let start = self.i;
                while self
                    .s
                    .get(self.i)
                    .is_some_and(|c| c.is_ascii_alphanumeric() || *c == b'_')
                {
                    self.i += 1;
                }
                let word = self.text.get(start..self.i)?;
                if word.eq_ignore_ascii_case("TRUE") {
                    Some(Expr::Bool(true))
                } else if word.eq_ignore_ascii_case("FALSE") {
                    Some(Expr::Bool(false))
                } else if self.names {
                    Some(Expr::Name(word.to_string()))
                } else {
                    None
                }
            }
            _ => None,
        }
    }

    fn number(&mut self) -> Option<Expr> {
        let start = self.i;
        while let Some(&c) = self.s.get(self.i) {
            let exp_sign = (c == b'+' || c == b'-')
                && self.i > start
                && matches!(self.s.get(self.i - 1), Some(b'e' | b'E'));
            if c.is_ascii_alphanumeric() || c == b'.' || exp_sign {
                self.i += 1;
            } else {
                break;
            }
        }
        let text = self.text.get(start..self.i)?;
        crate::literal::parse_num_literal(text).ok()?;
        Some(Expr::Num(text.to_string()))
    }
}
