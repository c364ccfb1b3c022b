//! `rapid dap`: a debug adapter (Debug Adapter Protocol over stdin and
//! stdout) for RAPID programs on the virtual controller.
//!
//! `launch` arguments: `program` (a module, a task's folder, or a backup:
//! its tasks run together, each a thread), `entry` (the procedure, `main`
//! by default; a test routine too), `task` (run only that task), `test`
//! (load the assertion module as `rapid test` does), `stopOnEntry`,
//! `signals` (`["di1=1@2.5"]`, as `rapid run --set`), `maxSteps` and
//! `maxTime` (the budgets, as `rapid run`'s), `answers` (the operator's, as
//! `rapid run --answers`), `robot` (the robot model every motion task moves,
//! as `rapid run --robot`; an unknown one fails the launch), `noDebug`,
//! `plot` (a file: the page that `rapid run --plot` writes, drawing the
//! run's motion with the arm, kept at each stop: [`path`]; the editors'
//! "Show path" opens it and follows the `rapidPath` events).
//!
//! The adapter drives the controller itself, in slices, between messages
//! (a thread only reads the input): it runs until the next event (a
//! breakpoint, with its condition; the end of a step; a pause; an error
//! no handler takes; the end), and every task is a thread. While stopped,
//! the stack, the scopes (the routine's data, its module's data,
//! `ERRNO`/`INTNO`) and their values can be read and changed, and
//! expressions evaluated in any frame of any task. `TPWrite` and
//! `ErrWrite` lines are output events.

mod debugger;
mod path;
mod wire;

use std::collections::HashMap;
use std::process::ExitCode;
use std::sync::mpsc::{Receiver, TryRecvError, channel};

use rapid_runtime::{Controller, Event, Resume, Stop, Stream};
use serde_json::{Value, json};

use crate::run::{RunOptions, Sandbox, load};
use debugger::{Breakpoint, Inspector, canonical};
use wire::{Writer, read_message};

#[derive(Debug, clap::Args)]
pub struct DapArgs {}

/// How many statements run between two looks at the client's messages.
const SLICE: u64 = 20_000;

/// A launch waiting for `configurationDone`.
struct Launch {
    loaded: load::Loaded,
    options: RunOptions,
    stop_on_entry: bool,
    debug: bool,
    /// The path page to keep at each stop and at the end.
    plot: Option<path::PathPage>,
    /// Said once the program runs (a motion task without a robot).
    notes: Vec<String>,
}

struct Session {
    writer: Writer,
    launch: Option<Launch>,
    configured: bool,
    controller: Option<Controller>,
    /// The program runs (no stop is shown).
    running: bool,
    /// A pause was asked for and not yet met.
    pausing: bool,
    /// Breakpoints by the file's canonical path.
    breakpoints: HashMap<String, Vec<Breakpoint>>,
    /// The module files of the tasks: canonical path to the path the
    /// tasks know them by.
    units: HashMap<String, Vec<String>>,
    inspector: Inspector,
    sandbox: Option<Sandbox>,
    plot: Option<path::PathPage>,
    /// Said at the end of a program that moved (as `rapid run` says them).
    notes: Vec<String>,
}

pub fn run(_args: DapArgs) -> ExitCode {
    let (tx, rx) = channel();
    std::thread::spawn(move || {
        let stdin = std::io::stdin();
        let mut input = stdin.lock();
        loop {
            match read_message(&mut input) {
                Ok(Some(m)) => {
                    if tx.send(Ok(m)).is_err() {
                        break;
                    }
                }
                Ok(None) => break,
                Err(e) => {
                    let _ = tx.send(Err(e.to_string()));
                    break;
                }
            }
        }
    });
    let mut session = Session {
        writer: Writer::new(Box::new(std::io::stdout())),
        launch: None,
        configured: false,
        controller: None,
        running: false,
        pausing: false,
        breakpoints: HashMap::new(),
        units: HashMap::new(),
        inspector: Inspector::default(),
        sandbox: None,
        plot: None,
        notes: Vec::new(),
    };
    session.serve(&rx);
    session.end();
    ExitCode::SUCCESS
}

impl Session {
    /// Answers messages and runs the program between them until the
    /// session ends.
    fn serve(&mut self, rx: &Receiver<Result<Value, String>>) {
        loop {
            let message = if self.running {
                match rx.try_recv() {
                    Ok(m) => Some(m),
                    Err(TryRecvError::Empty) => None,
                    Err(TryRecvError::Disconnected) => return,
                }
            } else {
                match rx.recv() {
                    Ok(m) => Some(m),
                    Err(_) => return,
                }
            };
            match message {
                Some(Ok(m)) => {
                    if !self.handle(&m) {
                        return;
                    }
                }
                Some(Err(e)) => {
                    let _ = std::io::Write::write_all(
                        &mut std::io::stderr(),
                        format!("rapid: dap: {e}\n").as_bytes(),
                    );
                    return;
                }
                None => self.run_slice(),
            }
        }
    }

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
                self.breakpoints.insert(path.clone(), list);
                self.apply_breakpoints(&path);
                self.writer.respond(req, json!({"breakpoints": answer}));
            }
            "setExceptionBreakpoints" => self.writer.respond(req, json!({})),
            "configurationDone" => {
                self.configured = true;
                self.writer.respond(req, json!({}));
                self.start();
            }
            "threads" => {
                let threads: Vec<Value> = match &self.controller {
                    Some(c) => c
                        .tasks()
                        .iter()
                        .enumerate()
                        .map(|(i, t)| json!({"id": i + 1, "name": t.name()}))
                        .collect(),
                    None => vec![json!({"id": 1, "name": "T_ROB1"})],
                };
                self.writer.respond(req, json!({"threads": threads}));
            }
            "stackTrace" | "scopes" | "variables" | "setVariable" | "evaluate" => {
                match (&mut self.controller, self.running) {
                    (Some(c), false) => self.inspector.answer(c, &self.writer, req),
                    _ if req["command"] == "stackTrace" => self
                        .writer
                        .respond(req, json!({"stackFrames": [], "totalFrames": 0})),
                    _ => self.writer.fail(req, "the program is running"),
                }
            }
            "continue" | "next" | "stepIn" | "stepOut" => {
                let task = args["threadId"].as_u64().unwrap_or(1).saturating_sub(1) as usize;
                let how = match req["command"].as_str() {
                    Some("next") => Resume::StepOver { task },
                    Some("stepIn") => Resume::StepIn { task },
                    Some("stepOut") => Resume::StepOut { task },
                    _ => Resume::Continue,
                };
                self.writer
                    .respond(req, json!({"allThreadsContinued": true}));
                if let Some(c) = &mut self.controller {
                    c.resume(how);
                    self.running = true;
                }
            }
            "pause" => {
                if let Some(c) = &mut self.controller {
                    c.pause();
                    self.pausing = true;
                }
                self.writer.respond(req, json!({}));
            }
            "terminate" => {
                self.finish_program(true);
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

    /// Builds the controller of the launched program once the client's
    /// configuration is done, and lets it run.
    fn start(&mut self) {
        if self.controller.is_some() {
            return;
        }
        let Some(mut launch) = self.launch.take() else {
            return;
        };
        let sandbox = Sandbox::seeded(None, launch.loaded.home.as_deref()).ok();
        launch.options.sandbox = sandbox.as_ref().map(|s| s.path.clone());
        self.sandbox = sandbox;
        let writer = self.writer.clone();
        let out = move |_: Stream, line: &str| {
            writer.event(
                "output",
                json!({"category": "stdout", "output": format!("{line}\n")}),
            );
        };
        match crate::run::build(&launch.loaded, &launch.options, Box::new(out)).map(|b| b.0) {
            Ok(mut c) => {
                if launch.debug {
                    c.debug(launch.stop_on_entry);
                }
                for t in &launch.loaded.tasks {
                    for u in t.task.units.iter() {
                        self.units
                            .entry(canonical(&u.path))
                            .or_default()
                            .push(u.path.clone());
                    }
                }
                self.controller = Some(c);
                self.plot = launch.plot;
                self.notes = launch.notes;
                let paths: Vec<String> = self.breakpoints.keys().cloned().collect();
                for p in paths {
                    self.apply_breakpoints(&p);
                }
                self.running = true;
            }
            Err(e) => {
                self.writer.event(
                    "output",
                    json!({"category": "stderr", "output": format!("{e}\n")}),
                );
                self.writer.event("exited", json!({"exitCode": 2}));
                self.writer.event("terminated", json!({}));
            }
        }
    }

    /// Gives the controller the breakpoint lines of a file.
    fn apply_breakpoints(&mut self, canonical_path: &str) {
        let Some(c) = &mut self.controller else {
            return;
        };
        let lines: Vec<u32> = self
            .breakpoints
            .get(canonical_path)
            .map(|l| l.iter().map(|b| b.line as u32).collect())
            .unwrap_or_default();
        for unit_path in self.units.get(canonical_path).into_iter().flatten() {
            c.set_breakpoints(unit_path, &lines);
        }
    }

    /// Runs the program until the next event or the end of a slice.
    fn run_slice(&mut self) {
        let Some(c) = &mut self.controller else {
            self.running = false;
            return;
        };
        let mut event = c.run_for(SLICE);
        if matches!(event, Event::Running) && self.pausing {
            event = c.take_pause().unwrap_or(Event::Running);
        }
        match event {
            Event::Running => {}
            Event::Stopped { task, stop } => {
                if let Stop::Breakpoint = stop
                    && !self.condition_holds(task)
                {
                    if let Some(c) = &mut self.controller {
                        c.resume(Resume::Continue);
                    }
                    return;
                }
                self.pausing = false;
                self.running = false;
                self.inspector.stopped();
                let thread = task + 1;
                let body = match stop {
                    Stop::Entry => json!({"reason": "entry"}),
                    Stop::Breakpoint => json!({"reason": "breakpoint"}),
                    Stop::Step => json!({"reason": "step"}),
                    Stop::Pause => json!({"reason": "pause"}),
                    Stop::Error(o) => {
                        let name = o.errno.as_ref().map_or("error", |(_, n)| n.as_str());
                        let text = format!("{name}: {}", o.message);
                        json!({"reason": "exception", "description": text, "text": text})
                    }
                };
                let mut body = body;
                body["threadId"] = json!(thread);
                body["allThreadsStopped"] = json!(true);
                if let Some(c) = &self.controller {
                    show_path(&self.writer, &mut self.plot, c, Some(task));
                }
                self.writer.event("stopped", body);
            }
            Event::Ended => self.finish_program(false),
        }
    }

    /// Does a condition of a breakpoint at the line task `task` stopped
    /// at hold (one without a condition always does)?
    fn condition_holds(&mut self, task: usize) -> bool {
        let Some(c) = &mut self.controller else {
            return true;
        };
        let Some(at) = c.stack(task).first().map(|f| f.at.clone()) else {
            return true;
        };
        let conditions: Vec<Option<String>> = self
            .breakpoints
            .get(&canonical(&at.path))
            .map(|list| {
                list.iter()
                    .filter(|b| b.line == at.line)
                    .map(|b| b.condition.clone())
                    .collect()
            })
            .unwrap_or_default();
        if conditions.is_empty() {
            return true;
        }
        conditions.into_iter().any(|cond| match cond {
            None => true,
            Some(text) => match c.evaluate(task, 0, &text) {
                Ok(rapid_evaluator::Value::Bool(b)) => b,
                Ok(other) => {
                    self.writer.event(
                        "output",
                        json!({"category": "console", "output": format!("breakpoint condition `{text}` is {other}, not a bool\n")}),
                    );
                    true
                }
                Err(e) => {
                    self.writer.event(
                        "output",
                        json!({"category": "console", "output": format!("breakpoint condition `{text}`: {e}\n")}),
                    );
                    true
                }
            },
        })
    }

    /// The program ended (or is ended now): the path page, how the tasks
    /// ended, `exited` and `terminated`.
    fn finish_program(&mut self, now: bool) {
        let Some(mut c) = self.controller.take() else {
            return;
        };
        if now {
            c.terminate();
        }
        self.running = false;
        let report = crate::run::report_of(&c);
        show_path(&self.writer, &mut self.plot, &c, None);
        if report.move_count > 0 {
            for note in &self.notes {
                self.writer.event(
                    "output",
                    json!({"category": "console", "output": format!("rapid: dap: {note}\n")}),
                );
            }
        }
        for line in report.describe() {
            self.writer.event(
                "output",
                json!({"category": "stderr", "output": format!("{line}\n")}),
            );
        }
        let code = if report.is_success() { 0 } else { 1 };
        self.writer.event("exited", json!({"exitCode": code}));
        self.writer.event("terminated", json!({}));
        self.sandbox = None;
    }

    /// Ends the program (if it runs) and removes its sandbox.
    fn end(&mut self) {
        if let Some(mut c) = self.controller.take() {
            c.terminate();
        }
        self.running = false;
        self.sandbox = None;
    }
}

/// Keeps the path page at the stop of task `task` (`None`: the end) and
/// tells the client (`rapidPath`), when the launch asked for a page.
fn show_path(
    writer: &Writer,
    plot: &mut Option<path::PathPage>,
    c: &Controller,
    task: Option<usize>,
) {
    let Some(page) = plot else {
        return;
    };
    match page.write(c, task) {
        Ok(body) => writer.event("rapidPath", body),
        Err(e) => writer.event(
            "output",
            json!({"category": "stderr", "output": format!("{e}\n")}),
        ),
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
    let mut loaded = load::controller(&path, args["task"].as_str(), args["entry"].as_str())?;
    if args["test"].as_bool().unwrap_or(false) {
        // A test runs in the task that declares it, as `rapid test` runs
        // it: that task (its controller's name and configuration) with
        // the assertion module.
        loaded.tasks.retain(|t| load::declares(&t.task, entry));
        let Some(mut t) = loaded.tasks.pop().filter(|_| loaded.tasks.is_empty()) else {
            return Err(format!("{program}: no task (or several) declares {entry}"));
        };
        t.task = load::with_modules(
            &t.task,
            &[(crate::test_cmd::ASSERT_PATH, crate::test_cmd::ASSERT_MODULE)],
        );
        entry.clone_into(&mut t.entry);
        t.kind = rapid_runtime::TaskKind::Normal;
        loaded.tasks = vec![t];
    }
    let errors: Vec<String> = loaded
        .tasks
        .iter()
        .flat_map(|t| rapid_runtime::load_errors(&t.task))
        .map(|e| e.to_string())
        .collect();
    if !errors.is_empty() {
        return Err(format!(
            "the controller would not load the program:\n{}",
            errors.join("\n")
        ));
    }
    let defaults = rapid_runtime::Limits::default();
    let robot = args["robot"].as_str().filter(|r| !r.trim().is_empty());
    let notes = crate::run::robot::notes(&loaded.tasks, robot)
        .map_err(|e| format!("launch: {}", e.trim_start_matches("--")))?;
    let plot = args["plot"].as_str().filter(|p| !p.is_empty()).map(|p| {
        path::PathPage::new(
            std::path::PathBuf::from(p),
            format!("{} ({entry})", path.display()),
            crate::run::robot::drawn_arm(&loaded.tasks, robot),
        )
    });
    Ok(Launch {
        loaded,
        options: RunOptions {
            sets,
            limits: rapid_runtime::Limits {
                max_steps: args["maxSteps"].as_u64().unwrap_or(defaults.max_steps),
                max_time: args["maxTime"].as_f64().unwrap_or(defaults.max_time),
                ..defaults
            },
            sandbox: None,
            trace: plot.is_some(),
            // The operator's answers (`"answers": ["1", "@2 Yes"]`): a
            // debuggee has no terminal of its own.
            operator: crate::run::operator::OperatorOptions::listed(
                args["answers"]
                    .as_array()
                    .map(|a| {
                        a.iter()
                            .map(|v| v.as_str().map_or_else(|| v.to_string(), str::to_owned))
                            .collect()
                    })
                    .unwrap_or_default(),
            ),
            socket_map: Some(Vec::new()),
            robot: robot.map(str::to_owned),
        },
        stop_on_entry: args["stopOnEntry"].as_bool().unwrap_or(false),
        debug: !args["noDebug"].as_bool().unwrap_or(false),
        plot,
        notes,
    })
}
