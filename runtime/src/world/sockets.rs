//! Sockets (`SocketCreate`, `SocketConnect`, `SocketBind`,
//! `SocketListen`, `SocketAccept`, `SocketSend`, `SocketReceive`,
//! `SocketClose`, `SocketGetStatus`; UDP: `SocketCreate \UDP`,
//! `SocketSendTo`, `SocketReceiveFrom`), behind [`Sockets`]. [`NoSockets`]
//! (the default) has none: the instructions are not supported in the
//! simulation; `rapid run` gives real sockets of the host.
//!
//! Waits (`\Time` of `SocketConnect`, `SocketAccept`, `SocketReceive`) are
//! real time, bounded by the timeout given; the simulated clock moves by
//! the time waited.

/// Why a socket operation failed.
#[derive(Clone, Debug, PartialEq)]
pub enum SocketError {
    /// Sockets are not available in this simulation.
    Unsupported,
    /// The socket is closed, or the other side closed it
    /// (`ERR_SOCK_CLOSED`).
    Closed(String),
    /// Nothing came in time (`ERR_SOCK_TIMEOUT`).
    Timeout(String),
    /// Nothing will come: the task waits `after` simulated seconds (other
    /// tasks run meanwhile), then times out (`ERR_SOCK_TIMEOUT`).
    NeverAnswers { after: f64, message: String },
    /// Anything else the controller reports as a socket error (an address
    /// in use, an operation the socket's state does not allow):
    /// `ERR_SOCK_CLOSED` too, with the host's reason.
    Failed(String),
}

/// A socket's state, as `SocketGetStatus` gives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SocketState {
    Created,
    Connected,
    Bound,
    Listening,
    Closed,
}

impl SocketState {
    /// The `socketstatus` constant of the state.
    pub fn constant(self) -> &'static str {
        match self {
            SocketState::Created => "SOCKET_CREATED",
            SocketState::Connected => "SOCKET_CONNECTED",
            SocketState::Bound => "SOCKET_BOUND",
            SocketState::Listening => "SOCKET_LISTENING",
            SocketState::Closed => "SOCKET_CLOSED",
        }
    }
}

/// The controller's sockets; a socket is known by the number `create`
/// (or `accept`) gave it, from 1. Timeouts are in seconds.
pub trait Sockets: Send {
    fn create(&mut self, udp: bool) -> Result<u32, SocketError>;
    fn connect(
        &mut self,
        socket: u32,
        address: &str,
        port: u32,
        timeout: f64,
    ) -> Result<(), SocketError>;
    fn bind(&mut self, socket: u32, address: &str, port: u32) -> Result<(), SocketError>;
    fn listen(&mut self, socket: u32) -> Result<(), SocketError>;
    /// A connection that came in: the new socket's number and the other
    /// side's address.
    fn accept(&mut self, socket: u32, timeout: f64) -> Result<(u32, String), SocketError>;
    fn send(&mut self, socket: u32, data: &[u8]) -> Result<(), SocketError>;
    /// What has come in: at least one byte and at most `max`, or exactly
    /// `max` with `exact`.
    fn receive(
        &mut self,
        socket: u32,
        max: usize,
        exact: bool,
        timeout: f64,
    ) -> Result<Vec<u8>, SocketError>;
    fn close(&mut self, socket: u32) -> Result<(), SocketError>;
    fn state(&self, socket: u32) -> SocketState;
    /// A UDP datagram to `address:port` (a socket not bound yet is bound
    /// to any free port first).
    fn send_to(
        &mut self,
        _socket: u32,
        _address: &str,
        _port: u32,
        _data: &[u8],
    ) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    /// The next UDP datagram (at most `max` bytes of it; the rest is
    /// lost, as on the controller) and its sender's address and port.
    fn receive_from(
        &mut self,
        _socket: u32,
        _max: usize,
        _timeout: f64,
    ) -> Result<(Vec<u8>, String, u32), SocketError> {
        Err(SocketError::Unsupported)
    }
    /// How many bytes have come in and wait to be read (`SocketPeek`),
    /// without reading them and without waiting: the size of the next
    /// datagram on a UDP socket.
    fn peek(&mut self, _socket: u32) -> Result<usize, SocketError> {
        Err(SocketError::Unsupported)
    }
    /// The real seconds the sockets waited since this was last asked (the
    /// simulated clock moves by as much).
    fn waited(&mut self) -> f64 {
        0.0
    }
    /// The simulated clock moves from `from` to `to` seconds. Sockets with
    /// a real peer keep it from running ahead of real time while a socket
    /// is open, as the peer sees a controller's timing (a `WaitTime 0.1`
    /// in a polling loop takes 0.1 s).
    fn pace(&mut self, _from: f64, _to: f64) {}
}

/// No sockets.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoSockets;

impl Sockets for NoSockets {
    fn create(&mut self, _: bool) -> Result<u32, SocketError> {
        Err(SocketError::Unsupported)
    }
    fn connect(&mut self, _: u32, _: &str, _: u32, _: f64) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn bind(&mut self, _: u32, _: &str, _: u32) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn listen(&mut self, _: u32) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn accept(&mut self, _: u32, _: f64) -> Result<(u32, String), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn send(&mut self, _: u32, _: &[u8]) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn receive(&mut self, _: u32, _: usize, _: bool, _: f64) -> Result<Vec<u8>, SocketError> {
        Err(SocketError::Unsupported)
    }
    fn close(&mut self, _: u32) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn state(&self, _: u32) -> SocketState {
        SocketState::Closed
    }
}

/// A controller on a network where nobody answers: sockets are created,
/// bound and listen, but a connection never comes and a connect gets no
/// answer, each after its whole `\Time` (simulated); a receive or send on
/// a socket that is not connected fails as closed. A UDP datagram is sent
/// (nobody hears it) and none comes. The default of
/// [`super::World::simulated`]: deterministic, and a program that waits
/// for its peer waits as it would in a cell with the peer switched off.
#[derive(Debug, Default)]
pub struct EmptyNetwork {
    states: Vec<SocketState>,
    /// The UDP sockets' numbers.
    udp: Vec<u32>,
}

/// `WAIT_MAX`, the largest time a wait takes: a wait that long waits
/// forever.
pub const WAIT_MAX: f64 = 8_388_608.0;

impl EmptyNetwork {
    fn slot(&mut self, socket: u32) -> Result<&mut SocketState, SocketError> {
        match self.states.get_mut((socket as usize).wrapping_sub(1)) {
            Some(s) if *s != SocketState::Closed => Ok(s),
            _ => Err(SocketError::Closed(
                "the socket is not created, or closed".to_owned(),
            )),
        }
    }

    fn nobody(&mut self, timeout: f64, what: &str) -> SocketError {
        let message = if timeout >= WAIT_MAX {
            format!("{what}: nobody on the network, and WAIT_MAX waits forever")
        } else {
            format!(
                "{what} within {} s (nobody on the network)",
                super::num_text(timeout)
            )
        };
        SocketError::NeverAnswers {
            after: timeout,
            message,
        }
    }
}

impl Sockets for EmptyNetwork {
    fn create(&mut self, udp: bool) -> Result<u32, SocketError> {
        self.states.push(SocketState::Created);
        let id = self.states.len() as u32;
        if udp {
            self.udp.push(id);
        }
        Ok(id)
    }
    fn connect(
        &mut self,
        socket: u32,
        address: &str,
        port: u32,
        timeout: f64,
    ) -> Result<(), SocketError> {
        self.slot(socket)?;
        if self.udp.contains(&socket) {
            return Err(SocketError::Failed(
                "a UDP socket does not connect".to_owned(),
            ));
        }
        Err(self.nobody(timeout, &format!("no connection to {address}:{port}")))
    }
    fn send_to(&mut self, socket: u32, _: &str, _: u32, _: &[u8]) -> Result<(), SocketError> {
        self.slot(socket)?;
        if !self.udp.contains(&socket) {
            return Err(SocketError::Failed(
                "the socket is not a UDP socket".to_owned(),
            ));
        }
        Ok(())
    }
    fn receive_from(
        &mut self,
        socket: u32,
        _: usize,
        timeout: f64,
    ) -> Result<(Vec<u8>, String, u32), SocketError> {
        if *self.slot(socket)? != SocketState::Bound || !self.udp.contains(&socket) {
            return Err(SocketError::Failed(
                "the socket is not a bound UDP socket".to_owned(),
            ));
        }
        Err(self.nobody(timeout, "no datagram came"))
    }
    fn bind(&mut self, socket: u32, _: &str, _: u32) -> Result<(), SocketError> {
        *self.slot(socket)? = SocketState::Bound;
        Ok(())
    }
    fn listen(&mut self, socket: u32) -> Result<(), SocketError> {
        if self.udp.contains(&socket) {
            return Err(SocketError::Failed(
                "a UDP socket does not listen".to_owned(),
            ));
        }
        let s = self.slot(socket)?;
        if *s != SocketState::Bound {
            return Err(SocketError::Failed("the socket is not bound".to_owned()));
        }
        *s = SocketState::Listening;
        Ok(())
    }
    fn accept(&mut self, socket: u32, timeout: f64) -> Result<(u32, String), SocketError> {
        if *self.slot(socket)? != SocketState::Listening {
            return Err(SocketError::Failed(
                "the socket is not listening".to_owned(),
            ));
        }
        Err(self.nobody(timeout, "no connection came"))
    }
    fn send(&mut self, socket: u32, _: &[u8]) -> Result<(), SocketError> {
        self.slot(socket)?;
        Err(SocketError::Closed(
            "the socket is not connected".to_owned(),
        ))
    }
    fn receive(&mut self, socket: u32, _: usize, _: bool, _: f64) -> Result<Vec<u8>, SocketError> {
        self.slot(socket)?;
        Err(SocketError::Closed(
            "the socket is not connected".to_owned(),
        ))
    }
    fn peek(&mut self, socket: u32) -> Result<usize, SocketError> {
        if *self.slot(socket)? == SocketState::Bound && self.udp.contains(&socket) {
            return Ok(0);
        }
        Err(SocketError::Closed(
            "the socket is not connected".to_owned(),
        ))
    }
    fn close(&mut self, socket: u32) -> Result<(), SocketError> {
        if let Ok(s) = self.slot(socket) {
            *s = SocketState::Closed;
        }
        Ok(())
    }
    fn state(&self, socket: u32) -> SocketState {
        self.states
            .get((socket as usize).wrapping_sub(1))
            .copied()
            .unwrap_or(SocketState::Closed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn never(e: Result<(u32, String), SocketError>) -> (f64, String) {
        match e {
            Err(SocketError::NeverAnswers { after, message }) => (after, message),
            other => panic!("not a wait nobody ends: {other:?}"),
        }
    }

    #[test]
    fn nobody_connects_within_the_time_or_ever() {
        let mut net = EmptyNetwork::default();
        let s = net.create(false).expect("created");
        net.bind(s, "192.168.125.1", 1025).expect("bound");
        net.listen(s).expect("listening");
        let (after, message) = never(net.accept(s, 10.0));
        assert_eq!(after, 10.0);
        assert!(
            message.ends_with("within 10 s (nobody on the network)"),
            "{message}"
        );
        let (_, message) = never(net.accept(s, 8_388_608.0));
        assert!(
            message.ends_with(": nobody on the network, and WAIT_MAX waits forever"),
            "{message}"
        );
    }
}
