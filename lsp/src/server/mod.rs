//! `rapid lsp`: the language server, over standard input and output.
//!
//! The protocol lives here and only here: the analyzer hands out plain data
//! with byte ranges ([`rapid_analyzer::ide`]); this module converts positions
//! (UTF-16 or UTF-8 columns), types and JSON.
//!
//! - Document notifications (open, change, close, watched files) mutate the
//!   [`state::State`] in order, under a short synchronous lock, before their
//!   handler first awaits: the transport starts handlers in arrival order.
//! - Requests take a [`state::Snapshot`] (an `Arc<Task>` and the unit) under
//!   the lock and run on the blocking pool; a panic there becomes an error
//!   answer and a log message, never a dead server.
//! - Diagnostics are published per file with the document version, after a
//!   short pause while typing (none for a newly opened file); a publication
//!   that is no longer the latest for its document is dropped.

mod backend;
mod capabilities;
mod configure;
mod diagnostics;
mod document;
mod handlers;
mod implicit;
mod indexing;
mod lifecycle;
mod position;
mod publish;
mod requests;
mod settings;
mod state;
mod sync;
#[cfg(test)]
mod tests;
mod transport;
mod watch;
mod workspace_report;

use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use tokio::io::{AsyncRead, AsyncWrite};
use tower_lsp_server::{LspService, Server};

pub use backend::Backend;

/// Arguments of `rapid lsp`.
#[derive(Debug, clap::Args)]
pub struct LspArgs {
    /// Speak the protocol over standard input and output (the default, and
    /// the only transport; accepted because editors pass it).
    #[arg(long)]
    pub stdio: bool,
}

pub fn run(_args: LspArgs) -> ExitCode {
    // A long-lived process answering keystrokes: steady latency matters
    // more than the last percent of throughput (see `no_huge_pages`).
    if !crate::alloc::no_huge_pages() && cfg!(target_os = "linux") {
        eprintln!("rapid lsp: transparent huge pages stay on (prctl refused)");
    }
    let runtime = match tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
    {
        Ok(rt) => rt,
        Err(e) => {
            eprintln!("rapid lsp: cannot start: {e}");
            return ExitCode::from(2);
        }
    };
    let clean = runtime.block_on(serve(tokio::io::stdin(), tokio::io::stdout()));
    // Work still running on the blocking pool (indexing, a long request) is
    // abandoned: the client asked us to exit.
    runtime.shutdown_background();
    if clean {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

/// How often the server looks whether the process that started it is
/// still there.
const PARENT_POLL: std::time::Duration = std::time::Duration::from_secs(3);

/// Ends this process when the client process `pid` (the `processId` of
/// `initialize`) is gone, as the protocol asks: an editor that crashed or
/// was killed may leave the server's input open, and the server would run
/// on, checking files for nobody. Nothing is lost: the server writes no
/// files. A thread of its own, so a busy runtime cannot delay it. A pid
/// this process cannot see at the start (a client on the host of a
/// container the server runs in) is not watched.
#[cfg(unix)]
pub(crate) fn exit_with_parent(pid: u32) {
    let Ok(pid) = libc::pid_t::try_from(pid) else {
        return;
    };
    if !process_exists(pid) {
        return;
    }
    let spawned = std::thread::Builder::new()
        .name("parent-watch".to_owned())
        .spawn(move || {
            while process_exists(pid) {
                std::thread::sleep(PARENT_POLL);
            }
            std::process::exit(0);
        });
    drop(spawned);
}

#[cfg(not(unix))]
pub(crate) fn exit_with_parent(_pid: u32) {}

/// Is there a process `pid` (alive, or a zombie not yet reaped)?
#[cfg(unix)]
#[allow(unsafe_code)]
fn process_exists(pid: libc::pid_t) -> bool {
    // SAFETY: signal 0 sends nothing; kill only checks that `pid` exists
    // and may be signalled, and touches no memory of this process.
    let sent = unsafe { libc::kill(pid, 0) } == 0;
    // EPERM: it exists but belongs to someone else.
    sent || std::io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
}

/// Serves one client until it sends `exit` or closes the input. Returns
/// whether the exit was clean (`shutdown` came first), as the protocol
/// wants the exit code to say.
pub async fn serve<I, O>(input: I, output: O) -> bool
where
    I: AsyncRead + Unpin + Send + 'static,
    O: AsyncWrite + Unpin + Send + 'static,
{
    let shut_down = Arc::new(AtomicBool::new(false));
    let flag = shut_down.clone();
    let (service, socket) = LspService::build(move |client| Backend::new(client, flag))
        .custom_method("rapid/indentation", Backend::indentation)
        .finish();
    run_service(input, output, service, socket).await;
    shut_down.load(Ordering::SeqCst)
}

/// How long requests still running when the input ends may take to answer
/// before the server exits without them.
const EXIT_GRACE: std::time::Duration = std::time::Duration::from_secs(2);

/// Runs the service behind the hardened transport ([`transport`]).
async fn run_service<I, O>(
    input: I,
    output: O,
    service: LspService<Backend>,
    socket: tower_lsp_server::ClientSocket,
) where
    I: AsyncRead + Unpin + Send + 'static,
    O: AsyncWrite + Unpin + Send + 'static,
{
    let (to_server, server_in) = transport::pipe();
    let (server_out, from_server) = transport::pipe();
    let (frames_tx, frames_rx) = tokio::sync::mpsc::unbounded_channel();
    let reader = tokio::spawn(transport::filter_input(
        input,
        to_server.tx,
        frames_tx.clone(),
    ));
    let forwarder = tokio::spawn(transport::forward_frames(from_server, frames_tx));
    let writer = tokio::spawn(transport::write_output(output, frames_rx));
    let mut server = Box::pin(Server::new(server_in, server_out, socket).serve(service));
    let mut reader = reader;
    tokio::select! {
        () = &mut server => {}
        _ = &mut reader => {
            // The input ended (the client is gone, or it sent `exit`):
            // nothing more can be asked. The server's framework would wait
            // for every request in flight, however long; they get a moment
            // to answer, then the process leaves them behind.
            let _ = tokio::time::timeout(EXIT_GRACE, &mut server).await;
        }
    }
    // The server is done (dropping it closes its output): stop reading,
    // send what is left, unless nobody reads it any more.
    drop(server);
    reader.abort();
    let _ = tokio::time::timeout(EXIT_GRACE, async {
        let _ = forwarder.await;
        let _ = writer.await;
    })
    .await;
}

/// [`serve`], with a method that panics on the blocking pool, to test that
/// a panicking handler answers an error and the server goes on.
#[cfg(test)]
async fn serve_with_test_methods<I, O>(input: I, output: O) -> bool
where
    I: AsyncRead + Unpin + Send + 'static,
    O: AsyncWrite + Unpin + Send + 'static,
{
    let shut_down = Arc::new(AtomicBool::new(false));
    let flag = shut_down.clone();
    let (service, socket) = LspService::build(move |client| Backend::new(client, flag))
        .custom_method("rapid/testPanic", Backend::test_panic)
        .custom_method("rapid/indentation", Backend::indentation)
        .finish();
    run_service(input, output, service, socket).await;
    shut_down.load(Ordering::SeqCst)
}
