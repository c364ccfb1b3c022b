//! `rapid`: the language server, CI linter, evaluator and formatter for ABB
//! RAPID.

mod alloc;
mod builtins;
mod check;
mod config;
mod dap;
mod diff;
mod eval;
mod fmt;
mod mcp;
mod project;
mod rules_cmd;
mod run;
mod server;
mod test_cmd;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Language tooling for ABB RAPID: check programs offline the way the
/// controller does.
#[derive(Debug, Parser)]
#[command(name = "rapid", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Check RAPID files and folders and report every problem found.
    Check(check::CheckArgs),
    /// Compute a RAPID expression as the controller would (constants of a
    /// program with --file).
    Eval(eval::EvalArgs),
    /// Rewrite RAPID files in the canonical layout.
    Fmt(fmt::FmtArgs),
    /// Show the built-in catalogue: functions, instructions, data types and
    /// predefined data.
    Builtins(builtins::BuiltinsArgs),
    /// List the rules of `rapid check`, or show one with its documentation.
    Rules(rules_cmd::RulesArgs),
    /// Run the language server (LSP over standard input and output).
    Lsp(server::LspArgs),
    /// Run a task's entry routine on a simulated controller.
    Run(run::RunArgs),
    /// Run the debug adapter (Debug Adapter Protocol over standard input
    /// and output) for RAPID programs on a simulated controller.
    Dap(dap::DapArgs),
    /// Run the Model Context Protocol server (stdio, or streamable HTTP on
    /// loopback) that gives AI assistants the checker, fixes, catalogue,
    /// evaluator and simulated controller.
    Mcp(mcp::McpArgs),
    /// Show what really changed between two backups, task folders,
    /// modules or git revisions: modules, routines, data, moved targets,
    /// configuration.
    Diff(diff::DiffArgs),
    /// Run the test routines of RAPID programs (test_* procedures, modules
    /// named *_test) on a simulated controller.
    Test(test_cmd::TestArgs),
}

fn main() -> ExitCode {
    alloc::init();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() {
                ExitCode::from(2)
            } else {
                ExitCode::SUCCESS
            };
        }
    };
    match cli.command {
        Command::Check(args) => check::run(args),
        Command::Eval(args) => eval::run(args),
        Command::Fmt(args) => fmt::run(args),
        Command::Builtins(args) => builtins::run(args),
        Command::Rules(args) => rules_cmd::run(args),
        Command::Lsp(args) => server::run(args),
        Command::Run(args) => run::run(args),
        Command::Test(args) => test_cmd::run(args),
        Command::Dap(args) => dap::run(args),
        Command::Mcp(args) => mcp::run(args),
        Command::Diff(args) => diff::run(args),
    }
}
