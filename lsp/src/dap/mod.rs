//! `rapid dap`: a debug adapter (Debug Adapter Protocol over stdin and
//! stdout) for RAPID programs on the simulated controller.
//!
//! `launch` arguments: `program` (a module or a task's folder), `entry`
//! (the procedure, `main` by default; a test routine too), `test` (load
//! the assertion module as `rapid test` does), `stopOnEntry`, `signals`
//! (`["di1=1@2.5"]`, as `rapid run --set`), `maxSteps` and `maxTime` (the
//! budgets, as `rapid run`'s), `noDebug`, `plot` (a file: when the
//! program ends, the page that `rapid run --plot` writes, drawing the
//! run's motion; the VS Code extension's "Show path" opens it). The
//! program runs on
//! its own thread; it stops at line breakpoints (with conditions), steps
//! (over, into, out), pauses, and stops at a run-time error that no
//! handler takes. While stopped, the stack, the scopes (the routine's
//! data, its module's data, `ERRNO`/`INTNO`) and their values can be read
//! and changed, and expressions evaluated in any frame. `TPWrite` and
//! `ErrWrite` lines are output events.

mod debugger;
mod wire;

use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::sync::mpsc::{Sender, channel};

use rapid_runtime::{Config, Machine, Program, Stream};
use serde_json::{Value, json};

use crate::run::{Sandbox, load};
use debugger::{Breakpoint, Command, DapDebugger, Resume, Shared, canonical};
use wire::{Writer, read_message};

#[derive(Debug, clap::Args)]
pub struct DapArgs {}

/// A launch waiting for `configurationDone`.
struct Launch {
    program: Arc<Program>,
    entry: u32,
    config: Config,
    stop_on_entry: bool,
    debug: bool,
    /// Where to write the path page at the end, and its title.
    plot: Option<(std::path::PathBuf, String)>,
}

struct Session {
    writer: Writer,
    shared: Arc<Shared>,
    commands: Option<Sender<Command>>,
    launch: Option<Launch>,
    configured: bool,
    worker: Option<std::thread::JoinHandle<()>>,
}

pub fn run(_args: DapArgs) -> ExitCode {
    let writer = Writer::new(Box::new(std::io::stdout()));
    let mut session = Session {
        writer,
        shared: Arc::default(),
        commands: None,
        launch: None,
        configured: false,
        worker: None,
    };
    let stdin = std::io::stdin();
    let mut input = stdin.lock();
    loop {
        match read_message(&mut input) {
            Ok(Some(message)) => {
                if !session.handle(&message) {
                    break;
                }
            }
            Ok(None) => break,
            Err(e) => {
                let _ = std::io::Write::write_all(
                    &mut std::io::stderr(),
                    format!("rapid: dap: {e}\n").as_bytes(),
                );
                break;
            }
        }
    }
    session.end();
    ExitCode::SUCCESS
}

impl Session {
    /// Handles one message; `false` when the session is over.
    fn handle(&mut self, req: &Value) -> bool {
        if req["type"] != "request" {
            return true;
        }
        let args = &req["arguments"];
        match req["command"].as_str().unwrap_or_default() {
            "initialize" => {
                self.writer.respond(
                    req,
                    json!({
                        "supportsConfigurationDoneRequest": true,
                        "supportsConditionalBreakpoints": true,
                        "supportsSetVariable": true,
                        "supportsEvaluateForHovers": true,
                        "supportsTerminateRequest": true,
                    }),
                );
                self.writer.event("initialized", json!({}));
            }
            "launch" => match prepare(args) {
                Ok(launch) => {
                    self.launch = Some(launch);
                    self.writer.respond(req, json!({}));
                    if self.configured {
                        self.start();
                    }
                }
                Err(e) => self.writer.fail(req, &e),
            },
            "setBreakpoints" => {
                let path = canonical(args["source"]["path"].as_str().unwrap_or_default());
                let list: Vec<Breakpoint> = args["breakpoints"]
                    .as_array()
                    .map(|a| {
                        a.iter()
                            .map(|b| Breakpoint {
                                line: b["line"].as_u64().unwrap_or(0) as usize,
                                condition: b["condition"]
                                    .as_str()
                                    .filter(|c| !c.trim().is_empty())
                                    .map(str::to_owned),
                            })
                            .collect()
                    })
                    .unwrap_or_default();
                let answer: Vec<Value> = list
                    .iter()
                    .map(|b| json!({"verified": true, "line": b.line}))
                    .collect();
                if let Ok(mut all) = self.shared.breakpoints.lock() {
                    all.insert(path, list);
                }
                self.writer.respond(req, json!({"breakpoints": answer}));
            }
            "setExceptionBreakpoints" => self.writer.respond(req, json!({})),
            "configurationDone" => {
                self.configured = true;
                self.writer.respond(req, json!({}));
                self.start();
            }
            "threads" => self
                .writer
                .respond(req, json!({"threads": [{"id": 1, "name": "T_ROB1"}]})),
            "stackTrace" | "scopes" | "variables" | "setVariable" | "evaluate" => {
                if self.shared.paused.load(Ordering::SeqCst) {
                    self.send(Command::Request(req.clone()));
                } else if req["command"] == "stackTrace" {
                    self.writer
                        .respond(req, json!({"stackFrames": [], "totalFrames": 0}));
                } else {
                    self.writer.fail(req, "the program is running");
                }
            }
            "continue" | "next" | "stepIn" | "stepOut" => {
                let how = match req["command"].as_str() {
                    Some("next") => Resume::Next,
                    Some("stepIn") => Resume::StepIn,
                    Some("stepOut") => Resume::StepOut,
                    _ => Resume::Continue,
                };
                self.writer
                    .respond(req, json!({"allThreadsContinued": true}));
                self.send(Command::Resume(how));
            }
            "pause" => {
                self.shared.pause.store(true, Ordering::SeqCst);
                self.writer.respond(req, json!({}));
            }
            "terminate" => {
                self.stop_program();
                self.writer.respond(req, json!({}));
            }
            "disconnect" => {
                // The program ends and its sandbox is removed before the
                // answer: a client may end the adapter as soon as it has it.
                self.end();
                self.writer.respond(req, json!({}));
                return false;
            }
            other => self
                .writer
                .fail(req, &format!("rapid dap does not support {other}")),
        }
        true
    }

    fn send(&self, command: Command) {
        if let Some(tx) = &self.commands {
            let _ = tx.send(command);
        }
    }

    fn stop_program(&self) {
        self.shared.terminate.store(true, Ordering::SeqCst);
        self.send(Command::Terminate);
    }

    /// Starts the launched program once the client's configuration is done.
    fn start(&mut self) {
        if self.worker.is_some() {
            return;
        }
        let Some(launch) = self.launch.take() else {
            return;
        };
        let (tx, rx) = channel();
        self.commands = Some(tx);
        let debugger = DapDebugger::new(
            self.shared.clone(),
            rx,
            self.writer.clone(),
            launch.stop_on_entry,
        );
        let writer = self.writer.clone();
        let worker = std::thread::Builder::new()
            .name("rapid-dap-program".to_owned())
            .stack_size(rapid_runtime::STACK_BYTES)
            .spawn(move || {
                let sandbox = Sandbox::new(None);
                let mut config = launch.config;
                config.sandbox = sandbox.as_ref().ok().map(|s| s.path.clone());
                let out_writer = writer.clone();
                let out = move |_: Stream, line: &str| {
                    out_writer.event(
                        "output",
                        json!({"category": "stdout", "output": format!("{line}\n")}),
                    );
                };
                let mut m = Machine::new(launch.program, config, Box::new(out));
                if launch.debug {
                    m.set_debugger(Box::new(debugger));
                }
                let outcome = m.run(launch.entry);
                if let Some((file, title)) = &launch.plot {
                    let page = crate::run::trace::html(m.moves(), title);
                    if let Err(e) = std::fs::write(file, page) {
                        writer.event(
                            "output",
                            json!({"category": "stderr", "output": format!("{}: {e}\n", file.display())}),
                        );
                    }
                }
                for line in crate::run::describe(&outcome) {
                    writer.event(
                        "output",
                        json!({"category": "stderr", "output": format!("{line}\n")}),
                    );
                }
                let code = if outcome.is_success() { 0 } else { 1 };
                writer.event("exited", json!({"exitCode": code}));
                writer.event("terminated", json!({}));
            });
        match worker {
            Ok(w) => self.worker = Some(w),
            Err(e) => {
                self.writer.event(
                    "output",
                    json!({"category": "stderr", "output": format!("cannot start the program: {e}\n")}),
                );
                self.writer.event("terminated", json!({}));
            }
        }
    }

    /// Ends the program and waits for its thread.
    fn end(&mut self) {
        self.stop_program();
        if let Some(w) = self.worker.take() {
            let _ = w.join();
        }
    }
}

/// Loads what a `launch` request names.
fn prepare(args: &Value) -> Result<Launch, String> {
    let program = args["program"]
        .as_str()
        .ok_or("launch: `program` (a module or a task's folder) is missing")?;
    let entry = args["entry"].as_str().unwrap_or("main");
    let sets = args["signals"]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(Value::as_str)
                .map(load::parse_set)
                .collect::<Result<Vec<_>, _>>()
        })
        .transpose()?
        .unwrap_or_default();
    let path = std::path::PathBuf::from(program);
    let mut task = load::one_task(&path, entry)?;
    if args["test"].as_bool().unwrap_or(false) {
        task = load::with_modules(
            &task,
            &[(crate::test_cmd::ASSERT_PATH, crate::test_cmd::ASSERT_MODULE)],
        );
    }
    let program = load::program(task, &sets);
    let defaults = rapid_runtime::Limits::default();
    let plot = args["plot"].as_str().filter(|p| !p.is_empty()).map(|p| {
        (
            std::path::PathBuf::from(p),
            format!("{} ({entry})", path.display()),
        )
    });
    let entry_id = program.find_routine(entry).ok_or_else(|| {
        format!(
            "{program}: no procedure {entry} in the task",
            program = path.display()
        )
    })?;
    Ok(Launch {
        program,
        entry: entry_id,
        config: Config {
            signals: sets,
            limits: rapid_runtime::Limits {
                max_steps: args["maxSteps"].as_u64().unwrap_or(defaults.max_steps),
                max_time: args["maxTime"].as_f64().unwrap_or(defaults.max_time),
                ..defaults
            },
            trace: plot.is_some(),
            ..Config::default()
        },
        stop_on_entry: args["stopOnEntry"].as_bool().unwrap_or(false),
        debug: !args["noDebug"].as_bool().unwrap_or(false),
        plot,
    })
}
