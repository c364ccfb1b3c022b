//! The bit functions on `byte` values.

use super::Args;
use crate::error::{ErrorCode, EvalError, err};
use crate::value::{Value, format_g};

type R = Result<Value, EvalError>;

fn two(a: &Args<'_>, f: fn(u8, u8) -> u8) -> R {
    let x = byte_arg(a, "BitData1")?;
    let y = byte_arg(a, "BitData2")?;
    Ok(Value::Num(f32::from(f(x, y))))
}

pub(super) fn bit_and(a: &Args<'_>) -> R {
    two(a, |x, y| x & y)
}

pub(super) fn bit_or(a: &Args<'_>) -> R {
    two(a, |x, y| x | y)
}

pub(super) fn bit_xor(a: &Args<'_>) -> R {
    two(a, |x, y| x ^ y)
}

pub(super) fn bit_neg(a: &Args<'_>) -> R {
    Ok(Value::Num(f32::from(!byte_arg(a, "BitData1")?)))
}

fn shift(a: &Args<'_>, left: bool) -> R {
    let x = byte_arg(a, "BitData")?;
    let n = a.num("ShiftSteps")?;
    if n.fract() != 0.0 || !(0.0..=8.0).contains(&n) {
        return err(
            ErrorCode::ArgValErr,
            format!("{}: ShiftSteps must be a whole number from 0 to 8", a.func),
        );
    }
    let v = u32::from(x);
    let r = if left { v << n as u32 } else { v >> n as u32 };
    Ok(Value::Num((r & 0xff) as f32))
}

pub(super) fn bit_lsh(a: &Args<'_>) -> R {
    shift(a, true)
}

pub(super) fn bit_rsh(a: &Args<'_>) -> R {
    shift(a, false)
}

pub(super) fn bit_check(a: &Args<'_>) -> R {
    let x = byte_arg(a, "BitData")?;
    let p = a.num("BitPos")?;
    if p.fract() != 0.0 || !(1.0..=8.0).contains(&p) {
        return err(
            ErrorCode::ArgValErr,
            "BitCheck: BitPos must be a whole number from 1 to 8",
        );
    }
    Ok(Value::Bool(x & (1 << (p as u32 - 1)) != 0))
}

/// A `byte` argument: a whole number from 0 to 255.
pub(super) fn byte_arg(a: &Args<'_>, name: &str) -> Result<u8, EvalError> {
    let b = a.num(name)?;
    if b.fract() != 0.0 || !(0.0..=255.0).contains(&b) {
        return err(
            ErrorCode::ArgValErr,
            format!("{}: {} is not a byte (0 to 255)", a.func, format_g(b, 6)),
        );
    }
    Ok(b as u8)
}
