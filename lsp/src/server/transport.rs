//! The stdio transport, hardened.
//!
//! `tower-lsp-server` stops reading its input after the first message it
//! cannot decode (its framed reader ends the stream on a decoder error), so a
//! single malformed message would leave the editor with a deaf server. The
//! protocol wants a parse error (or invalid request) answer and the server
//! serving on. So the raw input is framed here first: well-formed JSON-RPC
//! messages are passed on to the server byte for byte; anything else is
//! answered here, with a JSON-RPC error, and dropped. Answers from both
//! sources are written to the output whole frame by whole frame.

use std::future::poll_fn;
use std::pin::Pin;
use std::task::{Context, Poll};

use serde_json::{Value, json};
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::sync::mpsc::{UnboundedReceiver, UnboundedSender, unbounded_channel};
use tower_lsp_server::jsonrpc::{Request, Response};

/// The reading end of an in-memory byte pipe.
pub struct PipeReader {
    rx: UnboundedReceiver<Vec<u8>>,
    buf: Vec<u8>,
    pos: usize,
}

impl AsyncRead for PipeReader {
    fn poll_read(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        out: &mut ReadBuf<'_>,
    ) -> Poll<std::io::Result<()>> {
        while self.pos == self.buf.len() {
            match self.rx.poll_recv(cx) {
                Poll::Ready(Some(chunk)) => {
                    self.buf = chunk;
                    self.pos = 0;
                }
                Poll::Ready(None) => return Poll::Ready(Ok(())),
                Poll::Pending => return Poll::Pending,
            }
        }
        let n = out.remaining().min(self.buf.len() - self.pos);
        let pos = self.pos;
        out.put_slice(&self.buf[pos..pos + n]);
        self.pos += n;
        Poll::Ready(Ok(()))
    }
}

/// The writing end of an in-memory byte pipe (never blocks).
pub struct PipeWriter {
    pub tx: UnboundedSender<Vec<u8>>,
}

impl AsyncWrite for PipeWriter {
    fn poll_write(
        self: Pin<&mut Self>,
        _: &mut Context<'_>,
        data: &[u8],
    ) -> Poll<std::io::Result<usize>> {
        match self.tx.send(data.to_vec()) {
            Ok(()) => Poll::Ready(Ok(data.len())),
            Err(_) => Poll::Ready(Err(std::io::ErrorKind::BrokenPipe.into())),
        }
    }

    fn poll_flush(self: Pin<&mut Self>, _: &mut Context<'_>) -> Poll<std::io::Result<()>> {
        Poll::Ready(Ok(()))
    }

    fn poll_shutdown(self: Pin<&mut Self>, _: &mut Context<'_>) -> Poll<std::io::Result<()>> {
        Poll::Ready(Ok(()))
    }
}

impl PipeReader {
    #[cfg(test)]
    pub fn into_receiver(self) -> UnboundedReceiver<Vec<u8>> {
        self.rx
    }
}

pub fn pipe() -> (PipeWriter, PipeReader) {
    let (tx, rx) = unbounded_channel();
    (
        PipeWriter { tx },
        PipeReader {
            rx,
            buf: Vec::new(),
            pos: 0,
        },
    )
}

/// Splits a byte stream into `Content-Length` frames.
#[derive(Default)]
pub struct Framer {
    buf: Vec<u8>,
}

/// One frame, or a header block that cannot be used.
#[derive(Debug, PartialEq, Eq)]
pub enum Frame {
    Message(Vec<u8>),
    BadHeader(String),
}

impl Framer {
    pub fn push(&mut self, bytes: &[u8]) {
        self.buf.extend_from_slice(bytes);
    }

    /// The next complete frame's body, if any.
    pub fn next_frame(&mut self) -> Option<Frame> {
        let Some(end) = find(&self.buf[..self.buf.len().min(MAX_HEADER)], b"\r\n\r\n") else {
            if self.buf.len() < MAX_HEADER {
                return None;
            }
            // No header ends in the first bytes: junk. Drop it up to the
            // next header (each byte is looked at once, however long the
            // junk runs).
            let next = find(&self.buf[1..], b"Content-Length").map_or(self.buf.len(), |i| i + 1);
            self.buf.drain(..next);
            return Some(Frame::BadHeader(format!(
                "{next} bytes without a message header"
            )));
        };
        let header = String::from_utf8_lossy(&self.buf[..end]).into_owned();
        let length = header.split("\r\n").find_map(|line| {
            let (name, value) = line.split_once(':')?;
            name.trim()
                .eq_ignore_ascii_case("content-length")
                .then(|| value.trim().parse::<usize>().ok())?
        });
        let Some(length) = length else {
            // Skip the header block, and any junk up to the next header.
            self.buf.drain(..end + 4);
            let next = find(&self.buf, b"Content-Length").unwrap_or(self.buf.len());
            self.buf.drain(..next);
            return Some(Frame::BadHeader(format!(
                "a message header without a valid Content-Length: {header:?}"
            )));
        };
        let start = end + 4;
        if self.buf.len() < start.saturating_add(length) {
            return None;
        }
        let body = self.buf[start..start + length].to_vec();
        self.buf.drain(..start + length);
        Some(Frame::Message(body))
    }
}

/// The longest header block looked for: real ones are under 100 bytes.
const MAX_HEADER: usize = 8 * 1024;

fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    haystack.windows(needle.len()).position(|w| w == needle)
}

pub fn encode(body: &[u8]) -> Vec<u8> {
    let mut out = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
    out.extend_from_slice(body);
    out
}

/// The `$/` requests the server answers itself (none: `$/cancelRequest`
/// and `$/setTrace` are notifications).
const KNOWN_DOLLAR_REQUESTS: &[&str] = &[];

/// Checks a message body; returns the error answer for a bad one, or for a
/// request the server would leave unanswered.
pub fn check_message(body: &[u8]) -> Result<(), Value> {
    let error = |id: Value, code: i64, message: String| json!({"jsonrpc": "2.0", "id": id, "error": {"code": code, "message": message}});
    let Ok(text) = std::str::from_utf8(body) else {
        return Err(error(
            Value::Null,
            -32700,
            "parse error: the message is not UTF-8".to_owned(),
        ));
    };
    let value: Value = match serde_json::from_str(text) {
        Ok(v) => v,
        Err(e) => return Err(error(Value::Null, -32700, format!("parse error: {e}"))),
    };
    let id = value.get("id").cloned().unwrap_or(Value::Null);
    // Requests whose method starts with `$/` are optional for a server,
    // which must answer the ones it does not know with MethodNotFound (the
    // server's framework leaves them unanswered); notifications are ignored.
    if let Some(method) = value.get("method").and_then(Value::as_str)
        && method.starts_with("$/")
        && (id.is_string() || id.is_number())
        && !KNOWN_DOLLAR_REQUESTS.contains(&method)
    {
        return Err(error(id, -32601, format!("method not found: {method}")));
    }
    let is_request = serde_json::from_value::<Request>(value.clone()).is_ok();
    let is_response = !is_request && serde_json::from_value::<Response>(value).is_ok();
    if is_request || is_response {
        Ok(())
    } else {
        let id = if id.is_string() || id.is_number() {
            id
        } else {
            Value::Null
        };
        Err(error(
            id,
            -32600,
            "invalid request: not a JSON-RPC 2.0 message".to_owned(),
        ))
    }
}

async fn read_some<R: AsyncRead + Unpin>(input: &mut R, buf: &mut [u8]) -> std::io::Result<usize> {
    poll_fn(|cx| {
        let mut read = ReadBuf::new(buf);
        match Pin::new(&mut *input).poll_read(cx, &mut read) {
            Poll::Ready(Ok(())) => Poll::Ready(Ok(read.filled().len())),
            Poll::Ready(Err(e)) => Poll::Ready(Err(e)),
            Poll::Pending => Poll::Pending,
        }
    })
    .await
}

async fn write_all<W: AsyncWrite + Unpin>(output: &mut W, mut data: &[u8]) -> std::io::Result<()> {
    while !data.is_empty() {
        let n = poll_fn(|cx| Pin::new(&mut *output).poll_write(cx, data)).await?;
        if n == 0 {
            return Err(std::io::ErrorKind::WriteZero.into());
        }
        data = &data[n..];
    }
    poll_fn(|cx| Pin::new(&mut *output).poll_flush(cx)).await
}

/// Is this message the `exit` notification? (Cheap: only short messages
/// that spell it are parsed.)
fn is_exit(body: &[u8]) -> bool {
    body.len() < 256
        && body.windows(6).any(|w| w == b"\"exit\"")
        && serde_json::from_slice::<Value>(body).is_ok_and(|v| {
            v.get("method").and_then(Value::as_str) == Some("exit") && v.get("id").is_none()
        })
}

/// Reads `input`, passing well-formed messages to `to_server` and answering
/// the others on `to_output`. Ends at the end of the input, or after
/// passing on the `exit` notification (a client need not close the input
/// after it).
pub async fn filter_input<R: AsyncRead + Unpin>(
    mut input: R,
    to_server: UnboundedSender<Vec<u8>>,
    to_output: UnboundedSender<Vec<u8>>,
) {
    let mut framer = Framer::default();
    let mut buf = vec![0u8; 64 * 1024];
    loop {
        let n = match read_some(&mut input, &mut buf).await {
            Ok(0) | Err(_) => return,
            Ok(n) => n,
        };
        framer.push(&buf[..n]);
        while let Some(frame) = framer.next_frame() {
            match frame {
                Frame::Message(body) => match check_message(&body) {
                    Ok(()) => {
                        if to_server.send(encode(&body)).is_err() || is_exit(&body) {
                            return;
                        }
                    }
                    Err(answer) => {
                        if answer["error"]["code"] == -32601 {
                            eprintln!("rapid lsp: {}", answer["error"]["message"]);
                        } else {
                            eprintln!("rapid lsp: a malformed message was answered with an error");
                        }
                        let _ = to_output.send(encode(answer.to_string().as_bytes()));
                    }
                },
                Frame::BadHeader(why) => {
                    eprintln!("rapid lsp: {why}");
                    let answer = json!({"jsonrpc": "2.0", "id": null, "error": {"code": -32700, "message": format!("parse error: {why}")}});
                    let _ = to_output.send(encode(answer.to_string().as_bytes()));
                }
            }
        }
    }
}

/// Re-frames the server's output so frames from both sources never
/// interleave.
pub async fn forward_frames(mut from_server: PipeReader, to_output: UnboundedSender<Vec<u8>>) {
    let mut framer = Framer::default();
    let mut buf = vec![0u8; 64 * 1024];
    loop {
        let n = match read_some(&mut from_server, &mut buf).await {
            Ok(0) | Err(_) => return,
            Ok(n) => n,
        };
        framer.push(&buf[..n]);
        while let Some(frame) = framer.next_frame() {
            if let Frame::Message(body) = frame
                && to_output.send(encode(&body)).is_err()
            {
                return;
            }
        }
    }
}

/// Writes whole frames to the output until every sender is gone.
pub async fn write_output<W: AsyncWrite + Unpin>(
    mut output: W,
    mut frames: UnboundedReceiver<Vec<u8>>,
) {
    while let Some(frame) = frames.recv().await {
        if write_all(&mut output, &frame).await.is_err() {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_split_and_resynchronise() {
        let mut f = Framer::default();
        f.push(b"Content-Length: 2\r\n\r\n{}Content-Len");
        assert_eq!(f.next_frame(), Some(Frame::Message(b"{}".to_vec())));
        assert_eq!(f.next_frame(), None);
        f.push(b"gth: 3\r\n\r\nabc");
        assert_eq!(f.next_frame(), Some(Frame::Message(b"abc".to_vec())));
        f.push(b"X-Junk: 1\r\n\r\ngarbage Content-Length: 1\r\ncontent-type: application/vscode-jsonrpc; charset=utf-8\r\n\r\nx");
        assert!(matches!(f.next_frame(), Some(Frame::BadHeader(_))));
        assert_eq!(f.next_frame(), Some(Frame::Message(b"x".to_vec())));
    }

    #[test]
    fn junk_without_a_header_is_dropped_as_it_comes() {
        let mut f = Framer::default();
        // Megabytes of bytes that never end a header: dropped in pieces,
        // each looked at a bounded number of times, and the next message
        // still comes through.
        let junk = vec![b'x'; 64 * 1024];
        let mut dropped = 0;
        for _ in 0..64 {
            f.push(&junk);
            while let Some(frame) = f.next_frame() {
                assert!(matches!(frame, Frame::BadHeader(_)), "{frame:?}");
                dropped += 1;
            }
            assert!(f.buf.len() < MAX_HEADER, "{}", f.buf.len());
        }
        assert!(dropped > 0);
        f.push(b"Content-Length: 2\r\n\r\n{}");
        assert_eq!(f.next_frame(), Some(Frame::Message(b"{}".to_vec())));
    }

    #[test]
    fn messages_are_checked() {
        assert!(
            check_message(br#"{"jsonrpc":"2.0","id":1,"method":"initialize","params":{}}"#).is_ok()
        );
        assert!(check_message(br#"{"jsonrpc":"2.0","method":"initialized","params":{}}"#).is_ok());
        assert!(check_message(br#"{"jsonrpc":"2.0","id":1,"result":null}"#).is_ok());
        let parse = check_message(b"{\"jsonrpc\"").expect_err("bad");
        assert_eq!(parse["error"]["code"], -32700);
        let utf8 = check_message(b"{\"a\":\"\xff\"}").expect_err("bad");
        assert_eq!(utf8["error"]["code"], -32700);
        let unknown = check_message(br#"{"jsonrpc":"2.0","id":"a","method":"$/unknown"}"#)
            .expect_err("unanswered otherwise");
        assert_eq!(unknown["error"]["code"], -32601);
        assert_eq!(unknown["id"], "a");
        assert!(check_message(br#"{"jsonrpc":"2.0","method":"$/unknown"}"#).is_ok());
        assert!(
            check_message(br#"{"jsonrpc":"2.0","method":"$/cancelRequest","params":{"id":1}}"#)
                .is_ok()
        );
        let invalid = check_message(br#"{"id":7,"hello":"world"}"#).expect_err("bad");
        assert_eq!(invalid["error"]["code"], -32600);
        assert_eq!(invalid["id"], 7);
    }
}
