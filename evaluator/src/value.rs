//! Values and how RAPID prints them.

use std::fmt;

/// A RAPID value.
///
/// `Display` prints the value the way `ValToStr` and the controller write it:
/// `num` with at most 6 significant digits (`0.333333`, `9E+09`), `dnum` with
/// up to 15, booleans as `TRUE`/`FALSE`, strings as quoted literals (`"a""b"`),
/// records and arrays as aggregates (`[[1,2,3],[1,0,0,0]]`).
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// `num` (and its aliases: byte, errnum, opnum, ...): single precision.
    Num(f32),
    /// `dnum`: double precision.
    Dnum(f64),
    /// `bool`.
    Bool(bool),
    /// `string`: at most 80 characters, each in ISO 8859-1 (`'\0'..='\u{ff}'`).
    Str(String),
    /// A record value (`pos`, `robtarget`, user records); field names as
    /// declared, in declaration order.
    Record {
        /// The record type name (`"pos"`, `"robtarget"`).
        ty: String,
        /// The components in declaration order.
        fields: Vec<(String, Value)>,
    },
    /// An array, or an aggregate whose type was not known. Multi-dimensional
    /// arrays are arrays of arrays.
    Array(Vec<Value>),
}

impl Value {
    /// A `pos` record.
    pub fn pos(x: f32, y: f32, z: f32) -> Value {
        Value::Record {
            ty: "pos".into(),
            fields: vec![
                ("x".into(), Value::Num(x)),
                ("y".into(), Value::Num(y)),
                ("z".into(), Value::Num(z)),
            ],
        }
    }

    /// An `orient` record `[q1, q2, q3, q4]`.
    pub fn orient(q: [f32; 4]) -> Value {
        Value::Record {
            ty: "orient".into(),
            fields: vec![
                ("q1".into(), Value::Num(q[0])),
                ("q2".into(), Value::Num(q[1])),
                ("q3".into(), Value::Num(q[2])),
                ("q4".into(), Value::Num(q[3])),
            ],
        }
    }

    /// A `pose` record from its translation and rotation.
    pub fn pose(trans: [f32; 3], rot: [f32; 4]) -> Value {
        Value::Record {
            ty: "pose".into(),
            fields: vec![
                ("trans".into(), Value::pos(trans[0], trans[1], trans[2])),
                ("rot".into(), Value::orient(rot)),
            ],
        }
    }

    /// The RAPID type name of the value (`"num"`, `"pos"`, ...); `None` for
    /// an array or an untyped aggregate.
    pub fn type_name(&self) -> Option<&str> {
        match self {
            Value::Num(_) => Some("num"),
            Value::Dnum(_) => Some("dnum"),
            Value::Bool(_) => Some("bool"),
            Value::Str(_) => Some("string"),
            Value::Record { ty, .. } => Some(ty),
            Value::Array(_) => None,
        }
    }

    /// The component `name` of a record (case-insensitive).
    pub fn field(&self, name: &str) -> Option<&Value> {
        match self {
            Value::Record { fields, .. } => fields
                .iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(name))
                .map(|(_, v)| v),
            _ => None,
        }
    }

    /// The component `name` of a record (case-insensitive), to change.
    pub fn field_mut(&mut self, name: &str) -> Option<&mut Value> {
        match self {
            Value::Record { fields, .. } => fields
                .iter_mut()
                .find(|(n, _)| n.eq_ignore_ascii_case(name))
                .map(|(_, v)| v),
            _ => None,
        }
    }

    /// The numeric value of a `num` or `dnum`.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Num(x) => Some(f64::from(*x)),
            Value::Dnum(x) => Some(*x),
            _ => None,
        }
    }

    /// For an `orient`, or a record with a `rot` component (`pose`,
    /// `robtarget`), the Euler ZYX angles `[z, y, x]` in degrees, as
    /// [`crate::euler_zyx_deg`] computes them; for hovers.
    pub fn euler_zyx(&self) -> Option<[f64; 3]> {
        let q = self.field("rot").unwrap_or(self);
        let mut c = [0.0; 4];
        for (slot, name) in c.iter_mut().zip(["q1", "q2", "q3", "q4"]) {
            *slot = q.field(name)?.as_f64()?;
        }
        Some(crate::geometry::euler_zyx_deg(c))
    }

    /// The text of a string value (without quotes).
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::Str(s) => Some(s),
            _ => None,
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Num(x) => f.write_str(&format_num(*x)),
            Value::Dnum(x) => f.write_str(&format_dnum(*x)),
            Value::Bool(true) => f.write_str("TRUE"),
            Value::Bool(false) => f.write_str("FALSE"),
            Value::Str(s) => f.write_str(&quote_string(s)),
            Value::Record { fields, .. } => {
                f.write_str("[")?;
                for (i, (_, v)) in fields.iter().enumerate() {
                    if i > 0 {
                        f.write_str(",")?;
                    }
                    write!(f, "{v}")?;
                }
                f.write_str("]")
            }
            Value::Array(items) => {
                f.write_str("[")?;
                for (i, v) in items.iter().enumerate() {
                    if i > 0 {
                        f.write_str(",")?;
                    }
                    write!(f, "{v}")?;
                }
                f.write_str("]")
            }
        }
    }
}

/// Writes a string as a RAPID string literal: quotes doubled, backslashes
/// doubled, control characters as `\hh`.
pub fn quote_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\"\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 || (0x7f..0xa0).contains(&(c as u32)) || (c as u32) > 0xff => {
                out.push_str(&format!("\\{:02X}", (c as u32) & 0xff));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Prints a `num` as the controller does (`ValToStr`): at most 6
/// significant digits, trailing zeros dropped, a fraction closer than
/// 0.000005 to an integer rounded away, exponent form `1.5E+07` for large
/// and small magnitudes.
pub fn format_num(x: f32) -> String {
    let mut v = f64::from(x);
    let frac = (v - v.trunc()).abs();
    if !(0.000005..=0.999995).contains(&frac) {
        v = v.round();
    }
    format_g(v, 6)
}

/// Prints a `dnum`: at most 15 significant digits, trailing zeros dropped.
pub fn format_dnum(x: f64) -> String {
    format_g(x, 15)
}

/// C's `%.{prec}g` with trailing zeros removed, an upper-case `E` and an
/// exponent of at least two digits.
pub(crate) fn format_g(v: f64, prec: usize) -> String {
    if !v.is_finite() {
        return if v.is_nan() {
            "NaN".into()
        } else if v > 0.0 {
            "Inf".into()
        } else {
            "-Inf".into()
        };
    }
    if v == 0.0 {
        return "0".into();
    }
    let prec = prec.max(1);
    let sci = format!("{:.*e}", prec - 1, v);
    let (mantissa, exp) = match sci.split_once('e') {
        Some((m, e)) => (m.to_string(), e.parse::<i32>().unwrap_or(0)),
        None => (sci.clone(), 0),
    };
    if exp >= -4 && exp < prec as i32 {
        let decimals = (prec as i32 - 1 - exp).max(0) as usize;
        strip_zeros(&format!("{:.*}", decimals, v))
    } else {
        let m = strip_zeros(&mantissa);
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{m}E{sign}{:02}", exp.abs())
    }
}

fn strip_zeros(s: &str) -> String {
    if s.contains('.') {
        let t = s.trim_end_matches('0').trim_end_matches('.');
        if t == "-0" { "0".into() } else { t.into() }
    } else if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}
