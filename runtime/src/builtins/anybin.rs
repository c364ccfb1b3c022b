//! `WriteAnyBin` and `ReadAnyBin`: any value to a file and back.
//!
//! The bytes are the simulation's own, not the controller's: a record
//! starts with `RAB1`, then the length of the value's bytes (4 bytes, big
//! endian), the value (a tag and its content: `n` a `num`, 4 bytes IEEE
//! 754; `d` a `dnum`, 8 bytes; `b` a `bool`, 1 byte; `s` a string, its
//! length then its Latin-1 bytes; `r` a record, its type's name and its
//! components; `a` an array, its length and its elements) and a checksum
//! byte (the sum of the value's bytes). So a program reads back exactly
//! what it wrote, across runs; a file a real controller wrote cannot be
//! read (`ERR_RANYBIN_CHK`), nor this one by a controller.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, fault, named_error};

const MAGIC: &[u8; 4] = b"RAB1";

fn put(v: &Value, out: &mut Vec<u8>) {
    match v {
        Value::Num(n) => {
            out.push(b'n');
            out.extend_from_slice(&n.to_be_bytes());
        }
        Value::Dnum(d) => {
            out.push(b'd');
            out.extend_from_slice(&d.to_be_bytes());
        }
        Value::Bool(b) => out.extend_from_slice(&[b'b', u8::from(*b)]),
        Value::Str(s) => {
            out.push(b's');
            put_text(s, out);
        }
        Value::Record { ty, fields } => {
            out.push(b'r');
            put_text(ty, out);
            out.extend_from_slice(&(fields.len() as u32).to_be_bytes());
            for (_, f) in fields {
                put(f, out);
            }
        }
        Value::Array(items) => {
            out.push(b'a');
            out.extend_from_slice(&(items.len() as u32).to_be_bytes());
            for i in items {
                put(i, out);
            }
        }
    }
}

/// A string as its length (up to 255 characters) and Latin-1 bytes.
fn put_text(s: &str, out: &mut Vec<u8>) {
    let bytes: Vec<u8> = s.chars().map(|c| u32::from(c).min(255) as u8).collect();
    let n = bytes.len().min(255);
    out.push(n as u8);
    out.extend_from_slice(&bytes[..n]);
}

/// The bytes `WriteAnyBin` writes for `v`.
pub(crate) fn encode(v: &Value) -> Vec<u8> {
    let mut body = Vec::new();
    put(v, &mut body);
    let mut out = MAGIC.to_vec();
    out.extend_from_slice(&(body.len() as u32).to_be_bytes());
    let sum = body.iter().fold(0u8, |s, b| s.wrapping_add(*b));
    out.extend_from_slice(&body);
    out.push(sum);
    out
}

/// Reads a value shaped as `like` (the same types, record types and
/// array sizes) from the front of `bytes`.
struct Reader<'b> {
    bytes: &'b [u8],
}

impl<'b> Reader<'b> {
    fn take(&mut self, n: usize) -> Option<&'b [u8]> {
        let (head, rest) = self.bytes.split_at_checked(n)?;
        self.bytes = rest;
        Some(head)
    }

    fn u32(&mut self) -> Option<usize> {
        let b: [u8; 4] = self.take(4)?.try_into().ok()?;
        Some(u32::from_be_bytes(b) as usize)
    }

    fn text(&mut self) -> Option<String> {
        let n = usize::from(*self.take(1)?.first()?);
        Some(self.take(n)?.iter().map(|&b| char::from(b)).collect())
    }

    fn value(&mut self, like: &Value) -> Option<Value> {
        let tag = *self.take(1)?.first()?;
        match (tag, like) {
            (b'n', Value::Num(_)) => Some(Value::Num(f32::from_be_bytes(
                self.take(4)?.try_into().ok()?,
            ))),
            (b'd', Value::Dnum(_)) => Some(Value::Dnum(f64::from_be_bytes(
                self.take(8)?.try_into().ok()?,
            ))),
            (b'b', Value::Bool(_)) => Some(Value::Bool(*self.take(1)?.first()? != 0)),
            (b's', Value::Str(_)) => Some(Value::Str(self.text()?)),
            (b'r', Value::Record { ty, fields }) => {
                if !self.text()?.eq_ignore_ascii_case(ty) || self.u32()? != fields.len() {
                    return None;
                }
                let mut out = Vec::with_capacity(fields.len());
                for (name, f) in fields {
                    out.push((name.clone(), self.value(f)?));
                }
                Some(Value::Record {
                    ty: ty.clone(),
                    fields: out,
                })
            }
            (b'a', Value::Array(items)) => {
                if self.u32()? != items.len() {
                    return None;
                }
                items
                    .iter()
                    .map(|i| self.value(i))
                    .collect::<Option<Vec<_>>>()
                    .map(Value::Array)
            }
            _ => None,
        }
    }
}

/// What reading a record from the front of `bytes` gives.
#[derive(Debug, PartialEq)]
pub(crate) enum Read {
    /// The value and how many bytes it took.
    Value(Value, usize),
    /// No byte is left.
    End,
    /// Bytes that are not a record of a value shaped as the data.
    Bad,
}

/// Reads a record `encode` wrote of a value shaped as `like`.
pub(crate) fn decode(bytes: &[u8], like: &Value) -> Read {
    if bytes.is_empty() {
        return Read::End;
    }
    let mut r = Reader { bytes };
    let framed = (|| {
        if r.take(4)? != MAGIC {
            return None;
        }
        let n = r.u32()?;
        let body = r.take(n)?;
        let sum = *r.take(1)?.first()?;
        (body.iter().fold(0u8, |s, b| s.wrapping_add(*b)) == sum).then_some((body, 9 + n))
    })();
    let Some((body, used)) = framed else {
        return Read::Bad;
    };
    let mut inner = Reader { bytes: body };
    match inner.value(like) {
        Some(v) if inner.bytes.is_empty() => Read::Value(v, used),
        _ => Read::Bad,
    }
}

/// `WriteAnyBin IODevice, Data`.
pub(crate) fn write_any_bin(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let v = cx.req(a, "Data")?;
    super::files::write_bytes(cx, a, &encode(&v))
}

/// `ReadAnyBin IODevice, Data [\Time]`: `ERR_RANYBIN_EOF` at the end of
/// the file, `ERR_RANYBIN_CHK` for bytes that are not a value of Data's
/// type as `WriteAnyBin` wrote it.
pub(crate) fn read_any_bin(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let place = cx.place_arg(a, "Data")?;
    let Some(like) = cx.m.get(cx.sh, &place).cloned() else {
        return crate::machine::invalid("ReadAnyBin: Data no longer exists");
    };
    let (rest, pos) = super::files::unread(cx, a)?;
    let read = decode(rest, &like);
    if let Read::Value(_, used) = &read {
        *pos += used;
    }
    let (code, why) = match read {
        Read::Value(v, _) => {
            cx.store(&place, v)?;
            return Ok(Done::Next);
        }
        Read::End => ("ERR_RANYBIN_EOF", "the end of the file"),
        Read::Bad => (
            "ERR_RANYBIN_CHK",
            "the bytes are not a value of Data's type as WriteAnyBin writes it",
        ),
    };
    fault(named_error(&cx.m.prog, code, format!("ReadAnyBin: {why}")))
}

#[cfg(test)]
mod tests {
    use super::{Read, decode, encode};
    use rapid_evaluator::Value;

    fn sample() -> Value {
        Value::Array(vec![
            Value::Record {
                ty: "step".to_owned(),
                fields: vec![
                    ("p".to_owned(), Value::pos(1.5, -2.25, 1e-7)),
                    ("name".to_owned(), Value::Str("pick \u{e9}".to_owned())),
                    ("on".to_owned(), Value::Bool(true)),
                    ("n".to_owned(), Value::Dnum(123_456_789.123)),
                ],
            };
            2
        ])
    }

    #[test]
    fn a_value_reads_back_exactly_as_written() {
        let v = sample();
        let mut bytes = encode(&v);
        let len = bytes.len();
        bytes.extend(encode(&Value::Num(7.0)));
        assert_eq!(decode(&bytes, &v), Read::Value(v.clone(), len));
        assert_eq!(
            decode(&bytes[len..], &Value::Num(0.0)),
            Read::Value(Value::Num(7.0), bytes.len() - len)
        );
        assert_eq!(decode(&[], &v), Read::End);
    }

    #[test]
    fn bytes_of_another_shape_or_damaged_are_refused() {
        let v = sample();
        let bytes = encode(&v);
        // Another type, another array size.
        assert_eq!(decode(&bytes, &Value::Num(0.0)), Read::Bad);
        let Value::Array(items) = &v else {
            unreachable!("an array")
        };
        assert_eq!(
            decode(&bytes, &Value::Array(items[..1].to_vec())),
            Read::Bad
        );
        // A changed byte, a cut record, bytes of another writer.
        let mut changed = bytes.clone();
        changed[12] ^= 1;
        assert_eq!(decode(&changed, &v), Read::Bad);
        assert_eq!(decode(&bytes[..bytes.len() - 1], &v), Read::Bad);
        assert_eq!(decode(b"\x00\x01\x02", &v), Read::Bad);
    }
}
