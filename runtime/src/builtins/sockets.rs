//! Sockets, through the world's [`crate::world::Sockets`]; a `socketdev`
//! holds the socket's number.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, R, fault, invalid, named_error};
use crate::world::SocketError;

fn socket_error<T>(cx: &Cx<'_>, a: &Args, e: SocketError) -> R<T> {
    match e {
        SocketError::Unsupported => fault(FaultKind::Unsupported(a.name.to_owned())),
        SocketError::Closed(m) => fault(named_error(&cx.m.prog, "ERR_SOCK_CLOSED", m)),
        SocketError::Timeout(m) => fault(named_error(&cx.m.prog, "ERR_SOCK_TIMEOUT", m)),
    }
}

fn socket(cx: &mut Cx<'_>, a: &Args) -> R<u32> {
    let v = cx.req(a, "Socket")?;
    Ok(v.field("handle").and_then(Value::as_f64).unwrap_or(0.0) as u32)
}

/// `SocketCreate Socket [\UDP]`.
pub(crate) fn socket_create(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id = match cx.sh.sockets.create() {
        Ok(id) => id,
        Err(e) => return socket_error(cx, a, e),
    };
    let p = cx.place_arg(a, "Socket")?;
    cx.store(
        &p,
        Value::Record {
            ty: "socketdev".to_owned(),
            fields: vec![("handle".to_owned(), Value::Num(id as f32))],
        },
    )?;
    Ok(Done::Next)
}

/// `SocketConnect Socket, Address, Port [\Time]`.
pub(crate) fn socket_connect(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a)?;
    let address = cx.string(a, "Address")?;
    let port = cx.num(a, "Port")?;
    match cx.sh.sockets.connect(s, &address, port.max(0.0) as u32) {
        Ok(()) => Ok(Done::Next),
        Err(e) => socket_error(cx, a, e),
    }
}

/// `SocketSend Socket, \Str | \RawData | \Data [\NoOfBytes]`.
pub(crate) fn socket_send(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a)?;
    let bytes: Vec<u8> = match cx.opt(a, "Str")? {
        Some(Value::Str(text)) => text.chars().map(|c| u32::from(c).min(255) as u8).collect(),
        _ => match cx.opt(a, "Data")? {
            Some(Value::Array(items)) => items
                .iter()
                .map(|v| v.as_f64().unwrap_or(0.0).clamp(0.0, 255.0) as u8)
                .collect(),
            _ => return invalid("SocketSend: \\Str or \\Data is needed"),
        },
    };
    let n = cx
        .opt_num(a, "NoOfBytes")?
        .map_or(bytes.len(), |n| n as usize);
    match cx.sh.sockets.send(s, &bytes[..n.min(bytes.len())]) {
        Ok(()) => Ok(Done::Next),
        Err(e) => socket_error(cx, a, e),
    }
}

/// `SocketReceive Socket, \Str | \Data ... [\NoRecBytes]`.
pub(crate) fn socket_receive(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a)?;
    let bytes = match cx.sh.sockets.receive(s) {
        Ok(b) => b,
        Err(e) => return socket_error(cx, a, e),
    };
    if let Some(p) = cx.opt_place(a, "Str")? {
        let text: String = bytes.iter().map(|b| char::from(*b)).collect();
        cx.store(&p, Value::Str(text))?;
    } else if let Some(p) = cx.opt_place(a, "Data")? {
        let items = bytes.iter().map(|b| Value::Num(f32::from(*b))).collect();
        cx.store(&p, Value::Array(items))?;
    }
    if let Some(p) = cx.opt_place(a, "NoRecBytes")? {
        cx.store(&p, Value::Num(bytes.len() as f32))?;
    }
    Ok(Done::Next)
}

/// `SocketClose Socket`.
pub(crate) fn socket_close(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a)?;
    match cx.sh.sockets.close(s) {
        Ok(()) => Ok(Done::Next),
        Err(e) => socket_error(cx, a, e),
    }
}
