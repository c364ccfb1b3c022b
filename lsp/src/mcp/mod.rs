//! `rapid mcp`: a Model Context Protocol server (on the `rmcp` SDK) that
//! gives AI assistants the checker, the fixes, the formatter, the
//! catalogue, the evaluator and the simulated controller, over stdio or
//! streamable HTTP on a loopback address.
//!
//! Every tool goes through the same code as its command: the project
//! loader (confined to the roots, [`roots::Confined`]), `rapid check`'s run
//! ([`crate::check::report_in`]), `rapid run`'s and `rapid test`'s entry
//! points, `rapid eval`'s evaluator and `rapid builtins`' catalogue. Tools
//! read only inside the roots, write no file, and run programs in a
//! temporary sandbox folder within budgets. Each answers with a summary for
//! people (text) and a typed value (`structuredContent`, with its schema).
//!
//! Where the tools go: `check.rs` (check, fix, format), `lookup.rs`
//! (explain_rule, lookup_builtin, evaluate, list_symbols), `reach.rs`
//! (reach: the joint solutions of a target for the task's robot),
//! `exec.rs` (run, test), `pages.rs` (resources and prompts), `http.rs`
//! (the HTTP transport), `roots.rs` (what may be read).

mod check;
mod exec;
mod http;
mod lookup;
mod pages;
mod reach;
mod roots;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Duration;

use rmcp::handler::server::common::schema_for_output;
use rmcp::handler::server::router::prompt::PromptRouter;
use rmcp::handler::server::router::tool::ToolRouter;
use rmcp::handler::server::wrapper::Parameters;
use rmcp::model::{
    CallToolResult, ContentBlock, GetPromptResult, Implementation, ListResourceTemplatesResult,
    ListResourcesResult, PaginatedRequestParams, ReadResourceRequestParams, ReadResourceResponse,
    ServerCapabilities, ServerConfig,
};
use rmcp::service::{NotificationContext, RequestContext};
use rmcp::{ErrorData, Peer, RoleServer, ServerHandler, prompt, prompt_handler, prompt_router};
use rmcp::{tool, tool_handler, tool_router};
use serde::Serialize;

use check::{CheckParams, CheckReport, FixParams, FixReport, FormatParams, FormatReport};
use exec::{RunParams, RunReport, TestParams, TestReport};
use lookup::{
    BuiltinInfo, BuiltinParams, EvaluateParams, EvaluateReport, RuleInfo, RuleParams,
    SymbolsParams, SymbolsReport,
};
use pages::{FixPromptParams, TestPromptParams};
use reach::{ReachParams, ReachReport};
use roots::Roots;

/// The largest message read from stdio or an HTTP request (a module may
/// have 8 MB; JSON escapes make it larger): a larger one is answered with
/// an error by the transport, or dropped.
const MAX_MESSAGE_BYTES: usize = 64 * 1024 * 1024;

#[derive(Debug, clap::Args)]
pub struct McpArgs {
    /// A folder the tools may read (repeatable; relative paths in requests
    /// start at the first). The client's roots are added when it shares
    /// them; with neither, the current folder.
    #[arg(long = "root", value_name = "FOLDER")]
    pub roots: Vec<PathBuf>,
    /// Serve streamable HTTP at http://ADDR/mcp instead of stdio; ADDR must
    /// be a loopback address (default 127.0.0.1:7343; port 0 picks a free
    /// one, said on stderr).
    #[arg(long, value_name = "ADDR", num_args = 0..=1, default_missing_value = "127.0.0.1:7343")]
    pub http: Option<String>,
}

pub fn run(args: McpArgs) -> ExitCode {
    let runtime = match tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
    {
        Ok(rt) => rt,
        Err(e) => return fail(&format!("cannot start: {e}")),
    };
    let served = runtime.block_on(async move {
        match args.http {
            Some(addr) => http::serve(args.roots, &addr).await,
            None => serve_stdio(&args.roots).await,
        }
    });
    match served {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(&e),
    }
}

fn fail(message: &str) -> ExitCode {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "rapid: mcp: {message}");
    ExitCode::from(2)
}

async fn serve_stdio(given: &[PathBuf]) -> Result<(), String> {
    use rmcp::ServiceExt;
    let roots = Arc::new(Roots::new(given)?);
    use rmcp::transport::async_rw::AsyncRwTransport;
    let (stdin, stdout) = rmcp::transport::stdio();
    let transport =
        AsyncRwTransport::new_server(stdin, stdout).with_max_line_length(MAX_MESSAGE_BYTES);
    let running = RapidMcp::new(roots)
        .serve(transport)
        .await
        .map_err(|e| format!("the client did not start a session: {e}"))?;
    running
        .waiting()
        .await
        .map(|_| ())
        .map_err(|e| format!("the session ended: {e}"))
}

/// A tool's answer: a summary for people and the typed value.
pub struct Answer<T> {
    summary: String,
    value: T,
}

impl<T: Serialize> Answer<T> {
    pub fn new(summary: String, value: T) -> Answer<T> {
        Answer { summary, value }
    }

    fn into_result(self) -> CallToolResult {
        let mut result = CallToolResult::success(vec![ContentBlock::text(self.summary)]);
        result.structured_content = serde_json::to_value(self.value).ok();
        result
    }
}

/// Runs a tool's work off the protocol's threads; its error, or a panic,
/// is an error answer the client shows.
async fn blocking<T: Serialize + Send + 'static>(
    work: impl FnOnce() -> Result<Answer<T>, String> + Send + 'static,
) -> CallToolResult {
    match tokio::task::spawn_blocking(work).await {
        Ok(Ok(answer)) => answer.into_result(),
        Ok(Err(message)) => CallToolResult::error(vec![ContentBlock::text(message)]),
        Err(_) => CallToolResult::error(vec![ContentBlock::text(
            "the tool failed unexpectedly (this is a bug in rapid)",
        )]),
    }
}

/// `path` for an answer: relative to the root it lies in, else as it is.
pub fn shown(roots: &[PathBuf], path: &Path) -> String {
    roots
        .iter()
        .find_map(|r| path.strip_prefix(r).ok())
        .filter(|rest| !rest.as_os_str().is_empty())
        .unwrap_or(path)
        .to_string_lossy()
        .into_owned()
}

/// The server: its roots, tools and prompts.
#[derive(Clone)]
pub struct RapidMcp {
    roots: Arc<Roots>,
    tool_router: ToolRouter<Self>,
    prompt_router: PromptRouter<Self>,
}

#[tool_router(router = tool_router)]
impl RapidMcp {
    pub fn new(roots: Arc<Roots>) -> RapidMcp {
        RapidMcp {
            roots,
            tool_router: Self::tool_router(),
            prompt_router: Self::prompt_router(),
        }
    }

    /// The roots in force, after asking the client for its own when it has
    /// roots and has not said them yet (or said they changed).
    #[allow(
        deprecated,
        reason = "clients of the 2025 protocol versions list their roots this way"
    )]
    async fn roots(&self, peer: &Peer<RoleServer>) -> Vec<PathBuf> {
        let has_roots = peer
            .peer_info()
            .is_some_and(|info| info.capabilities.roots.is_some());
        if has_roots && self.roots.wants_client_roots() {
            let asked = tokio::time::timeout(Duration::from_secs(5), peer.list_roots()).await;
            match asked {
                Ok(Ok(list)) => self
                    .roots
                    .set_client(list.roots.iter().map(|r| r.uri.as_str())),
                _ => self.roots.set_client(std::iter::empty()),
            }
        }
        self.roots.current()
    }

    #[tool(
        description = "Check RAPID code as the controller loads it: a module or folder (its whole task is read, as `rapid check` does), or an unsaved module text with the path of the file or task folder it belongs to. Answers every finding with file, line, column, severity, stable code, message, and the rule's fix (safe fixes are what `fix` applies). Reads only inside the roots; writes nothing.",
        annotations(title = "Check RAPID", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<CheckReport>()
    )]
    async fn check(
        &self,
        Parameters(params): Parameters<CheckParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || check::check(&roots, params)).await
    }

    #[tool(
        description = "Apply the checker's safe fixes to a RAPID module text (or the text of the file at `path`) and answer the repaired text with what remains. Give `path` (the file or its task folder) so the rest of the task is known. Nothing is written: write the text back yourself.",
        annotations(title = "Fix RAPID", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<FixReport>()
    )]
    async fn fix(
        &self,
        Parameters(params): Parameters<FixParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || check::fix(&roots, params)).await
    }

    #[tool(
        description = "Lay out a RAPID module text (or the file at `path`) as `rapid fmt` does, with the `[format]` settings of the project's rapid.toml. Answers the formatted text; nothing is written. A text with a syntax error is refused with its position.",
        annotations(title = "Format RAPID", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<FormatReport>()
    )]
    async fn format(
        &self,
        Parameters(params): Parameters<FormatParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || check::format(&roots, params)).await
    }

    #[tool(
        description = "Explain a rule of the checker by its code (W201) or name (unused-data): what it reports, why it matters, an example, its default severity.",
        annotations(title = "Explain a rule", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<RuleInfo>()
    )]
    async fn explain_rule(&self, Parameters(params): Parameters<RuleParams>) -> CallToolResult {
        blocking(move || lookup::explain_rule(params)).await
    }

    #[tool(
        description = "Look up a RAPID built-in (function, instruction, data type or predefined datum such as MoveL, Offs, robtarget, v100): its signature with parameter modes, documentation, the RobotWare versions that have it and the option package that brings it. With `robotware`, that version's signature.",
        annotations(title = "Look up a built-in", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<BuiltinInfo>()
    )]
    async fn lookup_builtin(
        &self,
        Parameters(params): Parameters<BuiltinParams>,
    ) -> CallToolResult {
        blocking(move || lookup::lookup_builtin(params)).await
    }

    #[tool(
        description = "List what the tasks of a module or folder declare: routines (with their declarations), data (filter by `type`: every wobjdata, tooldata, robtarget...) and the signals of EIO.cfg, each with file and line.",
        annotations(title = "List symbols", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<SymbolsReport>()
    )]
    async fn list_symbols(
        &self,
        Parameters(params): Parameters<SymbolsParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || lookup::list_symbols(&roots, params)).await
    }

    #[tool(
        description = "Compute a constant RAPID expression as the controller does (single-precision num, degrees), alone or with the data of a module or task folder (`path`): Offs(pHome, 0, 0, 100), OrientZYX(90, 0, 0), 10 DIV 3.",
        annotations(title = "Evaluate an expression", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<EvaluateReport>()
    )]
    async fn evaluate(
        &self,
        Parameters(params): Parameters<EvaluateParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || lookup::evaluate(&roots, params)).await
    }

    #[tool(
        description = "The joint solutions of a robtarget for the task's robot (the one `rapid check` uses: MOC.cfg's, else rapid.toml's [controller] robot, else the `robot` argument): every solution within the working ranges with its confdata, the one the target's confdata selects, or the controller's error for a move there (out of reach by how many mm, an axis beyond its range by how many degrees, another configuration) with its event number and rule. The target, tool and work object are names the task declares or RAPID literals.",
        annotations(title = "Reach a target", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<ReachReport>()
    )]
    async fn reach(
        &self,
        Parameters(params): Parameters<ReachParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || reach::reach(&roots, params)).await
    }

    #[tool(
        description = "Run a program on a simulated controller, as `rapid run` does: a module or task folder from its procedure (default main), or a controller backup's tasks together, with a script of signal values, the operator's answers and budgets (statements, simulated seconds, call depth). Answers the pendant and event-log output, how each task ended (an error with its name, line and active routines), and a summary of the moves. File instructions work in a temporary sandbox folder; the network is simulated (nobody answers).",
        annotations(title = "Run RAPID", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<RunReport>()
    )]
    async fn run(
        &self,
        Parameters(params): Parameters<RunParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || exec::run(&roots, params)).await
    }

    #[tool(
        description = "Run the tests of the tasks of a module or folder on the simulated controller: procedures named test_... (or every procedure of a module named *_test), each on a fresh controller within budgets, with RapidAssert's AssertEqual/AssertTrue/AssertNear... Answers each test's result, failure message and line.",
        annotations(title = "Test RAPID", read_only_hint = true, open_world_hint = false),
        output_schema = schema_for_output::<TestReport>()
    )]
    async fn test(
        &self,
        Parameters(params): Parameters<TestParams>,
        peer: Peer<RoleServer>,
    ) -> CallToolResult {
        let roots = self.roots(&peer).await;
        blocking(move || exec::test(&roots, params)).await
    }
}

#[prompt_router]
impl RapidMcp {
    /// Check a RAPID module, apply the safe fixes, and repair what remains.
    #[prompt(name = "check-and-fix")]
    async fn check_and_fix(
        &self,
        Parameters(params): Parameters<FixPromptParams>,
    ) -> Result<GetPromptResult, ErrorData> {
        Ok(pages::check_and_fix(params))
    }

    /// Write a unit test for a RAPID routine and run it.
    #[prompt(name = "write-test")]
    async fn write_test(
        &self,
        Parameters(params): Parameters<TestPromptParams>,
    ) -> Result<GetPromptResult, ErrorData> {
        Ok(pages::write_test(params))
    }
}

#[tool_handler(router = self.tool_router)]
#[prompt_handler(router = self.prompt_router)]
impl ServerHandler for RapidMcp {
    fn get_info(&self) -> ServerConfig {
        ServerConfig::new(
            ServerCapabilities::builder()
                .enable_tools()
                .enable_prompts()
                .enable_resources()
                .build(),
        )
        .with_server_info(Implementation::new("rapid", env!("CARGO_PKG_VERSION")))
        .with_instructions(pages::INSTRUCTIONS)
    }

    async fn list_resources(
        &self,
        _request: Option<PaginatedRequestParams>,
        _context: RequestContext<RoleServer>,
    ) -> Result<ListResourcesResult, ErrorData> {
        Ok(ListResourcesResult::with_all_items(pages::resources()))
    }

    async fn list_resource_templates(
        &self,
        _request: Option<PaginatedRequestParams>,
        _context: RequestContext<RoleServer>,
    ) -> Result<ListResourceTemplatesResult, ErrorData> {
        Ok(ListResourceTemplatesResult::with_all_items(
            pages::templates(),
        ))
    }

    async fn read_resource(
        &self,
        request: ReadResourceRequestParams,
        _context: RequestContext<RoleServer>,
    ) -> Result<ReadResourceResponse, ErrorData> {
        pages::read(&request.uri).map(Into::into)
    }

    async fn on_roots_list_changed(&self, _context: NotificationContext<RoleServer>) {
        self.roots.client_changed();
    }
}
