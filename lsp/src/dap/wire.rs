//! The Debug Adapter Protocol's framing: `Content-Length` headers and
//! JSON bodies, read from stdin and written to stdout (each message whole,
//! under a lock, with the adapter's own sequence numbers).

use std::io::{self, BufRead, Write};
use std::sync::atomic::{AtomicI64, Ordering};
use std::sync::{Arc, Mutex};

use serde_json::{Value, json};

/// Reads one message; `Ok(None)` at the end of the input.
pub fn read_message(input: &mut impl BufRead) -> io::Result<Option<Value>> {
    let mut length: Option<usize> = None;
    loop {
        let mut line = String::new();
        if input.read_line(&mut line)? == 0 {
            return Ok(None);
        }
        let line = line.trim_end_matches(['\r', '\n']);
        if line.is_empty() {
            if length.is_some() {
                break;
            }
            continue;
        }
        if let Some((name, value)) = line.split_once(':')
            && name.trim().eq_ignore_ascii_case("content-length")
        {
            length = value.trim().parse().ok();
        }
    }
    let n = length.unwrap_or(0);
    if n > MAX_MESSAGE {
        return Err(io::Error::new(
            io::ErrorKind::InvalidData,
            format!("a message of {n} bytes (the limit is {MAX_MESSAGE})"),
        ));
    }
    let mut body = vec![0; n];
    input.read_exact(&mut body)?;
    serde_json::from_slice(&body)
        .map(Some)
        .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))
}

/// The largest message read (a client sends nothing near this).
const MAX_MESSAGE: usize = 64 << 20;

/// Writes messages to the client; shared by the threads of the adapter.
#[derive(Clone)]
pub struct Writer {
    out: Arc<Mutex<Box<dyn Write + Send>>>,
    seq: Arc<AtomicI64>,
}

impl Writer {
    pub fn new(out: Box<dyn Write + Send>) -> Writer {
        Writer {
            out: Arc::new(Mutex::new(out)),
            seq: Arc::new(AtomicI64::new(1)),
        }
    }

    fn send(&self, mut message: Value) {
        message["seq"] = json!(self.seq.fetch_add(1, Ordering::Relaxed));
        let body = message.to_string();
        if let Ok(mut out) = self.out.lock() {
            let _ = write!(out, "Content-Length: {}\r\n\r\n{body}", body.len());
            let _ = out.flush();
        }
    }

    /// A successful response to `request`, with `body`.
    pub fn respond(&self, request: &Value, body: Value) {
        self.send(json!({
            "type": "response",
            "request_seq": request["seq"],
            "command": request["command"],
            "success": true,
            "body": body,
        }));
    }

    /// A failed response to `request`.
    pub fn fail(&self, request: &Value, message: &str) {
        self.send(json!({
            "type": "response",
            "request_seq": request["seq"],
            "command": request["command"],
            "success": false,
            "message": message,
            "body": { "error": { "id": 1, "format": message } },
        }));
    }

    pub fn event(&self, event: &str, body: Value) {
        self.send(json!({ "type": "event", "event": event, "body": body }));
    }
}
