//! String functions: searching, mapping, parts, conversions to and from
//! text, digit strings.

use super::Args;
use super::bits::byte_arg;
use crate::env::{Env, Lookup};
use crate::error::{ErrorCode, EvalError, err};
use crate::eval::{Ctx, check_len};
use crate::expr::{Expr, Type};
use crate::value::{Value, format_g};

type R = Result<Value, EvalError>;

/// The characters of `Str` and the checked position `ChPos`, counting the
/// scan as work.
fn scan(a: &Args<'_>, ctx: &mut Ctx) -> Result<(Vec<char>, usize), EvalError> {
    let s: Vec<char> = a.str("Str")?.chars().collect();
    let pos = char_pos(a, s.len())?;
    ctx.step(s.len() as u64)?;
    Ok((s, pos))
}

pub(super) fn str_find(a: &Args<'_>, ctx: &mut Ctx, _: &dyn Env) -> R {
    let (s, pos) = scan(a, ctx)?;
    let set = a.str("Set")?;
    let not = a.sw("NotInSet");
    let found = s
        .iter()
        .enumerate()
        .skip(pos - 1)
        .find(|(_, c)| set.contains(**c) != not)
        .map_or(s.len() + 1, |(i, _)| i + 1);
    Ok(Value::Num(found as f32))
}

pub(super) fn str_match(a: &Args<'_>, ctx: &mut Ctx, _: &dyn Env) -> R {
    let (s, pos) = scan(a, ctx)?;
    let pat: Vec<char> = a.str("Pattern")?.chars().collect();
    let found = (pos - 1..=s.len())
        .find(|&i| s.get(i..i + pat.len()) == Some(&pat[..]))
        .map_or(s.len() + 1, |i| i + 1);
    Ok(Value::Num(found as f32))
}

pub(super) fn str_memb(a: &Args<'_>, ctx: &mut Ctx, _: &dyn Env) -> R {
    let (s, pos) = scan(a, ctx)?;
    let set = a.str("Set")?;
    Ok(Value::Bool(
        s.get(pos - 1).is_some_and(|c| set.contains(*c)),
    ))
}

pub(super) fn str_len(a: &Args<'_>) -> R {
    Ok(Value::Num(a.str("Str")?.chars().count() as f32))
}

pub(super) fn str_map(a: &Args<'_>) -> R {
    let from: Vec<char> = a.str("FromMap")?.chars().collect();
    let to: Vec<char> = a.str("ToMap")?.chars().collect();
    let out: String = a
        .str("Str")?
        .chars()
        .map(|c| {
            from.iter()
                .position(|f| *f == c)
                .and_then(|i| to.get(i).copied())
                .unwrap_or(c)
        })
        .collect();
    check_len(out)
}

pub(super) fn str_order(a: &Args<'_>) -> R {
    let order: Vec<char> = a.str("Order")?.chars().collect();
    let rank = |c: char| {
        order
            .iter()
            .position(|o| *o == c)
            .map_or(order.len() as u32 + c as u32, |i| i as u32)
    };
    let s1: Vec<u32> = a.str("Str1")?.chars().map(rank).collect();
    let s2: Vec<u32> = a.str("Str2")?.chars().map(rank).collect();
    Ok(Value::Bool(s1 <= s2))
}

pub(super) fn str_part(a: &Args<'_>) -> R {
    let s: Vec<char> = a.str("Str")?.chars().collect();
    let pos = char_pos(a, s.len())?;
    let len = a.num("Len")?;
    if len.fract() != 0.0 {
        return err(
            ErrorCode::NotIntVal,
            "StrPart: the length must be an integer",
        );
    }
    if len < 0.0 || (pos - 1) as f64 + len > s.len() as f64 {
        return err(
            ErrorCode::OutOfBnd,
            format!(
                "StrPart: {} characters from position {pos} go past the end of the string ({} characters)",
                format_g(len, 6),
                s.len()
            ),
        );
    }
    Ok(Value::Str(
        s[pos - 1..pos - 1 + len as usize].iter().collect(),
    ))
}

pub(super) fn byte_to_str(a: &Args<'_>) -> R {
    let b = byte_arg(a, "BitData")?;
    Ok(Value::Str(if a.sw("Hex") {
        format!("{b:02X}")
    } else if a.sw("Okt") {
        format!("{b:03o}")
    } else if a.sw("Bin") {
        format!("{b:08b}")
    } else if a.sw("Char") {
        if b < 0x20 || (0x7f..0xa0).contains(&b) {
            format!("\\{b:02X}")
        } else {
            char::from(b).to_string()
        }
    } else {
        b.to_string()
    }))
}

pub(super) fn str_to_byte(a: &Args<'_>) -> R {
    let s = a.str("ConStr")?;
    let parsed = if a.sw("Hex") {
        digits(s, 16, 2)
    } else if a.sw("Okt") {
        digits(s, 8, 3)
    } else if a.sw("Bin") {
        digits(s, 2, 8)
    } else if a.sw("Char") {
        let cs: Vec<char> = s.chars().collect();
        match cs.as_slice() {
            [c] => Some(*c as u32),
            ['\\', h1, h2] => match (h1.to_digit(16), h2.to_digit(16)) {
                (Some(x), Some(y)) => Some(x * 16 + y),
                _ => None,
            },
            _ => None,
        }
    } else {
        digits(s, 10, 3)
    };
    match parsed {
        Some(v) if v <= 255 => Ok(Value::Num(v as f32)),
        _ => err(
            ErrorCode::ArgValErr,
            format!(
                "StrToByte: {} is not a valid byte in this format",
                crate::value::quote_string(s)
            ),
        ),
    }
}

pub(super) fn val_to_str(a: &Args<'_>) -> R {
    check_len(a.val("Val")?.to_string())
}

pub(super) fn dec_to_hex(a: &Args<'_>) -> R {
    let s = a.str("Str")?;
    match digits(s, 10, 20).map(u64::from).or_else(|| dec_u64(s)) {
        Some(v) => Ok(Value::Str(format!("{v:X}"))),
        None => err(
            ErrorCode::ArgValErr,
            "DecToHex: the string must hold only decimal digits",
        ),
    }
}

pub(super) fn hex_to_dec(a: &Args<'_>) -> R {
    let s = a.str("Str")?;
    let ok = !s.is_empty() && s.len() <= 16 && s.chars().all(|c| c.is_ascii_hexdigit());
    match u64::from_str_radix(s, 16) {
        Ok(v) if ok => Ok(Value::Str(v.to_string())),
        _ => err(
            ErrorCode::ArgValErr,
            "HexToDec: the string must hold only hexadecimal digits",
        ),
    }
}

pub(super) fn str_dig_calc(a: &Args<'_>) -> R {
    let n1 = dig_value(a.func, a.str("StrDig1")?)?;
    let n2 = dig_value(a.func, a.str("StrDig2")?)?;
    let op = a.num("Operation")?;
    let op = if op.fract() == 0.0 { op as i64 } else { 0 };
    let r = match op {
        1 => n1.checked_add(n2),
        2 => n1.checked_sub(n2),
        3 => n1.checked_mul(n2),
        4 | 5 if n2 == 0 => {
            return err(ErrorCode::DivZero, "StrDigCalc: division by zero");
        }
        4 => Some(n1 / n2),
        5 => Some(n1 % n2),
        _ => {
            return err(
                ErrorCode::ArgValErr,
                "StrDigCalc: the operation must be OpAdd, OpSub, OpMult, OpDiv or OpMod",
            );
        }
    };
    match r {
        Some(v) if v <= 4_294_967_295 => Ok(Value::Str(v.to_string())),
        _ => err(
            ErrorCode::MaxIntVal,
            "StrDigCalc: the result is outside 0 to 4294967295",
        ),
    }
}

pub(super) fn str_dig_cmp(a: &Args<'_>) -> R {
    let n1 = dig_value(a.func, a.str("StrDig1")?)?;
    let n2 = dig_value(a.func, a.str("StrDig2")?)?;
    let rel = a.num("Relation")?;
    let rel = if rel.fract() == 0.0 { rel as i64 } else { 0 };
    Ok(Value::Bool(match rel {
        1 => n1 < n2,
        2 => n1 <= n2,
        3 => n1 == n2,
        4 => n1 != n2,
        5 => n1 >= n2,
        6 => n1 > n2,
        _ => {
            return err(
                ErrorCode::ArgValErr,
                "StrDigCmp: the relation must be LT, LTEQ, EQ, NOTEQ, GTEQ or GT",
            );
        }
    }))
}

pub(super) fn str_to_val(a: &Args<'_>, ctx: &mut Ctx, env: &dyn Env) -> R {
    let text = a.str("Str")?.to_string();
    let ty = match a.reference("Val") {
        Some(Expr::Name(n)) => match env.lookup(n) {
            Lookup::Constant { ty, .. } | Lookup::Variable { ty, .. } => ty,
            Lookup::Known { value } => match value.type_name() {
                Some(t) => Type::named(t),
                None => {
                    return err(
                        ErrorCode::Unsupported,
                        "StrToVal: the type of the target is not known",
                    );
                }
            },
            Lookup::Unknown => {
                return err(ErrorCode::UnknownName, format!("`{n}` is not known"));
            }
        },
        _ => {
            return err(
                ErrorCode::Unsupported,
                "StrToVal: the target must be a data object name",
            );
        }
    };
    let Some(expr) = crate::literal_value::parse(&text) else {
        return Ok(Value::Bool(false));
    };
    match ctx.eval(&expr, Some(&ty), env) {
        Ok(_) => Ok(Value::Bool(true)),
        Err(e) if matches!(e.code, ErrorCode::TooComplex | ErrorCode::TooDeep) => Err(e),
        Err(_) => Ok(Value::Bool(false)),
    }
}

fn dec_u64(s: &str) -> Option<u64> {
    if s.is_empty() || !s.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

/// A `stringdig` argument: decimal digits only, at most 4294967295.
fn dig_value(func: &str, s: &str) -> Result<u64, EvalError> {
    if s.is_empty() || !s.chars().all(|c| c.is_ascii_digit()) {
        return err(
            ErrorCode::NotIntVal,
            format!("{func}: the strings must hold only decimal digits"),
        );
    }
    let significant = s.trim_start_matches('0');
    match significant.parse::<u64>() {
        Ok(v) if significant.len() <= 10 && v <= 4_294_967_295 => Ok(v),
        _ if significant.is_empty() => Ok(0),
        _ => err(
            ErrorCode::MaxIntVal,
            format!("{func}: the value is larger than 4294967295"),
        ),
    }
}

/// Parses 1..=`max_len` digits of `radix`.
fn digits(s: &str, radix: u32, max_len: usize) -> Option<u32> {
    if s.is_empty() || s.chars().count() > max_len || !s.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    u32::from_str_radix(s, radix).ok()
}

/// A 1-based character position argument `ChPos`, checked against the
/// string length.
fn char_pos(a: &Args<'_>, len: usize) -> Result<usize, EvalError> {
    let p = a.num("ChPos")?;
    if p.fract() != 0.0 {
        return err(
            ErrorCode::NotIntVal,
            format!("{}: the position must be an integer", a.func),
        );
    }
    if p < 1.0 || p > len as f64 {
        return err(
            ErrorCode::OutOfBnd,
            format!(
                "{}: position {} is outside the string (1 to {len})",
                a.func,
                format_g(p, 6)
            ),
        );
    }
    Ok(p as usize)
}
