//! The debugger on the program's thread: decides where to stop (pause,
//! steps, breakpoints with their conditions, errors that end the run) and,
//! while stopped, answers the requests that read or change the program's
//! state (stack, scopes, variables, evaluate, set variable).

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::Receiver;
use std::sync::{Arc, Mutex};

use rapid_evaluator::Value;
use rapid_runtime::{Control, Debugger, Machine, Outcome, Variable};
use serde_json::{Value as Json, json};

use super::wire::Writer;

/// A line breakpoint, with its condition (a RAPID expression).
#[derive(Clone, Debug)]
pub struct Breakpoint {
    pub line: usize,
    pub condition: Option<String>,
}

/// What the adapter's two threads share.
#[derive(Default)]
pub struct Shared {
    /// Breakpoints by the file's canonical path.
    pub breakpoints: Mutex<HashMap<String, Vec<Breakpoint>>>,
    /// A pause was asked for.
    pub pause: AtomicBool,
    /// The program is stopped, answering requests.
    pub paused: AtomicBool,
    /// The session ends.
    pub terminate: AtomicBool,
}

/// What the adapter sends the program's thread.
pub enum Command {
    /// A request answered while stopped.
    Request(Json),
    Resume(Resume),
    Terminate,
}

#[derive(Clone, Copy)]
pub enum Resume {
    Continue,
    Next,
    StepIn,
    StepOut,
}

#[derive(Clone, Copy)]
enum Mode {
    Run,
    StepIn,
    /// Stop at the next statement of this depth or less.
    StepOver(usize),
    /// Stop at the next statement of less than this depth.
    StepOut(usize),
}

/// What a `variablesReference` stands for while stopped.
enum Ref {
    Locals(usize),
    Module(usize),
    System,
    /// A record or an array: the frame, the RAPID expression that names it,
    /// whether it is an element of an array, and its value.
    Value {
        frame: usize,
        path: String,
        element: bool,
        value: Value,
    },
}

pub struct DapDebugger {
    shared: Arc<Shared>,
    commands: Receiver<Command>,
    writer: Writer,
    mode: Mode,
    stop_on_entry: bool,
    refs: Vec<Ref>,
    canonical: HashMap<String, String>,
}

impl DapDebugger {
    pub fn new(
        shared: Arc<Shared>,
        commands: Receiver<Command>,
        writer: Writer,
        stop_on_entry: bool,
    ) -> DapDebugger {
        DapDebugger {
            shared,
            commands,
            writer,
            mode: Mode::Run,
            stop_on_entry,
            refs: Vec::new(),
            canonical: HashMap::new(),
        }
    }

    /// The canonical path of a unit's path (as breakpoints name files).
    fn canonical(&mut self, path: &str) -> String {
        if let Some(c) = self.canonical.get(path) {
            return c.clone();
        }
        let c = canonical(path);
        self.canonical.insert(path.to_owned(), c.clone());
        c
    }

    fn breakpoint_hit(&mut self, m: &mut Machine, path: &str, line: usize) -> bool {
        let key = self.canonical(path);
        let conditions: Vec<Option<String>> = match self.shared.breakpoints.lock() {
            Ok(b) => b
                .get(&key)
                .map(|list| {
                    list.iter()
                        .filter(|b| b.line == line)
                        .map(|b| b.condition.clone())
                        .collect()
                })
                .unwrap_or_default(),
            Err(_) => return false,
        };
        conditions.into_iter().any(|c| match c {
            None => true,
            Some(c) => match m.evaluate(0, &c) {
                Ok(Value::Bool(b)) => b,
                Ok(other) => {
                    self.writer.event(
                        "output",
                        json!({"category": "console", "output": format!("breakpoint condition `{c}` is {other}, not a bool\n")}),
                    );
                    true
                }
                Err(e) => {
                    self.writer.event(
                        "output",
                        json!({"category": "console", "output": format!("breakpoint condition `{c}`: {e}\n")}),
                    );
                    true
                }
            },
        })
    }

    /// Stops: tells the client, answers its requests, and returns how to go
    /// on.
    fn stop(&mut self, m: &mut Machine, body: Json) -> Control {
        self.refs.clear();
        self.shared.paused.store(true, Ordering::SeqCst);
        self.writer.event("stopped", body);
        let control = loop {
            match self.commands.recv() {
                Ok(Command::Request(req)) => self.answer(m, &req),
                Ok(Command::Resume(r)) => {
                    let depth = m.depth();
                    self.mode = match r {
                        Resume::Continue => Mode::Run,
                        Resume::Next => Mode::StepOver(depth),
                        Resume::StepIn => Mode::StepIn,
                        Resume::StepOut => Mode::StepOut(depth),
                    };
                    break Control::Continue;
                }
                Ok(Command::Terminate) | Err(_) => break Control::Terminate,
            }
        };
        self.shared.paused.store(false, Ordering::SeqCst);
        control
    }

    fn add(&mut self, r: Ref) -> usize {
        self.refs.push(r);
        self.refs.len()
    }

    fn answer(&mut self, m: &mut Machine, req: &Json) {
        let args = &req["arguments"];
        let frame = |key: &str| args[key].as_u64().unwrap_or(0) as usize;
        match req["command"].as_str().unwrap_or_default() {
            "stackTrace" => {
                let frames: Vec<Json> = m
                    .stack_frames()
                    .iter()
                    .enumerate()
                    .map(|(i, f)| {
                        let path = self.canonical(&f.at.path);
                        json!({
                            "id": i,
                            "name": f.routine,
                            "source": {"name": file_name(&path), "path": path},
                            "line": f.at.line,
                            "column": f.at.column,
                        })
                    })
                    .collect();
                let total = frames.len();
                self.writer
                    .respond(req, json!({"stackFrames": frames, "totalFrames": total}));
            }
            "scopes" => {
                let f = frame("frameId");
                let scopes = json!([
                    {"name": "Locals", "presentationHint": "locals", "variablesReference": self.add(Ref::Locals(f)), "expensive": false},
                    {"name": "Module", "variablesReference": self.add(Ref::Module(f)), "expensive": false},
                    {"name": "System", "variablesReference": self.add(Ref::System), "expensive": false},
                ]);
                self.writer.respond(req, json!({"scopes": scopes}));
            }
            "variables" => {
                let r = frame("variablesReference");
                let vars = self.children(m, r);
                self.writer.respond(req, json!({"variables": vars}));
            }
            "setVariable" => {
                let r = frame("variablesReference");
                let name = args["name"].as_str().unwrap_or_default();
                let text = args["value"].as_str().unwrap_or_default();
                let Some((f, target)) = self.target(r, name) else {
                    return self.writer.fail(req, "this variable cannot be changed");
                };
                match m.assign(f, &target, text) {
                    Ok(v) => {
                        let (shown, reference) = self.show(f, &target, false, &v);
                        self.writer.respond(
                            req,
                            json!({"value": shown, "type": type_of(&v), "variablesReference": reference}),
                        );
                    }
                    Err(e) => self.writer.fail(req, &e),
                }
            }
            "evaluate" => {
                let f = frame("frameId");
                let text = args["expression"].as_str().unwrap_or_default();
                match m.evaluate(f, text) {
                    Ok(v) => {
                        let (shown, reference) = self.show(f, text, false, &v);
                        self.writer.respond(
                            req,
                            json!({"result": shown, "type": type_of(&v), "variablesReference": reference}),
                        );
                    }
                    Err(e) => self.writer.fail(req, &e),
                }
            }
            other => self
                .writer
                .fail(req, &format!("{other} is not answered while stopped")),
        }
    }

    /// The text of a value and, for a record or an array, a reference to
    /// its parts.
    fn show(&mut self, frame: usize, path: &str, element: bool, v: &Value) -> (String, usize) {
        let reference = match v {
            Value::Record { .. } | Value::Array(_) => self.add(Ref::Value {
                frame,
                path: path.to_owned(),
                element,
                value: v.clone(),
            }),
            _ => 0,
        };
        (v.to_string(), reference)
    }

    fn variable(&mut self, frame: usize, path: String, element: bool, var: &Variable) -> Json {
        let name = var.name.clone();
        match &var.value {
            None => {
                json!({"name": name, "value": "<not present>", "type": var.ty, "variablesReference": 0})
            }
            Some(v) => {
                let (shown, reference) = self.show(frame, &path, element, v);
                json!({
                    "name": name,
                    "value": shown,
                    "type": var.ty,
                    "variablesReference": reference,
                    "evaluateName": path,
                })
            }
        }
    }

    fn children(&mut self, m: &Machine, r: usize) -> Vec<Json> {
        let (frame, vars, parent): (usize, Vec<Variable>, Option<(String, bool)>) =
            match self.refs.get(r.wrapping_sub(1)) {
                Some(Ref::Locals(f)) => (*f, m.frame_variables(*f), None),
                Some(Ref::Module(f)) => (*f, m.module_variables(*f), None),
                Some(Ref::System) => (0, m.system_variables(), None),
                Some(Ref::Value {
                    frame,
                    path,
                    element,
                    value,
                }) => (*frame, parts(value), Some((path.clone(), *element))),
                None => return Vec::new(),
            };
        vars.iter()
            .map(|v| {
                let (path, element) = match &parent {
                    None => (v.name.clone(), false),
                    Some((p, element)) => child_path(p, *element, &v.name),
                };
                self.variable(frame, path, element, v)
            })
            .collect()
    }

    /// The frame and the expression naming child `name` of reference `r`.
    fn target(&self, r: usize, name: &str) -> Option<(usize, String)> {
        match self.refs.get(r.wrapping_sub(1))? {
            Ref::Locals(f) | Ref::Module(f) => Some((*f, name.to_owned())),
            Ref::System => Some((0, name.to_owned())),
            Ref::Value {
                frame,
                path,
                element,
                ..
            } => Some((*frame, child_path(path, *element, name).0)),
        }
    }
}

impl Debugger for DapDebugger {
    fn statement(&mut self, m: &mut Machine) -> Control {
        if self.shared.terminate.load(Ordering::SeqCst) {
            return Control::Terminate;
        }
        let Some(at) = m.location() else {
            return Control::Continue;
        };
        let depth = m.depth();
        let reason = if std::mem::take(&mut self.stop_on_entry) {
            Some("entry")
        } else if self.shared.pause.swap(false, Ordering::SeqCst) {
            Some("pause")
        } else {
            match self.mode {
                Mode::StepIn => Some("step"),
                Mode::StepOver(d) if depth <= d => Some("step"),
                Mode::StepOut(d) if depth < d => Some("step"),
                _ => None,
            }
        };
        let reason = match reason {
            Some(r) => Some(r),
            None if self.breakpoint_hit(m, &at.path, at.line) => Some("breakpoint"),
            None => None,
        };
        match reason {
            Some(reason) => self.stop(
                m,
                json!({"reason": reason, "threadId": 1, "allThreadsStopped": true}),
            ),
            None => Control::Continue,
        }
    }

    fn error(&mut self, m: &mut Machine, outcome: &Outcome) {
        let name = outcome.errno.as_ref().map_or("error", |(_, n)| n.as_str());
        let text = format!("{name}: {}", outcome.message);
        let _ = self.stop(
            m,
            json!({"reason": "exception", "description": text, "text": text, "threadId": 1, "allThreadsStopped": true}),
        );
        self.mode = Mode::Run;
    }
}

/// The parts of a record or an array, as variables.
fn parts(v: &Value) -> Vec<Variable> {
    match v {
        Value::Record { fields, .. } => fields
            .iter()
            .map(|(n, v)| Variable {
                name: n.clone(),
                ty: type_of(v),
                value: Some(v.clone()),
            })
            .collect(),
        Value::Array(items) => items
            .iter()
            .enumerate()
            .map(|(i, v)| Variable {
                name: format!("{{{}}}", i + 1),
                ty: type_of(v),
                value: Some(v.clone()),
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// The expression naming a part: `p.trans`, `a{2}`, and `grid{1,2}` for
/// an element of a two-dimensional array; and whether it is an element.
fn child_path(parent: &str, parent_is_element: bool, name: &str) -> (String, bool) {
    match name.strip_prefix('{').and_then(|n| n.strip_suffix('}')) {
        Some(index) if parent_is_element && parent.ends_with('}') => {
            (format!("{},{index}}}", &parent[..parent.len() - 1]), true)
        }
        Some(index) => (format!("{parent}{{{index}}}"), true),
        None => (format!("{parent}.{name}"), false),
    }
}

fn type_of(v: &Value) -> String {
    match v {
        Value::Array(items) => format!("array{{{}}}", items.len()),
        other => other.type_name().unwrap_or("").to_owned(),
    }
}

/// A file's canonical path (the path itself when it cannot be resolved).
pub fn canonical(path: &str) -> String {
    std::fs::canonicalize(path)
        .map(|p| p.to_string_lossy().into_owned())
        .unwrap_or_else(|_| path.to_owned())
}

fn file_name(path: &str) -> &str {
    path.rsplit(['/', '\\']).next().unwrap_or(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parts_are_named_as_rapid_names_them() {
        assert_eq!(child_path("p", false, "trans"), ("p.trans".into(), false));
        assert_eq!(
            child_path("p.trans", false, "x"),
            ("p.trans.x".into(), false)
        );
        assert_eq!(child_path("a", false, "{2}"), ("a{2}".into(), true));
        assert_eq!(
            child_path("grid{1}", true, "{3}"),
            ("grid{1,3}".into(), true)
        );
        assert_eq!(
            child_path("parts{1}", true, "name"),
            ("parts{1}.name".into(), false)
        );
    }
}
