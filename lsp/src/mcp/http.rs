//! `rapid mcp --http`: the streamable HTTP transport of the SDK, served by
//! hyper on a loopback address only (the SDK also refuses requests whose
//! `Host` is not a loopback name, against DNS rebinding).

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;

use hyper_util::rt::TokioIo;
use hyper_util::service::TowerToHyperService;
use rmcp::transport::streamable_http_server::session::local::LocalSessionManager;
use rmcp::transport::streamable_http_server::{StreamableHttpServerConfig, StreamableHttpService};

use super::roots::Roots;
use super::{MAX_MESSAGE_BYTES, RapidMcp};

/// Serves sessions at `addr`, each with its own roots: `given` (`--root`)
/// and its client's.
pub async fn serve(given: Vec<PathBuf>, addr: &str) -> Result<(), String> {
    // Said at the start rather than at the first session.
    Roots::new(&given)?;
    let addr: SocketAddr = addr
        .parse()
        .map_err(|_| format!("--http {addr}: expected an address such as 127.0.0.1:7343"))?;
    if !addr.ip().is_loopback() {
        return Err(format!(
            "--http {addr}: the server listens only on a loopback address (127.0.0.1, ::1)"
        ));
    }
    let listener = tokio::net::TcpListener::bind(addr)
        .await
        .map_err(|e| format!("--http {addr}: {e}"))?;
    let bound = listener.local_addr().map_err(|e| e.to_string())?;
    {
        use std::io::Write;
        let _ = writeln!(std::io::stderr(), "rapid mcp: serving http://{bound}/mcp");
    }
    let mut config = StreamableHttpServerConfig::default();
    config.max_request_body_bytes = MAX_MESSAGE_BYTES;
    let service = StreamableHttpService::new(
        move || {
            let roots = Roots::new(&given).map_err(std::io::Error::other)?;
            Ok(RapidMcp::new(Arc::new(roots)))
        },
        Arc::new(LocalSessionManager::default()),
        config,
    );
    loop {
        let (stream, _) = match listener.accept().await {
            Ok(accepted) => accepted,
            // A connection that failed before it was accepted (reset,
            // too many open files for a moment) is not the server's end.
            Err(_) => {
                tokio::time::sleep(std::time::Duration::from_millis(50)).await;
                continue;
            }
        };
        let service = TowerToHyperService::new(service.clone());
        tokio::spawn(async move {
            let _ = hyper::server::conn::http1::Builder::new()
                .serve_connection(TokioIo::new(stream), service)
                .await;
        });
    }
}
