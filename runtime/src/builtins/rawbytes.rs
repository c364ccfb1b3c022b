//! `rawbytes` data (binary messages for sockets and files): the value
//! holds its valid bytes as an array of `num`s (at most 1024);
//! `RawBytesLen`, `ClearRawBytes`, `CopyRawBytes`, `PackRawBytes`,
//! `UnpackRawBytes` (`\Hex1`, `\IntX`, `\Float4`, `\ASCII`, little-endian
//! unless `\Network`).

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, invalid, named_error};

/// The most bytes a `rawbytes` holds.
pub(crate) const MAX_BYTES: usize = 1024;

/// The valid bytes of a `rawbytes` value.
pub(crate) fn bytes(v: &Value) -> Vec<u8> {
    match v.field("bytes") {
        Some(Value::Array(items)) => items
            .iter()
            .map(|b| b.as_f64().unwrap_or(0.0) as u8)
            .collect(),
        _ => Vec::new(),
    }
}

/// A `rawbytes` value of `data`.
pub(crate) fn value(data: &[u8]) -> Value {
    Value::Record {
        ty: "rawbytes".to_owned(),
        fields: vec![(
            "bytes".to_owned(),
            Value::Array(data.iter().map(|b| Value::Num(f32::from(*b))).collect()),
        )],
    }
}

fn raw_arg(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<(crate::machine::Place, Vec<u8>)> {
    let p = cx.place_arg(a, param)?;
    let v = cx.m.load(cx.sh, &p)?;
    Ok((p, bytes(&v)))
}

/// A 1-based index into a `rawbytes`, checked.
fn index(cx: &Cx<'_>, a: &Args, i: f64, len: usize) -> R<usize> {
    if i < 1.0 || i.fract() != 0.0 || i as usize > len {
        return crate::machine::fault(named_error(
            &cx.m.prog,
            "ERR_OUTOFBND",
            format!("{}: index {i} outside 1..{len}", a.name),
        ));
    }
    Ok(i as usize - 1)
}

/// `RawBytesLen(RawData)`.
pub(crate) fn raw_bytes_len(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let v = cx.req(a, "RawData")?;
    Ok(Value::Num(bytes(&v).len() as f32))
}

/// `ClearRawBytes RawData [\FromIndex]`.
pub(crate) fn clear_raw_bytes(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (p, mut data) = raw_arg(cx, a, "RawData")?;
    let from = cx.opt_num(a, "FromIndex")?.unwrap_or(1.0);
    let keep = index(cx, a, from, MAX_BYTES)?;
    data.truncate(keep);
    cx.store(&p, value(&data))?;
    Ok(Done::Next)
}

/// `CopyRawBytes From, FromIndex, To, ToIndex [\NoOfBytes]`.
pub(crate) fn copy_raw_bytes(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (_, from) = raw_arg(cx, a, "FromRawData")?;
    let start = cx.num(a, "FromIndex")?;
    let start = index(cx, a, start, from.len())?;
    let (p, mut to) = raw_arg(cx, a, "ToRawData")?;
    let at = cx.num(a, "ToIndex")?;
    let at = index(cx, a, at, to.len() + 1)?;
    let n = cx
        .opt_num(a, "NoOfBytes")?
        .map_or(from.len() - start, |n| n.max(0.0) as usize);
    let piece = &from[start..(start + n).min(from.len())];
    write_at(cx, a, &mut to, at, piece)?;
    cx.store(&p, value(&to))?;
    Ok(Done::Next)
}

fn write_at(cx: &Cx<'_>, a: &Args, data: &mut Vec<u8>, at: usize, piece: &[u8]) -> R<()> {
    let end = at + piece.len();
    if end > MAX_BYTES {
        return crate::machine::fault(named_error(
            &cx.m.prog,
            "ERR_OUTOFBND",
            format!("{}: more than {MAX_BYTES} bytes", a.name),
        ));
    }
    if data.len() < end {
        data.resize(end, 0);
    }
    data[at..end].copy_from_slice(piece);
    Ok(())
}

/// The encoding of `\Hex1`, `\IntX`, `\Float4`, `\ASCII`: the width in
/// bytes, signed, a float.
enum Form {
    Int { width: usize, signed: bool },
    Float4,
    Ascii,
}

fn form(cx: &mut Cx<'_>, a: &Args) -> R<Form> {
    if a.given("Hex1") {
        return Ok(Form::Int {
            width: 1,
            signed: false,
        });
    }
    if a.given("Float4") {
        return Ok(Form::Float4);
    }
    if a.given("ASCII") {
        return Ok(Form::Ascii);
    }
    if let Some(x) = cx.opt_num(a, "IntX")? {
        let signed = x < 0.0;
        let width = x.abs() as usize;
        if [1, 2, 4, 8].contains(&width) {
            return Ok(Form::Int { width, signed });
        }
    }
    invalid(format!(
        "{}: \\Hex1, \\IntX, \\Float4 or \\ASCII is needed",
        a.name
    ))
}

/// `PackRawBytes Value, RawData [\Network], StartIndex, \Hex1 | \IntX |
/// \Float4 | \ASCII`.
pub(crate) fn pack_raw_bytes(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let v = cx.req(a, "Value")?;
    let (p, mut data) = raw_arg(cx, a, "RawData")?;
    let start = cx.num(a, "StartIndex")?;
    let at = index(cx, a, start, data.len() + 1)?;
    let network = a.given("Network");
    let mut piece = match (form(cx, a)?, &v) {
        (Form::Ascii, Value::Str(s)) => s.chars().map(|c| u32::from(c).min(255) as u8).collect(),
        (Form::Float4, v) => (v.as_f64().unwrap_or(0.0) as f32).to_le_bytes().to_vec(),
        (Form::Int { width, .. }, v) => {
            let x = v.as_f64().unwrap_or(0.0) as i64;
            x.to_le_bytes()[..width].to_vec()
        }
        (Form::Ascii, other) => {
            return invalid(format!("PackRawBytes: \\ASCII packs a string, not {other}"));
        }
    };
    if network && !matches!(&v, Value::Str(_)) {
        piece.reverse();
    }
    write_at(cx, a, &mut data, at, &piece)?;
    cx.store(&p, value(&data))?;
    Ok(Done::Next)
}

/// `UnpackRawBytes RawData [\Network], StartIndex, Value, \Hex1 | \IntX |
/// \Float4 | \ASCII:=N`.
pub(crate) fn unpack_raw_bytes(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let v = cx.req(a, "RawData")?;
    let data = bytes(&v);
    let start = cx.num(a, "StartIndex")?;
    let at = index(cx, a, start, data.len())?;
    let to = cx.place_arg(a, "Value")?;
    let network = a.given("Network");
    let take = |n: usize| -> Option<Vec<u8>> {
        let mut b = data.get(at..at + n)?.to_vec();
        if network {
            b.reverse();
        }
        Some(b)
    };
    let out = if a.given("ASCII") {
        let n = cx.num(a, "ASCII")?.max(0.0) as usize;
        match data.get(at..at + n) {
            Some(b) => Value::Str(b.iter().map(|c| char::from(*c)).collect()),
            None => return short(cx),
        }
    } else {
        match form(cx, a)? {
            Form::Float4 => match take(4) {
                Some(b) => Value::Num(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                None => return short(cx),
            },
            Form::Int { width, signed } => match take(width) {
                Some(b) => {
                    let mut full = [0u8; 8];
                    full[..width].copy_from_slice(&b);
                    if signed && b[width - 1] & 0x80 != 0 {
                        full[width..].fill(0xff);
                    }
                    let x = i64::from_le_bytes(full);
                    if width > 4 {
                        Value::Dnum(x as f64)
                    } else {
                        Value::Num(x as f32)
                    }
                }
                None => return short(cx),
            },
            Form::Ascii => unreachable_ascii()?,
        }
    };
    cx.store(&to, out)?;
    Ok(Done::Next)
}

fn short<T>(cx: &Cx<'_>) -> R<T> {
    crate::machine::fault(named_error(
        &cx.m.prog,
        "ERR_OUTOFBND",
        "UnpackRawBytes: not so many bytes".to_owned(),
    ))
}

fn unreachable_ascii() -> R<Value> {
    invalid("UnpackRawBytes: \\ASCII needs the number of characters")
}
