//! The operators on values: what each computes. Which operand types an
//! operator takes is the catalogue's operator table
//! (`rapid_catalogue::operators`), shared with the checker.

use rapid_catalogue::operators;

use crate::error::{ErrorCode, EvalError, err};
use crate::eval::{DNUM_INT_MAX, NUM_INT_MAX, check_len, describe, dnum_result, num_result};
use crate::expr::{BinOp, UnOp};
use crate::value::Value;

pub(crate) fn unary(op: UnOp, v: Value) -> Result<Value, EvalError> {
    match (op, v) {
        (UnOp::Neg, Value::Num(x)) => Ok(Value::Num(-x)),
        (UnOp::Neg, Value::Dnum(x)) => Ok(Value::Dnum(-x)),
        (UnOp::Plus, v @ (Value::Num(_) | Value::Dnum(_))) => Ok(v),
        (UnOp::Neg, v) if is_record(&v, "pos") => map_pos(&v, |x| -x),
        (UnOp::Plus, v) if is_record(&v, "pos") => Ok(v),
        (UnOp::Not, Value::Bool(b)) => Ok(Value::Bool(!b)),
        (op, v) => err(
            ErrorCode::TypeMismatch,
            format!(
                "the operator {} cannot be applied to {}",
                match op {
                    UnOp::Neg => "-",
                    UnOp::Plus => "+",
                    UnOp::Not => "NOT",
                },
                describe(&v)
            ),
        ),
    }
}

pub(crate) fn is_record(v: &Value, name: &str) -> bool {
    matches!(v, Value::Record { ty, .. } if ty.eq_ignore_ascii_case(name))
}

fn map_pos(v: &Value, f: impl Fn(f32) -> f32) -> Result<Value, EvalError> {
    let p = pos_of(v)?;
    Ok(Value::pos(f(p[0]), f(p[1]), f(p[2])))
}

/// The x, y, z of a pos value.
pub(crate) fn pos_of(v: &Value) -> Result<[f32; 3], EvalError> {
    let get = |n: &str| match v.field(n) {
        Some(Value::Num(x)) => Ok(*x),
        _ => err(
            ErrorCode::TypeMismatch,
            format!("expected pos, found {}", describe(v)),
        ),
    };
    Ok([get("x")?, get("y")?, get("z")?])
}

/// The q1..q4 of an orient value.
pub(crate) fn orient_of(v: &Value) -> Result<[f32; 4], EvalError> {
    let get = |n: &str| match v.field(n) {
        Some(Value::Num(x)) => Ok(*x),
        _ => err(
            ErrorCode::TypeMismatch,
            format!("expected orient, found {}", describe(v)),
        ),
    };
    Ok([get("q1")?, get("q2")?, get("q3")?, get("q4")?])
}

fn int_operand(x: f64, limit: f64) -> Result<f64, EvalError> {
    if x.fract() != 0.0 {
        return err(ErrorCode::NotIntVal, "DIV and MOD need integer operands");
    }
    if x.abs() > limit {
        return err(
            ErrorCode::MaxIntVal,
            "the operand is too large for an integer operation",
        );
    }
    Ok(x)
}

pub(crate) fn values_equal(a: &Value, b: &Value) -> Result<bool, EvalError> {
    match (a, b) {
        (Value::Num(_) | Value::Dnum(_), Value::Num(_) | Value::Dnum(_)) => {
            Ok(a.as_f64() == b.as_f64())
        }
        (Value::Bool(x), Value::Bool(y)) => Ok(x == y),
        (Value::Str(x), Value::Str(y)) => Ok(x == y),
        (Value::Record { ty: t1, fields: f1 }, Value::Record { ty: t2, fields: f2 }) => {
            if !t1.eq_ignore_ascii_case(t2) || f1.len() != f2.len() {
                return err(
                    ErrorCode::TypeMismatch,
                    format!("cannot compare {t1} with {t2}"),
                );
            }
            for ((_, x), (_, y)) in f1.iter().zip(f2) {
                if !values_equal(x, y)? {
                    return Ok(false);
                }
            }
            Ok(true)
        }
        (Value::Array(x), Value::Array(y)) => {
            if x.len() != y.len() {
                return err(
                    ErrorCode::TypeMismatch,
                    "cannot compare aggregates of different sizes",
                );
            }
            for (x, y) in x.iter().zip(y) {
                if !values_equal(x, y)? {
                    return Ok(false);
                }
            }
            Ok(true)
        }
        _ => err(
            ErrorCode::TypeMismatch,
            format!("cannot compare {} with {}", describe(a), describe(b)),
        ),
    }
}

pub(crate) fn binary(op: BinOp, a: Value, b: Value) -> Result<Value, EvalError> {
    use Value::{Bool, Dnum, Num, Str};
    let mismatch = |a: &Value, b: &Value| {
        err(
            ErrorCode::TypeMismatch,
            format!(
                "the operator {} cannot be applied to {} and {}",
                op.as_str(),
                describe(a),
                describe(b)
            ),
        )
    };
    let is_num = |v: &Value| matches!(v, Num(_) | Dnum(_));
    let any_dnum = matches!(a, Dnum(_)) || matches!(b, Dnum(_));
    // The shared operator table says which operands an operator takes
    // (equality compares any two values of one type: `values_equal`).
    if !op.is_equality() {
        let known = match (&a, &b) {
            (Num(_) | Dnum(_), Num(_) | Dnum(_)) => {
                operators::numeric(op, matches!(a, Dnum(_)), matches!(b, Dnum(_)))
            }
            _ => match (a.type_name(), b.type_name()) {
                (Some(x), Some(y)) => operators::binary(op, x, y).is_some(),
                _ => false,
            },
        };
        if !known {
            return mismatch(&a, &b);
        }
    }
    match op {
        BinOp::Eq => return Ok(Bool(values_equal(&a, &b)?)),
        BinOp::Ne => return Ok(Bool(!values_equal(&a, &b)?)),
        BinOp::And | BinOp::Or | BinOp::Xor => {
            return match (&a, &b) {
                (Bool(x), Bool(y)) => Ok(Bool(match op {
                    BinOp::And => *x && *y,
                    BinOp::Or => *x || *y,
                    _ => x ^ y,
                })),
                _ => mismatch(&a, &b),
            };
        }
        _ => {}
    }
    if is_num(&a) && is_num(&b) {
        let x = a.as_f64().unwrap_or(0.0);
        let y = b.as_f64().unwrap_or(0.0);
        let wrap = |r: f64| {
            if any_dnum {
                dnum_result(r)
            } else {
                num_result(r)
            }
        };
        return match op {
            BinOp::Add => wrap(x + y),
            BinOp::Sub => wrap(x - y),
            BinOp::Mul => wrap(x * y),
            BinOp::Div => {
                if y == 0.0 {
                    err(ErrorCode::DivZero, "division by zero")
                } else {
                    wrap(x / y)
                }
            }
            BinOp::IntDiv | BinOp::Mod => {
                let limit = if any_dnum { DNUM_INT_MAX } else { NUM_INT_MAX };
                let x = int_operand(x, limit)?;
                let y = int_operand(y, limit)?;
                if y == 0.0 {
                    return err(ErrorCode::DivZero, "division by zero");
                }
                let q = (x / y).trunc();
                wrap(if op == BinOp::IntDiv { q } else { x - q * y })
            }
            BinOp::Lt => Ok(Bool(x < y)),
            BinOp::Le => Ok(Bool(x <= y)),
            BinOp::Gt => Ok(Bool(x > y)),
            BinOp::Ge => Ok(Bool(x >= y)),
            _ => mismatch(&a, &b),
        };
    }
    match (op, &a, &b) {
        (BinOp::Add, Str(x), Str(y)) => {
            let mut s = String::with_capacity(x.len() + y.len());
            s.push_str(x);
            s.push_str(y);
            check_len(s)
        }
        (BinOp::Add | BinOp::Sub, _, _) if is_record(&a, "pos") && is_record(&b, "pos") => {
            let p = pos_of(&a)?;
            let q = pos_of(&b)?;
            let f = |i: usize| {
                let (x, y) = (f64::from(p[i]), f64::from(q[i]));
                num_result(if op == BinOp::Add { x + y } else { x - y })
            };
            pos_value([f(0)?, f(1)?, f(2)?])
        }
        (BinOp::Mul, _, _) if is_record(&a, "pos") && is_num(&b) => {
            scale_pos(&a, b.as_f64().unwrap_or(0.0))
        }
        (BinOp::Mul, _, _) if is_num(&a) && is_record(&b, "pos") => {
            scale_pos(&b, a.as_f64().unwrap_or(0.0))
        }
        (BinOp::Mul, _, _) if is_record(&a, "pos") && is_record(&b, "pos") => {
            let p = pos_of(&a)?.map(f64::from);
            let q = pos_of(&b)?.map(f64::from);
            pos_value([
                num_result(p[1] * q[2] - p[2] * q[1])?,
                num_result(p[2] * q[0] - p[0] * q[2])?,
                num_result(p[0] * q[1] - p[1] * q[0])?,
            ])
        }
        (BinOp::Div, _, _) if is_record(&a, "pos") && is_num(&b) => {
            let k = b.as_f64().unwrap_or(0.0);
            if k == 0.0 {
                return err(ErrorCode::DivZero, "division by zero");
            }
            let p = pos_of(&a)?.map(f64::from);
            pos_value([
                num_result(p[0] / k)?,
                num_result(p[1] / k)?,
                num_result(p[2] / k)?,
            ])
        }
        (BinOp::Mul, _, _) if is_record(&a, "orient") && is_record(&b, "orient") => {
            let p = crate::geometry::unit_quat(orient_of(&a)?)?;
            let q = crate::geometry::unit_quat(orient_of(&b)?)?;
            crate::geometry::orient_value(&(p * q), false)
        }
        _ => mismatch(&a, &b),
    }
}

fn scale_pos(p: &Value, k: f64) -> Result<Value, EvalError> {
    let p = pos_of(p)?.map(f64::from);
    pos_value([
        num_result(p[0] * k)?,
        num_result(p[1] * k)?,
        num_result(p[2] * k)?,
    ])
}

fn pos_value(c: [Value; 3]) -> Result<Value, EvalError> {
    let f = |v: &Value| match v {
        Value::Num(x) => *x,
        _ => 0.0,
    };
    Ok(Value::pos(f(&c[0]), f(&c[1]), f(&c[2])))
}
