//! Sockets (`SocketCreate`, `SocketConnect`, `SocketBind`,
//! `SocketListen`, `SocketAccept`, `SocketSend`, `SocketReceive`,
//! `SocketClose`, `SocketGetStatus`), behind [`Sockets`]. [`NoSockets`]
//! (the default) has none: the instructions are not supported in the
//! simulation; `rapid run` gives real sockets of the host.
//!
//! Waits (`\Time` of `SocketConnect`, `SocketAccept`, `SocketReceive`) are
//! real time, bounded by the timeout given; the simulated clock moves by
//! the time waited.

/// Why a socket operation failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SocketError {
    /// Sockets are not available in this simulation.
    Unsupported,
    /// The socket is closed, or the other side closed it
    /// (`ERR_SOCK_CLOSED`).
    Closed(String),
    /// Nothing came in time (`ERR_SOCK_TIMEOUT`).
    Timeout(String),
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
    /// The real seconds the sockets waited since this was last asked (the
    /// simulated clock moves by as much).
    fn waited(&mut self) -> f64 {
        0.0
    }
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
