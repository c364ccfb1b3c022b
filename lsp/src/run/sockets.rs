//! The sockets of `rapid run`: real TCP and UDP sockets of the host. An address
//! the program names (`SocketConnect sock, "192.168.125.1", 1025`,
//! `SocketBind`) goes to the loopback interface with the same port,
//! unless `--socket-map ADDR:PORT=HOST:PORT` sends it elsewhere. So the
//! robot side of a PC-robot protocol runs on a laptop, and the PC side
//! (or a test) talks to it.

use std::collections::HashMap;
use std::io::{ErrorKind, Read, Write};
use std::net::{SocketAddr, TcpListener, TcpStream, ToSocketAddrs, UdpSocket};
use std::time::{Duration, Instant};

use rapid_runtime::world::{SocketError, SocketState, Sockets};

/// How often a wait looks again (connection refused, nothing to accept).
const RETRY: Duration = Duration::from_millis(20);

/// `--socket-map ADDR:PORT=HOST:PORT`: the controller's address and
/// port, and where the host reaches it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SocketMap {
    pub address: String,
    pub port: u32,
    pub host: SocketAddr,
}

/// Parses a `--socket-map` option.
pub fn parse_map(text: &str) -> Result<SocketMap, String> {
    let bad = || format!("--socket-map {text}: expected ADDR:PORT=HOST:PORT");
    let (from, to) = text.split_once('=').ok_or_else(bad)?;
    let (address, port) = from.trim().rsplit_once(':').ok_or_else(bad)?;
    let port: u32 = port.parse().map_err(|_| bad())?;
    let host = to
        .trim()
        .to_socket_addrs()
        .map_err(|e| format!("--socket-map {text}: {e}"))?
        .next()
        .ok_or_else(bad)?;
    Ok(SocketMap {
        address: address.to_owned(),
        port,
        host,
    })
}

enum Sock {
    Created,
    /// A UDP socket not bound yet (`SocketCreate \UDP`).
    CreatedUdp,
    /// A bound UDP socket.
    Udp(UdpSocket),
    Listener {
        listener: TcpListener,
        listening: bool,
    },
    Stream(TcpStream),
}

/// The host's sockets, as the controller's.
pub struct HostSockets {
    map: Vec<SocketMap>,
    socks: HashMap<u32, Sock>,
    next: u32,
    waited: Duration,
    /// While a socket is open: a real instant and the simulated time
    /// then, from which the simulated clock may not run ahead.
    anchor: Option<(Instant, f64)>,
}

impl HostSockets {
    pub fn new(map: Vec<SocketMap>) -> HostSockets {
        HostSockets {
            map,
            socks: HashMap::new(),
            next: 1,
            waited: Duration::ZERO,
            anchor: None,
        }
    }

    /// Where the host reaches the controller's `address:port`.
    fn target(&self, address: &str, port: u32) -> Result<SocketAddr, SocketError> {
        if let Some(m) = self
            .map
            .iter()
            .find(|m| m.port == port && m.address.eq_ignore_ascii_case(address))
        {
            return Ok(m.host);
        }
        let port = u16::try_from(port)
            .map_err(|_| SocketError::Failed(format!("{port} is not a port number")))?;
        Ok(SocketAddr::from(([127, 0, 0, 1], port)))
    }

    fn sock(&mut self, id: u32) -> Result<&mut Sock, SocketError> {
        self.socks
            .get_mut(&id)
            .ok_or_else(|| SocketError::Closed("the socket is not created, or closed".to_owned()))
    }

    fn stream(&mut self, id: u32) -> Result<&mut TcpStream, SocketError> {
        match self.sock(id)? {
            Sock::Stream(s) => Ok(s),
            _ => Err(SocketError::Failed(
                "the socket is not connected".to_owned(),
            )),
        }
    }

    fn add(&mut self, s: Sock) -> u32 {
        let id = self.next;
        self.next += 1;
        self.socks.insert(id, s);
        id
    }
}

fn closed(e: &std::io::Error) -> SocketError {
    SocketError::Closed(format!("the connection is closed ({e})"))
}

impl Sockets for HostSockets {
    fn create(&mut self, udp: bool) -> Result<u32, SocketError> {
        Ok(self.add(if udp { Sock::CreatedUdp } else { Sock::Created }))
    }

    fn send_to(
        &mut self,
        socket: u32,
        address: &str,
        port: u32,
        data: &[u8],
    ) -> Result<(), SocketError> {
        let target = self.target(address, port)?;
        if matches!(self.sock(socket)?, Sock::CreatedUdp) {
            let any = UdpSocket::bind(SocketAddr::from(([127, 0, 0, 1], 0)))
                .map_err(|e| SocketError::Failed(format!("cannot bind a UDP socket: {e}")))?;
            self.socks.insert(socket, Sock::Udp(any));
        }
        let Sock::Udp(s) = self.sock(socket)? else {
            return Err(SocketError::Failed(
                "the socket is not a UDP socket".to_owned(),
            ));
        };
        s.send_to(data, target)
            .map(|_| ())
            .map_err(|e| SocketError::Failed(format!("{address}:{port} ({target}): {e}")))
    }

    fn receive_from(
        &mut self,
        socket: u32,
        max: usize,
        timeout: f64,
    ) -> Result<(Vec<u8>, String, u32), SocketError> {
        let Sock::Udp(s) = self.sock(socket)? else {
            return Err(SocketError::Failed(
                "the socket is not a bound UDP socket".to_owned(),
            ));
        };
        let start = Instant::now();
        let limit = Duration::from_secs_f64(timeout.max(0.001));
        // A datagram longer than `max` is cut: read it whole, keep `max`.
        let mut buf = vec![0u8; 65_536];
        let result = loop {
            let left = limit.saturating_sub(start.elapsed());
            if left.is_zero() {
                break Err(SocketError::Timeout(format!(
                    "no datagram came within {timeout} s"
                )));
            }
            if let Err(e) = s.set_read_timeout(Some(left)) {
                break Err(SocketError::Failed(e.to_string()));
            }
            match s.recv_from(&mut buf) {
                Ok((n, peer)) => break Ok((n, peer)),
                Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => {}
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                Err(e) => break Err(SocketError::Failed(e.to_string())),
            }
        };
        self.waited += start.elapsed();
        let (n, peer) = result?;
        buf.truncate(n.min(max));
        Ok((buf, peer.ip().to_string(), u32::from(peer.port())))
    }

    fn connect(
        &mut self,
        socket: u32,
        address: &str,
        port: u32,
        timeout: f64,
    ) -> Result<(), SocketError> {
        if !matches!(self.sock(socket)?, Sock::Created) {
            return Err(SocketError::Failed(
                "the socket is connected or bound already".to_owned(),
            ));
        }
        let target = self.target(address, port)?;
        let start = Instant::now();
        let limit = Duration::from_secs_f64(timeout);
        let result = loop {
            let left = limit.saturating_sub(start.elapsed());
            if left.is_zero() {
                break Err(SocketError::Timeout(format!(
                    "no connection to {address}:{port} ({target}) within {timeout} s"
                )));
            }
            match TcpStream::connect_timeout(&target, left) {
                Ok(s) => break Ok(s),
                Err(e) if e.kind() == ErrorKind::TimedOut => continue,
                // Refused: the other side is not listening yet.
                Err(_) => std::thread::sleep(RETRY.min(left)),
            }
        };
        self.waited += start.elapsed();
        let stream = result?;
        let _ = stream.set_nodelay(true);
        self.socks.insert(socket, Sock::Stream(stream));
        Ok(())
    }

    fn bind(&mut self, socket: u32, address: &str, port: u32) -> Result<(), SocketError> {
        let udp = match self.sock(socket)? {
            Sock::Created => false,
            Sock::CreatedUdp => true,
            _ => {
                return Err(SocketError::Failed(
                    "the socket is connected or bound already".to_owned(),
                ));
            }
        };
        let target = self.target(address, port)?;
        if udp {
            let s = UdpSocket::bind(target).map_err(|e| {
                SocketError::Failed(format!("cannot bind {address}:{port} ({target}): {e}"))
            })?;
            self.socks.insert(socket, Sock::Udp(s));
            return Ok(());
        }
        let listener = TcpListener::bind(target).map_err(|e| {
            SocketError::Failed(format!("cannot bind {address}:{port} ({target}): {e}"))
        })?;
        self.socks.insert(
            socket,
            Sock::Listener {
                listener,
                listening: false,
            },
        );
        Ok(())
    }

    fn listen(&mut self, socket: u32) -> Result<(), SocketError> {
        match self.sock(socket)? {
            Sock::Listener { listening, .. } => {
                *listening = true;
                Ok(())
            }
            _ => Err(SocketError::Failed("the socket is not bound".to_owned())),
        }
    }

    fn accept(&mut self, socket: u32, timeout: f64) -> Result<(u32, String), SocketError> {
        let listener = match self.sock(socket)? {
            Sock::Listener {
                listener,
                listening: true,
            } => listener,
            _ => {
                return Err(SocketError::Failed(
                    "the socket is not listening".to_owned(),
                ));
            }
        };
        listener
            .set_nonblocking(true)
            .map_err(|e| SocketError::Failed(e.to_string()))?;
        let start = Instant::now();
        let limit = Duration::from_secs_f64(timeout);
        let result = loop {
            match listener.accept() {
                Ok(pair) => break Ok(pair),
                Err(e) if e.kind() == ErrorKind::WouldBlock => {
                    let left = limit.saturating_sub(start.elapsed());
                    if left.is_zero() {
                        break Err(SocketError::Timeout(format!(
                            "no connection came within {timeout} s"
                        )));
                    }
                    std::thread::sleep(RETRY.min(left));
                }
                Err(e) => break Err(SocketError::Failed(e.to_string())),
            }
        };
        self.waited += start.elapsed();
        let (stream, peer) = result?;
        let _ = stream.set_nonblocking(false);
        let _ = stream.set_nodelay(true);
        let id = self.add(Sock::Stream(stream));
        Ok((id, peer.ip().to_string()))
    }

    fn send(&mut self, socket: u32, data: &[u8]) -> Result<(), SocketError> {
        let s = self.stream(socket)?;
        s.write_all(data).map_err(|e| closed(&e))
    }

    fn receive(
        &mut self,
        socket: u32,
        max: usize,
        exact: bool,
        timeout: f64,
    ) -> Result<Vec<u8>, SocketError> {
        let start = Instant::now();
        let limit = Duration::from_secs_f64(timeout.max(0.001));
        let s = self.stream(socket)?;
        let mut out = vec![0u8; max];
        let mut got = 0;
        let result = loop {
            let left = limit.saturating_sub(start.elapsed());
            if left.is_zero() {
                break Err(SocketError::Timeout(format!(
                    "nothing came within {timeout} s"
                )));
            }
            if let Err(e) = s.set_read_timeout(Some(left)) {
                break Err(SocketError::Failed(e.to_string()));
            }
            match s.read(&mut out[got..]) {
                Ok(0) if max > 0 => {
                    break Err(SocketError::Closed(
                        "the other side closed the connection".to_owned(),
                    ));
                }
                Ok(n) => {
                    got += n;
                    if !exact || got == max {
                        break Ok(());
                    }
                }
                Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => {}
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                Err(e) => break Err(closed(&e)),
            }
        };
        self.waited += start.elapsed();
        result?;
        out.truncate(got);
        Ok(out)
    }

    fn peek(&mut self, socket: u32) -> Result<usize, SocketError> {
        let mut buf = vec![0u8; 65_536];
        match self.sock(socket)? {
            Sock::Stream(s) => {
                let _ = s.set_nonblocking(true);
                let r = match s.peek(&mut buf) {
                    Ok(0) => Err(SocketError::Closed(
                        "the other side closed the connection".to_owned(),
                    )),
                    Ok(n) => Ok(n),
                    Err(e) if e.kind() == ErrorKind::WouldBlock => Ok(0),
                    Err(e) => Err(closed(&e)),
                };
                let _ = s.set_nonblocking(false);
                r
            }
            Sock::Udp(s) => {
                let _ = s.set_nonblocking(true);
                let r = match s.peek_from(&mut buf) {
                    Ok((n, _)) => Ok(n),
                    Err(e) if e.kind() == ErrorKind::WouldBlock => Ok(0),
                    Err(e) => Err(SocketError::Failed(e.to_string())),
                };
                let _ = s.set_nonblocking(false);
                r
            }
            _ => Err(SocketError::Failed(
                "the socket is not connected".to_owned(),
            )),
        }
    }

    fn close(&mut self, socket: u32) -> Result<(), SocketError> {
        if let Some(Sock::Stream(s)) = self.socks.remove(&socket) {
            let _ = s.shutdown(std::net::Shutdown::Both);
        }
        Ok(())
    }

    fn state(&self, socket: u32) -> SocketState {
        match self.socks.get(&socket) {
            None => SocketState::Closed,
            Some(Sock::Created | Sock::CreatedUdp) => SocketState::Created,
            Some(Sock::Udp(_)) => SocketState::Bound,
            Some(Sock::Listener {
                listening: false, ..
            }) => SocketState::Bound,
            Some(Sock::Listener { .. }) => SocketState::Listening,
            Some(Sock::Stream(_)) => SocketState::Connected,
        }
    }

    fn waited(&mut self) -> f64 {
        std::mem::take(&mut self.waited).as_secs_f64()
    }

    fn pace(&mut self, from: f64, to: f64) {
        if self.socks.is_empty() {
            self.anchor = None;
            return;
        }
        let (real, simulated) = *self.anchor.get_or_insert((Instant::now(), from));
        let ahead = Duration::try_from_secs_f64(to - simulated).unwrap_or(Duration::ZERO);
        let due = real + ahead;
        let now = Instant::now();
        if due > now {
            std::thread::sleep(due - now);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn socket_maps_parse_or_say_what_is_wrong() {
        let m = parse_map("192.168.125.1:1025=127.0.0.1:40000").expect("valid");
        assert_eq!(
            (m.address.as_str(), m.port, m.host.port()),
            ("192.168.125.1", 1025, 40000)
        );
        assert!(parse_map("192.168.125.1=127.0.0.1:1").is_err());
        assert!(parse_map("a:x=127.0.0.1:1").is_err());
        assert!(parse_map("a:1").is_err());
    }
}
