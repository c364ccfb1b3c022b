//! Arithmetic, trigonometry, rounding, num and dnum conversions, `Dim`.

use super::Args;
use crate::error::{ErrorCode, EvalError, err};
use crate::eval::{check_len, dnum_result, num_result};
use crate::geometry as g;
use crate::value::{Value, format_g};

type R = Result<Value, EvalError>;

pub(super) fn abs(a: &Args<'_>) -> R {
    num_result(a.num("Input")?.abs())
}

pub(super) fn abs_dnum(a: &Args<'_>) -> R {
    dnum_result(a.num("Value")?.abs())
}

pub(super) fn sqrt_dnum(a: &Args<'_>) -> R {
    let x = a.num("Value")?;
    if x < 0.0 {
        return err(ErrorCode::ArgValErr, "SqrtDnum: the argument is negative");
    }
    dnum_result(x.sqrt())
}

pub(super) fn round_dnum(a: &Args<'_>) -> R {
    let dec = decimals(a, "Dec", a.opt_num("Dec")?.unwrap_or(0.0))?;
    dnum_result(round_dec(a.num("Val")?, dec))
}

pub(super) fn trunc_dnum(a: &Args<'_>) -> R {
    let dec = decimals(a, "Dec", a.opt_num("Dec")?.unwrap_or(0.0))?;
    dnum_result(trunc_dec(a.num("Val")?, dec))
}

pub(super) fn dnum_to_str(a: &Args<'_>) -> R {
    let dec = decimals(a, "Dec", a.num("Dec")?)?;
    let x = a.num("Val")?;
    fixed_or_exp(a, x, dec)
}

pub(super) fn num_to_str(a: &Args<'_>) -> R {
    let dec = decimals(a, "Dec", a.num("Dec")?)?;
    let x = decimal_of(a.val("Val")?);
    fixed_or_exp(a, x, dec)
}

fn fixed_or_exp(a: &Args<'_>, x: f64, dec: i32) -> R {
    let s = if a.sw("Exp") {
        exp_format(x, dec)
    } else {
        format!("{:.*}", dec as usize, round_dec(x, dec))
    };
    check_len(s)
}

fn inverse_trig(a: &Args<'_>, f: fn(f64) -> f64) -> R {
    let x = a.num("Value")?;
    if !(-1.0..=1.0).contains(&x) {
        return err(
            ErrorCode::ArgValErr,
            format!(
                "{}: the argument {} is outside [-1, 1]",
                a.func,
                format_g(x, 6)
            ),
        );
    }
    num_result(f(x).to_degrees())
}

pub(super) fn acos(a: &Args<'_>) -> R {
    inverse_trig(a, f64::acos)
}

pub(super) fn asin(a: &Args<'_>) -> R {
    inverse_trig(a, f64::asin)
}

pub(super) fn atan(a: &Args<'_>) -> R {
    num_result(a.num("Value")?.atan().to_degrees())
}

pub(super) fn atan2(a: &Args<'_>) -> R {
    num_result(a.num("Y")?.atan2(a.num("X")?).to_degrees())
}

pub(super) fn sin(a: &Args<'_>) -> R {
    num_result(g::sin_deg(a.num("Angle")?))
}

pub(super) fn cos(a: &Args<'_>) -> R {
    num_result(g::cos_deg(a.num("Angle")?))
}

pub(super) fn tan(a: &Args<'_>) -> R {
    let x = a.num("Angle")?;
    let c = g::cos_deg(x);
    if c == 0.0 {
        return err(
            ErrorCode::NumLimit,
            "Tan: the tangent of this angle is infinite",
        );
    }
    num_result(g::sin_deg(x) / c)
}

pub(super) fn exp(a: &Args<'_>) -> R {
    num_result(a.num("Exponent")?.exp())
}

pub(super) fn pow(a: &Args<'_>) -> R {
    let (x, y) = (a.num("Base")?, a.num("Exponent")?);
    if x < 0.0 && y.fract() != 0.0 {
        return err(
            ErrorCode::ArgValErr,
            "Pow: a negative base needs an integer exponent",
        );
    }
    if x == 0.0 && y < 0.0 {
        return err(
            ErrorCode::ArgValErr,
            "Pow: zero cannot have a negative exponent",
        );
    }
    num_result(x.powf(y))
}

pub(super) fn sqrt(a: &Args<'_>) -> R {
    let x = a.num("Value")?;
    if x < 0.0 {
        return err(ErrorCode::ArgValErr, "Sqrt: the argument is negative");
    }
    num_result(x.sqrt())
}

pub(super) fn round(a: &Args<'_>) -> R {
    let dec = decimals(a, "Dec", a.opt_num("Dec")?.unwrap_or(0.0))?;
    num_result(round_dec(decimal_of(a.val("Val")?), dec))
}

pub(super) fn trunc(a: &Args<'_>) -> R {
    let dec = decimals(a, "Dec", a.opt_num("Dec")?.unwrap_or(0.0))?;
    num_result(trunc_dec(decimal_of(a.val("Val")?), dec))
}

pub(super) fn num_to_dnum(a: &Args<'_>) -> R {
    dnum_result(a.num("Value")?)
}

pub(super) fn dnum_to_num(a: &Args<'_>) -> R {
    let x = a.num("Value")?;
    if a.sw("Integer") && (x.fract() != 0.0 || x.abs() > crate::eval::NUM_INT_MAX) {
        return err(
            ErrorCode::ArgValErr,
            "DnumToNum: the value is not an integer that num holds exactly",
        );
    }
    num_result(x)
}

pub(super) fn dim(a: &Args<'_>) -> R {
    let d = a.num("DimNo")?;
    let mut v = a.val("ArrPar")?;
    if !matches!(v, Value::Array(_)) {
        return err(ErrorCode::TypeMismatch, "Dim: the argument is not an array");
    }
    if d.fract() != 0.0 || d < 1.0 {
        return err(ErrorCode::IllDim, "Dim: the dimension must be 1, 2 or 3");
    }
    let no_such = || {
        err(
            ErrorCode::IllDim,
            format!("Dim: the array has no dimension {}", format_g(d, 6)),
        )
    };
    let mut k = 1.0;
    loop {
        let Value::Array(items) = v else {
            return no_such();
        };
        if k == d {
            return Ok(Value::Num(items.len() as f32));
        }
        match items.first() {
            Some(first) => v = first,
            None => return no_such(),
        }
        k += 1.0;
    }
}

/// A number-of-decimals argument: an integer from 0 to 15.
fn decimals(a: &Args<'_>, name: &str, d: f64) -> Result<i32, EvalError> {
    if d.fract() != 0.0 || !(0.0..=15.0).contains(&d) {
        return err(
            ErrorCode::ArgValErr,
            format!(
                "{}: {name} must be a whole number of decimals from 0 to 15, not {}",
                a.func,
                format_g(d, 6)
            ),
        );
    }
    Ok(d as i32)
}

/// The decimal number a value stands for: a num is taken as the shortest
/// decimal that reads back as the same single-precision value (0.7, not
/// 0.699999988), so rounding and truncation act on the digits the user
/// wrote.
fn decimal_of(v: &Value) -> f64 {
    match v {
        Value::Num(x) => x.to_string().parse().unwrap_or(f64::from(*x)),
        Value::Dnum(x) => *x,
        _ => 0.0,
    }
}

/// Rounds half away from zero to `dec` decimals.
fn round_dec(x: f64, dec: i32) -> f64 {
    let m = 10f64.powi(dec);
    let y = x * m;
    // A half written in decimal may be stored just below it (2.675 is
    // 2.67499999999999982236431605997495353221893310546875 in binary): it
    // rounds up, as the decimal says. Only a few units in the last place
    // count as such a half; a relative nudge of its own would move large
    // values by whole units (16777216e6 printed as 16777216000017).
    // (Past about 1e14 a unit in the last place is a sizeable part of one:
    // no nudge there.)
    let half = y.abs().fract();
    let tolerance = 8.0 * f64::EPSILON * y.abs();
    let r = if tolerance < 0.25 && (half - 0.5).abs() <= tolerance {
        (y.abs().trunc() + 1.0).copysign(y)
    } else {
        y.round()
    };
    r / m
}

/// Truncates towards zero to `dec` decimals.
fn trunc_dec(x: f64, dec: i32) -> f64 {
    let m = 10f64.powi(dec);
    let y = x * m;
    let r = y.round();
    if (y - r).abs() <= 1e-9 * r.abs().max(1.0) {
        r / m
    } else {
        y.trunc() / m
    }
}

/// `d.ddE+xx` with `dec` decimals.
fn exp_format(x: f64, dec: i32) -> String {
    let s = format!("{:.*E}", dec as usize, x);
    match s.split_once('E') {
        Some((m, e)) => {
            let e: i32 = e.parse().unwrap_or(0);
            let sign = if e < 0 { '-' } else { '+' };
            format!("{m}E{sign}{:02}", e.abs())
        }
        None => s,
    }
}
