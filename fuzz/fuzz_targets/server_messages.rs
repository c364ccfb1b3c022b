//! The language server's input: any bytes are framed and checked as the
//! server's transport does before anything reaches a handler (a bad frame
//! or message gets an error answer and the stream goes on). Handlers
//! themselves run the analyzer, which the `check` target covers, and the
//! server process is driven end to end by `lsp/tests/server_robust.rs`.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "../../lsp/src/server/transport.rs"]
#[allow(dead_code)]
mod transport;

fuzz_target!(|data: &[u8]| {
    let mut framer = transport::Framer::default();
    // In pieces, as reads deliver them.
    for piece in data.chunks(7) {
        framer.push(piece);
        while let Some(frame) = framer.next_frame() {
            if let transport::Frame::Message(body) = frame {
                if let Err(answer) = transport::check_message(&body) {
                    assert!(answer["error"]["code"].is_i64());
                }
            }
        }
    }
});
