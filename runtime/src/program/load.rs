//! What the controller's loader finds in a task before it runs: the errors
//! that keep it from loading, and the signals and mechanical units it uses
//! that no configuration declares (taken from their use).

use std::sync::Arc;

use rapid_analyzer::names::fold;
use rapid_analyzer::task::Task;
use rapid_analyzer::text::LineIndex;

use super::{Location, SignalKind};

/// An error that keeps the controller from loading a task (and so from
/// running it): a syntax error, or what the checker finds the controller
/// would refuse when it loads and links the modules (names, types,
/// arguments; not `constant-error`, which the controller meets only when
/// the statement runs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadError {
    pub at: Location,
    /// The rule's code and name (`E001`, `syntax-error`).
    pub code: &'static str,
    pub name: &'static str,
    pub message: String,
}

impl std::fmt::Display for LoadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}:{}: error[{}] {} ({})",
            self.at.path, self.at.line, self.at.column, self.code, self.message, self.name
        )
    }
}

/// A signal the task uses that its configuration does not declare (or
/// that has no `EIO.cfg`), declared by the simulation from its first use.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TakenSignal {
    pub name: String,
    pub kind: SignalKind,
    /// The use it was taken from.
    pub at: Location,
}

impl std::fmt::Display for TakenSignal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}:{}: note: {} is declared by no EIO.cfg here: simulated as a {} from its use",
            self.at.path,
            self.at.line,
            self.at.column,
            self.name,
            self.kind.type_name()
        )
    }
}

/// What the controller's loader finds in a task: the errors that keep it
/// from loading, and the signals it uses that no configuration declares.
#[derive(Clone, Debug, Default)]
pub struct LoadCheck {
    pub errors: Vec<LoadError>,
    /// One a name, at its first use.
    pub signals: Vec<TakenSignal>,
    /// The mechanical units it names that no `MOC.cfg` declares.
    pub units: Vec<String>,
    /// The names its modules use that none of them declares, where a
    /// module may be missing (not in a complete backup, where they are
    /// errors): one a name, as written at its first use.
    pub missing: Vec<String>,
}

impl LoadCheck {
    /// `task` with the mechanical units taken from their use.
    pub fn with_units(&self, task: Arc<Task>) -> Arc<Task> {
        if self.units.is_empty() {
            return task;
        }
        let mut t = task.with_signals(&[]);
        let mut units = (*task.mecunits).clone();
        units.extend(self.units.iter().map(|u| fold(u)));
        t.set_controller_names(units, (*task.task_ids).clone());
        Arc::new(t)
    }

    /// The signals taken from use, for [`Program::new`].
    pub fn extra_signals(&self) -> Vec<(String, SignalKind)> {
        self.signals
            .iter()
            .map(|s| (s.name.clone(), s.kind))
            .collect()
    }
}

/// The errors that keep the controller from loading `task` (see
/// [`load_check`]), the signals the configuration lacks aside.
pub fn load_errors(task: &Task) -> Vec<LoadError> {
    load_check(task).errors
}

/// The errors that keep the controller from loading `task`, in the order
/// of its files and of their positions: the checker's errors (at their
/// default severities, which inline suppressions and a project's
/// configuration do not change: the controller knows neither). A signal
/// that no configuration declares is not an error here: it is taken from
/// its use (a `signaldo` where `SetDO` takes one), once a name. A module
/// that clashes with another of the group (two versions of one module) is
/// checked in its own view ([`Task::view`]), as `rapid check` checks it:
/// the signals and units it uses are taken from there too.
pub fn load_check(task: &Task) -> LoadCheck {
    let mut out = LoadCheck::default();
    for (i, unit) in task.units.iter().enumerate() {
        let owned = task.owns(i);
        let view;
        let seen_in = if owned {
            task
        } else if task.owner.is_none() {
            view = task.view(i);
            &view
        } else {
            continue;
        };
        let lines = LineIndex::new(&unit.text);
        for d in rapid_analyzer::workspace::diagnostics_of(seen_in, unit) {
            let (line, column) = lines.human(d.range.start, &unit.text);
            let at = Location {
                path: unit.path.clone(),
                line,
                column,
            };
            if let Some((name, ty)) = rapid_analyzer::rules::unconfigured_signal::taken_signal(&d) {
                if ty == "mecunit" {
                    if !out.units.iter().any(|u| u.eq_ignore_ascii_case(name)) {
                        out.units.push(name.to_owned());
                    }
                    continue;
                }
                let known = out
                    .signals
                    .iter()
                    .any(|s| s.name.eq_ignore_ascii_case(name));
                if !known && let Some(kind) = SignalKind::from_type(ty) {
                    out.signals.push(TakenSignal {
                        name: name.to_owned(),
                        kind,
                        at,
                    });
                }
                continue;
            }
            if owned
                && d.rule.code == rapid_analyzer::rules::unresolved_name::RULE.code
                && d.severity != rapid_analyzer::diagnostic::Severity::Error
                && let Some(name) = unit.text.get(d.range.clone())
                && !out.missing.iter().any(|m| m.eq_ignore_ascii_case(name))
            {
                out.missing.push(name.to_owned());
                continue;
            }
            // Errors the controller meets only when the statement runs: a
            // constant's evaluation, and a move to a target out of reach or
            // beyond a working range (the robot stops there). A version of a
            // module checked in its own view keeps its errors to `rapid
            // check`: which version the controller loads is not known.
            let load_time = !matches!(d.rule.code, "E413" | "E601" | "E602");
            if !owned || d.severity != rapid_analyzer::diagnostic::Severity::Error || !load_time {
                continue;
            }
            out.errors.push(LoadError {
                at,
                code: d.rule.code,
                name: d.rule.name,
                message: d.message,
            });
        }
    }
    out
}
