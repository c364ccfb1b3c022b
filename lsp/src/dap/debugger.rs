//! What the adapter answers while the controller is stopped: stacks (a
//! thread per task), scopes, variables, evaluations and assignments. A
//! frame id names a task and a routine frame of it; a variables reference
//! names a scope or a record or array shown.

use std::collections::HashMap;

use rapid_evaluator::Value;
use rapid_runtime::{Controller, Variable};
use serde_json::{Value as Json, json};

use super::wire::Writer;

/// A line breakpoint, with its condition (a RAPID expression).
#[derive(Clone, Debug)]
pub struct Breakpoint {
    pub line: usize,
    pub condition: Option<String>,
}

/// Frame ids: `task * FRAMES + frame`.
const FRAMES: usize = 1_000_000;

/// What a `variablesReference` stands for while stopped.
enum Ref {
    Locals(usize, usize),
    Module(usize, usize),
    System(usize),
    /// A record or an array: the task and frame, the RAPID expression that
    /// names it, whether it is an element of an array, and its value.
    Value {
        task: usize,
        frame: usize,
        path: String,
        element: bool,
        value: Value,
    },
}

#[derive(Default)]
pub struct Inspector {
    refs: Vec<Ref>,
    canonical: HashMap<String, String>,
}

impl Inspector {
    /// The controller stopped: earlier references no longer hold.
    pub fn stopped(&mut self) {
        self.refs.clear();
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

    fn add(&mut self, r: Ref) -> usize {
        self.refs.push(r);
        self.refs.len()
    }

    pub fn answer(&mut self, c: &mut Controller, writer: &Writer, req: &Json) {
        let args = &req["arguments"];
        let number = |key: &str| args[key].as_u64().unwrap_or(0) as usize;
        let frame_of = |id: usize| (id / FRAMES, id % FRAMES);
        match req["command"].as_str().unwrap_or_default() {
            "stackTrace" => {
                let task = number("threadId").saturating_sub(1);
                let frames: Vec<Json> = c
                    .stack(task)
                    .iter()
                    .enumerate()
                    .map(|(i, f)| {
                        let path = self.canonical(&f.at.path);
                        json!({
                            "id": task * FRAMES + i,
                            "name": f.routine,
                            "source": {"name": file_name(&path), "path": path},
                            "line": f.at.line,
                            "column": f.at.column,
                        })
                    })
                    .collect();
                let total = frames.len();
                writer.respond(req, json!({"stackFrames": frames, "totalFrames": total}));
            }
            "scopes" => {
                let (task, frame) = frame_of(number("frameId"));
                let scopes = json!([
                    {"name": "Locals", "presentationHint": "locals", "variablesReference": self.add(Ref::Locals(task, frame)), "expensive": false},
                    {"name": "Module", "variablesReference": self.add(Ref::Module(task, frame)), "expensive": false},
                    {"name": "System", "variablesReference": self.add(Ref::System(task)), "expensive": false},
                ]);
                writer.respond(req, json!({"scopes": scopes}));
            }
            "variables" => {
                let vars = self.children(c, number("variablesReference"));
                writer.respond(req, json!({"variables": vars}));
            }
            "setVariable" => {
                let name = args["name"].as_str().unwrap_or_default();
                let text = args["value"].as_str().unwrap_or_default();
                let Some((task, frame, target)) = self.target(number("variablesReference"), name)
                else {
                    return writer.fail(req, "this variable cannot be changed");
                };
                match c.assign(task, frame, &target, text) {
                    Ok(v) => {
                        let (shown, reference) = self.show(task, frame, &target, false, &v);
                        writer.respond(
                            req,
                            json!({"value": shown, "type": type_of(&v), "variablesReference": reference}),
                        );
                    }
                    Err(e) => writer.fail(req, &e),
                }
            }
            "evaluate" => {
                let (task, frame) = frame_of(number("frameId"));
                let text = args["expression"].as_str().unwrap_or_default();
                match c.evaluate(task, frame, text) {
                    Ok(v) => {
                        let (shown, reference) = self.show(task, frame, text, false, &v);
                        writer.respond(
                            req,
                            json!({"result": shown, "type": type_of(&v), "variablesReference": reference}),
                        );
                    }
                    Err(e) => writer.fail(req, &e),
                }
            }
            other => writer.fail(req, &format!("{other} is not answered while stopped")),
        }
    }

    /// The text of a value and, for a record or an array, a reference to
    /// its parts.
    fn show(
        &mut self,
        task: usize,
        frame: usize,
        path: &str,
        element: bool,
        v: &Value,
    ) -> (String, usize) {
        let reference = match v {
            Value::Record { .. } | Value::Array(_) => self.add(Ref::Value {
                task,
                frame,
                path: path.to_owned(),
                element,
                value: v.clone(),
            }),
            _ => 0,
        };
        (v.to_string(), reference)
    }

    fn variable(
        &mut self,
        task: usize,
        frame: usize,
        path: String,
        element: bool,
        var: &Variable,
    ) -> Json {
        let name = var.name.clone();
        match &var.value {
            None => {
                json!({"name": name, "value": "<not present>", "type": var.ty, "variablesReference": 0})
            }
            Some(v) => {
                let (shown, reference) = self.show(task, frame, &path, element, v);
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

    fn children(&mut self, c: &Controller, r: usize) -> Vec<Json> {
        type Parent = Option<(String, bool)>;
        let (task, frame, vars, parent): (usize, usize, Vec<Variable>, Parent) =
            match self.refs.get(r.wrapping_sub(1)) {
                Some(Ref::Locals(t, f)) => (*t, *f, c.frame_variables(*t, *f), None),
                Some(Ref::Module(t, f)) => (*t, *f, c.module_variables(*t, *f), None),
                Some(Ref::System(t)) => (*t, 0, c.system_variables(*t), None),
                Some(Ref::Value {
                    task,
                    frame,
                    path,
                    element,
                    value,
                }) => (*task, *frame, parts(value), Some((path.clone(), *element))),
                None => return Vec::new(),
            };
        vars.iter()
            .map(|v| {
                let (path, element) = match &parent {
                    None => (v.name.clone(), false),
                    Some((p, element)) => child_path(p, *element, &v.name),
                };
                self.variable(task, frame, path, element, v)
            })
            .collect()
    }

    /// The task, frame and expression naming child `name` of reference
    /// `r`.
    fn target(&self, r: usize, name: &str) -> Option<(usize, usize, String)> {
        match self.refs.get(r.wrapping_sub(1))? {
            Ref::Locals(t, f) | Ref::Module(t, f) => Some((*t, *f, name.to_owned())),
            Ref::System(t) => Some((*t, 0, name.to_owned())),
            Ref::Value {
                task,
                frame,
                path,
                element,
                ..
            } => Some((*task, *frame, child_path(path, *element, name).0)),
        }
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
