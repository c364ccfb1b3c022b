//! The tools that look things up: `explain_rule` (the rules' registry),
//! `lookup_builtin` (the catalogue, as `rapid builtins`), `evaluate` (the
//! constant evaluator, as `rapid eval`) and `list_symbols` (the item trees
//! and configuration of the tasks the project loader groups).

use std::path::PathBuf;

use rapid_analyzer::catalogue::Origin;
use rapid_analyzer::items::{RoutineKind, Scope};
use rapid_analyzer::names::{fold, same};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::roots::{Confined, resolve};
use super::{Answer, shown};
use crate::builtins::{Entry, catalogue_of, describe, find};

/// The arguments of `explain_rule`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RuleParams {
    /// A rule's code (`W201`) or name (`unused-data`), any letter case.
    pub rule: String,
}

/// A rule of the checker.
#[derive(Debug, Serialize, JsonSchema)]
pub struct RuleInfo {
    pub code: String,
    pub name: String,
    /// The severity unless `rapid.toml` sets another.
    pub severity: String,
    /// Whether the rule is on unless `rapid.toml` selects otherwise.
    pub on_by_default: bool,
    pub summary: String,
    /// Markdown: what it checks, why, an example.
    pub documentation: String,
}

pub fn explain_rule(params: RuleParams) -> Result<Answer<RuleInfo>, String> {
    let rule = rapid_analyzer::rules::find(params.rule.trim()).ok_or_else(|| {
        format!(
            "no rule has the code or name `{}` (the resource rapid://rules lists them)",
            params.rule
        )
    })?;
    let info = RuleInfo {
        code: rule.code.to_owned(),
        name: rule.name.to_owned(),
        severity: rule.severity.as_str().to_owned(),
        on_by_default: rule.default_on,
        summary: rule.summary.to_owned(),
        documentation: crate::rules_cmd::doc(rule),
    };
    Ok(Answer::new(crate::rules_cmd::describe(rule), info))
}

/// The arguments of `lookup_builtin`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BuiltinParams {
    /// A built-in function, instruction, data type or predefined datum
    /// (`MoveL`, `Offs`, `robtarget`, `v100`), any letter case.
    pub name: String,
    /// A RobotWare version (`6.15`): the signature that version has, and an
    /// error if it lacks the name.
    pub robotware: Option<String>,
    /// With `robotware`: the option packages installed (`arc`, `egm`...);
    /// default: every package.
    pub options: Option<Vec<String>>,
}

/// A built-in, as the catalogue has it.
#[derive(Debug, Serialize, JsonSchema)]
pub struct BuiltinInfo {
    pub name: String,
    /// `function`, `instruction`, `data type` or `datum`.
    pub kind: String,
    /// The declaration as the manual writes it.
    pub signature: String,
    pub summary: String,
    pub documentation: String,
    /// The parameters of a routine, in order.
    pub parameters: Vec<ParamInfo>,
    /// The type a function returns.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub returns: Option<String>,
    /// The RobotWare versions that have it (`5.0-`, `6.10-7.0 (removed in 7.0)`).
    pub robotware: String,
    /// The option package that brings it (`None`: the base language).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub option: Option<String>,
    /// Where the facts come from.
    pub source: String,
}

/// A parameter of a built-in routine.
#[derive(Debug, Serialize, JsonSchema)]
pub struct ParamInfo {
    pub name: String,
    #[serde(rename = "type")]
    pub ty: String,
    /// `IN`, `VAR`, `PERS` or `INOUT` (none for switches).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mode: Option<String>,
    pub optional: bool,
    pub switch: bool,
    /// Array dimensions (0: not an array).
    pub array: u8,
    /// Parameters with the same group exclude each other (`|`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alternative_group: Option<u32>,
}

pub fn lookup_builtin(params: BuiltinParams) -> Result<Answer<BuiltinInfo>, String> {
    let cat = catalogue_of(params.robotware.as_deref(), params.options.as_deref())?;
    let clean = |e: String| e.replace("rapid builtins: ", "");
    let name = params.name.trim();
    let text = describe(&cat, name).map_err(clean)?;
    let option = |origin: &Origin| {
        origin.package.as_ref().map(|id| match cat.package(id) {
            Some(p) => format!("{} ({id})", p.name),
            None => id.clone(),
        })
    };
    let source = |origin: &Origin| match &origin.section {
        Some(section) => format!("{}, section {section}", origin.source.describe()),
        None => origin.source.describe().to_owned(),
    };
    let info = match find(&cat, name).map_err(clean)? {
        Entry::Routine(r) => BuiltinInfo {
            name: r.name.clone(),
            kind: if r.is_function() {
                "function"
            } else {
                "instruction"
            }
            .to_owned(),
            signature: r.signature(),
            summary: r.summary.clone(),
            documentation: r.doc.clone(),
            parameters: r
                .params
                .iter()
                .map(|p| ParamInfo {
                    name: p.name.clone(),
                    ty: p.ty.clone(),
                    mode: p.mode.map(|m| m.keyword().to_owned()),
                    optional: p.optional,
                    switch: p.switch,
                    array: p.array,
                    alternative_group: p.alt_group,
                })
                .collect(),
            returns: r.returns.clone(),
            robotware: r.origin.versions(),
            option: option(&r.origin),
            source: source(&r.origin),
        },
        Entry::DataType(t) => BuiltinInfo {
            name: t.name.clone(),
            kind: "data type".to_owned(),
            signature: t.signature(),
            summary: t.summary.clone(),
            documentation: t.doc.clone(),
            parameters: Vec::new(),
            returns: None,
            robotware: t.origin.versions(),
            option: option(&t.origin),
            source: source(&t.origin),
        },
        Entry::Datum(d) => BuiltinInfo {
            name: d.name.clone(),
            kind: "datum".to_owned(),
            signature: d.signature(),
            summary: d.summary.clone(),
            documentation: String::new(),
            parameters: Vec::new(),
            returns: None,
            robotware: d.origin.versions(),
            option: option(&d.origin),
            source: source(&d.origin),
        },
    };
    Ok(Answer::new(text, info))
}

/// The arguments of `evaluate`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EvaluateParams {
    /// A RAPID expression: `Sqrt(2) * Sin(30)`, `Offs(pHome, 0, 0, 100)`.
    pub expression: String,
    /// A module (names resolve as inside it, with the rest of its task) or
    /// a task's folder (its global data); without it, built-ins only.
    pub path: Option<String>,
    /// Use the initial values of VAR and PERS data instead of refusing
    /// them as not constant.
    #[serde(default)]
    pub initial: bool,
}

/// A value, as the controller computes it.
#[derive(Debug, Serialize, JsonSchema)]
pub struct EvaluateReport {
    /// The RAPID type (`num`, `robtarget`...).
    #[serde(rename = "type")]
    pub ty: String,
    /// The value as RAPID writes it.
    pub value: String,
    /// Data whose initial value was used (with `initial`).
    pub initial_values: Vec<String>,
}

pub fn evaluate(
    roots: &[PathBuf],
    params: EvaluateParams,
) -> Result<Answer<EvaluateReport>, String> {
    let env = Confined::new(roots.to_vec());
    let path = params
        .path
        .as_deref()
        .map(|p| resolve(roots, p))
        .transpose()?;
    let value = crate::eval::evaluate(&env, &params.expression, path.as_deref(), params.initial)
        .map_err(|f| f.to_string())?;
    let report = EvaluateReport {
        ty: rapid_analyzer::consteval::value_type(&value.value).to_string(),
        value: value.value.to_string(),
        initial_values: value.initial_values_used.clone(),
    };
    let mut summary = format!("{} ({})", report.value, report.ty);
    if !report.initial_values.is_empty() {
        summary.push_str(&format!(
            "\ncomputed from the initial value of {} (not constant: it may differ at run time)",
            report.initial_values.join(", ")
        ));
    }
    Ok(Answer::new(summary, report))
}

/// The arguments of `list_symbols`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SymbolsParams {
    /// A module (its task) or a folder (each task under it).
    pub path: String,
    /// What to list: `routines`, `data`, `signals`; default: all three.
    pub kinds: Option<Vec<String>>,
    /// Only data of this type (`wobjdata`, `tooldata`, `robtarget`), any
    /// letter case.
    #[serde(rename = "type")]
    pub ty: Option<String>,
    /// Only names that contain this text (any letter case).
    pub name: Option<String>,
    /// At most this many entries per list and task (default 500).
    pub limit: Option<usize>,
}

/// The answer of `list_symbols`.
#[derive(Debug, Serialize, JsonSchema)]
pub struct SymbolsReport {
    pub tasks: Vec<TaskSymbols>,
}

/// What one task declares.
#[derive(Debug, Serialize, JsonSchema)]
pub struct TaskSymbols {
    /// The task's folder.
    pub task: String,
    /// Its modules.
    pub modules: Vec<String>,
    pub routines: Vec<RoutineSymbol>,
    pub data: Vec<DataSymbol>,
    /// Signals of the task's `EIO.cfg` (names folded to lower case, as
    /// RAPID compares them).
    pub signals: Vec<SignalSymbol>,
    /// Whether an `EIO.cfg` was found for the task.
    pub signals_configured: bool,
    /// Whether a list was cut at the limit.
    pub truncated: bool,
}

#[derive(Debug, Serialize, JsonSchema)]
pub struct RoutineSymbol {
    pub name: String,
    /// `PROC`, `FUNC` or `TRAP`.
    pub kind: String,
    pub module: String,
    pub file: String,
    pub line: usize,
    /// Visible only in its module.
    pub local: bool,
    /// The declaration's first line, as written.
    pub declaration: String,
}

#[derive(Debug, Serialize, JsonSchema)]
pub struct DataSymbol {
    pub name: String,
    /// `VAR`, `PERS` or `CONST`.
    pub storage: String,
    #[serde(rename = "type")]
    pub ty: String,
    pub module: String,
    pub file: String,
    pub line: usize,
    /// `global`, `local` (its module only) or `task` (a `TASK PERS`).
    pub scope: String,
    /// The initial value as written (cut after 200 characters).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<String>,
}

#[derive(Debug, Serialize, JsonSchema)]
pub struct SignalSymbol {
    pub name: String,
    /// `signaldi`, `signaldo`, `signalai`...
    #[serde(rename = "type")]
    pub ty: String,
}

pub fn list_symbols(
    roots: &[PathBuf],
    params: SymbolsParams,
) -> Result<Answer<SymbolsReport>, String> {
    let path = resolve(roots, &params.path)?;
    let env = Confined::new(roots.to_vec());
    let found = crate::run::load::tasks_in(&env, std::slice::from_ref(&path))?;
    let kinds = params.kinds.clone().unwrap_or_default();
    for k in &kinds {
        if !["routines", "data", "signals"].contains(&k.as_str()) {
            return Err(format!("kinds: `{k}` is not routines, data or signals"));
        }
    }
    let wants = |k: &str| kinds.is_empty() || kinds.iter().any(|x| x == k);
    let limit = params.limit.unwrap_or(500);
    let name_ok = |n: &str| {
        params
            .name
            .as_ref()
            .is_none_or(|w| fold(n).contains(&fold(w)))
    };
    let mut tasks = Vec::new();
    for task in &found.tasks {
        let mut t = TaskSymbols {
            task: shown(roots, std::path::Path::new(&task.key)),
            modules: Vec::new(),
            routines: Vec::new(),
            data: Vec::new(),
            signals: Vec::new(),
            signals_configured: task.signals.is_some(),
            truncated: false,
        };
        for unit in task.units.iter() {
            let file = shown(roots, std::path::Path::new(&unit.path));
            let line_of = |offset: usize| {
                unit.text[..offset.min(unit.text.len())]
                    .matches('\n')
                    .count()
                    + 1
            };
            for m in &unit.items.modules {
                t.modules.push(m.name.clone());
                for r in m.routines.iter().filter(|_| wants("routines")) {
                    if !name_ok(&r.name) {
                        continue;
                    }
                    if t.routines.len() >= limit {
                        t.truncated = true;
                        break;
                    }
                    let declaration = unit.text[r.range.clone()]
                        .lines()
                        .next()
                        .unwrap_or_default()
                        .trim()
                        .to_owned();
                    t.routines.push(RoutineSymbol {
                        name: r.name.clone(),
                        kind: match r.kind {
                            RoutineKind::Proc => "PROC",
                            RoutineKind::Func => "FUNC",
                            RoutineKind::Trap => "TRAP",
                        }
                        .to_owned(),
                        module: m.name.clone(),
                        file: file.clone(),
                        line: line_of(r.name_range.start),
                        local: r.local,
                        declaration,
                    });
                }
                for d in m.data.iter().filter(|_| wants("data")) {
                    let ty = d.ty.as_ref().map_or("", |t| t.name.as_str());
                    let type_ok = params.ty.as_ref().is_none_or(|w| same(w, ty));
                    if !type_ok || !name_ok(&d.name) {
                        continue;
                    }
                    if t.data.len() >= limit {
                        t.truncated = true;
                        break;
                    }
                    t.data.push(DataSymbol {
                        name: d.name.clone(),
                        storage: d.storage.keyword().to_owned(),
                        ty: ty.to_owned(),
                        module: m.name.clone(),
                        file: file.clone(),
                        line: line_of(d.name_range.start),
                        scope: match d.scope {
                            Scope::Global => "global",
                            Scope::Local => "local",
                            Scope::Task => "task",
                        }
                        .to_owned(),
                        value: d.init.clone().map(|r| {
                            let v: String = unit.text[r].chars().take(200).collect();
                            v.split_whitespace().collect::<Vec<_>>().join(" ")
                        }),
                    });
                }
            }
        }
        if wants("signals")
            && let Some(signals) = &task.signals
        {
            let mut list: Vec<(&String, &&str)> = signals
                .iter()
                .filter(|(n, ty)| name_ok(n) && params.ty.as_ref().is_none_or(|w| same(w, ty)))
                .collect();
            list.sort();
            if list.len() > limit {
                t.truncated = true;
                list.truncate(limit);
            }
            t.signals = list
                .into_iter()
                .map(|(n, ty)| SignalSymbol {
                    name: n.clone(),
                    ty: (*ty).to_owned(),
                })
                .collect();
        }
        tasks.push(t);
    }
    if tasks.is_empty() {
        return Err(format!("{}: no RAPID modules found", params.path));
    }
    let report = SymbolsReport { tasks };
    Ok(Answer::new(symbols_summary(&report), report))
}

fn symbols_summary(r: &SymbolsReport) -> String {
    let mut out = String::new();
    for t in &r.tasks {
        out.push_str(&format!(
            "task {} ({} module{})\n",
            t.task,
            t.modules.len(),
            super::check::plural(t.modules.len())
        ));
        for x in &t.routines {
            out.push_str(&format!("  {}  ({}:{})\n", x.declaration, x.file, x.line));
        }
        for d in &t.data {
            let value = d
                .value
                .as_ref()
                .map(|v| format!(" := {v}"))
                .unwrap_or_default();
            out.push_str(&format!(
                "  {} {} {}{value}  ({}:{})\n",
                d.storage, d.ty, d.name, d.file, d.line
            ));
        }
        for s in &t.signals {
            out.push_str(&format!("  signal {} {}\n", s.ty, s.name));
        }
        if t.truncated {
            out.push_str("  (more left out: raise `limit` or filter)\n");
        }
    }
    out
}
