//! The dnum forms of the arithmetic and bit functions (`PowDnum`,
//! `SinDnum`, `BitAndDnum`, `BitCheckDnum`...): double precision, angles
//! in degrees, the bit functions on whole numbers from 0 to 4294967295;
//! `Max`/`Min`, on nums or dnums; and `CrossProd`. Their parameters are
//! those loaded code calls them with (the catalogue's `params_unchecked`),
//! so the runtime, not the pure evaluator, has them.

use rapid_evaluator::Value;

use super::{Args, Cx};
use crate::machine::{R, fault, named_error};

fn arg_error<T>(cx: &Cx<'_>, a: &Args, why: String) -> R<T> {
    fault(named_error(
        &cx.m.prog,
        "ERR_ARGVALERR",
        format!("{}: {why}", a.name),
    ))
}

/// A whole number of 32 bits.
fn bits(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<u32> {
    let x = cx.num(a, param)?;
    if x.fract() != 0.0 || !(0.0..=f64::from(u32::MAX)).contains(&x) {
        return arg_error(
            cx,
            a,
            format!(
                "{param} {} is not a whole number from 0 to 4294967295",
                crate::world::num_text(x)
            ),
        );
    }
    Ok(x as u32)
}

/// A bit position or a shift, 1 to 32.
fn position(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<u32> {
    let x = cx.num(a, param)?;
    if x.fract() != 0.0 || !(1.0..=32.0).contains(&x) {
        return arg_error(
            cx,
            a,
            format!(
                "{param} {} is not a whole number from 1 to 32",
                crate::world::num_text(x)
            ),
        );
    }
    Ok(x as u32)
}

fn dnum(x: f64) -> R<Value> {
    Ok(Value::Dnum(x))
}

/// `PowDnum(Base, Exponent)`.
pub(crate) fn pow(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let base = cx.num(a, "Base")?;
    let exponent = cx.num(a, "Exponent")?;
    let x = base.powf(exponent);
    if !x.is_finite() {
        return arg_error(
            cx,
            a,
            format!("{base} to the power {exponent} is not a number"),
        );
    }
    dnum(x)
}

/// `SinDnum`, `CosDnum`, `TanDnum` (`Angle` in degrees).
pub(crate) fn trig(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let angle = cx.num(a, "Angle")?.to_radians();
    match a.name {
        "SinDnum" => dnum(angle.sin()),
        "CosDnum" => dnum(angle.cos()),
        _ => dnum(angle.tan()),
    }
}

/// `ASinDnum`, `ACosDnum` (`Value` from -1 to 1), `ATanDnum`: degrees.
pub(crate) fn inverse_trig(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let v = cx.num(a, "Value")?;
    if a.name != "ATanDnum" && !(-1.0..=1.0).contains(&v) {
        return arg_error(
            cx,
            a,
            format!("{} is outside -1 to 1", crate::world::num_text(v)),
        );
    }
    let r = match a.name {
        "ASinDnum" => v.asin(),
        "ACosDnum" => v.acos(),
        _ => v.atan(),
    };
    dnum(r.to_degrees())
}

/// `ATan2Dnum(Y, X)`: degrees.
pub(crate) fn atan2(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let y = cx.num(a, "Y")?;
    let x = cx.num(a, "X")?;
    dnum(y.atan2(x).to_degrees())
}

/// `BitAndDnum`, `BitOrDnum`, `BitXOrDnum`.
pub(crate) fn two(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let x = bits(cx, a, "Value1")?;
    let y = bits(cx, a, "Value2")?;
    let r = match a.name {
        "BitAndDnum" => x & y,
        "BitOrDnum" => x | y,
        _ => x ^ y,
    };
    dnum(f64::from(r))
}

/// `BitNegDnum(Value)`.
pub(crate) fn neg(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let x = bits(cx, a, "Value")?;
    dnum(f64::from(!x))
}

/// `BitLShDnum`, `BitRShDnum` (`ShiftSteps` 1 to 32; bits shifted out are
/// lost).
pub(crate) fn shift(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let x = u64::from(bits(cx, a, "Value")?);
    let n = position(cx, a, "ShiftSteps")?;
    let r = if a.name == "BitLShDnum" {
        (x << n) & u64::from(u32::MAX)
    } else {
        x >> n
    };
    dnum(r as f64)
}

/// `BitCheckDnum(Value, BitPos)`: bit 1 is the lowest.
pub(crate) fn check(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let x = bits(cx, a, "Value")?;
    let n = position(cx, a, "BitPos")?;
    Ok(Value::Bool(x >> (n - 1) & 1 == 1))
}

/// `Max(Value1, Value2)`, `Min(Value1, Value2)`: a num, or a dnum when
/// either argument is one.
pub(crate) fn max_min(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let x = cx.req(a, "Value1")?;
    let y = cx.req(a, "Value2")?;
    let wide = matches!(x, Value::Dnum(_)) || matches!(y, Value::Dnum(_));
    let (Some(p), Some(q)) = (x.as_f64(), y.as_f64()) else {
        return crate::machine::invalid(format!("{}: the arguments must be numbers", a.name));
    };
    let r = if a.name == "Max" { p.max(q) } else { p.min(q) };
    Ok(if wide {
        Value::Dnum(r)
    } else {
        Value::Num(r as f32)
    })
}

/// `CrossProd(Vector1, Vector2)`: the cross product of two `pos` vectors,
/// a `pos` perpendicular to both (right-handed: `[1,0,0]` by `[0,1,0]` is
/// `[0,0,1]`).
pub(crate) fn cross_prod(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let mut vector = |param: &str| -> R<_> {
        let v = cx.req(a, param)?;
        rapid_evaluator::geometry::vec_of(&v).or_else(|e| cx.m.eval_error(e))
    };
    let (u, v) = (vector("Vector1")?, vector("Vector2")?);
    rapid_evaluator::geometry::pos_value(&u.cross(&v)).or_else(|e| cx.m.eval_error(e))
}
