//! Sockets (`SocketCreate`, `SocketConnect`, `SocketSend`,
//! `SocketReceive`, `SocketClose`), behind [`Sockets`]. [`NoSockets`] (the
//! default) has none: the instructions are not supported in the
//! simulation.

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
}

/// The controller's sockets; a socket is known by the number `create`
/// gave it.
pub trait Sockets: Send {
    fn create(&mut self) -> Result<u32, SocketError>;
    fn connect(&mut self, socket: u32, address: &str, port: u32) -> Result<(), SocketError>;
    fn send(&mut self, socket: u32, data: &[u8]) -> Result<(), SocketError>;
    /// What has come in (up to a message).
    fn receive(&mut self, socket: u32) -> Result<Vec<u8>, SocketError>;
    fn close(&mut self, socket: u32) -> Result<(), SocketError>;
}

/// No sockets.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoSockets;

impl Sockets for NoSockets {
    fn create(&mut self) -> Result<u32, SocketError> {
        Err(SocketError::Unsupported)
    }
    fn connect(&mut self, _: u32, _: &str, _: u32) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn send(&mut self, _: u32, _: &[u8]) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
    fn receive(&mut self, _: u32) -> Result<Vec<u8>, SocketError> {
        Err(SocketError::Unsupported)
    }
    fn close(&mut self, _: u32) -> Result<(), SocketError> {
        Err(SocketError::Unsupported)
    }
}
