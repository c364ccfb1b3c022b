//! Sockets, through the world's [`crate::world::Sockets`]; a `socketdev`
//! holds the socket's number (0: not created). A wait for the other side
//! (`\Time`, 60 s when not given, as on the controller) is real time, and
//! the simulated clock moves by the time waited. `rawbytes` data hold
//! their bytes as an array (see [`super::rawbytes`]).

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, R, Timeout, Wait, WaitKind, fault, invalid, named_error};
use crate::world::SocketError;

/// The controller's default `\Time` of a socket wait, in seconds.
const DEFAULT_TIME: f64 = 60.0;
/// The longest string a `SocketReceive \Str` takes (RAPID strings hold
/// up to 80 characters).
const MAX_STRING: usize = 80;

fn socket_error<T>(cx: &mut Cx<'_>, a: &Args, e: SocketError) -> R<T> {
    cx.socket_time();
    match e {
        SocketError::NeverAnswers { after, message } => {
            // Reached only through `done`, which waits first.
            fault(named_error(
                &cx.m.prog,
                "ERR_SOCK_TIMEOUT",
                format!("{}: {message} ({after} s)", a.name),
            ))
        }
        SocketError::Unsupported => fault(FaultKind::Unsupported(a.name.to_owned())),
        SocketError::Closed(m) | SocketError::Failed(m) => fault(named_error(
            &cx.m.prog,
            "ERR_SOCK_CLOSED",
            format!("{}: {m}", a.name),
        )),
        SocketError::Timeout(m) => fault(named_error(
            &cx.m.prog,
            "ERR_SOCK_TIMEOUT",
            format!("{}: {m}", a.name),
        )),
    }
}

impl Cx<'_> {
    /// The simulated clock moves by the real time the sockets waited.
    fn socket_time(&mut self) {
        let waited = self.sh.sockets.waited();
        if waited > 0.0 {
            let t = self.sh.clock + waited;
            self.sh.advance_to(t);
        }
    }
}

/// The socket number a `socketdev` argument holds.
fn socket(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<u32> {
    let v = cx.req(a, param)?;
    Ok(super::handle_in(&v).unwrap_or(0.0) as u32)
}

fn store_socket(cx: &mut Cx<'_>, a: &Args, param: &str, id: u32) -> R<()> {
    let p = cx.place_arg(a, param)?;
    cx.store(&p, super::handle_value("socketdev", f64::from(id)))
}

fn time(cx: &mut Cx<'_>, a: &Args) -> R<f64> {
    Ok(cx.opt_num(a, "Time")?.unwrap_or(DEFAULT_TIME).max(0.0))
}

/// The result of a socket operation; `None`: nothing will come, and the
/// instruction waits ([`waiting`]).
fn done<T>(cx: &mut Cx<'_>, a: &Args, r: Result<T, SocketError>) -> R<Option<T>> {
    match r {
        Ok(v) => {
            cx.socket_time();
            Ok(Some(v))
        }
        Err(SocketError::NeverAnswers { after, message }) => {
            // The task waits the whole time (other tasks run), then the
            // wait times out with the error; a `WAIT_MAX` wait never ends.
            let w = Wait {
                kind: WaitKind::Never,
                deadline: (after < crate::world::WAIT_MAX).then(|| cx.now() + after.max(0.0)),
                on_timeout: Timeout::Error("ERR_SOCK_TIMEOUT", format!("{}: {message}", a.name)),
                what: format!("{} ({message})", a.name),
            };
            cx.m.function_wait = Some(Box::new(w));
            Ok(None)
        }
        Err(e) => socket_error(cx, a, e),
    }
}

/// The wait of an operation that gets no answer.
fn waiting(cx: &mut Cx<'_>) -> R<Done> {
    match cx.m.function_wait.take() {
        Some(w) => Ok(Done::Wait(w)),
        None => invalid("a socket wait that is not there"),
    }
}

/// `SocketCreate Socket [\UDP]`.
pub(crate) fn socket_create(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let r = cx.sh.sockets.create(a.given("UDP"));
    let Some(id) = done(cx, a, r)? else {
        return waiting(cx);
    };
    store_socket(cx, a, "Socket", id)?;
    Ok(Done::Next)
}

/// `SocketConnect Socket, Address, Port [\Time]`.
pub(crate) fn socket_connect(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let address = cx.string(a, "Address")?;
    let port = cx.num(a, "Port")?.max(0.0) as u32;
    let t = time(cx, a)?;
    let r = cx.sh.sockets.connect(s, &address, port, t);
    if done(cx, a, r)?.is_none() {
        return waiting(cx);
    }
    Ok(Done::Next)
}

/// `SocketBind Socket, LocalAddress, LocalPort`.
pub(crate) fn socket_bind(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let address = cx.string(a, "LocalAddress")?;
    let port = cx.num(a, "LocalPort")?.max(0.0) as u32;
    let r = cx.sh.sockets.bind(s, &address, port);
    if done(cx, a, r)?.is_none() {
        return waiting(cx);
    }
    Ok(Done::Next)
}

/// `SocketListen Socket`.
pub(crate) fn socket_listen(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let r = cx.sh.sockets.listen(s);
    if done(cx, a, r)?.is_none() {
        return waiting(cx);
    }
    Ok(Done::Next)
}

/// `SocketAccept Socket, ClientSocket [\ClientAddress] [\Time]`.
pub(crate) fn socket_accept(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let t = time(cx, a)?;
    let r = cx.sh.sockets.accept(s, t);
    let Some((client, address)) = done(cx, a, r)? else {
        return waiting(cx);
    };
    store_socket(cx, a, "ClientSocket", client)?;
    if let Some(p) = cx.opt_place(a, "ClientAddress")? {
        cx.store(&p, Value::Str(address))?;
    }
    Ok(Done::Next)
}

/// The bytes of `\Str`, `\RawData` or `\Data`, cut to `\NoOfBytes`.
fn bytes_to_send(cx: &mut Cx<'_>, a: &Args) -> R<Vec<u8>> {
    let bytes: Vec<u8> = if let Some(v) = cx.opt(a, "Str")? {
        match v {
            Value::Str(text) => text.chars().map(|c| u32::from(c).min(255) as u8).collect(),
            other => return invalid(format!("{}: \\Str is {other}", a.name)),
        }
    } else if let Some(v) = cx.opt(a, "RawData")? {
        super::rawbytes::bytes(&v)
    } else if let Some(v) = cx.opt(a, "Data")? {
        match v {
            Value::Array(items) => items
                .iter()
                .map(|v| v.as_f64().unwrap_or(0.0).clamp(0.0, 255.0) as u8)
                .collect(),
            other => vec![other.as_f64().unwrap_or(0.0).clamp(0.0, 255.0) as u8],
        }
    } else {
        return invalid(format!("{}: \\Str, \\RawData or \\Data is needed", a.name));
    };
    let n = cx
        .opt_num(a, "NoOfBytes")?
        .map_or(bytes.len(), |n| n.max(0.0) as usize);
    Ok(bytes[..n.min(bytes.len())].to_vec())
}

/// `SocketSend Socket, \Str | \RawData | \Data [\NoOfBytes]`.
pub(crate) fn socket_send(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let bytes = bytes_to_send(cx, a)?;
    let r = cx.sh.sockets.send(s, &bytes);
    if done(cx, a, r)?.is_none() {
        return waiting(cx);
    }
    Ok(Done::Next)
}

/// `SocketSendTo Socket, RemoteAddress, RemotePort, \Str | \RawData |
/// \Data [\NoOfBytes]`: one UDP datagram.
pub(crate) fn socket_send_to(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let address = cx.string(a, "RemoteAddress")?;
    let port = cx.num(a, "RemotePort")?.max(0.0) as u32;
    let bytes = bytes_to_send(cx, a)?;
    let r = cx.sh.sockets.send_to(s, &address, port, &bytes);
    if done(cx, a, r)?.is_none() {
        return waiting(cx);
    }
    Ok(Done::Next)
}

/// Where received bytes go (`\Str`, `\RawData`, `\Data`) and how many
/// it holds (80 characters, 1024 raw bytes, the array's length).
fn receive_target(cx: &mut Cx<'_>, a: &Args) -> R<(Target, usize)> {
    Ok(if let Some(p) = cx.opt_place(a, "Str")? {
        (Target::Str(p), MAX_STRING)
    } else if let Some(p) = cx.opt_place(a, "RawData")? {
        (Target::Raw(p), super::rawbytes::MAX_BYTES)
    } else if let Some(p) = cx.opt_place(a, "Data")? {
        let len = match cx.m.load(cx.sh, &p)? {
            Value::Array(items) => items.len(),
            _ => 1,
        };
        (Target::Data(p), len)
    } else {
        return invalid(format!("{}: \\Str, \\RawData or \\Data is needed", a.name));
    })
}

/// Stores received bytes, and their count in `\NoRecBytes`.
fn store_received(cx: &mut Cx<'_>, a: &Args, target: Target, bytes: &[u8]) -> R<()> {
    match target {
        Target::Str(p) => {
            let text: String = bytes.iter().map(|b| char::from(*b)).collect();
            cx.store(&p, Value::Str(text))?;
        }
        Target::Raw(p) => cx.store(&p, super::rawbytes::value(bytes))?,
        Target::Data(p) => {
            let mut items = match cx.m.load(cx.sh, &p)? {
                Value::Array(items) => items,
                _ => Vec::new(),
            };
            for (slot, b) in items.iter_mut().zip(bytes) {
                *slot = Value::Num(f32::from(*b));
            }
            cx.store(&p, Value::Array(items))?;
        }
    }
    if let Some(p) = cx.opt_place(a, "NoRecBytes")? {
        cx.store(&p, Value::Num(bytes.len() as f32))?;
    }
    Ok(())
}

/// `SocketReceive Socket, \Str | \RawData | \Data [\ReadNoOfBytes]
/// [\NoRecBytes] [\Time]`: what has come in (at most what the data
/// holds: 80 characters, 1024 raw bytes, the array's length), or exactly
/// `\ReadNoOfBytes` bytes.
pub(crate) fn socket_receive(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let (target, room) = receive_target(cx, a)?;
    let exact = cx.opt_num(a, "ReadNoOfBytes")?.map(|n| n.max(0.0) as usize);
    if exact.is_some_and(|n| n > room) {
        return fault(named_error(
            &cx.m.prog,
            "ERR_OUTOFBND",
            format!("SocketReceive: \\ReadNoOfBytes is more than the data holds ({room})"),
        ));
    }
    let t = time(cx, a)?;
    let r = cx
        .sh
        .sockets
        .receive(s, exact.unwrap_or(room), exact.is_some(), t);
    let Some(bytes) = done(cx, a, r)? else {
        return waiting(cx);
    };
    store_received(cx, a, target, &bytes)?;
    Ok(Done::Next)
}

/// `SocketReceiveFrom Socket, \Str | \RawData | \Data [\NoRecBytes],
/// RemoteAddress, RemotePort [\Time]`: the next UDP datagram (what the
/// data holds of it) and who sent it.
pub(crate) fn socket_receive_from(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    let (target, room) = receive_target(cx, a)?;
    let t = time(cx, a)?;
    let r = cx.sh.sockets.receive_from(s, room, t);
    let Some((bytes, address, port)) = done(cx, a, r)? else {
        return waiting(cx);
    };
    store_received(cx, a, target, &bytes)?;
    let p = cx.place_arg(a, "RemoteAddress")?;
    cx.store(&p, Value::Str(address))?;
    let p = cx.place_arg(a, "RemotePort")?;
    cx.store(&p, Value::Num(port as f32))?;
    Ok(Done::Next)
}

enum Target {
    Str(crate::machine::Place),
    Raw(crate::machine::Place),
    Data(crate::machine::Place),
}

/// `SocketClose Socket`: a socket not created (or closed already) is
/// left as it is.
pub(crate) fn socket_close(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = socket(cx, a, "Socket")?;
    if s != 0 {
        let r = cx.sh.sockets.close(s);
        if done(cx, a, r)?.is_none() {
            return waiting(cx);
        }
    }
    store_socket(cx, a, "Socket", 0)?;
    Ok(Done::Next)
}

/// `SocketGetStatus(Socket)`: the socket's state (`SOCKET_CONNECTED`...).
pub(crate) fn socket_get_status(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let s = socket(cx, a, "Socket")?;
    let state = if s == 0 {
        crate::world::SocketState::Closed
    } else {
        cx.sh.sockets.state(s)
    };
    cx.predefined(state.constant())
}

/// `SocketPeek(Socket)`: how many bytes have come in and wait to be read,
/// at once (a program polls with it instead of waiting in
/// `SocketReceive`).
pub(crate) fn socket_peek(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let s = socket(cx, a, "Socket")?;
    match cx.sh.sockets.peek(s) {
        Ok(n) => Ok(Value::Num(n as f32)),
        Err(e) => socket_error(cx, a, e),
    }
}
